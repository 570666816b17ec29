// SPDX-License-Identifier: BSD-3-Clause
// `mesolight vlf view` and `mesolight vlf render --mode`: the light
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
} // namespace mesolight

#endif
