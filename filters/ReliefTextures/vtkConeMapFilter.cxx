// SPDX-License-Identifier: BSD-3-Clause
#include "vtkConeMapFilter.h"
#include "Progress.h"
#include "vtkOutOfMemory.h"

#include "ConeMaps.h"
#include "MemoryBudget.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cstdint>
#include <new>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkConeMapFilter);

//------------------------------------------------------------------------------
vtkConeMapFilter::vtkConeMapFilter() = default;

//------------------------------------------------------------------------------
int vtkConeMapFilter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(0),
    this->Packing == RATIO_8BIT ? VTK_UNSIGNED_CHAR : VTK_FLOAT, 4);
  return 1;
}

//------------------------------------------------------------------------------
int vtkConeMapFilter::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  return mesolight::ExecuteReportingOutOfMemory(
    this, [&]() { return this->Execute(request, inputVector, outputVector); });
}

//------------------------------------------------------------------------------
int vtkConeMapFilter::Execute(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  // Point scalars, or the cells ParaView's GDAL Raster Reader gives the pixels as (the relief
  // filter reads those at their corners).
  vtkDataArray* scalars = input ? input->GetPointData()->GetScalars() : nullptr;
  if (!input || input->GetNumberOfPoints() == 0 ||
    (!scalars && !input->GetCellData()->GetScalars()))
  {
    vtkErrorMacro(<< "No input image (or no point or cell scalars) to make a cone map of.");
    return 0;
  }
  // A relief texture given as input keeps its depth channel; anything else is baked exactly as
  // the relief filter bakes it (input conversion, NaN checks, no data).
  const bool isReliefTexture = scalars && scalars->GetNumberOfComponents() == 4 &&
    input->GetFieldData()->GetArray("MesolightDepthScale");

  {
    // Per texel: the relief bake (unless given), depths and cone ratios (float), the cell bounds
    // (double) and tile pyramid of the cone search, and the RGBA float output.
    int inputDims[3];
    input->GetDimensions(inputDims);
    const std::string memory = mesolight::CheckMemoryBudget(
      "A " + std::to_string(inputDims[0]) + " x " + std::to_string(inputDims[1]) + " cone map",
      static_cast<std::uint64_t>(input->GetNumberOfPoints()) *
        ((isReliefTexture ? 0 : 16) + 4 + 4 + 8 + 16 + 16),
      this->MemoryBudget);
    if (!memory.empty())
    {
      vtkErrorMacro(<< memory << ".");
      return 0;
    }
  }
  vtkNew<vtkImageData> relief;
  if (isReliefTexture)
  {
    relief->ShallowCopy(input);
    vtkDataArray* scale = input->GetFieldData()->GetArray("MesolightDepthScale");
    this->AppliedDepthScale = scale->GetNumberOfTuples() > 0 ? scale->GetComponent(0, 0) : 0.0;
    this->TrueDepthScale = 0.0;
    this->AppliedNoData = false;
    this->AppliedNoDataValue = 0.0;
    this->NumberOfNoDataTexels = 0;
  }
  else
  {
    // The relief texture of the depth map, as vtkReliefTextureFilter bakes it (its errors are
    // this filter's), the first tenth of the progress; then the cones over it.
    this->SetProgressShiftScale(0.0, 0.1);
    const int baked = this->Superclass::RequestData(request, inputVector, outputVector);
    this->SetProgressShiftScale(0.0, 1.0);
    if (!baked || this->GetAbortExecute())
    {
      return baked;
    }
    relief->ShallowCopy(output);
    output->Initialize();
  }

  int dims[3];
  relief->GetDimensions(dims);
  const int w = dims[0], h = dims[1];
  vtkDataArray* rgba = relief->GetPointData()->GetScalars();
  const vtkIdType count = static_cast<vtkIdType>(w) * h;
  // The 8-bit packing stores the depth rounded to 1/255: the cones must be valid for the surface
  // the renderer will sample, so they are computed from that quantized depth.
  auto byte = [](double x)
  { return static_cast<unsigned char>(std::min(255.0, std::max(0.0, x * 255.0 + 0.5))); };
  std::vector<float> depth(static_cast<size_t>(count));
  for (vtkIdType i = 0; i < count; ++i)
  {
    const double d = rgba->GetComponent(i, 3);
    depth[static_cast<size_t>(i)] =
      this->Packing == RATIO_8BIT ? static_cast<float>(byte(d) / 255.0) : static_cast<float>(d);
  }

  mesolight::ConeMapOptions options;
  options.Progress = mesolight::AlgorithmProgress(this, isReliefTexture ? 0.0 : 0.1, 1.0);
  const std::vector<float> cones =
    mesolight::ComputeConeMap(this->ConeType == CONSERVATIVE ? mesolight::ConeType::Conservative
                                                             : mesolight::ConeType::Relaxed,
      depth.data(), w, h, options);
  if (cones.empty())
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro(<< "Cone map computation failed.");
    }
    return this->GetAbortExecute() ? 1 : 0;
  }

  output->SetExtent(relief->GetExtent());
  output->SetSpacing(relief->GetSpacing());
  output->SetOrigin(relief->GetOrigin());
  if (this->Packing == RATIO_8BIT)
  {
    vtkNew<vtkUnsignedCharArray> packed;
    packed->SetName("ConeRelief");
    packed->SetNumberOfComponents(4);
    packed->SetNumberOfTuples(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      packed->SetTypedComponent(i, 0, byte(rgba->GetComponent(i, 0)));
      packed->SetTypedComponent(i, 1, byte(rgba->GetComponent(i, 1)));
      packed->SetTypedComponent(i, 2, mesolight::EncodeConeRatio8(cones[static_cast<size_t>(i)]));
      packed->SetTypedComponent(i, 3, byte(rgba->GetComponent(i, 3)));
    }
    output->GetPointData()->SetScalars(packed);
  }
  else
  {
    vtkNew<vtkFloatArray> packed;
    packed->SetName("ConeRelief");
    packed->SetNumberOfComponents(4);
    packed->SetNumberOfTuples(count);
    for (vtkIdType i = 0; i < count; ++i)
    {
      packed->SetTypedComponent(i, 0, static_cast<float>(rgba->GetComponent(i, 0)));
      packed->SetTypedComponent(i, 1, static_cast<float>(rgba->GetComponent(i, 1)));
      packed->SetTypedComponent(i, 2, cones[static_cast<size_t>(i)]);
      packed->SetTypedComponent(i, 3, depth[static_cast<size_t>(i)]);
    }
    output->GetPointData()->SetScalars(packed);
  }
  output->GetFieldData()->PassData(relief->GetFieldData());
  vtkNew<vtkStringArray> type;
  type->SetName("MesolightConeType");
  type->InsertNextValue(this->ConeType == CONSERVATIVE ? "conservative" : "relaxed");
  output->GetFieldData()->AddArray(type);
  return 1;
}

//------------------------------------------------------------------------------
void vtkConeMapFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ConeType: " << (this->ConeType == CONSERVATIVE ? "Conservative" : "Relaxed")
     << "\n";
  os << indent << "Packing: " << (this->Packing == RATIO_8BIT ? "Ratio8Bit" : "Float") << "\n";
}
