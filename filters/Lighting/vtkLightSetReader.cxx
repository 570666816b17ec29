// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightSetReader.h"

#include "LightSetCsv.h"
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

#include <filesystem>
#include <fstream>

vtkStandardNewMacro(vtkLightSetReader);

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
  // Regular files only: a device such as /dev/zero never ends a line, /dev/stdin waits.
  std::error_code code;
  if (!std::filesystem::is_regular_file(fileName, code))
  {
    error = std::filesystem::exists(fileName, code)
      ? fileName + " is not a regular file (a light set is a CSV file)"
      : "cannot open the light set " + fileName;
    return false;
  }
  std::ifstream in(fileName);
  if (!in)
  {
    error = "cannot open the light set " + fileName;
    return false;
  }
  try
  {
    values = mesolight::ParseLightSetCsv(in, fileName);
  }
  catch (const mesolight::LightSetCsvError& e)
  {
    error = e.what();
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
  mesolight::SetLightTextureInformation(outputVector->GetInformationObject(1), n);
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
