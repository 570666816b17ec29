// SPDX-License-Identifier: BSD-3-Clause
// A minimal linear DNG writer for tests: RAW input without a camera. A DNG with the LinearRaw
// photometric interpretation (Adobe, "Digital Negative Specification" 1.4, chapter 4) holds
// demosaiced camera RGB; its ColorMatrix1 (XYZ -> camera) is set to the XYZ -> linear sRGB matrix,
// so the camera space is linear sRGB and a correct reader gives the stored values back, scaled
// by the white level. LibRaw (OpenImageIO's "raw" plugin) refuses images under 22 pixels wide
// or high; such files still open, through OpenImageIO's TIFF reader.
#ifndef LinearDngWriter_h
#define LinearDngWriter_h

#include <cmath>
#include <cstdint>
#include <fstream>
#include <string>
#include <vector>

namespace mesolight_test
{

/// Writes width x height RGB samples (row-major, top row first, 16 bits, white level 65535).
inline bool WriteLinearDng(
  const std::string& path, int width, int height, const std::vector<std::uint16_t>& rgb)
{
  if (width <= 0 || height <= 0 || rgb.size() != 3u * width * height)
  {
    return false;
  }
  struct Entry
  {
    std::uint16_t Tag, Type;
    std::uint32_t Count;
    std::vector<std::uint8_t> Bytes; // the value, inline when it fits in 4 bytes
  };
  auto put16 = [](std::vector<std::uint8_t>& b, std::uint32_t v)
  {
    b.push_back(static_cast<std::uint8_t>(v & 0xff));
    b.push_back(static_cast<std::uint8_t>((v >> 8) & 0xff));
  };
  auto put32 = [&](std::vector<std::uint8_t>& b, std::uint32_t v)
  {
    put16(b, v & 0xffff);
    put16(b, v >> 16);
  };
  enum : std::uint16_t
  {
    BYTE = 1,
    ASCII = 2,
    SHORT = 3,
    LONG = 4,
    RATIONAL = 5,
    SRATIONAL = 10
  };
  std::vector<Entry> entries;
  auto shorts = [&](std::uint16_t tag, std::vector<std::uint32_t> values)
  {
    Entry e{ tag, SHORT, static_cast<std::uint32_t>(values.size()), {} };
    for (auto v : values)
    {
      put16(e.Bytes, v);
    }
    entries.push_back(e);
  };
  auto longValue = [&](std::uint16_t tag, std::uint32_t value)
  {
    Entry e{ tag, LONG, 1, {} };
    put32(e.Bytes, value);
    entries.push_back(e);
  };
  auto text = [&](std::uint16_t tag, const std::string& s)
  {
    Entry e{ tag, ASCII, static_cast<std::uint32_t>(s.size() + 1), {} };
    e.Bytes.assign(s.begin(), s.end());
    e.Bytes.push_back(0);
    entries.push_back(e);
  };
  auto bytes = [&](std::uint16_t tag, std::vector<std::uint8_t> values) {
    entries.push_back({ tag, BYTE, static_cast<std::uint32_t>(values.size()), values });
  };
  auto rationals = [&](std::uint16_t tag, std::uint16_t type, const std::vector<double>& values)
  {
    Entry e{ tag, type, static_cast<std::uint32_t>(values.size()), {} };
    for (double v : values)
    {
      put32(e.Bytes, static_cast<std::uint32_t>(static_cast<std::int32_t>(std::lround(v * 1e4))));
      put32(e.Bytes, 10000);
    }
    entries.push_back(e);
  };
  const std::uint32_t dataBytes = static_cast<std::uint32_t>(rgb.size() * 2);
  longValue(254, 0); // NewSubFileType: the main image
  longValue(256, static_cast<std::uint32_t>(width));
  longValue(257, static_cast<std::uint32_t>(height));
  shorts(258, { 16, 16, 16 }); // BitsPerSample
  shorts(259, { 1 });          // no compression
  shorts(262, { 34892 });      // LinearRaw
  text(271, "Mesolight");      // Make
  text(272, "Linear test");    // Model
  longValue(273, 0);           // StripOffsets, patched below
  shorts(274, { 1 });          // Orientation
  shorts(277, { 3 });          // SamplesPerPixel
  longValue(278, static_cast<std::uint32_t>(height));
  longValue(279, dataBytes);
  shorts(284, { 1 });              // PlanarConfiguration: interleaved
  bytes(50706, { 1, 4, 0, 0 });    // DNGVersion
  bytes(50707, { 1, 1, 0, 0 });    // DNGBackwardVersion
  text(50708, "Mesolight linear"); // UniqueCameraModel
  longValue(50717, 65535);         // WhiteLevel
  // XYZ (D65) -> linear sRGB (IEC 61966-2-1): camera RGB is linear sRGB.
  rationals(50721, SRATIONAL,
    { 3.2404542, -1.5371385, -0.4985314, -0.9692660, 1.8760108, 0.0415560, 0.0556434, -0.2040259,
      1.0572252 });
  rationals(50728, RATIONAL, { 1.0, 1.0, 1.0 }); // AsShotNeutral: no white balance
  shorts(50778, { 21 });                         // CalibrationIlluminant1: D65

  const std::uint32_t ifdOffset = 8;
  const std::uint32_t ifdSize = static_cast<std::uint32_t>(2 + 12 * entries.size() + 4);
  std::vector<std::uint8_t> outOfLine;
  std::vector<std::uint8_t> ifd;
  put16(ifd, static_cast<std::uint32_t>(entries.size()));
  std::vector<std::size_t> stripOffsetField;
  for (const Entry& e : entries) // already in ascending tag order, as TIFF requires
  {
    put16(ifd, e.Tag);
    put16(ifd, e.Type);
    put32(ifd, e.Count);
    if (e.Tag == 273)
    {
      stripOffsetField.push_back(ifd.size());
    }
    if (e.Bytes.size() <= 4)
    {
      std::vector<std::uint8_t> value = e.Bytes;
      value.resize(4, 0);
      ifd.insert(ifd.end(), value.begin(), value.end());
    }
    else
    {
      put32(ifd, ifdOffset + ifdSize + static_cast<std::uint32_t>(outOfLine.size()));
      outOfLine.insert(outOfLine.end(), e.Bytes.begin(), e.Bytes.end());
      if (outOfLine.size() % 2)
      {
        outOfLine.push_back(0); // values start on word boundaries
      }
    }
  }
  put32(ifd, 0); // no next IFD
  const std::uint32_t dataOffset =
    ifdOffset + ifdSize + static_cast<std::uint32_t>(outOfLine.size());
  for (std::size_t at : stripOffsetField)
  {
    for (int k = 0; k < 4; ++k)
    {
      ifd[at + k] = static_cast<std::uint8_t>((dataOffset >> (8 * k)) & 0xff);
    }
  }
  std::vector<std::uint8_t> file = { 'I', 'I', 42, 0 };
  put32(file, ifdOffset);
  file.insert(file.end(), ifd.begin(), ifd.end());
  file.insert(file.end(), outOfLine.begin(), outOfLine.end());
  for (std::uint16_t v : rgb)
  {
    put16(file, v);
  }
  std::ofstream out(path, std::ios::binary);
  out.write(reinterpret_cast<const char*>(file.data()), static_cast<std::streamsize>(file.size()));
  return static_cast<bool>(out);
}

} // namespace mesolight_test

#endif
