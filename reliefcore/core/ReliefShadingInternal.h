// SPDX-License-Identifier: BSD-3-Clause
// The pieces ReliefShading's two sources share: ReliefShading.cxx (the relief at a point: its
// shares, the probes, ShadeReliefRay) and ReliefShareMaps.cxx (the same over the grids the relief
// mapper looks up). Private to Mesolight::ReliefCore.
#ifndef mesolight_ReliefShadingInternal_h
#define mesolight_ReliefShadingInternal_h

#include "HeightFieldTracer.h"
#include "ReliefShading.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <optional>
#include <vector>

namespace mesolight
{
namespace relief_internal
{

// Fixed cosine-distributed directions around +z (Hammersley points, Malley's method).
const std::vector<glm::dvec3>& CosineDirections(int count);

// The world direction of cosine direction c around the unit normal n (the frame both the
// radiance-weighted occlusion and the visible share use).
struct NormalFrame
{
  glm::dvec3 X, Y, N;
  explicit NormalFrame(const glm::dvec3& n)
    : N(n)
  {
    const glm::dvec3 t = std::abs(n.z) < 0.9 ? glm::dvec3(0, 0, 1) : glm::dvec3(1, 0, 0);
    this->X = glm::normalize(glm::cross(t, n));
    this->Y = glm::cross(n, this->X);
  }
  glm::dvec3 operator()(const glm::dvec3& c) const { return c.x * X + c.y * Y + c.z * N; }
};

// Whether world direction w from the relief point hit leaves the relief.
bool LeavesRelief(
  const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit, const glm::dvec3& w);

// What a direction from a relief point meets: nothing (it leaves the relief), or the point it
// meets, empty when the march lost it numerically (counted as dark).
struct DirectionHit
{
  bool Leaves = false;
  std::optional<RayHit> Seen;
};

// The point direction w from the relief point `from` (depth clamped to the top) meets, for a
// direction that does not leave the relief: every such direction meets it within the unit
// square's diagonal and the depth range.
std::optional<RayHit> MarchToSeenPoint(
  const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& from, const glm::dvec3& w);

// Direction w from the relief point hit marched twice, as the seen share does without the first
// pass's hits: whether it leaves (LeavesRelief), then what it meets.
DirectionHit MarchDirection(
  const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit, const glm::dvec3& w);

// ReliefVisibleShare, also noting (when `kinds` is given) what each direction k meets into
// kinds[k] and where[2k], [2k + 1] (ReliefDirectionHits). The direction's one march decides
// whether it leaves and stops where it does not (VisibleOrBlocker); a direction below the macro
// plane, occluded without a march, is marched to its point.
double VisibleShareNoting(const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit,
  const glm::dvec3& n, int count, double* abovePlane, std::uint8_t* kinds, float* where);

// The side wall's visible share at the wall point `point` (RayHit::wall `wall`) from the walls'
// pairs over `width` cells along each wall and 4 x levels rows, as mlReliefShare reads it:
// bilinear between cell centres along the wall and between levels down it (level l's centre at
// (l + 1/2) / levels of the wall's foot, the border's depth there), clamped.
double WallShareAt(const HeightField& hf, const std::vector<float>& walls, int width, int levels,
  const glm::dvec2& wall, const glm::dvec3& point);

// Whether wallShares hold the walls' pairs for a visible-share map `width` cells wide.
bool WallSharesFit(const ReliefWallShares& walls, int width);

// ReliefSeenShare around the normal n with met(k, w): what direction k, world w, meets from the
// shaded point (DirectionHit).
template <typename Met>
double SeenShareWith(const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& n,
  int count, const std::vector<float>* shareMap, int mapWidth, int mapHeight,
  ReliefWallShares wallShares, const Met& met)
{
  if (count < 1)
  {
    return 1.0;
  }
  const bool map = shareMap && mapWidth > 0 && mapHeight > 0 &&
    shareMap->size() >= 2 * static_cast<std::size_t>(mapWidth) * mapHeight;
  // The map's V at (u, v): bilinear between cell centres, clamped (the GPU's GL_LINEAR +
  // GL_CLAMP_TO_EDGE fetch of the same values).
  const auto mapped = [&](double u, double v)
  {
    const double x = std::clamp(u * mapWidth - 0.5, 0.0, mapWidth - 1.0);
    const double y = std::clamp(v * mapHeight - 0.5, 0.0, mapHeight - 1.0);
    const int i0 = static_cast<int>(std::floor(x)), j0 = static_cast<int>(std::floor(y));
    const int i1 = std::min(i0 + 1, mapWidth - 1), j1 = std::min(j0 + 1, mapHeight - 1);
    const double fx = x - i0, fy = y - j0;
    const auto at = [&](int i, int j)
    { return static_cast<double>((*shareMap)[2 * (static_cast<std::size_t>(j) * mapWidth + i)]); };
    return (1.0 - fy) * ((1.0 - fx) * at(i0, j0) + fx * at(i1, j0)) +
      fy * ((1.0 - fx) * at(i0, j1) + fx * at(i1, j1));
  };
  const NormalFrame local(n);
  double sum = 0.0;
  int occluded = 0, k = 0;
  for (const glm::dvec3& c : CosineDirections(count))
  {
    const DirectionHit direction = met(k++, local(c));
    if (direction.Leaves)
    {
      continue;
    }
    ++occluded;
    if (!direction.Seen)
    {
      continue; // lost numerically: dark
    }
    const RayHit& seen = *direction.Seen;
    const bool wall = seen.wall.x != 0.0 || seen.wall.y != 0.0;
    if (map && !wall)
    {
      sum += mapped(seen.point.x, seen.point.y);
      continue;
    }
    if (wall && WallSharesFit(wallShares, mapWidth))
    {
      sum +=
        WallShareAt(hf, *wallShares.Values, mapWidth, wallShares.Levels, seen.wall, seen.point);
      continue;
    }
    const glm::dvec3 normal = wall ? ReliefWallNormal(frame, seen.wall)
                                   : ReliefNormalAt(hf, frame, seen.point.x, seen.point.y);
    sum += ReliefVisibleShare(hf, frame, seen.point, normal, count);
  }
  return occluded > 0 ? sum / occluded : 1.0;
}

} // namespace relief_internal
} // namespace mesolight

#endif
