// SPDX-License-Identifier: BSD-3-Clause
// vtkReliefMapper on meshes other than a plane: tangents are generated, and a curved, tiled
// surface renders without errors and with visible relief.
#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefMapper.h"
#include "vtkReliefTextureFilter.h"

#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkTexturedSphereSource.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace
{
using namespace mesolight;

Frame RenderSphere(
  double depthScale, vtkReliefMapper* mapper, mesolight_test::MessageCapture* messages)
{
  vtkNew<vtkProceduralReliefSource> source;
  source->SetPatternToBricks();
  source->SetResolution(256, 256);
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputConnection(source->GetOutputPort(0));
  relief->SetDepthScale(depthScale);
  relief->SetBorderModeToWrap();
  vtkNew<vtkTexturedSphereSource> sphere;
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  mapper->SetInputConnection(sphere->GetOutputPort());
  mapper->SetReliefTextureConnection(relief->GetOutputPort());
  mapper->GetReliefProperty()->SetDepthScale(depthScale);
  mapper->GetReliefProperty()->SilhouettesOff(); // the texture wraps around the sphere
  mapper->GetReliefProperty()->RepeatTextureOn();
  messages->Watch(mapper);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.1);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(-1.5, -2, 1.5); // from the camera side, upper left
  light->SetFocalPoint(0, 0, 0);
  renderer->AddLight(light);
  renderer->GetActiveCamera()->SetPosition(0, -3, 0.5);
  renderer->GetActiveCamera()->SetViewUp(0, 0, 1);
  renderer->ResetCamera();
  ReliefSceneOptions size;
  size.Width = size.Height = 200;
  auto window = MakeOffscreenWindow(size, renderer);
  return CaptureFrame(window);
}
} // namespace

TEST(ReliefMeshes, TexturedSphereGetsTangentsAndShowsRelief)
{
  vtkNew<vtkReliefMapper> flatMapper, reliefMapper;
  vtkNew<mesolight_test::MessageCapture> messages;
  const Frame flat = RenderSphere(0.0, flatMapper, messages);
  const Frame relief = RenderSphere(0.03, reliefMapper, messages);
  WritePng(relief, test::OutputPath("sphere-relief.png").c_str());
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  ASSERT_NE(reliefMapper->GetPreparedInput(), nullptr);
  EXPECT_NE(reliefMapper->GetPreparedInput()->GetPointData()->GetTangents(), nullptr);
  long long covered = 0;
  for (size_t p = 0; p < relief.Depth.size(); ++p)
  {
    covered += relief.Covered(p) ? 1 : 0;
  }
  EXPECT_GT(covered, 200 * 200 / 5); // the sphere fills about a quarter of the view
  // The relief (mortar recessed, self-shadowed) must change the image the way mortar does: it
  // darkens a band of pixels (the mortar lines and their shadows) and brightens few, so the lit
  // sphere's mean level drops. Any change at all (noise, a shift, a blank sphere) does not pass.
  const double difference = CompareFrames(flat, relief, 1e30).MeanColorError;
  long long darker = 0, brighter = 0, both = 0;
  double flatSum = 0.0, reliefSum = 0.0;
  for (size_t p = 0; p < relief.Depth.size(); ++p)
  {
    if (!relief.Covered(p) || !flat.Covered(p))
    {
      continue;
    }
    ++both;
    const int f = flat.Rgb[3 * p] + flat.Rgb[3 * p + 1] + flat.Rgb[3 * p + 2];
    const int r = relief.Rgb[3 * p] + relief.Rgb[3 * p + 1] + relief.Rgb[3 * p + 2];
    flatSum += f;
    reliefSum += r;
    darker += r < f - 30 ? 1 : 0;
    brighter += r > f + 30 ? 1 : 0;
  }
  const double darkerFraction = static_cast<double>(darker) / both;
  const double brighterFraction = static_cast<double>(brighter) / both;
  std::cout << "sphere: mean colour difference " << difference << " levels; of " << both
            << " pixels " << 100.0 * darkerFraction << "% darker, " << 100.0 * brighterFraction
            << "% brighter; mean level " << flatSum / (3.0 * both) << " flat, "
            << reliefSum / (3.0 * both) << " relief\n";
  EXPECT_GT(difference, 3.0);
  // Measured: 31% darker, 14% brighter, mean level 0.88 x the flat sphere's.
  EXPECT_GT(darkerFraction, 0.15);
  EXPECT_LT(darkerFraction, 0.5);
  EXPECT_LT(brighterFraction, 0.25);
  EXPECT_LT(reliefSum, 0.95 * flatSum);
}
