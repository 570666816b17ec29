// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench gather`: the movable object's gathered shading, cost per vertex, cache hit
// rate and error against the path tracer (GatherBenchmark.cxx).
#ifndef mesolight_GatherBenchmark_h
#define mesolight_GatherBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{
int RunGatherBenchmark(const std::vector<std::string>& args);
}

#endif
