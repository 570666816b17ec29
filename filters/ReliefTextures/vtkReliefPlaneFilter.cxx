// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefPlaneFilter.h"
#include "vtkWholeExtentRequest.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <cmath>

vtkStandardNewMacro(vtkReliefPlaneFilter);

//------------------------------------------------------------------------------
vtkReliefPlaneFilter::vtkReliefPlaneFilter()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
int vtkReliefPlaneFilter::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
void vtkReliefPlaneFilter::SetWidth(double width)
{
  if (!(width > 0.0) || !std::isfinite(width))
  {
    vtkErrorMacro(<< "Width " << width << " is not a plane's width (a positive number of world "
                  << "units); keeping " << this->Width << ".");
    return;
  }
  if (width != this->Width)
  {
    this->Width = width;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkReliefPlaneFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  mesolight::RequestWholeInputExtent(inputVector);
  return 1;
}

//------------------------------------------------------------------------------
double vtkReliefPlaneFilter::GetGroundProportions(vtkImageData* image)
{
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  if (dims[0] < 1 || dims[1] < 1)
  {
    return 1.0;
  }
  double proportions = static_cast<double>(dims[1]) / dims[0];
  vtkDataArray* pixelSize = image->GetFieldData()->GetArray("MesolightPixelSize");
  if (pixelSize && pixelSize->GetNumberOfTuples() == 1 && pixelSize->GetNumberOfComponents() == 2)
  {
    const double along = pixelSize->GetComponent(0, 0), across = pixelSize->GetComponent(0, 1);
    const double ground = proportions * (across / along);
    // Sizes that overflow or vanish in the ratio (a corrupt georeference) are ignored too.
    if (along > 0.0 && across > 0.0 && std::isfinite(along) && std::isfinite(across) &&
      std::isfinite(ground) && ground > 0.0)
    {
      return ground;
    }
  }
  // Otherwise the image's own spacing, VTK's pixel shape (ParaView's GDAL Raster Reader gives a
  // projected raster's pixel size in metres there; most readers give 1).
  const double* spacing = image->GetSpacing();
  const double spaced = proportions * (spacing[1] / spacing[0]);
  if (spacing[0] > 0.0 && spacing[1] > 0.0 && std::isfinite(spaced) && spaced > 0.0)
  {
    return spaced;
  }
  return proportions;
}

//------------------------------------------------------------------------------
int vtkReliefPlaneFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* image = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  if (!image || !output)
  {
    vtkErrorMacro("No input image.");
    return 0;
  }
  if (image->GetNumberOfPoints() < 1)
  {
    vtkErrorMacro("The input image is empty: it has no texels to take the plane's proportions "
                  "from (a reader that could not read its file leaves it empty: see the reader's "
                  "error).");
    return 0;
  }
  // One quad: piece 0 has it, the other pieces (MPI ranks) are empty.
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  if (outInfo->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()) > 0)
  {
    output->Initialize();
    return 1;
  }
  const double x = 0.5 * this->Width;
  const double y = 0.5 * this->Width * GetGroundProportions(image);
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-x, -y, 0.0);
  points->InsertNextPoint(x, -y, 0.0);
  points->InsertNextPoint(x, y, 0.0);
  points->InsertNextPoint(-x, y, 0.0);
  vtkNew<vtkCellArray> quad;
  const vtkIdType corners[4] = { 0, 1, 2, 3 };
  quad->InsertNextCell(4, corners);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TextureCoordinates");
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  const float uv[4][2] = { { 0.f, 0.f }, { 1.f, 0.f }, { 1.f, 1.f }, { 0.f, 1.f } };
  for (const auto& c : uv)
  {
    tcoords->InsertNextTuple2(c[0], c[1]);
    normals->InsertNextTuple3(0.0, 0.0, 1.0);
  }
  output->SetPoints(points);
  output->SetPolys(quad);
  output->GetPointData()->SetTCoords(tcoords);
  output->GetPointData()->SetNormals(normals);
  return 1;
}

//------------------------------------------------------------------------------
void vtkReliefPlaneFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Width: " << this->Width << "\n";
}
