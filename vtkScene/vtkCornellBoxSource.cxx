// SPDX-License-Identifier: BSD-3-Clause
#include "vtkCornellBoxSource.h"

#include "TriangleScene.h"
#include "vtkTriangleSceneConverter.h"

#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

vtkStandardNewMacro(vtkCornellBoxSource);

vtkCornellBoxSource::vtkCornellBoxSource()
{
  this->SetNumberOfInputPorts(0);
}

int vtkCornellBoxSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector);
  mesolight::TriangleScene box = mesolight::MakeCornellBox();
  if (this->NormalizeToUnitSphere)
  {
    mesolight::NormalizeToUnitSphere(box);
  }
  vtkNew<vtkTriangleSceneConverter> converter;
  converter->ToPolyData(box, output);
  return 1;
}

void vtkCornellBoxSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NormalizeToUnitSphere: " << this->NormalizeToUnitSphere << "\n";
}
