// SPDX-License-Identifier: BSD-3-Clause
#include "TiffNoDataTag.h"

#include <algorithm>
#include <charconv>
#include <cstdint>
#include <cstring>
#include <fstream>
#include <functional>
#include <string>
#include <vector>

namespace mesolight
{
namespace
{
/// Reads `n` bytes at `offset` into `out`; false when they are not all there.
using ReadAt = std::function<bool(std::uint64_t offset, std::size_t n, unsigned char* out)>;

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

std::optional<double> FindNoDataTag(const ReadAt& read)
{
  // Header: byte order, 42 (classic) or 43 (BigTIFF), the first directory's offset.
  unsigned char header[16];
  if (!read(0, 8, header))
  {
    return std::nullopt;
  }
  bool bigEndian = false;
  if (header[0] == 'M' && header[1] == 'M')
  {
    bigEndian = true;
  }
  else if (!(header[0] == 'I' && header[1] == 'I'))
  {
    return std::nullopt;
  }
  const std::uint64_t version = Unsigned(header + 2, 2, bigEndian);
  const bool bigTiff = version == 43;
  if (version != 42 && !bigTiff)
  {
    return std::nullopt;
  }
  std::uint64_t directory = 0;
  if (bigTiff)
  {
    if (!read(0, 16, header) || Unsigned(header + 4, 2, bigEndian) != 8)
    {
      return std::nullopt;
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
    return std::nullopt;
  }
  const std::uint64_t entries = Unsigned(countBytes, countSize, bigEndian);
  // A real directory holds a few dozen entries; the cap bounds the work on a corrupt count.
  constexpr std::uint64_t maxEntries = 4096;
  for (std::uint64_t e = 0; e < std::min(entries, maxEntries); ++e)
  {
    unsigned char entry[20];
    if (!read(directory + countSize + e * entrySize, entrySize, entry))
    {
      return std::nullopt;
    }
    const std::uint64_t tag = Unsigned(entry, 2, bigEndian);
    if (tag != TiffTagGdalNoData)
    {
      continue;
    }
    constexpr std::uint64_t asciiType = 2;
    const std::uint64_t count = Unsigned(entry + 4, bigTiff ? 8 : 4, bigEndian);
    constexpr std::uint64_t maxText = 256; // a number, written as text
    if (Unsigned(entry + 2, 2, bigEndian) != asciiType || count == 0 || count > maxText)
    {
      return std::nullopt;
    }
    std::vector<unsigned char> text(static_cast<std::size_t>(count));
    const unsigned char* value = entry + (bigTiff ? 12 : 8);
    if (count <= inlineSize)
    {
      std::memcpy(text.data(), value, text.size());
    }
    else if (!read(Unsigned(value, inlineSize, bigEndian), text.size(), text.data()))
    {
      return std::nullopt;
    }
    return ParseNumber(text);
  }
  return std::nullopt;
}
} // namespace

//------------------------------------------------------------------------------
std::optional<double> ParseTiffNoDataTag(const unsigned char* data, std::size_t size)
{
  return FindNoDataTag(
    [data, size](std::uint64_t offset, std::size_t n, unsigned char* out)
    {
      if (!data || offset > size || n > size - offset)
      {
        return false;
      }
      std::memcpy(out, data + offset, n);
      return true;
    });
}

//------------------------------------------------------------------------------
std::optional<double> ReadTiffNoDataTag(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  if (!in)
  {
    return std::nullopt;
  }
  in.seekg(0, std::ios::end);
  const std::streamoff end = in.tellg();
  if (end <= 0)
  {
    return std::nullopt;
  }
  const auto size = static_cast<std::uint64_t>(end);
  return FindNoDataTag(
    [&in, size](std::uint64_t offset, std::size_t n, unsigned char* out)
    {
      if (offset > size || n > size - offset)
      {
        return false;
      }
      in.clear();
      in.seekg(static_cast<std::streamoff>(offset));
      return static_cast<bool>(
        in.read(reinterpret_cast<char*>(out), static_cast<std::streamsize>(n)));
    });
}

} // namespace mesolight
