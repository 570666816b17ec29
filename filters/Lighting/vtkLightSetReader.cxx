// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightSetReader.h"

#include "LightSetData.h"

#include "vtkCellArray.h"
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

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <sstream>

vtkStandardNewMacro(vtkLightSetReader);

namespace
{
std::string Trim(const std::string& s)
{
  const char* space = " \t\r\n";
  const size_t first = s.find_first_not_of(space);
  if (first == std::string::npos)
  {
    return std::string();
  }
  const size_t last = s.find_last_not_of(space);
  return s.substr(first, last - first + 1);
}

// The whole field as a finite double, or false.
bool ParseNumber(const std::string& field, double& value)
{
  const std::string text = Trim(field);
  if (text.empty())
  {
    return false;
  }
  char* end = nullptr;
  errno = 0;
  value = std::strtod(text.c_str(), &end);
  return end == text.c_str() + text.size() && errno != ERANGE && std::isfinite(value);
}
} // namespace

//------------------------------------------------------------------------------
vtkLightSetReader::vtkLightSetReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightSetReader::GetLightTexture()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
int vtkLightSetReader::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLightSetReader::ParseCsv(
  const std::string& fileName, std::vector<double>& values, std::string& error)
{
  values.clear();
  if (fileName.empty())
  {
    error = "no light-set file name given";
    return false;
  }
  std::ifstream in(fileName);
  if (!in)
  {
    error = "cannot open the light set " + fileName;
    return false;
  }
  std::string line;
  if (!std::getline(in, line) || Trim(line).empty())
  {
    error = fileName + " is empty (expected the header \"u,v,x,y,z,r,g,b\" and one row per light)";
    return false;
  }
  if (Trim(line) != "u,v,x,y,z,r,g,b")
  {
    error = fileName + ", line 1: the header is \"" + Trim(line).substr(0, 80) +
      "\", expected \"u,v,x,y,z,r,g,b\" (a light set written by mesolight lights)";
    return false;
  }
  static const char* names[8] = { "u", "v", "x", "y", "z", "r", "g", "b" };
  long lineNumber = 1;
  while (std::getline(in, line))
  {
    ++lineNumber;
    if (Trim(line).empty())
    {
      continue;
    }
    std::vector<std::string> fields;
    std::stringstream row(line);
    std::string field;
    while (std::getline(row, field, ','))
    {
      fields.push_back(field);
    }
    if (!line.empty() && line.back() == ',')
    {
      fields.emplace_back();
    }
    const std::string where = fileName + ", line " + std::to_string(lineNumber) + ": ";
    if (fields.size() != 8)
    {
      error = where + std::to_string(fields.size()) + " fields, expected 8 (u,v,x,y,z,r,g,b)";
      return false;
    }
    double v[8];
    for (int k = 0; k < 8; ++k)
    {
      if (!ParseNumber(fields[k], v[k]))
      {
        error = where + "the " + names[k] + " field \"" + Trim(fields[k]).substr(0, 40) +
          "\" is not a finite number";
        return false;
      }
    }
    const double length = std::sqrt(v[2] * v[2] + v[3] * v[3] + v[4] * v[4]);
    if (std::abs(length - 1.0) > 1e-3)
    {
      error = where + "the direction (x, y, z) has length " + std::to_string(length) +
        ", expected a unit vector";
      return false;
    }
    if (v[5] < 0.0 || v[6] < 0.0 || v[7] < 0.0)
    {
      error = where + "negative irradiance (r, g, b)";
      return false;
    }
    values.insert(values.end(), v, v + 8);
  }
  if (in.bad())
  {
    error = "error while reading " + fileName;
    return false;
  }
  if (values.empty())
  {
    error = fileName + " has a header but no lights";
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkLightSetReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  std::string error;
  if (!ParseCsv(this->FileName, this->Values, error))
  {
    vtkErrorMacro(<< error << ".");
    return 0;
  }
  const int n = static_cast<int>(this->Values.size() / 8);
  const int extent[6] = { 0, n - 1, 0, 1, 0, 0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  vtkInformation* texInfo = outputVector->GetInformationObject(1);
  texInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  texInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  texInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(texInfo, VTK_FLOAT, 4);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightSetReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkImageData* texture = vtkImageData::GetData(outputVector, 1);
  if (!output || !texture || this->Values.empty())
  {
    vtkErrorMacro("No light set was read (see the previous error).");
    return 0;
  }
  // The CSV's rows (u, v, x, y, z, r, g, b) as the median cut's lights; a CSV has no solid angles.
  std::vector<mesolight::MedianCutLight> lights(this->Values.size() / 8);
  for (std::size_t k = 0; k < lights.size(); ++k)
  {
    const double* v = this->Values.data() + 8 * k;
    mesolight::MedianCutLight& light = lights[k];
    light.U = v[0];
    light.V = v[1];
    for (int c = 0; c < 3; ++c)
    {
      light.Direction[c] = v[2 + c];
      light.Rgb[c] = v[5 + c];
    }
  }
  mesolight::FillLightSetData(lights, output, texture);
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightSetReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << this->FileName << "\n";
}
