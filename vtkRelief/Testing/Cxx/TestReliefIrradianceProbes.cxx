// SPDX-License-Identifier: BSD-3-Clause
// vtkReliefMapper lit per pixel by a light field's lighting on the GPU: SH9 irradiance probes
// over the relief's texture, and the field's emitters as VTK point lights with a cosine lobe.
// References: the analytic furnace case (constant radiance L: irradiance pi L at every normal),
// and the CPU evaluation of the same lighting on the exact height-field intersector
// (reliefcore/core/ReliefShading, what `mesolight vlf render --relief` shades with), pixel by
// pixel along the rays of the rendered pixels. Negative cases: the flat normal, the probes'
// coefficients in the wrong place, an emitter without its cosine lobe or without its 1 / d^2.
// The scene is ReliefProbesTestScene's; the side walls of a walled relief are tested in
// TestReliefIrradianceProbesWalls.cxx.
#include "MessageCapture.h"
#include "ReliefProbesTestScene.h"
#include "vtkCompositeReliefMapper.h"
#include "vtkIrradianceProbesTexture.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkActor.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkOutputWindow.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkTrivialProducer.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <iostream>
#include <vector>

namespace
{
using namespace mesolight;
using namespace mesolight::test::probes;

// The largest |frame - 255 x value| over the covered pixels' channels, and how many pixels that
// is.
double WorstError(const Frame& frame, const glm::dvec3& value, long long& covered)
{
  double worst = 0.0;
  covered = 0;
  for (size_t p = 0; p < frame.Depth.size(); ++p)
  {
    if (frame.Covered(p))
    {
      ++covered;
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst, std::abs(frame.Rgb[3 * p + c] - 255.0 * value[c]));
      }
    }
  }
  return worst;
}

// A 4 x 3 grid of probes, each a clamped-cosine lobe max(0, d . axis) of its own axis and colour:
// smooth light that changes across the texture, so the bilinear interpolation between probes
// and the world-space basis are both exercised.
ReliefLighting DirectionalProbes(int nu, int nv)
{
  ReliefLighting lighting;
  lighting.ProbesU = nu;
  lighting.ProbesV = nv;
  lighting.OcclusionDirections = 0; // the GPU path does not model the relief's own occlusion
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const double a = 1.2 * (i / (nu - 1.0) - 0.5), b = 1.2 * (j / (nv - 1.0) - 0.5);
      const glm::dvec3 axis = glm::normalize(glm::dvec3(a, b, 1.0));
      const glm::dvec3 colour(0.9 + 0.3 * i / (nu - 1.0), 0.8, 0.7 + 0.4 * j / (nv - 1.0));
      lighting.Probes.push_back(
        Project([&](const glm::dvec3& d) { return colour * std::max(0.0, glm::dot(d, axis)); }));
    }
  }
  return lighting;
}
} // namespace

// A uniform radiance L from every direction: the irradiance is pi L at every normal, so every
// pixel of a bumpy relief shows albedo x L whatever its slope. Negative: the same coefficient in
// another pixel of the probe (L_1-1 instead of L_00) is not that light.
TEST(ReliefIrradianceProbes, ConstantRadianceGivesAlbedoTimesRadiance)
{
  Scene scene;
  BuildScene(scene, Bumps, true);
  const glm::dvec3 albedo(0.8, 0.6, 0.4);
  scene.Actor->GetProperty()->SetColor(albedo.x, albedo.y, albedo.z);
  const glm::dvec3 radiance(0.9, 0.7, 0.5);
  const std::vector<SH9> probes(4, ConstantRadiance(radiance));
  scene.Mapper->SetIrradianceProbesData(ProbeImage(2, 2, probes));
  long long covered = 0;
  const double worst = WorstError(Render(scene), albedo * radiance, covered);
  std::cout << "[constant] " << covered << " pixels, worst |error| " << worst << " levels\n";
  EXPECT_GT(covered, Pixels * Pixels / 4);
  EXPECT_LE(worst, 1.5);

  // Negative: the constant in coefficient 1 (a y-dipole) instead of 0 is far from albedo x L.
  std::vector<SH9> shifted(4);
  for (SH9& sh : shifted)
  {
    sh.L[1] = probes[0].L[0];
  }
  scene.Mapper->SetIrradianceProbesData(ProbeImage(2, 2, shifted));
  const Frame wrong = Render(scene);
  double mean = 0.0;
  long long n = 0;
  for (size_t p = 0; p < wrong.Depth.size(); ++p)
  {
    if (wrong.Covered(p))
    {
      mean += std::abs(wrong.Rgb[3 * p] - 255.0 * albedo[0] * radiance[0]);
      ++n;
    }
  }
  mean /= std::max<long long>(1, n);
  std::cout << "[constant] coefficient in the wrong pixel: mean |error| " << mean << " levels\n";
  EXPECT_GT(mean, 20.0);
  // Without probes (and without lights) the relief is black.
  scene.Mapper->SetIrradianceProbesData(nullptr);
  const Frame dark = Render(scene);
  for (size_t p = 0; p < dark.Depth.size(); ++p)
  {
    if (dark.Covered(p))
    {
      ASSERT_LE(dark.Rgb[3 * p], 1) << "pixel " << p;
    }
  }
}

// Directional probes over a bumpy relief seen obliquely, against the CPU evaluation (exact first
// hit, SH9 irradiance at the exact perturbed normal, the same bilinear probe interpolation). The
// negative case, the CPU image shaded with the flat normal, fails the same tolerance.
TEST(ReliefIrradianceProbes, DirectionalProbesMatchTheCpuEvaluationAtThePerturbedNormal)
{
  Scene scene;
  BuildScene(scene, Bumps, true);
  const ReliefLighting lighting = DirectionalProbes(4, 3);
  scene.Mapper->SetIrradianceProbesData(ProbeImage(4, 3, lighting.Probes));
  const Frame gpu = Render(scene);
  const glm::dvec3 albedo(1.0);
  long long compared = 0;
  const double perturbed =
    MeanError(gpu, CpuImage(scene, lighting, ReliefNormal::Perturbed, albedo), &compared);
  const double flat = MeanError(gpu, CpuImage(scene, lighting, ReliefNormal::Flat, albedo));
  std::cout << "[probes] " << compared << " pixels: mean |GPU - CPU| " << perturbed
            << " levels at the perturbed normal, " << flat << " against the flat normal\n";
  EXPECT_GT(compared, Pixels * Pixels / 4);
  EXPECT_LT(perturbed, 2.0);
  EXPECT_GT(flat, 2.0 * 2.0);

  // The same through vtkCompositeReliefMapper: the same pixels.
  vtkNew<vtkCompositeReliefMapper> composite;
  composite->SetInputData(scene.Mapper->GetInput());
  composite->SetReliefTextureData(scene.Mapper->GetReliefTexture());
  composite->SetReliefProperty(scene.Mapper->GetReliefProperty());
  composite->SetIrradianceProbesData(scene.Mapper->GetIrradianceProbes());
  scene.Actor->SetMapper(composite);
  const Frame viaComposite = Render(scene);
  scene.Actor->SetMapper(scene.Mapper);
  long long different = 0, covered = 0;
  for (size_t p = 0; p < gpu.Depth.size(); ++p)
  {
    covered += gpu.Covered(p) ? 1 : 0;
    for (int c = 0; c < 3; ++c)
    {
      different += std::abs(gpu.Rgb[3 * p + c] - viaComposite.Rgb[3 * p + c]) > 1 ? 1 : 0;
    }
  }
  std::cout << "[probes] composite mapper: " << different << " differing channels of "
            << 3 * covered << "\n";
  EXPECT_LT(different, 3 * covered / 1000 + 1);
}

namespace
{
// An emitter beside and above the relief, facing it obliquely: its cosine lobe and 1 / d^2 change
// by factors of 2-3 across the square, and its light is low enough for the bumps to shadow.
struct Emitter
{
  double Position[3] = { 0.5, -0.3, 0.22 };
  double Normal[3] = { 0.0, 0.9, -0.45 };
  double Intensity[3] = { 2.4, 2.0, 1.5 }; // Le x A

  // The same emitter as the CPU evaluation takes it.
  ReliefEmitterSample Sample() const
  {
    ReliefEmitterSample sample;
    sample.Position = glm::dvec3(this->Position[0], this->Position[1], this->Position[2]);
    sample.Normal = glm::normalize(glm::dvec3(this->Normal[0], this->Normal[1], this->Normal[2]));
    sample.RadianceArea = glm::dvec3(this->Intensity[0], this->Intensity[1], this->Intensity[2]);
    return sample;
  }
};

ReliefLighting EmitterLighting(const Emitter& e)
{
  ReliefLighting lighting;
  lighting.OcclusionDirections = 0;
  lighting.Emitters.push_back(e.Sample());
  return lighting;
}
} // namespace

// A field's emitter as a VTK light (vtkReliefMapper::ConfigureEmitterLight) with the relief's
// self-shadowing, against the CPU evaluation albedo / pi x Le A cos cos / d^2 with exact
// visibility. Negative cases: the same light without the cosine lobe (a plain point light) or
// without the falloff, each scaled to agree at the square's centre, fail the tolerance.
TEST(ReliefIrradianceProbes, EmitterLightMatchesTheCpuEvaluation)
{
  Scene scene;
  BuildScene(scene, Bumps, true);
  const Emitter e;
  vtkNew<vtkLight> light;
  vtkReliefMapper::ConfigureEmitterLight(light, e.Position, e.Normal, e.Intensity);
  EXPECT_TRUE(light->GetPositional());
  EXPECT_DOUBLE_EQ(light->GetConeAngle(), 90.0);
  EXPECT_DOUBLE_EQ(light->GetExponent(), 1.0);
  scene.Renderer->AddLight(light);
  const Frame gpu = Render(scene);
  const std::vector<double> cpu =
    CpuImage(scene, EmitterLighting(e), ReliefNormal::Perturbed, glm::dvec3(1.0));
  long long compared = 0;
  const double error = MeanError(gpu, cpu, &compared);
  long long shadowed = 0;
  for (size_t p = 0; p < gpu.Depth.size(); ++p)
  {
    shadowed += gpu.Covered(p) && cpu[3 * p] == 0.0 ? 1 : 0;
  }

  // The centre's distance and emitter cosine, to scale the wrong lights to agree there.
  const glm::dvec3 centre(0.5, 0.5, 0.0);
  const glm::dvec3 position = e.Sample().Position;
  const glm::dvec3 normal = e.Sample().Normal;
  const double d = glm::length(centre - position);
  const double cosine = glm::dot(normal, (centre - position) / d);
  // Without the lobe: a plain point light, intensity times the centre's cosine.
  light->SetConeAngle(180.0);
  light->SetIntensity(light->GetIntensity() * cosine);
  const double noLobe = MeanError(Render(scene), cpu);
  // Without the falloff: constant attenuation, intensity over the centre's d^2.
  vtkReliefMapper::ConfigureEmitterLight(light, e.Position, e.Normal, e.Intensity);
  light->SetAttenuationValues(1.0, 0.0, 0.0);
  light->SetIntensity(light->GetIntensity() / (d * d));
  const double noFalloff = MeanError(Render(scene), cpu);
  // Without self-shadowing: compared where the exact evaluation has the relief's shadow but the
  // unshadowed light would show (the pixels where shadowing matters).
  vtkReliefMapper::ConfigureEmitterLight(light, e.Position, e.Normal, e.Intensity);
  scene.Mapper->GetReliefProperty()->SelfShadowingOff();
  const Frame unshadowed = Render(scene);
  scene.Mapper->GetReliefProperty()->SelfShadowingOn();
  double inShadow = 0.0, inShadowUnshadowed = 0.0;
  long long shadowPixels = 0;
  for (size_t p = 0; p < gpu.Depth.size(); ++p)
  {
    if (gpu.Covered(p) && cpu[3 * p] == 0.0 && unshadowed.Rgb[3 * p] > 8)
    {
      inShadow += gpu.Rgb[3 * p];
      inShadowUnshadowed += unshadowed.Rgb[3 * p];
      ++shadowPixels;
    }
  }
  inShadow /= std::max<long long>(1, shadowPixels);
  inShadowUnshadowed /= std::max<long long>(1, shadowPixels);
  std::cout << "[emitter] " << compared << " pixels (" << shadowed
            << " black in the CPU evaluation): mean |GPU - CPU| " << error
            << " levels; no cosine lobe " << noLobe << ", no 1/d^2 " << noFalloff << "; in the "
            << shadowPixels
            << " pixels of the relief's shadow where the light faces the surface: " << inShadow
            << " levels shadowed, " << inShadowUnshadowed << " without self-shadowing\n";
  EXPECT_GT(compared, Pixels * Pixels / 4);
  EXPECT_GT(shadowPixels, compared / 50);
  EXPECT_LT(error, 2.0);
  EXPECT_GT(noLobe, 2.0 * 2.0);
  EXPECT_GT(noFalloff, 2.0 * 2.0);
  EXPECT_LT(inShadow, 4.0);
  EXPECT_GT(inShadowUnshadowed, 12.0);
}

// An area emitter (a 0.15 x 0.15 square facing the relief, 4 x 4 samples) as one VTK light at its
// centre, with the relief's shadow of its area from the visible-share map's fourth value
// (ReliefEmitterShadowMap), against the CPU evaluation summing the 16 samples, each shadowed by
// the exact march. Compared where the area's penumbra matters: the pixels where the CPU's area
// light and its point light at the centre differ by more than 2 levels. The negative case is the
// mapper without that value (a three-value map): one hard shadow ray to the light's centre.
TEST(ReliefIrradianceProbes, AreaEmitterShadowFromTheMapMatchesTheCpuPenumbra)
{
  Scene scene;
  BuildScene(scene, Bumps, true);
  const Emitter e;
  const ReliefEmitterSample whole = e.Sample();
  const glm::dvec3 centre = whole.Position;
  const glm::dvec3 normal = whole.Normal;
  const glm::dvec3 side(1.0, 0.0, 0.0);
  const glm::dvec3 up = glm::cross(normal, side);
  ReliefLighting area = EmitterLighting(e);
  area.Emitters.clear();
  for (int a = 0; a < 4; ++a)
  {
    for (int b = 0; b < 4; ++b)
    {
      ReliefEmitterSample sample;
      sample.Position =
        centre + 0.15 * ((a + 0.5) / 4.0 - 0.5) * side + 0.15 * ((b + 0.5) / 4.0 - 0.5) * up;
      sample.Normal = normal;
      sample.RadianceArea = whole.RadianceArea / 16.0;
      area.Emitters.push_back(sample);
    }
  }
  vtkNew<vtkLight> light;
  vtkReliefMapper::ConfigureEmitterLight(light, e.Position, e.Normal, e.Intensity);
  scene.Renderer->AddLight(light);
  const std::vector<float> shadow = ReliefEmitterShadowMap(scene.Height, scene.Plane, area.Emitters,
    std::vector<int>(area.Emitters.size(), 0), 1, DepthSize, DepthSize);
  // Probes of no light: only the emitter light shows.
  const auto probesWith = [&shadow](int components)
  {
    vtkSmartPointer<vtkImageData> probes = ProbeImage(1, 1, { ConstantRadiance(glm::dvec3(0.0)) });
    AttachVisibleShare(probes, DepthSize, DepthSize, static_cast<vtkIdType>(shadow.size()),
      components,
      [&shadow](vtkIdType t, int c) { return c == 3 ? shadow[static_cast<std::size_t>(t)] : 1.0; });
    return probes;
  };
  scene.Mapper->SetIrradianceProbesData(probesWith(4));
  const Frame mapped = Render(scene);
  scene.Mapper->SetIrradianceProbesData(probesWith(3));
  const Frame marched = Render(scene);
  const std::vector<double> cpu = CpuImage(scene, area, ReliefNormal::Perturbed, glm::dvec3(1.0));
  const std::vector<double> point =
    CpuImage(scene, EmitterLighting(e), ReliefNormal::Perturbed, glm::dvec3(1.0));
  double errorMapped = 0.0, errorMarched = 0.0;
  long long penumbra = 0;
  for (size_t p = 0; p < mapped.Depth.size(); ++p)
  {
    if (!mapped.Covered(p) || cpu[3 * p] < 0.0 || point[3 * p] < 0.0 ||
      std::abs(cpu[3 * p] - point[3 * p]) <= 2.0)
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      errorMapped += std::abs(mapped.Rgb[3 * p + c] - cpu[3 * p + c]) / 3.0;
      errorMarched += std::abs(marched.Rgb[3 * p + c] - cpu[3 * p + c]) / 3.0;
    }
    ++penumbra;
  }
  long long compared = 0;
  const double overall = MeanError(mapped, cpu, &compared);
  const double overallMarched = MeanError(marched, cpu);
  errorMapped /= std::max<long long>(1, penumbra);
  errorMarched /= std::max<long long>(1, penumbra);
  std::cout << "[area emitter] " << compared << " pixels, mean |GPU - CPU| " << overall
            << " levels (one hard ray: " << overallMarched << "); in the " << penumbra
            << " penumbra pixels: " << errorMapped << " with the map's shadow, " << errorMarched
            << " with one hard ray (negative)\n";
  EXPECT_GT(penumbra, compared / 50);
  EXPECT_LT(overall, 2.0);
  EXPECT_LT(overall, overallMarched);
  EXPECT_LT(errorMapped, 0.5 * errorMarched);
  EXPECT_GT(errorMarched, 4.0);
}

// Bad probe images: a width that is not a multiple of 9, a NaN coefficient, an empty image. Each
// is reported with a clear error, nothing crashes, and the relief is drawn as without probes
// (here by its one VTK light).
TEST(ReliefIrradianceProbes, BadProbesAreReportedAndLeftOut)
{
  Scene scene;
  BuildScene(scene, Bumps, false);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(0.2, 0.3, 1.0);
  light->SetFocalPoint(0.5, 0.5, 0.0);
  scene.Renderer->AddLight(light);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(scene.Mapper);
  const Frame without = Render(scene);
  ASSERT_TRUE(messages->Errors.empty()) << messages->AllErrors();

  auto notNine = vtkSmartPointer<vtkImageData>::New();
  notNine->SetDimensions(10, 2, 1);
  notNine->AllocateScalars(VTK_FLOAT, 3);
  std::fill_n(static_cast<float*>(notNine->GetScalarPointer()), 60, 0.5f);
  auto nan = ProbeImage(2, 2, std::vector<SH9>(4, ConstantRadiance(glm::dvec3(0.5))));
  static_cast<float*>(nan->GetScalarPointer())[3 * 11 + 1] = std::nanf("");
  auto empty = vtkSmartPointer<vtkImageData>::New();
  struct Case
  {
    const char* Name;
    vtkImageData* Image;
    const char* Message;
  };
  const Case cases[] = { { "width 10", notNine, "not a multiple of 9" },
    { "NaN coefficient", nan, "Coefficient 2 of irradiance probe (1, 0) is not finite" },
    { "empty image", empty, "irradiance probes image is empty" } };
  for (const Case& c : cases)
  {
    messages->Clear();
    scene.Mapper->SetIrradianceProbesData(c.Image);
    const Frame frame = Render(scene);
    Render(scene); // reported once, not at every frame
    std::cout << "[bad probes] " << c.Name << ": " << messages->AllErrors() << "\n";
    EXPECT_TRUE(messages->HasError(c.Message)) << c.Name << ": " << messages->AllErrors();
    EXPECT_EQ(messages->Errors.size(), 1u) << c.Name;
    ASSERT_EQ(frame.Rgb.size(), without.Rgb.size());
    long long different = 0;
    for (size_t i = 0; i < frame.Rgb.size(); ++i)
    {
      different += frame.Rgb[i] != without.Rgb[i] ? 1 : 0;
    }
    EXPECT_EQ(different, 0) << c.Name << ": drawn as without probes";
  }
  // Good probes again: drawn with them, no error.
  messages->Clear();
  scene.Mapper->SetIrradianceProbesData(
    ProbeImage(2, 2, std::vector<SH9>(4, ConstantRadiance(glm::dvec3(0.5)))));
  const Frame good = Render(scene);
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  long long brighter = 0;
  for (size_t p = 0; p < good.Depth.size(); ++p)
  {
    brighter +=
      good.Covered(p) && good.Rgb[3 * p] >= std::min(255, without.Rgb[3 * p] + 50) ? 1 : 0;
  }
  EXPECT_GT(brighter, Pixels * Pixels / 2);
}

// Probes from a pipeline (input port 3) shade as the same data given directly, and a modified
// probe image is uploaded again: the new radiance shows at the next render.
TEST(ReliefIrradianceProbes, AttachingANullShareMapWarnsAndAttachesNothing)
{
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(vtkOutputWindow::GetInstance());
  vtkSmartPointer<vtkImageData> probes = ProbeImage(1, 1, { ConstantRadiance(glm::dvec3(1.0)) });
  vtkIrradianceProbesTexture::AttachVisibleShare(probes, nullptr, 4, 4);
  EXPECT_TRUE(messages->HasWarning("no share map given")) << messages->AllWarnings();
  EXPECT_EQ(probes->GetFieldData()->GetArray(vtkIrradianceProbesTexture::GetVisibleShareSizeName()),
    nullptr);
  vtkNew<vtkFloatArray> share;
  vtkIrradianceProbesTexture::AttachVisibleShare(nullptr, share, 4, 4);
  EXPECT_TRUE(messages->HasWarning("no probes given")) << messages->AllWarnings();
  EXPECT_EQ(share->GetName(), nullptr);
}

TEST(ReliefIrradianceProbes, ProbesFromAConnectionFollowTheirChanges)
{
  Scene scene;
  BuildScene(scene, Bumps, false);
  auto image = ProbeImage(2, 2, std::vector<SH9>(4, ConstantRadiance(glm::dvec3(0.25))));
  vtkNew<vtkTrivialProducer> producer;
  producer->SetOutput(image);
  scene.Mapper->SetIrradianceProbesConnection(producer->GetOutputPort());
  const Frame first = Render(scene);
  EXPECT_EQ(scene.Mapper->GetIrradianceProbes(), image.Get());
  auto* values = static_cast<float*>(image->GetScalarPointer());
  for (int p = 0; p < 4; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      values[3 * 9 * p + c] *= 2.0f; // L_00 of every probe: radiance 0.5
    }
  }
  image->GetPointData()->GetScalars()->Modified();
  const Frame second = Render(scene);
  const size_t centre = size_t(Pixels / 2) * Pixels + Pixels / 2;
  ASSERT_TRUE(first.Covered(centre));
  std::cout << "[connection] centre " << int(first.Rgb[3 * centre]) << " then "
            << int(second.Rgb[3 * centre]) << "\n";
  EXPECT_NEAR(first.Rgb[3 * centre], 255.0 * 0.25, 1.5);
  EXPECT_NEAR(second.Rgb[3 * centre], 255.0 * 0.5, 1.5);
}

// With a light set too, the probes' light adds to it; by default (ToneMapping on, Exposure 1) the
// sum is tone mapped as the light set alone is: Reinhard's x / (1 + x).
TEST(ReliefIrradianceProbes, ProbesAddToALightSetAndAreToneMappedByDefault)
{
  Scene scene;
  BuildScene(
    scene, [](double, double) { return 0.0; }, false); // flat: the normal is +z
  auto lights = vtkSmartPointer<vtkImageData>::New();
  lights->SetDimensions(1, 2, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(2);
  values->SetTuple3(0, 0.0, 0.0, 1.0); // straight down
  const double fromLights = 0.2;       // radiance it gives
  values->SetTuple3(1, vtkMath::Pi() * fromLights, vtkMath::Pi() * fromLights,
    vtkMath::Pi() * fromLights); // irradiance pi x 0.2 at normal incidence
  lights->GetPointData()->SetScalars(values);
  scene.Mapper->SetLightSetData(lights);
  const double fromProbes = 0.3;
  scene.Mapper->SetIrradianceProbesData(
    ProbeImage(1, 1, std::vector<SH9>(1, ConstantRadiance(glm::dvec3(fromProbes)))));
  const size_t centre = size_t(Pixels / 2) * Pixels + Pixels / 2;
  const Frame linear = Render(scene);
  scene.Mapper->GetReliefProperty()->ToneMappingOn();
  const Frame toneMapped = Render(scene);
  const double sum = fromLights + fromProbes;
  std::cout << "[light set + probes] linear " << int(linear.Rgb[3 * centre]) << ", tone mapped "
            << int(toneMapped.Rgb[3 * centre]) << "\n";
  EXPECT_NEAR(linear.Rgb[3 * centre], 255.0 * sum, 1.5);
  EXPECT_NEAR(toneMapped.Rgb[3 * centre], 255.0 * sum / (1.0 + sum), 1.5);
}

// The relief's precomputed occlusion (vtkIrradianceProbesTexture's visible-share map and the
// probes' fourth component, the scene's visibility of each light): on a flat relief under
// constant radiance L, a uniform map (V, S, Vs) gives albedo / pi x (S pi L + the multi-bounce
// inter-reflection of V at the seen share Vs), the formula of the CPU renderer
// (ReliefInterReflected), and a map of pairs (V, S) the series at Vs = V; a light seen by a
// quarter from every probe gives a quarter of its light. Negative: the map left out gives
// albedo x L, and the triple's Vs ignored the pair's value. A map of the wrong size is reported
// and the probes left out.
TEST(ReliefIrradianceProbes, VisibleShareAndLightVisibilityFollowTheCpuFormula)
{
  Scene scene;
  BuildScene(
    scene, [](double, double) { return 0.0; }, false);
  const glm::dvec3 albedo(0.8, 0.6, 0.4);
  scene.Actor->GetProperty()->SetColor(albedo.x, albedo.y, albedo.z);
  const glm::dvec3 radiance(0.9, 0.7, 0.5);
  const double visible = 0.5, sky = 0.8, seenShare = 0.35;
  vtkSmartPointer<vtkImageData> probes = ProbeImage(1, 1, { ConstantRadiance(radiance) });
  const auto attach = [&probes, visible, sky, seenShare](
                        int w, int h, vtkIdType tuples, int components = 3)
  {
    const double values[3] = { visible, sky, seenShare };
    AttachVisibleShare(
      probes, w, h, tuples, components, [&values](vtkIdType, int c) { return values[c]; });
  };
  attach(4, 4, 16);
  scene.Mapper->SetIrradianceProbesData(probes);
  const glm::dvec3 expected = albedo / vtkMath::Pi() *
    (sky * vtkMath::Pi() * radiance +
      ReliefInterReflected(
        ReliefInterReflection::MultiBounce, visible, seenShare, albedo, vtkMath::Pi() * radiance));
  const glm::dvec3 expectedPairs = albedo / vtkMath::Pi() *
    (sky * vtkMath::Pi() * radiance +
      ReliefInterReflected(
        ReliefInterReflection::MultiBounce, visible, albedo, vtkMath::Pi() * radiance));
  long long covered = 0;
  const double worst = WorstError(Render(scene), expected, covered);
  std::cout << "[visible share] " << covered << " pixels, worst |error| " << worst << " levels\n";
  EXPECT_GT(covered, Pixels * Pixels / 4);
  EXPECT_LE(worst, 1.5);
  // Negative: the seen share ignored (the pair's series) is off by more than the quantization.
  EXPECT_GT(WorstError(Render(scene), expectedPairs, covered), 4.0);
  // A map of pairs: the series at the point's own share.
  probes = ProbeImage(1, 1, { ConstantRadiance(radiance) });
  attach(4, 4, 16, 2);
  scene.Mapper->SetIrradianceProbesData(probes);
  const double worstPairs = WorstError(Render(scene), expectedPairs, covered);
  std::cout << "[visible share pairs] worst |error| " << worstPairs << " levels\n";
  EXPECT_LE(worstPairs, 1.5);
  // Negative: without the map the relief is albedo x L, far from the occluded value.
  vtkSmartPointer<vtkImageData> plain = ProbeImage(1, 1, { ConstantRadiance(radiance) });
  scene.Mapper->SetIrradianceProbesData(plain);
  EXPECT_GT(WorstError(Render(scene), expected, covered), 10.0);

  // The scene's visibility of light 0 (a fourth component of 0.25): a quarter of its light.
  // Compared against the same light fully visible (a fourth component of 1), no probe light.
  vtkNew<vtkLight> light;
  const double position[3] = { 0.5, 0.5, 1.0 }, normal[3] = { 0.0, 0.0, -1.0 },
               intensity[3] = { 1.5, 1.5, 1.5 };
  vtkReliefMapper::ConfigureEmitterLight(light, position, normal, intensity);
  scene.Renderer->AddLight(light);
  const auto lightOnly = [](double visibility)
  {
    vtkSmartPointer<vtkImageData> image = ProbeImage(1, 1, { SH9() });
    vtkNew<vtkFloatArray> values;
    values->SetNumberOfComponents(4);
    values->SetNumberOfTuples(9);
    for (vtkIdType k = 0; k < 9; ++k)
    {
      values->SetTuple4(k, 0.0, 0.0, 0.0, k == 0 ? visibility : 1.0);
    }
    image->GetPointData()->SetScalars(values);
    return image;
  };
  // The light's red over the relief with factor `high` over that with `low` (unclipped pixels).
  const auto lightRatio = [&](double low, double high)
  {
    scene.Mapper->SetIrradianceProbesData(lightOnly(low));
    const Frame lowFrame = Render(scene);
    scene.Mapper->SetIrradianceProbesData(lightOnly(high));
    const Frame highFrame = Render(scene);
    double sumLow = 0.0, sumHigh = 0.0;
    for (size_t p = 0; p < lowFrame.Depth.size(); ++p)
    {
      if (lowFrame.Covered(p) && highFrame.Covered(p) && lowFrame.Rgb[3 * p] < 250.0 &&
        highFrame.Rgb[3 * p] < 250.0)
      {
        sumLow += lowFrame.Rgb[3 * p];
        sumHigh += highFrame.Rgb[3 * p];
      }
    }
    EXPECT_GT(sumLow, 0.0);
    return sumHigh / sumLow;
  };
  const double quarter = 1.0 / lightRatio(0.25, 1.0);
  std::cout << "[light visibility] quarter / full = " << quarter << "\n";
  EXPECT_NEAR(quarter, 0.25, 0.01);
  // A factor above 1 (a light that stands for more than its point delivers,
  // vlf::EmitterLightFactors) is applied as it is: 1.5 gives three times 0.5's light. One above
  // vtkIrradianceProbesTexture::MaxLightFactor is reported.
  const double more = lightRatio(0.5, 1.5);
  std::cout << "[light factor] 1.5 / 0.5 = " << more << "\n";
  EXPECT_NEAR(more, 3.0, 0.05);
  {
    vtkNew<mesolight_test::MessageCapture> tooLarge;
    tooLarge->Watch(scene.Mapper);
    scene.Mapper->SetIrradianceProbesData(lightOnly(9.0));
    Render(scene);
    EXPECT_TRUE(tooLarge->HasError("The factor of light 0 at irradiance probe (0, 0) is 9"))
      << tooLarge->AllErrors();
  }
  scene.Renderer->RemoveAllLights();

  // A map whose size does not match its values: reported, the relief drawn without the probes.
  probes = ProbeImage(1, 1, { ConstantRadiance(radiance) });
  attach(4, 5, 16);
  scene.Mapper->SetIrradianceProbesData(probes);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(scene.Mapper);
  Render(scene);
  EXPECT_TRUE(messages->HasError("visible share holds 16 values for a 4 x 5 grid"))
    << messages->AllErrors();
}
