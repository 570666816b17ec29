// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ImageFile.h
 * @brief Opening an image file through OpenImageIO (SRTM height tiles, `.hgt`, without it) and
 * refusing bad ones (plain C++17).
 *
 * What vtkOIIOImageReader (and so every image the `mesolight` tool reads: depth maps,
 * photographs, environments, masks) does before and while reading pixels, without VTK types, so
 * that unit tests and the `image_file` fuzz target (fuzz/image_file.cxx) reach every check:
 * a missing, unreadable, empty or directory path; a file OpenImageIO cannot open (corrupt, or of
 * no known type); a zero-sized image or one without channels; a volume (depth > 1); pixels whose
 * size exceeds the memory budget, refused before anything is allocated; a file that changed
 * between the header and the pixels; truncated pixel data. Each refusal throws ImageFileError: its
 * reason (which vtkOIIOImageReader maps to a vtkErrorCode) and one sentence naming the file.
 */
#ifndef mesolight_ImageFile_h
#define mesolight_ImageFile_h

#include "MesolightImageIOModule.h" // for the export macro

#include <cstddef>
#include <cstdint>
#include <functional>
#include <stdexcept>
#include <string>

namespace mesolight
{

/** How samples are read: 8-, 16- and 32-bit integer files stay integers (signed ones too:
 *  elevation maps keep their metres and their no-data value), everything else becomes float. */
enum class ImageSampleType
{
  UInt8,
  UInt16,
  Int16,
  UInt32,
  Int32,
  Float
};

/** Why a file was refused (ImageFileError::GetReason; vtkOIIOImageReader maps these to
 *  vtkErrorCode values). */
enum class ImageFileStatus
{
  NoFileName,
  FileNotFound,
  CannotOpen,       // a directory, no permission
  UnrecognizedType, // OpenImageIO knows neither the extension nor the contents
  FileFormat,       // corrupt, zero-sized, a volume, truncated, changed while reading
  TooLarge          // the pixels would exceed the memory budget
};

/** A refused file; what() is one sentence for the user that names the file. */
class MESOLIGHTIMAGEIO_EXPORT ImageFileError : public std::runtime_error
{
public:
  ImageFileError(ImageFileStatus reason, const std::string& message)
    : std::runtime_error(message)
    , Reason(reason)
  {
  }
  ImageFileStatus GetReason() const { return this->Reason; }

private:
  ImageFileStatus Reason;
};

/** What the header says, as it will be read. */
struct MESOLIGHTIMAGEIO_EXPORT ImageFileInfo
{
  int Width = 0;
  int Height = 0;
  int FileChannels = 0; // channels in the file
  int Channels = 0;     // channels read: min(FileChannels, 4)
  ImageSampleType Type = ImageSampleType::Float;
  std::string FormatName; // OpenImageIO's name: "png", "openexr", ...
  /** The file's EXIF/TIFF orientation (1-8; 1: stored as shown). Width and Height are the image
   *  as shown (swapped from the stored ones for 5-8), and the pixels are read turned that way,
   *  as every viewer shows a photograph taken with the camera turned. */
  int Orientation = 1;
  /** The value a GeoTIFF names for pixels without data (GDAL_NODATA, GeoTiffTags.h). */
  bool HasNoDataValue = false;
  double NoDataValue = 0.0;
  /** A pixel's size on the ground in metres, along rows (X) and columns (Y), where the file is
   *  georeferenced (GeoTIFF tags, GeoTiffTags.h; an SRTM tile's name, SrtmHeightFile.h). */
  bool HasPixelSize = false;
  double PixelSizeX = 0.0;
  double PixelSizeY = 0.0;
  /** Metres per unit of the pixel values, where a georeferenced file names their unit
   *  (GeoPixelSize::VerticalUnit; 0: a unit that is neither metres nor feet). */
  bool HasElevationUnit = false;
  double ElevationUnit = 1.0;

  /** 1, 2 or 4 bytes. */
  std::size_t SampleSize() const;
  /** Width * Height * Channels * SampleSize(), computed without overflow. */
  std::uint64_t ByteSize() const;
};

/**
 * The checks of a header, as OpenImageIO's ImageSpec gives it (ReadImageFileInfo calls this):
 * refuses a zero size or no channels, a volume (depth > 1), and pixels beyond `memoryBudget`
 * (bytes; 0: the machine's memory); keeps at most 4 channels. Returns the header as it will be
 * read (FormatName empty); throws ImageFileError (FileFormat, TooLarge) when refused.
 */
MESOLIGHTIMAGEIO_EXPORT ImageFileInfo CheckImageHeader(const std::string& path, int width,
  int height, int depth, int channels, ImageSampleType type, std::int64_t memoryBudget);

/**
 * Opens `path` and checks its header. `memoryBudget`: bytes the pixels may take (0: the
 * machine's memory, see EffectiveMemoryBudget). Throws ImageFileError on a refusal, whose
 * what() starts "Cannot read image '<path>'" (or says that no file name was given).
 */
MESOLIGHTIMAGEIO_EXPORT ImageFileInfo ReadImageFileInfo(
  const std::string& path, std::int64_t memoryBudget);

/**
 * Reads the pixels of `path`, whose header `info` is (from ReadImageFileInfo), into `pixels`
 * (info.ByteSize() bytes), bottom row first (VTK's order; files store the top row first),
 * interleaved channels. progress(portion done) may return true to stop: then returns false
 * (the pixels are incomplete), else true. Throws ImageFileError (FileFormat) for a file whose
 * header no longer matches `info` or whose pixels are truncated or corrupt, and as
 * ReadImageFileInfo for a file that no longer opens. A read the decoder finished but complained
 * about (a truncated baseline JPEG: libjpeg fills the missing rows and says "Premature end of
 * JPEG file") sets `warning`, when given, to one line; otherwise it is left empty.
 */
MESOLIGHTIMAGEIO_EXPORT bool ReadImageFilePixels(const std::string& path, const ImageFileInfo& info,
  void* pixels, const std::function<bool(float)>& progress = {}, std::string* warning = nullptr);

/**
 * The header of an SRTM height tile (`.hgt`, SrtmHeightFile.h), which ReadImageFileInfo reads for
 * such a file instead of OpenImageIO: N x N, one Int16 channel, FormatName "srtm-hgt", no-data
 * value -32768. Throws ImageFileError (FileFormat) when the size is not 2 N^2 bytes, and
 * (TooLarge) beyond `memoryBudget`.
 */
MESOLIGHTIMAGEIO_EXPORT ImageFileInfo ReadSrtmTileInfo(
  const std::string& path, std::int64_t memoryBudget);

/** True when `path` is a regular file OpenImageIO opens as a non-empty image (or an SRTM height
 *  tile of a valid size). */
MESOLIGHTIMAGEIO_EXPORT bool CanReadImageFile(const std::string& path);

/** The number of NaN or infinite values among `count` floats. */
MESOLIGHTIMAGEIO_EXPORT std::size_t CountNonFiniteSamples(const float* samples, std::size_t count);

} // namespace mesolight

#endif
