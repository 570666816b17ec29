// SPDX-License-Identifier: BSD-3-Clause
// vtkReliefMapper's measurement outputs decode to what they encode: on a flat map seen straight
// down through a parallel camera, the hit coordinate of each pixel is the pixel's own position,
// and the sample count is exactly what the march skeleton takes.
#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"
#include "vtkReliefMapper.h"

#include <vtkActor.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <string>

namespace
{
using namespace mesolight;
constexpr int Pixels = 256;

Frame RenderTopDown(
  int output, double depth = 0.0, const std::function<void(vtkReliefMapper*)>& configure = nullptr)
{
  auto relief =
    test::BakeRelief(test::MakeDepthMap(64, 64, [depth](double, double) { return depth; }), 0.1);
  vtkNew<vtkReliefMapper> mapper;
  auto actor = test::UnitSquareRelief(mapper, relief, 0.1);
  mapper->GetReliefProperty()->SetOutput(output);
  if (configure)
  {
    configure(mapper);
  }
  return test::CaptureTopDown({ actor }, Pixels);
}
} // namespace

TEST(ReliefOutputs, HitCoordinatesDecodeToThePixelPosition)
{
  const Frame us = RenderTopDown(vtkReliefProperty::HitUOutput);
  const Frame vs = RenderTopDown(vtkReliefProperty::HitVOutput);
  double worst = 0.0;
  for (int y = 2; y < Pixels - 2; ++y)
  {
    for (int x = 2; x < Pixels - 2; ++x)
    {
      const size_t p = size_t(y) * Pixels + x;
      double u = -1.0, v = -1.0;
      ASSERT_TRUE(DecodeHitCoordinate(us, p, u));
      ASSERT_TRUE(DecodeHitCoordinate(vs, p, v));
      worst = std::max(worst, std::abs(u - (x + 0.5) / Pixels));
      worst = std::max(worst, std::abs(v - (y + 0.5) / Pixels));
    }
  }
  EXPECT_LT(worst, 1e-3) << "a tenth of a pixel";
}

TEST(ReliefOutputs, LightVisibilityIsWhiteUnderAnOverheadLight)
{
  const Frame lit = RenderTopDown(vtkReliefProperty::LightVisibilityOutput);
  const size_t centre = size_t(Pixels / 2) * Pixels + Pixels / 2;
  EXPECT_EQ(lit.Rgb[3 * centre], 255);
}

// Relief 10+4 on a flat map at depth 0.35, straight down: the linear search samples t = 0.1 ..
// 0.4 (4 samples, the last one below), 4 binary steps, 1 normal fetch for shading = 9. With
// self-shadowing under an overhead light, the shadow march from the top down to the hit adds
// ceil(10 * 0.35) = 4 samples (it skips the hit itself). Texture mapping samples nothing.
TEST(ReliefOutputs, SampleCountIsWhatTheMarchTakes)
{
  const auto count = [](const Frame& frame)
  {
    const size_t centre = size_t(Pixels / 2) * Pixels + Pixels / 2;
    int n = -1;
    EXPECT_TRUE(DecodeSampleCount(frame, centre, n));
    return n;
  };
  const auto relief = [](bool shadows)
  {
    return [shadows](vtkReliefMapper* m)
    {
      m->GetReliefProperty()->SetMethod(vtkReliefProperty::Relief);
      m->GetReliefProperty()->SetLinearSteps(10);
      m->GetReliefProperty()->SetRefinementSteps(4);
      m->GetReliefProperty()->SetSelfShadowing(shadows);
    };
  };
  EXPECT_EQ(count(RenderTopDown(vtkReliefProperty::SampleCountOutput, 0.35, relief(false))), 9);
  EXPECT_EQ(count(RenderTopDown(vtkReliefProperty::SampleCountOutput, 0.35, relief(true))), 13);
  EXPECT_EQ(count(RenderTopDown(vtkReliefProperty::SampleCountOutput, 0.35,
              [](vtkReliefMapper* m)
              { m->GetReliefProperty()->SetMethod(vtkReliefProperty::TextureMapping); })),
    0);
}

// Cone-stepped shadow rays take the linear search's samples at most (its depth-proportional
// budget, its first and last sample), so on Bricks, whose hits are mostly shallow, they sample no
// more than relief's shadow rays (3.5 against 8.5 per pixel). With a fixed budget of LinearSteps
// per ray they took 15.0.
TEST(ReliefOutputs, ConeShadowsSampleNoMoreThanReliefShadows)
{
  const auto shadowSamples = [](const char* method)
  {
    double withShadows = 0.0;
    for (bool shadows : { true, false })
    {
      ReliefSceneOptions o;
      o.Pattern = "Bricks";
      o.Resolution = 128;
      o.Method = method;
      o.LinearSteps = 32;
      o.RefinementSteps = 8;
      o.SelfShadowing = shadows;
      o.Width = o.Height = 192;
      ReliefScene scene;
      std::string error;
      EXPECT_TRUE(BuildReliefScene(o, scene, error)) << error;
      if (!scene.Mapper)
      {
        return -1.0;
      }
      scene.Mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::SampleCountOutput);
      auto window = MakeOffscreenWindow(o, scene.Renderer);
      const double mean = MeanSampleCount(CaptureFrame(window));
      withShadows = shadows ? mean : withShadows - mean;
    }
    return withShadows; // shadow samples per pixel
  };
  const double relief = shadowSamples("relief");
  const double cone = shadowSamples("relaxed-cone");
  std::cout << "shadow samples per pixel: relief " << relief << ", relaxed cone " << cone << "\n";
  EXPECT_GT(relief, 1.0);
  EXPECT_GT(cone, 0.0);
  EXPECT_LT(cone, 1.25 * relief);
}
