// SPDX-License-Identifier: BSD-3-Clause
// vtkReliefMapper under an image-based light set: radiometry against the analytic furnace case,
// soft self-shadows, and the skips (negligible lights, K shadowed lights) measured against the
// unskipped render.
#include "ImageCompare.h"
#include "LightSetReference.h"
#include "ReliefReference.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"
#include "vtkMedianCutLights.h"
#include "vtkReliefMapper.h"

#include <vtkCamera.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRendererCollection.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>

namespace
{
using namespace mesolight;

// N lights evenly spread over the upper hemisphere (Fibonacci), each carrying the irradiance
// L * (2 pi / N) of its share of a uniform sky of radiance L: together they are that sky.
vtkSmartPointer<vtkImageData> UniformSkyLights(int n, double radiance)
{
  auto lights = vtkSmartPointer<vtkImageData>::New();
  lights->SetDimensions(n, 2, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(4);
  values->SetNumberOfTuples(2 * n);
  const double golden = vtkMath::Pi() * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i)
  {
    const double z = 1.0 - (i + 0.5) / n; // uniform in solid angle over z in (0, 1]
    const double r = std::sqrt(1.0 - z * z);
    const double phi = golden * i;
    values->SetTuple4(i, r * std::cos(phi), r * std::sin(phi), z, 0.0);
    const double e = radiance * 2.0 * vtkMath::Pi() / n;
    values->SetTuple4(n + i, e, e, e, 0.0);
  }
  lights->GetPointData()->SetScalars(values);
  return lights;
}

Frame RenderTopDown(vtkImageData* relief, vtkImageData* lights, double exposure)
{
  vtkNew<vtkReliefMapper> mapper;
  auto actor = test::UnitSquareRelief(mapper, relief, 0.1);
  if (lights)
  {
    mapper->SetLightSetData(lights);
  }
  mapper->GetReliefProperty()->SetExposure(exposure);
  mapper->GetReliefProperty()->ToneMappingOff(); // linear shading, compared with radiance
  vtkNew<vtkRenderer> renderer;
  renderer->AutomaticLightCreationOff(); // the light set only
  renderer->AddActor(actor);
  test::LookStraightDown(renderer);
  // One window for the whole test program: opening a new X window right after a light-set render
  // was seen to fail under Xvfb + llvmpipe ("bad X server connection"), see docs/known-issues.md.
  ReliefSceneOptions size;
  size.Width = size.Height = 128;
  static vtkSmartPointer<vtkRenderWindow> window = MakeOffscreenWindow(size, renderer);
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(renderer);
  const Frame frame = CaptureFrame(window);
  window->RemoveRenderer(renderer);
  return frame;
}

double MeanRed(const Frame& frame)
{
  double sum = 0.0;
  long long n = 0;
  for (size_t p = 0; p < frame.Depth.size(); ++p)
  {
    if (frame.Covered(p))
    {
      sum += frame.Rgb[3 * p];
      ++n;
    }
  }
  return n > 0 ? sum / n : 0.0;
}
} // namespace

// A flat white Lambertian surface under a uniform sky of radiance L reflects radiance L:
// albedo / pi times the irradiance pi L.
TEST(ReliefLightSet, UniformSkyFurnace)
{
  auto flat = test::BakeRelief(test::MakeDepthMap(16, 16, [](double, double) { return 0.0; }), 0.1);
  const double radiance = 0.5;
  const double value = MeanRed(RenderTopDown(flat, UniformSkyLights(256, radiance), 1.0));
  std::cout << "[furnace] " << value << " of expected " << 255.0 * radiance << std::endl;
  EXPECT_NEAR(value, 255.0 * radiance, 3.0);
  // Exposure scales it; without the light set the surface is black (negative test).
  EXPECT_NEAR(MeanRed(RenderTopDown(flat, UniformSkyLights(256, radiance), 0.5)),
    0.5 * 255.0 * radiance, 3.0);
  EXPECT_LT(MeanRed(RenderTopDown(flat, nullptr, 1.0)), 1.0);
}

// A deep pit under a uniform sky: its floor sees only the sky inside its opening, so self-shadowed
// lights must darken it, by about the fraction of the sky's cosine-weighted irradiance hidden.
TEST(ReliefLightSet, PitFloorIsDarkenedBySelfShadowing)
{
  auto pit = test::BakeRelief(
    test::MakeDepthMap(128, 128,
      [](double u, double v)
      { return (std::abs(u - 0.5) < 0.1 && std::abs(v - 0.5) < 0.1) ? 1.0 : 0.0; }),
    0.1);
  const Frame frame = RenderTopDown(pit, UniformSkyLights(256, 0.5), 1.0);
  const size_t centre = size_t(64) * 128 + 64;
  const size_t outside = size_t(10) * 128 + 10;
  // The pit (0.2 wide, 0.1 deep) floor centre sees the sky within 45 degrees of the zenith in
  // the u and v directions: its irradiance is well below the open surface's.
  const double inside = frame.Rgb[3 * centre];
  const double open = frame.Rgb[3 * outside];
  std::cout << "[pit] floor " << inside << ", open surface " << open << std::endl;
  EXPECT_NEAR(open, 127.5, 3.0);
  EXPECT_LT(inside, 0.8 * open);
  EXPECT_GT(inside, 0.2 * open);
}

namespace
{
// HemisphereTorus lit only by `lights` median-cut lights of the procedural sun and sky, as a white
// Lambertian surface: the references' radiance is then albedo / pi x irradiance.
bool BuildSunLitScene(
  int lights, int linearSteps, ReliefSceneOptions& o, ReliefScene& scene, std::string& error)
{
  o.Pattern = "HemisphereTorus";
  o.Resolution = 128;
  o.DepthScale = 0.12;
  o.ViewAngle = 40.0;
  o.ViewDistance = 2.2;
  o.Width = o.Height = 200;
  o.Lights = 0;
  o.LinearSteps = linearSteps;
  o.Environment = "procedural:sun";
  o.EnvironmentLights = lights;
  if (!BuildReliefScene(o, scene, error))
  {
    return false;
  }
  scene.Actor->SetTexture(nullptr);
  scene.Actor->GetProperty()->SetAmbient(0.0);
  scene.Actor->GetProperty()->SetDiffuse(1.0);
  scene.Actor->GetProperty()->SetSpecular(0.0);
  return true;
}

// Exposure that puts the brightest reference pixel at 200 of 255 (0 if all are black).
double ExposureFor(const std::vector<EnvironmentIrradianceSample>& reference)
{
  double brightest = 0.0;
  for (const auto& s : reference)
  {
    brightest = std::max(brightest, (s.Irradiance[0] + s.Irradiance[1] + s.Irradiance[2]) / 3.0);
  }
  return brightest > 0.0 ? 200.0 / 255.0 * vtkMath::Pi() / brightest : 0.0;
}
} // namespace

// The relief lit by median-cut lights of a sun-and-sky environment against Monte Carlo
// integration of the whole environment with exact first hits and exact height-field visibility.
// More lights converge toward it; without self-shadowing the error is much larger (negative).
TEST(ReliefLightSet, MedianCutLightsAgainstMonteCarlo)
{
  ReliefSceneOptions o;
  std::string error;
  ReliefScene scene;
  ASSERT_TRUE(BuildSunLitScene(16, 16, o, scene, error)) << error;
  ReliefReference hits;
  ASSERT_TRUE(ComputeReliefReference(MakeReliefReferenceInput(scene, o), hits, error)) << error;
  auto environment = LoadEnvironment(o.Environment, error);
  ASSERT_TRUE(environment) << error;
  const auto reference = ComputeEnvironmentReference(
    hits, scene.ReliefTexture, environment, o.DepthScale, 800, 2048, true);
  const double exposure = ExposureFor(reference);
  ASSERT_GT(exposure, 0.0);
  scene.Mapper->GetReliefProperty()->SetExposure(exposure);

  static vtkSmartPointer<vtkRenderWindow> window = MakeOffscreenWindow(o, scene.Renderer);
  window->GetRenderers()->RemoveAllItems();
  window->SetSize(o.Width, o.Height);
  window->AddRenderer(scene.Renderer);
  auto errorWith = [&](int lights, bool shadows)
  {
    ReliefSceneOptions lo = o;
    lo.EnvironmentLights = lights;
    scene.Mapper->SetLightSetData(MakeEnvironmentLights(lo, error));
    scene.Mapper->GetReliefProperty()->SetSelfShadowing(shadows);
    const double e = EnvironmentError(CaptureFrame(window), reference, exposure);
    std::cout << "[ibl] " << lights << " lights" << (shadows ? "" : ", no shadows") << ": " << e
              << "% mean error vs Monte Carlo" << std::endl;
    return e;
  };
  const double e16 = errorWith(16, true);
  const double e256 = errorWith(256, true);
  const double unshadowed = errorWith(256, false);
  window->RemoveRenderer(scene.Renderer);
  EXPECT_LT(e256, 5.0);
  EXPECT_LT(e256, e16);
  EXPECT_GT(unshadowed, 1.5 * e256);
}

// The light-set render against the exact render of the same lights (ComputeLightSetReference:
// exact first hits, exact visibility of each light, the texture's own normals), which is what
// `mesolight bench ibl` compares relief and relaxed cones with. Both methods stay within 1%;
// without self-shadowing the error is several times larger (negative).
TEST(ReliefLightSet, LightSetRenderAgainstTheExactRenderOfTheSameLights)
{
  ReliefSceneOptions o;
  std::string error;
  ReliefScene scene;
  ASSERT_TRUE(BuildSunLitScene(32, 32, o, scene, error)) << error;
  vtkSmartPointer<vtkImageData> coneRelief;
  vtkSmartPointer<vtkTexture> albedo;
  ASSERT_TRUE(BuildReliefTextures(o, coneRelief, albedo, error, vtkReliefProperty::RelaxedConeMap))
    << error;
  ReliefReference hits;
  ASSERT_TRUE(ComputeReliefReference(MakeReliefReferenceInput(scene, o), hits, error)) << error;
  const auto reliefReference =
    ComputeLightSetReference(hits, scene.ReliefTexture, scene.LightSet, o.DepthScale, 800);
  const auto coneReference =
    ComputeLightSetReference(hits, coneRelief, scene.LightSet, o.DepthScale, 800);
  ASSERT_FALSE(reliefReference.empty());
  // Not a light texture (none; one row only): no reference rather than a black one.
  EXPECT_TRUE(
    ComputeLightSetReference(hits, scene.ReliefTexture, nullptr, o.DepthScale, 800).empty());
  vtkNew<vtkImageData> oneRow;
  oneRow->SetDimensions(4, 1, 1);
  oneRow->AllocateScalars(VTK_FLOAT, 4);
  EXPECT_TRUE(
    ComputeLightSetReference(hits, scene.ReliefTexture, oneRow, o.DepthScale, 800).empty());
  // An 8-bit relief texture (0-255, as the mapper also reads them) gives the reference of the
  // same values in float (k / 255); read as 0-1 values its depth and normals were garbage.
  {
    vtkDataArray* source = scene.ReliefTexture->GetPointData()->GetScalars();
    vtkNew<vtkFloatArray> rounded;
    vtkNew<vtkUnsignedCharArray> bytes;
    for (vtkDataArray* a :
      { static_cast<vtkDataArray*>(rounded), static_cast<vtkDataArray*>(bytes) })
    {
      a->SetNumberOfComponents(4);
      a->SetNumberOfTuples(source->GetNumberOfTuples());
    }
    for (vtkIdType t = 0; t < source->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < 4; ++c)
      {
        const double b = std::round(255.0 * source->GetComponent(t, c));
        bytes->SetComponent(t, c, b);
        rounded->SetComponent(t, c, b / 255.0);
      }
    }
    std::vector<EnvironmentIrradianceSample> references[2];
    for (int k = 0; k < 2; ++k)
    {
      vtkNew<vtkImageData> texture;
      texture->CopyStructure(scene.ReliefTexture);
      texture->GetFieldData()->ShallowCopy(scene.ReliefTexture->GetFieldData());
      texture->GetPointData()->SetScalars(
        k == 0 ? static_cast<vtkDataArray*>(rounded) : static_cast<vtkDataArray*>(bytes));
      references[k] = ComputeLightSetReference(hits, texture, scene.LightSet, o.DepthScale, 800);
    }
    ASSERT_EQ(references[1].size(), references[0].size());
    ASSERT_FALSE(references[0].empty());
    double difference = 0.0, total = 0.0;
    for (size_t k = 0; k < references[0].size(); ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        difference += std::fabs(references[1][k].Irradiance[c] - references[0][k].Irradiance[c]);
        total += references[0][k].Irradiance[c];
      }
    }
    std::cout << "[same lights] 8-bit relief texture against the same values in float: mean "
              << "|difference| " << 100.0 * difference / total << "%" << std::endl;
    EXPECT_LT(difference, 1e-4 * total);
  }
  const double exposure = ExposureFor(reliefReference);
  ASSERT_GT(exposure, 0.0);
  scene.Mapper->GetReliefProperty()->SetExposure(exposure);
  auto window = MakeOffscreenWindow(o, scene.Renderer);

  const double relief = EnvironmentError(CaptureFrame(window), reliefReference, exposure);
  scene.Mapper->GetReliefProperty()->SelfShadowingOff();
  const double unshadowed = EnvironmentError(CaptureFrame(window), reliefReference, exposure);
  scene.Mapper->GetReliefProperty()->SelfShadowingOn();
  scene.Mapper->SetReliefTextureData(coneRelief);
  scene.Mapper->GetReliefProperty()->SetMethod(vtkReliefProperty::RelaxedConeBinary);
  const double cone = EnvironmentError(CaptureFrame(window), coneReference, exposure);
  std::cout << "[same lights] relief " << relief << "%, relaxed cone " << cone << "%, no shadows "
            << unshadowed << "%" << std::endl;
  EXPECT_LT(relief, 1.0);
  EXPECT_LT(cone, 1.0);
  EXPECT_GT(unshadowed, 3.0 * relief);
}

// The skips of the many-light path (LightSetThreshold, ShadowedLights, ShadowCulling) against
// the exact render of the same lights: each skip takes fewer relief-texture samples than the
// unskipped render and stays within a stated error of the reference; culling is exact.
TEST(ReliefLightSet, SkipsCostFewerSamplesWithinTheirError)
{
  ReliefSceneOptions o;
  // Even-energy cuts: the threshold skip assumes lights of similar energy. Variance cuts give
  // the sun one light far above the others', and a 5% threshold then drops the sky (31% error).
  o.EnvironmentVarianceCuts = false;
  std::string error;
  ReliefScene scene;
  ASSERT_TRUE(BuildSunLitScene(64, 32, o, scene, error)) << error;
  ReliefReference hits;
  ASSERT_TRUE(ComputeReliefReference(MakeReliefReferenceInput(scene, o), hits, error)) << error;
  const auto reference =
    ComputeLightSetReference(hits, scene.ReliefTexture, scene.LightSet, o.DepthScale, 800);
  ASSERT_FALSE(reference.empty());
  const double exposure = ExposureFor(reference);
  ASSERT_GT(exposure, 0.0);
  vtkReliefProperty* settings = scene.Mapper->GetReliefProperty();
  settings->SetExposure(exposure);
  auto window = MakeOffscreenWindow(o, scene.Renderer);

  struct Measure
  {
    double Error;
    double Samples;
  };
  auto measure = [&]() -> Measure
  {
    settings->SetOutput(vtkReliefProperty::ShadedOutput);
    const double e = EnvironmentError(CaptureFrame(window), reference, exposure);
    settings->SetOutput(vtkReliefProperty::SampleCountOutput);
    const double samples = MeanSampleCount(CaptureFrame(window));
    settings->SetOutput(vtkReliefProperty::ShadedOutput);
    return { e, samples };
  };
  const Measure all = measure();
  settings->SetLightSetThreshold(0.05);
  const Measure threshold = measure();
  settings->SetLightSetThreshold(0.0);
  settings->SetShadowedLights(8);
  const Measure shadowed = measure();
  settings->SetShadowedLights(0);
  settings->ShadowCullingOff();
  const Measure unculled = measure();
  settings->ShadowCullingOn();
  settings->SelfShadowingOff();
  const Measure unshadowed = measure();
  settings->SelfShadowingOn();
  std::cout << "[skips] error % / samples per pixel: all " << all.Error << " / " << all.Samples
            << ", threshold 0.05 " << threshold.Error << " / " << threshold.Samples
            << ", 8 shadowed " << shadowed.Error << " / " << shadowed.Samples << ", no culling "
            << unculled.Error << " / " << unculled.Samples << ", no self-shadowing "
            << unshadowed.Error << std::endl;
  ASSERT_GT(all.Samples, 0.0);
  EXPECT_LT(threshold.Samples, all.Samples);
  EXPECT_LT(shadowed.Samples, all.Samples);
  EXPECT_GT(unculled.Samples, all.Samples);
  EXPECT_NEAR(unculled.Error, all.Error, 0.05);
  // docs/ibl.md: skipping lights below 5% of the strongest costs about 0.01 points here and
  // there; shadows for the 8 strongest only about 2.5-3 points, still better than none (0.7x).
  EXPECT_LT(threshold.Error, all.Error + 0.2);
  EXPECT_LT(shadowed.Error, all.Error + 4.0);
  EXPECT_LT(shadowed.Error, 0.8 * unshadowed.Error);
}

namespace
{
// A lat-long environment of `width` x width/2 float RGB texels: `sky` everywhere, plus `sun` at
// one texel (when > 0) and a relative ripple of `ripple` (deterministic).
vtkSmartPointer<vtkImageData> MakeEnvironment(int width, double sky, double sun, double ripple)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, width / 2, 1);
  image->AllocateScalars(VTK_FLOAT, 3);
  auto* values = static_cast<float*>(image->GetScalarPointer());
  const int n = width * (width / 2);
  for (int p = 0; p < n; ++p)
  {
    const double r = sky * (1.0 + ripple * std::sin(12.9898 * p));
    values[3 * p] = values[3 * p + 1] = values[3 * p + 2] = static_cast<float>(r);
  }
  if (sun > 0.0)
  {
    const int p = (width / 2) * (3 * width / 8) + width / 3; // high in the sky
    values[3 * p] = values[3 * p + 1] = values[3 * p + 2] = static_cast<float>(sun);
  }
  return image;
}
} // namespace

// HDR extremes in the light-set path: a 1e6 sun in a 1e-3 sky (9 orders of magnitude), and 1024
// nearly equal lights of a uniform sky. No NaN or Inf reaches the framebuffer, and the render
// stays within its usual error of the exact render of the same lights.
TEST(ReliefLightSet, HdrExtremesStayFiniteAndAccurate)
{
  ReliefSceneOptions o;
  std::string error;
  ReliefScene scene;
  ASSERT_TRUE(BuildSunLitScene(16, 32, o, scene, error)) << error;
  ReliefReference hits;
  ASSERT_TRUE(ComputeReliefReference(MakeReliefReferenceInput(scene, o), hits, error)) << error;
  auto window = MakeOffscreenWindow(o, scene.Renderer);
  vtkReliefProperty* settings = scene.Mapper->GetReliefProperty();
  struct Case
  {
    const char* Name;
    vtkSmartPointer<vtkImageData> Environment;
    int Lights;
  };
  const Case cases[] = { { "1e6 sun in a 1e-3 sky", MakeEnvironment(256, 1e-3, 1e6, 0.0), 64 },
    { "1024 nearly equal lights", MakeEnvironment(256, 1.0, 0.0, 1e-6), 1024 } };
  for (const Case& c : cases)
  {
    vtkNew<vtkMedianCutLights> cut;
    cut->SetInputData(c.Environment);
    cut->SetNumberOfLights(c.Lights);
    cut->Update();
    vtkImageData* lights = cut->GetLightTexture();
    ASSERT_NE(lights, nullptr) << c.Name;
    scene.Mapper->SetLightSetData(lights);
    const auto reference =
      ComputeLightSetReference(hits, scene.ReliefTexture, lights, o.DepthScale, 800);
    ASSERT_FALSE(reference.empty()) << c.Name;
    const double exposure = ExposureFor(reference);
    ASSERT_GT(exposure, 0.0) << c.Name;
    ASSERT_TRUE(std::isfinite(exposure)) << c.Name;
    settings->SetExposure(exposure);
    settings->SetOutput(vtkReliefProperty::NonFiniteCheckOutput);
    const Frame check = CaptureFrame(window);
    long long red = 0, covered = 0;
    for (size_t p = 0; p < check.Depth.size(); ++p)
    {
      if (check.Covered(p))
      {
        ++covered;
        red += check.Rgb[3 * p] > 128 && check.Rgb[3 * p + 1] < 128 ? 1 : 0;
      }
    }
    settings->SetOutput(vtkReliefProperty::ShadedOutput);
    const double e = EnvironmentError(CaptureFrame(window), reference, exposure);
    std::cout << "[hdr] " << c.Name << ": " << red << " non-finite of " << covered << " pixels, "
              << e << "% error vs the exact render of the same lights\n";
    EXPECT_GT(covered, 1000) << c.Name;
    EXPECT_EQ(red, 0) << c.Name;
    EXPECT_LT(e, 1.0) << c.Name;
  }
  // The detector fires in the light-set path too. Non-finite lights are refused before drawing
  // (vtkLightSetTexture), so the NaN is handed to the shader as the material's diffuse colour,
  // which every light's contribution is multiplied by: the fragments must show red.
  scene.Actor->GetProperty()->SetDiffuseColor(std::nan(""), std::nan(""), std::nan(""));
  settings->SetOutput(vtkReliefProperty::NonFiniteCheckOutput);
  const Frame check = CaptureFrame(window);
  long long red = 0, covered = 0;
  for (size_t p = 0; p < check.Depth.size(); ++p)
  {
    if (check.Covered(p))
    {
      ++covered;
      red += check.Rgb[3 * p] > 128 && check.Rgb[3 * p + 1] < 128 ? 1 : 0;
    }
  }
  std::cout << "[hdr] NaN diffuse colour: " << red << " non-finite of " << covered << " pixels\n";
  EXPECT_GT(red, covered / 2);
}
