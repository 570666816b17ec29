// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOIIOImageReader.h"
#include "Progress.h"

#include "ImageFile.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkDoubleArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <string>

vtkStandardNewMacro(vtkOIIOImageReader);

namespace
{
/// The vtkErrorCode of a refusal.
unsigned long VTKErrorCode(mesolight::ImageFileStatus status)
{
  switch (status)
  {
    case mesolight::ImageFileStatus::NoFileName:
      return vtkErrorCode::NoFileNameError;
    case mesolight::ImageFileStatus::FileNotFound:
      return vtkErrorCode::FileNotFoundError;
    case mesolight::ImageFileStatus::CannotOpen:
      return vtkErrorCode::CannotOpenFileError;
    case mesolight::ImageFileStatus::UnrecognizedType:
      return vtkErrorCode::UnrecognizedFileTypeError;
    default:
      return vtkErrorCode::FileFormatError;
  }
}

int VTKType(mesolight::ImageSampleType type)
{
  switch (type)
  {
    case mesolight::ImageSampleType::UInt8:
      return VTK_UNSIGNED_CHAR;
    case mesolight::ImageSampleType::UInt16:
      return VTK_UNSIGNED_SHORT;
    case mesolight::ImageSampleType::Int16:
      return VTK_SHORT;
    case mesolight::ImageSampleType::UInt32:
      return VTK_UNSIGNED_INT;
    case mesolight::ImageSampleType::Int32:
      return VTK_INT;
    default:
      return VTK_FLOAT;
  }
}
}

//------------------------------------------------------------------------------
vtkOIIOImageReader::vtkOIIOImageReader()
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

//------------------------------------------------------------------------------
vtkOIIOImageReader::~vtkOIIOImageReader()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkOIIOImageReader::CanReadFile(const char* fileName)
{
  return fileName && mesolight::CanReadImageFile(fileName);
}

//------------------------------------------------------------------------------
bool vtkOIIOImageReader::ReadHeader(mesolight::ImageFileInfo& header)
{
  try
  {
    header = mesolight::ReadImageFileInfo(this->FileName ? this->FileName : "", this->MemoryBudget);
  }
  catch (const mesolight::ImageFileError& e)
  {
    this->SetErrorCode(VTKErrorCode(e.GetReason()));
    vtkErrorMacro(<< e.what());
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
int vtkOIIOImageReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  mesolight::ImageFileInfo header;
  if (!this->ReadHeader(header))
  {
    // Do not leave the previous image in the output.
    if (vtkImageData* output = vtkImageData::GetData(outInfo))
    {
      output->Initialize();
    }
    this->ImageSize[0] = this->ImageSize[1] = 0;
    this->NumberOfChannelsInFile = 0;
    this->FormatName.clear();
    this->HasNoDataValue = false;
    this->NoDataValue = 0.0;
    this->HasPixelSize = false;
    this->PixelSize[0] = this->PixelSize[1] = 0.0;
    this->HasElevationUnit = false;
    this->ElevationUnit = 1.0;
    return 0;
  }
  if (header.FileChannels > 4)
  {
    vtkWarningMacro("Image '" << this->FileName << "' has " << header.FileChannels
                              << " channels: only the first 4 are read.");
  }
  this->ImageSize[0] = header.Width;
  this->ImageSize[1] = header.Height;
  this->NumberOfChannelsInFile = header.FileChannels;
  this->FormatName = header.FormatName;
  this->HasNoDataValue = header.HasNoDataValue;
  this->NoDataValue = header.NoDataValue;
  this->HasPixelSize = header.HasPixelSize;
  this->PixelSize[0] = header.PixelSizeX;
  this->PixelSize[1] = header.PixelSizeY;
  this->HasElevationUnit = header.HasElevationUnit;
  this->ElevationUnit = header.ElevationUnit;

  const int extent[6] = { 0, header.Width - 1, 0, header.Height - 1, 0, 0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, VTKType(header.Type), header.Channels);
  return 1;
}

//------------------------------------------------------------------------------
int vtkOIIOImageReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  mesolight::ClearAbort(this);
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro("Missing output image.");
    return 0;
  }
  output->Initialize();
  this->NumberOfNonFiniteValues = 0;

  // Re-read the header: the file may have changed since RequestInformation.
  mesolight::ImageFileInfo header;
  if (!this->ReadHeader(header))
  {
    return 0;
  }
  output->SetExtent(0, header.Width - 1, 0, header.Height - 1, 0, 0);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->AllocateScalars(VTKType(header.Type), header.Channels);
  vtkDataArray* scalars = output->GetPointData()->GetScalars();
  scalars->SetName("ImageScalars");

  bool complete = false;
  std::string warning;
  try
  {
    complete = mesolight::ReadImageFilePixels(
      this->FileName, header, scalars->GetVoidPointer(0),
      [this](float portionDone)
      {
        this->UpdateProgress(portionDone);
        return this->GetAbortExecute() != 0;
      },
      &warning);
  }
  catch (const mesolight::ImageFileError& e)
  {
    if (!this->GetAbortExecute())
    {
      this->SetErrorCode(VTKErrorCode(e.GetReason()));
      vtkErrorMacro(<< e.what());
      output->Initialize();
      return 0;
    }
  }
  if (!complete || this->GetAbortExecute())
  {
    output->Initialize();
    return 1;
  }
  if (!warning.empty())
  {
    vtkWarningMacro(<< warning);
  }
  if (header.HasNoDataValue)
  {
    vtkNew<vtkDoubleArray> noData;
    noData->SetName("MesolightNoDataValue");
    noData->InsertNextValue(header.NoDataValue);
    output->GetFieldData()->AddArray(noData);
  }
  if (header.HasPixelSize)
  {
    vtkNew<vtkDoubleArray> pixelSize;
    pixelSize->SetName("MesolightPixelSize");
    pixelSize->SetNumberOfComponents(2);
    pixelSize->InsertNextTuple2(header.PixelSizeX, header.PixelSizeY);
    output->GetFieldData()->AddArray(pixelSize);
  }
  if (header.HasElevationUnit)
  {
    vtkNew<vtkDoubleArray> unit;
    unit->SetName("MesolightElevationUnit");
    unit->InsertNextValue(header.ElevationUnit);
    output->GetFieldData()->AddArray(unit);
  }
  // NaN is how geometry images mark holes: counted for the consumers that refuse it, not warned.
  if (header.Type == mesolight::ImageSampleType::Float)
  {
    this->NumberOfNonFiniteValues = static_cast<vtkIdType>(
      mesolight::CountNonFiniteSamples(static_cast<const float*>(scalars->GetVoidPointer(0)),
        static_cast<std::size_t>(header.ByteSize() / sizeof(float))));
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkOIIOImageReader::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "ImageSize: " << this->ImageSize[0] << " x " << this->ImageSize[1] << "\n";
  os << indent << "NumberOfChannelsInFile: " << this->NumberOfChannelsInFile << "\n";
  os << indent << "FormatName: " << this->FormatName << "\n";
  os << indent << "MemoryBudget: " << this->MemoryBudget << "\n";
  os << indent << "NumberOfNonFiniteValues: " << this->NumberOfNonFiniteValues << "\n";
  os << indent << "HasNoDataValue: " << (this->HasNoDataValue ? "true" : "false") << "\n";
  os << indent << "NoDataValue: " << this->NoDataValue << "\n";
  os << indent << "HasPixelSize: " << (this->HasPixelSize ? "true" : "false") << "\n";
  os << indent << "PixelSize: " << this->PixelSize[0] << " x " << this->PixelSize[1] << " m\n";
  os << indent << "HasElevationUnit: " << (this->HasElevationUnit ? "true" : "false") << "\n";
  os << indent << "ElevationUnit: " << this->ElevationUnit << " m\n";
}
