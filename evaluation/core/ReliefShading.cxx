// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefShading.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace mesolight
{

double ReliefFrame::WorldDepth() const
{
  return this->DepthScale * glm::length(this->AxisU);
}

glm::dvec3 ReliefFrame::Point(double u, double v, double d) const
{
  return this->Origin + u * this->AxisU + v * this->AxisV - d * this->WorldDepth() * this->Normal;
}

glm::dvec3 ReliefFrame::ToTexture(const glm::dvec3& world) const
{
  const glm::dmat3 m(this->AxisU, this->AxisV, -this->WorldDepth() * this->Normal);
  return glm::inverse(m) * world;
}

glm::dvec3 ReliefNormalAt(const HeightField& hf, const ReliefFrame& frame, double u, double v)
{
  const glm::dvec2 g = hf.GradientAt(u, v);
  const double w = frame.WorldDepth();
  const glm::dvec3 du = frame.AxisU - w * g.x * frame.Normal;
  const glm::dvec3 dv = frame.AxisV - w * g.y * frame.Normal;
  glm::dvec3 n = glm::cross(du, dv);
  const double length = glm::length(n);
  if (!(length > 0.0))
  {
    return frame.Normal;
  }
  n /= length;
  return glm::dot(n, frame.Normal) < 0.0 ? -n : n;
}

glm::dvec3 ProbeIrradiance(const ReliefLighting& lighting, double u, double v, const glm::dvec3& n)
{
  const int pu = std::max(1, lighting.ProbesU), pv = std::max(1, lighting.ProbesV);
  if (lighting.Probes.size() != static_cast<std::size_t>(pu) * pv)
  {
    return glm::dvec3(0.0);
  }
  // Continuous probe coordinates (probe centres at integers), clamped to the grid.
  const double x = std::clamp(u * pu - 0.5, 0.0, pu - 1.0);
  const double y = std::clamp(v * pv - 0.5, 0.0, pv - 1.0);
  const int a0 = static_cast<int>(std::floor(x)), b0 = static_cast<int>(std::floor(y));
  const int a1 = std::min(a0 + 1, pu - 1), b1 = std::min(b0 + 1, pv - 1);
  const double fx = x - a0, fy = y - b0;
  SH9 sh;
  const auto add = [&](int a, int b, double weight)
  {
    const SH9& p = lighting.Probes[static_cast<std::size_t>(b) * pu + a];
    for (int k = 0; k < 9; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        sh.L[k][c] += weight * p.L[k][c];
      }
    }
  };
  add(a0, b0, (1.0 - fx) * (1.0 - fy));
  add(a1, b0, fx * (1.0 - fy));
  add(a0, b1, (1.0 - fx) * fy);
  add(a1, b1, fx * fy);
  const double normal[3] = { n.x, n.y, n.z };
  double e[3];
  IrradianceSH9(sh, normal, e);
  return glm::dvec3(std::max(0.0, e[0]), std::max(0.0, e[1]), std::max(0.0, e[2]));
}

std::optional<ReliefShade> ShadeReliefRay(const HeightField& hf, const ReliefFrame& frame,
  const ReliefLighting& lighting, const glm::dvec3& origin, const glm::dvec3& dir,
  ReliefNormal normal)
{
  const double facing = glm::dot(frame.Normal, dir);
  if (!(facing < 0.0))
  {
    return std::nullopt; // parallel to the plane or seeing its back
  }
  // Where the ray enters the relief's slab: the macro plane (d = 0).
  const double t0 = glm::dot(frame.Normal, frame.Origin - origin) / facing;
  if (!(t0 >= 0.0))
  {
    return std::nullopt;
  }
  const glm::dvec3 entry = origin + t0 * dir;
  const glm::dvec3 entryTexture = frame.ToTexture(entry - frame.Origin);
  const glm::dvec3 start(entryTexture.x, entryTexture.y, 0.0);
  const glm::dvec3 step = frame.ToTexture(dir);
  if (!(step.z > 0.0))
  {
    return std::nullopt;
  }
  // Down to d = 1 and a little beyond: a depth map reaching 1 is met there.
  const std::optional<RayHit> hit = IntersectFirst(hf, start, step, 1.0001 / step.z);
  if (!hit)
  {
    return std::nullopt;
  }
  ReliefShade shade;
  shade.Texture = hit->point;
  const double u = hit->point.x, v = hit->point.y, d = std::max(0.0, hit->point.z);
  shade.Point = frame.Point(u, v, d);
  shade.Normal = normal == ReliefNormal::Perturbed ? ReliefNormalAt(hf, frame, u, v) : frame.Normal;
  shade.Indirect = ProbeIrradiance(lighting, u, v, shade.Normal);
  const double w = frame.WorldDepth();
  for (const ReliefEmitterSample& e : lighting.Emitters)
  {
    const glm::dvec3 toLight = e.Position - shade.Point;
    const double r2 = glm::dot(toLight, toLight);
    if (!(r2 > 0.0))
    {
      continue;
    }
    const glm::dvec3 l = toLight / std::sqrt(r2);
    const double cosine = glm::dot(shade.Normal, l);
    const double cosineEmitter = -glm::dot(e.Normal, l);
    const double rise = glm::dot(frame.Normal, l); // the light must be above the macro plane
    if (!(cosine > 0.0 && cosineEmitter > 0.0 && rise > 0.0))
    {
      continue;
    }
    // The relief's own shadow: the march toward the light must leave the top of the height field.
    if (normal == ReliefNormal::Perturbed &&
      !Visible(hf, glm::dvec3(u, v, d), frame.ToTexture(l), 1e-6))
    {
      continue;
    }
    // The rest of the scene, from where the ray to the light leaves the relief's slab.
    if (lighting.SceneVisible &&
      !lighting.SceneVisible(shade.Point + (d * w / rise) * l, e.Position))
    {
      continue;
    }
    shade.Direct += e.RadianceArea * (cosine * cosineEmitter / r2);
  }
  return shade;
}

} // namespace mesolight
