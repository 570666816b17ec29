// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the unit tests of the Mesolight modules (message capture, temporary files).
#ifndef MesolightTestUtilities_h
#define MesolightTestUtilities_h

#include "MessageCapture.h" // the one test observer of VTK errors and warnings
#include "TestDirectory.h"  // a fresh directory per test

#endif
