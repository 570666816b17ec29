// SPDX-License-Identifier: BSD-3-Clause
#include "LightFieldCamera.h"

#include "CommandLine.h"

#include "LightField.h"
#include "PatchComparison.h" // ToWorld
#include "TriangleScene.h"

#include <vtkCamera.h>

#include <glm/geometric.hpp>

namespace mesolight
{

void AddLightFieldCameraOptions(CommandLine& cl)
{
  cl.AddValue("--camera", "X,Y,Z,FX,FY,FZ",
    "camera position and focal point in scene coordinates (default: the Cornell box camera for "
    "the Cornell box, else a view of the whole scene along +z)");
  cl.AddValue("--view-up", "X,Y,Z", "camera up direction", "0,1,0");
  cl.AddValue("--view-angle", "DEG", "vertical field of view", "39.3077");
}

bool ReadLightFieldCamera(const CommandLine& cl, const vlf::LightField& field, glm::vec3& eye,
  glm::vec3& focal, double up[3], std::string& error)
{
  if (!cl.GetDoubleVector("--view-up", 3, up))
  {
    error = "--view-up needs X,Y,Z";
    return false;
  }
  if (cl.Has("--camera"))
  {
    double c[6];
    if (!cl.GetDoubleVector("--camera", 6, c))
    {
      error = "--camera needs X,Y,Z,FX,FY,FZ";
      return false;
    }
    eye = glm::vec3(c[0], c[1], c[2]);
    focal = glm::vec3(c[3], c[4], c[5]);
    return true;
  }
  glm::vec3 lower, upper;
  SceneBounds(field.Scene(), lower, upper);
  const glm::vec3 worldLower = vlf::ToWorld(field, lower), worldUpper = vlf::ToWorld(field, upper);
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
    const glm::vec3 centre = 0.5f * (worldLower + worldUpper);
    const float radius = 0.5f * glm::length(worldUpper - worldLower);
    focal = centre;
    eye = centre - glm::vec3(0.0f, 0.0f, 2.2f * radius);
  }
  return true;
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

} // namespace mesolight
