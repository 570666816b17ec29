// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TiffNoDataTag.h
 * @brief The no-data value a GeoTIFF names in GDAL's GDAL_NODATA tag (plain C++17).
 *
 * Elevation maps (DEMs) written by GDAL mark the pixels without a measurement with one value
 * (-32768, -9999, NaN...) and name it in the private TIFF tag 42113, GDAL_NODATA, as ASCII text.
 * OpenImageIO does not pass that tag on, so this reads it from the first image file directory
 * itself: classic and BigTIFF, either byte order. Anything it cannot follow (not a TIFF, offsets
 * past the end, a tag of another type, text that is not a number) gives no value: the tag is a
 * convenience, the pixels are read and checked elsewhere (ImageFile.h).
 */
#ifndef mesolight_TiffNoDataTag_h
#define mesolight_TiffNoDataTag_h

#include "MesolightImageIOModule.h" // for the export macro

#include <cstddef>
#include <optional>
#include <string>

namespace mesolight
{

/** TIFF tag number of GDAL's no-data value (ASCII). */
constexpr unsigned TiffTagGdalNoData = 42113;

/** The value of GDAL_NODATA in the first directory of the TIFF bytes `data` (`size` bytes),
 *  if there is one that parses as a number ("nan" included). */
MESOLIGHTIMAGEIO_EXPORT std::optional<double> ParseTiffNoDataTag(
  const unsigned char* data, std::size_t size);

/** The same for the file `path`. */
MESOLIGHTIMAGEIO_EXPORT std::optional<double> ReadTiffNoDataTag(const std::string& path);

} // namespace mesolight

#endif
