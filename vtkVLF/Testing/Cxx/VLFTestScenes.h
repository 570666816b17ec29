// Small scenes with known answers for the light field tests.
#ifndef mesolight_VLFTestScenes_h
#define mesolight_VLFTestScenes_h

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

// A square emitter of side `side` facing down at height `height` above the centre of a square
// floor of side `floorSide` (z = 0, facing up) with albedo `albedo`. Emitter: radiance
// `emission`, black.
inline TriangleScene MakeEmitterOverFloor(float side, float height, float floorSide, float albedo, float emission)
{
  TriangleScene scene;
  SceneMaterial floor;
  floor.Name = "floor";
  floor.Diffuse = glm::vec3(albedo);
  SceneMaterial light;
  light.Name = "light";
  light.Diffuse = glm::vec3(0.0f);
  light.Emission = glm::vec3(emission);
  const std::uint32_t floorId = scene.AddMaterial(floor);
  const std::uint32_t lightId = scene.AddMaterial(light);
  const float f = 0.5f * floorSide, s = 0.5f * side;
  scene.AddPolygon({ { -f, -f, 0.0f }, { f, -f, 0.0f }, { f, f, 0.0f }, { -f, f, 0.0f } }, floorId);
  scene.AddPolygon({ { -s, -s, height }, { -s, s, height }, { s, s, height }, { s, -s, height } }, lightId);
  return scene;
}

// Form factor from a differential area to a parallel rectangle of sides a x b whose corner lies
// at distance h straight above it (Howell's catalogue, C-11).
inline double CornerFormFactor(double a, double b, double h)
{
  const double x = a / h, y = b / h;
  const double pi = 3.14159265358979323846;
  return (x / std::sqrt(1.0 + x * x) * std::atan(y / std::sqrt(1.0 + x * x)) +
           y / std::sqrt(1.0 + y * y) * std::atan(x / std::sqrt(1.0 + y * y))) /
    (2.0 * pi);
}

// Form factor from a differential area at horizontal offset (px, py) under a parallel square
// of side `side` centred at height h: sum of four corner rectangles (signed for offsets
// outside the square's footprint).
inline double SquareFormFactor(double side, double h, double px, double py)
{
  const double s = 0.5 * side;
  auto signedCorner = [&](double a, double b) {
    const double sa = a < 0 ? -1.0 : 1.0, sb = b < 0 ? -1.0 : 1.0;
    return sa * sb * CornerFormFactor(std::abs(a), std::abs(b), h);
  };
  return signedCorner(s - px, s - py) + signedCorner(s + px, s - py) + signedCorner(s - px, s + py) +
    signedCorner(s + px, s + py);
}

} // namespace vlftest
} // namespace mesolight

#endif
