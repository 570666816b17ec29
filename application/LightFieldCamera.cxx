// SPDX-License-Identifier: BSD-3-Clause
#include "LightFieldCamera.h"

#include "CommandLine.h"

#include "LightField.h"
#include "PatchComparison.h" // ToWorld
#include "TriangleScene.h"

#include <vtkCamera.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <sstream>

namespace mesolight
{

void AddLightFieldCameraOptions(CommandLine& cl)
{
  cl.AddValue("--camera", "X,Y,Z,FX,FY,FZ[,UX,UY,UZ]",
    "camera position and focal point (and view up) in scene coordinates (default: the Cornell "
    "box camera for the Cornell box, else a view of the whole scene along +z)");
  cl.AddValue("--view-up", "X,Y,Z", "camera up direction", "0,1,0");
  cl.AddValue("--fov", "DEG", "vertical field of view (the same as --view-angle)", "39.3077");
  cl.AddValue("--view-angle", "DEG", "vertical field of view", "39.3077");
}

bool ReadViewAngle(const CommandLine& cl, double& degrees, std::string& error)
{
  double fov = 39.3077, angle = 39.3077;
  if (!cl.GetDouble("--fov", 1.0, 179.0, fov, error) ||
    !cl.GetDouble("--view-angle", 1.0, 179.0, angle, error))
  {
    return false;
  }
  if (cl.Has("--fov") && cl.Has("--view-angle") && fov != angle)
  {
    error = "--fov and --view-angle give two different fields of view: give one";
    return false;
  }
  degrees = cl.Has("--fov") ? fov : angle;
  return true;
}

bool ReadCameraOptions(const CommandLine& cl, const glm::vec3& worldLower,
  const glm::vec3& worldUpper, glm::vec3& eye, glm::vec3& focal, double up[3], std::string& error)
{
  if (!cl.GetDoubleVector("--view-up", 3, up))
  {
    error = "--view-up needs X,Y,Z (three finite numbers), not '" + cl.Get("--view-up") + "'";
    return false;
  }
  if (cl.Has("--camera"))
  {
    double c[9];
    const bool withUp = cl.GetDoubleVector("--camera", 9, c);
    if (!withUp && !cl.GetDoubleVector("--camera", 6, c))
    {
      error = "--camera needs X,Y,Z,FX,FY,FZ or X,Y,Z,FX,FY,FZ,UX,UY,UZ (finite numbers), not '" +
        cl.Get("--camera") + "'";
      return false;
    }
    if (withUp)
    {
      if (cl.Has("--view-up"))
      {
        error = "--camera with a view up (nine values) and --view-up: give the view up once";
        return false;
      }
      up[0] = c[6];
      up[1] = c[7];
      up[2] = c[8];
    }
    eye = glm::vec3(c[0], c[1], c[2]);
    focal = glm::vec3(c[3], c[4], c[5]);
  }
  else
  {
    const TriangleScene cornell = MakeCornellBox();
    glm::vec3 cornellLower, cornellUpper;
    SceneBounds(cornell, cornellLower, cornellUpper);
    if (glm::length(cornellLower - worldLower) + glm::length(cornellUpper - worldUpper) < 1.0f)
    {
      const CornellCamera camera;
      eye = camera.Position;
      focal = camera.FocalPoint;
    }
    else
    {
      // From outside the bounds along +z, or along +y when the view up is mostly z (a scene
      // with z up, --view-up 0,0,1: looking along it was refused as parallel).
      const glm::vec3 centre = 0.5f * (worldLower + worldUpper);
      const float radius = 0.5f * glm::length(worldUpper - worldLower);
      const bool zUp = std::abs(up[2]) > std::max(std::abs(up[0]), std::abs(up[1]));
      focal = centre;
      eye = centre - 2.2f * radius * (zUp ? glm::vec3(0, 1, 0) : glm::vec3(0, 0, 1));
    }
  }
  const glm::vec3 forward = focal - eye;
  const glm::vec3 upVector(up[0], up[1], up[2]);
  if (!(glm::length(forward) > 0.0f) || !(glm::length(upVector) > 0.0f) ||
    !(glm::length(glm::cross(glm::normalize(forward), glm::normalize(upVector))) > 1e-6f))
  {
    error = "the camera needs distinct position and focal point and a view-up direction not "
            "parallel to the view direction";
    return false;
  }
  return true;
}

bool ReadLightFieldCamera(const CommandLine& cl, const vlf::LightField& field, glm::vec3& eye,
  glm::vec3& focal, double up[3], std::string& error)
{
  glm::vec3 lower, upper;
  SceneBounds(field.Scene(), lower, upper);
  return ReadCameraOptions(
    cl, vlf::ToWorld(field, lower), vlf::ToWorld(field, upper), eye, focal, up, error);
}

//------------------------------------------------------------------------------
void SetCornellCamera(vtkCamera* camera)
{
  const CornellCamera c;
  camera->SetPosition(c.Position.x, c.Position.y, c.Position.z);
  camera->SetFocalPoint(c.FocalPoint.x, c.FocalPoint.y, c.FocalPoint.z);
  camera->SetViewUp(c.ViewUp.x, c.ViewUp.y, c.ViewUp.z);
  camera->SetViewAngle(c.ViewAngleDegrees);
}

void WarnIfAllBlack(
  const std::string& command, const std::vector<float>& rgb, const CommandLine& cl)
{
  if (rgb.empty() || std::any_of(rgb.begin(), rgb.end(), [](float v) { return v > 0.0f; }))
  {
    return;
  }
  std::cerr << command << ": warning: every pixel is black. "
            << (cl.Has("--camera")
                   ? "The camera may face away from the lit scene"
                   : "The default camera looks from outside the scene's bounds along +z (along "
                     "+y with --view-up 0,0,1): in a closed room it sees the walls' backs, and a "
                     "scene with z up is seen from below (give --view-up 0,0,1)")
            << "; place it with --camera EYE_X,EYE_Y,EYE_Z,TARGET_X,TARGET_Y,TARGET_Z[,UP_X,UP_Y,"
               "UP_Z].\n";
}

} // namespace mesolight
