// SPDX-License-Identifier: BSD-3-Clause
// `mesolight vlf view`, `mesolight vlf render --mode` and `mesolight bench walkthrough`: the light
// field walkthrough through vtkLightFieldActor (Wither 2005 §2.4.2.2). docs/walkthrough.md has
// examples and measured figures. `mesolight vlf render` without --mode stays the CPU reference in
// VlfCommand.cxx.
#ifndef mesolight_LightFieldViewCommand_h
#define mesolight_LightFieldViewCommand_h

#include <string>
#include <vector>

namespace mesolight
{
/** mesolight vlf view FIELD [--mode M] [--size WxH] [--camera ...] [--exposure X] [--frames N] */
int RunLightFieldView(const std::vector<std::string>& args);
/** mesolight vlf render FIELD --mode geometry|raytrace|progressive|coherent --out F.png [...] */
int RunLightFieldRender(const std::vector<std::string>& args);
/** mesolight bench walkthrough [FIELD] [--size 800x800] [--frames N] [--csv F] [--plot F.png] */
int RunWalkthroughBenchmark(const std::vector<std::string>& args);
} // namespace mesolight

#endif
