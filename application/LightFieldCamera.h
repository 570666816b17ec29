// SPDX-License-Identifier: BSD-3-Clause
// The camera options every light-field command shares (`vlf render` on the CPU and through
// vtkLightFieldActor, `vlf view`): --camera X,Y,Z,FX,FY,FZ and --view-up X,Y,Z in world
// coordinates, and the default view when --camera is not given.
#ifndef mesolight_LightFieldCamera_h
#define mesolight_LightFieldCamera_h

#include <glm/vec3.hpp>

#include <string>

class vtkCamera;

namespace mesolight
{
class CommandLine;
namespace vlf
{
class LightField;
}

/** Declares --camera, --view-up and --view-angle. */
void AddLightFieldCameraOptions(CommandLine& cl);

/**
 * Reads --camera and --view-up for a field. Without --camera: the published Cornell box camera
 * when the field's scene is the Cornell box, else a view of the whole scene along +z. False with
 * a message in error when a value is malformed.
 */
bool ReadLightFieldCamera(const CommandLine& cl, const vlf::LightField& field, glm::vec3& eye,
  glm::vec3& focal, double up[3], std::string& error);

/** Puts the published Cornell box camera (CornellCamera: position, focal point, view up and
 * angle) on a VTK camera, as the benchmarks view the built-in boxes. */
void SetCornellCamera(vtkCamera* camera);

} // namespace mesolight

#endif
