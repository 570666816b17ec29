// SPDX-License-Identifier: BSD-3-Clause
// Fuzz target: opening an image through OpenImageIO and Mesolight's checks
// (filters/ImageIO/core/ImageFile, behind vtkOIIOImageReader and so every image `mesolight`
// reads: depth maps, photographs, environments, masks).
//
// Input: one byte choosing the file's extension (.png, .exr, .hdr, .pfm, .tif, .jpg, none, which
// makes OpenImageIO try every reader, or .hgt, an SRTM height tile read without it; the corpus
// names them '0' to '7'), then the file's bytes, written to the scratch
// directory. A header accepted must describe 1 to 4 channels of a positive size within the
// 64 MiB budget; its pixels are then read into a buffer of exactly that size (AddressSanitizer
// catches a write past it); a refusal (ImageFileError, the one exception bad input may raise)
// must say why, naming the file. Anything else aborts.
#include "FuzzSupport.h"
#include "ImageFile.h"

#include <OpenImageIO/imageio.h>

#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

namespace
{
const char* const Extensions[] = { ".png", ".exr", ".hdr", ".pfm", ".tif", ".jpg", "", ".hgt" };
constexpr std::int64_t Budget = 64 << 20;

void CheckRefusal(const mesolight::ImageFileError& error, const std::string& path)
{
  if (std::string(error.what()).find(path) == std::string::npos)
  {
    std::abort(); // a refusal names the file
  }
}
}

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size)
{
  static const bool configured = []
  {
    // One thread: the fuzzer runs one input at a time, and OpenImageIO's pool would only add
    // threads that outlive the input.
    OIIO::attribute("threads", 1);
    return true;
  }();
  (void)configured;
  if (size < 1)
  {
    return 0;
  }
  const char* extension = Extensions[data[0] % (sizeof(Extensions) / sizeof(Extensions[0]))];
  const std::string path = mesolight::fuzz::ScratchDirectory() + "/image" + extension;
  if (!mesolight::fuzz::WriteFile(path, data + 1, size - 1))
  {
    return 0;
  }
  mesolight::ImageFileInfo info;
  try
  {
    info = mesolight::ReadImageFileInfo(path, Budget);
  }
  catch (const mesolight::ImageFileError& e)
  {
    CheckRefusal(e, path);
    return 0;
  }
  if (info.Width <= 0 || info.Height <= 0 || info.Channels < 1 || info.Channels > 4 ||
    info.FileChannels < info.Channels || info.ByteSize() == 0 ||
    info.ByteSize() > static_cast<std::uint64_t>(Budget))
  {
    std::abort();
  }
  std::vector<unsigned char> pixels(static_cast<std::size_t>(info.ByteSize()));
  try
  {
    mesolight::ReadImageFilePixels(path, info, pixels.data());
  }
  catch (const mesolight::ImageFileError& e)
  {
    CheckRefusal(e, path);
    return 0;
  }
  if (info.Type == mesolight::ImageSampleType::Float)
  {
    const std::size_t count = pixels.size() / sizeof(float);
    if (mesolight::CountNonFiniteSamples(reinterpret_cast<const float*>(pixels.data()), count) >
      count)
    {
      std::abort();
    }
  }
  return 0;
}
