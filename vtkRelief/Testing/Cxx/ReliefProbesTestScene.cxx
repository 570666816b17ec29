// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefProbesTestScene.h"

#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"
#include "vtkIrradianceProbesTexture.h"
#include "vtkReliefProperty.h"

#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRendererCollection.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <limits>

namespace mesolight
{
namespace test
{
namespace probes
{
namespace
{
std::vector<float> DepthSamples(const std::function<double(double, double)>& depth)
{
  std::vector<float> samples(static_cast<size_t>(DepthSize) * DepthSize);
  for (int j = 0; j < DepthSize; ++j)
  {
    for (int i = 0; i < DepthSize; ++i)
    {
      samples[static_cast<size_t>(j) * DepthSize + i] =
        static_cast<float>(depth((i + 0.5) / DepthSize, (j + 0.5) / DepthSize));
    }
  }
  return samples;
}

// One window for the whole program (see TestReliefLightSet.cxx: new X windows after a
// light-set render were seen to fail under Xvfb + llvmpipe).
vtkRenderWindow* Window()
{
  static vtkSmartPointer<vtkRenderWindow> window;
  if (!window)
  {
    ReliefSceneOptions size;
    size.Width = size.Height = Pixels;
    vtkNew<vtkRenderer> unused;
    window = MakeOffscreenWindow(size, unused);
    window->RemoveRenderer(unused);
  }
  return window;
}
} // namespace

double Bumps(double u, double v)
{
  return 0.5 +
    0.5 * std::sin(2.0 * vtkMath::Pi() * 2.0 * u) * std::cos(2.0 * vtkMath::Pi() * 2.0 * v);
}

SH9 Project(const std::function<glm::dvec3(const glm::dvec3&)>& radiance)
{
  SH9 sh;
  const int nz = 256, nphi = 512;
  const double dOmega = (2.0 / nz) * (2.0 * vtkMath::Pi() / nphi);
  for (int a = 0; a < nz; ++a)
  {
    const double z = -1.0 + (a + 0.5) * 2.0 / nz;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int b = 0; b < nphi; ++b)
    {
      const double phi = (b + 0.5) * 2.0 * vtkMath::Pi() / nphi;
      const double d[3] = { r * std::cos(phi), r * std::sin(phi), z };
      const glm::dvec3 l = radiance(glm::dvec3(d[0], d[1], d[2]));
      double y[9];
      EvaluateSHBasis(d, y);
      for (int k = 0; k < 9; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          sh.L[k][c] += l[c] * y[k] * dOmega;
        }
      }
    }
  }
  return sh;
}

SH9 ConstantRadiance(const glm::dvec3& l)
{
  SH9 sh;
  const double y00 = 0.282095;
  for (int c = 0; c < 3; ++c)
  {
    sh.L[0][c] = l[c] * 4.0 * vtkMath::Pi() * y00; // the projection of a constant
  }
  return sh;
}

vtkSmartPointer<vtkImageData> ProbeImage(int nu, int nv, const std::vector<SH9>& probes)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(9 * nu, nv, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(9 * nu) * nv);
  for (int j = 0; j < nv; ++j)
  {
    for (int i = 0; i < nu; ++i)
    {
      const SH9& sh = probes[static_cast<size_t>(j) * nu + i];
      for (int k = 0; k < 9; ++k)
      {
        values->SetTuple3(
          static_cast<vtkIdType>(j) * 9 * nu + 9 * i + k, sh.L[k][0], sh.L[k][1], sh.L[k][2]);
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

void AttachVisibleShare(vtkImageData* probes, int w, int h, vtkIdType tuples, int components,
  const std::function<double(vtkIdType, int)>& value)
{
  vtkNew<vtkFloatArray> share;
  share->SetNumberOfComponents(components);
  share->SetNumberOfTuples(tuples);
  for (vtkIdType t = 0; t < tuples; ++t)
  {
    for (int c = 0; c < components; ++c)
    {
      share->SetComponent(t, c, value(t, c));
    }
  }
  vtkIrradianceProbesTexture::AttachVisibleShare(probes, share, w, h);
  probes->Modified();
}

void BuildScene(Scene& scene, const std::function<double(double, double)>& depth, bool oblique)
{
  auto relief = BakeRelief(MakeDepthMap(DepthSize, DepthSize, depth), DepthScale);
  scene.Actor = UnitSquareRelief(scene.Mapper, relief, DepthScale);
  scene.Mapper->GetReliefProperty()->ToneMappingOff();
  scene.Mapper->GetReliefProperty()->SetExposure(1.0);
  scene.Mapper->GetReliefProperty()->SetLinearSteps(64);
  scene.Renderer->AutomaticLightCreationOff();
  scene.Renderer->AddActor(scene.Actor);
  LookStraightDown(scene.Renderer);
  if (oblique)
  {
    vtkCamera* camera = scene.Renderer->GetActiveCamera();
    camera->ParallelProjectionOff();
    camera->SetFocalPoint(0.5, 0.5, -0.05);
    camera->SetPosition(0.5, -0.45, 1.05);
    camera->SetViewUp(0, 0, 1);
    camera->SetViewAngle(50.0);
    camera->SetClippingRange(0.3, 4.0);
  }
  scene.Height = HeightField(DepthSize, DepthSize, DepthSamples(depth));
  scene.Plane.DepthScale = DepthScale;
}

Frame Render(Scene& scene)
{
  vtkRenderWindow* window = Window();
  window->GetRenderers()->RemoveAllItems();
  window->AddRenderer(scene.Renderer);
  const Frame frame = CaptureFrame(window);
  return frame;
}

void PixelRay(vtkRenderer* renderer, int x, int y, glm::dvec3& origin, glm::dvec3& direction)
{
  double ends[2][4];
  for (int e = 0; e < 2; ++e)
  {
    renderer->SetDisplayPoint(x + 0.5, y + 0.5, e);
    renderer->DisplayToWorld();
    renderer->GetWorldPoint(ends[e]);
    for (int c = 0; c < 3; ++c)
    {
      ends[e][c] /= ends[e][3];
    }
  }
  origin = glm::dvec3(ends[0][0], ends[0][1], ends[0][2]);
  direction = glm::normalize(glm::dvec3(ends[1][0], ends[1][1], ends[1][2]) - origin);
}

std::vector<double> CpuImage(
  Scene& scene, const ReliefLighting& lighting, ReliefNormal normal, const glm::dvec3& albedo)
{
  std::vector<double> image(static_cast<size_t>(3) * Pixels * Pixels, -1.0);
  for (int y = 0; y < Pixels; ++y)
  {
    for (int x = 0; x < Pixels; ++x)
    {
      glm::dvec3 origin, dir;
      PixelRay(scene.Renderer, x, y, origin, dir);
      const auto shade = ShadeReliefRay(scene.Height, scene.Plane, lighting, origin, dir, normal);
      if (!shade || shade->Texture.x < 0.0 || shade->Texture.x > 1.0 || shade->Texture.y < 0.0 ||
        shade->Texture.y > 1.0)
      {
        continue;
      }
      const glm::dvec3 radiance = albedo / vtkMath::Pi() * (shade->Indirect + shade->Direct);
      for (int c = 0; c < 3; ++c)
      {
        image[3 * (static_cast<size_t>(y) * Pixels + x) + c] =
          255.0 * std::min(1.0, std::max(0.0, radiance[c]));
      }
    }
  }
  return image;
}

double MeanError(const Frame& gpu, const std::vector<double>& cpu, long long* count)
{
  double sum = 0.0;
  long long n = 0;
  for (size_t p = 0; p < gpu.Depth.size(); ++p)
  {
    if (!gpu.Covered(p) || cpu[3 * p] < 0.0)
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      sum += std::abs(gpu.Rgb[3 * p + c] - cpu[3 * p + c]);
    }
    ++n;
  }
  if (count)
  {
    *count = n;
  }
  return n > 0 ? sum / (3.0 * n) : std::numeric_limits<double>::infinity();
}

} // namespace probes
} // namespace test
} // namespace mesolight
