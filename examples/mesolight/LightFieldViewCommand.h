// `mesolight vlf view|render --mode|bench`: the light field walkthrough through
// vtkLightFieldActor (Wither 2005 §2.4.2.2). docs/walkthrough.md has examples and measured
// figures. `mesolight vlf render` without --mode stays the CPU reference in VlfCommand.cxx.
#ifndef mesolight_LightFieldViewCommand_h
#define mesolight_LightFieldViewCommand_h

#include <string>
#include <vector>

namespace mesolight
{

/** True when `mesolight vlf ARGS` is handled here: view, bench, and render with --mode. */
bool IsLightFieldViewCommand(const std::vector<std::string>& args);

/**
 * mesolight vlf view FIELD [--mode M] [--size WxH] [--camera ...] [--exposure X] [--frames N]
 * mesolight vlf render FIELD --mode geometry|raytrace|progressive|coherent --out F.png [...]
 * mesolight vlf bench [FIELD] [--size 800x800] [--frames N] [--csv F] [--plot F.png]
 * `args` excludes the word "vlf". Returns 0 on success, 1 on failure, 2 on bad arguments.
 */
int RunLightFieldViewCommand(const std::vector<std::string>& args);

} // namespace mesolight

#endif
