// SPDX-License-Identifier: BSD-3-Clause
// PinholeCamera: a perspective camera as VTK describes one (position, focal point, view up,
// vertical view angle), generating primary rays for image pixels in VTK row order (row 0 at
// the bottom), so traced images line up with what a vtkRenderer shows.
#ifndef mesolight_PinholeCamera_h
#define mesolight_PinholeCamera_h

#include "EmbreeScene.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>
#include <glm/vec3.hpp>

#include <cmath>

namespace mesolight
{

struct PinholeCamera
{
  glm::vec3 Position{ 0.0f, 0.0f, 1.0f };
  glm::vec3 FocalPoint{ 0.0f };
  glm::vec3 ViewUp{ 0.0f, 1.0f, 0.0f };
  float ViewAngleDegrees = 30.0f; // vertical, as vtkCamera::GetViewAngle

  PinholeCamera() = default;
  explicit PinholeCamera(const CornellCamera& cornell)
    : Position(cornell.Position)
    , FocalPoint(cornell.FocalPoint)
    , ViewUp(cornell.ViewUp)
    , ViewAngleDegrees(cornell.ViewAngleDegrees)
  {
  }

  // True when the camera defines a frame (distinct position and focal point, view up not
  // parallel to the view direction, angle in (0, 180)).
  bool Valid() const
  {
    const glm::vec3 forward = this->FocalPoint - this->Position;
    const float length = glm::length(forward);
    if (!(length > 0.0f) || !(this->ViewAngleDegrees > 0.0f && this->ViewAngleDegrees < 180.0f))
    {
      return false;
    }
    const glm::vec3 side = glm::cross(forward / length, this->ViewUp);
    return glm::length(side) > 1e-6f * glm::length(this->ViewUp);
  }

  // Unit ray through image point (x, y) in pixel units: pixel (i, j) covers [i, i+1) x [j, j+1),
  // its centre is (i + 0.5, j + 0.5); y grows upward.
  SceneRay Ray(float x, float y, int width, int height) const
  {
    const glm::vec3 forward = glm::normalize(this->FocalPoint - this->Position);
    const glm::vec3 right = glm::normalize(glm::cross(forward, this->ViewUp));
    const glm::vec3 up = glm::cross(right, forward);
    const float halfHeight = std::tan(glm::radians(0.5f * this->ViewAngleDegrees));
    const float halfWidth = halfHeight * static_cast<float>(width) / static_cast<float>(height);
    const float sx = (2.0f * x / static_cast<float>(width) - 1.0f) * halfWidth;
    const float sy = (2.0f * y / static_cast<float>(height) - 1.0f) * halfHeight;
    SceneRay ray;
    ray.Origin = this->Position;
    ray.Direction = glm::normalize(forward + sx * right + sy * up);
    return ray;
  }
};

} // namespace mesolight

#endif
