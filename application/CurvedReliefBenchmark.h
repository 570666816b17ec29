// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench curved-relief`: relief mapping on curved meshes (Oliveira & Policarpo 2005,
// "An efficient representation for surface details") against the flat-plane march on the same
// coarse mesh: the outline's coverage mismatch against the dense displaced mesh, and the frame
// time of both, measured in the same run (frames interleaved).
#ifndef mesolight_CurvedReliefBenchmark_h
#define mesolight_CurvedReliefBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{

/** args: the options after "curved-relief". Returns the process exit code. */
int RunCurvedReliefBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
