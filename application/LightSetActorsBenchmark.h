// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench light-set-actors`: ordinary VTK actors lit by a light set (vtkLightSetLighting)
// against the path tracer and exact references, per number of directional VTK lights, remainder
// model and shadow maps, with the frame time of each (docs/light-set-actors.md).
#ifndef mesolight_LightSetActorsBenchmark_h
#define mesolight_LightSetActorsBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{
/** `mesolight bench light-set-actors [--counts 0,1,2,4,8,16] [--csv FILE] ...` */
int RunLightSetActorsBenchmark(const std::vector<std::string>& args);
} // namespace mesolight

#endif
