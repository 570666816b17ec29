// SPDX-License-Identifier: BSD-3-Clause
// Numerical stress: grazing views up to 89.9 degrees, depth scales 0 and 10, 1x1, non-power-of-two,
// flat, spike and 4096^2 maps. vtkReliefMapper's NonFiniteCheckOutput paints a fragment red when a
// NaN or Inf arose anywhere on the way to its colour (hit, position, normal, colour), so "no red
// pixel" means no NaN or Inf reached the framebuffer.
#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"
#include "vtkConeMapFilter.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkImageData.h>
#include <vtkProperty.h>
#include <vtkRendererCollection.h>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <iostream>
#include <limits>
#include <sstream>
#include <string>

namespace
{
using namespace mesolight;

struct StressResult
{
  long long Red = 0;
  long long Covered = 0;
  std::string Errors;
};

// Renders the wall with the given relief texture (or the options' pattern when null) and counts
// red (non-finite) and covered pixels.
StressResult Stress(
  ReliefSceneOptions o, vtkImageData* relief, const std::function<void(ReliefScene&)>& tamper = {})
{
  o.Width = o.Height = 160;
  o.ViewDistance = 2.2;
  std::string error;
  ReliefScene scene;
  StressResult result;
  if (!BuildReliefScene(o, scene, error))
  {
    result.Errors = error;
    return result;
  }
  if (relief)
  {
    // Cone methods step by the cone map of the same relief, baked as the tool and ParaView do.
    const int coneMap =
      vtkReliefProperty::GetRequiredConeMap(vtkReliefProperty::GetMethodFromName(o.Method.c_str()));
    if (coneMap != vtkReliefProperty::NoConeMap)
    {
      vtkNew<vtkConeMapFilter> cones;
      cones->SetInputData(relief);
      cones->SetDepthScale(o.DepthScale);
      if (coneMap == vtkReliefProperty::ConservativeConeMap)
      {
        cones->SetConeTypeToConservative();
      }
      cones->Update();
      scene.Mapper->SetReliefTextureData(cones->GetOutput());
    }
    else
    {
      scene.Mapper->SetReliefTextureData(relief);
    }
  }
  if (tamper)
  {
    tamper(scene);
  }
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(scene.Mapper);
  scene.Mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::NonFiniteCheckOutput);
  // One window for all cases: each X window costs the server resources, and a test process
  // opening a hundred of them can exhaust Xvfb.
  static vtkSmartPointer<vtkRenderWindow> window = MakeOffscreenWindow(o, scene.Renderer);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(scene.Renderer);
  const Frame frame = CaptureFrame(window);
  window->RemoveRenderer(scene.Renderer);
  for (size_t p = 0; p < frame.Depth.size(); ++p)
  {
    if (!frame.Covered(p))
    {
      continue;
    }
    ++result.Covered;
    const unsigned char* c = &frame.Rgb[3 * p];
    result.Red += (c[0] > 128 && c[1] < 128) ? 1 : 0;
  }
  result.Errors = messages->AllErrors();
  return result;
}

// A stress scene: `method` with enough steps for it (max-mipmap counts iterations).
ReliefSceneOptions StressOptions(
  const char* pattern, int resolution, const char* method, double viewAngle, double depthScale)
{
  ReliefSceneOptions o;
  o.Pattern = pattern;
  o.Resolution = resolution;
  o.Method = method;
  o.LinearSteps = std::string(method) == "max-mipmap" ? 128 : 16;
  o.ViewAngle = viewAngle;
  o.DepthScale = depthScale;
  return o;
}

// Every method the mapper has but plain texture mapping.
const char* const StressMethods[] = { "relief", "pom", "interval", "linear", "parallax",
  "parallax-limit", "parallax-slope", "iterative-parallax", "binary", "secant", "max-mipmap",
  "bump", "relaxed-cone", "relaxed-cone-interval", "cone" };
static_assert(
  sizeof(StressMethods) / sizeof(StressMethods[0]) == vtkReliefProperty::NumberOfMethods - 1,
  "the stress tests cover every method but texture");
} // namespace

TEST(ReliefStress, GrazingViewsUpTo89Point9Degrees)
{
  for (const char* method : StressMethods)
  {
    for (double angle : { 80.0, 89.0, 89.9 })
    {
      const StressResult r = Stress(StressOptions("Bricks", 128, method, angle, 0.1), nullptr);
      EXPECT_TRUE(r.Errors.empty()) << method << " " << angle << ": " << r.Errors;
      EXPECT_EQ(r.Red, 0) << method << " at " << angle << " degrees";
    }
  }
}

TEST(ReliefStress, DepthScaleZeroAndVeryLarge)
{
  for (const char* method : StressMethods)
  {
    for (double depthScale : { 0.0, 10.0 })
    {
      const StressResult r =
        Stress(StressOptions("HemisphereTorus", 64, method, 60.0, depthScale), nullptr);
      EXPECT_TRUE(r.Errors.empty()) << method << " " << depthScale << ": " << r.Errors;
      EXPECT_EQ(r.Red, 0) << method << " with depth scale " << depthScale;
      if (depthScale == 0.0)
      {
        EXPECT_GT(r.Covered, 1000) << method << ": a flat relief covers the wall";
      }
    }
  }
}

TEST(ReliefStress, DegenerateAndSpikyMaps)
{
  struct Map
  {
    const char* Name;
    int Width, Height;
    std::function<double(double, double)> Depth;
  };
  const Map maps[] = {
    { "1x1", 1, 1, [](double, double) { return 0.4; } },
    { "37x23", 37, 23,
      [](double u, double v) { return 0.5 + 0.45 * std::sin(17 * u) * std::cos(11 * v); } },
    { "flat-deep", 32, 32, [](double, double) { return 1.0; } },
    { "flat-top", 32, 32, [](double, double) { return 0.0; } },
    { "spike", 64, 64,
      [](double u, double v)
      { return (std::abs(u - 0.5) < 0.008 && std::abs(v - 0.5) < 0.008) ? 0.0 : 1.0; } },
    { "2x1", 2, 1, [](double u, double) { return u < 0.5 ? 0.0 : 1.0; } },
  };
  for (const Map& map : maps)
  {
    auto relief = test::BakeRelief(test::MakeDepthMap(map.Width, map.Height, map.Depth), 0.1);
    for (const char* method : StressMethods)
    {
      ReliefSceneOptions o;
      o.Pattern = "Flat";
      o.Resolution = 8;
      o.Method = method;
      o.LinearSteps = std::string(method) == "max-mipmap" ? 128 : 16;
      o.DepthScale = 0.1;
      o.ViewAngle = 70.0;
      const StressResult r = Stress(o, relief);
      EXPECT_TRUE(r.Errors.empty()) << map.Name << " " << method << ": " << r.Errors;
      EXPECT_EQ(r.Red, 0) << map.Name << " " << method;
    }
  }
}

// The detector the tests above rely on fires. The inputs a NaN could come from are refused before
// drawing (relief texels, texture coordinates, light sets, depth scales: tried), so it is handed
// to the shader as the material's diffuse colour, which a light set's shading multiplies (under
// VTK's own lights the check runs before VTK's lighting code): every fragment must show red.
TEST(ReliefStress, NonFiniteCheckSeesANaNOrInfColour)
{
  for (const double bad : { std::nan(""), std::numeric_limits<double>::infinity() })
  {
    for (const char* method : { "relief", "pom", "relief+albedo" })
    {
      // With the albedo texture, whose clamp(colour, 0, 1) may turn a NaN into a number (GLSL
      // leaves clamp of NaN undefined): the check looks at the colour before that clamp.
      const bool albedo = std::string(method) == "relief+albedo";
      ReliefSceneOptions o;
      o.Pattern = "HemisphereTorus";
      o.Resolution = 64;
      o.Method = albedo ? "relief" : method;
      o.LinearSteps = 16;
      o.DepthScale = 0.1;
      o.ViewAngle = 30.0;
      o.Environment = "procedural:sky";
      o.EnvironmentLights = 32;
      const StressResult r = Stress(o, nullptr,
        [bad, albedo](ReliefScene& scene)
        {
          if (!albedo)
          {
            scene.Actor->SetTexture(nullptr);
          }
          scene.Actor->GetProperty()->SetDiffuseColor(bad, bad, bad);
        });
      std::cout << "[diffuse colour " << bad << "] " << method << ": " << r.Red << " red of "
                << r.Covered << " pixels\n";
      EXPECT_GT(r.Covered, 1000) << method;
      EXPECT_GT(r.Red, r.Covered / 2) << bad << " " << method;
    }
  }
}

TEST(ReliefStress, Map4096Squared)
{
  ReliefSceneOptions o;
  o.Pattern = "Stone";
  o.Resolution = 4096;
  o.Method = "relief";
  o.DepthScale = 0.03;
  o.ViewAngle = 75.0;
  const StressResult r = Stress(o, nullptr);
  EXPECT_TRUE(r.Errors.empty()) << r.Errors;
  EXPECT_EQ(r.Red, 0);
  EXPECT_GT(r.Covered, 1000);
  o.Method = "max-mipmap";
  o.LinearSteps = 256;
  const StressResult m = Stress(o, nullptr);
  EXPECT_TRUE(m.Errors.empty()) << m.Errors;
  EXPECT_EQ(m.Red, 0);
}

// Absurd parameters are refused with a message, never passed to the shader.
TEST(ReliefStress, NaNDepthScaleIsRefused)
{
  vtkNew<vtkReliefMapper> mapper;
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  mapper->GetReliefProperty()->SetDepthScale(0.2);
  mapper->GetReliefProperty()->SetDepthScale(std::nan(""));
  EXPECT_EQ(mapper->GetReliefProperty()->GetDepthScale(), 0.2);
  EXPECT_TRUE(messages->HasError("NaN"));
  mapper->GetReliefProperty()->SetDepthScale(1e300);
  EXPECT_EQ(mapper->GetReliefProperty()->GetDepthScale(), 10.0);
}
