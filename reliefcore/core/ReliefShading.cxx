// SPDX-License-Identifier: BSD-3-Clause
// The relief at a point (ReliefShading.h): its frame and normals, its shares, the probes and
// ShadeReliefRay; the maps over its grid are in ReliefShareMaps.cxx.
#include "ReliefShading.h"
#include "ReliefShadingInternal.h"

#include "Luminance.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>

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

glm::dvec3 ReliefWallNormal(const ReliefFrame& frame, const glm::dvec2& wall)
{
  // The wall holds the macro normal and the border's direction (AxisV along u = 0 or 1, AxisU
  // along v = 0 or 1); its normal points back into the rectangle.
  const glm::dvec3 along = wall.x != 0.0 ? frame.AxisV : frame.AxisU;
  glm::dvec3 n = glm::cross(along, frame.Normal);
  const double length = glm::length(n);
  if (!(length > 0.0))
  {
    return frame.Normal;
  }
  n /= length;
  const glm::dvec3 inward = wall.x * frame.AxisU + wall.y * frame.AxisV;
  return glm::dot(n, inward) < 0.0 ? -n : n;
}

namespace
{
// The probes' SH9 at (u, v), bilinear; false without probes.
bool ProbeAt(const ReliefLighting& lighting, double u, double v, SH9& sh)
{
  const int pu = std::max(1, lighting.ProbesU), pv = std::max(1, lighting.ProbesV);
  if (lighting.Probes.size() != static_cast<std::size_t>(pu) * pv)
  {
    return false;
  }
  // Continuous probe coordinates (probe centres at integers), clamped to the grid.
  const double x = std::clamp(u * pu - 0.5, 0.0, pu - 1.0);
  const double y = std::clamp(v * pv - 0.5, 0.0, pv - 1.0);
  const int a0 = static_cast<int>(std::floor(x)), b0 = static_cast<int>(std::floor(y));
  const int a1 = std::min(a0 + 1, pu - 1), b1 = std::min(b0 + 1, pv - 1);
  const double fx = x - a0, fy = y - b0;
  sh = SH9();
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
  return true;
}
} // namespace

namespace relief_internal
{
// Fixed cosine-distributed directions around +z (Hammersley points, Malley's method).
const std::vector<glm::dvec3>& CosineDirections(int count)
{
  thread_local std::vector<glm::dvec3> directions;
  if (static_cast<int>(directions.size()) != count)
  {
    directions.clear();
    for (int i = 0; i < count; ++i)
    {
      unsigned bits = static_cast<unsigned>(i);
      bits = (bits << 16u) | (bits >> 16u);
      bits = ((bits & 0x55555555u) << 1u) | ((bits & 0xAAAAAAAAu) >> 1u);
      bits = ((bits & 0x33333333u) << 2u) | ((bits & 0xCCCCCCCCu) >> 2u);
      bits = ((bits & 0x0F0F0F0Fu) << 4u) | ((bits & 0xF0F0F0F0u) >> 4u);
      bits = ((bits & 0x00FF00FFu) << 8u) | ((bits & 0xFF00FF00u) >> 8u);
      const double r = std::sqrt((i + 0.5) / count);
      const double phi = 2.0 * 3.14159265358979323846 * (bits * 2.3283064365386963e-10);
      directions.emplace_back(
        r * std::cos(phi), r * std::sin(phi), std::sqrt(std::max(0.0, 1.0 - r * r)));
    }
  }
  return directions;
}

// Whether world direction w from the relief point hit leaves the relief.
bool LeavesRelief(
  const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit, const glm::dvec3& w)
{
  return glm::dot(w, frame.Normal) > 0.0 &&
    Visible(hf, glm::dvec3(hit.x, hit.y, std::max(0.0, hit.z)), frame.ToTexture(w), 1e-6);
}

// The point direction w from the relief point `from` (depth clamped to the top) meets, for a
// direction that does not leave the relief: every such direction meets it within the unit
// square's diagonal and the depth range.
std::optional<RayHit> MarchToSeenPoint(
  const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& from, const glm::dvec3& w)
{
  const glm::dvec3 step = frame.ToTexture(w);
  const double length = glm::length(step);
  return IntersectFirst(hf, from + (1e-6 / length) * step, step, 4.0 / length);
}

// Direction w from the relief point hit marched twice, as the seen share does without the first
// pass's hits: whether it leaves (LeavesRelief), then what it meets.
DirectionHit MarchDirection(
  const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit, const glm::dvec3& w)
{
  if (LeavesRelief(hf, frame, hit, w))
  {
    return { true, std::nullopt };
  }
  return { false, MarchToSeenPoint(hf, frame, glm::dvec3(hit.x, hit.y, std::max(0.0, hit.z)), w) };
}

// The side wall's visible share at the wall point `point` (RayHit::wall `wall`) from the walls'
// pairs over `width` cells along each wall and 4 x levels rows, as mlReliefShare reads it:
// bilinear between cell centres along the wall and between levels down it (level l's centre at
// (l + 1/2) / levels of the wall's foot, the border's depth there), clamped.
double WallShareAt(const HeightField& hf, const std::vector<float>& walls, int width, int levels,
  const glm::dvec2& wall, const glm::dvec3& point)
{
  const int block = wall.x > 0.0 ? 0 : wall.x < 0.0 ? 1 : wall.y > 0.0 ? 2 : 3;
  const double along = wall.x != 0.0 ? point.y : point.x;
  const double foot = hf.DepthAt(std::clamp(point.x, 0.0, 1.0), std::clamp(point.y, 0.0, 1.0));
  const double down = foot > 0.0 ? std::clamp(point.z / foot, 0.0, 1.0) : 0.0;
  const double x = std::clamp(along * width - 0.5, 0.0, width - 1.0);
  const double y = std::clamp(down * levels, 0.5, levels - 0.5) - 0.5;
  const int i0 = static_cast<int>(std::floor(x)), l0 = static_cast<int>(std::floor(y));
  const int i1 = std::min(i0 + 1, width - 1), l1 = std::min(l0 + 1, levels - 1);
  const double fx = x - i0, fy = y - l0;
  const auto at = [&](int i, int l)
  {
    const std::size_t row = static_cast<std::size_t>(block) * levels + l;
    return static_cast<double>(walls[2 * (row * width + i)]);
  };
  return (1.0 - fy) * ((1.0 - fx) * at(i0, l0) + fx * at(i1, l0)) +
    fy * ((1.0 - fx) * at(i0, l1) + fx * at(i1, l1));
}

bool WallSharesFit(const ReliefWallShares& walls, int width)
{
  return walls.Values && walls.Levels > 0 && width > 0 &&
    walls.Values->size() == 2 * static_cast<std::size_t>(width) * 4 * walls.Levels;
}

} // namespace relief_internal

//------------------------------------------------------------------------------
double EmitterSampleGeometry(const ReliefEmitterSample& e, const glm::dvec3& point,
  const glm::dvec3& normal, glm::dvec3& l, double& r2)
{
  const glm::dvec3 toSample = e.Position - point;
  const double d2 = glm::dot(toSample, toSample);
  if (!(d2 > 0.0))
  {
    return 0.0;
  }
  r2 = d2;
  l = toSample / std::sqrt(d2);
  const double cosine = glm::dot(normal, l);
  const double cosineEmitter = -glm::dot(e.Normal, l);
  // Both must be positive: their product alone is also positive where the point faces away
  // from a sample that faces away from it.
  return cosine > 0.0 && cosineEmitter > 0.0 ? cosine * cosineEmitter / d2 : 0.0;
}

using namespace relief_internal;

double ReliefVisibleShare(const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit,
  const glm::dvec3& n, int count, double* abovePlane)
{
  return VisibleShareNoting(hf, frame, hit, n, count, abovePlane, nullptr, nullptr);
}

double ReliefSeenShare(const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit,
  const glm::dvec3& n, int count, const std::vector<float>* shareMap, int mapWidth, int mapHeight,
  ReliefWallShares wallShares)
{
  return SeenShareWith(hf, frame, n, count, shareMap, mapWidth, mapHeight, wallShares,
    [&](int, const glm::dvec3& w) { return MarchDirection(hf, frame, hit, w); });
}

glm::dvec3 ReliefInterReflected(ReliefInterReflection model, double visibleShare, double seenShare,
  const glm::dvec3& albedo, const glm::dvec3& flatIrradiance)
{
  const double occluded = 1.0 - visibleShare;
  const glm::dvec3 a = glm::clamp(albedo, 0.0, 1.0);
  if (model == ReliefInterReflection::None || !(occluded > 0.0))
  {
    return glm::dvec3(0.0);
  }
  glm::dvec3 seen = flatIrradiance;
  if (model == ReliefInterReflection::MultiBounce)
  {
    // Bounded away from 0: a white relief that hides the whole hemisphere (Vs = 0) stays 0.
    const double vs = std::clamp(seenShare, 0.0, 1.0);
    seen *= vs / glm::max(1.0 - a * (1.0 - vs), glm::dvec3(1e-9));
  }
  return occluded * a * seen;
}

glm::dvec3 ReliefInterReflected(ReliefInterReflection model, double visibleShare,
  const glm::dvec3& albedo, const glm::dvec3& flatIrradiance)
{
  return ReliefInterReflected(model, visibleShare, visibleShare, albedo, flatIrradiance);
}

glm::dvec3 ProbeRadiance(const ReliefLighting& lighting, double u, double v, const glm::dvec3& w)
{
  SH9 sh;
  if (!ProbeAt(lighting, u, v, sh))
  {
    return glm::dvec3(0.0);
  }
  const double d[3] = { w.x, w.y, w.z };
  double y[9];
  EvaluateSHBasis(d, y);
  glm::dvec3 radiance(0.0);
  for (int k = 0; k < 9; ++k)
  {
    radiance += y[k] * glm::dvec3(sh.L[k][0], sh.L[k][1], sh.L[k][2]);
  }
  return glm::max(radiance, glm::dvec3(0.0));
}

glm::dvec3 ProbeIrradiance(const ReliefLighting& lighting, double u, double v, const glm::dvec3& n)
{
  SH9 sh;
  if (!ProbeAt(lighting, u, v, sh))
  {
    return glm::dvec3(0.0);
  }
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
  if (normal == ReliefNormal::Perturbed && (hit->wall.x != 0.0 || hit->wall.y != 0.0))
  {
    shade.Normal = ReliefWallNormal(frame, hit->wall); // the side wall of a walled relief
  }
  shade.Indirect = ProbeIrradiance(lighting, u, v, shade.Normal);
  double occludedShare = 0.0;
  if (normal == ReliefNormal::Perturbed && lighting.OcclusionDirections > 0)
  {
    // The share of the SH radiance (luminance, cosine-distributed) that reaches the hit past the
    // relief: a direction below the macro plane or blocked by the height field brings nothing.
    const NormalFrame local(shade.Normal);
    double all = 0.0, visible = 0.0;
    int seen = 0; // directions that leave the relief (unweighted: the cosine-weighted share)
    for (const glm::dvec3& c : CosineDirections(lighting.OcclusionDirections))
    {
      const glm::dvec3 w = local(c);
      const glm::dvec3 l = ProbeRadiance(lighting, u, v, w);
      const double weight = Luminance(l.x, l.y, l.z) + 1e-12;
      all += weight;
      if (LeavesRelief(hf, frame, hit->point, w))
      {
        visible += weight;
        ++seen;
      }
    }
    shade.IndirectVisible = all > 0.0 ? visible / all : 1.0;
    shade.Indirect *= shade.IndirectVisible;
    occludedShare = 1.0 - static_cast<double>(seen) / lighting.OcclusionDirections;
  }
  const bool bounce = occludedShare > 0.0 &&
    lighting.InterReflection != ReliefInterReflection::None &&
    (lighting.Albedo.x > 0.0 || lighting.Albedo.y > 0.0 || lighting.Albedo.z > 0.0);
  glm::dvec3 flatDirect(0.0); // the emitters' irradiance on the flat wall, for the bounce
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
    if (!(cosineEmitter > 0.0 && rise > 0.0))
    {
      continue;
    }
    // The relief's own shadow: the march toward the light must leave the top of the height field.
    const bool lit = cosine > 0.0 &&
      (normal != ReliefNormal::Perturbed ||
        Visible(hf, glm::dvec3(u, v, d), frame.ToTexture(l), 1e-6));
    if (!lit && !bounce)
    {
      continue;
    }
    // The rest of the scene, from where the ray to the light leaves the relief's slab.
    if (lighting.SceneVisible &&
      !lighting.SceneVisible(shade.Point + (d * w / rise) * l, e.Position))
    {
      continue;
    }
    if (lit)
    {
      shade.Direct += e.RadianceArea * (cosine * cosineEmitter / r2);
    }
    flatDirect += e.RadianceArea * (rise * cosineEmitter / r2);
  }
  if (bounce)
  {
    // What an occluded direction sees: the relief, lit about as the flat wall is (see the header).
    const double seenShare = lighting.InterReflection == ReliefInterReflection::MultiBounce
      ? ReliefSeenShare(hf, frame, hit->point, shade.Normal, lighting.OcclusionDirections)
      : 1.0;
    shade.InterReflected = ReliefInterReflected(lighting.InterReflection, 1.0 - occludedShare,
      seenShare, lighting.Albedo, ProbeIrradiance(lighting, u, v, frame.Normal) + flatDirect);
    shade.Indirect += shade.InterReflected;
  }
  return shade;
}

} // namespace mesolight
