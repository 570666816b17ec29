// SPDX-License-Identifier: BSD-3-Clause
// The `lights` CSV read back (vtkLightSetReader): a write and a read give vtkMedianCutLights'
// outputs to float precision; malformed files give a clear error and no output, never a crash.
#include "vtkLightSetReader.h"
#include "vtkMedianCutLights.h"
#include "vtkProceduralEnvironmentSource.h"

#include "MesolightTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>

using mesolight_test::MessageCapture;

namespace
{
// Relative difference in float units: 0 when the two are the same float.
double FloatUlps(double a, double b)
{
  const double scale = std::max({ std::abs(a), std::abs(b), 1e-30 });
  return std::abs(a - b) / (scale * std::numeric_limits<float>::epsilon());
}

std::string WriteText(
  const std::filesystem::path& dir, const std::string& name, const std::string& text)
{
  const std::string file = (dir / name).string();
  std::ofstream out(file);
  out << text;
  return file;
}

// Reads `file`; true when the reader failed with an error containing `needle` and no lights.
::testing::AssertionResult FailsWith(const std::string& file, const std::string& needle)
{
  vtkNew<vtkLightSetReader> reader;
  vtkNew<MessageCapture> messages;
  messages->Watch(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  if (!messages->HasError(needle))
  {
    return ::testing::AssertionFailure()
      << "expected an error with \"" << needle << "\", got: " << messages->AllErrors();
  }
  if (reader->GetOutput()->GetNumberOfPoints() != 0)
  {
    return ::testing::AssertionFailure() << "lights were output despite the error";
  }
  return ::testing::AssertionSuccess();
}

const char* Header = "u,v,x,y,z,r,g,b\n";
const char* GoodRow = "0.25,0.5,0,1,0,1,2,3\n";
} // namespace

TEST(LightsCsv, RoundTripIsIdenticalToFloatPrecision)
{
  const auto dir = mesolight_test::TestDirectory();
  vtkNew<vtkProceduralEnvironmentSource> sky;
  sky->SetMapToSunSky();
  sky->WindowOn();
  sky->SetResolution(256, 128);
  vtkNew<vtkMedianCutLights> cut;
  cut->SetInputConnection(sky->GetOutputPort());
  cut->SetNumberOfLights(37);
  cut->Update();
  const std::string file = (dir / "lights.csv").string();
  std::string error;
  ASSERT_TRUE(vtkMedianCutLights::WriteCsv(cut->GetOutput(), file, error)) << error;

  vtkNew<vtkLightSetReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkPolyData* a = cut->GetOutput();
  vtkPolyData* b = reader->GetOutput();
  ASSERT_EQ(b->GetNumberOfPoints(), 37);
  ASSERT_EQ(b->GetNumberOfVerts(), 37);
  double worst = 0.0;
  for (vtkIdType k = 0; k < 37; ++k)
  {
    double pa[3], pb[3];
    a->GetPoint(k, pa);
    b->GetPoint(k, pb);
    for (int c = 0; c < 3; ++c)
    {
      // Directions are doubles in the filter; the CSV keeps them to float precision.
      EXPECT_NEAR(pa[c], pb[c], 2e-7) << "light " << k;
    }
    for (const char* name : { "Irradiance", "MapCoordinates" })
    {
      vtkDataArray* xa = a->GetPointData()->GetArray(name);
      vtkDataArray* xb = b->GetPointData()->GetArray(name);
      ASSERT_TRUE(xb) << name;
      ASSERT_EQ(xa->GetNumberOfComponents(), xb->GetNumberOfComponents());
      for (int c = 0; c < xa->GetNumberOfComponents(); ++c)
      {
        // Float arrays: written with max_digits10, read back to the identical float.
        EXPECT_EQ(
          static_cast<float>(xa->GetComponent(k, c)), static_cast<float>(xb->GetComponent(k, c)))
          << name << " of light " << k;
        worst = std::max(worst, FloatUlps(xa->GetComponent(k, c), xb->GetComponent(k, c)));
      }
    }
  }
  EXPECT_EQ(worst, 0.0);

  // The light texture: same extent; the same directions and irradiances (the solid angle, not in
  // the CSV, is 0).
  vtkImageData* ta = cut->GetLightTexture();
  vtkImageData* tb = reader->GetLightTexture();
  int ea[6], eb[6];
  ta->GetExtent(ea);
  tb->GetExtent(eb);
  for (int i = 0; i < 6; ++i)
  {
    EXPECT_EQ(ea[i], eb[i]);
  }
  vtkDataArray* sa = ta->GetPointData()->GetScalars();
  vtkDataArray* sb = tb->GetPointData()->GetScalars();
  ASSERT_TRUE(sb);
  ASSERT_EQ(sb->GetNumberOfComponents(), 4);
  for (vtkIdType t = 0; t < 2 * 37; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(sa->GetComponent(t, c), sb->GetComponent(t, c),
        2e-7 * std::max(1.0, std::abs(sa->GetComponent(t, c))));
    }
  }

  // Negative: a file written with 6 significant digits (the stream default) does not round-trip
  // to the float: the check above is able to fail.
  const std::string coarse = (dir / "coarse.csv").string();
  {
    std::ofstream out(coarse);
    out << Header;
    vtkDataArray* e = a->GetPointData()->GetArray("Irradiance");
    vtkDataArray* uv = a->GetPointData()->GetArray("MapCoordinates");
    for (vtkIdType k = 0; k < 37; ++k)
    {
      double p[3];
      a->GetPoint(k, p);
      out << uv->GetComponent(k, 0) << ',' << uv->GetComponent(k, 1) << ',' << p[0] << ',' << p[1]
          << ',' << p[2] << ',' << e->GetComponent(k, 0) << ',' << e->GetComponent(k, 1) << ','
          << e->GetComponent(k, 2) << '\n';
    }
  }
  vtkNew<vtkLightSetReader> coarseReader;
  coarseReader->SetFileName(coarse.c_str());
  coarseReader->Update();
  ASSERT_EQ(coarseReader->GetOutput()->GetNumberOfPoints(), 37);
  int different = 0;
  vtkDataArray* ca = a->GetPointData()->GetArray("Irradiance");
  vtkDataArray* cb = coarseReader->GetOutput()->GetPointData()->GetArray("Irradiance");
  for (vtkIdType k = 0; k < 37; ++k)
  {
    different +=
      static_cast<float>(ca->GetComponent(k, 0)) != static_cast<float>(cb->GetComponent(k, 0)) ? 1
                                                                                               : 0;
  }
  EXPECT_GT(different, 0);
}

TEST(LightsCsv, BlankLinesAndSpacesAndCrlfAreAccepted)
{
  const auto dir = mesolight_test::TestDirectory();
  const std::string file = WriteText(
    dir, "ok.csv", "u,v,x,y,z,r,g,b\r\n 0.25, 0.5, 0, 1, 0, 1, 2, 3\r\n\n0.5,0,0,0,1,4,5,6\n");
  vtkNew<vtkLightSetReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  ASSERT_EQ(reader->GetOutput()->GetNumberOfPoints(), 2);
  double p[3];
  reader->GetOutput()->GetPoint(1, p);
  EXPECT_EQ(p[2], 1.0);
  EXPECT_EQ(reader->GetOutput()->GetPointData()->GetArray("Irradiance")->GetComponent(0, 2), 3.0);
}

TEST(LightsCsv, MalformedFilesFailWithAClearError)
{
  const auto dir = mesolight_test::TestDirectory();
  const std::string h = Header;
  EXPECT_TRUE(FailsWith(WriteText(dir, "empty.csv", ""), "is empty"));
  EXPECT_TRUE(FailsWith(WriteText(dir, "blank.csv", "\n\n"), "is empty"));
  EXPECT_TRUE(FailsWith(
    WriteText(dir, "header.csv", std::string("x,y,z,r,g,b\n") + GoodRow), "line 1: the header"));
  EXPECT_TRUE(FailsWith(WriteText(dir, "only-header.csv", h), "no lights"));
  EXPECT_TRUE(FailsWith(WriteText(dir, "missing.csv", h + GoodRow + "0.25,0.5,0,1,0,1,2\n"),
    "line 3: 7 fields, expected 8"));
  EXPECT_TRUE(
    FailsWith(WriteText(dir, "extra.csv", h + "0.25,0.5,0,1,0,1,2,3,4\n"), "9 fields, expected 8"));
  EXPECT_TRUE(
    FailsWith(WriteText(dir, "trailing.csv", h + "0.25,0.5,0,1,0,1,2,\n"), "the b field \"\""));
  EXPECT_TRUE(FailsWith(WriteText(dir, "nan.csv", h + "0.25,0.5,0,1,0,nan,2,3\n"),
    "the r field \"nan\" is not a finite"));
  EXPECT_TRUE(
    FailsWith(WriteText(dir, "inf.csv", h + "0.25,0.5,0,1,0,1,inf,3\n"), "the g field \"inf\""));
  EXPECT_TRUE(
    FailsWith(WriteText(dir, "word.csv", h + "0.25,0.5,0,1,0,1,2,bright\n"), "\"bright\""));
  EXPECT_TRUE(FailsWith(WriteText(dir, "huge.csv", h + "0.25,0.5,0,1,0,1e999,2,3\n"), "1e999"));
  EXPECT_TRUE(FailsWith(
    WriteText(dir, "length.csv", h + "0.25,0.5,0,2,0,1,2,3\n"), "has length 2.000000, expected"));
  EXPECT_TRUE(FailsWith(
    WriteText(dir, "negative.csv", h + "0.25,0.5,0,1,0,-1,2,3\n"), "negative irradiance"));
  EXPECT_TRUE(FailsWith((dir / "does-not-exist.csv").string(), "cannot open"));
  EXPECT_TRUE(FailsWith("", "no light-set file name"));
  // Binary garbage: an error, not a crash.
  std::string garbage(4096, '\0');
  for (size_t i = 0; i < garbage.size(); ++i)
  {
    garbage[i] = static_cast<char>((i * 7919) & 0xff);
  }
  EXPECT_TRUE(FailsWith(WriteText(dir, "garbage.csv", garbage), "line 1: the header"));
  // A row with no end: refused at the line limit, never read into memory whole; a device (a
  // file that never ends a line) is not opened at all.
  EXPECT_TRUE(FailsWith(WriteText(dir, "endless.csv", h + std::string(100000, '1')),
    "line 2: longer than 4096 characters"));
  EXPECT_TRUE(FailsWith("/dev/zero", "is not a regular file"));
}

// Irradiance the renderer cannot hold (its lights are single precision) is refused with the line
// and field, rather than accepted and turned into infinity that blacks out the relief.
TEST(LightsCsv, ValuesOutsideSinglePrecisionAreRefused)
{
  const auto dir = mesolight_test::TestDirectory();
  const std::string h = Header;
  EXPECT_TRUE(FailsWith(WriteText(dir, "1e39.csv", h + GoodRow + "0.25,0.5,0,1,0,1e39,2,3\n"),
    "line 3: the r field \"1e39\" is outside single precision"));
  EXPECT_TRUE(FailsWith(WriteText(dir, "3.5e38.csv", h + "0.25,0.5,0,1,0,1,3.5e38,3\n"),
    "line 2: the g field \"3.5e38\" is outside single precision"));
  EXPECT_TRUE(FailsWith(WriteText(dir, "u.csv", h + "1e39,0.5,0,1,0,1,2,3\n"),
    "the u field \"1e39\" is outside single precision"));
  // Each light representable, their sum not.
  EXPECT_TRUE(
    FailsWith(WriteText(dir, "sum.csv", h + "0.25,0.5,0,1,0,1,2,3e38\n0.5,0.5,0,1,0,1,2,3e38\n"),
      "line 3: the total b irradiance"));
  // The largest float itself is still a light.
  const std::string largest = WriteText(dir, "largest.csv", h + "0.25,0.5,0,1,0,3.4e38,2,3\n");
  vtkNew<vtkLightSetReader> reader;
  reader->SetFileName(largest.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 1);
}

// Spreadsheets start a CSV with a UTF-8 byte order mark: skipped, not reported as a bad header.
TEST(LightsCsv, ByteOrderMarkIsSkipped)
{
  const auto dir = mesolight_test::TestDirectory();
  const std::string file =
    WriteText(dir, "bom.csv", std::string("\xEF\xBB\xBF") + Header + GoodRow);
  vtkNew<vtkLightSetReader> reader;
  vtkNew<MessageCapture> messages;
  messages->Watch(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 1) << messages->AllErrors();
}

// A binary file's bytes are shown escaped in the message, never echoed raw to a terminal.
TEST(LightsCsv, BinaryBytesAreNotEchoed)
{
  const auto dir = mesolight_test::TestDirectory();
  const std::string file = WriteText(dir, "binary.csv", std::string("\x1B[2J\x89PNG\x07,v\n"));
  vtkNew<vtkLightSetReader> reader;
  vtkNew<MessageCapture> messages;
  messages->Watch(reader);
  reader->SetFileName(file.c_str());
  reader->Update();
  ASSERT_TRUE(messages->HasError("line 1: the header is \"\\x1B[2J\\x89PNG\\x07,v\""))
    << messages->AllErrors();
  for (const char c : messages->AllErrors())
  {
    const auto byte = static_cast<unsigned char>(c);
    EXPECT_TRUE(byte == '\n' || (byte >= 0x20 && byte < 0x7f)) << "raw byte " << int(byte);
  }
}
