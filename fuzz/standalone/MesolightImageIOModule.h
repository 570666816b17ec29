// SPDX-License-Identifier: BSD-3-Clause
// The fuzz build (MESOLIGHT_FUZZ=ON) compiles the cores it needs without VTK's module system,
// which generates this header (the export macro) in the normal build. Static code: no export.
#ifndef MesolightImageIOModule_h
#define MesolightImageIOModule_h
#define MESOLIGHTIMAGEIO_EXPORT
#endif
