// SPDX-License-Identifier: BSD-3-Clause
// Test helper: gives a TIFF written by OpenImageIO (which writes no GDAL tags) GDAL's no-data
// tag, as GDAL writes it in a DEM. The first directory is rewritten at the end of the file with
// tag 42113 (ASCII) in its sorted place; everything else stays where it was. Classic TIFF,
// either byte order (tests/cli/AddGdalNoData.py does the same for the tool's tests).
#ifndef GdalNoDataTagWriter_h
#define GdalNoDataTagWriter_h

#include <algorithm>
#include <cstdint>
#include <fstream>
#include <iterator>
#include <string>
#include <vector>

namespace mesolight_test
{

/// Adds GDAL_NODATA = `value` (written as given) to the TIFF file `path`; false if it is not a
/// classic TIFF.
inline bool AddGdalNoDataTag(const std::string& path, const std::string& value)
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
  const std::uint32_t ifd = get(4, 4);
  const std::uint32_t count = get(ifd, 2);
  std::vector<std::vector<unsigned char>> entries;
  for (std::uint32_t k = 0; k < count; ++k)
  {
    const auto first = data.begin() + ifd + 2 + 12 * k;
    if (get(ifd + 2 + 12 * k, 2) != 42113)
    {
      entries.emplace_back(first, first + 12);
    }
  }
  const std::vector<unsigned char> following(
    data.begin() + ifd + 2 + 12 * count, data.begin() + ifd + 6 + 12 * count);

  std::vector<unsigned char> text(value.begin(), value.end());
  text.push_back(0);
  if (data.size() % 2)
  {
    data.push_back(0);
  }
  const auto newIfd = static_cast<std::uint32_t>(data.size());
  std::vector<unsigned char> entry;
  put(entry, 42113, 2);
  put(entry, 2, 2); // ASCII
  put(entry, static_cast<std::uint32_t>(text.size()), 4);
  if (text.size() <= 4)
  {
    entry.insert(entry.end(), text.begin(), text.end());
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
      const auto tag = [&](const std::vector<unsigned char>& e)
      { return big ? (e[0] << 8 | e[1]) : (e[1] << 8 | e[0]); };
      return tag(a) < tag(b);
    });

  std::vector<unsigned char> directory;
  put(directory, static_cast<std::uint32_t>(entries.size()), 2);
  for (const auto& e : entries)
  {
    directory.insert(directory.end(), e.begin(), e.end());
  }
  directory.insert(directory.end(), following.begin(), following.end());
  if (text.size() > 4)
  {
    directory.insert(directory.end(), text.begin(), text.end());
  }
  data.insert(data.end(), directory.begin(), directory.end());
  std::vector<unsigned char> offset;
  put(offset, newIfd, 4);
  std::copy(offset.begin(), offset.end(), data.begin() + 4);
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(reinterpret_cast<const char*>(data.data()), static_cast<std::streamsize>(data.size()));
  return static_cast<bool>(out);
}

} // namespace mesolight_test

#endif
