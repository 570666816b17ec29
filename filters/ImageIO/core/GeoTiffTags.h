// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file GeoTiffTags.h
 * @brief What a GeoTIFF says of its pixels beyond their values: the no-data value GDAL names in
 * its GDAL_NODATA tag, and a pixel's size on the ground from the GeoTIFF tags (plain C++17).
 *
 * Elevation maps (DEMs) written by GDAL mark the pixels without a measurement with one value
 * (-32768, -9999, NaN...) and name it in the private TIFF tag 42113, GDAL_NODATA, as ASCII text.
 * OpenImageIO does not pass that tag on, so this reads it from the first image file directory
 * itself: classic and BigTIFF, either byte order. Anything it cannot follow (not a TIFF, offsets
 * past the end, a tag of another type, text that is not a number) gives no value: the tag is a
 * convenience, the pixels are read and checked elsewhere (ImageFile.h).
 */
#ifndef mesolight_GeoTiffTags_h
#define mesolight_GeoTiffTags_h

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

/** A pixel's size on the ground, in metres, along the raster's rows (X) and columns (Y). */
struct GeoPixelSize
{
  double X = 0.0;
  double Y = 0.0;
  bool Geographic = false; ///< from degrees of longitude and latitude (else a projection's units)
  /** Metres per unit of the raster's values where the file names their unit
   *  (VerticalUnitsGeoKey: metres 1, feet 0.3048, US survey feet 1200 / 3937); 0 for a unit it
   *  names but that is not one of those. Without the key the values' unit is not known (GDAL
   *  writes it only for a vertical datum): metres are the usual one. */
  bool HasVerticalUnit = false;
  double VerticalUnit = 1.0;
};

/**
 * A pixel's size from the GeoTIFF tags of the TIFF bytes `data` (GeoTIFF 1.0, OGC 19-008r4): the
 * ModelPixelScaleTag (or the lengths of the ModelTransformationTag's columns, for a rotated
 * raster) in the model's units. A projected model (GTModelTypeGeoKey 1) gives metres, or feet
 * (ProjLinearUnitsGeoKey 9002, 9003) converted to metres; a geographic one (2) gives degrees,
 * converted at the raster's middle latitude (from the tie point and `height`, the raster's rows)
 * by GeographicPixelSize. Anything else (no GeoKeyDirectory, a geocentric or user-defined model,
 * other units, a corrupt tag) gives no size. The values' unit, where VerticalUnitsGeoKey names
 * it, comes with the size (GeoPixelSize::VerticalUnit).
 */
MESOLIGHTIMAGEIO_EXPORT std::optional<GeoPixelSize> ParseGeoTiffPixelSize(
  const unsigned char* data, std::size_t size, int height);

/** The same for the file `path`. */
MESOLIGHTIMAGEIO_EXPORT std::optional<GeoPixelSize> ReadGeoTiffPixelSize(
  const std::string& path, int height);

/** Degrees of longitude and latitude at `latitude` to metres, on a sphere of the Earth's mean
 *  radius (6371008.8 m; within 0.5% of the ellipsoid's lengths); none at or beyond a pole. */
MESOLIGHTIMAGEIO_EXPORT std::optional<GeoPixelSize> GeographicPixelSize(
  double degreesX, double degreesY, double latitude);

} // namespace mesolight

#endif
