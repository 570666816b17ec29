// SPDX-License-Identifier: BSD-3-Clause
// The TEST ORACLES of ConeMaps.h: the cone definitions by exhaustive O((w h)^2) search,
// single-threaded, from the same bounds as the fast searches (ConeMapBounds.h).
#include "ConeMapBounds.h"
#include "ConeMaps.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace mesolight
{
namespace
{
using namespace conemaps;

// The bilinear-safe cones: every cell pair.
std::vector<float> CellBoundBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options, bool relaxed)
{
  const CellPairBounds search(depth, w, h, relaxed);
  const int cw = w + 1;
  const int ch = h + 1;
  std::vector<double> cells(static_cast<std::size_t>(cw) * ch);
  for (int xj = 0; xj < ch; ++xj)
  {
    for (int xi = 0; xi < cw; ++xi)
    {
      const CellCorners cx(depth, w, h, xi, xj);
      double best = options.MaxRatio;
      for (int yj = 0; yj < ch; ++yj)
      {
        for (int yi = 0; yi < cw; ++yi)
        {
          best = std::min(best, search.PairBound(xi, xj, cx, yi, yj, best));
        }
      }
      cells[static_cast<std::size_t>(xj) * cw + xi] = best;
    }
  }
  return TexelsFromCells(cells, w, h);
}

std::vector<float> ComputeBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options, bool relaxed)
{
  if (!depth || w < 1 || h < 1)
  {
    return {};
  }
  if (options.BilinearSafe)
  {
    return CellBoundBruteForce(depth, w, h, options, relaxed);
  }
  std::vector<float> ratio(static_cast<std::size_t>(w) * h);
  for (int pj = 0; pj < h; ++pj)
  {
    for (int pi = 0; pi < w; ++pi)
    {
      const double dp = depth[static_cast<std::size_t>(pj) * w + pi];
      double best = options.MaxRatio;
      for (int qj = 0; qj < h; ++qj)
      {
        for (int qi = 0; qi < w; ++qi)
        {
          const double dq = depth[static_cast<std::size_t>(qj) * w + qi];
          if (!(dq < dp) || (relaxed && !IsFallingEdgeNear(depth, w, h, pi, pj, qi, qj)))
          {
            continue;
          }
          const long long di = qi - pi;
          const long long dj = qj - pj;
          best = std::min(best, Ratio(di * di + dj * dj, w, dp, dq));
        }
      }
      ratio[static_cast<std::size_t>(pj) * w + pi] = static_cast<float>(best);
    }
  }
  return ratio;
}

} // namespace

std::vector<float> ComputeConservativeConeMapBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options)
{
  return ComputeBruteForce(depth, w, h, options, false);
}

std::vector<float> ComputeRelaxedConeMapBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options)
{
  return ComputeBruteForce(depth, w, h, options, true);
}

} // namespace mesolight
