// SPDX-License-Identifier: BSD-3-Clause
// The shading normal of detail a texel or two wide: the relief mapper must shade the surface it
// marches, the bilinear interpolation of the depth texels, as the exact CPU intersector and the
// path tracer do. Analytic case: depth alternating 0, 1, 0, 1 from texel column to column is a
// triangle wave whose slope is one depth unit per texel everywhere, so under a light straight
// overhead, seen straight down, a white Lambertian wall reads 255 / sqrt(1 + (s w)^2) at every
// pixel (s the depth scale in wall widths, w texels per wall width). A 3 x 3 Sobel normal, the
// normal vtkReliefTextureFilter bakes, is flat there (its central differences are all zero) and
// reads 255: the negative case, the same texture without its baked depth scale, whose normals
// the mapper cannot tell from a normal map made apart and so shades as given.
#include "ImageCompare.h"
#include "TestReliefTestUtilities.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkActor.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <string>

namespace
{
using namespace mesolight;

constexpr int Texels = 64;
constexpr double DepthScale = 0.01; // a world slope of s w = 0.64, n . l = 0.842
constexpr int Pixels = 240;         // 3.75 pixels per texel: the base level shades every pixel

struct Shading
{
  double Mean = 0.0; // mean rendered value, 8-bit levels
  double MaxError = 0.0;
};

Shading MeasureStripes(const char* method, bool keepBakedScale)
{
  auto depth = test::MakeDepthMap(Texels, Texels,
    [](double u, double) { return static_cast<int>(std::floor(u * Texels)) % 2 == 0 ? 0.0 : 1.0; });
  auto relief = test::BakeRelief(depth, DepthScale);
  if (!keepBakedScale)
  {
    relief->GetFieldData()->RemoveArray("MesolightDepthScale");
  }
  vtkNew<vtkReliefMapper> mapper;
  auto actor = test::UnitSquareRelief(mapper, relief, DepthScale);
  EXPECT_TRUE(mapper->GetReliefProperty()->SetMethodByName(method)) << method;
  const Frame frame = test::CaptureTopDown({ actor }, Pixels);

  const double slope = DepthScale * Texels;
  const double expected = 255.0 / std::sqrt(1.0 + slope * slope);
  Shading s;
  long long count = 0;
  // A border of 8 pixels (two texels) left out: the edge texels are clamped.
  for (int y = 8; y < Pixels - 8; ++y)
  {
    for (int x = 8; x < Pixels - 8; ++x)
    {
      const double rendered = frame.Rgb[3 * (size_t(y) * Pixels + x)];
      s.Mean += rendered;
      s.MaxError = std::max(s.MaxError, std::abs(rendered - expected));
      ++count;
    }
  }
  s.Mean /= double(count);
  std::cout << "[stripes a texel wide, " << method
            << (keepBakedScale ? "" : ", baked depth scale removed") << "] mean " << s.Mean
            << " levels (analytic " << expected << "), largest |error| " << s.MaxError << std::endl;
  return s;
}

double Analytic()
{
  const double slope = DepthScale * Texels;
  return 255.0 / std::sqrt(1.0 + slope * slope);
}
} // namespace

// The default method and bump mapping (which shades the undisplaced point with the same normal).
TEST(ReliefShadingNormal, DetailATexelWideShadesWithTheSurfacesOwnSlope)
{
  for (const char* method : { "relief", "bump" })
  {
    const Shading s = MeasureStripes(method, true);
    EXPECT_NEAR(s.Mean, Analytic(), 2.0) << method;
    EXPECT_LT(s.MaxError, 4.0) << method;
  }
}

// Negative: the Sobel normals (the texture's, shaded as given once the texture does not say
// which depth scale they were baked at) are flat on these stripes, about 40 levels too bright.
TEST(ReliefShadingNormal, TheSmoothedNormalFailsTheCheck)
{
  const Shading s = MeasureStripes("relief", false);
  EXPECT_GT(s.Mean, Analytic() + 20.0);
}
