// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightProbeToLatLong.h"
#include "vtkUnitScale.h"
#include "vtkWholeExtentRequest.h"

#include "EnvironmentMaps.h"
#include "MemoryBudget.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <string>

vtkStandardNewMacro(vtkLightProbeToLatLong);

namespace
{
int OutputWidthFor(int requested, int probeSize)
{
  const int w = requested > 0 ? requested : 2 * probeSize;
  return std::max(2, w - (w % 2));
}
} // namespace

//------------------------------------------------------------------------------
int vtkLightProbeToLatLong::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* inInfo = inputVector[0]->GetInformationObject(0);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  int inExtent[6];
  inInfo->Get(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), inExtent);
  const int size = inExtent[1] - inExtent[0] + 1;
  const int w = OutputWidthFor(this->OutputWidth, size);
  const int extent[6] = { 0, w - 1, 0, w / 2 - 1, 0, 0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTK_FLOAT, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightProbeToLatLong::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  mesolight::RequestWholeInputExtent(inputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightProbeToLatLong::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0]);
  vtkImageData* output = vtkImageData::GetData(outputVector);
  vtkDataArray* scalars = input ? input->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (input)
  {
    input->GetDimensions(dims);
  }
  if (!scalars || dims[0] < 2 || dims[1] < 2 || scalars->GetNumberOfComponents() < 3)
  {
    vtkErrorMacro(<< "The light probe must be an RGB(A) image of at least 2x2 pixels.");
    return 0;
  }
  if (dims[0] != dims[1])
  {
    vtkWarningMacro(<< "The light probe picture is " << dims[0] << "x" << dims[1]
                    << ", not square; it is read as a " << std::min(dims[0], dims[1])
                    << " pixel square from its lower left corner.");
  }
  const int size = std::min(dims[0], dims[1]);
  {
    // The probe as floats, the lat-long map and its VTK copy: 12 bytes per pixel each.
    const std::uint64_t w = static_cast<std::uint64_t>(OutputWidthFor(this->OutputWidth, size));
    const std::string memory = mesolight::CheckMemoryBudget(
      "A " + std::to_string(w) + " x " + std::to_string(w / 2) + " lat-long map",
      12 * (static_cast<std::uint64_t>(size) * size + 2 * w * (w / 2)), this->MemoryBudget);
    if (!memory.empty())
    {
      vtkErrorMacro(<< memory << ".");
      return 0;
    }
  }
  mesolight::RgbImage probe(size, size);
  long long nonFinite = 0;
  const double unitScale = mesolight::UnitScale(scalars);
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const vtkIdType id = static_cast<vtkIdType>(j) * dims[0] + i;
      float* px = probe.Pixel(i, j);
      for (int c = 0; c < 3; ++c)
      {
        // 8/16-bit PNG/TIFF probes mean [0, 1] too.
        double value = scalars->GetComponent(id, c) * unitScale;
        if (!std::isfinite(value))
        {
          ++nonFinite;
          value = 0.0;
        }
        px[c] = static_cast<float>(std::max(0.0, value));
      }
    }
  }
  if (nonFinite > 0)
  {
    vtkErrorMacro(<< "The light probe has " << nonFinite << " non-finite (NaN or Inf) values.");
    return 0;
  }
  mesolight::ProbeView view;
  for (int c = 0; c < 3; ++c)
  {
    view.Forward[c] = this->Forward[c];
    view.Up[c] = this->Up[c];
  }
  const double* f = this->Forward;
  const double* u = this->Up;
  const double cross[3] = { f[1] * u[2] - f[2] * u[1], f[2] * u[0] - f[0] * u[2],
    f[0] * u[1] - f[1] * u[0] };
  if (cross[0] * cross[0] + cross[1] * cross[1] + cross[2] * cross[2] < 1e-12)
  {
    vtkErrorMacro(<< "Forward and Up must be non-zero and not parallel.");
    return 0;
  }
  const int w = OutputWidthFor(this->OutputWidth, size);
  this->UpdateProgress(0.1);
  const mesolight::RgbImage map = this->ProbeType == MIRROR_BALL
    ? mesolight::MirrorBallToLatLong(probe, view, w, w / 2, this->Samples)
    : mesolight::AngularMapToLatLong(probe, view, w, w / 2, this->Samples);
  output->SetExtent(0, w - 1, 0, w / 2 - 1, 0, 0);
  vtkNew<vtkFloatArray> rgb;
  rgb->SetName("Radiance");
  rgb->SetNumberOfComponents(3);
  rgb->SetNumberOfTuples(static_cast<vtkIdType>(w) * (w / 2));
  std::copy(map.Rgb.begin(), map.Rgb.end(), rgb->GetPointer(0));
  output->GetPointData()->SetScalars(rgb);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightProbeToLatLong::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ProbeType: " << (this->ProbeType == MIRROR_BALL ? "MirrorBall" : "AngularMap")
     << "\n";
  os << indent << "OutputWidth: " << this->OutputWidth << "\n";
  os << indent << "Samples: " << this->Samples << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << "\n";
  os << indent << "Forward: " << this->Forward[0] << " " << this->Forward[1] << " "
     << this->Forward[2] << "\n";
  os << indent << "Up: " << this->Up[0] << " " << this->Up[1] << " " << this->Up[2] << "\n";
}
