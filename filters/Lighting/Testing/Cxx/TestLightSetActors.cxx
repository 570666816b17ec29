// SPDX-License-Identifier: BSD-3-Clause
// Ordinary VTK actors (vtkPolyDataMapper) lit by a light set through
// vtkLightSetLighting, measured per pixel against independent references on a white Lambertian
// sphere (alone, and above a plane for shadows): the path tracer under the procedural sky, the
// exact irradiance of the sun-and-sky map, and the exact light set with Embree visibility.
// Negative tests: VTK's headlight alone, the lights read y-up, the lights without the remainder,
// the sun left to the spherical harmonics, and no shadow maps must all fail the same checks.
#include "ImageCompare.h"
#include "LightSetActorsScene.h"
#include "LightSetSplit.h"
#include "vtkLightSetLighting.h"
#include "vtkLightSetReader.h"
#include "vtkMedianCutLights.h"

#include "MesolightTestUtilities.h"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <iostream>
#include <string>

using mesolight::CompareLightSetActors;
using mesolight::LightSetActorsError;
using mesolight::LightSetActorsOptions;
using mesolight::LightSetActorsScene;
using mesolight::LightSetActorsVariant;

namespace
{
// Renders a variant and compares it with the reference; prints the figures.
LightSetActorsError Measure(const LightSetActorsScene& scene, const LightSetActorsVariant& variant,
  const std::vector<float>& reference, const std::string& label)
{
  std::string error;
  mesolight::LightSetActorsView view = mesolight::MakeLightSetActorsView(scene, variant, error);
  EXPECT_TRUE(view.Window) << error;
  if (!view.Window)
  {
    return LightSetActorsError{ 1e9, 1e9, 0 };
  }
  const mesolight::Frame frame = mesolight::CaptureFrame(view.Window);
  const LightSetActorsError e = CompareLightSetActors(frame, reference, scene.Exposure);
  std::cout << "[ LightSetActors ] " << label << ": mean " << 100.0 * e.Mean << "%, p95 "
            << 100.0 * e.P95 << "% over " << e.Pixels << " pixels" << std::endl;
  const std::string png =
    (std::filesystem::path(MESOLIGHT_TEST_TEMP_DIR) / ("light-set-actors-" + label + ".png"))
      .string();
  mesolight::WritePng(frame, png.c_str());
  return e;
}

LightSetActorsScene Build(const LightSetActorsOptions& options)
{
  LightSetActorsScene scene;
  std::string error;
  EXPECT_TRUE(mesolight::BuildLightSetActorsScene(options, scene, error)) << error;
  return scene;
}

std::vector<mesolight::SetLight> SetLights(vtkPolyData* lights)
{
  std::vector<mesolight::SetLight> out(static_cast<size_t>(lights->GetNumberOfPoints()));
  vtkDataArray* e = lights->GetPointData()->GetArray("Irradiance");
  for (vtkIdType k = 0; k < lights->GetNumberOfPoints(); ++k)
  {
    lights->GetPoint(k, out[k].Direction);
    e->GetTuple(k, out[k].Irradiance);
  }
  return out;
}

// Mean relative luminance error of a split against the exact light set over the upper normals.
double SplitError(
  const std::vector<mesolight::SetLight>& lights, int k, mesolight::RemainderModel m)
{
  const mesolight::LightSetSplit split = mesolight::SplitLightSet(lights, k, m);
  double sum = 0.0;
  int count = 0;
  for (int i = 0; i < 2000; ++i)
  {
    const double z = 1.0 - (i + 0.5) / 2000.0; // upper hemisphere
    const double r = std::sqrt(1.0 - z * z);
    const double phi = 2.399963 * i;
    const double n[3] = { r * std::cos(phi), r * std::sin(phi), z };
    double exact[3], approx[3];
    mesolight::LightSetIrradiance(lights, n, exact);
    split.Evaluate(n, approx);
    const double y = mesolight::Luminance(exact[0], exact[1], exact[2]);
    sum += std::abs(mesolight::Luminance(approx[0], approx[1], approx[2]) - y) / y;
    ++count;
  }
  return sum / count;
}
} // namespace

TEST(LightSetActors, SplitOnTheCpu)
{
  LightSetActorsOptions options;
  options.Environment = "procedural:sun";
  const LightSetActorsScene scene = Build(options);
  const auto lights = SetLights(scene.Lights);
  using mesolight::RemainderModel;
  const double sh8 = SplitError(lights, 8, RemainderModel::SphericalHarmonics);
  const double ambient8 = SplitError(lights, 8, RemainderModel::Ambient);
  const double none8 = SplitError(lights, 8, RemainderModel::None);
  const double sh0 = SplitError(lights, 0, RemainderModel::SphericalHarmonics);
  const double all = SplitError(lights, 1000, RemainderModel::None);
  std::cout << "[ LightSetActors ] split errors on the sun sky: K=8+SH " << 100 * sh8
            << "%, K=8+ambient " << 100 * ambient8 << "%, K=8 alone " << 100 * none8
            << "%, SH alone " << 100 * sh0 << "%" << std::endl;
  EXPECT_LT(all, 1e-12); // every light directional: exact
  EXPECT_LT(sh8, 0.03);
  EXPECT_GT(none8, 0.15);
  EXPECT_GT(sh0, 0.05);
  EXPECT_LT(sh8, ambient8);

  // vtkLightSetLighting evaluates the same split.
  vtkNew<vtkLightSetLighting> lighting;
  lighting->SetLightSet(scene.Lights);
  lighting->SetNumberOfDirectionalLights(8);
  const double n[3] = { 0.0, 0.6, 0.8 };
  double a[3], b[3];
  ASSERT_TRUE(lighting->EvaluateIrradiance(n, a));
  mesolight::SplitLightSet(lights, 8, RemainderModel::SphericalHarmonics).Evaluate(n, b);
  EXPECT_NEAR(a[1], b[1], 1e-9 * b[1]);
}

TEST(LightSetActors, BadLightSetsFailClearly)
{
  vtkNew<vtkLightSetLighting> lighting;
  vtkNew<mesolight_test::MessageCapture> messages;
  lighting->AddObserver(vtkCommand::ErrorEvent, messages);
  vtkNew<vtkRenderer> renderer;
  EXPECT_FALSE(lighting->Apply(renderer));
  EXPECT_TRUE(messages->HasError("No light set"));
  vtkNew<vtkPolyData> empty;
  lighting->SetLightSet(empty);
  EXPECT_FALSE(lighting->Apply(renderer));
  EXPECT_TRUE(messages->HasError("\"Irradiance\""));
  EXPECT_FALSE(lighting->Apply(nullptr));
}

TEST(LightSetActors, SphereUnderSkyAgainstPathTracer)
{
  LightSetActorsOptions options;
  options.Environment = "procedural:sky";
  const LightSetActorsScene scene = Build(options);
  const std::vector<float> reference = mesolight::PathTracedLightSetActors(scene, 256);
  mesolight::WritePng(mesolight::ReferenceFrame(reference, options.Size, scene.Exposure),
    (std::filesystem::path(MESOLIGHT_TEST_TEMP_DIR) / "light-set-actors-sky-pathtraced.png")
      .string()
      .c_str());
  LightSetActorsVariant variant; // K = 4, spherical-harmonic remainder
  const LightSetActorsError good = Measure(scene, variant, reference, "sky-K4-sh");
  EXPECT_GT(good.Pixels, 5000);
  EXPECT_LT(good.Mean, 0.04);
  EXPECT_LT(good.P95, 0.10);

  LightSetActorsVariant ambient = variant;
  ambient.Remainder = vtkLightSetLighting::RemainderAmbient;
  const LightSetActorsError constant = Measure(scene, ambient, reference, "sky-K4-ambient");
  EXPECT_GT(constant.Mean, good.Mean);

  // Negative: VTK's headlight, the lights read y-up, the lights without their remainder.
  LightSetActorsVariant headlight;
  headlight.HeadlightOnly = true;
  EXPECT_GT(Measure(scene, headlight, reference, "sky-headlight").Mean, 0.15);
  LightSetActorsVariant flipped = variant;
  flipped.FlippedUp = true;
  EXPECT_GT(Measure(scene, flipped, reference, "sky-flipped").Mean, 0.15);
  LightSetActorsVariant none = variant;
  none.Remainder = vtkLightSetLighting::RemainderNone;
  EXPECT_GT(Measure(scene, none, reference, "sky-K4-none").Mean, 0.15);
}

TEST(LightSetActors, SphereUnderSunAgainstExactIrradiance)
{
  LightSetActorsOptions options;
  options.Environment = "procedural:sun";
  const LightSetActorsScene scene = Build(options);
  const std::vector<float> reference = mesolight::ExactEnvironmentLightSetActors(scene);
  LightSetActorsVariant variant;
  variant.DirectionalLights = 8;
  const LightSetActorsError good = Measure(scene, variant, reference, "sun-K8-sh");
  EXPECT_LT(good.Mean, 0.04);
  EXPECT_LT(good.P95, 0.10);

  // Negative: the sun left to the spherical harmonics (K = 0); the lights read y-up.
  LightSetActorsVariant shOnly = variant;
  shOnly.DirectionalLights = 0;
  EXPECT_GT(Measure(scene, shOnly, reference, "sun-K0-sh").Mean, 0.10);
  LightSetActorsVariant flipped = variant;
  flipped.FlippedUp = true;
  EXPECT_GT(Measure(scene, flipped, reference, "sun-flipped").Mean, 0.15);
}

TEST(LightSetActors, ShadowsUnderSunAgainstExactLightSet)
{
  LightSetActorsOptions options;
  options.Environment = "procedural:sun";
  options.Plane = true;
  const LightSetActorsScene scene = Build(options);
  const std::vector<float> reference = mesolight::ExactLightSetLightSetActors(scene);
  mesolight::WritePng(mesolight::ReferenceFrame(reference, options.Size, scene.Exposure),
    (std::filesystem::path(MESOLIGHT_TEST_TEMP_DIR) / "light-set-actors-plane-exact.png")
      .string()
      .c_str());
  // 16 lights with shadow maps: the sun's pixels and the brightest sky lights (4.8% here; 8
  // lights give 7.9%, docs/light-set-actors.md).
  LightSetActorsVariant variant;
  variant.DirectionalLights = 16;
  variant.Shadows = true;
  const LightSetActorsError shadowed = Measure(scene, variant, reference, "plane-K16-shadows");
  LightSetActorsVariant unshadowed = variant;
  unshadowed.Shadows = false;
  const LightSetActorsError plain = Measure(scene, unshadowed, reference, "plane-K16-noshadows");
  EXPECT_LT(shadowed.Mean, 0.07);
  EXPECT_LT(shadowed.P95, 0.35);
  // Negative: without shadow maps the sphere's shadow is missing.
  EXPECT_GT(plain.Mean, shadowed.Mean + 0.05);
}

TEST(LightSetActors, LightsCsvReadBackLightsTheSame)
{
  // The light set through `mesolight lights`' CSV and vtkLightSetReader gives the same lighting
  // (model and rendered frame) as the median cut's own output.
  LightSetActorsOptions options;
  options.Environment = "procedural:sun";
  options.Size = 96;
  LightSetActorsScene scene = Build(options);
  const std::string csv =
    (std::filesystem::path(MESOLIGHT_TEST_TEMP_DIR) / "light-set-actors-readback.csv").string();
  std::filesystem::remove(csv);
  std::string error;
  ASSERT_TRUE(vtkMedianCutLights::WriteCsv(scene.Lights, csv, error)) << error;
  vtkNew<vtkLightSetReader> reader;
  reader->SetFileName(csv.c_str());
  reader->Update();
  ASSERT_EQ(reader->GetOutput()->GetNumberOfPoints(), scene.Lights->GetNumberOfPoints());

  vtkNew<vtkLightSetLighting> fromFilter;
  fromFilter->SetLightSet(scene.Lights);
  vtkNew<vtkLightSetLighting> fromCsv;
  fromCsv->SetLightSet(reader->GetOutput());
  const std::array<std::array<double, 3>, 2> normals = { { { 0.0, 0.0, 1.0 },
    { 0.6, -0.8, 0.0 } } };
  for (const auto& normal : normals)
  {
    double a[3], b[3];
    ASSERT_TRUE(fromFilter->EvaluateIrradiance(normal.data(), a));
    ASSERT_TRUE(fromCsv->EvaluateIrradiance(normal.data(), b));
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(a[c], b[c], 1e-6 * std::abs(a[c]) + 1e-12);
    }
  }

  LightSetActorsVariant variant;
  variant.DirectionalLights = 8;
  const mesolight::Frame original =
    mesolight::CaptureFrame(mesolight::MakeLightSetActorsView(scene, variant, error).Window);
  scene.Lights = reader->GetOutput();
  const mesolight::Frame readBack =
    mesolight::CaptureFrame(mesolight::MakeLightSetActorsView(scene, variant, error).Window);
  ASSERT_EQ(original.Rgb.size(), readBack.Rgb.size());
  int largest = 0;
  for (size_t k = 0; k < original.Rgb.size(); ++k)
  {
    largest = std::max(largest, std::abs(int(original.Rgb[k]) - int(readBack.Rgb[k])));
  }
  EXPECT_LE(largest, 1);
}
