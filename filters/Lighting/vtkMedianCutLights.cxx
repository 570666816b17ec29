// SPDX-License-Identifier: BSD-3-Clause
#include "vtkMedianCutLights.h"
#include "Progress.h"
#include "vtkOutOfMemory.h"
#include "vtkRasterRowOrder.h"
#include "vtkWholeExtentRequest.h"

#include "EnvironmentMaps.h"
#include "LightSetData.h"
#include "MedianCut.h"
#include "MemoryBudget.h"
#include "ScalarConversion.h"

#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSMPTools.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iomanip>
#include <limits>
#include <new>
#include <vector>

vtkStandardNewMacro(vtkMedianCutLights);

namespace
{
/// nComp-component tuples of type T -> RGB floats (radiance).
template <typename T>
void ToRgb(const T* data, vtkIdType n, int nComp, float* out)
{
  vtkSMPTools::For(0, n,
    [&](vtkIdType begin, vtkIdType end)
    {
      for (vtkIdType k = begin; k < end; ++k)
      {
        const T* t = data + k * nComp;
        for (int c = 0; c < 3; ++c)
        {
          // One or two components (grey, grey and alpha): the grey in all three.
          out[3 * k + c] = static_cast<float>(mesolight::ToUnitValue(t[nComp >= 3 ? c : 0]));
        }
      }
    });
}
}

//------------------------------------------------------------------------------
vtkMedianCutLights::vtkMedianCutLights()
{
  this->SetNumberOfOutputPorts(2);
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
vtkImageData* vtkMedianCutLights::GetLightTexture()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkMedianCutLights::FillInputPortInformation(int, vtkInformation* info)
{
  // Optional so that a missing input gets our own, explicit error message.
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkMedianCutLights::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkMedianCutLights::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (inputVector[0]->GetNumberOfInformationObjects() < 1)
  {
    vtkErrorMacro("No input image: connect a lat-long environment map with "
                  "SetInputConnection() or SetInputData().");
    return 0;
  }
  const int n = std::max(1, this->NumberOfLights);
  mesolight::SetLightTextureInformation(outputVector->GetInformationObject(1), n);
  return 1;
}

//------------------------------------------------------------------------------
int vtkMedianCutLights::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The median cut needs the whole map.
  mesolight::RequestWholeInputExtent(inputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkMedianCutLights::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  return mesolight::ExecuteReportingOutOfMemory(
    this, [&]() { return this->Execute(inputVector, outputVector); });
}

//------------------------------------------------------------------------------
int vtkMedianCutLights::Execute(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkImageData* texture = vtkImageData::GetData(outputVector, 1);
  if (!output || !texture)
  {
    vtkErrorMacro("Missing output data objects.");
    return 0;
  }
  output->Initialize();
  texture->Initialize();
  if (!input)
  {
    vtkErrorMacro("No input image: connect a lat-long environment map with "
                  "SetInputConnection() or SetInputData().");
    return 0;
  }

  int dims[3];
  input->GetDimensions(dims);
  if (input->GetNumberOfPoints() < 1 || dims[0] < 1 || dims[1] < 1 || dims[2] != 1)
  {
    vtkErrorMacro("The input must be a non-empty 2D lat-long image in the XY plane; got "
                  "dimensions "
      << dims[0] << " x " << dims[1] << " x " << dims[2] << ".");
    return 0;
  }
  int w = dims[0];
  int h = dims[1];
  vtkIdType n = input->GetNumberOfPoints();
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, inputVector);
  if (!scalars)
  {
    // ParaView's GDAL Raster Reader gives a raster's pixels as the cells of a grid one point
    // larger: a lat-long map's pixels are those cells, read as they are (no interpolation).
    scalars = input->GetCellData()->GetScalars();
  }
  bool topFirst = false;
  if (scalars && dims[0] > 1 && dims[1] > 1 && scalars->GetNumberOfTuples() != n &&
    scalars->GetNumberOfTuples() == input->GetNumberOfCells())
  {
    w = dims[0] - 1;
    h = dims[1] - 1;
    n = input->GetNumberOfCells();
    // A plain image (not georeferenced) through GDAL Raster Reader: the file's top row first.
    topFirst = mesolight::RowsTopFirst(input);
  }
  if (!scalars)
  {
    vtkErrorMacro("The input image has no point or cell scalars (or no array selected by "
                  "SetInputArrayToProcess()) to read radiance from.");
    return 0;
  }
  const int nComp = scalars->GetNumberOfComponents();
  if (nComp < 1 || scalars->GetNumberOfTuples() != n)
  {
    vtkErrorMacro("The environment map's values (array \""
      << (scalars->GetName() ? scalars->GetName() : "")
      << "\") must be one per pixel, grey or RGB first; it has " << scalars->GetNumberOfTuples()
      << " values of " << nComp << " components for " << n << " pixels.");
    return 0;
  }
  if (this->NumberOfLights < 1 || this->NumberOfLights > n)
  {
    vtkErrorMacro("NumberOfLights must be between 1 and the number of pixels ("
      << n << "); it is " << this->NumberOfLights << ".");
    return 0;
  }
  if (scalars->GetDataType() == VTK_UNSIGNED_CHAR)
  {
    // Median cut splits the map by energy: an 8-bit map has the sun clipped to the sky's white
    // and its sRGB curve read as linear light, so the lights lose the light's real balance.
    vtkWarningMacro("The environment map is 8-bit: its values are usually sRGB-encoded and "
                    "clipped at white (the sun no brighter than a cloud), and they are read as "
                    "linear radiance. Use a high-dynamic-range map (.exr, .hdr) for real light.");
  }
  if (w != 2 * h)
  {
    vtkWarningMacro("The environment map is " << w << " x " << h
                                              << " pixels, not 2:1; it is still read as a "
                                                 "lat-long map (360 degrees across, 180 down), "
                                                 "so its pixels are not square in angle.");
  }

  {
    // Per pixel: RGB floats, and the median cut's summed-area tables (double; five with
    // variance minimization, over cells of k x k pixels: a bound) and per-pixel energy.
    const std::string memory = mesolight::CheckMemoryBudget(
      "Median cut of a " + std::to_string(w) + " x " + std::to_string(h) + " environment",
      static_cast<std::uint64_t>(n) * (12 + 8 * (this->VarianceMinimization ? 5 : 1) + 8),
      this->MemoryBudget);
    if (!memory.empty())
    {
      vtkErrorMacro(<< memory << ".");
      return 0;
    }
  }

  // 1. RGB floats; validate.
  std::vector<float> rgb(static_cast<size_t>(n) * 3);
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(
      ToRgb(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)), n, nComp, rgb.data()));
    default:
      vtkErrorMacro("Unsupported input scalar type " << scalars->GetDataTypeAsString() << ".");
      return 0;
  }
  if (topFirst)
  {
    mesolight::ReverseRows(rgb, static_cast<std::size_t>(h), 3 * static_cast<std::size_t>(w));
  }
  vtkIdType nonFinite = 0;
  vtkIdType firstNonFinite = -1;
  vtkIdType negative = 0;
  vtkIdType firstNegative = -1;
  for (vtkIdType k = 0; k < 3 * n; ++k)
  {
    const float x = rgb[k];
    if (!std::isfinite(x))
    {
      if (nonFinite++ == 0)
      {
        firstNonFinite = k / 3;
      }
    }
    else if (x < 0.0f)
    {
      if (negative++ == 0)
      {
        firstNegative = k / 3;
      }
      rgb[k] = 0.0f;
    }
  }
  if (nonFinite > 0)
  {
    vtkErrorMacro("The environment map contains "
      << nonFinite << " NaN or infinite value(s) in " << 3 * n
      << " RGB values; the first is at pixel (i=" << firstNonFinite % w
      << ", j=" << firstNonFinite / w
      << ", VTK row order). Fix the map (e.g. fill holes) before sampling lights.");
    return 0;
  }
  if (negative > 0)
  {
    vtkWarningMacro("The environment map contains "
      << negative << " negative value(s), the first at pixel (i=" << firstNegative % w
      << ", j=" << firstNegative / w << "); they are clamped to 0.");
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }
  this->UpdateProgress(0.1);

  // 2. Median cut (core/MedianCut.h).
  mesolight::MedianCutOptions options;
  options.NumberOfLights = this->NumberOfLights;
  options.VarianceMinimization = this->VarianceMinimization;
  options.Progress = mesolight::AlgorithmProgress(this, 0.1, 0.9);
  std::vector<mesolight::MedianCutLight> lights;
  try
  {
    lights = mesolight::ComputeMedianCut(rgb.data(), 3, w, h, options);
  }
  catch (const mesolight::MedianCutAbortedError&)
  {
    return 1; // an abort is not an error: empty output
  }
  catch (const mesolight::MedianCutError& e)
  {
    vtkErrorMacro("Median cut failed: " << e.what() << ".");
    return 0;
  }

  // The lights are shaded in single precision (light texture, GLSL): sums and products of
  // irradiances near FLT_MAX overflow to Inf and render black. Keep a wide margin below it.
  constexpr double brightest = 1e30;
  double total = 0.0;
  for (const mesolight::MedianCutLight& light : lights)
  {
    total += light.Rgb[0] + light.Rgb[1] + light.Rgb[2];
  }
  if (!(total <= brightest))
  {
    vtkErrorMacro("The environment's total irradiance ("
      << total << ") is beyond what single-precision shading can sum (" << brightest
      << "); scale the map down (its exposure) before sampling lights.");
    return 0;
  }

  // 3. Outputs.
  mesolight::FillLightSetData(lights, output, texture);
  this->UpdateProgress(1.0);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkMedianCutLights::WriteCsv(
  vtkPolyData* lights, const std::string& fileName, std::string& error)
{
  if (!lights || !lights->GetPoints())
  {
    error = "no lights to write";
    return false;
  }
  vtkDataArray* irradiance = lights->GetPointData()->GetArray("Irradiance");
  vtkDataArray* uv = lights->GetPointData()->GetArray("MapCoordinates");
  const vtkIdType n = lights->GetNumberOfPoints();
  if (!irradiance || !uv || irradiance->GetNumberOfComponents() != 3 ||
    uv->GetNumberOfComponents() != 2 || irradiance->GetNumberOfTuples() != n ||
    uv->GetNumberOfTuples() != n)
  {
    error = "the lights lack the \"Irradiance\" (RGB) or \"MapCoordinates\" (u, v) point arrays";
    return false;
  }
  std::ofstream out(fileName);
  if (!out)
  {
    error = "cannot open " + fileName + " for writing";
    return false;
  }
  out << std::setprecision(std::numeric_limits<float>::max_digits10);
  out << "u,v,x,y,z,r,g,b\n";
  for (vtkIdType k = 0; k < n; ++k)
  {
    double p[3];
    lights->GetPoint(k, p);
    const double* t = uv->GetTuple2(k);
    const double u = t[0];
    const double v = t[1];
    const double* c = irradiance->GetTuple3(k);
    out << u << ',' << v << ',' << p[0] << ',' << p[1] << ',' << p[2] << ',' << c[0] << ',' << c[1]
        << ',' << c[2] << '\n';
  }
  out.close();
  if (!out)
  {
    error = "error while writing " + fileName;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkMedianCutLights::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "NumberOfLights: " << this->NumberOfLights << "\n";
  os << indent << "VarianceMinimization: " << (this->VarianceMinimization ? "On" : "Off") << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << "\n";
}
