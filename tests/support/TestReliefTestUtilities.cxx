// SPDX-License-Identifier: BSD-3-Clause
#include "TestReliefTestUtilities.h"

#include "ReliefScene.h" // MakeOffscreenWindow
#include "vtkReliefMapper.h"
#include "vtkReliefTextureFilter.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkPlaneSource.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

namespace mesolight
{
namespace test
{

vtkSmartPointer<vtkImageData> MakeDepthMap(
  int width, int height, const std::function<double(double, double)>& depth)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  vtkNew<vtkFloatArray> values;
  values->SetName("Depth");
  values->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      values->SetValue(static_cast<vtkIdType>(j) * width + i,
        static_cast<float>(depth((i + 0.5) / width, (j + 0.5) / height)));
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

vtkSmartPointer<vtkImageData> BakeRelief(vtkImageData* depth, double depthScale)
{
  vtkNew<vtkReliefTextureFilter> bake;
  bake->SetInputData(depth);
  bake->SetDepthScale(depthScale);
  bake->SetBorderModeToClamp();
  bake->Update();
  auto relief = vtkSmartPointer<vtkImageData>::New();
  relief->DeepCopy(bake->GetOutput());
  return relief;
}

vtkSmartPointer<vtkActor> UnitSquareRelief(
  vtkReliefMapper* mapper, vtkImageData* relief, double depthScale)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0, 0, 0);
  plane->SetPoint1(1, 0, 0);
  plane->SetPoint2(0, 1, 0);
  plane->Update();
  mapper->SetInputData(plane->GetOutput());
  mapper->SetReliefTextureData(relief);
  mapper->GetReliefProperty()->SetDepthScale(depthScale);
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetAmbient(0.0);
  actor->GetProperty()->SetDiffuse(1.0);
  actor->GetProperty()->SetSpecular(0.0);
  actor->GetProperty()->SetColor(1, 1, 1);
  return actor;
}

void LookStraightDown(vtkRenderer* renderer)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->ParallelProjectionOn();
  camera->SetParallelScale(0.5);
  camera->SetFocalPoint(0.5, 0.5, 0.0);
  camera->SetPosition(0.5, 0.5, 2.0);
  camera->SetViewUp(0, 1, 0);
  camera->SetClippingRange(0.5, 4.0);
}

Frame CaptureTopDown(
  const std::vector<vtkActor*>& actors, int pixels, const std::array<double, 3>& toLight)
{
  vtkNew<vtkRenderer> renderer;
  for (vtkActor* actor : actors)
  {
    renderer->AddActor(actor);
  }
  renderer->AutomaticLightCreationOff();
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetFocalPoint(0.5, 0.5, 0.0);
  light->SetPosition(0.5 + toLight[0], 0.5 + toLight[1], toLight[2]);
  renderer->AddLight(light);
  LookStraightDown(renderer);
  ReliefSceneOptions size;
  size.Width = size.Height = pixels;
  auto window = MakeOffscreenWindow(size, renderer);
  return CaptureFrame(window);
}

std::string OutputPath(const std::string& name)
{
  return std::string(MESOLIGHT_TEST_OUTPUT) + "/" + name;
}

} // namespace test
} // namespace mesolight
