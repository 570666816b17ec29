// SPDX-License-Identifier: BSD-3-Clause
#include "vtkProceduralEnvironmentSource.h"

#include "ProceduralEnvironments.h"

#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cstring>

vtkStandardNewMacro(vtkProceduralEnvironmentSource);

//------------------------------------------------------------------------------
vtkProceduralEnvironmentSource::vtkProceduralEnvironmentSource()
{
  this->SetNumberOfInputPorts(0);
  const mesolight::SkyParameters defaults;
  this->SunElevation = defaults.SunElevation;
  this->SunAzimuth = defaults.SunAzimuth;
  this->SunDiameter = defaults.SunDiameter;
  this->SunIntensity = defaults.SunIntensity;
  this->Window = defaults.Window;
  this->WindowElevation = defaults.WindowElevation;
  this->WindowAzimuth = defaults.WindowAzimuth;
  this->WindowWidth = defaults.WindowWidth;
  this->WindowHeight = defaults.WindowHeight;
  this->WindowRadiance = defaults.WindowRadiance;
}

//------------------------------------------------------------------------------
void vtkProceduralEnvironmentSource::SetResolution(int w, int h)
{
  w = std::min(16384, std::max(2, w));
  h = std::min(16384, std::max(2, h));
  if (w != this->Resolution[0] || h != this->Resolution[1])
  {
    this->Resolution[0] = w;
    this->Resolution[1] = h;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
int vtkProceduralEnvironmentSource::RequestInformation(
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
int vtkProceduralEnvironmentSource::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro("Missing output image.");
    return 0;
  }
  mesolight::SkyParameters p;
  p.Sun = this->Map == SUN_SKY;
  p.SunElevation = this->SunElevation;
  p.SunAzimuth = this->SunAzimuth;
  p.SunDiameter = this->SunDiameter;
  p.SunIntensity = this->SunIntensity;
  p.Window = this->Map == SUN_SKY && this->Window;
  p.WindowElevation = this->WindowElevation;
  p.WindowAzimuth = this->WindowAzimuth;
  p.WindowWidth = this->WindowWidth;
  p.WindowHeight = this->WindowHeight;
  p.WindowRadiance = this->WindowRadiance;
  const int w = this->Resolution[0];
  const int h = this->Resolution[1];
  const mesolight::RgbImage map = mesolight::MakeSkyMap(w, h, p);
  this->UpdateProgress(0.9);

  vtkNew<vtkFloatArray> radiance;
  radiance->SetName("Radiance");
  radiance->SetNumberOfComponents(3);
  radiance->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  std::memcpy(radiance->GetPointer(0), map.Rgb.data(), map.Rgb.size() * sizeof(float));
  output->Initialize();
  output->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->GetPointData()->SetScalars(radiance);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
void vtkProceduralEnvironmentSource::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Map: " << (this->Map == SUN_SKY ? "SunSky" : "SmoothSky") << "\n";
  os << indent << "Resolution: " << this->Resolution[0] << " x " << this->Resolution[1] << "\n";
  os << indent << "SunElevation: " << this->SunElevation << "\n";
  os << indent << "SunAzimuth: " << this->SunAzimuth << "\n";
  os << indent << "SunDiameter: " << this->SunDiameter << "\n";
  os << indent << "SunIntensity: " << this->SunIntensity << "\n";
  os << indent << "Window: " << (this->Window ? "On" : "Off") << "\n";
  os << indent << "WindowElevation: " << this->WindowElevation << "\n";
  os << indent << "WindowAzimuth: " << this->WindowAzimuth << "\n";
  os << indent << "WindowWidth: " << this->WindowWidth << "\n";
  os << indent << "WindowHeight: " << this->WindowHeight << "\n";
  os << indent << "WindowRadiance: " << this->WindowRadiance << "\n";
}
