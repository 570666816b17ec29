// SPDX-License-Identifier: BSD-3-Clause
// The per-texel comparison and the bilateral texture filter (TextureComparison.h).
// 1. Cornell box against the path tracer at every texel centre: the filter must lower the p95
//    and the local-contrast error (the mottling), and the reference's own noise (two seeds)
//    must be well below the field's error, else the comparison measures the reference.
// 2. A shadow edge (a step of 5:1 with a +-3% checkerboard of noise on a floor texture): the
//    bilateral filter keeps the texels next to the step within 5% and removes most of the
//    noise; a box blur of the same width (the negative) moves them by far more.
#include "EmbreeScene.h"
#include "PathTracedTexels.h"
#include "PathTracer.h"
#include "Propagation.h"
#include "TextureComparison.h"
#include "VLFTestScenes.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>

namespace
{
using namespace mesolight;
using namespace mesolight::vlf;
using mesolight::vlftest::PathTraced;

TEST(VLFTextureFilter, LowersTheCornellBoxTexelErrors)
{
  LightFieldSettings settings;
  settings.Directions = 513;
  settings.RaysPerSide = 32;
  settings.TilesPerSide = 4;
  const TriangleScene cornell = MakeCornellBox();
  std::unique_ptr<LightField> field = LightField::Build(cornell, settings);
  Propagate(*field, 10); // 4 would leave ~9% of the light (later bounces) out of every texel
  const std::vector<TexelPoint> texels = SurfaceTexels(*field);
  ASSERT_GT(texels.size(), 1000u);
  const std::vector<glm::vec3> reference = PathTraced(cornell, *field, texels, 2048, 1);
  const std::vector<glm::vec3> second = PathTraced(cornell, *field, texels, 2048, 2);
  const TexelError noise = CompareTexels(*field, texels, second, reference);
  const TexelError before = CompareTexels(*field, texels, FieldAtTexels(*field, texels), reference);
  FilterTotalDiffuse(*field, TextureFilterSettings());
  const TexelError after = CompareTexels(*field, texels, FieldAtTexels(*field, texels), reference);
  std::printf("reference noise (two seeds): %s\nfield:          %s\nfiltered:       %s\n",
    noise.Describe().c_str(), before.Describe().c_str(), after.Describe().c_str());
  EXPECT_LT(noise.P95, 0.5 * before.P95);
  EXPECT_LT(noise.ContrastP95, 0.5 * before.ContrastP95);
  EXPECT_LT(after.P95, 0.9 * before.P95);
  EXPECT_LT(after.ContrastP95, 0.8 * before.ContrastP95);
  EXPECT_THROW(CompareTexels(*field, texels, reference, {}), std::invalid_argument);
}

// Largest relative change of the texels beside the step, and RMS of the noise left far from it.
void FilterStep(const TextureFilterSettings& filter, double& edgeError, double& noiseLeft)
{
  LightFieldSettings settings;
  settings.Directions = 33;
  settings.RaysPerSide = 32;
  settings.TilesPerSide = 4;
  std::unique_ptr<LightField> field =
    LightField::Build(vlftest::MakeEmitterOverFloor(1.0f, 1.0f, 2.0f, 0.5f, 2.0f), settings);
  const std::uint32_t floor = 0;
  ASSERT_EQ(field->MaterialOf(floor).Emission.x, 0.0f);
  const Surface& s = field->Surfaces()[floor];
  ASSERT_GT(s.TextureWidth, 12);
  const int step = s.TextureWidth / 2;
  auto clean = [&](int a) { return a < step ? 1.0f : 0.2f; };
  for (int b = 0; b < s.TextureHeight; ++b)
  {
    for (int a = 0; a < s.TextureWidth; ++a)
    {
      const float noise = ((a + b) % 2 == 0) ? 1.03f : 0.97f;
      field->TotalDiffuse[s.TexelOffset + static_cast<std::size_t>(b) * s.TextureWidth + a] =
        glm::vec3(clean(a) * noise);
    }
  }
  FilterTotalDiffuse(*field, filter);
  edgeError = 0.0;
  double squares = 0.0;
  int count = 0;
  for (int b = 0; b < s.TextureHeight; ++b)
  {
    for (int a = 0; a < s.TextureWidth; ++a)
    {
      const float v =
        field->TotalDiffuse[s.TexelOffset + static_cast<std::size_t>(b) * s.TextureWidth + a].x;
      const double e = std::abs(v - clean(a)) / clean(a);
      if (a == step - 1 || a == step)
      {
        edgeError = std::max(edgeError, e);
      }
      else if (std::abs(a - step) > 3 && a > 2 && a < s.TextureWidth - 3 && b > 2 &&
        b < s.TextureHeight - 3)
      {
        squares += e * e;
        ++count;
      }
    }
  }
  noiseLeft = std::sqrt(squares / std::max(count, 1));
}

TEST(VLFTextureFilter, KeepsAShadowEdgeWhereABoxBlurDoesNot)
{
  double edge = 0.0, noise = 0.0;
  FilterStep(TextureFilterSettings(), edge, noise);
  std::printf("bilateral: edge texels moved %.1f%%, noise left %.2f%% (of 3%%)\n", 100.0 * edge,
    100.0 * noise);
  EXPECT_LT(edge, 0.05);
  EXPECT_LT(noise, 0.01);
  TextureFilterSettings box;
  box.RangeSigma = 0.0f;
  FilterStep(box, edge, noise);
  std::printf(
    "box blur:  edge texels moved %.1f%%, noise left %.2f%%\n", 100.0 * edge, 100.0 * noise);
  EXPECT_GT(edge, 0.2);
  TextureFilterSettings none;
  none.Radius = 0;
  FilterStep(none, edge, noise);
  EXPECT_NEAR(noise, 0.03, 1e-3); // the check sees the noise when nothing filters it
}

} // namespace
