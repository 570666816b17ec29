// SPDX-License-Identifier: BSD-3-Clause
// Sobel gradient and relief-texture packing (core/SobelNormals.h) against analytic values.
#include "MathConstants.h"
#include "SobelNormals.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using mesolight::BorderMode;

namespace
{

// h(u, v) = 0.5 + 0.25 sin(2 pi u) cos(2 pi v) and its partial derivatives.
double H(double u, double v)
{
  return 0.5 +
    0.25 * std::sin(2 * mesolight::Pi<double> * u) * std::cos(2 * mesolight::Pi<double> * v);
}
double DHdu(double u, double v)
{
  return 0.5 * mesolight::Pi<double> * std::cos(2 * mesolight::Pi<double> * u) *
    std::cos(2 * mesolight::Pi<double> * v);
}
double DHdv(double u, double v)
{
  return -0.5 * mesolight::Pi<double> * std::sin(2 * mesolight::Pi<double> * u) *
    std::sin(2 * mesolight::Pi<double> * v);
}

struct SampledMap
{
  int W;
  int Hgt;
  std::vector<float> Depth;
  double U(double i) const { return (i + 0.5) / W; }
  double V(double j) const { return (j + 0.5) / Hgt; }
  float At(int i, int j) const { return Depth[j * W + i]; }
};

// Non-square on purpose, so that swapped dimensions cannot pass.
SampledMap MakeSine(int w = 64, int h = 48)
{
  SampledMap m{ w, h, std::vector<float>(static_cast<size_t>(w) * h) };
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      m.Depth[j * w + i] = static_cast<float>(H(m.U(i), m.V(j)));
    }
  }
  return m;
}

std::vector<float> Gradient(const SampledMap& m, BorderMode mode)
{
  std::vector<float> g(2 * m.Depth.size());
  mesolight::ComputeSobelGradient(m.Depth.data(), m.W, m.Hgt, mode, g.data());
  return g;
}

// Interior/smoothing tolerance: O(h^2) central difference + [1 2 1] smoothing, amplitude pi/2.
constexpr double TightTolerance = 0.015;
}

TEST(SobelGradient, WrapMatchesAnalyticEverywhere)
{
  const SampledMap m = MakeSine();
  const std::vector<float> g = Gradient(m, BorderMode::Wrap);
  double maxErr = 0;
  for (int j = 0; j < m.Hgt; ++j)
  {
    for (int i = 0; i < m.W; ++i)
    {
      // Per-texel derivative -> per-unit derivative: multiply by the number of texels.
      const double gu = g[2 * (j * m.W + i)] * m.W;
      const double gv = g[2 * (j * m.W + i) + 1] * m.Hgt;
      maxErr = std::max(maxErr, std::fabs(gu - DHdu(m.U(i), m.V(j))));
      maxErr = std::max(maxErr, std::fabs(gv - DHdv(m.U(i), m.V(j))));
    }
  }
  // h is periodic on the unit square, so wrap mode is O(h^2) at the borders too.
  EXPECT_LT(maxErr, TightTolerance);
}

TEST(SobelGradient, ClampMatchesAnalyticInterior)
{
  const SampledMap m = MakeSine();
  const std::vector<float> g = Gradient(m, BorderMode::Clamp);
  double maxErr = 0;
  for (int j = 1; j < m.Hgt - 1; ++j)
  {
    for (int i = 1; i < m.W - 1; ++i)
    {
      maxErr = std::max(maxErr, std::fabs(g[2 * (j * m.W + i)] * m.W - DHdu(m.U(i), m.V(j))));
      maxErr = std::max(maxErr, std::fabs(g[2 * (j * m.W + i) + 1] * m.Hgt - DHdv(m.U(i), m.V(j))));
    }
  }
  EXPECT_LT(maxErr, TightTolerance);
}

TEST(SobelGradient, ClampBordersAreOneSidedDifferences)
{
  const SampledMap m = MakeSine();
  const std::vector<float> g = Gradient(m, BorderMode::Clamp);

  // Left/right columns: d/du is maximal there (cos(2 pi u) ~ 1), the one-sided difference
  // is accurate, a naive (d(1) - d(0)) / 2 "central" difference halves it.
  double maxErr = 0;
  double maxNaiveErr = 0;
  for (int j = 1; j < m.Hgt - 1; ++j)
  {
    for (int i : { 0, m.W - 1 })
    {
      const int im = std::max(i - 1, 0);
      const int ip = std::min(i + 1, m.W - 1);
      const double gu = g[2 * (j * m.W + i)] * m.W;
      maxErr = std::max(maxErr, std::fabs(gu - DHdu(m.U(i), m.V(j))));
      // The same Sobel stencil divided by 8 regardless of the clamped index distance.
      const double naive = ((m.At(ip, j - 1) + 2.0 * m.At(ip, j) + m.At(ip, j + 1)) -
                             (m.At(im, j - 1) + 2.0 * m.At(im, j) + m.At(im, j + 1))) /
        8.0 * m.W;
      maxNaiveErr = std::max(maxNaiveErr, std::fabs(naive - DHdu(m.U(i), m.V(j))));
      // Exactly the derivative between the two texels used (midpoint), O(h^2).
      const double mid = 0.5 * (m.U(im) + m.U(ip));
      EXPECT_NEAR(gu, DHdu(mid, m.V(j)), TightTolerance) << "i=" << i << " j=" << j;
    }
  }
  const double borderTolerance = 0.03;
  EXPECT_LT(maxErr, borderTolerance);
  EXPECT_GT(maxNaiveErr, 10 * borderTolerance) << "the negative check must be able to fail";

  // Bottom/top rows: one-sided differences are O(h) away from the texel's own derivative
  // but O(h^2) from the midpoint derivative; the naive version is off by half.
  double maxMidErr = 0;
  double maxNaiveMidErr = 0;
  for (int i = 1; i < m.W - 1; ++i)
  {
    for (int j : { 0, m.Hgt - 1 })
    {
      const int jm = std::max(j - 1, 0);
      const int jp = std::min(j + 1, m.Hgt - 1);
      const double gv = g[2 * (j * m.W + i) + 1] * m.Hgt;
      const double mid = 0.5 * (m.V(jm) + m.V(jp));
      maxMidErr = std::max(maxMidErr, std::fabs(gv - DHdv(m.U(i), mid)));
      maxNaiveMidErr = std::max(maxNaiveMidErr, std::fabs(0.5 * gv - DHdv(m.U(i), mid)));
      EXPECT_NEAR(gv, DHdv(m.U(i), m.V(j)), 0.12) << "i=" << i << " j=" << j;
    }
  }
  EXPECT_LT(maxMidErr, TightTolerance);
  EXPECT_GT(maxNaiveMidErr, 3 * TightTolerance);
}

TEST(SobelGradient, ClampIsExactForLinearRamps)
{
  // d = a i + b j: every stencil, one-sided or not, must give exactly (a, b).
  const int w = 9;
  const int h = 7;
  const float a = 0.01f;
  const float b = -0.02f;
  std::vector<float> d(w * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      d[j * w + i] = 0.5f + a * i + b * j;
    }
  }
  std::vector<float> g(2 * w * h);
  mesolight::ComputeSobelGradient(d.data(), w, h, BorderMode::Clamp, g.data());
  for (int k = 0; k < w * h; ++k)
  {
    EXPECT_NEAR(g[2 * k], a, 1e-6) << "texel " << k;
    EXPECT_NEAR(g[2 * k + 1], b, 1e-6) << "texel " << k;
  }
}

TEST(ReliefTexture, NormalsMatchAnalyticNormal)
{
  const SampledMap m = MakeSine();
  const float k = 0.1f;
  std::vector<float> rgba(4 * m.Depth.size());
  mesolight::ComputeReliefTexture(m.Depth.data(), m.W, m.Hgt, k, BorderMode::Wrap, rgba.data());
  double maxErr = 0;
  for (int j = 0; j < m.Hgt; ++j)
  {
    for (int i = 0; i < m.W; ++i)
    {
      // Surface z = -k h(x, y), x = u, y = v H/W (square texels): n ~ (k dh/dx, k dh/dy, 1).
      double n[3] = { k * DHdu(m.U(i), m.V(j)),
        k * DHdv(m.U(i), m.V(j)) * m.W / static_cast<double>(m.Hgt), 1.0 };
      const double len = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
      const float* t = &rgba[4 * (j * m.W + i)];
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_GE(t[c], 0.f);
        EXPECT_LE(t[c], 1.f);
        maxErr = std::max(maxErr, std::fabs((2.0 * t[c] - 1.0) - n[c] / len));
      }
      EXPECT_EQ(t[3], m.At(i, j)) << "alpha must be the depth itself";
    }
  }
  EXPECT_LT(maxErr, 2e-3);
  // The slope is visible at all: normals are not all (0,0,1).
  EXPECT_GT(std::fabs(2.0 * rgba[0] - 1.0), 0.05);
}

TEST(ReliefTexture, DepthScaleZeroGivesFlatNormals)
{
  const SampledMap m = MakeSine(16, 16);
  std::vector<float> rgba(4 * m.Depth.size());
  mesolight::ComputeReliefTexture(m.Depth.data(), m.W, m.Hgt, 0.f, BorderMode::Clamp, rgba.data());
  for (size_t t = 0; t < m.Depth.size(); ++t)
  {
    EXPECT_FLOAT_EQ(rgba[4 * t], 0.5f);
    EXPECT_FLOAT_EQ(rgba[4 * t + 1], 0.5f);
    EXPECT_FLOAT_EQ(rgba[4 * t + 2], 1.f);
  }
}

TEST(ReliefTexture, OneByOneIsFlat)
{
  for (BorderMode mode : { BorderMode::Clamp, BorderMode::Wrap })
  {
    const float d = 0.3f;
    float g[2] = { -1.f, -1.f };
    mesolight::ComputeSobelGradient(&d, 1, 1, mode, g);
    EXPECT_EQ(g[0], 0.f);
    EXPECT_EQ(g[1], 0.f);
    float rgba[4];
    mesolight::ComputeReliefTexture(&d, 1, 1, 1.f, mode, rgba);
    EXPECT_FLOAT_EQ(rgba[0], 0.5f);
    EXPECT_FLOAT_EQ(rgba[1], 0.5f);
    EXPECT_FLOAT_EQ(rgba[2], 1.f);
    EXPECT_FLOAT_EQ(rgba[3], d);
  }
}

TEST(ReliefTexture, OneTexelWideMapsKeepTheOtherSlope)
{
  const int n = 12;
  std::vector<float> d(n);
  for (int k = 0; k < n; ++k)
  {
    d[k] = 0.05f * k; // slope 0.05 per texel
  }
  for (BorderMode mode : { BorderMode::Clamp, BorderMode::Wrap })
  {
    std::vector<float> g(2 * n);
    // 1 x n: a single column, slope along j.
    mesolight::ComputeSobelGradient(d.data(), 1, n, mode, g.data());
    for (int k = 1; k < n - 1; ++k)
    {
      EXPECT_EQ(g[2 * k], 0.f);
      EXPECT_NEAR(g[2 * k + 1], 0.05f, 1e-6);
    }
    // n x 1: a single row, slope along i.
    mesolight::ComputeSobelGradient(d.data(), n, 1, mode, g.data());
    for (int k = 1; k < n - 1; ++k)
    {
      EXPECT_NEAR(g[2 * k], 0.05f, 1e-6);
      EXPECT_EQ(g[2 * k + 1], 0.f);
    }
    if (mode == BorderMode::Clamp)
    {
      EXPECT_NEAR(g[0], 0.05f, 1e-6); // one-sided at the border
      EXPECT_NEAR(g[2 * (n - 1)], 0.05f, 1e-6);
    }
  }
  // The normal of a 1 x n map: x component 0, y from the slope.
  std::vector<float> rgba(4 * n);
  mesolight::ComputeReliefTexture(d.data(), 1, n, 0.5f, BorderMode::Clamp, rgba.data());
  float expected[3];
  mesolight::NormalFromGradient(0.f, 0.05f, 1, 0.5f, expected);
  EXPECT_FLOAT_EQ(rgba[4 * 5], 0.5f);
  EXPECT_NEAR(2 * rgba[4 * 5 + 1] - 1, expected[1], 1e-6);
  EXPECT_NEAR(2 * rgba[4 * 5 + 2] - 1, expected[2], 1e-6);
}

TEST(ReliefTexture, RowRangesComposeToTheWholeImage)
{
  const SampledMap m = MakeSine(33, 17);
  std::vector<float> whole(4 * m.Depth.size());
  std::vector<float> pieces(4 * m.Depth.size(), -1.f);
  mesolight::ComputeReliefTexture(
    m.Depth.data(), m.W, m.Hgt, 0.2f, BorderMode::Clamp, whole.data());
  for (int r = 0; r < m.Hgt; r += 5)
  {
    mesolight::ComputeReliefTextureRows(
      m.Depth.data(), m.W, m.Hgt, 0.2f, BorderMode::Clamp, r, r + 5, pieces.data());
  }
  EXPECT_EQ(whole, pieces);
}
