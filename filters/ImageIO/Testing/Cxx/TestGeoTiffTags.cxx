// SPDX-License-Identifier: BSD-3-Clause
// GeoTIFF tags (core/GeoTiffTags): GDAL's no-data value, in either byte order and in BigTIFF, and
// a pixel's size on the ground (projected, geographic, rotated), as GDAL writes them, and no value
// (never a crash) for anything else. Without VTK: also built by the
// cores-only sanitizer stage (tests/cores).
#include "GeoTiffTags.h"
#include "ImageFile.h"
#include "TiffTagWriter.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <utility>
#include <vector>

namespace fs = std::filesystem;
using mesolight::ParseTiffNoDataTag;
using mesolight::ReadTiffNoDataTag;

namespace
{
fs::path WriteInt16Tiff(const std::string& name)
{
  const fs::path dir = fs::path(MESOLIGHT_TEST_TEMP_DIR) / "GeoTiffTags";
  fs::create_directories(dir);
  const fs::path file = dir / name;
  EXPECT_TRUE(mesolight_test::WriteInt16Tiff(file.string(), 2, 2, { -32768, 141, 547, 300 }));
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

// A pixel's size on the ground from the GeoTIFF tags, as GDAL writes them.
TEST(GeoTiffPixelSize, ProjectedMetresAndFeet)
{
  const fs::path file = WriteInt16Tiff("projected.tif");
  EXPECT_FALSE(mesolight::ReadGeoTiffPixelSize(file.string(), 2).has_value()); // no tags yet
  // UTM (EPSG 32632): a projected model (GTModelTypeGeoKey 1), metres (ProjLinearUnitsGeoKey
  // 9001), 30 x 25 m pixels.
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), 30.0, 25.0, 500000.0, 5000000.0,
    { { 1024, 1 }, { 3072, 32632 }, { 3076, 9001 } }));
  auto size = mesolight::ReadGeoTiffPixelSize(file.string(), 2);
  ASSERT_TRUE(size.has_value());
  EXPECT_EQ(size->X, 30.0);
  EXPECT_EQ(size->Y, 25.0);
  EXPECT_FALSE(size->Geographic);
  // No linear unit key: metres, as in the projections GDAL names by EPSG code alone.
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), 30.0, 25.0, 0.0, 0.0, { { 1024, 1 } }));
  EXPECT_EQ(
    mesolight::ReadGeoTiffPixelSize(file.string(), 2).value_or(mesolight::GeoPixelSize{}).X, 30.0);
  // International and US survey feet.
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(
    file.string(), 10.0, 10.0, 0.0, 0.0, { { 1024, 1 }, { 3076, 9002 } }));
  EXPECT_NEAR(
    mesolight::ReadGeoTiffPixelSize(file.string(), 2).value_or(mesolight::GeoPixelSize{}).X, 3.048,
    1e-12);
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(
    file.string(), 10.0, 10.0, 0.0, 0.0, { { 1024, 1 }, { 3076, 9003 } }));
  EXPECT_NEAR(
    mesolight::ReadGeoTiffPixelSize(file.string(), 2).value_or(mesolight::GeoPixelSize{}).X,
    3.0480061, 1e-7);
  // Another linear unit (a link, 9098), a geocentric model (3), no model: no size.
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(
    file.string(), 10.0, 10.0, 0.0, 0.0, { { 1024, 1 }, { 3076, 9098 } }));
  EXPECT_FALSE(mesolight::ReadGeoTiffPixelSize(file.string(), 2).has_value());
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), 10.0, 10.0, 0.0, 0.0, { { 1024, 3 } }));
  EXPECT_FALSE(mesolight::ReadGeoTiffPixelSize(file.string(), 2).has_value());
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), 10.0, 10.0, 0.0, 0.0, { { 1025, 1 } }));
  EXPECT_FALSE(mesolight::ReadGeoTiffPixelSize(file.string(), 2).has_value());
}

// The values' unit, where VerticalUnitsGeoKey names it: metres, feet, US survey feet; another
// unit is named but not read (0); no key, no unit.
TEST(GeoTiffPixelSize, VerticalUnits)
{
  const fs::path file = WriteInt16Tiff("vertical.tif");
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), 30.0, 25.0, 0.0, 0.0, { { 1024, 1 } }));
  auto size = mesolight::ReadGeoTiffPixelSize(file.string(), 2);
  ASSERT_TRUE(size.has_value());
  EXPECT_FALSE(size->HasVerticalUnit);
  EXPECT_EQ(size->VerticalUnit, 1.0);
  const std::pair<std::uint16_t, double> units[] = { { 9001, 1.0 }, { 9002, 0.3048 },
    { 9003, 1200.0 / 3937.0 }, { 9098, 0.0 } };
  for (const auto& [code, metres] : units)
  {
    // Projected (a foot on the ground too: the vertical unit is its own key) and geographic.
    for (const std::uint16_t model : { 1, 2 })
    {
      ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), model == 1 ? 30.0 : 0.001,
        model == 1 ? 25.0 : 0.001, 0.0, 45.0, { { 1024, model }, { 3076, 9002 }, { 4099, code } }));
      size = mesolight::ReadGeoTiffPixelSize(file.string(), 2);
      ASSERT_TRUE(size.has_value()) << code;
      EXPECT_TRUE(size->HasVerticalUnit) << code;
      EXPECT_EQ(size->VerticalUnit, metres) << code;
    }
  }
}

TEST(GeoTiffPixelSize, GeographicDegreesAtTheMiddleLatitude)
{
  // r-cran-terra's elev.tif as GDAL wrote it: 30-arc-second pixels, the first row's top edge at
  // 50.19167 N, 90 rows (0.75 degrees): the middle latitude is 49.81667 N.
  const fs::path file = WriteInt16Tiff("geographic.tif");
  const double d = 1.0 / 120.0;
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(
    file.string(), d, d, 5.741666666666666, 50.19166666666666, { { 1024, 2 }, { 2054, 9102 } }));
  const auto size = mesolight::ReadGeoTiffPixelSize(file.string(), 90);
  ASSERT_TRUE(size.has_value());
  EXPECT_TRUE(size->Geographic);
  // A degree of latitude is 111.195 km on the mean sphere; of longitude that times the cosine.
  const double degree = 6371008.8 * 3.14159265358979323846 / 180.0;
  EXPECT_NEAR(size->Y, d * degree, 1e-9);
  EXPECT_NEAR(
    size->X, d * degree * std::cos(49.81666666666666 * 3.14159265358979323846 / 180.0), 1e-9);
  EXPECT_NEAR(size->X, 597.89, 0.01);
  EXPECT_NEAR(size->Y, 926.63, 0.01);
  // The height moves the middle latitude: with one row it is the first row's, further north,
  // where a degree of longitude is shorter.
  EXPECT_LT(mesolight::ReadGeoTiffPixelSize(file.string(), 1)->X, size->X);
  // Radians (9101) are not read: no size.
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(
    file.string(), d, d, 5.74, 50.19, { { 1024, 2 }, { 2054, 9101 } }));
  EXPECT_FALSE(mesolight::ReadGeoTiffPixelSize(file.string(), 90).has_value());
  // At a pole, and beyond: none.
  EXPECT_FALSE(mesolight::GeographicPixelSize(1.0, 1.0, 90.0).has_value());
  EXPECT_FALSE(mesolight::GeographicPixelSize(1.0, 1.0, -95.0).has_value());
  EXPECT_FALSE(mesolight::GeographicPixelSize(0.0, 1.0, 10.0).has_value());
}

TEST(GeoTiffPixelSize, RotatedRasterFromTheTransformation)
{
  // stars' geomatrix.tif: a ModelTransformationTag whose columns are (1.5, -5) and (-5, -1.5)
  // metres: 5.22 m pixels along a rotated grid.
  const fs::path file = WriteInt16Tiff("rotated.tif");
  ASSERT_TRUE(mesolight_test::AddTiffArrayTag(file.string(), 34264,
    std::vector<double>{
      1.5, -5.0, 0.0, 1841000.0, -5.0, -1.5, 0.0, 1144000.0, 0, 0, 0, 0, 0, 0, 0, 1 }));
  ASSERT_TRUE(mesolight_test::AddTiffArrayTag(
    file.string(), 34735, std::vector<std::uint16_t>{ 1, 1, 0, 1, 1024, 0, 1, 1 }));
  const auto size = mesolight::ReadGeoTiffPixelSize(file.string(), 20);
  ASSERT_TRUE(size.has_value());
  EXPECT_NEAR(size->X, std::hypot(1.5, 5.0), 1e-12);
  EXPECT_NEAR(size->Y, std::hypot(5.0, 1.5), 1e-12);
}

TEST(GeoTiffPixelSize, CorruptTagsGiveNoSize)
{
  // Every truncation of a good file, a zero or infinite scale, a key directory cut short.
  const fs::path file = WriteInt16Tiff("corrupt.tif");
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), 30.0, 25.0, 0.0, 0.0, { { 1024, 1 } }));
  std::vector<unsigned char> good;
  {
    std::ifstream in(file, std::ios::binary);
    good.assign(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
  }
  ASSERT_TRUE(mesolight::ParseGeoTiffPixelSize(good.data(), good.size(), 2).has_value());
  for (std::size_t size = 0; size < good.size(); size += 7)
  {
    const auto cut = mesolight::ParseGeoTiffPixelSize(good.data(), size, 2);
    EXPECT_TRUE(!cut.has_value() || (cut->X == 30.0 && cut->Y == 25.0)) << size;
  }
  for (const double bad : { 0.0, -0.0, std::numeric_limits<double>::infinity(),
         std::numeric_limits<double>::quiet_NaN() })
  {
    ASSERT_TRUE(
      mesolight_test::AddGeoTiffTags(file.string(), bad, 25.0, 0.0, 0.0, { { 1024, 1 } }));
    EXPECT_FALSE(mesolight::ReadGeoTiffPixelSize(file.string(), 2).has_value()) << bad;
  }
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), 30.0, 25.0, 0.0, 0.0, { { 1024, 1 } }));
  ASSERT_TRUE(mesolight_test::AddTiffArrayTag(
    file.string(), 34735, std::vector<std::uint16_t>{ 1, 1, 0, 1, 1024 }));
  EXPECT_FALSE(mesolight::ReadGeoTiffPixelSize(file.string(), 2).has_value());
  EXPECT_FALSE(mesolight::ReadGeoTiffPixelSize("/nonexistent/dem.tif", 2).has_value());
}
