// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefShading.h"

#include "Luminance.h"
#include "ParallelFor.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <optional>
#include <stdexcept>
#include <string>
#include <utility>

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
  const HeightField& hf, const ReliefFrame& frame, const glm::dvec3& hit, const glm::dvec3& w)
{
  return glm::dot(w, frame.Normal) > 0.0 &&
    Visible(hf, glm::dvec3(hit.x, hit.y, std::max(0.0, hit.z)), frame.ToTexture(w), 1e-6);
}

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
    const glm::dvec3 toLight = e.Position - point;
    const double r2 = glm::dot(toLight, toLight);
    if (!(r2 > 0.0))
    {
      continue;
    }
    const glm::dvec3 l = toLight / std::sqrt(r2);
    const double cosine = glm::dot(normal, l);
    const double cosineEmitter = -glm::dot(e.Normal, l);
    // As ShadeReliefRay: the light must face the point and be above the macro plane.
    if (!(cosine > 0.0 && cosineEmitter > 0.0 && glm::dot(frame.Normal, l) > 0.0))
    {
      continue;
    }
    const double weight =
      cosine * cosineEmitter / r2 * Luminance(e.RadianceArea.x, e.RadianceArea.y, e.RadianceArea.z);
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
} // namespace

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
