// SPDX-License-Identifier: BSD-3-Clause
// Lamps in a box for the emitter-light tests: a propagated field of a grey box with rectangular
// lamps under its ceiling, and the exact irradiance of such a lamp (a fine midpoint rule).
#ifndef mesolight_EmitterTestFields_h
#define mesolight_EmitterTestFields_h

#include "LightField.h"
#include "Propagation.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <utility>
#include <vector>

namespace mesolight
{
namespace emittertest
{
// A closed grey box [-1, 1]^3 (fronts inward) with lamps facing down just below its ceiling,
// [X0, X1] x [Z0, Z1] each (lamps of equal emission share one material), propagated coarsely.
inline constexpr float LampHeight = 0.999f;
struct Lamp
{
  float X0, X1, Z0, Z1;
  glm::vec3 Emission;
};
inline std::unique_ptr<vlf::LightField> BoxWithLamps(const std::vector<Lamp>& lamps)
{
  TriangleScene scene;
  SceneMaterial grey;
  grey.Diffuse = glm::vec3(0.5f);
  const std::uint32_t g = scene.AddMaterial(grey);
  for (int axis = 0; axis < 3; ++axis) // the box, fronts inward
  {
    for (const float side : { -1.0f, 1.0f })
    {
      const int u = (axis + 1) % 3, v = (axis + 2) % 3;
      std::vector<glm::vec3> quad(4, glm::vec3(0.0f));
      const float su[4] = { -1, 1, 1, -1 }, sv[4] = { -1, -1, 1, 1 };
      for (int q = 0; q < 4; ++q)
      {
        quad[q][axis] = side;
        quad[q][u] = su[q];
        quad[q][v] = sv[q];
      }
      glm::vec3 normal = glm::cross(quad[1] - quad[0], quad[2] - quad[0]);
      if (glm::dot(normal, glm::vec3(0.0f) - quad[0]) < 0.0f)
      {
        std::swap(quad[1], quad[3]);
      }
      scene.AddPolygon(quad, g);
    }
  }
  const float h = LampHeight;
  std::vector<std::pair<glm::vec3, std::uint32_t>> materials;
  for (const Lamp& lamp : lamps)
  {
    std::uint32_t m = 0;
    const auto same = std::find_if(materials.begin(), materials.end(),
      [&lamp](const auto& known) { return known.first == lamp.Emission; });
    if (same != materials.end())
    {
      m = same->second;
    }
    else
    {
      SceneMaterial emitter;
      emitter.Emission = lamp.Emission;
      m = scene.AddMaterial(emitter);
      materials.emplace_back(lamp.Emission, m);
    }
    // Counter-clockwise seen from below: facing down.
    scene.AddPolygon({ { lamp.X0, h, lamp.Z0 }, { lamp.X1, h, lamp.Z0 }, { lamp.X1, h, lamp.Z1 },
                       { lamp.X0, h, lamp.Z1 } },
      m);
  }
  vlf::LightFieldSettings settings;
  settings.Directions = 33;
  settings.RaysPerSide = 8;
  settings.TilesPerSide = 2;
  std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(scene, settings);
  vlf::Propagate(*field, 1);
  return field;
}

// Irradiance at p (normal n) from a one-sided rectangle [x0, x1] x [z0, z1] at height y facing
// down, of radiance 1, by a fine midpoint rule.
inline double RectangleIrradiance(
  const glm::vec3& p, const glm::vec3& n, double x0, double x1, double z0, double z1, double y)
{
  const int steps = 400;
  double sum = 0.0;
  const double du = (x1 - x0) / steps, dv = (z1 - z0) / steps;
  for (int a = 0; a < steps; ++a)
  {
    for (int b = 0; b < steps; ++b)
    {
      const glm::dvec3 d = glm::dvec3(x0 + (a + 0.5) * du, y, z0 + (b + 0.5) * dv) - glm::dvec3(p);
      const double r2 = glm::dot(d, d);
      const glm::dvec3 w = d / std::sqrt(r2);
      sum += std::max(0.0, w.y) * std::max(0.0, glm::dot(w, glm::dvec3(n))) / r2 * du * dv;
    }
  }
  return sum;
}
// Twelve 0.2 x 0.2 lamps of one material on a 4 x 3 grid of pitch 0.5 under the box's ceiling.
inline std::vector<Lamp> TwelveLamps()
{
  std::vector<Lamp> lamps;
  for (int i = 0; i < 4; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      const float x = -0.85f + 0.5f * i, z = -0.6f + 0.5f * j;
      lamps.push_back({ x, x + 0.2f, z, z + 0.2f, glm::vec3(4.0f) });
    }
  }
  return lamps;
}
} // namespace emittertest
} // namespace mesolight

#endif
