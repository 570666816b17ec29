// SPDX-License-Identifier: BSD-3-Clause
#include "BoundTraversalOracle.h"

#include "HeightFieldTracer.h"
#include "MinDepthPyramid.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mesolight
{
namespace
{
constexpr double kNever = std::numeric_limits<double>::infinity();

// Ray parameter at which the ray leaves level-L cell n along one axis. In cell space (x = u W -
// 0.5) level-0 cell k spans [k - 1, k], so level-L cell n spans [(n << L) - 1, ((n + 1) << L) - 1];
// the first and last cells of a level reach to infinity (the clamp bands; the last also holds the
// leftover cells).
double AxisExit(int level, int n, int size, double x0, double rate)
{
  if (rate > 0.0 && n < size - 1)
  {
    return (double((n + 1) << level) - 1.0 - x0) / rate;
  }
  if (rate < 0.0 && n > 0)
  {
    return (double(n << level) - 1.0 - x0) / rate;
  }
  return kNever;
}
} // namespace

BoundTraversalOracle::BoundTraversalOracle(const HeightField& hf)
  : W(hf.Width())
  , H(hf.Height())
{
  std::vector<float> depth(static_cast<size_t>(this->W) * this->H);
  for (int j = 0; j < this->H; ++j)
  {
    for (int i = 0; i < this->W; ++i)
    {
      depth[static_cast<size_t>(j) * this->W + i] = hf.Texel(i, j);
    }
  }
  this->Levels = ComputeMinDepthPyramid(depth.data(), this->W, this->H);
  for (int level = 0; level < static_cast<int>(this->Levels.size()); ++level)
  {
    int lw = 0, lh = 0;
    MinDepthPyramidLevelSize(this->W, this->H, level, lw, lh);
    this->LevelWidth.push_back(lw);
    this->LevelHeight.push_back(lh);
  }
}

int BoundTraversalOracle::Fetches(
  const glm::dvec3& origin, const glm::dvec3& dir, double tHit, int finestBoundLevel) const
{
  const bool finite = std::isfinite(origin.x) && std::isfinite(origin.y) &&
    std::isfinite(origin.z) && std::isfinite(dir.x) && std::isfinite(dir.y) &&
    std::isfinite(dir.z) && std::isfinite(tHit);
  if (!finite || !(dir.z > 0.0) || tHit < 0.0 || this->Levels.empty())
  {
    return 0;
  }
  const int top = static_cast<int>(this->Levels.size()) - 1;
  const int finest = std::clamp(finestBoundLevel, 0, top);
  const double x0 = origin.x * this->W - 0.5, y0 = origin.y * this->H - 0.5;
  const double rx = dir.x * this->W, ry = dir.y * this->H;
  // Above the map's smallest depth the ray meets nothing (the apex bounds every cell).
  double t = std::max(0.0, (double(this->Levels[top][0]) - origin.z) / dir.z);
  // The texel last fetched per level (its parent's level and index), -1: none yet.
  std::vector<long long> held(this->Levels.size() + 1, -1);
  int fetches = 0;
  // Each step passes at least one level-0 cell boundary, so W + H + 2 steps reach any tHit.
  for (int step = 0; step < 4 * (this->W + this->H + 2) && t < tHit; ++step)
  {
    const int kx = std::clamp(static_cast<int>(std::floor(x0 + t * rx)) + 1, 0, this->W);
    const int ky = std::clamp(static_cast<int>(std::floor(y0 + t * ry)) + 1, 0, this->H);
    bool cleared = false;
    for (int level = top; level >= finest && !cleared; --level)
    {
      const int nx = std::min(kx >> level, this->LevelWidth[level] - 1);
      const int ny = std::min(ky >> level, this->LevelHeight[level] - 1);
      const double exit = std::min(AxisExit(level, nx, this->LevelWidth[level], x0, rx),
        AxisExit(level, ny, this->LevelHeight[level], y0, ry));
      // The ray deepens along t: its deepest point in the cell is where it leaves.
      const double deepest = exit < kNever ? origin.z + exit * dir.z : kNever;
      const float bound =
        this->Levels[level][static_cast<size_t>(ny) * this->LevelWidth[level] + nx];
      if (!(deepest < bound))
      {
        continue;
      }
      cleared = true;
      // The bound comes from the parent's texel (the apex: from its own).
      const int parentLevel = std::min(level + 1, top);
      const int px = std::min(nx >> (parentLevel - level), this->LevelWidth[parentLevel] - 1);
      const int py = std::min(ny >> (parentLevel - level), this->LevelHeight[parentLevel] - 1);
      const long long texel = static_cast<long long>(py) * this->LevelWidth[parentLevel] + px;
      if (held[parentLevel] != texel)
      {
        held[parentLevel] = texel;
        ++fetches;
      }
      t = exit + 1e-9 * std::max(1.0, exit);
    }
    if (cleared)
    {
      continue;
    }
    // A level-0 cell under no cleared stored cell: its corners.
    ++fetches;
    const double exit =
      std::min(AxisExit(0, kx, this->W + 1, x0, rx), AxisExit(0, ky, this->H + 1, y0, ry));
    if (exit >= tHit)
    {
      return fetches; // the hit cell
    }
    t = exit + 1e-9 * std::max(1.0, exit);
  }
  return fetches + 1; // the hit cell's corners
}

} // namespace mesolight
