// SPDX-License-Identifier: BSD-3-Clause
#include "vtkOIIOImageWriter.h"
#include "Progress.h"
#include "vtkWholeExtentRequest.h"

#include "OneLineMessage.h"

#include "ScalarConversion.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include <OpenImageIO/imageio.h>

#include <atomic>
#include <cctype>
#include <chrono>
#include <cstdint>
#include <filesystem>
#include <string>
#include <type_traits>
#include <vector>

vtkStandardNewMacro(vtkOIIOImageWriter);

namespace fs = std::filesystem;

namespace
{
/// Convert (through [0,1]) and flip rows: VTK row j goes to file row h - 1 - j.
template <typename TIn, typename TOut>
void ConvertFlip(const TIn* in, int w, int h, int nComp, TOut* out)
{
  const size_t rowValues = static_cast<size_t>(w) * nComp;
  for (int j = 0; j < h; ++j)
  {
    const TIn* src = in + rowValues * j;
    TOut* dst = out + rowValues * (h - 1 - j);
    for (size_t k = 0; k < rowValues; ++k)
    {
      if constexpr (std::is_same<TIn, TOut>::value)
      {
        dst[k] = src[k];
      }
      else if constexpr (std::is_floating_point<TOut>::value)
      {
        dst[k] = static_cast<TOut>(mesolight::ToUnitValue(src[k]));
      }
      else
      {
        dst[k] = mesolight::FromUnitValue<TOut>(mesolight::ToUnitValue(src[k]));
      }
    }
  }
}

template <typename TIn>
void ConvertFlipTo(OIIO::TypeDesc format, const TIn* in, int w, int h, int nComp, void* out)
{
  if (format == OIIO::TypeDesc::UINT8)
  {
    ConvertFlip(in, w, h, nComp, static_cast<std::uint8_t*>(out));
  }
  else if (format == OIIO::TypeDesc::UINT16)
  {
    ConvertFlip(in, w, h, nComp, static_cast<std::uint16_t*>(out));
  }
  else
  {
    ConvertFlip(in, w, h, nComp, static_cast<float*>(out));
  }
}

std::string UniqueSuffix()
{
  static std::atomic<unsigned long> counter{ 0 };
  const auto ticks = std::chrono::steady_clock::now().time_since_epoch().count();
  return std::to_string(static_cast<unsigned long long>(ticks)) + "-" +
    std::to_string(counter.fetch_add(1));
}
}

//------------------------------------------------------------------------------
vtkOIIOImageWriter::vtkOIIOImageWriter()
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(0);
}

//------------------------------------------------------------------------------
vtkOIIOImageWriter::~vtkOIIOImageWriter()
{
  this->SetFileName(nullptr);
}

//------------------------------------------------------------------------------
bool vtkOIIOImageWriter::Write()
{
  this->SetErrorCode(vtkErrorCode::NoError);
  this->LastWriteSucceeded = false;
  if (!this->FileName || !*this->FileName)
  {
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    vtkErrorMacro("No FileName set: call SetFileName() before Write().");
    return false;
  }
  if (this->GetNumberOfInputConnections(0) < 1)
  {
    this->SetErrorCode(vtkErrorCode::UserError);
    vtkErrorMacro("No input: connect an image with SetInputConnection() or SetInputData() "
                  "before writing '"
      << this->FileName << "'.");
    return false;
  }
  // A writer has no output to be up to date: force execution.
  this->Modified();
  this->Update();
  return this->LastWriteSucceeded;
}

//------------------------------------------------------------------------------
int vtkOIIOImageWriter::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector*)
{
  return 1;
}

//------------------------------------------------------------------------------
int vtkOIIOImageWriter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  mesolight::RequestWholeInputExtent(inputVector);
  return 1;
}

//------------------------------------------------------------------------------
int vtkOIIOImageWriter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector*)
{
  mesolight::ClearAbort(this);
  this->LastWriteSucceeded = false;
  vtkImageData* input = vtkImageData::GetData(inputVector[0], 0);
  if (!input)
  {
    this->SetErrorCode(vtkErrorCode::UserError);
    vtkErrorMacro("No input image to write.");
    return 0;
  }
  // Failures are reported by our own message, ErrorCode and Write()'s result; returning 1
  // spares the caller the executive's generic "returned failure" dump.
  this->LastWriteSucceeded = this->WriteImage(input);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkOIIOImageWriter::ProgressCallback(void* self, float portionDone)
{
  auto* writer = static_cast<vtkOIIOImageWriter*>(self);
  writer->UpdateProgress(portionDone);
  return writer->GetAbortExecute() != 0;
}

//------------------------------------------------------------------------------
bool vtkOIIOImageWriter::WriteImage(vtkImageData* input)
{
  if (!this->FileName || !*this->FileName)
  {
    this->SetErrorCode(vtkErrorCode::NoFileNameError);
    vtkErrorMacro("No FileName set: call SetFileName() before Write().");
    return false;
  }
  const std::string fileName = this->FileName;

  int dims[3];
  input->GetDimensions(dims);
  vtkDataArray* scalars = input->GetPointData()->GetScalars();
  if (input->GetNumberOfPoints() < 1 || !scalars || scalars->GetNumberOfTuples() < 1)
  {
    this->SetErrorCode(vtkErrorCode::UserError);
    vtkErrorMacro("Cannot write '" << fileName
                                   << "': the input image is empty (no points or "
                                      "no point scalars).");
    return false;
  }
  if (dims[2] != 1)
  {
    this->SetErrorCode(vtkErrorCode::UserError);
    vtkErrorMacro("Cannot write '" << fileName << "': a 2D image in the XY plane is expected, got "
                                   << dims[0] << " x " << dims[1] << " x " << dims[2] << ".");
    return false;
  }
  const int nComp = scalars->GetNumberOfComponents();
  if (nComp < 1 || nComp > 4 || scalars->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    this->SetErrorCode(vtkErrorCode::UserError);
    vtkErrorMacro("Cannot write '" << fileName
                                   << "': 1 to 4 components per pixel are supported, "
                                      "the scalars have "
                                   << nComp << ".");
    return false;
  }
  const int w = dims[0];
  const int h = dims[1];

  // Target directory must exist (we never create directories behind the caller's back).
  const fs::path target(fileName);
  fs::path directory = target.parent_path();
  if (directory.empty())
  {
    directory = ".";
  }
  std::error_code ec;
  if (!fs::is_directory(directory, ec))
  {
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    vtkErrorMacro("Cannot write '" << fileName << "': directory '" << directory.string()
                                   << "' does not exist or is not a directory.");
    return false;
  }
  if (fs::is_directory(target, ec))
  {
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    vtkErrorMacro("Cannot write '" << fileName << "': it is an existing directory.");
    return false;
  }

  // The extension selects the format plugin.
  auto out = OIIO::ImageOutput::create(fileName);
  if (!out)
  {
    this->SetErrorCode(vtkErrorCode::UnrecognizedFileTypeError);
    vtkErrorMacro("Cannot write '"
      << fileName << "': unknown or unsupported file extension '" << target.extension().string()
      << "' (OpenImageIO: " << mesolight::OneLineMessage(OIIO::geterror()) << ").");
    return false;
  }
  const std::string format = out->format_name();
  if (format == "dpx" && nComp == 2)
  {
    // OpenImageIO 2.4's DPX writer aborts (assertion) on 2-channel images.
    this->SetErrorCode(vtkErrorCode::UserError);
    vtkErrorMacro("Cannot write '" << fileName << "': DPX cannot store 2-channel images.");
    return false;
  }
  const bool floatFormat = format == "openexr" || format == "hdr";
  const bool sixteenBitFormat = format == "png" || format == "tiff";
  OIIO::TypeDesc pixelType = OIIO::TypeDesc::UINT8;
  switch (this->DataType)
  {
    case UNSIGNED_CHAR:
      pixelType = OIIO::TypeDesc::UINT8;
      break;
    case UNSIGNED_SHORT:
      pixelType = OIIO::TypeDesc::UINT16;
      break;
    case FLOAT:
      pixelType = OIIO::TypeDesc::FLOAT;
      break;
    case AUTO:
    default:
      pixelType = floatFormat ? OIIO::TypeDesc::FLOAT
                              : ((sixteenBitFormat && this->BitDepth > 8) ? OIIO::TypeDesc::UINT16
                                                                          : OIIO::TypeDesc::UINT8);
      break;
  }

  // Convert + flip to the file's top-row-first order.
  std::vector<unsigned char> pixels(static_cast<size_t>(w) * h * nComp * pixelType.size());
  switch (scalars->GetDataType())
  {
    vtkTemplateMacro(ConvertFlipTo(pixelType,
      static_cast<const VTK_TT*>(scalars->GetVoidPointer(0)), w, h, nComp, pixels.data()));
    default:
      this->SetErrorCode(vtkErrorCode::UserError);
      vtkErrorMacro("Cannot write '" << fileName << "': unsupported scalar type "
                                     << scalars->GetDataTypeAsString() << ".");
      return false;
  }

  OIIO::ImageSpec spec(w, h, nComp, pixelType);
  // Alpha is data (the relief depth), not coverage: store it as is.
  spec.attribute("oiio:UnassociatedAlpha", 1);

  // Write next to the target, then rename: a failed write never leaves a broken file.
  const fs::path temporary = directory /
    ("." + target.stem().string() + ".tmp-" + UniqueSuffix() + target.extension().string());
  const auto removeTemporary = [&temporary]()
  {
    std::error_code ignored;
    fs::remove(temporary, ignored);
  };
  if (!out->open(temporary.string(), spec))
  {
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    vtkErrorMacro("Cannot write '"
      << fileName << "': cannot create a " << format << " file in '" << directory.string()
      << "' (OpenImageIO: " << mesolight::OneLineMessage(out->geterror()) << ").");
    out.reset();
    removeTemporary();
    return false;
  }
  const bool written = out->write_image(pixelType, pixels.data(), OIIO::AutoStride,
    OIIO::AutoStride, OIIO::AutoStride, &vtkOIIOImageWriter::ProgressCallback, this);
  const std::string writeError =
    written ? std::string() : mesolight::OneLineMessage(out->geterror());
  const bool closed = out->close();
  const std::string closeError =
    closed ? std::string() : mesolight::OneLineMessage(out->geterror());
  out.reset();
  if (this->GetAbortExecute())
  {
    removeTemporary();
    return false;
  }
  if (!written || !closed)
  {
    this->SetErrorCode(vtkErrorCode::OutOfDiskSpaceError);
    vtkErrorMacro("Cannot write '" << fileName << "': writing the pixels failed (OpenImageIO: "
                                   << (written ? closeError : writeError)
                                   << "); the target was left untouched.");
    removeTemporary();
    return false;
  }
  fs::rename(temporary, target, ec);
  if (ec)
  {
    this->SetErrorCode(vtkErrorCode::CannotOpenFileError);
    vtkErrorMacro("Cannot write '" << fileName << "': renaming the temporary file '"
                                   << temporary.string() << "' failed (" << ec.message() << ").");
    removeTemporary();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkOIIOImageWriter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  static const char* const names[] = { "Auto", "UnsignedChar", "UnsignedShort", "Float" };
  os << indent << "FileName: " << (this->FileName ? this->FileName : "(none)") << "\n";
  os << indent << "DataType: " << names[this->DataType] << "\n";
  os << indent << "BitDepth: " << this->BitDepth << "\n";
}
