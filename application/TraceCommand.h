// SPDX-License-Identifier: BSD-3-Clause
// `mesolight trace` (the Embree ray tracer of Ahern 1999 on built-in scenes, and the path-traced
// Cornell box) and `mesolight bench trace` (rays per second, path samples per second).
#ifndef mesolight_TraceCommand_h
#define mesolight_TraceCommand_h

#include <string>
#include <vector>

namespace mesolight
{

/** mesolight trace [--scene spheres|ring|cornell] [options]; `args` excludes "trace". */
int RunTraceCommand(const std::vector<std::string>& args);

/** mesolight bench trace [options]; `args` excludes "bench trace". */
int RunTraceBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
