// SPDX-License-Identifier: BSD-3-Clause
// `mesolight vlf propagate|render` and `mesolight bench vlf`: the virtual light field (vtkVLF,
// Wither 2005 §2.4) from the command line. docs/vlf.md has examples and measured figures.
#ifndef mesolight_VlfCommand_h
#define mesolight_VlfCommand_h

#include <string>
#include <vector>

namespace mesolight
{

/**
 * mesolight vlf propagate [SCENE.obj] --out FIELD [--directions N] [--rays N] [--tiles M]
 *   [--iterations K] [--memory-budget GIB] [--resume | --force]
 * `args` excludes the words "vlf propagate". Returns 0 on success, 1 on failure, 2 on bad
 * arguments.
 */
int RunVlfPropagate(const std::vector<std::string>& args);

/**
 * mesolight vlf render FIELD --out IMAGE.png [--size WxH] [--camera X,Y,Z,FX,FY,FZ]
 *   [--view-angle DEG] [--exposure X]
 * `args` excludes the words "vlf render". Returns 0 on success, 1 on failure, 2 on bad arguments.
 */
int RunVlfRender(const std::vector<std::string>& args);

/**
 * mesolight bench vlf [--directions 513,2049] [--rays 32,64,128] [--iterations K]
 *   [--csv FILE] [--plot FILE.png]. `args` excludes the words "bench vlf".
 */
int RunVlfBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
