// SPDX-License-Identifier: BSD-3-Clause
// SRTM height tiles (core/SrtmHeightFile, read by core/ImageFile in place of OpenImageIO): the
// heights as the same array written by OpenImageIO as a signed 16-bit TIFF reads them (an
// independent reader for the row order), the voids' no-data value, and refusals of files whose
// size is no tile's. Without VTK: also built by the cores-only sanitizer stage (tests/cores).
#include "ImageFile.h"
#include "SrtmHeightFile.h"
#include "TestDirectory.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <cstdint>
#include <filesystem>
#include <fstream>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using mesolight::ImageFileError;
using mesolight::ImageFileStatus;
using mesolight::ImageSampleType;

namespace
{
/// Heights in file order (the northernmost row first): distinct per texel, negative ones (below
/// sea level) and both bytes non-zero, voids in one corner.
std::vector<std::int16_t> TileHeights(int side)
{
  std::vector<std::int16_t> heights(static_cast<size_t>(side) * side);
  for (int r = 0; r < side; ++r)
  {
    for (int i = 0; i < side; ++i)
    {
      heights[static_cast<size_t>(r) * side + i] = static_cast<std::int16_t>(
        (r < 3 && i < 4) ? mesolight::SrtmVoidHeight : -400 + 7 * r + 3 * i + 256 * (i % 3));
    }
  }
  return heights;
}

/// Writes them as SRTM stores them: big-endian, no header.
void WriteTile(const fs::path& file, const std::vector<std::int16_t>& heights)
{
  std::ofstream out(file, std::ios::binary);
  for (const std::int16_t h : heights)
  {
    const auto u = static_cast<std::uint16_t>(h);
    const char bytes[2] = { static_cast<char>(u >> 8), static_cast<char>(u & 0xff) };
    out.write(bytes, 2);
  }
}

std::vector<std::int16_t> ReadPixels(const fs::path& file, const mesolight::ImageFileInfo& info)
{
  std::vector<std::int16_t> pixels(static_cast<size_t>(info.Width) * info.Height);
  EXPECT_TRUE(mesolight::ReadImageFilePixels(file.string(), info, pixels.data()));
  return pixels;
}
} // namespace

TEST(SrtmHeightFile, TileSidesFromFileSizes)
{
  EXPECT_EQ(mesolight::SrtmTileSide(2884802), 1201);
  EXPECT_EQ(mesolight::SrtmTileSide(25934402), 3601);
  EXPECT_EQ(mesolight::SrtmTileSide(8), 2);
  EXPECT_EQ(mesolight::SrtmTileSide(2884801), 0); // odd
  EXPECT_EQ(mesolight::SrtmTileSide(2884804), 0); // not a square
  EXPECT_EQ(mesolight::SrtmTileSide(2), 0);       // 1 x 1: no tile
  EXPECT_EQ(mesolight::SrtmTileSide(0), 0);
  EXPECT_EQ(mesolight::SrtmTileSide(~0ULL), 0);
  EXPECT_TRUE(mesolight::IsSrtmHeightFileName("/data/N45E006.hgt"));
  EXPECT_TRUE(mesolight::IsSrtmHeightFileName("S12W077.HGT"));
  EXPECT_FALSE(mesolight::IsSrtmHeightFileName("N45E006.hgt.zip"));
  EXPECT_FALSE(mesolight::IsSrtmHeightFileName("hgt"));
  // A tile's name gives its south-west corner.
  EXPECT_EQ(mesolight::SrtmTileSouthLatitude("/data/N45E006.hgt").value_or(-999), 45.0);
  EXPECT_EQ(mesolight::SrtmTileSouthLatitude("S12W077.HGT").value_or(-999), -12.0);
  EXPECT_EQ(mesolight::SrtmTileSouthLatitude("n00e000.hgt").value_or(-999), 0.0);
  EXPECT_FALSE(mesolight::SrtmTileSouthLatitude("terrain.hgt").has_value());
  EXPECT_FALSE(mesolight::SrtmTileSouthLatitude("N9E006.hgt").has_value());
  EXPECT_FALSE(mesolight::SrtmTileSouthLatitude("N95E006.hgt").has_value());
}

TEST(SrtmHeightFile, HeightsAsOpenImageIOReadsTheSameTiff)
{
  const fs::path dir = mesolight_test::TestDirectory();
  const int side = 1201;
  const std::vector<std::int16_t> heights = TileHeights(side);
  const fs::path tile = dir / "N45E006.hgt";
  WriteTile(tile, heights);
  // The same heights, north up, as a signed 16-bit TIFF, read by OpenImageIO.
  const fs::path tiff = dir / "N45E006.tif";
  {
    auto out = OIIO::ImageOutput::create(tiff.string());
    ASSERT_TRUE(out);
    const OIIO::ImageSpec spec(side, side, 1, OIIO::TypeDesc::INT16);
    ASSERT_TRUE(out->open(tiff.string(), spec) &&
      out->write_image(OIIO::TypeDesc::INT16, heights.data()) && out->close());
  }
  const mesolight::ImageFileInfo info = mesolight::ReadImageFileInfo(tile.string(), 0);
  EXPECT_EQ(info.Width, side);
  EXPECT_EQ(info.Height, side);
  EXPECT_EQ(info.Channels, 1);
  EXPECT_EQ(info.Type, ImageSampleType::Int16);
  EXPECT_EQ(info.FormatName, "srtm-hgt");
  EXPECT_TRUE(info.HasNoDataValue);
  EXPECT_EQ(info.NoDataValue, -32768.0);
  EXPECT_TRUE(mesolight::CanReadImageFile(tile.string()));
  const mesolight::ImageFileInfo tiffInfo = mesolight::ReadImageFileInfo(tiff.string(), 0);
  ASSERT_EQ(tiffInfo.Type, ImageSampleType::Int16);
  const std::vector<std::int16_t> fromTile = ReadPixels(tile, info);
  const std::vector<std::int16_t> fromTiff = ReadPixels(tiff, tiffInfo);
  ASSERT_EQ(fromTile.size(), fromTiff.size());
  EXPECT_TRUE(fromTile == fromTiff);
  // VTK's order: the bottom row first, so the voids (the file's first rows) are at the top.
  EXPECT_EQ(fromTile[static_cast<size_t>(side - 1) * side], mesolight::SrtmVoidHeight);
  EXPECT_NE(fromTile[0], mesolight::SrtmVoidHeight);
  // The negative case: little-endian samples are other heights.
  const std::int16_t u = heights[static_cast<size_t>(side - 1) * side + 1];
  const auto swapped = static_cast<std::int16_t>(static_cast<std::uint16_t>(
    ((static_cast<std::uint16_t>(u) & 0xff) << 8) | (static_cast<std::uint16_t>(u) >> 8)));
  EXPECT_NE(fromTile[1], swapped);
  EXPECT_EQ(fromTile[1], u);
}

TEST(SrtmHeightFile, SizesOfNoTileAreRefusedWithTheSizesExpected)
{
  const fs::path dir = mesolight_test::TestDirectory();
  const fs::path odd = dir / "odd.hgt";
  std::ofstream(odd, std::ios::binary) << std::string(2884801, '\0');
  try
  {
    mesolight::ReadImageFileInfo(odd.string(), 0);
    FAIL() << "a file of 2884801 bytes was read as a tile";
  }
  catch (const ImageFileError& e)
  {
    EXPECT_EQ(e.GetReason(), ImageFileStatus::FileFormat);
    EXPECT_NE(std::string(e.what()).find("2884802 for 1201 x 1201"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("this file has 2884801 bytes"), std::string::npos)
      << e.what();
  }
  EXPECT_FALSE(mesolight::CanReadImageFile(odd.string()));
  const fs::path one = dir / "one.hgt";
  std::ofstream(one, std::ios::binary) << std::string(2, '\0');
  EXPECT_THROW(mesolight::ReadImageFileInfo(one.string(), 0), ImageFileError);
  // An empty file: refused as any empty image.
  const fs::path empty = dir / "empty.hgt";
  std::ofstream(empty, std::ios::binary).close();
  EXPECT_THROW(mesolight::ReadImageFileInfo(empty.string(), 0), ImageFileError);
  // A budget smaller than the heights: refused before anything is allocated.
  const fs::path tile = dir / "tile.hgt";
  WriteTile(tile, TileHeights(64));
  try
  {
    mesolight::ReadImageFileInfo(tile.string(), 1024);
    FAIL() << "a 64 x 64 tile fitted a 1 KiB budget";
  }
  catch (const ImageFileError& e)
  {
    EXPECT_EQ(e.GetReason(), ImageFileStatus::TooLarge) << e.what();
  }
}

TEST(SrtmHeightFile, ATileThatChangedAfterItsHeaderIsRefused)
{
  const fs::path dir = mesolight_test::TestDirectory();
  const fs::path tile = dir / "tile.hgt";
  WriteTile(tile, TileHeights(64));
  const mesolight::ImageFileInfo info = mesolight::ReadImageFileInfo(tile.string(), 0);
  fs::resize_file(tile, 2 * 64 * 64 - 2);
  std::vector<std::int16_t> pixels(64 * 64);
  try
  {
    mesolight::ReadImageFilePixels(tile.string(), info, pixels.data());
    FAIL() << "a truncated tile was read";
  }
  catch (const ImageFileError& e)
  {
    EXPECT_EQ(e.GetReason(), ImageFileStatus::FileFormat) << e.what();
  }
  WriteTile(tile, TileHeights(32)); // another tile size under the same name
  EXPECT_THROW(mesolight::ReadImageFilePixels(tile.string(), info, pixels.data()), ImageFileError);
}

TEST(SrtmHeightFile, StoppingThroughProgressReadsNothingFurther)
{
  const fs::path dir = mesolight_test::TestDirectory();
  const fs::path tile = dir / "tile.hgt";
  WriteTile(tile, TileHeights(1201));
  const mesolight::ImageFileInfo info = mesolight::ReadImageFileInfo(tile.string(), 0);
  std::vector<std::int16_t> pixels(static_cast<size_t>(1201) * 1201, 12345);
  std::vector<float> reports;
  const bool complete = mesolight::ReadImageFilePixels(tile.string(), info, pixels.data(),
    [&](float portion)
    {
      reports.push_back(portion);
      return portion > 0.1f;
    });
  EXPECT_FALSE(complete);
  ASSERT_FALSE(reports.empty());
  EXPECT_LT(reports.back(), 0.2f);
  EXPECT_EQ(pixels[0], 12345); // the bottom row, the file's last: never read
}
