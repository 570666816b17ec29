// SPDX-License-Identifier: BSD-3-Clause
#include "MinDepthPyramid.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>

namespace mesolight
{

void AddMinPyramidLevels(std::vector<MinPyramidLevel>& levels, int channels, PyramidHalving halving)
{
  const bool up = halving == PyramidHalving::RoundUp;
  while (levels.back().W > 1 || levels.back().H > 1)
  {
    const MinPyramidLevel& c = levels.back();
    MinPyramidLevel p{ up ? (c.W + 1) / 2 : std::max(1, c.W / 2),
      up ? (c.H + 1) / 2 : std::max(1, c.H / 2), c.Size * 2, {} };
    p.Min.assign(
      static_cast<std::size_t>(p.W) * p.H * channels, std::numeric_limits<float>::infinity());
    for (int j = 0; j < c.H; ++j)
    {
      const int pj = std::min(j / 2, p.H - 1);
      for (int i = 0; i < c.W; ++i)
      {
        const int pi = std::min(i / 2, p.W - 1);
        const float* cm = &c.Min[(static_cast<std::size_t>(j) * c.W + i) * channels];
        float* pm = &p.Min[(static_cast<std::size_t>(pj) * p.W + pi) * channels];
        for (int s = 0; s < channels; ++s)
        {
          pm[s] = std::min(pm[s], cm[s]);
        }
      }
    }
    levels.push_back(std::move(p));
  }
}

bool MinDepthPyramidLevelSize(int w, int h, int level, int& lw, int& lh)
{
  if (w < 1 || h < 1 || level < 0)
  {
    return false;
  }
  lw = w + 1;
  lh = h + 1;
  for (int k = 0; k < level; ++k)
  {
    if (lw == 1 && lh == 1)
    {
      return false;
    }
    lw = std::max(1, lw / 2);
    lh = std::max(1, lh / 2);
  }
  return true;
}

std::vector<std::vector<float>> ComputeMinDepthPyramid(const float* depth, int w, int h)
{
  std::vector<std::vector<float>> out;
  if (!depth || w < 1 || h < 1)
  {
    return out;
  }
  // Texel (i, j) with indices clamped into the image (the clamp-extension border).
  auto at = [&](int i, int j)
  {
    i = std::min(std::max(i, 0), w - 1);
    j = std::min(std::max(j, 0), h - 1);
    return depth[static_cast<std::size_t>(j) * w + i];
  };
  MinPyramidLevel base{ w + 1, h + 1, 1, {} };
  base.Min.resize(static_cast<std::size_t>(base.W) * base.H);
  for (int cj = 0; cj < base.H; ++cj)
  {
    for (int ci = 0; ci < base.W; ++ci)
    {
      base.Min[static_cast<std::size_t>(cj) * base.W + ci] =
        std::min({ at(ci - 1, cj - 1), at(ci, cj - 1), at(ci - 1, cj), at(ci, cj) });
    }
  }
  std::vector<MinPyramidLevel> levels;
  levels.push_back(std::move(base));
  AddMinPyramidLevels(levels, 1, PyramidHalving::RoundDown);
  out.reserve(levels.size());
  for (MinPyramidLevel& level : levels)
  {
    out.push_back(std::move(level.Min));
  }
  return out;
}

} // namespace mesolight
