// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOIIOImageReader.h"

#include "OneLineMessage.h"

#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <filesystem>
#include <fstream>
#include <string>

vtkStandardNewMacro(vtkOIIOImageReader);

namespace fs = std::filesystem;

struct vtkOIIOImageReader::Header
{
  int Width = 0;
  int Height = 0;
  int FileChannels = 0;
  int Channels = 0; // channels read: min(FileChannels, 4)
  int VTKType = VTK_FLOAT;
  OIIO::TypeDesc Format = OIIO::TypeDesc::FLOAT;
  std::string FormatName;
};

namespace
{
/// Configuration hints: keep alpha as stored (A is the depth of relief textures, it must
/// not be multiplied into RGB); RAW photographs in linear light (the raw plugin's default is
/// sRGB-encoded, which would bend the shading that depth hallucination reads).
OIIO::ImageSpec ReadConfig()
{
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  config.attribute("raw:ColorSpace", "linear");
  return config;
}

/// True when some OpenImageIO plugin claims the file's extension.
bool IsKnownExtension(const fs::path& path)
{
  std::string ext = path.extension().string();
  if (ext.size() < 2)
  {
    return false;
  }
  ext = ext.substr(1);
  std::transform(ext.begin(), ext.end(), ext.begin(),
    [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  // "tiff:tif,tiff,tx;png:png;..."
  const std::string list = OIIO::get_string_attribute("extension_list");
  size_t pos = 0;
  while (pos < list.size())
  {
    size_t end = list.find(';', pos);
    end = end == std::string::npos ? list.size() : end;
    const std::string entry = list.substr(pos, end - pos);
    const size_t colon = entry.find(':');
    std::string exts = colon == std::string::npos ? entry : entry.substr(colon + 1);
    size_t p = 0;
    while (p <= exts.size())
    {
      size_t comma = exts.find(',', p);
      comma = comma == std::string::npos ? exts.size() : comma;
      if (exts.compare(p, comma - p, ext) == 0 && comma - p == ext.size())
      {
        return true;
      }
      p = comma + 1;
    }
    pos = end + 1;
  }
  return false;
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
  if (!fileName || !*fileName)
  {
    return false;
  }
  std::error_code ec;
  if (!fs::is_regular_file(fs::path(fileName), ec))
  {
    return false;
  }
  const OIIO::ImageSpec config = ReadConfig();
  auto in = OIIO::ImageInput::open(fileName, &config);
  if (!in)
  {
    OIIO::geterror(); // clear the pending message
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  const bool ok = spec.width > 0 && spec.height > 0 && spec.nchannels > 0;
  in->close();
  in->geterror();
  return ok;
}

//------------------------------------------------------------------------------
bool vtkOIIOImageReader::ReadHeader(Header& header)
{
  if (!this->FileName || !*this->FileName)
  {
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    vtkErrorMacro("No FileName set: call SetFileName() before reading.");
    return false;
  }
  const fs::path path(this->FileName);
  std::error_code ec;
  const fs::file_status status = fs::status(path, ec);
  if (!fs::exists(status))
  {
    this->SetErrorCode(vtkErrorCode::FileNotFoundError);
    vtkErrorMacro("Cannot read image '" << this->FileName << "': file not found.");
    return false;
  }
  if (fs::is_directory(status))
  {
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    vtkErrorMacro("Cannot read image '" << this->FileName << "': it is a directory, not a file.");
    return false;
  }
  if (fs::is_regular_file(status) && fs::file_size(path, ec) == 0 && !ec)
  {
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    vtkErrorMacro("Cannot read image '" << this->FileName << "': the file is empty (0 bytes).");
    return false;
  }
  if (!std::ifstream(path, std::ios::binary).is_open())
  {
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    vtkErrorMacro(
      "Cannot read image '" << this->FileName << "': the file cannot be opened (permissions?).");
    return false;
  }

  const OIIO::ImageSpec config = ReadConfig();
  auto in = OIIO::ImageInput::open(this->FileName, &config);
  if (!in)
  {
    const std::string oiioError = mesolight::OneLineMessage(OIIO::geterror());
    if (IsKnownExtension(path))
    {
      this->SetErrorCode(vtkErrorCode::FileFormatError);
      vtkErrorMacro("Cannot read image '" << this->FileName
                                          << "': not a valid image of the format its extension "
                                             "names, or corrupt (OpenImageIO: "
                                          << oiioError << ").");
    }
    else
    {
      this->SetErrorCode(vtkErrorCode::UnrecognizedFileTypeError);
      vtkErrorMacro("Cannot read image '"
        << this->FileName << "': unrecognized file type (OpenImageIO: " << oiioError << ").");
    }
    return false;
  }

  const OIIO::ImageSpec& spec = in->spec();
  header.FormatName = in->format_name();
  if (spec.width <= 0 || spec.height <= 0 || spec.nchannels <= 0)
  {
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    vtkErrorMacro("Cannot read image '" << this->FileName << "': zero-sized image (" << spec.width
                                        << " x " << spec.height << ", " << spec.nchannels
                                        << " channels).");
    in->close();
    in->geterror();
    return false;
  }
  if (spec.depth > 1)
  {
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    vtkErrorMacro("Cannot read image '" << this->FileName << "': volume images (depth "
                                        << spec.depth << ") are not supported.");
    in->close();
    in->geterror();
    return false;
  }
  header.Width = spec.width;
  header.Height = spec.height;
  header.FileChannels = spec.nchannels;
  header.Channels = std::min(4, spec.nchannels);
  switch (spec.format.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      header.VTKType = VTK_UNSIGNED_CHAR;
      header.Format = OIIO::TypeDesc::UINT8;
      break;
    case OIIO::TypeDesc::UINT16:
      header.VTKType = VTK_UNSIGNED_SHORT;
      header.Format = OIIO::TypeDesc::UINT16;
      break;
    default:
      header.VTKType = VTK_FLOAT;
      header.Format = OIIO::TypeDesc::FLOAT;
      break;
  }
  in->close();
  in->geterror();
  return true;
}

//------------------------------------------------------------------------------
int vtkOIIOImageReader::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  this->SetErrorCode(vtkErrorCode::NoError);
  vtkInformation* outInfo = outputVector->GetInformationObject(0);
  Header header;
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

  const int extent[6] = { 0, header.Width - 1, 0, header.Height - 1, 0, 0 };
  const double origin[3] = { 0.0, 0.0, 0.0 };
  const double spacing[3] = { 1.0, 1.0, 1.0 };
  outInfo->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  outInfo->Set(vtkDataObject::ORIGIN(), origin, 3);
  outInfo->Set(vtkDataObject::SPACING(), spacing, 3);
  vtkDataObject::SetPointDataActiveScalarInfo(outInfo, header.VTKType, header.Channels);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOIIOImageReader::ProgressCallback(void* self, float portionDone)
{
  auto* reader = static_cast<vtkOIIOImageReader*>(self);
  reader->UpdateProgress(portionDone);
  return reader->GetAbortExecute() != 0; // true asks OpenImageIO to stop
}

//------------------------------------------------------------------------------
int vtkOIIOImageReader::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector, 0);
  if (!output)
  {
    vtkErrorMacro("Missing output image.");
    return 0;
  }
  output->Initialize();

  // Re-read the header: the file may have changed since RequestInformation.
  Header header;
  if (!this->ReadHeader(header))
  {
    return 0;
  }
  const OIIO::ImageSpec config = ReadConfig();
  auto in = OIIO::ImageInput::open(this->FileName, &config);
  if (!in)
  {
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    vtkErrorMacro("Cannot read image '" << this->FileName << "' (OpenImageIO: "
                                        << mesolight::OneLineMessage(OIIO::geterror()) << ").");
    return 0;
  }

  output->SetExtent(0, header.Width - 1, 0, header.Height - 1, 0, 0);
  output->SetOrigin(0.0, 0.0, 0.0);
  output->SetSpacing(1.0, 1.0, 1.0);
  output->AllocateScalars(header.VTKType, header.Channels);
  vtkDataArray* scalars = output->GetPointData()->GetScalars();
  scalars->SetName("ImageScalars");

  // File rows are top first, VTK rows bottom first: start at the last VTK row and walk
  // backwards with a negative scanline stride.
  const OIIO::stride_t rowBytes = static_cast<OIIO::stride_t>(header.Width) * header.Channels *
    static_cast<OIIO::stride_t>(header.Format.size());
  auto* base = static_cast<unsigned char*>(scalars->GetVoidPointer(0));
  unsigned char* lastRow = base + static_cast<size_t>(rowBytes) * (header.Height - 1);
  const bool ok = in->read_image(0, 0, 0, header.Channels, header.Format, lastRow, OIIO::AutoStride,
    -rowBytes, OIIO::AutoStride, &vtkOIIOImageReader::ProgressCallback, this);
  const std::string oiioError = mesolight::OneLineMessage(in->geterror());
  in->close();
  in->geterror();
  if (this->GetAbortExecute())
  {
    output->Initialize();
    return 1;
  }
  if (!ok)
  {
    this->SetErrorCode(vtkErrorCode::FileFormatError);
    vtkErrorMacro("Cannot read the pixels of image '"
      << this->FileName << "': the file is truncated or corrupt (OpenImageIO: " << oiioError
      << ").");
    output->Initialize();
    return 0;
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
}
