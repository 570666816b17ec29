// SPDX-License-Identifier: BSD-3-Clause
#include "GeoTiffTags.h"

#include <algorithm>
#include <charconv>
#include <cmath>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <map>
#include <optional>
#include <string>
#include <vector>

namespace mesolight
{
namespace
{
/// Reads `n` bytes at `offset` into `out`; false when they are not all there.
using ReadAt = std::function<bool(std::uint64_t offset, std::size_t n, unsigned char* out)>;

/// Reads from `size` bytes at `data`.
ReadAt MemoryReader(const unsigned char* data, std::size_t size)
{
  return [data, size](std::uint64_t offset, std::size_t n, unsigned char* out)
  {
    if (!data || offset > size || n > size - offset)
    {
      return false;
    }
    std::memcpy(out, data + offset, n);
    return true;
  };
}

/// The size of the open file `in`, if it opened and is not empty.
std::optional<std::uint64_t> FileSize(std::ifstream& in)
{
  if (!in)
  {
    return std::nullopt;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  return end > 0 ? std::optional<std::uint64_t>(static_cast<std::uint64_t>(end)) : std::nullopt;
}

/// Reads from the open file `in` of `size` bytes.
ReadAt FileReader(std::ifstream& in, std::uint64_t size)
{
  return [&in, size](std::uint64_t offset, std::size_t n, unsigned char* out)
  {
    if (offset > size || n > size - offset)
    {
      return false;
    }
    in.clear();
    in.seekg(static_cast<std::streamoff>(offset));
    return static_cast<bool>(
      in.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n)));
  };
}

/// An unsigned integer of `n` bytes (2, 4 or 8) in the file's byte order.
std::uint64_t Unsigned(const unsigned char* bytes, std::size_t n, bool bigEndian)
{
  std::uint64_t v = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const std::size_t k = bigEndian ? i : n - 1 - i;
    v = (v << 8) | bytes[k];
  }
  return v;
}

/// GDAL writes the value as text ("-32768", "-9999", "nan", "-3.4028234663852886e+38").
std::optional<double> ParseNumber(const std::vector<unsigned char>& text)
{
  std::string s(text.begin(), text.end());
  s = s.substr(0, s.find('\0'));
  const auto first = s.find_first_not_of(" \t\r\n");
  if (first == std::string::npos)
  {
    return std::nullopt;
  }
  s = s.substr(first, s.find_last_not_of(" \t\r\n") - first + 1);
  // from_chars, not strtod: the text is C-locale whatever the process's locale (a GUI in a
  // decimal-comma locale would stop strtod at "-9999.9"'s point). It takes no leading '+'.
  const char* begin = s.c_str() + (s[0] == '+' ? 1 : 0);
  const char* end = s.c_str() + s.size();
  double v = 0.0;
  const std::from_chars_result parsed = std::from_chars(begin, end, v);
  if (parsed.ec != std::errc() || parsed.ptr != end)
  {
    return std::nullopt;
  }
  return v;
}

/// A tag's raw value: its TIFF type, count and bytes (in the file's byte order).
struct TagValue
{
  std::uint64_t Type = 0;
  std::uint64_t Count = 0;
  std::vector<unsigned char> Bytes;
};

/// The tags `wanted` of the first image file directory, those present and readable whole (at most
/// `maxBytes` each), with the file's byte order; empty when it is no TIFF.
std::map<unsigned, TagValue> FindTags(
  const ReadAt& read, const std::vector<unsigned>& wanted, std::size_t maxBytes, bool& bigEndian)
{
  std::map<unsigned, TagValue> found;
  // Header: byte order, 42 (classic) or 43 (BigTIFF), the first directory's offset.
  unsigned char header[16];
  if (!read(0, 8, header))
  {
    return found;
  }
  bigEndian = false;
  if (header[0] == 'M' && header[1] == 'M')
  {
    bigEndian = true;
  }
  else if (!(header[0] == 'I' && header[1] == 'I'))
  {
    return found;
  }
  const std::uint64_t version = Unsigned(header + 2, 2, bigEndian);
  const bool bigTiff = version == 43;
  if (version != 42 && !bigTiff)
  {
    return found;
  }
  std::uint64_t directory = 0;
  if (bigTiff)
  {
    if (!read(0, 16, header) || Unsigned(header + 4, 2, bigEndian) != 8)
    {
      return found;
    }
    directory = Unsigned(header + 8, 8, bigEndian);
  }
  else
  {
    directory = Unsigned(header + 4, 4, bigEndian);
  }

  // Directory: an entry count, then entries of tag, type, count and value (or its offset).
  const std::size_t countSize = bigTiff ? 8 : 2;
  const std::size_t entrySize = bigTiff ? 20 : 12;
  const std::size_t inlineSize = bigTiff ? 8 : 4;
  unsigned char countBytes[8];
  if (!read(directory, countSize, countBytes))
  {
    return found;
  }
  const std::uint64_t entries = Unsigned(countBytes, countSize, bigEndian);
  // A real directory holds a few dozen entries; the cap bounds the work on a corrupt count.
  constexpr std::uint64_t maxEntries = 4096;
  for (std::uint64_t e = 0; e < std::min(entries, maxEntries); ++e)
  {
    unsigned char entry[20];
    if (!read(directory + countSize + e * entrySize, entrySize, entry))
    {
      return found;
    }
    const auto tag = static_cast<unsigned>(Unsigned(entry, 2, bigEndian));
    if (std::find(wanted.begin(), wanted.end(), tag) == wanted.end() || found.count(tag))
    {
      continue;
    }
    TagValue value;
    value.Type = Unsigned(entry + 2, 2, bigEndian);
    value.Count = Unsigned(entry + 4, bigTiff ? 8 : 4, bigEndian);
    // Bytes per value of the types read here: ASCII 2, SHORT 3, DOUBLE 12.
    const std::uint64_t size = value.Type == 2 ? 1 : value.Type == 3 ? 2 : value.Type == 12 ? 8 : 0;
    if (size == 0 || value.Count == 0 || value.Count > maxBytes / size)
    {
      continue;
    }
    value.Bytes.resize(static_cast<std::size_t>(value.Count * size));
    const unsigned char* field = entry + (bigTiff ? 12 : 8);
    if (value.Bytes.size() <= inlineSize)
    {
      std::memcpy(value.Bytes.data(), field, value.Bytes.size());
    }
    else if (!read(Unsigned(field, inlineSize, bigEndian), value.Bytes.size(), value.Bytes.data()))
    {
      continue;
    }
    found[tag] = std::move(value);
  }
  return found;
}

std::optional<double> FindNoDataTag(const ReadAt& read)
{
  bool bigEndian = false;
  constexpr std::size_t maxText = 256; // a number, written as text
  const auto tags = FindTags(read, { TiffTagGdalNoData }, maxText, bigEndian);
  const auto it = tags.find(TiffTagGdalNoData);
  if (it == tags.end() || it->second.Type != 2)
  {
    return std::nullopt;
  }
  return ParseNumber(it->second.Bytes);
}

/// The `count` values of a SHORT or DOUBLE tag, as doubles.
std::vector<double> Numbers(const TagValue& value, bool bigEndian)
{
  std::vector<double> numbers;
  const std::size_t size = value.Type == 3 ? 2 : 8;
  for (std::size_t k = 0; k + size <= value.Bytes.size(); k += size)
  {
    const std::uint64_t bits = Unsigned(value.Bytes.data() + k, size, bigEndian);
    if (size == 2)
    {
      numbers.push_back(static_cast<double>(bits));
    }
    else
    {
      double d = 0.0;
      std::memcpy(&d, &bits, sizeof d);
      numbers.push_back(d);
    }
  }
  return numbers;
}

// GeoTIFF 1.0 (OGC 19-008r4): tags and the keys of the GeoKeyDirectory read here.
constexpr unsigned ModelPixelScaleTag = 33550;
constexpr unsigned ModelTiepointTag = 33922;
constexpr unsigned ModelTransformationTag = 34264;
constexpr unsigned GeoKeyDirectoryTag = 34735;
constexpr unsigned GTModelTypeGeoKey = 1024; // 1 projected, 2 geographic
constexpr unsigned GeogAngularUnitsGeoKey = 2054;
constexpr unsigned ProjLinearUnitsGeoKey = 3076;
constexpr unsigned VerticalUnitsGeoKey = 4099;

// Metres per unit of an EPSG linear unit code: metre, foot, US survey foot; 0 for others.
double MetresPerLinearUnit(double code)
{
  return code == 9001 ? 1.0 : code == 9002 ? 0.3048 : code == 9003 ? 1200.0 / 3937.0 : 0.0;
}

std::optional<GeoPixelSize> FindPixelSize(const ReadAt& read, int height)
{
  bool bigEndian = false;
  const auto tags = FindTags(read,
    { ModelPixelScaleTag, ModelTiepointTag, ModelTransformationTag, GeoKeyDirectoryTag }, 1 << 16,
    bigEndian);
  auto numbers = [&](unsigned tag, std::uint64_t type)
  {
    const auto it = tags.find(tag);
    return it == tags.end() || it->second.Type != type ? std::vector<double>()
                                                       : Numbers(it->second, bigEndian);
  };
  // The keys: a header (version, revision, minor, key count), then (key, location, count, value)
  // each; a value held in the directory itself has location 0.
  const std::vector<double> keys = numbers(GeoKeyDirectoryTag, 3);
  auto key = [&](unsigned id) -> std::optional<double>
  {
    for (std::size_t k = 4; k + 3 < keys.size(); k += 4)
    {
      if (keys[k] == id && keys[k + 1] == 0 && keys[k + 2] == 1)
      {
        return keys[k + 3];
      }
    }
    return std::nullopt;
  };
  const std::optional<double> modelType = key(GTModelTypeGeoKey);
  if (keys.size() < 4 || !modelType || (*modelType != 1 && *modelType != 2))
  {
    return std::nullopt; // no model, or a geocentric or user-defined one
  }
  // A pixel's size in model units: the pixel scale, or the lengths of the transformation's
  // columns (a rotated raster).
  double sx = 0.0, sy = 0.0;
  const std::vector<double> scale = numbers(ModelPixelScaleTag, 12);
  const std::vector<double> matrix = numbers(ModelTransformationTag, 12);
  const std::vector<double> tiepoint = numbers(ModelTiepointTag, 12);
  // The model y of the raster's middle row: a latitude, for a geographic model (rows run south).
  double middleY = 0.0;
  const double rows = std::max(height, 1);
  if (scale.size() >= 2)
  {
    sx = std::abs(scale[0]);
    sy = std::abs(scale[1]);
    if (tiepoint.size() >= 6)
    {
      middleY = tiepoint[4] - (0.5 * rows - tiepoint[1]) * sy;
    }
  }
  else if (matrix.size() >= 16)
  {
    sx = std::hypot(matrix[0], matrix[4]);
    sy = std::hypot(matrix[1], matrix[5]);
    middleY = matrix[7] + 0.5 * rows * matrix[5];
  }
  if (!(sx > 0.0 && sy > 0.0 && std::isfinite(sx) && std::isfinite(sy)))
  {
    return std::nullopt;
  }
  std::optional<GeoPixelSize> size;
  if (*modelType == 1)
  {
    // Projected: metres, unless the linear unit is a foot (EPSG 9002, 9003).
    const double metres = MetresPerLinearUnit(key(ProjLinearUnitsGeoKey).value_or(9001.0));
    if (metres == 0.0)
    {
      return std::nullopt;
    }
    size = GeoPixelSize{ sx * metres, sy * metres, false };
  }
  // Geographic: degrees (EPSG 9102, the default), at the raster's middle latitude.
  else if (key(GeogAngularUnitsGeoKey).value_or(9102.0) != 9102.0 ||
    (tiepoint.size() < 6 && matrix.size() < 16))
  {
    return std::nullopt;
  }
  else
  {
    size = GeographicPixelSize(sx, sy, middleY);
  }
  if (size)
  {
    if (const std::optional<double> vertical = key(VerticalUnitsGeoKey))
    {
      size->HasVerticalUnit = true;
      size->VerticalUnit = MetresPerLinearUnit(*vertical);
    }
  }
  return size;
}
} // namespace

//------------------------------------------------------------------------------
std::optional<double> ParseTiffNoDataTag(const unsigned char* data, std::size_t size)
{
  return FindNoDataTag(MemoryReader(data, size));
}

//------------------------------------------------------------------------------
std::optional<double> ReadTiffNoDataTag(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  const std::optional<std::uint64_t> size = FileSize(in);
  return size ? FindNoDataTag(FileReader(in, *size)) : std::nullopt;
}

//------------------------------------------------------------------------------
std::optional<GeoPixelSize> GeographicPixelSize(double degreesX, double degreesY, double latitude)
{
  // A sphere of the Earth's mean radius (IUGG): within 0.5% of the ellipsoid's lengths.
  constexpr double pi = 3.14159265358979323846;
  constexpr double metresPerDegree = 6371008.8 * pi / 180.0;
  if (!(degreesX > 0.0 && degreesY > 0.0 && std::isfinite(degreesX) && std::isfinite(degreesY) &&
        std::abs(latitude) < 90.0))
  {
    return std::nullopt;
  }
  return GeoPixelSize{ degreesX * metresPerDegree * std::cos(latitude * pi / 180.0),
    degreesY * metresPerDegree, true };
}

//------------------------------------------------------------------------------
std::optional<GeoPixelSize> ParseGeoTiffPixelSize(
  const unsigned char* data, std::size_t size, int height)
{
  return FindPixelSize(MemoryReader(data, size), height);
}

//------------------------------------------------------------------------------
std::optional<GeoPixelSize> ReadGeoTiffPixelSize(const std::string& path, int height)
{
  std::ifstream in(path, std::ios::binary);
  const std::optional<std::uint64_t> size = FileSize(in);
  return size ? FindPixelSize(FileReader(in, *size), height) : std::nullopt;
}

} // namespace mesolight
