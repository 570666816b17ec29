// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefTextureFilter.h"
#include "ParallelFor.h"
#include "Progress.h"
#include "vtkOutOfMemory.h"
#include "vtkRasterRowOrder.h"
#include "vtkUnitScale.h"
#include "vtkWholeExtentRequest.h"

#include "DepthScaleSetting.h"
#include "Luminance.h"
#include "MemoryBudget.h"
#include "RasterCells.h"
#include "ScalarConversion.h"
#include "SobelNormals.h"

#include "vtkAlgorithm.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkUnsignedCharArray.h"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <new>
#include <sstream>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkReliefTextureFilter);

namespace
{
/// A hint when the lowest stored value is one that DEMs use for "no data" (-32768 in SRTM and
/// int16 GeoTIFFs, -9999 and -99999 in ASCII grids, the lowest float) and none is set: such holes
/// make an elevation range thousands of metres too deep.
std::string NoDataHint(double lowest, bool noDataSet)
{
  if (noDataSet)
  {
    return {};
  }
  for (const double marker : { -32768.0, -32767.0, -9999.0, -99999.0,
         static_cast<double>(std::numeric_limits<float>::lowest()) })
  {
    if (lowest == marker)
    {
      std::ostringstream hint;
      hint << " The lowest value, " << marker
           << ", looks like a no-data value: name it (NoDataValue with UseNoDataValue; ParaView: "
              "Use No Data Value; mesolight: --no-data="
           << marker << ").";
      return hint.str();
    }
  }
  return {};
}

/// Convert nComp-component tuples of type T to one value per texel (double): unit values, or
/// with `stored` the stored values themselves (NormalizeRange rescales them anyway).
template <typename T>
void ToUnitDepth(const T* data, vtkIdType n, int nComp, bool stored, double* out)
{
  const auto value = [stored](T v)
  { return stored ? static_cast<double>(v) : mesolight::ToUnitValue(v); };
  mesolight::ParallelFor(0, static_cast<std::size_t>(n), 0,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t k = begin; k < end; ++k)
      {
        const T* t = data + k * nComp;
        if (nComp >= 3)
        {
          out[k] = mesolight::Luminance<double>(value(t[0]), value(t[1]), value(t[2]));
        }
        else
        {
          out[k] = value(t[0]);
        }
      }
    });
}

/// Marks the texels whose first component is `noData` (NaN: is NaN); returns how many.
template <typename T>
vtkIdType MarkNoData(const T* data, vtkIdType n, int nComp, double noData, std::vector<char>& mask)
{
  vtkIdType count = 0;
  const bool nan = std::isnan(noData);
  // A float map's no-data value as written (gdalinfo's -9999.9) is not a float: compare in the
  // stored type, as GDAL does (a value beyond the type's range matches nothing). Integers
  // compare exactly as doubles.
  double compared = noData;
  if constexpr (std::is_floating_point<T>::value)
  {
    if (!nan && std::abs(noData) <= std::numeric_limits<T>::max())
    {
      compared = static_cast<double>(static_cast<T>(noData));
    }
  }
  for (vtkIdType k = 0; k < n; ++k)
  {
    const double v = static_cast<double>(data[k * nComp]);
    mask[k] = nan ? std::isnan(v) : v == compared;
    count += mask[k];
  }
  return count;
}

/// Step 1 of the filter: the values (ToUnitDepth) and, when asked, the texels without data.
template <typename T>
vtkIdType ReadDepthValues(const T* data, vtkIdType n, int nComp, bool stored, double* out,
  bool useNoData, double noData, std::vector<char>& mask)
{
  ToUnitDepth(data, n, nComp, stored, out);
  return useNoData ? MarkNoData(data, n, nComp, noData, mask) : 0;
}
}

//------------------------------------------------------------------------------
vtkReliefTextureFilter::vtkReliefTextureFilter()
{
  this->SetInputArrayToProcess(
    0, 0, 0, vtkDataObject::FIELD_ASSOCIATION_POINTS, vtkDataSetAttributes::SCALARS);
}

//------------------------------------------------------------------------------
void vtkReliefTextureFilter::SetDepthScale(double requested)
{
  mesolight::SetDepthScaleOf(this, this->DepthScale, requested, mesolight::MaximumDepthScale);
}

//------------------------------------------------------------------------------
int vtkReliefTextureFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  // Optional so that a missing input gets our own, explicit error message.
  this->Superclass::FillInputPortInformation(port, info);
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkReliefTextureFilter::RequestInformation(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (inputVector[0]->GetNumberOfInformationObjects() < 1)
  {
    vtkErrorMacro("No input image: connect a depth map with SetInputConnection() or "
                  "SetInputData().");
    return 0;
  }
  vtkDataObject::SetPointDataActiveScalarInfo(outputVector->GetInformationObject(0), VTK_FLOAT, 4);
  return 1;
}

//------------------------------------------------------------------------------
int vtkReliefTextureFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  // The Sobel stencil and NormalizeRange need the whole image.
  mesolight::RequestWholeInputExtent(inputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkReliefTextureFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  return mesolight::ExecuteReportingOutOfMemory(
    this, [&]() { return this->Execute(inputVector, outputVector); });
}

//------------------------------------------------------------------------------
int vtkReliefTextureFilter::Execute(
  vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  this->AppliedNoData = false;
  this->AppliedNoDataValue = 0.0;
  this->NumberOfNoDataTexels = 0;
  if (!input)
  {
    vtkErrorMacro("No input image: connect a depth map with SetInputConnection() or "
                  "SetInputData().");
    return 0;
  }
  if (!output)
  {
    vtkErrorMacro("Missing output image.");
    return 0;
  }
  output->Initialize();

  int dims[3];
  input->GetDimensions(dims);
  if (input->GetNumberOfPoints() < 1 || dims[0] < 1 || dims[1] < 1 || dims[2] < 1)
  {
    vtkErrorMacro("The input image is empty: a depth map needs at least 1 x 1 texels (a reader "
                  "that could not read its file leaves it empty: see the reader's error).");
    return 0;
  }
  if (dims[2] != 1)
  {
    vtkErrorMacro("The input must be a 2D image in the XY plane; got dimensions "
      << dims[0] << " x " << dims[1] << " x " << dims[2] << ".");
    return 0;
  }
  // ParaView's GDAL Raster Reader gives a raster's pixels as the cells of a grid one point larger
  // (and hides the cells without data). The extent downstream is set before any data exist,
  // when nothing says the pixels will be cells, so the texels stay the points: each the mean of
  // the cells around it (mesolight::CellsToCorners, core/RasterCells.h).
  int association = vtkDataObject::FIELD_ASSOCIATION_POINTS;
  vtkDataArray* scalars = this->GetInputArrayToProcess(0, inputVector, association);
  bool cells = scalars && association == vtkDataObject::FIELD_ASSOCIATION_CELLS;
  if (!scalars && input->GetCellData()->GetScalars())
  {
    scalars = input->GetCellData()->GetScalars();
    cells = true;
  }
  if (!scalars)
  {
    vtkErrorMacro("The input image has no point or cell scalars (or no array selected by "
                  "SetInputArrayToProcess()) to read depths from.");
    return 0;
  }
  if (cells && (dims[0] < 2 || dims[1] < 2))
  {
    vtkErrorMacro("The input image carries its pixels as cells but has "
      << dims[0] << " x " << dims[1] << " points: no 2D cell to read.");
    return 0;
  }
  const int nComp = scalars->GetNumberOfComponents();
  const vtkIdType n = input->GetNumberOfPoints();
  // The samples read: the points, or the cells.
  const vtkIdType nRead = cells ? static_cast<vtkIdType>(dims[0] - 1) * (dims[1] - 1) : n;
  if (nComp < 1 || nComp > 4 || scalars->GetNumberOfTuples() != nRead)
  {
    vtkErrorMacro("The input array \"" << (scalars->GetName() ? scalars->GetName() : "")
                                       << "\" must have 1 to 4 components and one tuple per "
                                          "texel; it has "
                                       << nComp << " components and "
                                       << scalars->GetNumberOfTuples() << " tuples for " << nRead
                                       << (cells ? " cells." : " texels."));
    return 0;
  }
  const int w = dims[0];
  const int h = dims[1];
  // The no-data value: the one set here, else the one the image names (a GeoTIFF's GDAL_NODATA).
  bool useNoData = this->UseNoDataValue;
  double noDataValue = this->NoDataValue;
  vtkDataArray* inputNoData =
    vtkDataArray::SafeDownCast(input->GetFieldData()->GetAbstractArray("MesolightNoDataValue"));
  if (!useNoData && this->UseInputNoDataValue && inputNoData &&
    inputNoData->GetNumberOfTuples() == 1 && inputNoData->GetNumberOfComponents() == 1)
  {
    useNoData = true;
    noDataValue = inputNoData->GetComponent(0, 0);
  }
  // Hidden cells (a vtkUniformGrid's blanking: GDAL Raster Reader hides the cells holding the
  // raster's no-data value) have no data either, the input's own marking as the value is.
  vtkUnsignedCharArray* hidden =
    cells && this->UseInputNoDataValue ? input->GetCellGhostArray() : nullptr;
  hidden = hidden && hidden->GetNumberOfTuples() == nRead ? hidden : nullptr;
  // Peak working memory per texel: unit values (double), depths (float), the RGBA float output,
  // the no-data mask; for cells, their values and mask as well.
  const std::string memory = mesolight::CheckMemoryBudget(
    "A " + std::to_string(w) + " x " + std::to_string(h) + " relief texture",
    static_cast<std::uint64_t>(n) * (8 + 4 + 16 + (useNoData || cells ? 1 : 0)) +
      (cells ? static_cast<std::uint64_t>(nRead) * 9 : 0),
    this->MemoryBudget);
  if (!memory.empty())
  {
    vtkErrorMacro(<< memory << ".");
    return 0;
  }

  // 1. Stored values -> unit values (with NormalizeRange, the stored values), and the texels
  // without data.
  std::vector<double> value(static_cast<size_t>(nRead));
  std::vector<char> noData(useNoData || hidden ? static_cast<size_t>(nRead) : 0);
  vtkIdType noDataCount = 0;
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(
      noDataCount = ReadDepthValues(static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)), nRead,
        nComp, this->NormalizeRange, value.data(), useNoData, noDataValue, noData));
    default:
      vtkErrorMacro("Unsupported input scalar type " << scalars->GetDataTypeAsString() << ".");
      return 0;
  }
  if (cells)
  {
    for (vtkIdType k = 0; hidden && k < nRead; ++k)
    {
      noData[k] = noData[k] || (hidden->GetValue(k) & vtkDataSetAttributes::HIDDENCELL);
    }
    std::vector<double> cellValue;
    std::vector<char> cellNoData;
    cellValue.swap(value);
    cellNoData.swap(noData);
    mesolight::CellsToCorners(cellValue, cellNoData, w - 1, h - 1, value, noData);
    noDataCount = static_cast<vtkIdType>(std::count(noData.begin(), noData.end(), 1));
    if (mesolight::RowsTopFirst(input))
    {
      // A plain image (not georeferenced) through GDAL Raster Reader: the file's top row first.
      mesolight::ReverseRows(value, static_cast<std::size_t>(h), static_cast<std::size_t>(w));
      mesolight::ReverseRows(noData, static_cast<std::size_t>(h), static_cast<std::size_t>(w));
    }
  }
  this->AppliedNoData = useNoData || noDataCount > 0;
  this->AppliedNoDataValue = useNoData ? noDataValue : 0.0;
  this->NumberOfNoDataTexels = noDataCount;
  if (noDataCount == n)
  {
    std::ostringstream which;
    if (useNoData)
    {
      which << " holds the no-data value " << noDataValue
            << (this->UseNoDataValue ? "" : " (the image's own, as its file names it)")
            << (hidden ? " or" : "");
    }
    vtkErrorMacro("Every texel" << which.str() << (hidden ? " lies among hidden cells" : "")
                                << ": there is no depth to draw.");
    return 0;
  }

  // 2. Validate: NaN / Inf are data errors, never silently turned into normals.
  vtkIdType nonFinite = 0;
  vtkIdType firstNonFinite = -1;
  double minValue = VTK_DOUBLE_MAX;
  double maxValue = VTK_DOUBLE_MIN;
  vtkIdType firstOutOfRange = -1;
  vtkIdType outOfRange = 0;
  constexpr double tolerance = 1e-6; // float round-off of data meant to be in [0,1]
  for (vtkIdType k = 0; k < n; ++k)
  {
    const double x = value[k];
    if (noDataCount > 0 && noData[k])
    {
      continue;
    }
    if (!std::isfinite(x))
    {
      if (nonFinite++ == 0)
      {
        firstNonFinite = k;
      }
      continue;
    }
    minValue = std::min(minValue, x);
    maxValue = std::max(maxValue, x);
    if (x < -tolerance || x > 1.0 + tolerance)
    {
      if (outOfRange++ == 0)
      {
        firstOutOfRange = k;
      }
    }
  }
  if (nonFinite > 0)
  {
    vtkErrorMacro("The input depth map contains "
      << nonFinite << " NaN or infinite value(s) out of " << n
      << "; the first is at texel (i=" << firstNonFinite % w << ", j=" << firstNonFinite / w
      << "). Fix the data (e.g. fill holes), or take them as having no data (UseNoDataValue "
         "on, NoDataValue nan; ParaView: Use No Data Value; mesolight: --no-data nan).");
    return 0;
  }
  const int type = scalars->GetDataType();
  if (!this->NormalizeRange && type != VTK_FLOAT && type != VTK_DOUBLE &&
    scalars->GetDataTypeMin() < 0)
  {
    // Image formats store depth and height maps unsigned; signed integers (int16 GeoTIFFs,
    // SRTM tiles) hold elevations in metres, which as fractions of the type's maximum would
    // draw as a flat wall.
    const double unitScale = mesolight::UnitScale(scalars);
    vtkErrorMacro("The input holds signed integers ("
      << scalars->GetDataTypeAsString() << ", stored values [" << std::lround(minValue / unitScale)
      << ", " << std::lround(maxValue / unitScale) << "]"
      << (noDataCount > 0 ? " without the no-data texels" : "")
      << "): they store measurements such as elevations in metres (DEMs), not depths in [0,1]. "
         "Turn on NormalizeRange (ParaView: Normalize Range; mesolight: --normalize, with --relief "
         "--relief-normalize) to "
         "rescale their range to [0,1].");
    return 0;
  }
  if (outOfRange > 0 && !this->NormalizeRange)
  {
    // Integer samples are divided by the type's maximum: give their stored values too, the
    // units a no-data value is given in (e.g. -32768 in an int16 DEM).
    const double unitScale = mesolight::UnitScale(scalars);
    std::ostringstream stored;
    if (unitScale != 1.0 && nComp < 3)
    {
      stored << ", stored values [" << std::lround(minValue / unitScale) << ", "
             << std::lround(maxValue / unitScale) << "]";
    }
    vtkErrorMacro("The input depths must lie in [0,1] but range over ["
      << minValue << ", " << maxValue << "]" << stored.str()
      << (noDataCount > 0 ? " without the no-data texels" : "") << " (" << outOfRange
      << " texel(s) outside, the first at texel (i=" << firstOutOfRange % w
      << ", j=" << firstOutOfRange / w
      << ")). Turn on NormalizeRange (ParaView: Normalize Range; mesolight: --normalize, with "
         "--relief --relief-normalize) to "
         "rescale the input range to [0,1], as for elevations in metres, or fix the data.");
    return 0;
  }
  if (this->GetAbortExecute())
  {
    return 1;
  }
  this->UpdateProgress(0.1);

  // Texels without data: the deepest depth of the others (the lowest ground of an elevation map).
  if (noDataCount > 0)
  {
    const double deepest = this->InvertInput ? minValue : maxValue;
    for (vtkIdType k = 0; k < n; ++k)
    {
      value[k] = noData[k] ? deepest : value[k];
    }
  }

  // 3. Unit values -> depth (0 top, 1 deepest).
  std::vector<float> depth(static_cast<size_t>(n));
  double offset = 0.0;
  double scale = 1.0;
  if (this->NormalizeRange)
  {
    if (maxValue > minValue)
    {
      offset = minValue;
      scale = 1.0 / (maxValue - minValue);
    }
    else
    {
      // A flat map (a lake or sea tile) is the surface's plane, heights or depths alike.
      vtkWarningMacro("NormalizeRange: the input is constant ("
        << minValue << "); it is mapped to depth 0, the surface's plane.");
      offset = minValue;
      scale = 0.0;
    }
  }
  // The true vertical scale: the elevations' range over the map's width on the ground.
  this->TrueDepthScale = 0.0;
  vtkDataArray* pixelSize =
    vtkDataArray::SafeDownCast(input->GetFieldData()->GetAbstractArray("MesolightPixelSize"));
  const bool validPixelSize = pixelSize && pixelSize->GetNumberOfTuples() == 1 &&
    pixelSize->GetNumberOfComponents() == 2 && pixelSize->GetComponent(0, 0) > 0.0 &&
    std::isfinite(pixelSize->GetComponent(0, 0));
  // The elevations' unit, where the file names it (a GeoTIFF's VerticalUnitsGeoKey: feet are
  // 0.3048 m); metres otherwise.
  vtkDataArray* unitArray =
    vtkDataArray::SafeDownCast(input->GetFieldData()->GetAbstractArray("MesolightElevationUnit"));
  const double elevationUnit =
    unitArray && unitArray->GetNumberOfValues() == 1 ? unitArray->GetComponent(0, 0) : 1.0;
  const bool validUnit = elevationUnit > 0.0 && std::isfinite(elevationUnit);
  // (0 for constant elevations: a flat tile drawn flat.)
  const bool trueScaleKnown = this->NormalizeRange && validPixelSize && validUnit;
  if (trueScaleKnown)
  {
    this->TrueDepthScale =
      (maxValue - minValue) * elevationUnit / (w * pixelSize->GetComponent(0, 0));
  }
  if (this->UseTrueDepthScale && !trueScaleKnown)
  {
    vtkErrorMacro("UseTrueDepthScale (ParaView: Use True Depth Scale; mesolight: "
                  "--vertical-exaggeration) needs "
      << (!this->NormalizeRange ? "NormalizeRange on (elevations in metres)"
             : !pixelSize       ? "an image that carries its pixel size on the ground, as the "
                                  "Mesolight Image Reader (vtkOIIOImageReader) gives it for a "
                                  "GeoTIFF or an SRTM tile; this one carries none"
             : !validPixelSize  ? "a positive, finite pixel size (MesolightPixelSize: two values)"
                                : "elevations in metres or feet; the file names another unit "
                                  "(MesolightElevationUnit, from a GeoTIFF's VerticalUnitsGeoKey)")
      << ". Set the depth scale instead.");
    return 0;
  }
  // A pixel size far too small for the elevations (a corrupt georeference), or an absurd
  // exaggeration, would give a relief many times deeper than wide: refused, as DepthScale is
  // clamped to mesolight::MaximumDepthScale (which the mapper applies to a baked scale too).
  if (this->UseTrueDepthScale &&
    this->TrueDepthScale * this->VerticalExaggeration > mesolight::MaximumDepthScale)
  {
    vtkErrorMacro("The true vertical scale times VerticalExaggeration is a depth scale of "
      << this->TrueDepthScale * this->VerticalExaggeration << " ("
      << (maxValue - minValue) * elevationUnit << " m of elevation over " << w << " pixels of "
      << pixelSize->GetComponent(0, 0) << " m), above " << mesolight::MaximumDepthScale
      << ", the largest depth scale: lower VerticalExaggeration, or check the image's pixel size "
         "and its elevations' unit (or set the depth scale instead)."
      << NoDataHint(minValue, noDataCount > 0));
    return 0;
  }
  this->AppliedDepthScale =
    this->UseTrueDepthScale ? this->TrueDepthScale * this->VerticalExaggeration : this->DepthScale;

  const bool invert = this->InvertInput && scale != 0.0; // a constant input stays at depth 0
  for (vtkIdType k = 0; k < n; ++k)
  {
    const double d = std::min(1.0, std::max(0.0, (value[k] - offset) * scale));
    depth[k] = static_cast<float>(invert ? 1.0 - d : d);
  }
  value = std::vector<double>();

  if (w == 1 || h == 1)
  {
    vtkWarningMacro("The depth map is " << w << " x " << h
                                        << " texels: slopes cannot be estimated across a "
                                           "1-texel dimension, so the normals are flat along "
                                        << (w == 1 && h == 1 ? "both axes" : (w == 1 ? "x" : "y"))
                                        << ".");
  }

  // 4. Sobel normals + packing (core/SobelNormals.h), rows in parallel; a few serial
  // chunks report progress and honour aborts from this thread.
  vtkNew<vtkFloatArray> relief;
  relief->SetName("Relief");
  relief->SetNumberOfComponents(4);
  relief->SetNumberOfTuples(n);
  float* rgba = relief->GetPointer(0);
  const float depthScale = static_cast<float>(this->AppliedDepthScale);
  const mesolight::BorderMode mode =
    this->BorderMode == WRAP ? mesolight::BorderMode::Wrap : mesolight::BorderMode::Clamp;
  const float* depthPtr = depth.data();
  const int chunks = std::max(1, std::min(h, 16));
  for (int c = 0; c < chunks; ++c)
  {
    if (this->GetAbortExecute())
    {
      return 1;
    }
    const int rowBegin = static_cast<int>(static_cast<long long>(h) * c / chunks);
    const int rowEnd = static_cast<int>(static_cast<long long>(h) * (c + 1) / chunks);
    mesolight::ParallelFor(static_cast<std::size_t>(rowBegin), static_cast<std::size_t>(rowEnd), 0,
      [&](std::size_t begin, std::size_t end)
      {
        mesolight::ComputeReliefTextureRows(
          depthPtr, w, h, depthScale, mode, static_cast<int>(begin), static_cast<int>(end), rgba);
      });
    this->UpdateProgress(0.1 + 0.9 * (c + 1) / chunks);
  }

  output->SetExtent(input->GetExtent());
  output->SetOrigin(input->GetOrigin());
  output->SetSpacing(input->GetSpacing());
  output->GetPointData()->SetScalars(relief);

  vtkNew<vtkFloatArray> scaleArray;
  scaleArray->SetName("MesolightDepthScale");
  scaleArray->SetNumberOfComponents(1);
  scaleArray->SetNumberOfTuples(1);
  scaleArray->SetValue(0, depthScale);
  output->GetFieldData()->AddArray(scaleArray);
  if (validPixelSize && pixelSize->GetComponent(0, 1) > 0.0 &&
    std::isfinite(pixelSize->GetComponent(0, 1)))
  {
    // The texels' size on the ground, for the surface the relief is drawn on: a geographic
    // raster's pixels are not square (vtkReliefPlaneFilter).
    vtkNew<vtkDoubleArray> groundSize;
    groundSize->DeepCopy(pixelSize);
    groundSize->SetName("MesolightPixelSize");
    output->GetFieldData()->AddArray(groundSize);
  }
  if (this->TrueDepthScale > 0.0)
  {
    vtkNew<vtkDoubleArray> trueScale;
    trueScale->SetName("MesolightTrueDepthScale");
    trueScale->InsertNextValue(this->TrueDepthScale);
    output->GetFieldData()->AddArray(trueScale);
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkReliefTextureFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "UseTrueDepthScale: " << (this->UseTrueDepthScale ? "On" : "Off") << "\n";
  os << indent << "VerticalExaggeration: " << this->VerticalExaggeration << "\n";
  os << indent << "TrueDepthScale: " << this->TrueDepthScale << "\n";
  os << indent << "BorderMode: " << (this->BorderMode == WRAP ? "Wrap" : "Clamp") << "\n";
  os << indent << "InvertInput: " << (this->InvertInput ? "On" : "Off") << "\n";
  os << indent << "NormalizeRange: " << (this->NormalizeRange ? "On" : "Off") << "\n";
  os << indent << "NoDataValue: " << this->NoDataValue << "\n";
  os << indent << "UseNoDataValue: " << (this->UseNoDataValue ? "On" : "Off") << "\n";
  os << indent << "UseInputNoDataValue: " << (this->UseInputNoDataValue ? "On" : "Off") << "\n";
  os << indent << "AppliedNoData: " << (this->AppliedNoData ? "On" : "Off") << "\n";
  os << indent << "AppliedNoDataValue: " << this->AppliedNoDataValue << "\n";
  os << indent << "NumberOfNoDataTexels: " << this->NumberOfNoDataTexels << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << "\n";
}
