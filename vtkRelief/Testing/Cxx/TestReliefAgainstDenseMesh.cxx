// SPDX-License-Identifier: BSD-3-Clause
// The GPU relief render against an independent reference of the same scene: the height field
// as a dense displaced mesh (one vertex per texel, vtkHeightFieldMeshFilter) drawn by VTK's stock
// mapper with the same camera, lights, normals and albedo. Self-shadowing is off on both sides
// (the stock mapper has none); shadows are tested against exact visibility in TestReliefShadows.
#include "DenseMeshTestScene.h"
#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"

#include "vtkReliefMapper.h"

#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <functional>

#include <iostream>
#include <sstream>

namespace
{
using namespace mesolight;

FrameDifference CompareWithDenseMesh(const ReliefSceneOptions& options, const std::string& tag,
  const std::function<void(vtkRenderer*)>& lights = {})
{
  const FrameDifference d = test::CompareWithDenseMesh(options, tag, lights);
  EXPECT_GT(d.CoveredBoth, options.Width * options.Height / 4) << "the wall should fill the view";
  return d;
}

// Thresholds met by a correct first-hit march; plain texture mapping misses them by far.
constexpr double MaxMeanColorError = 3.0;     // 8-bit levels
constexpr double MaxSilhouetteMismatch = 1.0; // percent of pixels in the mesh footprint
constexpr double MaxDepthMismatch = 5.0;      // percent of common pixels off by > 5% of the depth

bool WithinTolerance(const FrameDifference& d)
{
  return d.MeanColorError <= MaxMeanColorError && d.SilhouetteMismatch <= MaxSilhouetteMismatch &&
    d.DepthMismatch <= MaxDepthMismatch;
}
} // namespace

// With no depth there is nothing to march: the relief shader must light exactly like the stock
// mapper (same Phong model, lights and texture modulation).
TEST(ReliefVsDenseMesh, FlatMapShadesLikeTheStockMapper)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Pattern = "Flat";
  const FrameDifference d = CompareWithDenseMesh(o, "flat");
  EXPECT_LT(d.MeanColorError, 1.0);
  EXPECT_LT(d.SilhouetteMismatch, 0.5);
  EXPECT_LT(d.DepthMismatch, 0.5);
}

struct MethodCase
{
  const char* Method;
  int Linear;
  int Refine;
  double ViewAngle;
  const char* Pattern;
  double DepthScale;
};

void PrintTo(const MethodCase& c, std::ostream* os)
{
  *os << c.Method << " " << c.Linear << "+" << c.Refine << " at " << c.ViewAngle << " deg on "
      << c.Pattern << " (depth scale " << c.DepthScale << ")";
}

class ReliefMethodVsDenseMesh : public ::testing::TestWithParam<MethodCase>
{
};

TEST_P(ReliefMethodVsDenseMesh, WithinTolerance)
{
  const MethodCase c = GetParam();
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Method = c.Method;
  o.LinearSteps = c.Linear;
  o.RefinementSteps = c.Refine;
  o.ViewAngle = c.ViewAngle;
  o.Pattern = c.Pattern;
  o.DepthScale = c.DepthScale;
  std::ostringstream tag;
  tag << c.Pattern << "-" << c.Method << c.Linear << "-" << c.Refine << "-view" << c.ViewAngle;
  const FrameDifference d = CompareWithDenseMesh(o, tag.str());
  EXPECT_LE(d.MeanColorError, MaxMeanColorError);
  EXPECT_LE(d.SilhouetteMismatch, MaxSilhouetteMismatch);
  EXPECT_LE(d.DepthMismatch, MaxDepthMismatch);
}

INSTANTIATE_TEST_SUITE_P(Methods, ReliefMethodVsDenseMesh,
  ::testing::Values(MethodCase{ "relief", 10, 8, 30.0, "Bricks", 0.04 },
    MethodCase{ "relief", 10, 8, 55.0, "Bricks", 0.04 },
    MethodCase{ "relief", 10, 8, 70.0, "Bricks", 0.04 },
    MethodCase{ "relief", 10, 8, 55.0, "HemisphereTorus", 0.15 },
    MethodCase{ "pom", 32, 0, 30.0, "Bricks", 0.04 },
    MethodCase{ "pom", 32, 0, 55.0, "HemisphereTorus", 0.15 }));

// Negative test: plain texture (and normal) mapping, no march, must fail the same comparison.
TEST(ReliefVsDenseMesh, PlainTextureMappingFailsTheComparison)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Method = "texture";
  o.ViewAngle = 55.0;
  const FrameDifference d = CompareWithDenseMesh(o, "bricks-texture-view55");
  EXPECT_FALSE(WithinTolerance(d));
  EXPECT_GT(d.DepthMismatch, 3.0 * MaxDepthMismatch);
}

// Negative test: without gl_FragDepth the relief keeps the mesh's depth, which the depth check
// must catch even though the colours match.
TEST(ReliefVsDenseMesh, WithoutDepthWriteTheDepthCheckFails)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.WriteDepth = false;
  o.ViewAngle = 55.0;
  const FrameDifference d = CompareWithDenseMesh(o, "bricks-relief-nodepth-view55");
  EXPECT_LE(d.MeanColorError, MaxMeanColorError);
  EXPECT_GT(d.DepthMismatch, MaxDepthMismatch);
}

namespace
{
// Lamps instead of the default directional key and fill: a positional point light with
// quadratic attenuation and a spot light (cone and exponent), scene lights in front of the wall
// (the wall spans x 0..1, y 0..height at z = 0, relief below z = 0).
// The stock mapper shades the dense mesh per fragment too (Phong interpolation). Intensities keep
// the sum of the lights below 1: the relief modulates its albedo texture as VTK does for a
// textured actor (lighting clamped to 1, then times the texture) while the dense mesh carries the
// albedo as vertex colours (no clamp before the product), so only a saturated sum differs.
void UseLamps(vtkRenderer* renderer)
{
  for (int i = 0; i < renderer->GetActors()->GetNumberOfItems(); ++i)
  {
    auto* actor = static_cast<vtkActor*>(renderer->GetActors()->GetItemAsObject(i));
    if (!vtkReliefMapper::SafeDownCast(actor->GetMapper()))
    {
      actor->GetProperty()->SetInterpolationToPhong();
    }
  }
  renderer->RemoveAllLights();
  vtkNew<vtkLight> lamp;
  lamp->SetLightTypeToSceneLight();
  lamp->SetPositional(true);
  lamp->SetConeAngle(180.0); // a point light
  lamp->SetPosition(0.25, 0.35, 0.45);
  lamp->SetFocalPoint(0.25, 0.35, 0.0);
  lamp->SetAttenuationValues(0.5, 0.5, 2.0);
  lamp->SetIntensity(0.5);
  renderer->AddLight(lamp);
  vtkNew<vtkLight> spot;
  spot->SetLightTypeToSceneLight();
  spot->SetPositional(true);
  spot->SetConeAngle(25.0);
  spot->SetExponent(6.0);
  spot->SetPosition(0.9, 0.2, 0.7);
  spot->SetFocalPoint(0.6, 0.55, 0.0);
  spot->SetColor(1.0, 0.9, 0.7);
  spot->SetIntensity(0.45);
  renderer->AddLight(spot);
}
} // namespace

// Point and spot lights (VTK's attenuation and spot cone): with no depth the relief must shade as
// the stock mapper does, and with depth stay within the comparison's tolerances. Must fail: the
// relief lit by the default lights against the dense mesh under the lamps.
TEST(ReliefVsDenseMesh, PointAndSpotLights)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Pattern = "Flat";
  const FrameDifference flat = CompareWithDenseMesh(o, "flat-lamps", UseLamps);
  EXPECT_LT(flat.MeanColorError, 0.1); // measured 0.001 levels
  o.Pattern = "Bricks";
  const FrameDifference bricks = CompareWithDenseMesh(o, "bricks-lamps", UseLamps);
  EXPECT_TRUE(WithinTolerance(bricks))
    << bricks.MeanColorError << " levels, " << bricks.SilhouetteMismatch << "% silhouettes, "
    << bricks.DepthMismatch << "% depth";
  const auto lampsOnTheMeshOnly = [](vtkRenderer* renderer)
  {
    if (renderer->GetActors()->GetNumberOfItems() > 0 &&
      !vtkReliefMapper::SafeDownCast(
        static_cast<vtkActor*>(renderer->GetActors()->GetItemAsObject(0))->GetMapper()))
    {
      UseLamps(renderer);
    }
  };
  const FrameDifference wrong = CompareWithDenseMesh(o, "bricks-lamps-wrong", lampsOnTheMeshOnly);
  EXPECT_GT(wrong.MeanColorError, 3.0 * MaxMeanColorError);
}

// More VTK lights than the relief shader holds (8, as VTK's own shaders): a warning saying so,
// once, and the first 8 are used -- never a silent drop.
TEST(ReliefVsDenseMesh, MoreLightsThanTheShaderHoldsWarns)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Width = o.Height = 64;
  std::string error;
  ReliefScene relief;
  ASSERT_TRUE(BuildReliefScene(o, relief, error)) << error;
  for (int i = 0; i < 10; ++i)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(0.1 * i, 0.5, 1.0);
    light->SetFocalPoint(0.5, 0.5, 0.0);
    light->SetIntensity(0.1);
    relief.Renderer->AddLight(light);
  }
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(relief.Mapper);
  auto window = MakeOffscreenWindow(o, relief.Renderer);
  CaptureFrame(window);
  CaptureFrame(window);
  EXPECT_TRUE(messages->HasWarning("More than 8")) << messages->AllWarnings();
  const std::string warnings = messages->AllWarnings();
  EXPECT_EQ(warnings.find("More than 8"), warnings.rfind("More than 8"))
    << "warned more than once: " << warnings;
}
