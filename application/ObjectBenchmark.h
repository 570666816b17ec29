// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench object`: the per-frame cost of a movable object in the light field walkthrough
// (Wither 2005, "Interactive dynamic objects in a virtual light field", the table of frame times
// per stage), the object moving every frame along a fixed circle so that runs repeat.
#ifndef mesolight_ObjectBenchmark_h
#define mesolight_ObjectBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{
/** mesolight bench object [--directions 513,2049] [--subdivisions 0,1,2,3] [--csv F] [--plot F] */
int RunObjectBenchmark(const std::vector<std::string>& args);
} // namespace mesolight

#endif
