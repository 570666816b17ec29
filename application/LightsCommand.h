// SPDX-License-Identifier: BSD-3-Clause
// `mesolight lights` (environment map -> median cut lights as CSV) and `mesolight bench lights`
// (accuracy of median cut and SH9 irradiance against exact integration, and timing).
// Conventions: filters/Lighting/core/EnvironmentMaps.h and docs/environment-maps.md.
#ifndef mesolight_LightsCommand_h
#define mesolight_LightsCommand_h

#include <string>
#include <vector>

namespace mesolight
{

/**
 * mesolight lights ENV_IMAGE --out lights.csv [--count N] [--plain] [--resolution H]
 * ENV_IMAGE is a lat-long image file (EXR, HDR, ...) or procedural:sky / procedural:sun.
 * Writes a CSV with the header u,v,x,y,z,r,g,b. Returns 0 on success, 1 on failure, 2 on
 * bad arguments. `args` excludes the word "lights".
 */
int RunLightsCommand(const std::vector<std::string>& args);

/**
 * mesolight bench lights [--counts 16,32,...] [--normals N] [--csv FILE] [--resolution H]
 * [--no-blender] [--timing-repeats N]. `args` excludes the words "bench lights".
 */
int RunLightsBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
