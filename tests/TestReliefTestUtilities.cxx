#include "TestReliefTestUtilities.h"

#include "vtkReliefTextureFilter.h"

#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

namespace mesolight
{
namespace test
{

void MessageRecorder::Execute(vtkObject*, unsigned long event, void* callData)
{
  const std::string text = callData ? static_cast<const char*>(callData) : "";
  if (event == vtkCommand::ErrorEvent)
  {
    this->Errors += text;
  }
  else
  {
    this->Warnings += text;
  }
}

void MessageRecorder::Watch(vtkObject* object)
{
  object->AddObserver(vtkCommand::ErrorEvent, this);
  object->AddObserver(vtkCommand::WarningEvent, this);
}

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

std::string OutputPath(const std::string& name)
{
  return std::string(MESOLIGHT_TEST_OUTPUT) + "/" + name;
}

} // namespace test
} // namespace mesolight
