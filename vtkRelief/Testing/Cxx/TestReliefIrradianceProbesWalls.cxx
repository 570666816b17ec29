// SPDX-License-Identifier: BSD-3-Clause
// vtkReliefMapper lit by irradiance probes on a walled relief (a relief on a wall whose border
// meets the wall's plane in side walls): the side walls' visible shares from the map's wall rows
// against the CPU evaluation on the exact intersector, pixel by pixel along the rendered pixels'
// rays. Negative case: the wall shaded with the border texel row's share. The scene is
// ReliefProbesTestScene's, as for TestReliefIrradianceProbes.cxx.
#include "ReliefProbesTestScene.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>

#include <glm/common.hpp>
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
} // namespace

// The side wall of a walled relief (a slot twice as deep as wide along the top edge, v = 1) seen
// from above and in front, so the view rays meet the wall from its lip to its foot: lit by probes
// of the room in front of the plane, albedo 0.7 (the multi-bounce inter-reflection), against the
// CPU evaluation on the exact intersector (ShadeReliefRay: the wall's visible share, its
// radiance weighting and the seen share marched at each pixel's hit). The mapper reads the wall's
// own values from the map's wall rows (ReliefWallShareMap); the negative case, the map without
// them, shades the wall with the texel row beside the border (the slot bottom's share, constant
// down the wall).
TEST(ReliefIrradianceProbes, SideWallSharesFromTheMapMatchTheCpuWall)
{
  // The bench's top slot (scripts/bench-vlf-relief.sh's bricks): 6 of 128 texels at depth 1 (0.1
  // of the square deep) and a 12-texel bevel below it, which the map's cells resolve (a one-texel
  // step would be read from the map's cells either side of it by the seen share).
  constexpr double Slot = 6.0 / 128.0, Bevel = 12.0 / 128.0;
  const auto slot = [](double, double v)
  {
    return v > 1.0 - Slot      ? 1.0
      : v > 1.0 - Slot - Bevel ? 0.05 + 0.95 * (v - (1.0 - Slot - Bevel)) / Bevel
                               : 0.05;
  };
  Scene scene;
  BuildScene(scene, slot, false);
  scene.Height.SetEdgeRule(HeightField::Edge::Walled);
  scene.Mapper->GetReliefProperty()->SilhouettesOff(); // the walled edge rule
  scene.Mapper->GetReliefProperty()->SetLinearSteps(128);
  const glm::dvec3 albedo(0.7);
  scene.Actor->GetProperty()->SetColor(albedo.x, albedo.y, albedo.z);
  vtkCamera* camera = scene.Renderer->GetActiveCamera();
  camera->ParallelProjectionOff();
  camera->SetFocalPoint(0.5, 0.975, -0.05);
  camera->SetPosition(0.5, 0.62, 0.9);
  camera->SetViewUp(0, 1, 0);
  camera->SetViewAngle(10.0);
  camera->SetClippingRange(0.3, 4.0);

  // The room: radiance from in front of the plane only, brighter overhead and toward -v.
  ReliefLighting lighting;
  lighting.Albedo = albedo;
  lighting.Probes.push_back(Project([](const glm::dvec3& d)
    { return d.z > 0.0 ? glm::dvec3(0.5 + 0.3 * d.z - 0.2 * d.y, 0.45, 0.4) : glm::dvec3(0.0); }));
  // The map as vtkLightFieldReliefSurface makes it (ReliefVisibleShareGrid's values).
  const int count = lighting.OcclusionDirections;
  const std::vector<float> share =
    ReliefVisibleShareMap(scene.Height, scene.Plane, DepthSize, DepthSize, count);
  const std::vector<float> seen =
    ReliefSeenShareMap(scene.Height, scene.Plane, share, DepthSize, DepthSize, count);
  constexpr int Levels = 8;
  const std::vector<float> walls = ReliefWallShareMap(
    scene.Height, scene.Plane, share, DepthSize, DepthSize, Levels, count, {}, {}, {}, &lighting);
  const auto probesWith = [&](bool withWalls)
  {
    vtkSmartPointer<vtkImageData> probes = ProbeImage(1, 1, lighting.Probes);
    AttachVisibleShare(probes, DepthSize, DepthSize, static_cast<vtkIdType>(seen.size()), 4,
      [&](vtkIdType t, int c)
      {
        const std::size_t cell = static_cast<std::size_t>(t);
        return c < 2 ? share[2 * cell + static_cast<std::size_t>(c)] : c == 2 ? seen[cell] : 1.0f;
      });
    if (withWalls)
    {
      vtkNew<vtkFloatArray> wall;
      wall->SetName("ReliefWallShare");
      wall->SetNumberOfComponents(4);
      wall->SetNumberOfTuples(static_cast<vtkIdType>(walls.size() / 4));
      std::copy(walls.begin(), walls.end(), wall->GetPointer(0));
      probes->GetFieldData()->AddArray(wall);
    }
    return probes;
  };
  scene.Mapper->SetIrradianceProbesData(probesWith(true));
  const Frame mapped = Render(scene);
  scene.Mapper->SetIrradianceProbesData(probesWith(false));
  const Frame border = Render(scene);

  // The CPU along each pixel's ray; the wall's pixels are those whose exact hit is on it.
  double wallMapped = 0.0, wallBorder = 0.0, signedMapped = 0.0, signedBorder = 0.0;
  double restMapped = 0.0, restChange = 0.0;
  long long wallPixels = 0, restPixels = 0;
  for (int y = 0; y < Pixels; ++y)
  {
    for (int x = 0; x < Pixels; ++x)
    {
      const size_t p = static_cast<size_t>(y) * Pixels + x;
      glm::dvec3 origin, dir;
      PixelRay(scene.Renderer, x, y, origin, dir);
      const auto shade = ShadeReliefRay(scene.Height, scene.Plane, lighting, origin, dir);
      if (!shade || !mapped.Covered(p) || shade->Texture.x < 0.0 || shade->Texture.x > 1.0 ||
        shade->Texture.y < 0.0 || shade->Texture.y > 1.0)
      {
        continue;
      }
      const glm::dvec3 cpu =
        255.0 * glm::clamp(albedo / vtkMath::Pi() * (shade->Indirect + shade->Direct), 0.0, 1.0);
      const bool onWall =
        shade->Texture.y > 1.0 - 1e-9 && shade->Texture.z > 0.02 && shade->Normal.y < -0.99;
      for (int c = 0; c < 3; ++c)
      {
        const double m = mapped.Rgb[3 * p + c] - cpu[c], b = border.Rgb[3 * p + c] - cpu[c];
        if (onWall)
        {
          wallMapped += std::abs(m) / 3.0;
          wallBorder += std::abs(b) / 3.0;
          signedMapped += m / 3.0;
          signedBorder += b / 3.0;
        }
        else
        {
          restMapped += std::abs(m) / 3.0;
          restChange += std::abs(mapped.Rgb[3 * p + c] - border.Rgb[3 * p + c]) / 3.0;
        }
      }
      (onWall ? wallPixels : restPixels) += 1;
    }
  }
  const double n = static_cast<double>(std::max<long long>(1, wallPixels));
  wallMapped /= n;
  wallBorder /= n;
  signedMapped /= n;
  signedBorder /= n;
  restMapped /= static_cast<double>(std::max<long long>(1, restPixels));
  restChange /= static_cast<double>(std::max<long long>(1, restPixels));
  std::cout << "[side wall] " << wallPixels << " wall pixels: mean |GPU - CPU| " << wallMapped
            << " levels (signed " << signedMapped << ") with the wall rows, " << wallBorder
            << " (signed " << signedBorder << ") with the border texel's (negative); " << restPixels
            << " other pixels: " << restMapped << " levels, " << restChange
            << " changed by the wall rows\n";
  EXPECT_GT(wallPixels, Pixels * Pixels / 10);
  EXPECT_GT(restPixels, Pixels * Pixels / 10);
  EXPECT_LT(wallMapped, 2.5);
  EXPECT_GT(wallBorder, 2.0 * wallMapped);
  EXPECT_GT(wallBorder, 4.0);
  EXPECT_LT(restChange, 0.1); // the height field's pixels read the same cells as before
  // The other pixels against the CPU too (measured 3.4 levels; a map of share 1 everywhere, the
  // field's occlusion ignored, reads 11.1).
  EXPECT_LT(restMapped, 5.0);
}
