// SPDX-License-Identifier: BSD-3-Clause
// ReliefShading.h's maps over the texture's grid (the visible-share, seen-share, emitter-shadow
// and side-wall maps the relief mapper looks up), on the same point shading as ReliefShading.cxx.
#include "ReliefShading.h"
#include "ReliefShadingInternal.h"

#include "Luminance.h"
#include "ParallelFor.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

namespace mesolight
{
using namespace relief_internal;

namespace
{
// Calls cell(i, j, u, v) for every cell of `rows` of a width x height grid over the texture (u, v
// at the cell's centre), rows in parallel; progress is reported per row (over the rows called)
// and a stop throws "aborted".
template <typename Cell>
void ForEachGridCell(
  int width, int height, GridRows rows, const ProgressCallback& progress, const Cell& cell)
{
  const std::size_t step = static_cast<std::size_t>(std::max(1, rows.Count));
  const std::size_t first = static_cast<std::size_t>(std::clamp(rows.Index, 0, rows.Count - 1));
  // The k-th row of this share is first + k step.
  const std::size_t rowCount = static_cast<std::size_t>(height);
  const std::size_t own = first < rowCount ? (rowCount - first + step - 1) / step : 0;
  std::atomic<std::size_t> rowsDone{ 0 };
  std::atomic<bool> stop{ false };
  ParallelFor(0, own, 1,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t k = begin; k < end && !stop; ++k)
      {
        const std::size_t j = first + k * step;
        const double v = (j + 0.5) / height;
        for (int i = 0; i < width; ++i)
        {
          cell(static_cast<std::size_t>(i), j, (i + 0.5) / width, v);
        }
        const std::size_t done = ++rowsDone;
        if (!ReportProgress(progress, static_cast<double>(done) / own))
        {
          stop = true;
        }
      }
    });
  if (stop)
  {
    throw std::runtime_error("aborted");
  }
}

// The share of each group's unshadowed direct irradiance from the emitter samples,
// RadianceArea cos cos_e / r^2 (luminance), that the height field lets through at the relief
// point hit = (u, v, d) of unit normal n (Visible, ShadeReliefRay's exact march); 1 where the group
// does not light the point. `groups` values into out.
void EmitterShadowAt(const HeightField& hf, const ReliefFrame& frame,
  const std::vector<ReliefEmitterSample>& samples, const std::vector<int>& group, int groups,
  const glm::dvec3& hit, const glm::dvec3& normal, float* out)
{
  const std::size_t count = static_cast<std::size_t>(groups);
  const glm::dvec3 point = frame.Point(hit.x, hit.y, hit.z);
  std::vector<double> all(count, 0.0), lit(count, 0.0);
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    const int g = group[s];
    if (g < 0 || g >= groups)
    {
      continue;
    }
    const ReliefEmitterSample& e = samples[s];
    glm::dvec3 l;
    double r2 = 0.0;
    const double geometry = EmitterSampleGeometry(e, point, normal, l, r2);
    // As ShadeReliefRay: the light must face the point and be above the macro plane.
    if (!(geometry > 0.0 && glm::dot(frame.Normal, l) > 0.0))
    {
      continue;
    }
    const double weight =
      geometry * Luminance(e.RadianceArea.x, e.RadianceArea.y, e.RadianceArea.z);
    all[static_cast<std::size_t>(g)] += weight;
    if (Visible(hf, hit, frame.ToTexture(l), 1e-6))
    {
      lit[static_cast<std::size_t>(g)] += weight;
    }
  }
  for (std::size_t g = 0; g < count; ++g)
  {
    out[g] = all[g] > 0.0 ? static_cast<float>(lit[g] / all[g]) : 1.0f;
  }
}

// ShadeReliefRay's IndirectVisible: the share of the probes' radiance (luminance) along the
// cosine-distributed directions around n at the relief point hit that leave the relief.
double RadianceVisibleShare(const ReliefLighting& lighting, const HeightField& hf,
  const ReliefFrame& frame, const glm::dvec3& hit, const glm::dvec3& n, int count)
{
  const NormalFrame local(n);
  double all = 0.0, visible = 0.0;
  for (const glm::dvec3& c : CosineDirections(count))
  {
    const glm::dvec3 w = local(c);
    const glm::dvec3 l = ProbeRadiance(lighting, hit.x, hit.y, w);
    const double weight = Luminance(l.x, l.y, l.z) + 1e-12;
    all += weight;
    visible += LeavesRelief(hf, frame, hit, w) ? weight : 0.0;
  }
  return all > 0.0 ? visible / all : 1.0;
}

// A direction's entries of ReliefDirectionHits from what it met, and back.
void NoteHit(const DirectionHit& met, std::uint8_t& kind, float* where)
{
  using Hits = ReliefDirectionHits;
  where[0] = where[1] = 0.0f;
  if (met.Leaves || !met.Seen)
  {
    kind = met.Leaves ? Hits::Leaves : Hits::Lost;
    return;
  }
  const RayHit& seen = *met.Seen;
  kind = seen.wall.x > 0.0 ? Hits::WallU0
    : seen.wall.x < 0.0    ? Hits::WallU1
    : seen.wall.y > 0.0    ? Hits::WallV0
    : seen.wall.y < 0.0    ? Hits::WallV1
                           : Hits::Surface;
  // (u, v) on the surface; on a wall the coordinate along it and the depth.
  const bool alongV = kind == Hits::WallU0 || kind == Hits::WallU1;
  where[0] = static_cast<float>(alongV ? seen.point.y : seen.point.x);
  where[1] = static_cast<float>(kind == Hits::Surface ? seen.point.y : seen.point.z);
}

DirectionHit NotedHit(const HeightField& hf, std::uint8_t kind, const float* where)
{
  using Hits = ReliefDirectionHits;
  if (kind == Hits::Leaves || kind == Hits::Lost)
  {
    return { kind == Hits::Leaves, std::nullopt };
  }
  const double a = where[0], b = where[1];
  RayHit seen{ 0.0, glm::dvec3(a, b, 0.0) };
  switch (kind)
  {
    case Hits::WallU0:
      seen.point = glm::dvec3(0.0, a, b);
      seen.wall = glm::dvec2(1.0, 0.0);
      break;
    case Hits::WallU1:
      seen.point = glm::dvec3(1.0, a, b);
      seen.wall = glm::dvec2(-1.0, 0.0);
      break;
    case Hits::WallV0:
      seen.point = glm::dvec3(a, 0.0, b);
      seen.wall = glm::dvec2(0.0, 1.0);
      break;
    case Hits::WallV1:
      seen.point = glm::dvec3(a, 1.0, b);
      seen.wall = glm::dvec2(0.0, -1.0);
      break;
    default:
      seen.point.z = hf.DepthAt(a, b);
  }
  return { false, seen };
}
} // namespace

namespace relief_internal
{
// ReliefVisibleShare, also noting (when `kinds` is given) what each direction k meets into
// kinds[k] and where[2k], [2k + 1] (ReliefDirectionHits). The direction's one march decides
// whether it leaves and stops where it does not (VisibleOrBlocker); a direction below the macro
// plane, occluded without a march, is marched to its point.
double VisibleShareNoting(const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit,
  const glm::dvec3& n, int count, double* abovePlane, std::uint8_t* kinds, float* where)
{
  if (count < 1)
  {
    if (abovePlane)
    {
      *abovePlane = 1.0;
    }
    return 1.0;
  }
  const NormalFrame local(n);
  const glm::dvec3 from(hit.x, hit.y, std::max(0.0, hit.z));
  int seen = 0, above = 0, k = 0;
  for (const glm::dvec3& c : CosineDirections(count))
  {
    const glm::dvec3 w = local(c);
    const bool up = glm::dot(w, frame.Normal) > 0.0;
    above += up ? 1 : 0;
    if (!kinds)
    {
      seen += LeavesRelief(hf, frame, hit, w) ? 1 : 0;
      continue;
    }
    // LeavesRelief's march, keeping where it stopped.
    DirectionHit met;
    if (up)
    {
      const Visibility visibility = VisibleOrBlocker(hf, from, frame.ToTexture(w), 1e-6);
      met = { visibility.Visible, visibility.Blocker };
    }
    if (!met.Leaves && !met.Seen)
    {
      met.Seen = MarchToSeenPoint(hf, frame, from, w);
    }
    seen += met.Leaves ? 1 : 0;
    NoteHit(met, kinds[k], where + 2 * k);
    ++k;
  }
  if (abovePlane)
  {
    *abovePlane = static_cast<double>(above) / count;
  }
  return static_cast<double>(seen) / count;
}
} // namespace relief_internal

std::vector<float> ReliefVisibleShareMap(const HeightField& hf, const ReliefFrame& frame, int width,
  int height, int count, const ProgressCallback& progress, GridRows rows, ReliefDirectionHits* hits)
{
  if (width < 1 || height < 1)
  {
    throw std::invalid_argument("ReliefVisibleShareMap: the grid must be at least 1 x 1");
  }
  if (rows.Count < 1 || rows.Index < 0 || rows.Index >= rows.Count)
  {
    throw std::invalid_argument("ReliefVisibleShareMap: the rows' index must lie in [0, count)");
  }
  std::vector<float> share(
    2 * static_cast<std::size_t>(width) * height, rows.Count > 1 ? 0.0f : 1.0f);
  const std::size_t directions = static_cast<std::size_t>(std::max(count, 0));
  if (hits)
  {
    hits->Kinds.assign(
      static_cast<std::size_t>(width) * height * directions, ReliefDirectionHits::Leaves);
    hits->Where.assign(2 * hits->Kinds.size(), 0.0f);
  }
  ForEachGridCell(width, height, rows, progress,
    [&](std::size_t i, std::size_t j, double u, double v)
    {
      const glm::dvec3 hit(u, v, hf.DepthAt(u, v));
      double above = 1.0;
      const double visible = VisibleShareNoting(hf, frame, hit, ReliefNormalAt(hf, frame, u, v),
        count, &above, hits ? hits->Kinds.data() + (j * width + i) * directions : nullptr,
        hits ? hits->Where.data() + 2 * (j * width + i) * directions : nullptr);
      share[2 * (j * width + i)] = static_cast<float>(visible);
      share[2 * (j * width + i) + 1] =
        static_cast<float>(above > 0.0 ? std::min(1.0, visible / above) : 1.0);
    });
  return share;
}

std::vector<float> ReliefSeenShareMap(const HeightField& hf, const ReliefFrame& frame,
  const std::vector<float>& share, int width, int height, int count,
  const ProgressCallback& progress, GridRows rows, const ReliefDirectionHits* hits,
  ReliefWallShares wallShares)
{
  if (width < 1 || height < 1 || share.size() != 2 * static_cast<std::size_t>(width) * height)
  {
    throw std::invalid_argument(
      "ReliefSeenShareMap: the visible-share map must hold two values per cell of the grid");
  }
  if (rows.Count < 1 || rows.Index < 0 || rows.Index >= rows.Count)
  {
    throw std::invalid_argument("ReliefSeenShareMap: the rows' index must lie in [0, count)");
  }
  const std::size_t directions = static_cast<std::size_t>(std::max(count, 0));
  if (hits &&
    (hits->Kinds.size() != static_cast<std::size_t>(width) * height * directions ||
      hits->Where.size() != 2 * hits->Kinds.size()))
  {
    throw std::invalid_argument("ReliefSeenShareMap: the first pass's hits must hold `count` "
                                "directions per cell of the grid");
  }
  if (wallShares.Values && !WallSharesFit(wallShares, width))
  {
    throw std::invalid_argument("ReliefSeenShareMap: the walls' shares must hold two values per "
                                "cell of the walls' grid (the map's width by 4 x levels rows)");
  }
  std::vector<float> seen(static_cast<std::size_t>(width) * height, rows.Count > 1 ? 0.0f : 1.0f);
  ForEachGridCell(width, height, rows, progress,
    [&](std::size_t i, std::size_t j, double u, double v)
    {
      const glm::dvec3 hit(u, v, hf.DepthAt(u, v));
      const std::size_t first = (j * width + i) * directions;
      seen[j * width + i] = static_cast<float>(SeenShareWith(hf, frame,
        ReliefNormalAt(hf, frame, u, v), count, &share, width, height, wallShares,
        [&](int k, const glm::dvec3& w)
        {
          const std::size_t d = first + static_cast<std::size_t>(k);
          return hits ? NotedHit(hf, hits->Kinds[d], &hits->Where[2 * d])
                      : MarchDirection(hf, frame, hit, w);
        }));
    });
  return seen;
}

std::vector<float> ReliefEmitterShadowMap(const HeightField& hf, const ReliefFrame& frame,
  const std::vector<ReliefEmitterSample>& samples, const std::vector<int>& group, int groups,
  int width, int height, const ProgressCallback& progress, GridRows rows)
{
  if (width < 1 || height < 1 || groups < 1 || group.size() != samples.size())
  {
    throw std::invalid_argument(
      "ReliefEmitterShadowMap: needs a grid, at least one group and one group per sample");
  }
  const std::size_t count = static_cast<std::size_t>(groups);
  // 0 outside `rows` (GridRows); every value of the cells computed is written below.
  std::vector<float> shadow(static_cast<std::size_t>(width) * height * count, 0.0f);
  ForEachGridCell(width, height, rows, progress,
    [&](std::size_t i, std::size_t j, double u, double v)
    {
      const glm::dvec3 hit(u, v, std::max(0.0, hf.DepthAt(u, v)));
      EmitterShadowAt(hf, frame, samples, group, groups, hit, ReliefNormalAt(hf, frame, u, v),
        &shadow[(j * width + i) * count]);
    });
  return shadow;
}

namespace
{
// The point of cell i of row r of the walls' grid (ReliefWallShareMap) and the wall's unit
// normal there; nothing where the border is at the surface (no wall) or the field is not walled.
std::optional<std::pair<glm::dvec3, glm::dvec3>> WallCellPoint(const HeightField& hf,
  const ReliefFrame& frame, int width, int levels, std::size_t i, std::size_t r)
{
  const int wall = static_cast<int>(r) / levels;
  const int level = static_cast<int>(r) % levels;
  const double s = (i + 0.5) / width;
  // The border's point and the wall's normal in (u, v), pointing back into the rectangle
  // (RayHit::wall, the relief mapper's mlSideWall).
  const glm::dvec2 uv = wall == 0 ? glm::dvec2(0.0, s)
    : wall == 1                   ? glm::dvec2(1.0, s)
    : wall == 2                   ? glm::dvec2(s, 0.0)
                                  : glm::dvec2(s, 1.0);
  const glm::dvec2 inward = wall == 0 ? glm::dvec2(1.0, 0.0)
    : wall == 1                       ? glm::dvec2(-1.0, 0.0)
    : wall == 2                       ? glm::dvec2(0.0, 1.0)
                                      : glm::dvec2(0.0, -1.0);
  const double bottom = hf.DepthAt(uv.x, uv.y);
  if (hf.EdgeRule() != HeightField::Edge::Walled || !(bottom > 0.0))
  {
    return std::nullopt;
  }
  return std::make_pair(
    glm::dvec3(uv.x, uv.y, bottom * (level + 0.5) / levels), ReliefWallNormal(frame, inward));
}

// The first two values of a wall cell: V at the wall's point around its normal, and V over the
// share of the directions above the macro plane (as ReliefVisibleShareMap's pairs).
void WallVisibleSharePair(const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit,
  const glm::dvec3& normal, int count, float* pair)
{
  double above = 1.0;
  const double visible = ReliefVisibleShare(hf, frame, hit, normal, count, &above);
  pair[0] = static_cast<float>(visible);
  pair[1] = static_cast<float>(above > 0.0 ? std::min(1.0, visible / above) : 1.0);
}

// The walls' grid of `perCell` values a cell (`width` cells along each wall, 4 x levels rows;
// the rows outside `rows` 0): cell(values, point, normal, index) fills each cell that has a wall
// (index: the cell's, row-major), the others are 1. Parallel, with ForEachGridCell's progress
// and stop.
template <typename Cell>
std::vector<float> WallGrid(const HeightField& hf, const ReliefFrame& frame, int width, int levels,
  std::size_t perCell, GridRows rows, const ProgressCallback& progress, const Cell& cell)
{
  std::vector<float> walls(
    perCell * static_cast<std::size_t>(width) * 4 * levels, rows.Count > 1 ? 0.0f : 1.0f);
  ForEachGridCell(width, 4 * levels, rows, progress,
    [&](std::size_t i, std::size_t r, double, double)
    {
      float* values = &walls[perCell * (r * width + i)];
      const auto point = WallCellPoint(hf, frame, width, levels, i, r);
      if (!point)
      {
        std::fill(values, values + perCell, 1.0f);
        return;
      }
      cell(values, point->first, point->second, r * width + i);
    });
  return walls;
}

void CheckWallGrid(const char* what, int width, int levels, GridRows rows)
{
  if (width < 1 || levels < 1)
  {
    throw std::invalid_argument(std::string(what) + ": needs a grid and at least one level");
  }
  if (rows.Count < 1 || rows.Index < 0 || rows.Index >= rows.Count)
  {
    throw std::invalid_argument(std::string(what) + ": the rows' index must lie in [0, count)");
  }
}
} // namespace

std::vector<float> ReliefWallVisibleShareMap(const HeightField& hf, const ReliefFrame& frame,
  int width, int levels, int count, const ProgressCallback& progress, GridRows rows)
{
  CheckWallGrid("ReliefWallVisibleShareMap", width, levels, rows);
  return WallGrid(hf, frame, width, levels, 2, rows, progress,
    [&](float* cell, const glm::dvec3& hit, const glm::dvec3& normal, std::size_t)
    { WallVisibleSharePair(hf, frame, hit, normal, count, cell); });
}

std::vector<float> ReliefWallShareMap(const HeightField& hf, const ReliefFrame& frame,
  const std::vector<float>& share, int width, int height, int levels, int count,
  const std::vector<ReliefEmitterSample>& samples, const ProgressCallback& progress, GridRows rows,
  const ReliefLighting* probes, const std::vector<float>* wallShare)
{
  CheckWallGrid("ReliefWallShareMap", width, levels, rows);
  if (height < 1 || share.size() != 2 * static_cast<std::size_t>(width) * height)
  {
    throw std::invalid_argument("ReliefWallShareMap: needs a grid, at least one level and the "
                                "visible-share map's two values per cell of the grid");
  }
  const ReliefWallShares given{ wallShare, levels };
  if (wallShare && !WallSharesFit(given, width))
  {
    throw std::invalid_argument("ReliefWallShareMap: the walls' visible shares must hold two "
                                "values per cell of the walls' grid (width by 4 x levels rows)");
  }
  const std::vector<int> group(samples.size(), 0);
  const bool weighted = probes && !probes->Probes.empty();
  return WallGrid(hf, frame, width, levels, 4, rows, progress,
    [&](float* cell, const glm::dvec3& hit, const glm::dvec3& normal, std::size_t c)
    {
      if (wallShare)
      {
        cell[0] = (*wallShare)[2 * c];
        cell[1] = (*wallShare)[2 * c + 1];
      }
      else
      {
        WallVisibleSharePair(hf, frame, hit, normal, count, cell);
      }
      if (weighted)
      {
        cell[1] = static_cast<float>(RadianceVisibleShare(*probes, hf, frame, hit, normal, count));
      }
      cell[2] = static_cast<float>(
        ReliefSeenShare(hf, frame, hit, normal, count, &share, width, height, given));
      cell[3] = 1.0f;
      if (!samples.empty())
      {
        EmitterShadowAt(hf, frame, samples, group, 1, hit, normal, &cell[3]);
      }
    });
}

} // namespace mesolight
