// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench cones`: speed and tightness of the cone-map generators
// (filters/ReliefTextures/core/ConeMaps.h) on procedural maps: seconds per map for the fast
// bilinear-safe searches (relaxed and conservative), the brute-force oracle measured on a small map
// and extrapolated by its complexity, and how wide the bilinear-safe cones are compared with
// per-texel-sample cones.
#ifndef mesolight_ConeBenchmark_h
#define mesolight_ConeBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{

/**
 * `mesolight bench cones [options]`: args are the options after "cones". Returns the process
 * exit code: 0 success (or --help), 1 a failed run, 2 bad arguments.
 */
int RunConeBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
