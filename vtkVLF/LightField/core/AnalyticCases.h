// SPDX-License-Identifier: BSD-3-Clause
// Scenes with closed-form answers for the light field: a square emitter over a floor, whose
// diffuse radiance is rho Le F(p) with F the point-to-square form factor (Howell's catalogue of
// configuration factors, C-11). Used by the tests and by `mesolight bench vlf`.
#ifndef mesolight_vlf_AnalyticCases_h
#define mesolight_vlf_AnalyticCases_h

#include "MathConstants.h"
#include "TriangleScene.h"

#include <cmath>
#include <cstdint>

namespace mesolight
{
namespace vlf
{

// A square emitter of side `side` facing down at height `height` above the centre of a square
// floor of side `floorSide` (z = 0, facing up) with albedo `albedo`. Emitter: radiance
// `emission`, black.
inline TriangleScene MakeEmitterOverFloor(
  float side, float height, float floorSide, float albedo, float emission)
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
  scene.AddPolygon(
    { { -s, -s, height }, { -s, s, height }, { s, s, height }, { s, -s, height } }, lightId);
  return scene;
}

// Form factor from a differential area to a parallel rectangle of sides a x b whose corner lies
// at distance h straight above it (Howell's catalogue, C-11).
inline double CornerFormFactor(double a, double b, double h)
{
  const double x = a / h, y = b / h;
  return (x / std::sqrt(1.0 + x * x) * std::atan(y / std::sqrt(1.0 + x * x)) +
           y / std::sqrt(1.0 + y * y) * std::atan(x / std::sqrt(1.0 + y * y))) /
    (2.0 * Pi<double>);
}

// Form factor from a differential area at horizontal offset (px, py) under a parallel square
// of side `side` centred at height h: sum of four corner rectangles (signed for offsets
// outside the square's footprint).
inline double SquareFormFactor(double side, double h, double px, double py)
{
  const double s = 0.5 * side;
  auto signedCorner = [&](double a, double b)
  {
    const double sa = a < 0 ? -1.0 : 1.0, sb = b < 0 ? -1.0 : 1.0;
    return sa * sb * CornerFormFactor(std::abs(a), std::abs(b), h);
  };
  return signedCorner(s - px, s - py) + signedCorner(s + px, s - py) +
    signedCorner(s - px, s + py) + signedCorner(s + px, s + py);
}

} // namespace vlf
} // namespace mesolight

#endif
