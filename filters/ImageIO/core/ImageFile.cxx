// SPDX-License-Identifier: BSD-3-Clause
#include "ImageFile.h"

#include "GeoTiffTags.h"
#include "MemoryBudget.h"
#include "OneLineMessage.h"
#include "SrtmHeightFile.h"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cmath>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <optional>
#include <sstream>
#include <vector>

namespace fs = std::filesystem;

namespace mesolight
{
namespace
{

/// Configuration hints: keep alpha as stored (A is the depth of relief textures, it must not be
/// multiplied into RGB); RAW photographs in linear light (the raw plugin's default is
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
  std::size_t pos = 0;
  while (pos < list.size())
  {
    std::size_t end = list.find(';', pos);
    end = end == std::string::npos ? list.size() : end;
    const std::string entry = list.substr(pos, end - pos);
    const std::size_t colon = entry.find(':');
    const std::string exts = colon == std::string::npos ? entry : entry.substr(colon + 1);
    std::size_t p = 0;
    while (p <= exts.size())
    {
      std::size_t comma = exts.find(',', p);
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

[[noreturn]] void Refuse(ImageFileStatus reason, const std::string& message)
{
  throw ImageFileError(reason, message);
}

/// Closes an input and drops its pending error text (OpenImageIO keeps it per thread otherwise).
void Close(OIIO::ImageInput& in)
{
  in.close();
  in.geterror();
}

ImageSampleType SampleType(const OIIO::TypeDesc& format)
{
  switch (format.basetype)
  {
    case OIIO::TypeDesc::UINT8:
      return ImageSampleType::UInt8;
    case OIIO::TypeDesc::UINT16:
      return ImageSampleType::UInt16;
    case OIIO::TypeDesc::INT16:
      return ImageSampleType::Int16;
    case OIIO::TypeDesc::UINT32:
      return ImageSampleType::UInt32;
    case OIIO::TypeDesc::INT32:
      return ImageSampleType::Int32;
    default:
      return ImageSampleType::Float;
  }
}

ImageFileInfo CheckSpec(
  const std::string& path, const OIIO::ImageSpec& spec, std::int64_t memoryBudget)
{
  int orientation = spec.get_int_attribute("Orientation", 1);
  orientation = orientation >= 1 && orientation <= 8 ? orientation : 1;
  const bool turned = orientation >= 5; // a quarter turn: shown width = stored height
  ImageFileInfo info =
    CheckImageHeader(path, turned ? spec.height : spec.width, turned ? spec.width : spec.height,
      spec.depth, spec.nchannels, SampleType(spec.format), memoryBudget);
  info.Orientation = orientation;
  if (orientation != 1)
  {
    // Read as stored into a second buffer, then turned into the output (ReadImageFile): both
    // are held at once.
    std::ostringstream what;
    what << "the " << info.Width << " x " << info.Height << " pixels of image '" << path
         << "', turned or mirrored as its Orientation tag " << orientation
         << " says (read through a second buffer of the same size)";
    const std::string budget = CheckMemoryBudget(what.str(), 2 * info.ByteSize(), memoryBudget);
    if (!budget.empty())
    {
      Refuse(ImageFileStatus::TooLarge, "Cannot read image '" + path + "': " + budget);
    }
  }
  return info;
}

/// Where the pixel shown at (x, y) (top-left origin, the shown image `width` x `height`) is
/// stored in a file of orientation `orientation` (EXIF 2.3 Orientation, TIFF 6.0 tag 274).
void StoredPixel(int orientation, int x, int y, int width, int height, int& sx, int& sy)
{
  switch (orientation)
  {
    case 2: // mirrored left-right
      sx = width - 1 - x;
      sy = y;
      break;
    case 3: // turned 180 degrees
      sx = width - 1 - x;
      sy = height - 1 - y;
      break;
    case 4: // mirrored top-bottom
      sx = x;
      sy = height - 1 - y;
      break;
    case 5: // transposed
      sx = y;
      sy = x;
      break;
    case 6: // shown turned 90 clockwise
      sx = y;
      sy = width - 1 - x;
      break;
    case 7: // transversed
      sx = height - 1 - y;
      sy = width - 1 - x;
      break;
    case 8: // shown turned 90 anticlockwise
      sx = height - 1 - y;
      sy = x;
      break;
    default:
      sx = x;
      sy = y;
      break;
  }
}

/// Little-endian 32-bit integer at `bytes`.
std::int64_t Int32At(const unsigned char* bytes, bool isSigned = true)
{
  const std::uint32_t u = static_cast<std::uint32_t>(bytes[0]) |
    (static_cast<std::uint32_t>(bytes[1]) << 8) | (static_cast<std::uint32_t>(bytes[2]) << 16) |
    (static_cast<std::uint32_t>(bytes[3]) << 24);
  return isSigned ? static_cast<std::int64_t>(static_cast<std::int32_t>(u))
                  : static_cast<std::int64_t>(u);
}

/// OpenEXR (3.1) allocates what a header claims before any check of ours can run: an attribute's
/// size field (a 600-byte file made it allocate 1.8 GB), and line or tile buffers sized by the data
/// window (16 million pixels wide in a 550-byte file: seconds of allocation and clearing). Both
/// were found by the image_file fuzz target. "" when the headers of an OpenEXR file claim no more
/// bytes than the file holds and buffers within `memoryBudget` (see CheckMemoryBudget), else why
/// not. Files that are not OpenEXR, and headers this walk cannot follow, are left to OpenImageIO.
std::string CheckOpenExrHeaders(const std::string& path, std::int64_t memoryBudget, bool& tooLarge)
{
  tooLarge = false;
  std::ifstream in(path, std::ios::binary);
  unsigned char start[8] = {};
  if (!in.read(reinterpret_cast<char*>(start), 8) || start[0] != 0x76 || start[1] != 0x2f ||
    start[2] != 0x31 || start[3] != 0x01)
  {
    return std::string();
  }
  std::error_code ec;
  const std::uint64_t fileSize = fs::file_size(fs::path(path), ec);
  if (ec)
  {
    return std::string();
  }
  const bool multipart = (start[5] & 0x10) != 0; // version flags bit 12
  auto readString = [&in](std::string& text)
  {
    text.clear();
    char c = 0;
    while (in.get(c) && c != '\0')
    {
      if (text.size() >= 256)
      {
        return false;
      }
      text += c;
    }
    return static_cast<bool>(in);
  };
  for (int header = 0; header < 1024; ++header)
  {
    std::int64_t width = 0;
    std::int64_t height = 0;
    std::uint64_t pixelBytes = 0; // bytes per pixel, all channels
    std::int64_t chunkLines = 1;
    std::uint64_t tileBytes = 0; // pixels per tile
    for (int attribute = 0;; ++attribute)
    {
      std::string name;
      std::string type;
      if (attribute > 4096 || !readString(name))
      {
        return std::string();
      }
      if (name.empty())
      {
        break; // the end of this header
      }
      unsigned char sizeBytes[4] = {};
      if (!readString(type) || !in.read(reinterpret_cast<char*>(sizeBytes), 4))
      {
        return std::string();
      }
      const std::int64_t size = Int32At(sizeBytes);
      const std::uint64_t position = static_cast<std::uint64_t>(in.tellg());
      if (size < 0 || static_cast<std::uint64_t>(size) > fileSize - std::min(fileSize, position))
      {
        return "its OpenEXR attribute '" + name + "' claims " + std::to_string(size) +
          " bytes, more than the file holds (" + std::to_string(fileSize) + " bytes)";
      }
      std::vector<unsigned char> value(static_cast<std::size_t>(size));
      if (!in.read(reinterpret_cast<char*>(value.data()), size))
      {
        return std::string();
      }
      if (name == "dataWindow" && type == "box2i" && size == 16)
      {
        width = Int32At(&value[8]) - Int32At(&value[0]) + 1;
        height = Int32At(&value[12]) - Int32At(&value[4]) + 1;
      }
      else if (name == "compression" && type == "compression" && size == 1)
      {
        // NONE, RLE, ZIPS: 1 line; ZIP, PXR24: 16; PIZ, B44, B44A, DWAA: 32; DWAB: 256.
        static const std::int64_t lines[] = { 1, 1, 1, 16, 32, 16, 32, 32, 32, 256 };
        chunkLines = value[0] < 10 ? lines[value[0]] : 256;
      }
      else if (name == "tiles" && type == "tiledesc" && size == 9)
      {
        tileBytes = static_cast<std::uint64_t>(Int32At(&value[0], false)) *
          static_cast<std::uint64_t>(Int32At(&value[4], false));
      }
      else if (name == "channels" && type == "chlist")
      {
        // name\0, int pixel type (0 uint, 1 half, 2 float), 12 more bytes; an empty name ends it.
        std::size_t k = 0;
        while (k < value.size() && value[k] != 0)
        {
          while (k < value.size() && value[k] != 0)
          {
            ++k;
          }
          if (k + 17 > value.size())
          {
            break;
          }
          pixelBytes += Int32At(&value[k + 1]) == 1 ? 2 : 4;
          k += 17;
        }
      }
    }
    if (width > 0 && height > 0)
    {
      // What OpenEXR allocates before reading a pixel, about: a chunk of lines or a tile.
      const std::uint64_t bytesPerPixel = std::max<std::uint64_t>(pixelBytes, 2);
      const std::uint64_t lines = static_cast<std::uint64_t>(std::max(height, chunkLines));
      const std::uint64_t buffers =
        std::max(static_cast<std::uint64_t>(width) * lines, tileBytes) * bytesPerPixel;
      const std::string budget = CheckMemoryBudget(
        "the OpenEXR data window (" + std::to_string(width) + " x " + std::to_string(height) + ")",
        buffers, memoryBudget);
      if (!budget.empty())
      {
        tooLarge = true;
        return budget;
      }
    }
    // Multi-part: headers follow one another until an empty one.
    if (!multipart || in.peek() == 0 || !in)
    {
      return std::string();
    }
  }
  return std::string();
}

/// Opens `path` with OpenImageIO, or throws why it cannot.
std::unique_ptr<OIIO::ImageInput> Open(const std::string& path, std::int64_t memoryBudget)
{
  bool tooLarge = false;
  const std::string exr = CheckOpenExrHeaders(path, memoryBudget, tooLarge);
  if (!exr.empty())
  {
    if (tooLarge)
    {
      Refuse(ImageFileStatus::TooLarge, "Cannot read image '" + path + "': " + exr);
    }
    Refuse(ImageFileStatus::FileFormat,
      "Cannot read image '" + path + "': not a valid OpenEXR file: " + exr + ".");
  }
  const OIIO::ImageSpec config = ReadConfig();
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in)
  {
    const std::string oiioError = OneLineMessage(OIIO::geterror());
    if (IsKnownExtension(fs::path(path)))
    {
      Refuse(ImageFileStatus::FileFormat,
        "Cannot read image '" + path +
          "': not a valid image of the format its extension names, or corrupt (OpenImageIO: " +
          oiioError + ").");
    }
    Refuse(ImageFileStatus::UnrecognizedType,
      "Cannot read image '" + path + "': unrecognized file type (OpenImageIO: " + oiioError + ").");
  }
  return in;
}

bool ProgressTrampoline(void* opaque, float portionDone)
{
  const auto* progress = static_cast<const std::function<bool(float)>*>(opaque);
  return (*progress)(portionDone); // true asks OpenImageIO to stop
}

} // namespace

//------------------------------------------------------------------------------
// An SRTM tile's header is its size (SrtmHeightFile.h): N x N signed 16-bit metres, voids at
// -32768, which is its no-data value as a GeoTIFF's GDAL_NODATA is.
ImageFileInfo ReadSrtmTileInfo(const std::string& path, std::int64_t memoryBudget)
{
  std::error_code ec;
  const std::uint64_t bytes = fs::file_size(fs::path(path), ec);
  const int side = ec ? 0 : SrtmTileSide(bytes);
  if (side == 0)
  {
    Refuse(ImageFileStatus::FileFormat,
      "Cannot read image '" + path + "': an SRTM height tile ('.hgt') holds N x N big-endian " +
        "16-bit heights, 2 N^2 bytes (2884802 for 1201 x 1201, 25934402 for 3601 x 3601); this " +
        "file has " + std::to_string(bytes) + " bytes.");
  }
  ImageFileInfo info =
    CheckImageHeader(path, side, side, 1, 1, ImageSampleType::Int16, memoryBudget);
  info.FormatName = "srtm-hgt";
  info.HasNoDataValue = true;
  info.NoDataValue = SrtmVoidHeight;
  // A tile spans one degree from the corner its name gives (N45E006: 45-46 degrees north).
  if (const std::optional<double> south = SrtmTileSouthLatitude(path))
  {
    if (const auto pixel = GeographicPixelSize(1.0 / (side - 1), 1.0 / (side - 1), *south + 0.5))
    {
      info.HasPixelSize = true;
      info.PixelSizeX = pixel->X;
      info.PixelSizeY = pixel->Y;
    }
  }
  return info;
}

//------------------------------------------------------------------------------
std::size_t ImageFileInfo::SampleSize() const
{
  switch (this->Type)
  {
    case ImageSampleType::UInt8:
      return 1;
    case ImageSampleType::UInt16:
    case ImageSampleType::Int16:
      return 2;
    default:
      return 4;
  }
}

//------------------------------------------------------------------------------
std::uint64_t ImageFileInfo::ByteSize() const
{
  // Each factor is below 2^31 (4 channels, 4 bytes): the product of the sides fits 2^62.
  return static_cast<std::uint64_t>(std::max(this->Width, 0)) *
    static_cast<std::uint64_t>(std::max(this->Height, 0)) *
    static_cast<std::uint64_t>(std::max(this->Channels, 0)) * this->SampleSize();
}

//------------------------------------------------------------------------------
ImageFileInfo CheckImageHeader(const std::string& path, int width, int height, int depth,
  int channels, ImageSampleType type, std::int64_t memoryBudget)
{
  const std::string prefix = "Cannot read image '" + path + "': ";
  if (width <= 0 || height <= 0 || channels <= 0)
  {
    std::ostringstream text;
    text << prefix << "zero-sized image (" << width << " x " << height << ", " << channels
         << " channels).";
    Refuse(ImageFileStatus::FileFormat, text.str());
  }
  if (depth > 1)
  {
    Refuse(ImageFileStatus::FileFormat,
      prefix + "volume images (depth " + std::to_string(depth) + ") are not supported.");
  }
  ImageFileInfo info;
  info.Width = width;
  info.Height = height;
  info.FileChannels = channels;
  info.Channels = std::min(4, channels);
  info.Type = type;
  // A header of a few bytes can claim 2^31 x 2^31 pixels: refuse before allocating.
  std::ostringstream what;
  what << "the " << width << " x " << height << " pixels of image '" << path << "' ("
       << info.Channels << " channels of " << info.SampleSize() << " bytes)";
  const std::string budget = CheckMemoryBudget(what.str(), info.ByteSize(), memoryBudget);
  if (!budget.empty())
  {
    Refuse(ImageFileStatus::TooLarge, prefix + budget);
  }
  return info;
}

//------------------------------------------------------------------------------
ImageFileInfo ReadImageFileInfo(const std::string& path, std::int64_t memoryBudget)
{
  if (path.empty())
  {
    Refuse(ImageFileStatus::NoFileName, "No FileName set: call SetFileName() before reading.");
  }
  const std::string prefix = "Cannot read image '" + path + "': ";
  const fs::path file(path);
  std::error_code ec;
  const fs::file_status status = fs::status(file, ec);
  if (!fs::exists(status))
  {
    Refuse(ImageFileStatus::FileNotFound, prefix + "file not found.");
  }
  if (fs::is_directory(status))
  {
    Refuse(ImageFileStatus::CannotOpen, prefix + "it is a directory, not a file.");
  }
  if (fs::is_regular_file(status) && fs::file_size(file, ec) == 0 && !ec)
  {
    Refuse(ImageFileStatus::FileFormat, prefix + "the file is empty (0 bytes).");
  }
  if (!std::ifstream(file, std::ios::binary).is_open())
  {
    Refuse(ImageFileStatus::CannotOpen, prefix + "the file cannot be opened (permissions?).");
  }
  if (IsSrtmHeightFileName(path))
  {
    return ReadSrtmTileInfo(path, memoryBudget);
  }
  auto in = Open(path, memoryBudget);
  ImageFileInfo info;
  try
  {
    info = CheckSpec(path, in->spec(), memoryBudget);
  }
  catch (const ImageFileError&)
  {
    Close(*in);
    throw;
  }
  info.FormatName = in->format_name();
  Close(*in);
  if (info.FormatName == "tiff")
  {
    if (const std::optional<double> noData = ReadTiffNoDataTag(path))
    {
      info.HasNoDataValue = true;
      info.NoDataValue = *noData;
    }
    if (const std::optional<GeoPixelSize> pixel = ReadGeoTiffPixelSize(path, info.Height))
    {
      info.HasPixelSize = true;
      info.PixelSizeX = pixel->X;
      info.PixelSizeY = pixel->Y;
      info.HasElevationUnit = pixel->HasVerticalUnit;
      info.ElevationUnit = pixel->VerticalUnit;
    }
  }
  return info;
}

//------------------------------------------------------------------------------
bool ReadImageFilePixels(const std::string& path, const ImageFileInfo& info, void* pixels,
  const std::function<bool(float)>& progress, std::string* warning)
{
  if (warning)
  {
    warning->clear();
  }
  if (IsSrtmHeightFileName(path))
  {
    const ImageFileInfo now = ReadSrtmTileInfo(path, 0);
    if (now.Width != info.Width || now.Height != info.Height || now.Type != info.Type ||
      now.Channels != info.Channels || !pixels)
    {
      Refuse(ImageFileStatus::FileFormat,
        "Cannot read image '" + path + "': the file changed while it was read.");
    }
    std::string error;
    if (!ReadSrtmTile(path, info.Width, static_cast<std::int16_t*>(pixels), error, progress))
    {
      if (error.empty())
      {
        return false; // stopped
      }
      Refuse(ImageFileStatus::FileFormat,
        "Cannot read the pixels of image '" + path + "': " + error + ".");
    }
    return true;
  }
  auto in = Open(path, 0);
  // The file may have changed since its header was read: never write past `pixels`.
  bool changed = true;
  try
  {
    const ImageFileInfo now = CheckSpec(path, in->spec(), 0);
    changed = now.Width != info.Width || now.Height != info.Height ||
      now.Orientation != info.Orientation || now.Channels != info.Channels || now.Type != info.Type;
  }
  catch (const ImageFileError&)
  {
  }
  if (changed || info.Width <= 0 || info.Height <= 0 || !pixels)
  {
    Close(*in);
    Refuse(ImageFileStatus::FileFormat,
      "Cannot read image '" + path + "': the file changed while it was read.");
  }
  const OIIO::TypeDesc format = info.Type == ImageSampleType::UInt8 ? OIIO::TypeDesc::UINT8
    : info.Type == ImageSampleType::UInt16                          ? OIIO::TypeDesc::UINT16
    : info.Type == ImageSampleType::Int16                           ? OIIO::TypeDesc::INT16
    : info.Type == ImageSampleType::UInt32                          ? OIIO::TypeDesc::UINT32
    : info.Type == ImageSampleType::Int32                           ? OIIO::TypeDesc::INT32
                                                                    : OIIO::TypeDesc::FLOAT;
  // File rows are top first, VTK rows bottom first: start at the last row and walk backwards
  // with a negative scanline stride. A turned or mirrored file (Orientation) is read as stored,
  // top first, and then placed as shown.
  const std::size_t pixelBytes = static_cast<std::size_t>(info.Channels) * info.SampleSize();
  const bool turned = info.Orientation >= 5;
  const int storedWidth = turned ? info.Height : info.Width;
  std::vector<unsigned char> stored(info.Orientation != 1 ? info.ByteSize() : 0);
  const OIIO::stride_t rowBytes =
    static_cast<OIIO::stride_t>(storedWidth) * static_cast<OIIO::stride_t>(pixelBytes);
  unsigned char* firstRow = info.Orientation != 1
    ? stored.data()
    : static_cast<unsigned char*>(pixels) + static_cast<std::size_t>(rowBytes) * (info.Height - 1);
  bool stopped = false;
  const std::function<bool(float)> watch = [&](float portion)
  { return stopped = progress && progress(portion); };
  const bool ok = in->read_image(0, 0, 0, info.Channels, format, firstRow, OIIO::AutoStride,
    info.Orientation != 1 ? rowBytes : -rowBytes, OIIO::AutoStride, &ProgressTrampoline,
    const_cast<std::function<bool(float)>*>(&watch));
  if (ok && info.Orientation != 1)
  {
    unsigned char* out = static_cast<unsigned char*>(pixels);
    for (int y = 0; y < info.Height; ++y) // shown rows, top first
    {
      unsigned char* row =
        out + static_cast<std::size_t>(info.Height - 1 - y) * info.Width * pixelBytes;
      for (int x = 0; x < info.Width; ++x)
      {
        int sx = 0, sy = 0;
        StoredPixel(info.Orientation, x, y, info.Width, info.Height, sx, sy);
        std::memcpy(row + static_cast<std::size_t>(x) * pixelBytes,
          &stored[(static_cast<std::size_t>(sy) * storedWidth + sx) * pixelBytes], pixelBytes);
      }
    }
  }
  const std::string decoderMessage = in->geterror();
  const std::string oiioError = OneLineMessage(decoderMessage);
  Close(*in);
  if (stopped)
  {
    return false;
  }
  if (!ok)
  {
    Refuse(ImageFileStatus::FileFormat,
      "Cannot read the pixels of image '" + path +
        "': the file is truncated or corrupt (OpenImageIO: " + oiioError + ").");
  }
  if (warning && !decoderMessage.empty())
  {
    const bool stop = !oiioError.empty() && oiioError.back() == '.';
    *warning = "Image '" + path + "' was read, but its decoder reported a problem: " + oiioError +
      (stop ? " " : ". ") + "Part of it may be missing or wrong (a truncated file's last rows).";
  }
  return true;
}

//------------------------------------------------------------------------------
bool CanReadImageFile(const std::string& path)
{
  if (path.empty())
  {
    return false;
  }
  std::error_code ec;
  if (!fs::is_regular_file(fs::path(path), ec))
  {
    return false;
  }
  if (IsSrtmHeightFileName(path))
  {
    return SrtmTileSide(static_cast<std::uint64_t>(fs::file_size(fs::path(path), ec))) > 0 && !ec;
  }
  const OIIO::ImageSpec config = ReadConfig();
  auto in = OIIO::ImageInput::open(path, &config);
  if (!in)
  {
    OIIO::geterror(); // clear the pending message
    return false;
  }
  const OIIO::ImageSpec& spec = in->spec();
  const bool ok = spec.width > 0 && spec.height > 0 && spec.nchannels > 0;
  Close(*in);
  return ok;
}

//------------------------------------------------------------------------------
std::size_t CountNonFiniteSamples(const float* samples, std::size_t count)
{
  std::size_t bad = 0;
  for (std::size_t i = 0; i < count; ++i)
  {
    bad += std::isfinite(samples[i]) ? 0 : 1;
  }
  return bad;
}

} // namespace mesolight
