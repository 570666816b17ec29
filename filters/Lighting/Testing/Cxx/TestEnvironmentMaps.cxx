// SPDX-License-Identifier: BSD-3-Clause
// Lat-long conventions, solid angles, exact irradiance, SH9 and light-probe converters
// (core/EnvironmentMaps.h) against analytic values and hand-derived picture positions.
#include "EnvironmentMaps.h"
#include "LightingTestMaps.h"
#include "MathConstants.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <vector>

using mesolight::RgbImage;
using mesolight::test::Constant;

namespace
{

/// Pixel (i, j) nearest to the radiance-weighted mean direction of the pixels brighter than
/// half the maximum (the centre of a bright spot).
void Brightest(const RgbImage& image, int& bi, int& bj)
{
  float best = 0.0f;
  for (size_t k = 0; k < image.Rgb.size(); k += 3)
  {
    best = std::max(best, image.Rgb[k]);
  }
  double sum[3] = { 0, 0, 0 };
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      const float x = image.Pixel(i, j)[0];
      if (x > 0.5f * best)
      {
        double d[3];
        mesolight::DirectionFromMapUV(
          mesolight::PixelCenterU(i, image.Width), mesolight::PixelCenterV(j, image.Height), d);
        for (int c = 0; c < 3; ++c)
        {
          sum[c] += x * mesolight::PixelSolidAngle(j, image.Width, image.Height) * d[c];
        }
      }
    }
  }
  double u = 0.0;
  double v = 0.0;
  mesolight::MapUVFromDirection(sum, u, v);
  bi = std::min(image.Width - 1, static_cast<int>(u * image.Width));
  bj = std::min(image.Height - 1, static_cast<int>((1.0 - v) * image.Height));
}

/// Draws a bright disc of radius r (picture units) at (a, b) in a square S x S picture.
void Spot(RgbImage& picture, double a, double b, double r, float value)
{
  const int s = picture.Width;
  for (int j = 0; j < s; ++j)
  {
    for (int i = 0; i < s; ++i)
    {
      const double x = 2.0 * (i + 0.5) / s - 1.0;
      const double y = 2.0 * (j + 0.5) / s - 1.0;
      if ((x - a) * (x - a) + (y - b) * (y - b) <= r * r)
      {
        float* p = picture.Pixel(i, j);
        p[0] = p[1] = p[2] = value;
      }
    }
  }
}

/// Angular distance (degrees) between the centre of lat-long pixel (i, j) and d.
double DegreesFromPixel(int i, int j, int w, int h, const double d[3])
{
  // Written out independently of the library: v from the top, theta = pi v, phi = 2 pi u.
  const double u = (i + 0.5) / w;
  const double v = 1.0 - (j + 0.5) / h;
  const double p[3] = { std::sin(mesolight::Pi<double> * v) *
      std::cos(2 * mesolight::Pi<double> * u),
    std::sin(mesolight::Pi<double> * v) * std::sin(2 * mesolight::Pi<double> * u),
    std::cos(mesolight::Pi<double> * v) };
  const double c = p[0] * d[0] + p[1] * d[1] + p[2] * d[2];
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / mesolight::Pi<double>;
}
} // namespace

TEST(EnvironmentMaps, DirectionConvention)
{
  double d[3];
  mesolight::DirectionFromMapUV(0.3, 0.0, d); // top row: zenith
  EXPECT_NEAR(d[2], 1.0, 1e-12);
  mesolight::DirectionFromMapUV(0.0, 0.5, d); // u = 0 on the horizon: +X
  EXPECT_NEAR(d[0], 1.0, 1e-12);
  mesolight::DirectionFromMapUV(0.25, 0.5, d); // a quarter turn: +Y
  EXPECT_NEAR(d[1], 1.0, 1e-12);
  mesolight::DirectionFromMapUV(0.7, 1.0, d); // bottom row: nadir
  EXPECT_NEAR(d[2], -1.0, 1e-12);
  // VTK row order: the last row is the top.
  EXPECT_NEAR(mesolight::PixelCenterV(255, 256), 0.5 / 256, 1e-15);
  for (double u : { 0.01, 0.3, 0.62, 0.99 })
  {
    for (double v : { 0.05, 0.5, 0.93 })
    {
      double back[2];
      mesolight::DirectionFromMapUV(u, v, d);
      mesolight::MapUVFromDirection(d, back[0], back[1]);
      EXPECT_NEAR(back[0], u, 1e-12);
      EXPECT_NEAR(back[1], v, 1e-12);
    }
  }
}

TEST(EnvironmentMaps, SolidAnglesSumToFourPi)
{
  for (int h : { 1, 7, 256 })
  {
    const int w = 2 * h;
    double sum = 0.0;
    double moment[3] = { 0.0, 0.0, 0.0 };
    for (int j = 0; j < h; ++j)
    {
      sum += w * mesolight::PixelSolidAngle(j, w, h);
      for (int i = 0; i < w; ++i)
      {
        double m[3];
        mesolight::PixelMoment(i, j, w, h, m);
        for (int c = 0; c < 3; ++c)
        {
          moment[c] += m[c];
        }
      }
    }
    EXPECT_NEAR(sum, 4 * mesolight::Pi<double>, 1e-12);
    EXPECT_NEAR(moment[0], 0.0, 1e-12);
    EXPECT_NEAR(moment[2], 0.0, 1e-12);
  }
  // Rows near the poles are smaller than rows at the equator (the weighting matters).
  EXPECT_LT(
    mesolight::PixelSolidAngle(255, 512, 256), 0.02 * mesolight::PixelSolidAngle(128, 512, 256));
}

TEST(EnvironmentMaps, ExactIrradianceAnalyticCases)
{
  const int w = 512;
  const int h = 256;
  const float l = 2.0f;
  const mesolight::ExactIrradiance uniform(Constant(w, h, l));
  const double normals[][3] = { { 0, 0, 1 }, { 1, 0, 0 }, { 0, -1, 0 }, { 0.48, 0.6, -0.64 } };
  for (const auto& n : normals)
  {
    double e[3];
    uniform.Evaluate(n, e);
    EXPECT_NEAR(e[0], mesolight::Pi<double> * l,
      1e-4 * mesolight::Pi<double> * l); // furnace: pi L for every normal
    EXPECT_NEAR(e[2], mesolight::Pi<double> * l, 1e-4 * mesolight::Pi<double> * l);
  }
  // L only on the upper hemisphere: E(up) = pi L, E(horizontal) = pi L / 2, E(down) = 0.
  RgbImage sky = Constant(w, h, 0.0f);
  for (int j = h / 2; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      float* p = sky.Pixel(i, j);
      p[0] = p[1] = p[2] = l;
    }
  }
  const mesolight::ExactIrradiance upper(sky);
  const double up[3] = { 0, 0, 1 };
  const double side[3] = { std::sqrt(0.5), std::sqrt(0.5), 0 };
  const double down[3] = { 0, 0, -1 };
  double e[3];
  upper.Evaluate(up, e);
  EXPECT_NEAR(e[1], mesolight::Pi<double> * l, 1e-9);
  upper.Evaluate(side, e);
  EXPECT_NEAR(e[1], 0.5 * mesolight::Pi<double> * l, 1e-3 * mesolight::Pi<double> * l);
  upper.Evaluate(down, e);
  EXPECT_NEAR(e[1], 0.0, 1e-12);
}

TEST(EnvironmentMaps, SH9UniformAndLinear)
{
  const mesolight::SH9 sh = mesolight::ProjectSH9(Constant(256, 128, 1.0f));
  const double n[3] = { 0.6, 0.0, 0.8 };
  double e[3];
  mesolight::IrradianceSH9(sh, n, e);
  EXPECT_NEAR(e[0], mesolight::Pi<double>, 1e-3);
  // L(d) = max(0, z) style maps are captured to a few percent at the pole.
  RgbImage sky(256, 128);
  for (int j = 0; j < 128; ++j)
  {
    const double z = std::cos(mesolight::Pi<double> * mesolight::PixelCenterV(j, 128));
    for (int i = 0; i < 256; ++i)
    {
      float* p = sky.Pixel(i, j);
      p[0] = p[1] = p[2] = static_cast<float>(1.0 + z); // linear in z: exact in SH1
    }
  }
  const mesolight::SH9 linear = mesolight::ProjectSH9(sky);
  const mesolight::ExactIrradiance exact(sky);
  const double down[3] = { 0, 0, -1 };
  for (const double* m : { n, down })
  {
    double es[3];
    double ee[3];
    mesolight::IrradianceSH9(linear, m, es);
    exact.Evaluate(m, ee);
    EXPECT_NEAR(es[0], ee[0], 2e-3 * ee[0]);
  }
}

TEST(EnvironmentMaps, AngularMapToLatLong)
{
  // Camera looks along +X with +Z up: right = Forward x Up = -Y. By Debevec's formula
  // r = acos(d.Forward) / pi, +X is at the centre, +Z at (0, 0.5), +Y at (-0.5, 0) (left),
  // -Y at (0.5, 0).
  const int s = 256;
  RgbImage probe(s, s);
  Spot(probe, 0.0, 0.5, 0.03, 100.0f);
  RgbImage zenith = probe;
  const mesolight::ProbeView view;
  const int w = 256;
  const int h = 128;
  int bi = 0;
  int bj = 0;
  Brightest(mesolight::AngularMapToLatLong(zenith, view, w, h), bi, bj);
  const double z[3] = { 0, 0, 1 };
  EXPECT_LT(DegreesFromPixel(bi, bj, w, h, z), 3.0);

  RgbImage left(s, s);
  Spot(left, -0.5, 0.0, 0.03, 100.0f);
  Brightest(mesolight::AngularMapToLatLong(left, view, w, h), bi, bj);
  const double y[3] = { 0, 1, 0 };
  EXPECT_LT(DegreesFromPixel(bi, bj, w, h, y), 3.0) << bi << " " << bj;

  RgbImage centre(s, s);
  Spot(centre, 0.0, 0.0, 0.03, 100.0f);
  Brightest(mesolight::AngularMapToLatLong(centre, view, w, h), bi, bj);
  const double x[3] = { 1, 0, 0 };
  EXPECT_LT(DegreesFromPixel(bi, bj, w, h, x), 3.0);

  // Round trip lat-long -> angular map -> lat-long keeps a smooth map.
  RgbImage smooth(w, h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      double d[3];
      mesolight::DirectionFromMapUV(
        mesolight::PixelCenterU(i, w), mesolight::PixelCenterV(j, h), d);
      float* p = smooth.Pixel(i, j);
      p[0] = p[1] = p[2] = static_cast<float>(2.0 + d[0] + 0.5 * d[1] - 0.7 * d[2]);
    }
  }
  const RgbImage back =
    mesolight::AngularMapToLatLong(mesolight::LatLongToAngularMap(smooth, view, 512), view, w, h);
  double err = 0.0;
  for (size_t k = 0; k < back.Rgb.size(); ++k)
  {
    err = std::max(err, static_cast<double>(std::abs(back.Rgb[k] - smooth.Rgb[k])));
  }
  // Directions near -Forward sit on the rim, which is poorly sampled: allow a bit more there.
  EXPECT_LT(err, 0.25);
}

TEST(EnvironmentMaps, MirrorBallToLatLong)
{
  // Camera looks along +X (from -X) with +Z up: the centre reflects -X (behind the camera),
  // the rim reflects +X; +Z appears where the normal is the half vector of +Z and -X:
  // (a, b) = (0, 0.7071); +Y at (-0.7071, 0) (right = -Y).
  const int s = 256;
  const mesolight::ProbeView view;
  const int w = 256;
  const int h = 128;
  const double half = std::sqrt(0.5);
  struct Case
  {
    double A, B;
    double D[3];
  };
  const Case cases[] = { { 0.0, half, { 0, 0, 1 } }, { -half, 0.0, { 0, 1, 0 } },
    { 0.0, 0.0, { -1, 0, 0 } }, { half, 0.0, { 0, -1, 0 } } };
  for (const Case& c : cases)
  {
    RgbImage ball(s, s);
    Spot(ball, c.A, c.B, 0.02, 100.0f);
    int bi = 0;
    int bj = 0;
    Brightest(mesolight::MirrorBallToLatLong(ball, view, w, h), bi, bj);
    EXPECT_LT(DegreesFromPixel(bi, bj, w, h, c.D), 4.0)
      << "spot at (" << c.A << ", " << c.B << ") -> pixel " << bi << ", " << bj;
  }
  // Round trip of directions.
  for (const Case& c : cases)
  {
    double a = 0.0;
    double b = 0.0;
    mesolight::MirrorBallPointFromDirection(view, c.D, a, b);
    EXPECT_NEAR(a, c.A, 1e-9);
    EXPECT_NEAR(b, c.B, 1e-9);
  }
}

TEST(EnvironmentMaps, MergeWithMask)
{
  RgbImage a = Constant(4, 2, 10.0f);
  RgbImage b = Constant(4, 2, 2.0f);
  std::vector<float> mask = { 0, 1, 0.25f, 0.5f, 1, 1, 0, 0 };
  const RgbImage m = mesolight::MergeWithMask(a, b, mask);
  ASSERT_EQ(m.Width, 4);
  EXPECT_FLOAT_EQ(m.Pixel(0, 0)[0], 2.0f);
  EXPECT_FLOAT_EQ(m.Pixel(1, 0)[1], 10.0f);
  EXPECT_FLOAT_EQ(m.Pixel(2, 0)[2], 4.0f);
  EXPECT_EQ(mesolight::MergeWithMask(a, Constant(2, 2, 1.0f), mask).Width, 0);
}
