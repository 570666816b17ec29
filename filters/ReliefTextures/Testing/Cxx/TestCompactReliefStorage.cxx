// SPDX-License-Identifier: BSD-3-Clause
// The compact relief storage's cores (core/CompactReliefStorage.h): 16-bit depth, the min-depth
// pyramid of those depths (levels 1 and up) and the check that a texture's normals are the
// Sobel normals of its depth. The pyramid is checked against the pyramid builder and against
// its defining property, every level bounding the depths below it; a pyramid rounded the wrong
// way (to nearest, in 8 bits) must break that property.
#include "CompactReliefStorage.h"
#include "MinDepthPyramid.h"
#include "ProceduralHeightFields.h"
#include "SobelNormals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
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
  EXPECT_TRUE(NormalsAreTheDepths(depth.data(), xy.data(), w, h, k));
  EXPECT_FALSE(NormalsAreTheDepths(depth.data(), twice.data(), w, h, k));
  EXPECT_FALSE(NormalsAreTheDepths(depth.data(), xy.data(), w, h, 0.0));
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
  for (const auto& [w, h] :
    std::vector<std::pair<int, int>>{ { 37, 23 }, { 64, 64 }, { 1, 9 }, { 12, 1 }, { 2, 2 } })
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

// ---------------------------------------------------------------------------------------------
// Level of detail's normal moments (NormalMoments, NormalMomentLevel): the uploaded layout keeps
// levels 2 and up in half floats and the shader computes levels 0 and 1 from the 8-bit
// octahedral normals (vtkReliefHeightFieldFS.glsl, mlAddLevelMoments). Below, that lookup is
// mirrored on the CPU and the visible normal it gives (mlVisibleNormal's formula) is compared
// with the one of float moments at every level, the layout before.
namespace
{
constexpr int K = NormalMomentCount;

// Successive 2 x 2 reductions, written out: the definition NormalMomentLevel computes directly.
std::vector<float> ReduceTwice(const std::vector<float>& m, int w, int h)
{
  const int lw = std::max(1, w / 2), lh = std::max(1, h / 2);
  std::vector<float> out(static_cast<size_t>(lw) * lh * K, 0.f);
  for (int j = 0; j < lh; ++j)
  {
    for (int i = 0; i < lw; ++i)
    {
      for (int d = 0; d < 4; ++d)
      {
        const int ci = std::min(2 * i + (d & 1), w - 1), cj = std::min(2 * j + (d >> 1), h - 1);
        for (int c = 0; c < K; ++c)
        {
          out[(static_cast<size_t>(j) * lw + i) * K + c] +=
            0.25f * m[(static_cast<size_t>(cj) * w + ci) * K + c];
        }
      }
    }
  }
  return out;
}

// A relief texture's normals (Sobel, as vtkReliefTextureFilter bakes them): x, y and z.
struct NormalMap
{
  int W = 0, H = 0;
  std::vector<float> XY, Z;
};

NormalMap BakedNormals(ReliefPattern pattern, int w, int h, float depthScale)
{
  HeightFieldParameters params;
  params.Pattern = pattern;
  std::vector<float> depth(static_cast<size_t>(w) * h), rgba(4 * depth.size());
  GenerateHeightField(params, w, h, depth.data(), nullptr);
  ComputeReliefTexture(depth.data(), w, h, depthScale, BorderMode::Clamp, rgba.data());
  NormalMap map;
  map.W = w;
  map.H = h;
  for (size_t i = 0; i < depth.size(); ++i)
  {
    map.XY.push_back(2.f * rgba[4 * i] - 1.f);
    map.XY.push_back(2.f * rgba[4 * i + 1] - 1.f);
    map.Z.push_back(2.f * rgba[4 * i + 2] - 1.f);
  }
  return map;
}

// Half-float rounding (GL_RGBA16F): 11 significant bits, subnormals below 2^-14.
float RoundToHalf(float v)
{
  if (v == 0.f)
  {
    return 0.f;
  }
  if (std::fabs(v) < std::ldexp(1.f, -14))
  {
    return std::ldexp(std::round(std::ldexp(v, 24)), -24);
  }
  int e = 0;
  const float m = std::frexp(v, &e);
  return std::ldexp(std::round(m * 2048.f) / 2048.f, e);
}

struct Level
{
  int W = 0, H = 0;
  std::vector<float> M;
};

// Bilinear lookup of a level clamped to its edge, as the sampler's, added with weight k.
void AddBilinear(const Level& l, float u, float v, float k, float* out)
{
  const float x = u * l.W - 0.5f, y = v * l.H - 0.5f;
  const int i0 = static_cast<int>(std::floor(x)), j0 = static_cast<int>(std::floor(y));
  const float fx = x - i0, fy = y - j0;
  for (int d = 0; d < 4; ++d)
  {
    const int i = std::min(std::max(i0 + (d & 1), 0), l.W - 1);
    const int j = std::min(std::max(j0 + (d >> 1), 0), l.H - 1);
    const float wgt = k * ((d & 1) ? fx : 1.f - fx) * ((d >> 1) ? fy : 1.f - fy);
    for (int c = 0; c < K; ++c)
    {
      out[c] += wgt * l.M[(static_cast<size_t>(j) * l.W + i) * K + c];
    }
  }
}

// Trilinear lookup of a chain of levels (the sampler's LINEAR_MIPMAP_LINEAR, lod clamped).
void Trilinear(const std::vector<Level>& chain, float u, float v, float lod, float* out)
{
  std::fill(out, out + K, 0.f);
  lod = std::min(std::max(lod, 0.f), static_cast<float>(chain.size() - 1));
  const int l = std::min(static_cast<int>(lod), static_cast<int>(chain.size()) - 1);
  const float f = lod - static_cast<float>(l);
  AddBilinear(chain[static_cast<size_t>(l)], u, v, 1.f - f, out);
  if (f > 0.f)
  {
    AddBilinear(chain[static_cast<size_t>(l + 1)], u, v, f, out);
  }
}

// The moment layouts compared.
enum class Layout
{
  Float,     // float moments at every level (the reference)
  Compact,   // the upload: levels 0 and 1 from the 8-bit normals, half floats from level 2
  Dropped,   // negative: levels 0 and 1 neither uploaded nor reconstructed (level 2 read instead)
  Unweighted // negative: levels 0 and 1 reconstructed without the area weight 1 / nz
};

struct Moments
{
  std::vector<Level> Chain;    // the float levels, or the uploaded ones from level 2
  std::vector<Level> Computed; // levels 0 and 1 as the shader computes them (compact layouts)
};

Moments BuildMoments(const NormalMap& map, Layout layout)
{
  Moments m;
  const int first = layout == Layout::Float ? 0 : NormalMomentFirstStoredLevel;
  for (int level = first;; ++level)
  {
    Level l;
    l.W = MipLevelSize(map.W, level);
    l.H = MipLevelSize(map.H, level);
    l.M = NormalMomentLevel(map.XY.data(), map.Z.data(), map.W, map.H, level);
    if (layout != Layout::Float)
    {
      for (float& x : l.M)
      {
        x = RoundToHalf(x);
      }
    }
    m.Chain.push_back(l);
    if (l.W == 1 && l.H == 1)
    {
      break;
    }
  }
  if (layout == Layout::Compact || layout == Layout::Unweighted)
  {
    // The shader's texel moments: the 8-bit octahedral normal decoded, then NormalMoments.
    NormalMap decoded = map;
    for (size_t i = 0; i < map.Z.size(); ++i)
    {
      std::int8_t e0 = 0, e1 = 0;
      EncodeOctahedral8(map.XY[2 * i], map.XY[2 * i + 1], map.Z[i], e0, e1);
      float n[3];
      DecodeOctahedral8(e0, e1, n);
      decoded.XY[2 * i] = n[0];
      decoded.XY[2 * i + 1] = n[1];
      decoded.Z[i] = n[2];
    }
    for (int level = 0; level < NormalMomentFirstStoredLevel; ++level)
    {
      Level l;
      l.W = MipLevelSize(map.W, level);
      l.H = MipLevelSize(map.H, level);
      l.M = NormalMomentLevel(decoded.XY.data(), decoded.Z.data(), map.W, map.H, level);
      if (layout == Layout::Unweighted)
      {
        // n n^T and n without the area weight w = 1 / nz: level 0's, then its box reduction.
        std::vector<float> unweighted(K * decoded.Z.size());
        for (size_t t = 0; t < decoded.Z.size(); ++t)
        {
          float* u = &unweighted[K * t];
          NormalMoments(decoded.XY[2 * t], decoded.XY[2 * t + 1], decoded.Z[t], u);
          for (int c = 0; c < K; ++c)
          {
            u[c] *= std::max(decoded.Z[t], 1.f / 16.f);
          }
        }
        l.M = level == 0 ? unweighted : ReduceTwice(unweighted, map.W, map.H);
      }
      m.Computed.push_back(l);
    }
  }
  return m;
}

// Moments at (u, v, lod) as the shader's mlVisibleNormal reads them for a layout.
void Lookup(const Moments& m, Layout layout, float u, float v, float lod, float* out)
{
  const float first = static_cast<float>(NormalMomentFirstStoredLevel);
  if (layout == Layout::Float || layout == Layout::Dropped || lod >= first)
  {
    Trilinear(m.Chain, u, v, layout == Layout::Float ? lod : lod - first, out);
    return;
  }
  std::fill(out, out + K, 0.f);
  const int level = static_cast<int>(lod);
  const float f = lod - static_cast<float>(level);
  AddBilinear(m.Computed[static_cast<size_t>(level)], u, v, 1.f - f, out);
  if (f > 0.f)
  {
    if (level + 1 < NormalMomentFirstStoredLevel)
    {
      AddBilinear(m.Computed[static_cast<size_t>(level + 1)], u, v, f, out);
    }
    else
    {
      AddBilinear(m.Chain[0], u, v, f, out);
    }
  }
}

// mlVisibleNormal's formula with the bake's depth scale (s = 1, so r = 1): S v / E[w n].v.
void VisibleNormal(const float* m, const float v[3], float n[3])
{
  const float r = 1.f;
  const float projected = v[0] * m[6] + v[1] * m[7] + v[2];
  if (projected <= 0.25f * v[2])
  {
    n[0] = m[4] / r;
    n[1] = m[5] / r;
    n[2] = m[3] / r;
    return;
  }
  n[0] = (m[0] * v[0] + m[2] * v[1] + m[4] * v[2]) / (projected * r);
  n[1] = (m[2] * v[0] + m[1] * v[1] + m[5] * v[2]) / (projected * r);
  n[2] = (m[4] * v[0] + m[5] * v[1] + m[3] * v[2]) / (projected * r);
}

struct NormalDifference
{
  double MeanDegrees = 0.0, MaxDegrees = 0.0; // direction
  double MeanLength = 0.0, MaxLength = 0.0;   // |length difference|, lengths clamped to 1
};

// The visible normals of a layout against the float moments' over uv, lod in (0, 4] and views
// from head-on to 80 degrees.
NormalDifference CompareWithFloat(const NormalMap& map, Layout layout)
{
  const Moments reference = BuildMoments(map, Layout::Float);
  const Moments tested = BuildMoments(map, layout);
  NormalDifference d;
  long long count = 0;
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.f, 1.f);
  for (int sample = 0; sample < 4000; ++sample)
  {
    const float u = unit(rng), v = unit(rng);
    const float lod = 0.05f + 3.95f * unit(rng);
    const float theta = 80.f * unit(rng) * 3.14159265f / 180.f, phi = 6.2831853f * unit(rng);
    const float view[3] = { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi),
      std::cos(theta) };
    float a[K], b[K], na[3], nb[3];
    Lookup(reference, Layout::Float, u, v, lod, a);
    Lookup(tested, layout, u, v, lod, b);
    VisibleNormal(a, view, na);
    VisibleNormal(b, view, nb);
    const double la = std::sqrt(na[0] * na[0] + na[1] * na[1] + na[2] * na[2]);
    const double lb = std::sqrt(nb[0] * nb[0] + nb[1] * nb[1] + nb[2] * nb[2]);
    const double c = (na[0] * nb[0] + na[1] * nb[1] + na[2] * nb[2]) / std::max(la * lb, 1e-12);
    const double degrees = std::acos(std::min(std::max(c, -1.0), 1.0)) * 180.0 / 3.14159265358979;
    d.MeanDegrees += degrees;
    d.MaxDegrees = std::max(d.MaxDegrees, degrees);
    // The length dims the light as the shader clamps it (mlNormalLength).
    const double ca = std::min(std::max(la, 1e-3), 1.0), cb = std::min(std::max(lb, 1e-3), 1.0);
    d.MaxLength = std::max(d.MaxLength, std::abs(ca - cb));
    d.MeanLength += std::abs(ca - cb);
    ++count;
  }
  d.MeanDegrees /= static_cast<double>(count);
  d.MeanLength /= static_cast<double>(count);
  return d;
}
} // namespace

TEST(CompactNormalMoments, LevelsAreSuccessiveBoxReductions)
{
  // Odd sizes: the last column / row of an odd level is left out, a size of 1 kept.
  const NormalMap map = BakedNormals(ReliefPattern::Stone, 37, 22, 0.1f);
  std::vector<float> level = NormalMomentLevel(map.XY.data(), map.Z.data(), map.W, map.H, 0);
  int w = map.W, h = map.H;
  for (size_t t = 0; t < map.Z.size(); ++t)
  {
    // Level 0: one normal's moments, w n n^T with E[w nz] = 1 (no wall steeper than the clamp).
    const float* m = &level[K * t];
    EXPECT_NEAR(m[0] * m[3], m[4] * m[4], 1e-5f);
    const float length = std::sqrt(
      map.XY[2 * t] * map.XY[2 * t] + map.XY[2 * t + 1] * map.XY[2 * t + 1] + map.Z[t] * map.Z[t]);
    EXPECT_NEAR(m[3], map.Z[t] / length, 1e-5f);
    EXPECT_NEAR(m[6] * m[3], m[4], 1e-5f); // w nx nz = (w nx) nz
  }
  for (int l = 1; l <= 5; ++l)
  {
    level = ReduceTwice(level, w, h);
    w = std::max(1, w / 2);
    h = std::max(1, h / 2);
    const std::vector<float> direct =
      NormalMomentLevel(map.XY.data(), map.Z.data(), map.W, map.H, l);
    ASSERT_EQ(direct.size(), level.size()) << "level " << l;
    for (size_t i = 0; i < direct.size(); ++i)
    {
      ASSERT_NEAR(direct[i], level[i], 1e-5f) << "level " << l << ", value " << i;
    }
  }
}

// The compact layout's visible normal is the float moments' within a stated tolerance; the
// layout without levels 0 and 1 (not reconstructed) and the one reconstructing them without the
// area weight both fail it.
TEST(CompactNormalMoments, FilterAsFloatMoments)
{
  // Tolerance: 8-bit octahedral normals are within about half a degree of the float ones, and
  // half floats keep 11 bits. Measured: Stone mean 0.031, max 0.65 degrees, length max 0.004;
  // Bricks 0.038, 1.03 degrees, 0.018 (grazing views divide by a small projected area).
  // Levels 0 and 1 dropped: 2.7 / 7.3 degrees mean; unweighted 0.43 / 4.7 degrees mean.
  const double meanDegrees = 0.25, maxDegrees = 2.0, maxLength = 0.03;
  for (ReliefPattern pattern : { ReliefPattern::Stone, ReliefPattern::Bricks })
  {
    const NormalMap map = BakedNormals(pattern, 128, 128, 0.08f);
    const char* name = pattern == ReliefPattern::Stone ? "Stone" : "Bricks";
    const NormalDifference compact = CompareWithFloat(map, Layout::Compact);
    const NormalDifference dropped = CompareWithFloat(map, Layout::Dropped);
    const NormalDifference unweighted = CompareWithFloat(map, Layout::Unweighted);
    for (auto [what, d] : { std::pair<const char*, NormalDifference>{ "compact", compact },
           { "levels 0-1 dropped", dropped }, { "unweighted", unweighted } })
    {
      std::cout << name << ", " << what << " against float moments: visible normal mean "
                << d.MeanDegrees << " deg, max " << d.MaxDegrees << " deg; length mean "
                << d.MeanLength << ", max " << d.MaxLength << std::endl;
    }
    EXPECT_LE(compact.MeanDegrees, meanDegrees) << name;
    EXPECT_LE(compact.MaxDegrees, maxDegrees) << name;
    EXPECT_LE(compact.MaxLength, maxLength) << name;
    EXPECT_TRUE(dropped.MeanDegrees > meanDegrees || dropped.MaxDegrees > maxDegrees ||
      dropped.MaxLength > maxLength)
      << name << ": negative case, levels 0 and 1 read from level 2";
    EXPECT_TRUE(unweighted.MeanDegrees > meanDegrees || unweighted.MaxDegrees > maxDegrees ||
      unweighted.MaxLength > maxLength)
      << name << ": negative case, moments without the area weight";
  }
}

// The moments of the surface a depth map defines (SurfaceNormalMomentLevel). A plane: those of its
// one normal, as NormalMomentLevel gives them from that normal. Stripes a texel wide (depth 0, 1,
// 0, 1 from column to column): the bilinear surface's slope is one depth unit per texel
// everywhere, half the quarters rising and half falling, so each interior texel's mean normal is
// flat but its second moment holds the spread, E[w nx^2] = (k w)^2 / sqrt(1 + (k w)^2), and
// E[w nz^2] = E[nz] = 1 / sqrt(1 + (k w)^2). The Sobel normals of the same stripes are flat and
// spread nothing: the negative case.
TEST(CompactNormalMoments, SurfaceMomentsHoldTheSpreadInsideATexel)
{
  const int w = 16, h = 12;
  const float k = 0.05f;
  std::vector<float> plane(static_cast<size_t>(w) * h), stripes(plane.size());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      plane[static_cast<size_t>(j) * w + i] = 0.02f * static_cast<float>(i) + 0.01f * j;
      stripes[static_cast<size_t>(j) * w + i] = static_cast<float>(i % 2);
    }
  }
  float n[3], expected[K];
  NormalFromGradient(0.02f, 0.01f, w, k, n);
  NormalMoments(n[0], n[1], n[2], expected);
  const std::vector<float> planeMoments = SurfaceNormalMomentLevel(plane.data(), w, h, k, 0);
  for (int j = 1; j + 1 < h; ++j)
  {
    for (int i = 1; i + 1 < w; ++i)
    {
      for (int c = 0; c < K; ++c)
      {
        ASSERT_NEAR(planeMoments[K * (static_cast<size_t>(j) * w + i) + c], expected[c], 1e-5f)
          << "texel " << i << ", " << j << ", moment " << c;
      }
    }
  }

  const double slope = static_cast<double>(k) * w;
  const double spread = slope * slope / std::sqrt(1.0 + slope * slope);
  const double nz = 1.0 / std::sqrt(1.0 + slope * slope);
  const std::vector<float> surface = SurfaceNormalMomentLevel(stripes.data(), w, h, k, 0);
  std::vector<float> rgba(4 * stripes.size()), xy(2 * stripes.size()), z(stripes.size());
  ComputeReliefTexture(stripes.data(), w, h, k, BorderMode::Clamp, rgba.data());
  for (size_t t = 0; t < stripes.size(); ++t)
  {
    xy[2 * t] = 2.f * rgba[4 * t] - 1.f;
    xy[2 * t + 1] = 2.f * rgba[4 * t + 1] - 1.f;
    z[t] = 2.f * rgba[4 * t + 2] - 1.f;
  }
  const std::vector<float> sobel = NormalMomentLevel(xy.data(), z.data(), w, h, 0);
  for (int j = 1; j + 1 < h; ++j)
  {
    for (int i = 1; i + 1 < w; ++i)
    {
      const float* m = &surface[K * (static_cast<size_t>(j) * w + i)];
      EXPECT_NEAR(m[0], spread, 1e-5) << "texel " << i << ", " << j;
      EXPECT_NEAR(m[3], nz, 1e-5) << "texel " << i << ", " << j;
      EXPECT_NEAR(m[6], 0.0, 1e-6) << "texel " << i << ", " << j;
      EXPECT_LT(sobel[K * (static_cast<size_t>(j) * w + i)], 0.01 * spread)
        << "negative: the Sobel normals of the stripes are flat";
    }
  }
}
