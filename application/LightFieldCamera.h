// SPDX-License-Identifier: BSD-3-Clause
// The camera options every walkthrough command shares (`vlf render` on the CPU and through
// vtkLightFieldActor, `vlf view`, and the path tracer's `trace --scene FILE.obj`):
// --camera X,Y,Z,FX,FY,FZ[,UX,UY,UZ] and --view-up X,Y,Z in world coordinates, --fov (or
// --view-angle) the vertical field of view in degrees, and the default view when --camera is not
// given. One parser, so that a camera string gives the same view in every renderer.
#ifndef mesolight_LightFieldCamera_h
#define mesolight_LightFieldCamera_h

#include <glm/vec3.hpp>

#include <string>
#include <vector>

class vtkCamera;

namespace mesolight
{
class CommandLine;
namespace vlf
{
class LightField;
}

/** Declares --camera, --view-up, --fov and --view-angle. */
void AddLightFieldCameraOptions(CommandLine& cl);

/**
 * Reads --camera and --view-up for a scene of the given world bounds. Without --camera: the
 * published Cornell box camera when the bounds are the Cornell box's, else a view of the whole
 * scene along +z. Values seven to nine of --camera is the view up (then --view-up must not
 * be given too). False with a message in error when a value is malformed, the position equals
 * the focal point, or the view up is parallel to the view direction.
 */
bool ReadCameraOptions(const CommandLine& cl, const glm::vec3& worldLower,
  const glm::vec3& worldUpper, glm::vec3& eye, glm::vec3& focal, double up[3], std::string& error);

/** ReadCameraOptions for a light field's scene. */
bool ReadLightFieldCamera(const CommandLine& cl, const vlf::LightField& field, glm::vec3& eye,
  glm::vec3& focal, double up[3], std::string& error);

/** The vertical field of view in degrees from --fov or --view-angle (default 39.3077, the
 * Cornell camera's); both given and different is an error, as is a value outside [1, 179]. */
bool ReadViewAngle(const CommandLine& cl, double& degrees, std::string& error);

/**
 * Prints a warning on stderr when every pixel of the linear image is black: with the default
 * view of a closed room (along +z from outside it) the camera sees the walls' backs and the
 * image is all black, which is written without a word otherwise. Says how to place the camera.
 */
void WarnIfAllBlack(
  const std::string& command, const std::vector<float>& rgb, const CommandLine& cl);

/** Puts the published Cornell box camera (CornellCamera: position, focal point, view up and
 * angle) on a VTK camera, as the benchmarks view the built-in boxes. */
void SetCornellCamera(vtkCamera* camera);

} // namespace mesolight

#endif
