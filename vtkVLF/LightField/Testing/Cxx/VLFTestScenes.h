// SPDX-License-Identifier: BSD-3-Clause
// Small scenes with known answers for the light field tests.
#ifndef mesolight_VLFTestScenes_h
#define mesolight_VLFTestScenes_h

#include "AnalyticCases.h"
#include "LightField.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <vector>

namespace mesolight
{
namespace vlftest
{

// The six faces of an axis-aligned box as quads whose fronts face `inward` ? the centre : away.
inline void AddBox(TriangleScene& scene, const glm::vec3& lower, const glm::vec3& upper,
  std::uint32_t material, bool inward)
{
  const glm::vec3 c = 0.5f * (lower + upper);
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int side = 0; side < 2; ++side)
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::vector<glm::vec3> quad(4);
      for (int q = 0; q < 4; ++q)
      {
        glm::vec3 p;
        p[axis] = side ? upper[axis] : lower[axis];
        p[u] = (q == 1 || q == 2) ? upper[u] : lower[u];
        p[v] = (q >= 2) ? upper[v] : lower[v];
        quad[q] = p;
      }
      const glm::vec3 normal = glm::cross(quad[1] - quad[0], quad[2] - quad[0]);
      const glm::vec3 centre = 0.25f * (quad[0] + quad[1] + quad[2] + quad[3]);
      const bool towardCentre = glm::dot(normal, c - centre) > 0.0f;
      if (towardCentre != inward)
      {
        std::swap(quad[1], quad[3]);
      }
      scene.AddPolygon(quad, material);
    }
  }
}

// A closed cube (12 triangles, normals inward): uniform emission and albedo everywhere.
inline TriangleScene MakeFurnaceCube(float albedo, float emission)
{
  TriangleScene scene;
  SceneMaterial m;
  m.Name = "furnace";
  m.Diffuse = glm::vec3(albedo);
  m.Emission = glm::vec3(emission);
  AddBox(scene, glm::vec3(-1.0f), glm::vec3(1.0f), scene.AddMaterial(m), true);
  return scene;
}

// A 2 x 2 floor under a 0.4 wide emitter at height 1 and a white box standing on the floor (the
// contact-texel and adaptive-texel tests).
inline TriangleScene MakeFloorWithBox(const glm::vec3& lower, const glm::vec3& upper)
{
  TriangleScene scene = vlf::MakeEmitterOverFloor(0.4f, 1.0f, 2.0f, 0.5f, 10.0f);
  SceneMaterial white;
  white.Name = "box";
  white.Diffuse = glm::vec3(0.5f);
  AddBox(scene, lower, upper, scene.AddMaterial(white), false);
  return scene;
}

using vlf::CornerFormFactor;
using vlf::MakeEmitterOverFloor;
using vlf::SquareFormFactor;

} // namespace vlftest
} // namespace mesolight

#endif
