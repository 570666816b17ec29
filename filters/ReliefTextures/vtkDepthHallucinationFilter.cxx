// SPDX-License-Identifier: BSD-3-Clause
#include "vtkDepthHallucinationFilter.h"
#include "vtkUnitScale.h"
#include "vtkWholeExtentRequest.h"

#include "DepthHallucination.h"
#include "Progress.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <string>

vtkStandardNewMacro(vtkDepthHallucinationFilter);

namespace
{
// The first three components as linear RGB (one component is grey); integer types scale to
// [0, 1] as the image readers store them. Empty for an image without scalars.
mesolight::RgbImage ToRgb(vtkImageData* image)
{
  if (!image || image->GetNumberOfPoints() == 0 || !image->GetPointData()->GetScalars())
  {
    return {};
  }
  int dims[3];
  image->GetDimensions(dims);
  if (dims[2] != 1)
  {
    return {};
  }
  vtkDataArray* values = image->GetPointData()->GetScalars();
  const int components = values->GetNumberOfComponents();
  const double scale = mesolight::UnitScale(values);
  mesolight::RgbImage rgb(dims[0], dims[1]);
  const vtkIdType count = static_cast<vtkIdType>(dims[0]) * dims[1];
  for (vtkIdType p = 0; p < count; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgb.Rgb[static_cast<size_t>(3 * p + c)] =
        static_cast<float>(scale * values->GetComponent(p, components >= 3 ? c : 0));
    }
  }
  return rgb;
}
} // namespace

//------------------------------------------------------------------------------
vtkDepthHallucinationFilter::vtkDepthHallucinationFilter()
{
  this->SetNumberOfInputPorts(3);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkImageData* vtkDepthHallucinationFilter::GetAlbedoOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(0));
}

//------------------------------------------------------------------------------
vtkImageData* vtkDepthHallucinationFilter::GetDepthOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkDepthHallucinationFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  if (port == 2)
  {
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkDepthHallucinationFilter::FillOutputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), "vtkImageData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkDepthHallucinationFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  for (int port = 0; port < 2; ++port)
  {
    vtkInformation* outInfo = outputVector->GetInformationObject(port);
    if (inInfo)
    {
      int extent[6];
      inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent);
      outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
    }
    vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, port == 0 ? 3 : 1);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkDepthHallucinationFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // Every layer sees the whole photograph.
  for (int port = 0; port < 3; ++port)
  {
    mesolight::RequestWholeInputExtent(inputVector, port);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkDepthHallucinationFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  this->DepthRangeTexels = 0.0;
  vtkImageData* albedoOut = vtkImageData::GetData(outputVector, 0);
  vtkImageData* depthOut = vtkImageData::GetData(outputVector, 1);
  vtkImageData* diffuseIn = vtkImageData::GetData(inputVector[0]);
  vtkImageData* flashIn = vtkImageData::GetData(inputVector[1]);
  vtkImageData* calibrationIn = inputVector[2]->GetNumberOfInformationObjects() > 0
    ? vtkImageData::GetData(inputVector[2])
    : nullptr;
  const mesolight::RgbImage diffuse = ToRgb(diffuseIn);
  const mesolight::RgbImage flash = ToRgb(flashIn);
  const mesolight::RgbImage calibration = ToRgb(calibrationIn);
  if (diffuse.Width == 0 || flash.Width == 0 || (calibrationIn && calibration.Width == 0))
  {
    vtkErrorMacro(<< "The "
                  << (diffuse.Width == 0
                         ? "diffuse (port 0)"
                         : (flash.Width == 0 ? "flash (port 1)" : "calibration (port 2)"))
                  << " image is empty, has no scalars or is not 2D.");
    return 0;
  }
  mesolight::HallucinationSettings settings;
  settings.Layers = this->NumberOfLayers;
  settings.Model =
    this->UseRatio ? mesolight::HallucinationModel::Ratio : mesolight::HallucinationModel::Shading;
  settings.BaseSigma = static_cast<float>(this->BaseSigma);
  settings.DepthScale = static_cast<float>(this->DepthScale);
  settings.ValleyWeight = static_cast<float>(this->ValleyWeight);
  settings.HillWeight = static_cast<float>(this->HillWeight);
  settings.ResidualWeight = static_cast<float>(this->ResidualWeight);
  mesolight::HallucinationResult result;
  try
  {
    result = mesolight::HallucinateDepth(diffuse, flash, calibrationIn ? &calibration : nullptr,
      settings, mesolight::AlgorithmProgress(this));
  }
  catch (const mesolight::HallucinationAbortedError&)
  {
    return 1; // the user stopped it: empty outputs, no error
  }
  catch (const mesolight::HallucinationError& e)
  {
    vtkErrorMacro(<< e.what());
    return 0;
  }
  this->DepthRangeTexels = result.DepthRangeTexels;
  this->LayersUsed = result.Layers;
  this->FeatureSizeTexels = result.FeatureSizeTexels;
  this->LayersAveraged = result.Averaged ? 1 : 0;
  this->CorrelationLengthTexels = result.CorrelationLengthTexels;

  const vtkIdType count = static_cast<vtkIdType>(diffuse.Width) * diffuse.Height;
  for (vtkImageData* out : { albedoOut, depthOut })
  {
    out->SetExtent(diffuseIn->GetExtent());
    out->SetSpacing(diffuseIn->GetSpacing());
    out->SetOrigin(diffuseIn->GetOrigin());
  }
  vtkNew<vtkFloatArray> albedo;
  albedo->SetName("Albedo");
  albedo->SetNumberOfComponents(3);
  albedo->SetNumberOfTuples(count);
  std::copy(result.Albedo.Rgb.begin(), result.Albedo.Rgb.end(), albedo->GetPointer(0));
  albedoOut->GetPointData()->SetScalars(albedo);

  vtkNew<vtkFloatArray> depth;
  depth->SetName("Depth");
  depth->SetNumberOfTuples(count);
  std::copy(result.Depth.begin(), result.Depth.end(), depth->GetPointer(0));
  depthOut->GetPointData()->SetScalars(depth);
  vtkNew<vtkDoubleArray> depthScale;
  depthScale->SetName("MesolightDepthScale");
  depthScale->InsertNextValue(result.DepthRangeTexels / diffuse.Width);
  depthOut->GetFieldData()->AddArray(depthScale);
  vtkNew<vtkDoubleArray> range;
  range->SetName("HallucinatedDepthRangeTexels");
  range->InsertNextValue(result.DepthRangeTexels);
  depthOut->GetFieldData()->AddArray(range);
  return 1;
}

//------------------------------------------------------------------------------
void vtkDepthHallucinationFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "NumberOfLayers: " << this->NumberOfLayers << "\n";
  os << indent << "UseRatio: " << this->UseRatio << "\n";
  os << indent << "BaseSigma: " << this->BaseSigma << "\n";
  os << indent << "ValleyWeight: " << this->ValleyWeight << "\n";
  os << indent << "HillWeight: " << this->HillWeight << "\n";
  os << indent << "ResidualWeight: " << this->ResidualWeight << "\n";
  os << indent << "DepthRangeTexels: " << this->DepthRangeTexels << "\n";
  os << indent << "LayersUsed: " << this->LayersUsed << "\n";
  os << indent << "LayersAveraged: " << this->LayersAveraged << "\n";
  os << indent << "CorrelationLengthTexels: " << this->CorrelationLengthTexels << "\n";
  os << indent << "FeatureSizeTexels: " << this->FeatureSizeTexels << "\n";
}
