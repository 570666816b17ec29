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
#include <random>
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
