// SPDX-License-Identifier: BSD-3-Clause
// What the ReliefShading tests (TestReliefShading.cxx, TestReliefShadingWalls.cxx) share: the unit
// square they shade on, uniform light from the room, and the path-traced inter-reflection inside a
// relief that the grooves and the walled slot are measured against.
#ifndef mesolight_ReliefShadingTestScene_h
#define mesolight_ReliefShadingTestScene_h

#include "ReliefShading.h"

#include "MathConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace mesolight
{
namespace test
{

// One probe of uniform radiance (L00 = 2 sqrt(pi) L) and a grey albedo.
inline ReliefLighting UniformLighting(double radiance, double albedo)
{
  ReliefLighting lighting;
  mesolight::SH9 sh;
  for (int c = 0; c < 3; ++c)
  {
    sh.L[0][c] = 2.0 * std::sqrt(mesolight::Pi<double>) * radiance;
  }
  lighting.Probes = { sh };
  lighting.Albedo = glm::dvec3(albedo);
  return lighting;
}

// A unit square in z = 0 facing +z, relief 0.15 deep.
inline ReliefFrame Square()
{
  ReliefFrame frame;
  frame.DepthScale = 0.15;
  return frame;
}

// Independent reference: the irradiance at a relief point under uniform radiance L from the
// room, with every inter-reflection inside the relief, by Monte-Carlo paths on the exact
// height-field intersector (cosine sampling: each bounce on the albedo-a diffuse relief
// multiplies the path by a; the path ends where it leaves the relief). On a walled relief a path
// that meets a side wall bounces off the wall's plane (RayHit::wall); startWall is the first
// point's wall, if it lies on one.
inline double PathTracedIrradiance(const HeightField& hf, const ReliefFrame& frame,
  glm::dvec3 point, double radiance, double albedo, int paths, unsigned& state,
  glm::dvec2 startWall = glm::dvec2(0.0))
{
  const auto random = [&state]()
  {
    state = state * 1664525u + 1013904223u;
    return (state >> 8) * (1.0 / 16777216.0);
  };
  double sum = 0.0;
  for (int p = 0; p < paths; ++p)
  {
    glm::dvec3 at = point;
    glm::dvec2 wall = startWall; // on a walled relief's side wall: its normal
    double throughput = 1.0;
    for (int bounce = 0; bounce < 64 && throughput > 1e-4; ++bounce)
    {
      const glm::dvec3 n = wall != glm::dvec2(0.0)
        ? mesolight::ReliefWallNormal(frame, wall)
        : mesolight::ReliefNormalAt(hf, frame, at.x, at.y);
      const glm::dvec3 t = std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
      const glm::dvec3 x = glm::normalize(glm::cross(t, n));
      const glm::dvec3 y = glm::cross(n, x);
      const double r = std::sqrt(random()), phi = 2.0 * mesolight::Pi<double> * random();
      const glm::dvec3 w =
        r * std::cos(phi) * x + r * std::sin(phi) * y + std::sqrt(std::max(0.0, 1.0 - r * r)) * n;
      const glm::dvec3 step = frame.ToTexture(w);
      if (w.z > 0.0 && mesolight::Visible(hf, at, step, 1e-6))
      {
        sum += throughput * radiance;
        break;
      }
      const auto hit =
        mesolight::IntersectFirst(hf, at + 1e-6 * step / glm::length(step), step, 10.0);
      if (!hit)
      {
        break; // numerically lost: counts as dark (rare)
      }
      at = glm::dvec3(hit->point.x, hit->point.y, std::max(0.0, hit->point.z));
      wall = hit->wall;
      throughput *= albedo;
    }
  }
  return mesolight::Pi<double> * sum / paths;
}

} // namespace test
} // namespace mesolight

#endif
