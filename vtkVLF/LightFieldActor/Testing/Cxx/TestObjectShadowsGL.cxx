// SPDX-License-Identifier: BSD-3-Clause
// Shadows of the movable object drawn by vtkLightFieldActor: the GPU's darkening
// (glsl/vtkLightFieldShadowFS.glsl) in progressive mode, and the CPU pass in raytrace mode,
// match the core's (ObjectShadows::Shade) on the Cornell box floor pixel by pixel, per mode; the
// same pixels without the shadow do not. `ctest -R ShadowMap` (needs scripts/xvfb.sh).
#include "WalkthroughTestViewer.h"

#include "ObjectMesh.h"
#include "ObjectShadows.h"

#include <glm/gtc/matrix_transform.hpp>

#include <vtkUnsignedCharArray.h>

#include <cstddef>
#include <cstdio>
#include <vector>

namespace mesolight
{
namespace walkthroughtest
{
namespace
{
struct FloorPixel
{
  std::size_t Index;
  glm::vec3 Point, Normal, Kd;
};

// Pixels of the view that show the floor (diffuse, facing up) and their points.
std::vector<FloorPixel> FloorPixels(const vlf::LightField& field, const vlf::ViewFrame& view)
{
  const vlf::WalkthroughTracer tracer(field);
  std::vector<FloorPixel> out;
  for (int row = 0; row < Size; ++row)
  {
    for (int column = 0; column < Size; ++column)
    {
      const SceneRay ray =
        view.Ray(static_cast<float>(column) + 0.5f, static_cast<float>(row) + 0.5f);
      const SceneHit hit = tracer.Embree().Intersect(ray);
      std::uint32_t s;
      if (tracer.Classify(ray, hit, s) != vlf::PixelClass::Diffuse ||
        field.Surfaces()[s].Normal.y < 0.99f)
      {
        continue;
      }
      out.push_back(
        { static_cast<std::size_t>(row) * Size + column, ray.Origin + hit.T * ray.Direction,
          field.Surfaces()[s].Normal, field.MaterialOf(s).Diffuse });
    }
  }
  return out;
}

// Display levels (0-255) between two radiances through the test's tone map.
float LevelDifference(const glm::vec3& a, const glm::vec3& b)
{
  const glm::vec3 da = vlf::ToneMap(a, Exposure, vlf::ToneMapOperator::Clamp);
  const glm::vec3 db = vlf::ToneMap(b, Exposure, vlf::ToneMapOperator::Clamp);
  const glm::vec3 d = glm::abs(da - db) * 255.0f;
  return std::max(d.x, std::max(d.y, d.z));
}
} // namespace

TEST(ShadowMapGL, GpuAndRaytraceDarkeningMatchCore)
{
  const vlf::LightField& field = MirrorCornellField(513);
  Viewer viewer(field);
  // Looking down at the front-right floor, where the cube's shadow falls.
  const vlf::ViewFrame view = viewer.SetCamera(
    field, glm::vec3(440.0f, 350.0f, -150.0f), glm::vec3(440.0f, 0.0f, 120.0f), 40.0f);
  const std::vector<FloorPixel> floor = FloorPixels(field, view);
  ASSERT_GT(floor.size(), 2000u);
  const vlf::ObjectMesh cube =
    vlf::TransformMesh(vlf::TransformMesh(vlf::MakeCube(90.0f),
                         glm::translate(glm::mat4(1.0f), glm::vec3(400.0f, 120.0f, 150.0f))),
      vlf::WorldToUnitSphere(field));
  vtkLightFieldActorTesting::SetShadowCaster(viewer.Actor, &cube);
  viewer.Actor->SetShadowMapResolution(256);

  for (const int renderMode : { vtkLightFieldActor::Progressive, vtkLightFieldActor::Raytrace })
  {
    viewer.Actor->SetShadowMode(vtkLightFieldActor::ShadowNone);
    const Images unshadowed = viewer.Render(renderMode);
    EXPECT_EQ(vtkLightFieldActorCore::GetObjectShadows(viewer.Actor), nullptr);
    for (const int mode : { vtkLightFieldActor::ShadowBlack, vtkLightFieldActor::ShadowBlend,
           vtkLightFieldActor::ShadowField, vtkLightFieldActor::ShadowPCF,
           vtkLightFieldActor::ShadowSoft })
    {
      viewer.Actor->SetShadowMode(mode);
      const Images shadowed = viewer.Render(renderMode);
      const vlf::ObjectShadows* shadows = vtkLightFieldActorCore::GetObjectShadows(viewer.Actor);
      ASSERT_NE(shadows, nullptr) << viewer.Actor->GetShadowProblem();
      std::size_t agree = 0, darkened = 0, agreeWithout = 0;
      double levels = 0.0;
      for (const FloorPixel& f : floor)
      {
        const glm::vec3 base = unshadowed.Radiance[f.Index];
        if (std::max(base.x, std::max(base.y, base.z)) * Exposure >= 0.98f)
        {
          continue; // clipped by the display: nothing to compare
        }
        const glm::vec3 expected = shadows->Shade(base, f.Point, f.Normal, f.Kd);
        const float difference = LevelDifference(shadowed.Radiance[f.Index], expected);
        levels += difference;
        agree += difference <= 2.5f ? 1 : 0;
        if (LevelDifference(expected, base) > 6.0f)
        {
          ++darkened;
          // Negative: the unshadowed pixel is not what the core asks for there.
          agreeWithout += LevelDifference(base, expected) <= 2.5f ? 1 : 0;
        }
      }
      const double fraction = static_cast<double>(agree) / static_cast<double>(floor.size());
      std::printf("[ figures  ] %s mode, shadows %s: %.1f%% of %zu floor pixels within 2.5 "
                  "display levels of the core (mean %.2f levels), %zu pixels darkened; maps "
                  "filled in %.2f ms\n",
        vtkLightFieldActor::GetRenderModeAsString(renderMode),
        vtkLightFieldActor::GetShadowModeAsString(mode), 100.0 * fraction, floor.size(),
        levels / static_cast<double>(floor.size()), darkened,
        1e3 * viewer.Actor->GetLastShadowSeconds());
      EXPECT_GT(darkened, 150u) << "the shadow should cover part of the floor";
      EXPECT_GE(fraction, 0.98);
      EXPECT_EQ(agreeWithout, 0u);
    }
  }
  // A broken caster is named, casts nothing and crashes nothing; removed: no shadow.
  vlf::ObjectMesh broken = cube;
  broken.Positions[0].x = std::nanf("");
  vtkLightFieldActorTesting::SetShadowCaster(viewer.Actor, &broken);
  viewer.Render(vtkLightFieldActor::Progressive);
  EXPECT_EQ(vtkLightFieldActorCore::GetObjectShadows(viewer.Actor), nullptr);
  EXPECT_NE(viewer.Actor->GetShadowProblem().find("finite"), std::string::npos);
  vtkLightFieldActorTesting::SetShadowCaster(viewer.Actor, nullptr);
  viewer.Render(vtkLightFieldActor::Progressive);
  EXPECT_EQ(vtkLightFieldActorCore::GetObjectShadows(viewer.Actor), nullptr);
  EXPECT_EQ(viewer.Actor->GetShadowProblem(), "");
}

// The shadow seen in the mirror wall: the mirror pixels whose reflection lands on the shadowed
// floor are darkened (on the CPU, ObjectShadows::Shade at the landing point) by the ratio the
// GPU darkens the directly seen floor there (glsl/vtkLightFieldShadowFS.glsl), coherent and
// raytrace modes; without the shadow the mirror keeps the floor's full light (the negative case).
TEST(ShadowMapGL, ShadowSeenInTheMirrorMatchesTheDirectlySeenFloor)
{
  const vlf::LightField& field = MirrorCornellField(513);
  Viewer viewer(field);
  const vlf::ObjectMesh cube =
    vlf::TransformMesh(vlf::TransformMesh(vlf::MakeCube(90.0f),
                         glm::translate(glm::mat4(1.0f), glm::vec3(400.0f, 130.0f, 140.0f))),
      vlf::WorldToUnitSphere(field));
  vtkLightFieldActorTesting::SetShadowCaster(viewer.Actor, &cube);
  // The floor under the cube seen directly (the GPU's darkening), with and without the shadow.
  const vlf::ViewFrame floorView = viewer.SetCamera(
    field, glm::vec3(440.0f, 350.0f, -150.0f), glm::vec3(440.0f, 0.0f, 120.0f), 40.0f);
  viewer.Actor->SetShadowMode(vtkLightFieldActor::ShadowNone);
  const Images floorLit = viewer.Render(vtkLightFieldActor::Progressive);
  viewer.Actor->SetShadowMode(vtkLightFieldActor::ShadowField);
  const Images floorShadowed = viewer.Render(vtkLightFieldActor::Progressive);
  // The same floor seen in the mirror wall (x = 550).
  const vlf::ViewFrame mirrorView = viewer.SetCamera(
    field, glm::vec3(150.0f, 280.0f, 30.0f), glm::vec3(662.0f, 0.0f, 96.0f), 50.0f);
  const vlf::WalkthroughTracer tracer(field);
  const float halfWidth = floorView.TanHalfHeight;
  auto sum = [](const glm::vec3& v) { return v.x + v.y + v.z; };
  for (const int mode : { vtkLightFieldActor::Coherent, vtkLightFieldActor::Raytrace })
  {
    viewer.Actor->SetShadowMode(vtkLightFieldActor::ShadowNone);
    const Images mirrorLit = viewer.Render(mode);
    viewer.Actor->SetShadowMode(vtkLightFieldActor::ShadowField);
    const Images mirrorShadowed = viewer.Render(mode);
    std::size_t count = 0;
    double error = 0.0, errorWithout = 0.0;
    for (int row = 0; row < Size; ++row)
    {
      for (int column = 0; column < Size; ++column)
      {
        // Where the mirror pixel's reflection lands (the ray cast), and the floor view's pixel
        // that sees that point directly.
        const SceneRay ray = mirrorView.Ray(column + 0.5f, row + 0.5f);
        const SceneHit hit = tracer.Embree().Intersect(ray);
        std::uint32_t s;
        if (tracer.Classify(ray, hit, s) != vlf::PixelClass::Mirror)
        {
          continue;
        }
        const glm::vec3 n = field.Surfaces()[s].Normal;
        const glm::vec3 d = glm::normalize(ray.Direction);
        SceneRay reflected;
        reflected.Origin = ray.Origin + hit.T * ray.Direction + 1e-4f * n;
        reflected.Direction = d - 2.0f * glm::dot(d, n) * n;
        const SceneHit landing = tracer.Embree().Intersect(reflected);
        if (tracer.Classify(reflected, landing, s) != vlf::PixelClass::Diffuse ||
          field.Surfaces()[s].Normal.y < 0.99f)
        {
          continue;
        }
        const glm::vec3 q = reflected.Origin + landing.T * reflected.Direction;
        const glm::vec3 r = q - floorView.Eye;
        const float z = glm::dot(r, floorView.Forward);
        const int x = static_cast<int>(
          std::floor((glm::dot(r, floorView.Right) / z / halfWidth + 1.0f) * 0.5f * Size));
        const int y = static_cast<int>(std::floor(
          (glm::dot(r, floorView.Up) / z / floorView.TanHalfHeight + 1.0f) * 0.5f * Size));
        if (x < 0 || y < 0 || x >= Size || y >= Size)
        {
          continue;
        }
        const std::size_t f = static_cast<std::size_t>(y) * Size + x;
        const std::size_t m = static_cast<std::size_t>(row) * Size + column;
        const glm::vec3 lit = floorLit.Radiance[f], mirrorBase = mirrorLit.Radiance[m];
        if (std::max(lit.x, std::max(lit.y, lit.z)) * Exposure >= 0.98f || sum(lit) < 0.05f ||
          std::max(mirrorBase.x, std::max(mirrorBase.y, mirrorBase.z)) * Exposure >= 0.98f ||
          sum(mirrorBase) < 0.05f)
        {
          continue; // clipped or too dark for 8-bit ratios
        }
        const float floorRatio = sum(floorShadowed.Radiance[f]) / sum(lit);
        if (!(floorRatio < 0.7f))
        {
          continue;
        }
        error += std::abs(sum(mirrorShadowed.Radiance[m]) / sum(mirrorBase) - floorRatio);
        errorWithout += std::abs(1.0f - floorRatio);
        ++count;
      }
    }
    std::printf("[ figures  ] %s mode: %zu mirror pixels show the shadowed floor; mean |mirror "
                "darkening - floor darkening| %.3f (without the shadow in the mirror %.3f)\n",
      vtkLightFieldActor::GetRenderModeAsString(mode), count, error / count, errorWithout / count);
    ASSERT_GT(count, 40u);
    // Coherent reads the landing point's texture; raytrace keeps the field's mirror value and
    // loses Ks x the floor's loss, so its ratio carries the field's error there.
    const double bound = mode == vtkLightFieldActor::Coherent ? 0.1 : 0.2;
    EXPECT_LT(error / count, bound);
    EXPECT_GT(errorWithout / count, bound);
  }
}

} // namespace walkthroughtest
} // namespace mesolight

namespace mesolight
{
namespace walkthroughtest
{
// Each shadow lookup (field, PCF, soft; 256^2 maps) darkens the 512 x 512 frame where the cube's
// shadow falls and brightens (almost) none of it, against the shadow-free frame; without the
// caster the same lookups darken nothing (the negative case). The coherent mode traces its
// mirrors within the frame, so each frame is what its settings draw however loaded the machine
// (the progressive mode refines its mirrors in a worker thread between frames: what a frame
// shows there depends on the time it had). What these frames cost is a benchmark's figure:
// `mesolight bench object --shadows none,field,pcf,soft` (docs/walkthrough.md, "Cost").
TEST(ShadowMapGL, EveryLookupDarkensTheFrameWhereTheShadowFalls)
{
  const vlf::LightField& field = MirrorCornellField(513);
  Viewer viewer(field);
  viewer.Window->SetSize(512, 512);
  viewer.SetCamera(
    field, glm::vec3(440.0f, 350.0f, -150.0f), glm::vec3(440.0f, 0.0f, 120.0f), 40.0f);
  const vlf::ObjectMesh cube =
    vlf::TransformMesh(vlf::TransformMesh(vlf::MakeCube(90.0f),
                         glm::translate(glm::mat4(1.0f), glm::vec3(400.0f, 120.0f, 150.0f))),
      vlf::WorldToUnitSphere(field));
  viewer.Actor->SetRenderModeToCoherent();
  viewer.Actor->SetShadowMapResolution(256);
  // The frame's pixels as the sum of their three channels (levels of 255).
  auto render = [&](int mode)
  {
    viewer.Actor->SetShadowMode(mode);
    viewer.Window->Render();
    vtkNew<vtkUnsignedCharArray> pixels;
    viewer.Window->GetPixelData(0, 0, 511, 511, 1, pixels);
    std::vector<int> levels(static_cast<std::size_t>(512) * 512);
    for (std::size_t i = 0; i < levels.size(); ++i)
    {
      const vtkIdType v = 3 * static_cast<vtkIdType>(i);
      levels[i] = pixels->GetValue(v) + pixels->GetValue(v + 1) + pixels->GetValue(v + 2);
    }
    return levels;
  };
  const std::vector<int> unshadowed = render(vtkLightFieldActor::ShadowNone);
  for (const bool caster : { true, false })
  {
    vtkLightFieldActorTesting::SetShadowCaster(viewer.Actor, caster ? &cube : nullptr);
    for (const int mode : { vtkLightFieldActor::ShadowField, vtkLightFieldActor::ShadowPCF,
           vtkLightFieldActor::ShadowSoft })
    {
      const std::vector<int> frame = render(mode);
      std::size_t darker = 0, brighter = 0;
      for (std::size_t i = 0; i < frame.size(); ++i)
      {
        const int d = frame[i] - unshadowed[i];
        darker += d < -12 ? 1 : 0;
        brighter += d > 12 ? 1 : 0;
      }
      const char* name = vtkLightFieldActor::GetShadowModeAsString(mode);
      std::printf("[ figures  ] coherent 512x512 frame, shadows %s 256^2%s: %zu pixels darker, "
                  "%zu brighter than without shadows\n",
        name, caster ? "" : ", no caster", darker, brighter);
      if (caster)
      {
        EXPECT_GT(darker, 25000u) << name;
        EXPECT_LT(brighter, darker / 20) << name;
      }
      else
      {
        EXPECT_EQ(darker, 0u) << name << ": darkened without a caster";
      }
    }
  }
}

} // namespace walkthroughtest
} // namespace mesolight
