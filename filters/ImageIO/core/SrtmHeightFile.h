// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SrtmHeightFile.h
 * @brief SRTM height tiles (`.hgt`), which OpenImageIO does not read (plain C++17).
 *
 * The tiles of the Shuttle Radar Topography Mission (and the DEMs distributed in its layout) are
 * headerless: N x N signed 16-bit heights in metres, big-endian, the northernmost row first, -32768
 * where there is no measurement (a void). N is 1201 (3 arc-seconds) or 3601 (1 arc-second); the
 * file's size is its only header, so a file named `.hgt` is read when its size is 2 N^2 bytes for
 * some N >= 2, and refused with the sizes expected otherwise.
 */
#ifndef mesolight_SrtmHeightFile_h
#define mesolight_SrtmHeightFile_h

#include "MesolightImageIOModule.h" // for the export macro

#include <cstdint>
#include <functional>
#include <optional>
#include <string>

namespace mesolight
{

/** The height SRTM stores where there is no measurement (a void). */
constexpr std::int16_t SrtmVoidHeight = -32768;

/** True when `path`'s extension is `.hgt` (any case). */
MESOLIGHTIMAGEIO_EXPORT bool IsSrtmHeightFileName(const std::string& path);

/** The latitude of the tile's southern edge from its file name (N45E006.hgt: 45, S12W077.hgt:
 *  -12), or none when the name is not a tile's. */
MESOLIGHTIMAGEIO_EXPORT std::optional<double> SrtmTileSouthLatitude(const std::string& path);

/** N when `bytes` is the size of an N x N tile (2 N^2 bytes, N >= 2), else 0. */
MESOLIGHTIMAGEIO_EXPORT int SrtmTileSide(std::uint64_t bytes);

/**
 * Reads the `side` x `side` heights of the tile `path` into `heights`, bottom row first (VTK's
 * order), in the machine's byte order. progress(portion done) may return true to stop: then
 * returns false. Returns false as well, with `error` set, when the file cannot be read whole (it
 * changed size, or cannot be opened).
 */
MESOLIGHTIMAGEIO_EXPORT bool ReadSrtmTile(const std::string& path, int side, std::int16_t* heights,
  std::string& error, const std::function<bool(float)>& progress = {});

} // namespace mesolight

#endif
