// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkOIIOImageReader
 * @brief   read any image format supported by OpenImageIO into vtkImageData
 *
 * vtkOIIOImageReader reads 8/16-bit PNG and TIFF, OpenEXR, Radiance HDR, JPEG and every
 * other format OpenImageIO supports. Pixel types: uint8 -> VTK_UNSIGNED_CHAR,
 * uint16 -> VTK_UNSIGNED_SHORT, int16 -> VTK_SHORT, uint32 -> VTK_UNSIGNED_INT, int32 -> VTK_INT
 * (elevation maps: metres and GDAL's no-data value as stored), anything else (half, float,
 * double, 8- and 64-bit signed integers) -> VTK_FLOAT (OpenImageIO's conversion: integers
 * become [0,1]). All channels are kept
 * (1 to 4; only the first 4 of more, with a warning). Alpha is read as stored, never
 * premultiplied, since Mesolight's relief textures keep the depth in A.
 *
 * Files store the top row first; VTK images start with the bottom row, so rows are
 * flipped: file row 0 becomes image row H-1. The output has origin (0,0,0), spacing
 * (1,1,1), extent [0, W-1, 0, H-1, 0, 0] and point scalars named "ImageScalars".
 *
 * The checks (mesolight::ReadImageFileInfo, core/ImageFile.h) refuse missing, empty, corrupt,
 * zero-sized and volume images and pixels beyond MemoryBudget before allocating them. NaN and
 * infinite float values are read as stored (geometry images mark holes with NaN) and counted:
 * GetNumberOfNonFiniteValues().
 *
 * A GeoTIFF that names a no-data value in GDAL's GDAL_NODATA tag (elevation maps written by
 * GDAL: -32768, -9999, NaN...) gives it as GetNoDataValue() and as the output's field data array
 * "MesolightNoDataValue" (one double), which vtkReliefTextureFilter applies by default
 * (OpenImageIO does not pass the tag on; mesolight::ReadTiffNoDataTag reads it). An SRTM height
 * tile (.hgt, which OpenImageIO does not read) is read as int16 metres with its voids, -32768, as
 * that value.
 *
 * A georeferenced file (GeoTIFF tags; an SRTM tile's name) gives a pixel's size on the ground in
 * metres, GetPixelSize(), and the field data array "MesolightPixelSize" (two doubles: along rows,
 * along columns), from which vtkReliefTextureFilter derives the depth scale of the true vertical
 * scale. The output's spacing stays 1.
 *
 * Failures report vtkErrorMacro messages with the file name and OpenImageIO's error text,
 * set ErrorCode (vtkErrorCode::NoFileNameError, FileNotFoundError, CannotOpenFileError,
 * UnrecognizedFileTypeError, FileFormatError) and produce an empty image.
 */
#ifndef vtkOIIOImageReader_h
#define vtkOIIOImageReader_h

#include "MesolightImageIOModule.h" // For export macro
#include "vtkImageAlgorithm.h"

#include <string> // For std::string

namespace mesolight
{
struct ImageFileInfo;
}

class MESOLIGHTIMAGEIO_EXPORT vtkOIIOImageReader : public vtkImageAlgorithm
{
public:
  static vtkOIIOImageReader* New();
  vtkTypeMacro(vtkOIIOImageReader, vtkImageAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Name of the file to read.
   */
  vtkSetStringMacro(FileName);
  vtkGetStringMacro(FileName);
  ///@}

  /**
   * True if fileName is an existing regular file that OpenImageIO can open as an image.
   */
  static bool CanReadFile(const char* fileName);

  ///@{
  /**
   * Bytes the pixels may take (0, the default: the machine's memory, the cgroup limit when one
   * is set). A larger image is refused before anything is allocated, with the size it needs.
   */
  vtkSetMacro(MemoryBudget, vtkTypeInt64);
  vtkGetMacro(MemoryBudget, vtkTypeInt64);
  ///@}

  ///@{
  /**
   * Information about the last file read (valid after UpdateInformation()): width, height,
   * number of channels in the file and the name of the OpenImageIO format ("png", ...).
   */
  vtkGetVector2Macro(ImageSize, int);
  vtkGetMacro(NumberOfChannelsInFile, int);
  /** NaN or infinite values in the pixels last read (float images only; valid after Update()). */
  vtkGetMacro(NumberOfNonFiniteValues, vtkIdType);
  const char* GetFormatName() const { return this->FormatName.c_str(); }
  ///@}

  ///@{
  /**
   * Whether the last file read names a no-data value (a GeoTIFF's GDAL_NODATA tag), and the
   * value, in the file's stored units (valid after UpdateInformation()).
   */
  vtkGetMacro(HasNoDataValue, bool);
  vtkGetMacro(NoDataValue, double);
  ///@}

  ///@{
  /**
   * Whether the last file read is georeferenced, and a pixel's size on the ground in metres along
   * its rows and columns (valid after UpdateInformation()). Degrees of a geographic raster are
   * converted at its middle latitude (mesolight::GeographicPixelSize).
   */
  vtkGetMacro(HasPixelSize, bool);
  vtkGetVector2Macro(PixelSize, double);
  ///@}

  ///@{
  /**
   * Whether the last file read names its values' unit (a GeoTIFF's VerticalUnitsGeoKey), and
   * how many metres one is (1, or 0.3048 for feet; 0 for a unit that is neither). Also the field
   * data array "MesolightElevationUnit", which vtkReliefTextureFilter's true vertical scale uses.
   * Without it, elevations are taken to be in metres.
   */
  vtkGetMacro(HasElevationUnit, bool);
  vtkGetMacro(ElevationUnit, double);
  ///@}

protected:
  vtkOIIOImageReader();
  ~vtkOIIOImageReader() override;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  char* FileName = nullptr;
  int ImageSize[2] = { 0, 0 };
  int NumberOfChannelsInFile = 0;
  std::string FormatName;
  vtkTypeInt64 MemoryBudget = 0;
  vtkIdType NumberOfNonFiniteValues = 0;
  bool HasNoDataValue = false;
  double NoDataValue = 0.0;
  bool HasPixelSize = false;
  double PixelSize[2] = { 0.0, 0.0 };
  bool HasElevationUnit = false;
  double ElevationUnit = 1.0;

private:
  vtkOIIOImageReader(const vtkOIIOImageReader&) = delete;
  void operator=(const vtkOIIOImageReader&) = delete;

  bool ReadHeader(mesolight::ImageFileInfo& header);
};

#endif
