// SPDX-License-Identifier: BSD-3-Clause
// Test helper: gives a TIFF written by OpenImageIO (which writes no GDAL or GeoTIFF tags) the tags
// GDAL writes in a DEM: the no-data value (42113, ASCII) and the GeoTIFF tags (SHORT and DOUBLE
// arrays). The first directory is rewritten at the end of the file with the tag in its sorted
// place (an earlier one of the same number dropped); everything else stays where it was. Classic
// TIFF, either byte order (tests/cli/AddGdalNoData.py does the no-data tag for the tool's tests).
#ifndef TiffTagWriter_h
#define TiffTagWriter_h

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace mesolight_test
{

/// Writes `metres` (w x h, the top row first) as a signed 16-bit TIFF with OpenImageIO, the DEM
/// the tags below are added to; false when it cannot.
inline bool WriteInt16Tiff(
  const std::string& path, int w, int h, const std::vector<std::int16_t>& metres)
{
  auto out = OIIO::ImageOutput::create(path);
  const bool ok = out && out->open(path, OIIO::ImageSpec(w, h, 1, OIIO::TypeDesc::INT16)) &&
    out->write_image(OIIO::TypeDesc::INT16, metres.data()) && out->close();
  OIIO::geterror();
  return ok;
}

/// Adds tag `tag` of TIFF type `type` (2 ASCII, 3 SHORT, 12 DOUBLE) whose `count` values are
/// `value` (bytes in the machine's order for SHORT and DOUBLE, converted to the file's) to the
/// TIFF file `path`; false if it is not a classic TIFF.
inline bool AddTiffTag(const std::string& path, std::uint16_t tag, std::uint16_t type,
  std::uint32_t count, std::vector<unsigned char> value)
{
  std::vector<unsigned char> data;
  {
    std::ifstream in(path, std::ios::binary);
    data.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  if (data.size() < 8 ||
    !((data[0] == 'I' && data[1] == 'I') || (data[0] == 'M' && data[1] == 'M')))
  {
    return false;
  }
  const bool big = data[0] == 'M';
  auto get = [&](std::size_t at, int n)
  {
    std::uint32_t v = 0;
    for (int i = 0; i < n; ++i)
    {
      v = (v << 8) | data[at + (big ? i : n - 1 - i)];
    }
    return v;
  };
  auto put = [&](std::vector<unsigned char>& out, std::uint32_t v, int n)
  {
    for (int i = 0; i < n; ++i)
    {
      out.push_back(static_cast<unsigned char>(v >> (8 * (big ? n - 1 - i : i))));
    }
  };
  if (get(2, 2) != 42)
  {
    return false;
  }
  // SHORT and DOUBLE values in the file's byte order (this machine is little-endian).
  const std::size_t size = type == 3 ? 2 : (type == 12 ? 8 : 1);
  if (big && size > 1)
  {
    for (std::size_t k = 0; k + size <= value.size(); k += size)
    {
      std::reverse(value.begin() + static_cast<std::ptrdiff_t>(k),
        value.begin() + static_cast<std::ptrdiff_t>(k + size));
    }
  }
  const std::uint32_t ifd = get(4, 4);
  const std::uint32_t entryCount = get(ifd, 2);
  std::vector<std::vector<unsigned char>> entries;
  for (std::uint32_t k = 0; k < entryCount; ++k)
  {
    const auto first = data.begin() + ifd + 2 + 12 * k;
    if (get(ifd + 2 + 12 * k, 2) != tag)
    {
      entries.emplace_back(first, first + 12);
    }
  }
  const std::vector<unsigned char> following(
    data.begin() + ifd + 2 + 12 * entryCount, data.begin() + ifd + 6 + 12 * entryCount);

  if (data.size() % 2)
  {
    data.push_back(0);
  }
  const auto newIfd = static_cast<std::uint32_t>(data.size());
  std::vector<unsigned char> entry;
  put(entry, tag, 2);
  put(entry, type, 2);
  put(entry, count, 4);
  if (value.size() <= 4)
  {
    entry.insert(entry.end(), value.begin(), value.end());
    entry.resize(12, 0);
  }
  else
  {
    put(entry, newIfd + 2 + 12 * static_cast<std::uint32_t>(entries.size() + 1) + 4, 4);
  }
  entries.push_back(entry);
  std::sort(entries.begin(), entries.end(),
    [&](const auto& a, const auto& b)
    {
      const auto number = [&](const std::vector<unsigned char>& e)
      { return big ? (e[0] << 8 | e[1]) : (e[1] << 8 | e[0]); };
      return number(a) < number(b);
    });

  std::vector<unsigned char> directory;
  put(directory, static_cast<std::uint32_t>(entries.size()), 2);
  for (const auto& e : entries)
  {
    directory.insert(directory.end(), e.begin(), e.end());
  }
  directory.insert(directory.end(), following.begin(), following.end());
  if (value.size() > 4)
  {
    directory.insert(directory.end(), value.begin(), value.end());
  }
  data.insert(data.end(), directory.begin(), directory.end());
  std::vector<unsigned char> offset;
  put(offset, newIfd, 4);
  std::copy(offset.begin(), offset.end(), data.begin() + 4);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
  return static_cast<bool>(out);
}

/// Adds GDAL_NODATA = `value` (written as given).
inline bool AddGdalNoDataTag(const std::string& path, const std::string& value)
{
  std::vector<unsigned char> text(value.begin(), value.end());
  text.push_back(0);
  return AddTiffTag(path, 42113, 2, static_cast<std::uint32_t>(text.size()), text);
}

/// Adds a SHORT (type 3) or DOUBLE (type 12) array tag.
template <typename T>
inline bool AddTiffArrayTag(
  const std::string& path, std::uint16_t tag, const std::vector<T>& values)
{
  static_assert(sizeof(T) == 2 || sizeof(T) == 8, "SHORT or DOUBLE values");
  std::vector<unsigned char> bytes(values.size() * sizeof(T));
  std::memcpy(bytes.data(), values.data(), bytes.size());
  return AddTiffTag(
    path, tag, sizeof(T) == 2 ? 3 : 12, static_cast<std::uint32_t>(values.size()), bytes);
}

/// A GeoTIFF's georeference, as GDAL writes it: pixel scale, tie point of pixel (0, 0) and the
/// GeoKeyDirectory's keys (id, value), each held in the directory itself.
inline bool AddGeoTiffTags(const std::string& path, double scaleX, double scaleY, double x0,
  double y0, const std::vector<std::pair<std::uint16_t, std::uint16_t>>& keys)
{
  std::vector<std::uint16_t> directory = { 1, 1, 0, static_cast<std::uint16_t>(keys.size()) };
  for (const auto& [id, value] : keys)
  {
    directory.insert(directory.end(), { id, 0, 1, value });
  }
  return AddTiffArrayTag(path, 33550, std::vector<double>{ scaleX, scaleY, 0.0 }) &&
    AddTiffArrayTag(path, 33922, std::vector<double>{ 0.0, 0.0, 0.0, x0, y0, 0.0 }) &&
    AddTiffArrayTag(path, 34735, directory);
}

} // namespace mesolight_test

#endif
