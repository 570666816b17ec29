// SPDX-License-Identifier: BSD-3-Clause
// The checks of core/ImageFile (behind vtkOIIOImageReader), one test per check, without VTK: also
// built by the cores-only sanitizer stage (tests/cores). Files are written with OpenImageIO or by
// hand (a PFM header is a line of text).
#include "ImageFile.h"
#include "TestDirectory.h"

#include <OpenImageIO/imageio.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <optional>
#include <stdexcept>
#include <string>
#include <unistd.h>
#include <vector>

namespace fs = std::filesystem;
using mesolight::ImageFileError;
using mesolight::ImageFileInfo;
using mesolight::ImageFileStatus;
using mesolight::ImageSampleType;

namespace
{
/// Writes a width x height float image with `channels` channels, value = index.
bool WriteFloat(
  const fs::path& file, int width, int height, int channels, std::vector<float> values = {})
{
  if (values.empty())
  {
    values.resize(static_cast<std::size_t>(width) * height * channels);
    for (std::size_t i = 0; i < values.size(); ++i)
    {
      values[i] = static_cast<float>(i);
    }
  }
  auto out = OIIO::ImageOutput::create(file.string());
  if (!out)
  {
    OIIO::geterror();
    return false;
  }
  const OIIO::ImageSpec spec(width, height, channels, OIIO::TypeDesc::FLOAT);
  const bool ok = out->open(file.string(), spec) &&
    out->write_image(OIIO::TypeDesc::FLOAT, values.data()) && out->close();
  out->geterror();
  return ok;
}

void WriteBytes(const fs::path& file, const std::string& bytes)
{
  std::ofstream(file, std::ios::binary) << bytes;
}

/// What a call of the core gave: nothing when it accepted, else the ImageFileError's reason,
/// with its what() in `message`.
using Outcome = std::optional<ImageFileStatus>;
const Outcome Accepted = std::nullopt;

template <typename Call>
Outcome Refusal(std::string& message, const Call& call)
{
  message.clear();
  try
  {
    call();
    return Accepted;
  }
  catch (const ImageFileError& e)
  {
    message = e.what();
    return e.GetReason();
  }
}

Outcome Info(
  const fs::path& file, ImageFileInfo& info, std::string& message, std::int64_t budget = 0)
{
  return Refusal(message, [&] { info = mesolight::ReadImageFileInfo(file.string(), budget); });
}

Outcome Header(const std::string& path, int width, int height, int depth, int channels,
  ImageSampleType type, std::int64_t budget, ImageFileInfo& info, std::string& message)
{
  return Refusal(message,
    [&]
    { info = mesolight::CheckImageHeader(path, width, height, depth, channels, type, budget); });
}

Outcome Pixels(const fs::path& file, const ImageFileInfo& info, void* pixels, std::string& message)
{
  return Refusal(message,
    [&]
    {
      if (!mesolight::ReadImageFilePixels(file.string(), info, pixels))
      {
        throw std::logic_error("stopped without a progress callback");
      }
    });
}
}

TEST(ImageFile, MissingEmptyAndDirectoryPathsAreRefused)
{
  const fs::path dir = mesolight_test::TestDirectory();
  ImageFileInfo info;
  std::string message;
  EXPECT_EQ(Info("", info, message), ImageFileStatus::NoFileName);
  EXPECT_EQ(Info(dir / "none.png", info, message), ImageFileStatus::FileNotFound);
  EXPECT_NE(message.find("file not found"), std::string::npos) << message;
  EXPECT_EQ(Info(dir, info, message), ImageFileStatus::CannotOpen);
  EXPECT_NE(message.find("directory"), std::string::npos) << message;
  WriteBytes(dir / "empty.png", "");
  EXPECT_EQ(Info(dir / "empty.png", info, message), ImageFileStatus::FileFormat);
  EXPECT_NE(message.find("empty (0 bytes)"), std::string::npos) << message;
}

TEST(ImageFile, UnreadableFileIsRefused)
{
  // Root reads files without read permission, and CI runs as root: there the check runs as the
  // unprivileged user "nobody" (effective uid only, restored after), in a directory of /tmp that
  // anyone may enter.
  const bool root = ::geteuid() == 0;
  const uid_t nobody = 65534;
  fs::path dir = mesolight_test::TestDirectory();
  if (root)
  {
    std::string pattern = (fs::temp_directory_path() / "mesolight-unreadable-XXXXXX").string();
    ASSERT_NE(::mkdtemp(pattern.data()), nullptr);
    dir = pattern;
    fs::permissions(dir, fs::perms::owner_all | fs::perms::group_exec | fs::perms::others_exec);
  }
  const fs::path file = dir / "a.exr";
  ASSERT_TRUE(WriteFloat(file, 2, 2, 1));
  ImageFileInfo info;
  std::string message;
  const auto infoAs = [&](fs::perms perms)
  {
    fs::permissions(file, perms);
    if (root)
    {
      EXPECT_EQ(::seteuid(nobody), 0);
    }
    const Outcome status = Info(file, info, message);
    if (root)
    {
      EXPECT_EQ(::seteuid(0), 0);
    }
    return status;
  };
  // The same file, readable by all: accepted (so a refusal below is the permission's).
  EXPECT_EQ(infoAs(fs::perms::owner_read | fs::perms::owner_write | fs::perms::group_read |
              fs::perms::others_read),
    Accepted)
    << message;
  EXPECT_EQ(infoAs(fs::perms::none), ImageFileStatus::CannotOpen) << message;
  EXPECT_NE(message.find("cannot be opened"), std::string::npos) << message;
  fs::permissions(file, fs::perms::owner_all);
  if (root)
  {
    fs::remove_all(dir);
  }
}

TEST(ImageFile, CorruptAndUnknownFilesAreRefusedWithOpenImageIOsReason)
{
  const fs::path dir = mesolight_test::TestDirectory();
  WriteBytes(dir / "bad.png", "this is not a PNG file at all");
  WriteBytes(dir / "bad.mesolight-unknown", "nor is this anything");
  ImageFileInfo info;
  std::string message;
  EXPECT_EQ(Info(dir / "bad.png", info, message), ImageFileStatus::FileFormat);
  EXPECT_NE(message.find("OpenImageIO:"), std::string::npos) << message;
  EXPECT_EQ(Info(dir / "bad.mesolight-unknown", info, message), ImageFileStatus::UnrecognizedType);
  EXPECT_NE(message.find("unrecognized file type"), std::string::npos) << message;
}

TEST(ImageFile, ZeroSizeAndNoChannelsAreRefused)
{
  ImageFileInfo info;
  std::string message;
  for (const auto& size : { std::vector<int>{ 0, 4, 3 }, { 4, 0, 3 }, { 4, 4, 0 }, { -1, 4, 3 } })
  {
    EXPECT_EQ(
      Header("x.png", size[0], size[1], 1, size[2], ImageSampleType::UInt8, 0, info, message),
      ImageFileStatus::FileFormat);
    EXPECT_NE(message.find("zero-sized image"), std::string::npos) << message;
  }
  // The same check accepts a 1 x 1 image of one channel.
  EXPECT_EQ(Header("x.png", 1, 1, 1, 1, ImageSampleType::UInt8, 0, info, message), Accepted);
}

TEST(ImageFile, VolumesAreRefused)
{
  ImageFileInfo info;
  std::string message;
  EXPECT_EQ(Header("v.tif", 4, 4, 3, 1, ImageSampleType::Float, 0, info, message),
    ImageFileStatus::FileFormat);
  EXPECT_NE(message.find("volume images (depth 3)"), std::string::npos) << message;
}

TEST(ImageFile, AtMostFourChannelsAreRead)
{
  ImageFileInfo info;
  std::string message;
  ASSERT_EQ(Header("c.exr", 2, 3, 1, 7, ImageSampleType::Float, 0, info, message), Accepted);
  EXPECT_EQ(info.FileChannels, 7);
  EXPECT_EQ(info.Channels, 4);
  EXPECT_EQ(info.ByteSize(), 2u * 3u * 4u * 4u);

  const fs::path dir = mesolight_test::TestDirectory();
  ASSERT_TRUE(WriteFloat(dir / "six.exr", 3, 2, 6));
  ASSERT_EQ(Info(dir / "six.exr", info, message), Accepted) << message;
  EXPECT_EQ(info.FileChannels, 6);
  EXPECT_EQ(info.Channels, 4);
  std::vector<float> pixels(3 * 2 * 4);
  ASSERT_EQ(Pixels(dir / "six.exr", info, pixels.data(), message), Accepted) << message;
  // Bottom row first: pixel (0, 1) of the file, channels 0..3 of 6.
  EXPECT_EQ(pixels[0], 18.f);
  EXPECT_EQ(pixels[3], 21.f);
}

// A photograph taken with the camera turned is stored sideways with an Orientation tag (EXIF 2.3
// tag 274, TIFF 6.0) that every viewer applies; it is read as shown. The reference is the EXIF
// table itself: the side of the shown image the stored 0th row and 0th column lie on. (OpenImageIO
// 2.4's ImageBufAlgo::reorient swaps 5 and 7 against that table, and against Pillow's
// exif_transpose: it cannot be the reference.) A reader that ignores the tag fails 2-8.
TEST(ImageFile, OrientedFilesAreReadAsShown)
{
  enum Side
  {
    Top,
    Bottom,
    Left,
    Right
  };
  // Per orientation 1-8: where the 0th row is, where the 0th column is.
  const Side rowSide[9] = { Top, Top, Top, Bottom, Bottom, Left, Right, Right, Left };
  const Side columnSide[9] = { Left, Left, Right, Right, Left, Top, Top, Bottom, Bottom };
  const int storedWidth = 3, storedHeight = 2;
  std::vector<float> values(storedWidth * storedHeight);
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    values[i] = static_cast<float>(i + 1);
  }
  const fs::path dir = mesolight_test::TestDirectory();
  for (int orientation = 1; orientation <= 8; ++orientation)
  {
    const fs::path file = dir / ("oriented-" + std::to_string(orientation) + ".tif");
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    OIIO::ImageSpec spec(storedWidth, storedHeight, 1, OIIO::TypeDesc::FLOAT);
    spec.attribute("Orientation", orientation);
    ASSERT_TRUE(out->open(file.string(), spec) &&
      out->write_image(OIIO::TypeDesc::FLOAT, values.data()) && out->close());

    ImageFileInfo info;
    std::string message;
    ASSERT_EQ(Info(file, info, message), Accepted) << message;
    EXPECT_EQ(info.Orientation, orientation);
    const bool sideways = rowSide[orientation] == Left || rowSide[orientation] == Right;
    ASSERT_EQ(info.Width, sideways ? storedHeight : storedWidth) << orientation;
    ASSERT_EQ(info.Height, sideways ? storedWidth : storedHeight) << orientation;
    std::vector<float> pixels(values.size());
    ASSERT_EQ(Pixels(file, info, pixels.data(), message), Accepted) << message;
    for (int sy = 0; sy < storedHeight; ++sy)
    {
      for (int sx = 0; sx < storedWidth; ++sx)
      {
        // Shown position (top-left origin) of stored pixel (sx, sy).
        int x = 0, y = 0;
        if (!sideways)
        {
          y = rowSide[orientation] == Top ? sy : info.Height - 1 - sy;
          x = columnSide[orientation] == Left ? sx : info.Width - 1 - sx;
        }
        else
        {
          x = rowSide[orientation] == Left ? sy : info.Width - 1 - sy;
          y = columnSide[orientation] == Top ? sx : info.Height - 1 - sx;
        }
        EXPECT_EQ(pixels[static_cast<std::size_t>(info.Height - 1 - y) * info.Width + x],
          values[static_cast<std::size_t>(sy) * storedWidth + sx])
          << "orientation " << orientation << ", stored pixel (" << sx << ", " << sy << ")";
      }
    }
  }
  // A turned file is read through a second buffer: its 24 bytes of pixels need 48 of the
  // budget, as the refusal says; the file stored upright fits 32.
  ImageFileInfo info;
  std::string message;
  EXPECT_EQ(Info(dir / "oriented-1.tif", info, message, 32), Accepted) << message;
  EXPECT_EQ(Info(dir / "oriented-6.tif", info, message, 32), ImageFileStatus::TooLarge);
  EXPECT_NE(message.find("Orientation tag 6"), std::string::npos) << message;
  EXPECT_EQ(Info(dir / "oriented-6.tif", info, message, 48), Accepted) << message;
}

TEST(ImageFile, AbsurdDimensionsAreRefusedBeforeAllocating)
{
  // A PFM header claiming 100000 x 100000 RGB floats (120 GB) and no pixels: 20 bytes.
  const fs::path dir = mesolight_test::TestDirectory();
  WriteBytes(dir / "huge.pfm", "PF\n100000 100000\n-1.0\n");
  ImageFileInfo info;
  std::string message;
  EXPECT_EQ(
    Info(dir / "huge.pfm", info, message, std::int64_t(1) << 30), ImageFileStatus::TooLarge);
  EXPECT_NE(message.find("100000 x 100000"), std::string::npos) << message;

  // The budget decides: 2 x 2 RGB floats (48 bytes) fit 64 bytes, not 32.
  EXPECT_EQ(Header("s.exr", 2, 2, 1, 3, ImageSampleType::Float, 64, info, message), Accepted);
  EXPECT_EQ(Header("s.exr", 2, 2, 1, 3, ImageSampleType::Float, 32, info, message),
    ImageFileStatus::TooLarge);
  // Sides near 2^31 do not overflow the size.
  EXPECT_EQ(Header("m.exr", std::numeric_limits<int>::max(), std::numeric_limits<int>::max(), 1, 4,
              ImageSampleType::Float, 0, info, message),
    ImageFileStatus::TooLarge);
}

TEST(ImageFile, TruncatedPixelsAreRefused)
{
  const fs::path dir = mesolight_test::TestDirectory();
  // OpenImageIO reads PFM but does not write it: header and little-endian floats by hand.
  std::string pfm = "PF\n64 64\n-1.0\n";
  pfm += std::string(64 * 64 * 3 * sizeof(float), '\0');
  WriteBytes(dir / "t.pfm", pfm);
  ImageFileInfo info;
  std::string message;
  const std::uintmax_t size = fs::file_size(dir / "t.pfm");
  fs::resize_file(dir / "t.pfm", size / 2);
  ASSERT_EQ(Info(dir / "t.pfm", info, message), Accepted) << message;
  std::vector<float> pixels(static_cast<std::size_t>(info.ByteSize() / 4));
  EXPECT_EQ(Pixels(dir / "t.pfm", info, pixels.data(), message), ImageFileStatus::FileFormat);
  EXPECT_NE(message.find("truncated or corrupt"), std::string::npos) << message;
}

// A baseline JPEG cut short decodes "successfully" (libjpeg fills the missing rows), with a
// complaint OpenImageIO keeps: the read is a warning, not silence. The whole file: none.
TEST(ImageFile, ADecodersComplaintIsAWarning)
{
  const fs::path dir = mesolight_test::TestDirectory();
  const int side = 64;
  std::vector<unsigned char> values(static_cast<std::size_t>(side) * side);
  for (std::size_t i = 0; i < values.size(); ++i)
  {
    values[i] = static_cast<unsigned char>((i * 37) % 251); // noise: no run compresses away
  }
  {
    auto out = OIIO::ImageOutput::create((dir / "whole.jpg").string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open((dir / "whole.jpg").string(),
                  OIIO::ImageSpec(side, side, 1, OIIO::TypeDesc::UINT8)) &&
      out->write_image(OIIO::TypeDesc::UINT8, values.data()) && out->close());
  }
  fs::copy_file(dir / "whole.jpg", dir / "cut.jpg");
  fs::resize_file(dir / "cut.jpg", fs::file_size(dir / "whole.jpg") / 2);
  for (const char* name : { "whole.jpg", "cut.jpg" })
  {
    ImageFileInfo info;
    std::string message;
    ASSERT_EQ(Info(dir / name, info, message), Accepted) << message;
    std::vector<unsigned char> pixels(static_cast<std::size_t>(info.ByteSize()));
    std::string warning;
    EXPECT_TRUE(
      mesolight::ReadImageFilePixels((dir / name).string(), info, pixels.data(), {}, &warning));
    if (std::string(name) == "cut.jpg")
    {
      EXPECT_NE(warning.find("Premature end of JPEG file"), std::string::npos) << warning;
      EXPECT_NE(warning.find("may be missing"), std::string::npos) << warning;
    }
    else
    {
      EXPECT_TRUE(warning.empty()) << warning;
    }
  }
}

TEST(ImageFile, AFileThatChangedAfterItsHeaderIsRefused)
{
  const fs::path dir = mesolight_test::TestDirectory();
  ASSERT_TRUE(WriteFloat(dir / "c.exr", 4, 4, 1));
  ImageFileInfo info;
  std::string message;
  ASSERT_EQ(Info(dir / "c.exr", info, message), Accepted) << message;
  std::vector<float> pixels(16);
  // Unchanged, it reads; grown to 64 x 64 it would write past the 16 floats.
  EXPECT_EQ(Pixels(dir / "c.exr", info, pixels.data(), message), Accepted);
  ASSERT_TRUE(WriteFloat(dir / "c.exr", 64, 64, 1));
  EXPECT_EQ(Pixels(dir / "c.exr", info, pixels.data(), message), ImageFileStatus::FileFormat);
  EXPECT_NE(message.find("changed while it was read"), std::string::npos) << message;
}

TEST(ImageFile, NonFiniteSamplesAreCounted)
{
  const fs::path dir = mesolight_test::TestDirectory();
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  ASSERT_TRUE(WriteFloat(dir / "n.exr", 2, 2, 1, { 1.f, nan, -inf, 3e38f }));
  ImageFileInfo info;
  std::string message;
  ASSERT_EQ(Info(dir / "n.exr", info, message), Accepted) << message;
  std::vector<float> pixels(4);
  ASSERT_EQ(Pixels(dir / "n.exr", info, pixels.data(), message), Accepted);
  EXPECT_EQ(mesolight::CountNonFiniteSamples(pixels.data(), pixels.size()), 2u);
  const float finite[3] = { 0.f, -1.f, 3e38f };
  EXPECT_EQ(mesolight::CountNonFiniteSamples(finite, 3), 0u);
}

TEST(ImageFile, StoppingThroughProgressReadsNothingFurther)
{
  const fs::path dir = mesolight_test::TestDirectory();
  ASSERT_TRUE(WriteFloat(dir / "a.exr", 8, 300, 1));
  ImageFileInfo info;
  std::string message;
  ASSERT_EQ(Info(dir / "a.exr", info, message), Accepted) << message;
  std::vector<float> pixels(8 * 300);
  // Not a refusal: false, the pixels incomplete.
  EXPECT_FALSE(mesolight::ReadImageFilePixels(
    (dir / "a.exr").string(), info, pixels.data(), [](float) { return true; }));
  EXPECT_TRUE(mesolight::ReadImageFilePixels(
    (dir / "a.exr").string(), info, pixels.data(), [](float) { return false; }));
}

TEST(ImageFile, OpenExrAttributesLargerThanTheFileAreRefused)
{
  // Found by the image_file fuzz target: OpenEXR allocated the 1.8 GB an attribute of a 600-byte
  // file claimed (fuzz/corpus/image_file/crash-exr-attribute-claims-1.8GB).
  const fs::path dir = mesolight_test::TestDirectory();
  std::string bytes("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
  bytes += std::string("comments\0string\0", 16);
  bytes += std::string("\x00\x00\x00\x70", 4); // 1.8 GB of comment
  bytes += "short";
  WriteBytes(dir / "claims.exr", bytes);
  ImageFileInfo info;
  std::string message;
  EXPECT_EQ(Info(dir / "claims.exr", info, message), ImageFileStatus::FileFormat);
  EXPECT_NE(message.find("attribute 'comments' claims 1879048192 bytes"), std::string::npos)
    << message;
  // Under another name too (OpenImageIO tries every reader).
  fs::rename(dir / "claims.exr", dir / "claims.bin");
  EXPECT_EQ(Info(dir / "claims.bin", info, message), ImageFileStatus::FileFormat) << message;

  // A data window of 2^31 scanlines in a 100-byte file: OpenEXR would allocate its offset table
  // and line buffers before OpenImageIO gives us the size (the fuzz target's
  // crash-exr-data-window-16M-wide took seconds of allocating and clearing).
  std::string window("\x76\x2f\x31\x01\x02\x00\x00\x00", 8);
  window += std::string("dataWindow\0box2i\0\x10\0\0\0", 21);
  const std::int32_t box[4] = { 0, 0, 3, std::numeric_limits<std::int32_t>::max() - 1 };
  window.append(reinterpret_cast<const char*>(box), 16);
  window += std::string(64, '\0');
  WriteBytes(dir / "window.exr", window);
  EXPECT_EQ(
    Info(dir / "window.exr", info, message, std::int64_t(1) << 30), ImageFileStatus::TooLarge);
  EXPECT_NE(message.find("OpenEXR data window (4 x 2147483647)"), std::string::npos) << message;

  // A valid file passes the same walk, within a budget of its size but not below it: 3 x 5 x 2
  // floats and ZIP's 16-line chunks (the walk's estimate: 3 x 16 x 8 = 384 bytes).
  ASSERT_TRUE(WriteFloat(dir / "valid.exr", 3, 5, 2));
  EXPECT_EQ(Info(dir / "valid.exr", info, message), Accepted) << message;
  EXPECT_EQ(Info(dir / "valid.exr", info, message, 384), Accepted) << message;
  EXPECT_EQ(Info(dir / "valid.exr", info, message, 383), ImageFileStatus::TooLarge) << message;
}
