// SPDX-License-Identifier: BSD-3-Clause
// The compact relief storage's cores (core/CompactReliefStorage.h): 16-bit depth, the min-depth
// pyramid of those depths (levels 1 and up) and the check that a texture's normals are the
// Sobel normals of its depth. The pyramid is checked against the pyramid builder and against
// its defining property, every level bounding the depths below it; a pyramid rounded the wrong
// way (to nearest, in 8 bits) must break that property.
#include "CompactReliefStorage.h"
#include "MinDepthPyramid.h"
#include "SobelNormals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <random>
#include <string>
#include <utility>
#include <vector>

namespace
{
using namespace mesolight;

std::vector<float> RandomDepth(int w, int h, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> u(0.f, 1.f);
  std::vector<float> d(static_cast<size_t>(w) * static_cast<size_t>(h));
  for (float& x : d)
  {
    x = u(rng);
  }
  return d;
}

// Whether every value of level l (l >= 1) is at most every 16-bit depth of the cells it covers:
// level-0 cell (ci, cj) has corners (ci - 1 .. ci, cj - 1 .. cj) clamped, and belongs to level-l
// cell (min(ci >> l, w_l - 1), min(cj >> l, h_l - 1)). value(c) gives level l's value of cell c
// as a depth.
template <typename Value>
bool LevelBounds(
  const std::vector<std::uint16_t>& d16, int w, int h, int l, int lw, int lh, const Value& value)
{
  for (int cj = 0; cj <= h; ++cj)
  {
    for (int ci = 0; ci <= w; ++ci)
    {
      const int pi = std::min(ci >> l, lw - 1), pj = std::min(cj >> l, lh - 1);
      const float bound = value(static_cast<size_t>(pj) * static_cast<size_t>(lw) + pi);
      for (int dj = -1; dj <= 0; ++dj)
      {
        for (int di = -1; di <= 0; ++di)
        {
          const int i = std::min(std::max(ci + di, 0), w - 1);
          const int j = std::min(std::max(cj + dj, 0), h - 1);
          if (bound > static_cast<float>(d16[static_cast<size_t>(j) * w + i]) / 65535.f)
          {
            return false;
          }
        }
      }
    }
  }
  return true;
}
} // namespace

TEST(CompactReliefStorage, SixteenBitDepthRoundsToNearest)
{
  for (float d : { 0.f, 1e-6f, 0.25f, 0.5f, 0.7777f, 1.f })
  {
    EXPECT_LE(std::fabs(QuantizeDepth16(d) / 65535.f - d), 0.5f / 65535.f + 1e-7f) << d;
  }
  EXPECT_EQ(QuantizeDepth16(-0.5f), 0);
  EXPECT_EQ(QuantizeDepth16(2.f), 65535);
  // An 8-bit depth k / 255 is exact in 16 bits: 257 k.
  for (int k : { 0, 1, 100, 254, 255 })
  {
    EXPECT_EQ(QuantizeDepth16(static_cast<float>(k) / 255.f), 257 * k);
  }
}

TEST(CompactReliefStorage, PyramidIsTheExactMinimaAboveLevelZero)
{
  const int w = 37, h = 23; // odd sizes: the last parent of a row takes the leftover child
  const std::vector<float> depth = RandomDepth(w, h, 7);
  std::vector<std::uint16_t> d16(depth.size());
  std::vector<float> dequantized(depth.size());
  for (size_t i = 0; i < depth.size(); ++i)
  {
    d16[i] = QuantizeDepth16(depth[i]);
    dequantized[i] = d16[i] / 65535.f;
  }
  std::vector<int> sizes;
  const auto levels = CompactMinDepthPyramid(d16.data(), w, h, sizes);
  const auto reference = ComputeMinDepthPyramid(dequantized.data(), w, h);
  ASSERT_EQ(levels.size() + 1, reference.size());
  ASSERT_EQ(sizes.size(), 2 * levels.size());
  for (size_t l = 0; l < levels.size(); ++l)
  {
    int lw = 0, lh = 0;
    ASSERT_TRUE(MinDepthPyramidLevelSize(w, h, static_cast<int>(l + 1), lw, lh));
    EXPECT_EQ(sizes[2 * l], lw);
    EXPECT_EQ(sizes[2 * l + 1], lh);
    ASSERT_EQ(levels[l].size(), reference[l + 1].size());
    for (size_t i = 0; i < levels[l].size(); ++i)
    {
      EXPECT_EQ(levels[l][i] / 65535.f, reference[l + 1][i]) << "level " << l + 1 << " cell " << i;
    }
    EXPECT_TRUE(LevelBounds(d16, w, h, static_cast<int>(l + 1), lw, lh,
      [&](size_t i) { return levels[l][i] / 65535.f; }));
  }
  EXPECT_EQ(sizes[sizes.size() - 2], 1);
  EXPECT_EQ(sizes.back(), 1);
}

// Negative test: the same pyramid in 8 bits rounded to nearest no longer bounds the surface (a
// traversal would skip cells it hits); rounded down it still does.
TEST(CompactReliefStorage, PyramidRoundedUpNoLongerBounds)
{
  const int w = 64, h = 64;
  const std::vector<float> depth = RandomDepth(w, h, 11);
  std::vector<std::uint16_t> d16(depth.size());
  for (size_t i = 0; i < depth.size(); ++i)
  {
    d16[i] = QuantizeDepth16(depth[i]);
  }
  std::vector<int> sizes;
  const auto levels = CompactMinDepthPyramid(d16.data(), w, h, sizes);
  const auto& level1 = levels[0];
  auto nearest = [&](size_t i) { return std::round(level1[i] / 257.f) / 255.f; };
  auto down = [&](size_t i) { return std::floor(level1[i] * 255.f / 65535.f) / 255.f; };
  EXPECT_TRUE(LevelBounds(d16, w, h, 1, sizes[0], sizes[1], down));
  EXPECT_FALSE(LevelBounds(d16, w, h, 1, sizes[0], sizes[1], nearest));
}

TEST(CompactReliefStorage, SobelNormalsAreRecognised)
{
  const int w = 48, h = 40;
  const float k = 0.05f;
  std::vector<float> depth(static_cast<size_t>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      depth[static_cast<size_t>(j) * w + i] =
        static_cast<float>(0.5 + 0.4 * std::sin(0.3 * i) * std::cos(0.2 * j));
    }
  }
  std::vector<float> rgba(4 * depth.size());
  ComputeReliefTexture(depth.data(), w, h, k, BorderMode::Clamp, rgba.data());
  std::vector<float> xy(2 * depth.size()), twice(2 * depth.size());
  for (size_t i = 0; i < depth.size(); ++i)
  {
    const float x = 2.f * rgba[4 * i] - 1.f, y = 2.f * rgba[4 * i + 1] - 1.f;
    const float z = 2.f * rgba[4 * i + 2] - 1.f;
    xy[2 * i] = x;
    xy[2 * i + 1] = y;
    const float len = std::sqrt(4.f * x * x + 4.f * y * y + z * z);
    twice[2 * i] = 2.f * x / len;
    twice[2 * i + 1] = 2.f * y / len;
  }
  EXPECT_LT(SobelNormalMismatch(depth.data(), xy.data(), w, h, k), 1e-5f);
  // Negative: normals of twice the slope, or the right normals with another depth scale, or no
  // depth scale at all.
  EXPECT_GT(SobelNormalMismatch(depth.data(), twice.data(), w, h, k), 0.02f);
  EXPECT_GT(SobelNormalMismatch(depth.data(), xy.data(), w, h, 2.0 * k), 0.02f);
  EXPECT_GT(SobelNormalMismatch(depth.data(), xy.data(), w, h, 0.0), 1.f);
}

namespace
{
// The child of level l - 1 (cell c) sits in quadrant q of its parent at level l; the odd child
// left over at the end of a row or column is the last parent's second child.
int ChildQuadrant(int cx, int cy, int pw, int ph)
{
  const int px = std::min(cx / 2, pw - 1), py = std::min(cy / 2, ph - 1);
  return std::min(cx - 2 * px, 1) + 2 * std::min(cy - 2 * py, 1);
}

// Whether every cell of level l - 1 is bounded by its parent's channel for it (the traversal
// skips a child when the ray stays above that channel), for every level l >= 1.
template <typename T>
bool ChildChannelsBound(const std::vector<std::vector<T>>& minima,
  const std::vector<std::vector<T>>& rgba, const std::vector<std::pair<int, int>>& sizes)
{
  for (size_t l = 1; l < minima.size(); ++l)
  {
    const int cw = sizes[l - 1].first, ch = sizes[l - 1].second;
    const int pw = sizes[l].first, ph = sizes[l].second;
    for (int cy = 0; cy < ch; ++cy)
    {
      for (int cx = 0; cx < cw; ++cx)
      {
        const int px = std::min(cx / 2, pw - 1), py = std::min(cy / 2, ph - 1);
        const T bound = rgba[l][4 * (static_cast<size_t>(py) * pw + px) +
          static_cast<size_t>(ChildQuadrant(cx, cy, pw, ph))];
        if (bound > minima[l - 1][static_cast<size_t>(cy) * cw + cx])
        {
          return false;
        }
      }
    }
  }
  return true;
}

template <typename T>
void ExpectPackedChildMinima(const std::vector<std::vector<T>>& minima,
  const std::vector<std::pair<int, int>>& sizes, const std::string& what)
{
  const std::vector<std::vector<T>> rgba = PackChildMinima(minima, sizes);
  ASSERT_EQ(rgba.size(), minima.size()) << what;
  EXPECT_TRUE(rgba[0].empty()) << what;
  EXPECT_TRUE(ChildChannelsBound(minima, rgba, sizes)) << what;
  for (size_t l = 1; l < minima.size(); ++l)
  {
    const int pw = sizes[l].first, ph = sizes[l].second;
    ASSERT_EQ(rgba[l].size(), 4 * static_cast<size_t>(pw) * ph) << what;
    for (size_t n = 0; n < static_cast<size_t>(pw) * ph; ++n)
    {
      // Each channel is some child's minimum (tight), and the four together are the cell's own.
      const T* c = &rgba[l][4 * n];
      EXPECT_EQ(std::min(std::min(c[0], c[1]), std::min(c[2], c[3])), minima[l][n])
        << what << " level " << l << " cell " << n;
    }
  }
  // Tight: every channel of a cell that has children in that quadrant is their exact minimum.
  for (size_t l = 1; l < minima.size(); ++l)
  {
    const int cw = sizes[l - 1].first, ch = sizes[l - 1].second;
    const int pw = sizes[l].first, ph = sizes[l].second;
    std::vector<T> expect(4 * static_cast<size_t>(pw) * ph, std::numeric_limits<T>::max());
    for (int cy = 0; cy < ch; ++cy)
    {
      for (int cx = 0; cx < cw; ++cx)
      {
        const int px = std::min(cx / 2, pw - 1), py = std::min(cy / 2, ph - 1);
        T& e = expect[4 * (static_cast<size_t>(py) * pw + px) +
          static_cast<size_t>(ChildQuadrant(cx, cy, pw, ph))];
        e = std::min(e, minima[l - 1][static_cast<size_t>(cy) * cw + cx]);
      }
    }
    for (size_t i = 0; i < expect.size(); ++i)
    {
      if (expect[i] != std::numeric_limits<T>::max())
      {
        EXPECT_EQ(rgba[l][i], expect[i]) << what << " level " << l << " channel " << i;
      }
    }
  }
}

std::vector<std::pair<int, int>> PyramidSizes(int w, int h, size_t levels)
{
  std::vector<std::pair<int, int>> sizes;
  for (size_t l = 0; l < levels; ++l)
  {
    int lw = 0, lh = 0;
    MinDepthPyramidLevelSize(w, h, static_cast<int>(l), lw, lh);
    sizes.emplace_back(lw, lh);
  }
  return sizes;
}
} // namespace

// The four-children packing (core/MinDepthPyramid.h) of float and 16-bit pyramids of odd, even,
// one-texel-wide and one-texel-high maps: each channel the exact minimum of its children, the
// leftover odd child folded into the last cell, a missing child repeating a present bound.
TEST(CompactReliefStorage, ChildMinimaPackingBoundsEveryChild)
{
  for (const auto& [w, h] : std::vector<std::pair<int, int>>{
         { 37, 23 }, { 64, 64 }, { 1, 9 }, { 12, 1 }, { 2, 2 } })
  {
    const std::string what = std::to_string(w) + "x" + std::to_string(h);
    const std::vector<float> depth = RandomDepth(w, h, 3);
    const auto levels = ComputeMinDepthPyramid(depth.data(), w, h);
    const auto sizes = PyramidSizes(w, h, levels.size());
    ExpectPackedChildMinima(levels, sizes, what + " float");
    std::vector<std::vector<std::uint16_t>> levels16(levels.size());
    for (size_t l = 0; l < levels.size(); ++l)
    {
      for (float d : levels[l])
      {
        levels16[l].push_back(QuantizeDepth16(d));
      }
    }
    ExpectPackedChildMinima(levels16, sizes, what + " 16-bit");
  }
}

// Negative test: the packing without the leftover fold (the last cell's second channel holding
// child 2n + 1 only) leaves a child unbounded on an odd-sized level.
TEST(CompactReliefStorage, ChildMinimaWithoutTheLeftoverFoldNoLongerBound)
{
  const int w = 37, h = 23; // 38 x 24 cells: level 1 is 19 x 12, level 2 9 x 6 (odd: a leftover)
  const std::vector<float> depth = RandomDepth(w, h, 5);
  const auto levels = ComputeMinDepthPyramid(depth.data(), w, h);
  const auto sizes = PyramidSizes(w, h, levels.size());
  auto rgba = PackChildMinima(levels, sizes);
  ASSERT_TRUE(ChildChannelsBound(levels, rgba, sizes));
  bool changed = false;
  for (size_t l = 1; l < levels.size(); ++l)
  {
    const int cw = sizes[l - 1].first, pw = sizes[l].first, ph = sizes[l].second;
    if (cw % 2 == 0 || cw < 3)
    {
      continue;
    }
    for (int py = 0; py < ph && 2 * py < sizes[l - 1].second; ++py)
    {
      const float unfolded = levels[l - 1][static_cast<size_t>(2 * py) * cw + 2 * (pw - 1) + 1];
      float& channel = rgba[l][4 * (static_cast<size_t>(py) * pw + pw - 1) + 1];
      changed = changed || channel != unfolded;
      channel = unfolded;
    }
  }
  ASSERT_TRUE(changed);
  EXPECT_FALSE(ChildChannelsBound(levels, rgba, sizes));
}
