// SPDX-License-Identifier: BSD-3-Clause
#include "LightSetData.h"

#include "vtkCellArray.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

namespace mesolight
{

void FillLightSetData(
  const std::vector<MedianCutLight>& lights, vtkPolyData* output, vtkImageData* texture)
{
  const vtkIdType count = static_cast<vtkIdType>(lights.size());
  vtkNew<vtkPoints> points;
  points->SetDataTypeToDouble();
  points->SetNumberOfPoints(count);
  vtkNew<vtkCellArray> verts;
  vtkNew<vtkFloatArray> irradiance;
  irradiance->SetName("Irradiance");
  irradiance->SetNumberOfComponents(3);
  irradiance->SetNumberOfTuples(count);
  vtkNew<vtkFloatArray> uv;
  uv->SetName("MapCoordinates");
  uv->SetNumberOfComponents(2);
  uv->SetNumberOfTuples(count);
  vtkNew<vtkFloatArray> solidAngle;
  solidAngle->SetName("SolidAngle");
  solidAngle->SetNumberOfComponents(1);
  solidAngle->SetNumberOfTuples(count);
  vtkNew<vtkFloatArray> texels;
  texels->SetName("Lights");
  texels->SetNumberOfComponents(4);
  texels->SetNumberOfTuples(2 * count);
  for (vtkIdType k = 0; k < count; ++k)
  {
    const MedianCutLight& l = lights[static_cast<std::size_t>(k)];
    points->SetPoint(k, l.Direction);
    verts->InsertNextCell(1, &k);
    irradiance->SetTuple3(k, l.Rgb[0], l.Rgb[1], l.Rgb[2]);
    uv->SetTuple2(k, l.U, l.V);
    solidAngle->SetValue(k, static_cast<float>(l.SolidAngle));
    texels->SetTuple4(k, l.Direction[0], l.Direction[1], l.Direction[2], 0.0);
    texels->SetTuple4(count + k, l.Rgb[0], l.Rgb[1], l.Rgb[2], l.SolidAngle);
  }
  output->SetPoints(points);
  output->SetVerts(verts);
  output->GetPointData()->AddArray(irradiance);
  output->GetPointData()->AddArray(uv);
  output->GetPointData()->AddArray(solidAngle);
  output->GetPointData()->SetActiveScalars("Irradiance");

  texture->SetExtent(0, static_cast<int>(count) - 1, 0, 1, 0, 0);
  texture->SetOrigin(0.0, 0.0, 0.0);
  texture->SetSpacing(1.0, 1.0, 1.0);
  texture->GetPointData()->SetScalars(texels);
}

//------------------------------------------------------------------------------
void SetLightTextureInformation(vtkInformation* textureInfo, int lights)
{
  const int extent[6] = { 0, lights - 1, 0, 1, 0, 0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  textureInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  textureInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  textureInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(textureInfo, VTK_FLOAT, 4);
}

} // namespace mesolight
