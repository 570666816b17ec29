// SPDX-License-Identifier: BSD-3-Clause
#include "vtkGeometryImageSource.h"

#include "ProceduralGeometryImages.h"

#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>
#include <limits>

#include <stdexcept>

vtkStandardNewMacro(vtkGeometryImageSource);

//------------------------------------------------------------------------------
vtkGeometryImageSource::vtkGeometryImageSource()
{
  this->SetNumberOfInputPorts(0);
}

//------------------------------------------------------------------------------
bool vtkGeometryImageSource::SetSurfaceByName(const char* name)
{
  if (!name)
  {
    return false;
  }
  try
  {
    this->SetSurface(static_cast<int>(mesolight::GeometrySurfaceFromName(name)));
  }
  catch (const std::invalid_argument&)
  {
    return false; // the caller names the accepted surfaces
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkGeometryImageSource::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int extent[6] = { 0, this->Resolution[0] - 1, 0, this->Resolution[1] - 1, 0, 0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkGeometryImageSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* image = vtkImageData::GetData(outputVector, 0);
  if (!image)
  {
    vtkErrorMacro("Missing output image.");
    return 0;
  }
  const int w = this->Resolution[0];
  const int h = this->Resolution[1];
  if (w < 2 || h < 2)
  {
    vtkErrorMacro("Resolution must be at least 2 x 2; got " << w << " x " << h << ".");
    return 0;
  }
  const mesolight::GeometryImage geometry =
    mesolight::MakeGeometryImage(static_cast<mesolight::GeometrySurface>(this->Surface), w, h);
  image->Initialize();
  image->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  image->SetOrigin(0.0, 0.0, 0.0);
  image->SetSpacing(1.0, 1.0, 1.0);
  const vtkIdType n = static_cast<vtkIdType>(w) * h;
  vtkNew<vtkFloatArray> positions;
  positions->SetName("Positions");
  positions->SetNumberOfComponents(3);
  positions->SetNumberOfTuples(n);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  normals->SetNumberOfTuples(n);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  for (vtkIdType k = 0; k < n; ++k)
  {
    const glm::dvec3& p = geometry.Positions[k];
    const glm::dvec3& nrm = geometry.Normals[k];
    const double u = mesolight::TexelCentre(static_cast<int>(k % w), w) - 0.3;
    const double v = mesolight::TexelCentre(static_cast<int>(k / w), h) - 0.6;
    if (this->Holes && u * u + v * v < 0.12 * 0.12)
    {
      positions->SetTuple3(k, nan, nan, nan);
    }
    else
    {
      positions->SetTuple3(k, p.x, p.y, p.z);
    }
    normals->SetTuple3(k, nrm.x, nrm.y, nrm.z);
  }
  image->GetPointData()->SetScalars(positions);
  image->GetPointData()->AddArray(normals);
  return 1;
}

//------------------------------------------------------------------------------
void vtkGeometryImageSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Surface: "
     << mesolight::GeometrySurfaceName(static_cast<mesolight::GeometrySurface>(this->Surface))
     << "\n";
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
  os << indent << "Holes: " << (this->Holes ? "On" : "Off") << "\n";
}
