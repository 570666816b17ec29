// SPDX-License-Identifier: BSD-3-Clause
// What the walkthrough tests share: the test view of a field through vtkLightFieldActor, the
// path-traced reference of the same camera (cached in the build tree), and the per-pixel error
// measures (mean, p95, bias over diffuse and mirror pixels).
#ifndef WalkthroughTestViewer_h
#define WalkthroughTestViewer_h

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"    // the field lent, the core objects read
#include "vtkLightFieldActorTesting.h" // the negative tests' hooks
#include "vtkVersionMacros.h"
#if VTK_VERSION_NUMBER < VTK_VERSION_CHECK(9, 3, 0)
#include "vtkCompositeLightFieldMapper.h"
#include <vtkMultiBlockDataSet.h>
#endif

#include "vtkCornellBoxSource.h"
#include "vtkTriangleSceneConverter.h"
#include "vtkVirtualLightField.h"

#include "WalkthroughImage.h"
#include "WalkthroughTestFields.h"
#include "WalkthroughTracer.h"

#include "EmbreeScene.h"
#include "Lookup.h"
#include "PatchComparison.h"
#include "PathTracer.h"
#include "PinholeCamera.h"
#include "Snapshot.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProceduralReliefSource.h>
#include <vtkProperty.h>
#include <vtkReliefMapper.h>
#include <vtkReliefTextureFilter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkUnsignedCharArray.h>

#include <gtest/gtest.h>

#include <unistd.h>

#include <glm/geometric.hpp>

#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <cstring>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <iterator>
#include <map>

namespace mesolight
{
namespace walkthroughtest
{

inline constexpr int Size = 96; // image side (pixels)
inline constexpr int ReferenceSamples =
  2048; // path-traced samples per pixel (the mirror's caustics are noisy)
inline constexpr float Exposure = 0.6f;

struct Images
{
  std::vector<glm::vec3> Radiance; // decoded from the 8-bit display values
  std::vector<glm::vec3> Display;  // display values in [0, 1]
};

// The scene's renderer: the actor alone (plus optional others), the Cornell camera.
struct Viewer
{
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkLightFieldActor> Actor;

  explicit Viewer(const vlf::LightField& field)
  {
    this->Window->SetOffScreenRendering(1);
    this->Window->SetMultiSamples(0);
    this->Window->SetSize(Size, Size);
    this->Window->AddRenderer(this->Renderer);
    this->Renderer->SetBackground(0.0, 0.0, 0.0);
    vtkLightFieldActorCore::SetLightField(this->Actor, &field);
    this->Actor->SetExposure(Exposure);
    this->Renderer->AddActor(this->Actor);
    const CornellCamera c;
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(c.Position.x, c.Position.y, c.Position.z);
    camera->SetFocalPoint(c.FocalPoint.x, c.FocalPoint.y, c.FocalPoint.z);
    camera->SetViewUp(c.ViewUp.x, c.ViewUp.y, c.ViewUp.z);
    camera->SetViewAngle(c.ViewAngleDegrees);
    this->Renderer->ResetCameraClippingRange();
  }

  Images Grab()
  {
    vtkNew<vtkUnsignedCharArray> pixels;
    this->Window->GetPixelData(0, 0, Size - 1, Size - 1, 1, pixels);
    Images images;
    images.Radiance.resize(static_cast<std::size_t>(Size) * Size);
    images.Display.resize(images.Radiance.size());
    for (std::size_t i = 0; i < images.Radiance.size(); ++i)
    {
      const glm::vec3 display(pixels->GetValue(3 * static_cast<vtkIdType>(i)) / 255.0f,
        pixels->GetValue(3 * static_cast<vtkIdType>(i) + 1) / 255.0f,
        pixels->GetValue(3 * static_cast<vtkIdType>(i) + 2) / 255.0f);
      images.Display[i] = display;
      images.Radiance[i] = vlf::InverseToneMap(display, Exposure, vlf::ToneMapOperator::Clamp);
    }
    return images;
  }

  // Another camera (world coordinates) and the ray-cast frame matching it.
  vlf::ViewFrame SetCamera(
    const vlf::LightField& field, const glm::vec3& eye, const glm::vec3& focal, float angle)
  {
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(eye.x, eye.y, eye.z);
    camera->SetFocalPoint(focal.x, focal.y, focal.z);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(angle);
    this->Renderer->ResetCameraClippingRange();
    vlf::ViewFrame view;
    vlf::ViewFrame::Make(vlf::ToUnit(field, eye), vlf::ToUnit(field, focal),
      glm::vec3(0.0f, 1.0f, 0.0f), angle, Size, Size, view);
    return view;
  }

  Images Render(int mode)
  {
    this->Actor->SetRenderMode(mode);
    this->Window->Render();
    return this->Grab();
  }
};

inline vlf::ViewFrame CornellView(const vlf::LightField& field)
{
  const CornellCamera c;
  vlf::ViewFrame view;
  vlf::ViewFrame::Make(vlf::ToUnit(field, c.Position), vlf::ToUnit(field, c.FocalPoint), c.ViewUp,
    c.ViewAngleDegrees, Size, Size, view);
  return view;
}

// The path-traced reference in display-quantised radiance (what an exact renderer would show
// through the same 8-bit display), and the mask of pixels to compare: 1 diffuse, 2 mirror, 0
// other (background, emitters, pixels the display clips).
struct Reference
{
  std::vector<glm::vec3> Radiance;
  std::vector<std::uint8_t> Mask;
  std::vector<glm::vec3> OtherSeed; // the same reference with another seed: the noise floor
};

// The path tracer's image of the camera, kept in the test directory between runs (the scene,
// camera, size and samples are fixed; ctest runs every test in its own process).
inline RgbImage CachedPathTrace(const std::string& name, const PathTracer& tracer,
  const PinholeCamera& camera, std::uint64_t seed)
{
  const std::string path = std::string(MESOLIGHT_TEST_TEMP_DIR) + "/walkthrough-reference-" + name +
    "-" + std::to_string(Size) + "-" + std::to_string(ReferenceSamples) + "-" +
    std::to_string(seed) + ".bin";
  RgbImage image(Size, Size);
  {
    std::ifstream in(path, std::ios::binary);
    if (in.read(reinterpret_cast<char*>(image.Rgb.data()),
          static_cast<std::streamsize>(image.Rgb.size() * sizeof(float))))
    {
      return image;
    }
  }
  const auto start = std::chrono::steady_clock::now();
  image = tracer.RenderImage(camera, Size, Size, ReferenceSamples, seed);
  std::cout << "path-traced reference " << Size << "x" << Size << " at " << ReferenceSamples
            << " spp (seed " << seed << "): "
            << std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count()
            << " s\n";
  // Written aside and renamed: tests running in parallel never read a half-written file.
  const std::string temporary = path + ".tmp-" + std::to_string(::getpid());
  std::ofstream out(temporary, std::ios::binary);
  out.write(reinterpret_cast<const char*>(image.Rgb.data()),
    static_cast<std::streamsize>(image.Rgb.size() * sizeof(float)));
  out.close();
  std::rename(temporary.c_str(), path.c_str());
  return image;
}

inline std::vector<glm::vec3> Quantised(const RgbImage& image)
{
  std::vector<glm::vec3> out(static_cast<std::size_t>(image.Width) * image.Height);
  for (std::size_t i = 0; i < out.size(); ++i)
  {
    const float* p = image.Rgb.data() + 3 * i;
    glm::vec3 display =
      vlf::ToneMap(glm::vec3(p[0], p[1], p[2]), Exposure, vlf::ToneMapOperator::Clamp);
    display = glm::round(display * 255.0f) / 255.0f;
    out[i] = vlf::InverseToneMap(display, Exposure, vlf::ToneMapOperator::Clamp);
  }
  return out;
}

// `name` identifies the scene (the same for every direction count of it).
inline const Reference& PathTracedReference(const vlf::LightField& field, const std::string& name)
{
  static std::map<std::string, Reference> cache;
  Reference& ref = cache[name];
  if (!ref.Radiance.empty())
  {
    return ref;
  }
  const EmbreeScene embree(field.Scene());
  const PathTracer tracer(embree);
  const CornellCamera c;
  PinholeCamera camera;
  camera.Position = vlf::ToUnit(field, c.Position);
  camera.FocalPoint = vlf::ToUnit(field, c.FocalPoint);
  camera.ViewUp = c.ViewUp;
  camera.ViewAngleDegrees = c.ViewAngleDegrees;
  const RgbImage image = CachedPathTrace(name, tracer, camera, 1);
  const vlf::WalkthroughTracer walk(field);
  const std::vector<vlf::PixelClass> classes = walk.ClassifyView(CornellView(field));
  ref.Radiance = Quantised(image);
  ref.OtherSeed = Quantised(CachedPathTrace(name, tracer, camera, 2));
  ref.Mask.assign(classes.size(), 0);
  for (std::size_t i = 0; i < classes.size(); ++i)
  {
    const glm::vec3 display = vlf::ToneMap(ref.Radiance[i], Exposure, vlf::ToneMapOperator::Clamp);
    const bool clipped = std::max(display.x, std::max(display.y, display.z)) >= 0.999f;
    if (!clipped && classes[i] == vlf::PixelClass::Diffuse)
    {
      ref.Mask[i] = 1;
    }
    else if (!clipped && classes[i] == vlf::PixelClass::Mirror)
    {
      ref.Mask[i] = 2;
    }
  }
  return ref;
}

// MESOLIGHT_WALKTHROUGH_DUMP=DIR writes the compared images as PPM files (for inspection).
inline void Dump(const std::string& name, const std::vector<glm::vec3>& radiance)
{
  const char* dir = std::getenv("MESOLIGHT_WALKTHROUGH_DUMP");
  if (!dir)
  {
    return;
  }
  std::ofstream out(std::string(dir) + "/" + name + ".ppm", std::ios::binary);
  out << "P6\n" << Size << " " << Size << "\n255\n";
  for (int y = Size - 1; y >= 0; --y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const glm::vec3 d = vlf::ToneMap(
        radiance[static_cast<std::size_t>(y) * Size + x], Exposure, vlf::ToneMapOperator::Clamp);
      for (int c = 0; c < 3; ++c)
      {
        out.put(static_cast<char>(std::lround(255.0f * d[c])));
      }
    }
  }
}

inline constexpr float Floor = 0.03f; // relative errors of pixels darker than this (RGB sum) use it

struct ModeErrors
{
  vlf::ErrorStatistics Diffuse, Mirror;
  double DiffuseBias = 0.0, MirrorBias = 0.0; // sum(image) / sum(reference) - 1
};

inline double Bias(const std::vector<glm::vec3>& image, const Reference& ref, std::uint8_t which)
{
  double a = 0.0, r = 0.0;
  for (std::size_t i = 0; i < ref.Mask.size(); ++i)
  {
    if (ref.Mask[i] == which)
    {
      a += image[i].x + image[i].y + image[i].z;
      r += ref.Radiance[i].x + ref.Radiance[i].y + ref.Radiance[i].z;
    }
  }
  return r > 0.0 ? a / r - 1.0 : 0.0;
}

inline ModeErrors Measure(const Images& images, const Reference& ref, const std::string& name = "")
{
  if (!name.empty())
  {
    Dump(name, images.Radiance);
    Dump("reference", ref.Radiance);
  }
  return ModeErrors{ vlf::RelativeError(images.Radiance, ref.Radiance, ref.Mask, 1, Floor),
    vlf::RelativeError(images.Radiance, ref.Radiance, ref.Mask, 2, Floor),
    Bias(images.Radiance, ref, 1), Bias(images.Radiance, ref, 2) };
}

inline void Print(std::size_t directions, const std::string& mode, const ModeErrors& e)
{
  std::cout << std::fixed << std::setprecision(4) << "errors " << directions << " " << std::setw(18)
            << std::left << mode << std::right << " diffuse mean " << e.Diffuse.Mean << " p95 "
            << e.Diffuse.Percentile95 << " (" << e.Diffuse.Pixels << " px)  mirror mean "
            << e.Mirror.Mean << " p95 " << e.Mirror.Percentile95 << " (" << e.Mirror.Pixels
            << " px)  bias diffuse " << std::showpos << e.DiffuseBias << " mirror " << e.MirrorBias
            << std::noshowpos << "\n";
}

} // namespace walkthroughtest
} // namespace mesolight

#endif
