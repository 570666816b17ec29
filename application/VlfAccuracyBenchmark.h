// SPDX-License-Identifier: BSD-3-Clause
#ifndef mesolight_VlfAccuracyBenchmark_h
#define mesolight_VlfAccuracyBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{

/**
 * mesolight bench vlf-accuracy [--scenes LIST] [--settings LIST] [--full] [--size WxH]
 *   [--samples N] [--cache DIR] [--csv FILE] [--plot FILE.png] [--images DIR]
 * The light field's per-pixel error against the path tracer per scene and setting, with time and
 * memory. `args` excludes the words "bench vlf-accuracy". Returns 0, 1 on failure, 2 on bad
 * arguments.
 */
int RunVlfAccuracyBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
