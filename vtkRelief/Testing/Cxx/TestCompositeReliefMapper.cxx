// SPDX-License-Identifier: BSD-3-Clause
// vtkCompositeReliefMapper (ParaView's path: a composite mapper drawing through
// vtkCompositeMapperHelper2) against vtkReliefMapper: the same relief split into two blocks,
// each carrying the relief texture as field data (vtkAttachReliefTexture), must render the
// same colours and depths as the plain mapper on the whole surface.
#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"

#include "vtkAttachReliefTexture.h"
#include "vtkCompositeReliefMapper.h"
#include "vtkReliefMapper.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkMultiBlockDataSet.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace
{
using namespace mesolight;

constexpr double DepthScale = 0.04;

vtkSmartPointer<vtkImageData> BrickRelief()
{
  auto depth = test::MakeDepthMap(128, 128,
    [](double u, double v)
    {
      // Rows of raised blocks with deep joints, enough relief for parallax and silhouettes.
      const double bu = std::fmod(u * 4.0 + (std::fmod(v * 8.0, 2.0) < 1.0 ? 0.0 : 0.5), 1.0);
      const double bv = std::fmod(v * 8.0, 1.0);
      return (bu < 0.08 || bv < 0.15) ? 1.0 : 0.1;
    });
  return test::BakeRelief(depth, DepthScale);
}

// The unit square from y0 to y1 with texture coordinates equal to (x, y).
vtkSmartPointer<vtkPolyData> Strip(double y0, double y1)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0, y0, 0);
  plane->SetPoint1(1, y0, 0);
  plane->SetPoint2(0, y1, 0);
  plane->SetResolution(8, 4);
  plane->Update();
  auto strip = vtkSmartPointer<vtkPolyData>::New();
  strip->DeepCopy(plane->GetOutput());
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TCoords");
  tcoords->SetNumberOfComponents(2);
  tcoords->SetNumberOfTuples(strip->GetNumberOfPoints());
  for (vtkIdType i = 0; i < strip->GetNumberOfPoints(); ++i)
  {
    double p[3];
    strip->GetPoint(i, p);
    tcoords->SetTypedComponent(i, 0, static_cast<float>(p[0]));
    tcoords->SetTypedComponent(i, 1, static_cast<float>(p[1]));
  }
  strip->GetPointData()->SetTCoords(tcoords);
  return strip;
}

vtkSmartPointer<vtkPolyData> Attached(vtkPolyData* surface, vtkImageData* relief)
{
  vtkNew<vtkAttachReliefTexture> attach;
  attach->SetInputData(0, surface);
  attach->SetInputData(1, relief);
  attach->Update();
  return vtkPolyData::SafeDownCast(attach->GetOutputDataObject(0));
}

Frame Render(vtkMapper* mapper, const std::string& name)
{
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.0);
  actor->GetProperty()->SetDiffuse(1.0);
  actor->GetProperty()->SetSpecular(0.0);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(-0.5, -1.0, 2.0);
  light->SetFocalPoint(0.5, 0.5, 0.0);
  renderer->AddLight(light);
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.5, -0.8, 1.2);
  camera->SetFocalPoint(0.5, 0.45, 0.0);
  camera->SetViewUp(0, 0, 1);
  camera->SetClippingRange(0.2, 5.0);
  ReliefSceneOptions size;
  size.Width = size.Height = 300;
  auto window = MakeOffscreenWindow(size, renderer);
  const Frame frame = CaptureFrame(window);
  WritePng(frame, test::OutputPath(name).c_str());
  return frame;
}
} // namespace

TEST(CompositeReliefMapper, TwoBlocksWithAttachedTexturesMatchTheReliefMapper)
{
  auto relief = BrickRelief();
  vtkNew<vtkReliefMapper> plain;
  plain->SetInputData(Strip(0.0, 1.0));
  plain->SetReliefTextureData(relief);
  plain->GetReliefProperty()->SetDepthScale(DepthScale);
  const Frame reference = Render(plain, "composite-reference.png");

  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(2);
  blocks->SetBlock(0, Attached(Strip(0.0, 0.5), relief));
  blocks->SetBlock(1, Attached(Strip(0.5, 1.0), relief));
  vtkNew<vtkCompositeReliefMapper> composite;
  composite->SetInputDataObject(blocks);
  composite->GetReliefProperty()->SetDepthScale(DepthScale);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(composite);
  const Frame frame = Render(composite, "composite-two-blocks.png");
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();

  const FrameDifference d = CompareFrames(frame, reference, 0.02 * DepthScale);
  std::cout << "composite vs plain: mean colour error " << d.MeanColorError
            << " levels, silhouette mismatch " << d.SilhouetteMismatch << "%, depth mismatch "
            << d.DepthMismatch << "%" << std::endl;
  EXPECT_GT(d.CoveredBoth, 300 * 300 / 4);
  EXPECT_LT(d.MeanColorError, 0.5);
  EXPECT_LT(d.SilhouetteMismatch, 0.2);
  EXPECT_LT(d.DepthMismatch, 0.2);

  // The comparison can fail: the same blocks without the march differ clearly.
  composite->GetReliefProperty()->SetMethod(vtkReliefProperty::TextureMapping);
  const FrameDifference flat =
    CompareFrames(Render(composite, "composite-texture-mapping.png"), reference, 0.02 * DepthScale);
  EXPECT_GT(flat.MeanColorError, 2.0);
}

TEST(CompositeReliefMapper, BlocksWithoutReliefTextureAreAnError)
{
  vtkNew<vtkMultiBlockDataSet> blocks;
  blocks->SetNumberOfBlocks(1);
  blocks->SetBlock(0, Strip(0.0, 1.0));
  vtkNew<vtkCompositeReliefMapper> composite;
  composite->SetInputDataObject(blocks);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(composite);
  Render(composite, "composite-no-texture.png");
  EXPECT_TRUE(messages->HasError("No relief texture")) << messages->AllErrors();
}
