// SPDX-License-Identifier: BSD-3-Clause
#include "MinDepthPyramid.h"

#include <algorithm>
#include <cstddef>
#include <limits>
#include <utility>

namespace mesolight
{

namespace
{
template <typename T>
std::vector<std::vector<T>> PackChildMinimaT(
  const std::vector<std::vector<T>>& minima, const std::vector<std::pair<int, int>>& sizes)
{
  std::vector<std::vector<T>> rgba(minima.size());
  for (std::size_t l = 1; l < minima.size() && l < sizes.size(); ++l)
  {
    const int lw = sizes[l].first, lh = sizes[l].second;
    const int cw = sizes[l - 1].first, ch = sizes[l - 1].second;
    const std::vector<T>& child = minima[l - 1];
    rgba[l].resize(4 * static_cast<std::size_t>(lw) * static_cast<std::size_t>(lh));
    // Children of cell `node` along one axis for channel c: [first, last], empty if first >
    // last or past the level below.
    auto range = [](int node, int c, int nodes, int children, int& first, int& last)
    {
      first = 2 * node + c;
      last = (c == 1 && node == nodes - 1) ? children - 1 : first;
    };
    for (int ny = 0; ny < lh; ++ny)
    {
      for (int nx = 0; nx < lw; ++nx)
      {
        T* c = &rgba[l][4 *
          (static_cast<std::size_t>(ny) * static_cast<std::size_t>(lw) +
            static_cast<std::size_t>(nx))];
        bool present[4] = { false, false, false, false };
        for (int q = 0; q < 4; ++q)
        {
          int x0 = 0, x1 = 0, y0 = 0, y1 = 0;
          range(nx, q & 1, lw, cw, x0, x1);
          range(ny, q >> 1, lh, ch, y0, y1);
          for (int y = y0; y <= y1 && y < ch; ++y)
          {
            for (int x = x0; x <= x1 && x < cw; ++x)
            {
              const T m = child[static_cast<std::size_t>(y) * static_cast<std::size_t>(cw) +
                static_cast<std::size_t>(x)];
              c[q] = present[q] ? std::min(c[q], m) : m;
              present[q] = true;
            }
          }
        }
        for (int q = 1; q < 4; ++q)
        {
          if (!present[q])
          {
            c[q] = present[q & 1] ? c[q & 1] : c[0]; // a missing child: a present one's bound
          }
        }
      }
    }
  }
  return rgba;
}
} // namespace

std::vector<std::vector<float>> PackChildMinima(
  const std::vector<std::vector<float>>& minima, const std::vector<std::pair<int, int>>& sizes)
{
  return PackChildMinimaT(minima, sizes);
}

std::vector<std::vector<std::uint16_t>> PackChildMinima(
  const std::vector<std::vector<std::uint16_t>>& minima,
  const std::vector<std::pair<int, int>>& sizes)
{
  return PackChildMinimaT(minima, sizes);
}

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

std::vector<std::vector<float>> ChildMinimaFromLevel(
  const float* depth, int w, int h, int firstLevel, std::vector<int>& levelSizes)
{
  levelSizes.clear();
  std::vector<std::vector<float>> out;
  if (!depth || w < 1 || h < 1 || firstLevel < 1)
  {
    return out;
  }
  std::vector<std::vector<float>> minima = ComputeMinDepthPyramid(depth, w, h);
  std::vector<std::pair<int, int>> sizes;
  for (std::size_t l = 0; l < minima.size(); ++l)
  {
    int lw = 0, lh = 0;
    MinDepthPyramidLevelSize(w, h, static_cast<int>(l), lw, lh);
    sizes.emplace_back(lw, lh);
  }
  // A map too small for firstLevel: repeat the 1 x 1 apex (one present child per cell).
  while (static_cast<int>(minima.size()) <= firstLevel)
  {
    minima.push_back(minima.back());
    sizes.emplace_back(1, 1);
  }
  std::vector<std::vector<float>> packed = PackChildMinimaT(minima, sizes);
  for (std::size_t l = static_cast<std::size_t>(firstLevel); l < packed.size(); ++l)
  {
    levelSizes.push_back(sizes[l].first);
    levelSizes.push_back(sizes[l].second);
    out.push_back(std::move(packed[l]));
  }
  return out;
}

} // namespace mesolight
