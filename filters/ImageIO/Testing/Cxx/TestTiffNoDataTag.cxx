// SPDX-License-Identifier: BSD-3-Clause
// GDAL's no-data tag (core/TiffNoDataTag): the value GDAL writes in a DEM, in either byte order
// and in BigTIFF, and no value (never a crash) for anything else. Without VTK: also built by the
// cores-only sanitizer stage (tests/cores).
#include "GdalNoDataTagWriter.h"
#include "ImageFile.h"
#include "TiffNoDataTag.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using mesolight::ParseTiffNoDataTag;
using mesolight::ReadTiffNoDataTag;

namespace
{
fs::path WriteInt16Tiff(const std::string& name)
{
  const fs::path dir = fs::path(MESOLIGHT_TEST_TEMP_DIR) / "TiffNoDataTag";
  fs::create_directories(dir);
  const fs::path file = dir / name;
  const std::vector<std::int16_t> metres = { -32768, 141, 547, 300 };
  auto out = OIIO::ImageOutput::create(file.string());
  EXPECT_TRUE(out);
  if (out)
  {
    EXPECT_TRUE(out->open(file.string(), OIIO::ImageSpec(2, 2, 1, OIIO::TypeDesc::INT16)));
    EXPECT_TRUE(out->write_image(OIIO::TypeDesc::INT16, metres.data()));
    EXPECT_TRUE(out->close());
  }
  return file;
}

/// A classic big-endian TIFF whose only directory entry is `tag` (`type`, `count`, with the
/// value's text out of line at offset 26).
std::vector<unsigned char> BigEndianDirectory(
  std::uint16_t tag, std::uint16_t type, const std::string& text)
{
  const auto count = static_cast<std::uint32_t>(text.size() + 1);
  std::vector<unsigned char> b = { 'M', 'M', 0, 42, 0, 0, 0, 8, // header, directory at 8
    0, 1,                                                       // one entry
    static_cast<unsigned char>(tag >> 8), static_cast<unsigned char>(tag & 0xff),
    static_cast<unsigned char>(type >> 8), static_cast<unsigned char>(type & 0xff), 0, 0, 0,
    static_cast<unsigned char>(count), 0, 0, 0, 26, // value at 26
    0, 0, 0, 0 };                                   // no next directory
  for (const char c : text)                         // (insert() trips GCC 12's -Warray-bounds here)
  {
    b.push_back(static_cast<unsigned char>(c));
  }
  b.push_back(0);
  return b;
}
} // namespace

TEST(TiffNoDataTag, ReadsTheValueGdalWritesInADem)
{
  const fs::path file = WriteInt16Tiff("dem.tif");
  // OpenImageIO writes no such tag: the negative case.
  EXPECT_FALSE(ReadTiffNoDataTag(file.string()).has_value());
  EXPECT_FALSE(mesolight::ReadImageFileInfo(file.string(), 0).HasNoDataValue);

  ASSERT_TRUE(mesolight_test::AddGdalNoDataTag(file.string(), "-32768"));
  const std::optional<double> value = ReadTiffNoDataTag(file.string());
  ASSERT_TRUE(value.has_value());
  EXPECT_EQ(*value, -32768.0);
  const mesolight::ImageFileInfo info = mesolight::ReadImageFileInfo(file.string(), 0);
  EXPECT_TRUE(info.HasNoDataValue);
  EXPECT_EQ(info.NoDataValue, -32768.0);
  EXPECT_EQ(info.Type, mesolight::ImageSampleType::Int16); // the pixels still read

  // Short values sit in the entry itself; NaN is a value GDAL writes for float DEMs.
  ASSERT_TRUE(mesolight_test::AddGdalNoDataTag(file.string(), "-99"));
  EXPECT_EQ(ReadTiffNoDataTag(file.string()).value_or(0.0), -99.0);
  ASSERT_TRUE(mesolight_test::AddGdalNoDataTag(file.string(), "nan"));
  ASSERT_TRUE(ReadTiffNoDataTag(file.string()).has_value());
  EXPECT_TRUE(std::isnan(*ReadTiffNoDataTag(file.string())));
  ASSERT_TRUE(mesolight_test::AddGdalNoDataTag(file.string(), " -3.4028234663852886e+38 "));
  EXPECT_EQ(ReadTiffNoDataTag(file.string()).value_or(0.0), -3.4028234663852886e+38);
}

TEST(TiffNoDataTag, BigEndianAndBigTiff)
{
  const auto big = BigEndianDirectory(42113, 2, "-9999.5");
  EXPECT_EQ(ParseTiffNoDataTag(big.data(), big.size()).value_or(0.0), -9999.5);

  // BigTIFF (little-endian): 16-byte header, 8-byte counts, 20-byte entries, 8 bytes inline.
  std::vector<unsigned char> b = { 'I', 'I', 43, 0, 8, 0, 0, 0, 16, 0, 0, 0, 0, 0, 0, 0 };
  const unsigned char directory[] = { 1, 0, 0, 0, 0, 0, 0, 0, // one entry
    0x81, 0xa4, 2, 0,                                         // tag 42113, ASCII
    7, 0, 0, 0, 0, 0, 0, 0,                                   // 7 bytes: inline
    '-', '1', 'e', '+', '3', '8', 0, 0 };
  b.insert(b.end(), std::begin(directory), std::end(directory));
  b.insert(b.end(), 8, 0); // no next directory
  EXPECT_EQ(ParseTiffNoDataTag(b.data(), b.size()).value_or(0.0), -1e38);
}

TEST(TiffNoDataTag, AnythingElseGivesNoValue)
{
  const auto good = BigEndianDirectory(42113, 2, "-9999");
  ASSERT_TRUE(ParseTiffNoDataTag(good.data(), good.size()).has_value());
  // Another tag, another type (SHORT), text that is not a number, nothing.
  const auto other = BigEndianDirectory(42112, 2, "-9999");
  EXPECT_FALSE(ParseTiffNoDataTag(other.data(), other.size()).has_value());
  const auto shorts = BigEndianDirectory(42113, 3, "-9999");
  EXPECT_FALSE(ParseTiffNoDataTag(shorts.data(), shorts.size()).has_value());
  for (const std::string text : { "deep", "-9999 m", "", "1e999" })
  {
    const auto bad = BigEndianDirectory(42113, 2, text);
    EXPECT_FALSE(ParseTiffNoDataTag(bad.data(), bad.size()).has_value()) << text;
  }
  // Every truncation of a good file, and offsets past its end.
  for (std::size_t size = 0; size < good.size(); ++size)
  {
    EXPECT_FALSE(ParseTiffNoDataTag(good.data(), size).has_value()) << size;
  }
  auto far = good;
  far[7] = 0xf0; // the directory past the end
  EXPECT_FALSE(ParseTiffNoDataTag(far.data(), far.size()).has_value());
  far = good;
  far[21] = 0xf0; // the text past the end
  EXPECT_FALSE(ParseTiffNoDataTag(far.data(), far.size()).has_value());
  far = good;
  far[8] = far[9] = 0xff; // 65535 entries in a 34-byte file, the first of another tag
  far[11] = 0x80;
  EXPECT_FALSE(ParseTiffNoDataTag(far.data(), far.size()).has_value());
  // Not a TIFF: a PNG signature, a TIFF version that is neither 42 nor 43, no file.
  const unsigned char png[] = { 0x89, 'P', 'N', 'G', 13, 10, 26, 10 };
  EXPECT_FALSE(ParseTiffNoDataTag(png, sizeof(png)).has_value());
  auto version = good;
  version[3] = 44;
  EXPECT_FALSE(ParseTiffNoDataTag(version.data(), version.size()).has_value());
  EXPECT_FALSE(ParseTiffNoDataTag(nullptr, 0).has_value());
  EXPECT_FALSE(ReadTiffNoDataTag("/nonexistent/dem.tif").has_value());
}
