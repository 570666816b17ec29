// SPDX-License-Identifier: BSD-3-Clause
// RAW photographs through vtkOIIOImageReader: OpenImageIO's raw plugin (LibRaw) outputs
// gamma-encoded sRGB unless asked for linear light, and depth hallucination needs linear light.
// A linear DNG written by the test (tests/support/LinearDngWriter.h) must come back with the
// values it stores.
#include "vtkOIIOImageReader.h"

#include "LinearDngWriter.h"
#include "MesolightTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
constexpr int W = 64; // LibRaw refuses images under 22 pixels
constexpr int H = 48;

std::uint16_t Stored(int i, int j, int c) // file row j, top first
{
  const int values[3] = { 100 * (i + 1), 150 * (j + 1), 500 + 40 * ((i + j) % 7) };
  return static_cast<std::uint16_t>(values[c]);
}

fs::path WriteTestDng(const std::string& name)
{
  std::vector<std::uint16_t> rgb;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        rgb.push_back(Stored(i, j, c));
      }
    }
  }
  const fs::path file = mesolight_test::TestDirectory() / name;
  EXPECT_TRUE(mesolight_test::WriteLinearDng(file.string(), W, H, rgb));
  return file;
}
} // namespace

TEST(OIIORawInput, LinearDngIsReadAsLinearLight)
{
  const fs::path file = WriteTestDng("linear.dng");
  {
    // The raw plugin, not the TIFF reader's fallback, must be the one reading it.
    auto in = OIIO::ImageInput::open(file.string());
    ASSERT_TRUE(in) << OIIO::geterror();
    EXPECT_STREQ(in->format_name(), "raw");
    in->close();
  }
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  ASSERT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  vtkImageData* image = reader->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  ASSERT_EQ(dims[0], W);
  ASSERT_EQ(dims[1], H);
  ASSERT_GE(image->GetNumberOfScalarComponents(), 3);
  const double scale = image->GetPointData()->GetScalars()->GetDataType() == VTK_FLOAT ? 65535 : 1;
  double worst = 0.0;
  for (int j = 0; j < H; ++j)
  {
    for (int i = 0; i < W; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        const double read = scale * image->GetScalarComponentAsDouble(i, H - 1 - j, 0, c);
        worst = std::max(worst, std::abs(read - Stored(i, j, c)));
      }
    }
  }
  // LibRaw rounds through its colour matrices: a code value or two.
  EXPECT_LE(worst, 3.0) << "worst difference in 16-bit code values";
}

// Negative case: OpenImageIO's default decoding of the same file (sRGB-encoded) is far from the
// stored values, so the check above fails for a reader that does not ask for linear light.
TEST(OIIORawInput, DefaultDecodingIsGammaEncodedAndFailsTheCheck)
{
  const fs::path file = WriteTestDng("default.dng");
  auto in = OIIO::ImageInput::open(file.string());
  ASSERT_TRUE(in) << OIIO::geterror();
  std::vector<std::uint16_t> pixels(static_cast<std::size_t>(W) * H * in->spec().nchannels);
  ASSERT_TRUE(in->read_image(0, 0, 0, 3, OIIO::TypeDesc::UINT16, pixels.data()));
  const int n = in->spec().nchannels;
  in->close();
  // The darkest red (stored 100 of 65535) comes back brightened by the sRGB curve, more than
  // ten times its linear value.
  EXPECT_GT(pixels[0], 10 * Stored(0, 0, 0));
  EXPECT_GT(std::abs(pixels[static_cast<std::size_t>(n) * (W - 1)] - Stored(W - 1, 0, 0)), 3);
}
