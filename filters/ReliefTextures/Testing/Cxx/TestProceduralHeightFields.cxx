// SPDX-License-Identifier: BSD-3-Clause
// Procedural depth maps (core/ProceduralHeightFields.h) and vtkProceduralReliefSource.
#include "MathConstants.h"
#include "ProceduralHeightFields.h"
#include "vtkProceduralReliefSource.h"

#include "MesolightTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <vector>

using mesolight::HeightFieldParameters;
using mesolight::ReliefPattern;

namespace
{
struct Maps
{
  std::vector<float> Depth;
  std::vector<std::uint8_t> Albedo;
};

Maps Generate(const HeightFieldParameters& p, int w, int h)
{
  Maps m{ std::vector<float>(static_cast<size_t>(w) * h),
    std::vector<std::uint8_t>(3 * static_cast<size_t>(w) * h) };
  mesolight::GenerateHeightField(p, w, h, m.Depth.data(), m.Albedo.data());
  return m;
}

HeightFieldParameters WithPattern(ReliefPattern pattern)
{
  HeightFieldParameters p;
  p.Pattern = pattern;
  return p;
}

const ReliefPattern AllPatterns[] = { ReliefPattern::Bricks, ReliefPattern::Stone,
  ReliefPattern::HemisphereTorus, ReliefPattern::Flat, ReliefPattern::SineWave };
}

TEST(ProceduralHeightFields, DeterministicAndInRange)
{
  for (ReliefPattern pattern : AllPatterns)
  {
    HeightFieldParameters p = WithPattern(pattern);
    p.Seed = 1234;
    const Maps a = Generate(p, 67, 41);
    const Maps b = Generate(p, 67, 41);
    EXPECT_EQ(a.Depth, b.Depth) << "pattern " << static_cast<int>(pattern);
    EXPECT_EQ(a.Albedo, b.Albedo) << "pattern " << static_cast<int>(pattern);
    const auto [lo, hi] = std::minmax_element(a.Depth.begin(), a.Depth.end());
    EXPECT_GE(*lo, 0.f);
    EXPECT_LE(*hi, 1.f);
    for (float d : a.Depth)
    {
      ASSERT_TRUE(std::isfinite(d));
    }
  }
}

TEST(ProceduralHeightFields, StoneDependsOnSeedAndHasRelief)
{
  HeightFieldParameters p = WithPattern(ReliefPattern::Stone);
  p.Seed = 1;
  const Maps a = Generate(p, 64, 64);
  p.Seed = 2;
  const Maps b = Generate(p, 64, 64);
  size_t differing = 0;
  for (size_t k = 0; k < a.Depth.size(); ++k)
  {
    differing += a.Depth[k] != b.Depth[k] ? 1 : 0;
  }
  EXPECT_GT(differing, a.Depth.size() / 2);
  const auto [lo, hi] = std::minmax_element(a.Depth.begin(), a.Depth.end());
  EXPECT_GT(*hi - *lo, 0.4f) << "stone should be rough, not flat";
}

TEST(ProceduralHeightFields, HemisphereIsResolutionIndependent)
{
  const HeightFieldParameters p = WithPattern(ReliefPattern::HemisphereTorus);
  const Maps coarse = Generate(p, 64, 64);
  const Maps fine = Generate(p, 128, 128);
  // Each 64-texel centre (2i+1)/128 lies halfway between four 128-texel centres: compare
  // with their bilinear interpolation (the mean).
  std::vector<double> errors;
  for (int j = 0; j < 64; ++j)
  {
    for (int i = 0; i < 64; ++i)
    {
      const double interp = 0.25 *
        (fine.Depth[(2 * j) * 128 + 2 * i] + fine.Depth[(2 * j) * 128 + 2 * i + 1] +
          fine.Depth[(2 * j + 1) * 128 + 2 * i] + fine.Depth[(2 * j + 1) * 128 + 2 * i + 1]);
      errors.push_back(std::fabs(interp - coarse.Depth[j * 64 + i]));
      // Same (u, v) gives exactly the same value at any resolution.
      const float u = (i + 0.5f) / 64.f;
      const float v = (j + 0.5f) / 64.f;
      ASSERT_EQ(coarse.Depth[j * 64 + i], mesolight::SampleHeightField(p, u, v, nullptr));
    }
  }
  std::sort(errors.begin(), errors.end());
  double mean = 0;
  for (double e : errors)
  {
    mean += e;
  }
  mean /= errors.size();
  EXPECT_LT(mean, 0.005);
  EXPECT_LT(errors[errors.size() * 95 / 100], 0.02); // only the steep rims differ more
}

TEST(ProceduralHeightFields, HemisphereTorusShape)
{
  const HeightFieldParameters p = WithPattern(ReliefPattern::HemisphereTorus);
  EXPECT_FLOAT_EQ(
    mesolight::SampleHeightField(p, 0.02f, 0.02f, nullptr), mesolight::HemisphereTorusBaseDepth);
  EXPECT_NEAR(mesolight::SampleHeightField(p, 0.28f, 0.5f, nullptr), 0.f, 1e-5); // apex
  // The torus ring: high on the ring, the base in the hole.
  EXPECT_LT(mesolight::SampleHeightField(p, 0.72f + 0.15f, 0.5f, nullptr), 0.6f);
  EXPECT_FLOAT_EQ(
    mesolight::SampleHeightField(p, 0.72f, 0.5f, nullptr), mesolight::HemisphereTorusBaseDepth);
}

TEST(ProceduralHeightFields, BricksHaveDeepMortar)
{
  HeightFieldParameters p = WithPattern(ReliefPattern::Bricks);
  p.BrickRows = 8;
  p.BrickColumns = 4;
  p.MortarWidth = 0.15f;
  const int n = 256;
  const Maps m = Generate(p, n, n);
  // Texel rows straddling the horizontal joints (v = k / 8) vs rows at brick mid-height.
  double joints = 0;
  double bricks = 0;
  for (int k = 1; k < 8; ++k)
  {
    const int jointRow = k * n / 8;          // centre v = (32k + 0.5)/256, inside the joint
    const int brickRow = k * n / 8 - n / 16; // mid-height of course k-1
    for (int i = 0; i < n; ++i)
    {
      joints += m.Depth[jointRow * n + i];
      bricks += m.Depth[brickRow * n + i];
    }
  }
  joints /= 7.0 * n;
  bricks /= 7.0 * n;
  EXPECT_GT(joints, 0.75);
  EXPECT_GT(joints - bricks, 0.4) << "mortar must be deeper than bricks";
  // Brick faces are near the top.
  EXPECT_LT(mesolight::SampleHeightField(p, 0.125f, 1.f / 16.f, nullptr), 0.15f);
  // Brick colours vary per brick, mortar is grey.
  std::uint8_t c1[3];
  std::uint8_t c2[3];
  std::uint8_t mortar[3];
  mesolight::SampleHeightField(p, 0.125f, 1.f / 16.f, c1);
  mesolight::SampleHeightField(p, 0.375f, 1.f / 16.f, c2);
  mesolight::SampleHeightField(p, 0.3f, 0.25f, mortar);
  EXPECT_GT(c1[0], c1[2] + 40) << "bricks are reddish";
  EXPECT_NE(std::memcmp(c1, c2, 3), 0) << "per-brick colour variation";
  EXPECT_LT(std::abs(int(mortar[0]) - int(mortar[2])), 30) << "mortar is grey";
}

TEST(ProceduralHeightFields, SineWaveAndFlatAreAnalytic)
{
  HeightFieldParameters p = WithPattern(ReliefPattern::SineWave);
  p.SineFrequency[0] = 2;
  p.SineFrequency[1] = 3;
  const int w = 40;
  const int h = 30;
  const Maps m = Generate(p, w, h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const double u = (i + 0.5) / w;
      const double v = (j + 0.5) / h;
      const double expected = 0.5 +
        0.5 * std::sin(2 * mesolight::Pi<double> * 2 * u) *
          std::cos(2 * mesolight::Pi<double> * 3 * v);
      ASSERT_NEAR(m.Depth[j * w + i], expected, 1e-5) << i << "," << j;
    }
  }
  p = WithPattern(ReliefPattern::Flat);
  p.FlatDepth = 0.25f;
  for (float d : Generate(p, 5, 3).Depth)
  {
    EXPECT_EQ(d, 0.25f);
  }
}

TEST(vtkProceduralReliefSource, OutputsAndDeterminism)
{
  vtkNew<vtkProceduralReliefSource> source;
  source->SetPatternToStone();
  source->SetResolution(48, 32);
  source->SetSeed(7);
  source->Update();
  vtkImageData* depth = source->GetDepthOutput();
  vtkImageData* albedo = source->GetAlbedoOutput();
  int dims[3];
  depth->GetDimensions(dims);
  EXPECT_EQ(dims[0], 48);
  EXPECT_EQ(dims[1], 32);
  EXPECT_EQ(dims[2], 1);
  vtkDataArray* d = depth->GetPointData()->GetScalars();
  ASSERT_NE(d, nullptr);
  EXPECT_STREQ(d->GetName(), "Depth");
  EXPECT_EQ(d->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(d->GetNumberOfComponents(), 1);
  vtkDataArray* a = albedo->GetPointData()->GetScalars();
  ASSERT_NE(a, nullptr);
  EXPECT_STREQ(a->GetName(), "Albedo");
  EXPECT_EQ(a->GetDataType(), VTK_UNSIGNED_CHAR);
  EXPECT_EQ(a->GetNumberOfComponents(), 3);
  albedo->GetDimensions(dims);
  EXPECT_EQ(dims[0], 48);
  EXPECT_EQ(dims[1], 32);

  // Same as the core, texel for texel (SMP chunks must not change anything).
  HeightFieldParameters p = WithPattern(ReliefPattern::Stone);
  p.Seed = 7;
  const Maps m = Generate(p, 48, 32);
  auto* values = static_cast<float*>(d->GetVoidPointer(0));
  EXPECT_TRUE(std::equal(m.Depth.begin(), m.Depth.end(), values));
  auto* colours = static_cast<unsigned char*>(a->GetVoidPointer(0));
  EXPECT_TRUE(std::equal(m.Albedo.begin(), m.Albedo.end(), colours));

  // A second source with the same settings gives the same image; another seed does not.
  vtkNew<vtkProceduralReliefSource> again;
  again->SetPatternToStone();
  again->SetResolution(48, 32);
  again->SetSeed(7);
  again->Update();
  auto* values2 =
    static_cast<float*>(again->GetDepthOutput()->GetPointData()->GetScalars()->GetVoidPointer(0));
  EXPECT_TRUE(std::equal(values, values + 48 * 32, values2));
  again->SetSeed(8);
  again->Update();
  values2 =
    static_cast<float*>(again->GetDepthOutput()->GetPointData()->GetScalars()->GetVoidPointer(0));
  EXPECT_FALSE(std::equal(values, values + 48 * 32, values2));
}

TEST(vtkProceduralReliefSource, PatternNamesAndClamping)
{
  vtkNew<vtkProceduralReliefSource> source;
  mesolight_test::MessageCapture* capture = mesolight_test::MessageCapture::New();
  capture->Watch(source);
  for (int p = 0; p < vtkProceduralReliefSource::NUMBER_OF_PATTERNS; ++p)
  {
    const char* name = vtkProceduralReliefSource::GetPatternName(p);
    ASSERT_NE(name, nullptr);
    EXPECT_TRUE(source->SetPatternByName(name));
    EXPECT_EQ(source->GetPattern(), p);
  }
  EXPECT_TRUE(source->SetPatternByName("hemispheretorus"));
  EXPECT_EQ(source->GetPattern(), vtkProceduralReliefSource::HEMISPHERE_TORUS);
  EXPECT_EQ(vtkProceduralReliefSource::GetPatternName(99), nullptr);
  EXPECT_FALSE(source->SetPatternByName("Marble"));
  EXPECT_EQ(source->GetPattern(), vtkProceduralReliefSource::HEMISPHERE_TORUS);
  EXPECT_TRUE(capture->HasError("Marble")) << capture->AllErrors();
  EXPECT_FALSE(source->SetPatternByName(nullptr));

  source->SetResolution(0, 100000);
  EXPECT_EQ(source->GetResolution()[0], 1);
  EXPECT_EQ(source->GetResolution()[1], 16384);
  source->SetResolution(1, 1);
  source->SetPatternToFlat();
  source->SetFlatDepth(2.0); // clamped
  source->Update();
  vtkDataArray* d = source->GetDepthOutput()->GetPointData()->GetScalars();
  ASSERT_EQ(d->GetNumberOfTuples(), 1);
  EXPECT_EQ(d->GetComponent(0, 0), 1.0);
  capture->Delete();
}
