// SPDX-License-Identifier: BSD-3-Clause
// vtkOIIOImageReader / vtkOIIOImageWriter: round trips, row order, bad files.
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"

#include "TiffTagWriter.h"

#include "MesolightTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <filesystem>
#include <fstream>
#include <limits>
#include <string>
#include <vector>

namespace fs = std::filesystem;
using mesolight_test::MessageCapture;

namespace
{
/// A w x h image whose values encode (i, j, c) so any permutation or flip shows.
template <typename ArrayT>
vtkSmartPointer<vtkImageData> Pattern(int w, int h, int nComp, double maxValue)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<ArrayT> scalars;
  scalars->SetNumberOfComponents(nComp);
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      for (int c = 0; c < nComp; ++c)
      {
        const double t = std::fmod(0.013 * i + 0.071 * j + 0.29 * c + 0.003 * i * j, 1.0);
        using T = typename ArrayT::ValueType;
        const T value = std::numeric_limits<T>::is_integer
          ? static_cast<T>(std::lround(t * maxValue))
          : static_cast<T>(t * maxValue);
        scalars->SetTypedComponent(j * w + i, c, value);
      }
    }
  }
  image->GetPointData()->SetScalars(scalars);
  return image;
}

bool Write(vtkImageData* image, const fs::path& file, int dataType = vtkOIIOImageWriter::AUTO,
  int bitDepth = 8)
{
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(file.string().c_str());
  writer->SetDataType(dataType);
  writer->SetBitDepth(bitDepth);
  return writer->Write();
}

vtkSmartPointer<vtkImageData> Read(const fs::path& file)
{
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError) << file;
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->DeepCopy(reader->GetOutput());
  return copy;
}

void ExpectSameImage(vtkImageData* expected, vtkImageData* actual)
{
  int de[3];
  int da[3];
  expected->GetDimensions(de);
  actual->GetDimensions(da);
  ASSERT_EQ(de[0], da[0]);
  ASSERT_EQ(de[1], da[1]);
  ASSERT_EQ(da[2], 1);
  vtkDataArray* e = expected->GetPointData()->GetScalars();
  vtkDataArray* a = actual->GetPointData()->GetScalars();
  ASSERT_NE(a, nullptr);
  EXPECT_STREQ(a->GetName(), "ImageScalars");
  ASSERT_EQ(a->GetDataType(), e->GetDataType());
  ASSERT_EQ(a->GetNumberOfComponents(), e->GetNumberOfComponents());
  ASSERT_EQ(a->GetNumberOfTuples(), e->GetNumberOfTuples());
  vtkIdType mismatches = 0;
  for (vtkIdType t = 0; t < e->GetNumberOfTuples(); ++t)
  {
    for (int c = 0; c < e->GetNumberOfComponents(); ++c)
    {
      if (e->GetComponent(t, c) != a->GetComponent(t, c) && mismatches++ < 5)
      {
        ADD_FAILURE() << "tuple " << t << " comp " << c << ": " << e->GetComponent(t, c)
                      << " != " << a->GetComponent(t, c);
      }
    }
  }
  EXPECT_EQ(mismatches, 0);
}

void WriteBytes(const fs::path& file, const std::vector<unsigned char>& bytes)
{
  std::ofstream out(file, std::ios::binary);
  out.write(
    reinterpret_cast<const char*>(bytes.data()), static_cast<std::streamsize>(bytes.size()));
}

std::vector<unsigned char> ReadBytes(const fs::path& file)
{
  std::ifstream in(file, std::ios::binary);
  return std::vector<unsigned char>(std::istreambuf_iterator<char>(in), {});
}

/// Read a file expecting failure; returns the reader's error code.
unsigned long ReadError(const fs::path& file, MessageCapture* capture)
{
  vtkNew<vtkOIIOImageReader> reader;
  capture->Watch(reader);
  reader->SetFileName(file.string().c_str());
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0) << file;
  EXPECT_FALSE(capture->Errors.empty()) << file;
  EXPECT_TRUE(capture->HasError(file.string())) << "the message names the file:\n"
                                                << capture->AllErrors();
  EXPECT_FALSE(vtkOIIOImageReader::CanReadFile(file.string().c_str()));
  return reader->GetErrorCode();
}

std::uint32_t Crc32(const unsigned char* data, size_t n)
{
  std::uint32_t crc = 0xffffffffu;
  for (size_t k = 0; k < n; ++k)
  {
    crc ^= data[k];
    for (int b = 0; b < 8; ++b)
    {
      crc = (crc >> 1) ^ (0xedb88320u & (0u - (crc & 1u)));
    }
  }
  return ~crc;
}
}

TEST(OIIOImageIO, FloatExrRoundTripIsExact)
{
  const fs::path dir = mesolight_test::TestDirectory();
  for (int nComp : { 1, 2, 3, 4 })
  {
    // Values outside [0,1] and negative ones must survive a float format untouched.
    auto image = Pattern<vtkFloatArray>(37, 23, nComp, 3.7);
    image->GetPointData()->GetScalars()->SetComponent(5, 0, -0.123456789);
    const fs::path file = dir / ("float" + std::to_string(nComp) + ".exr");
    ASSERT_TRUE(Write(image, file));
    ExpectSameImage(image, Read(file));
  }
}

TEST(OIIOImageIO, EightBitPngAndTiffRoundTrip)
{
  const fs::path dir = mesolight_test::TestDirectory();
  for (const char* ext : { ".png", ".tif" })
  {
    for (int nComp : { 1, 2, 3, 4 })
    {
      // With 4 channels, RGB must not be (un)premultiplied by A (A is the relief depth).
      auto image = Pattern<vtkUnsignedCharArray>(31, 17, nComp, 255);
      const fs::path file = dir / ("u8_" + std::to_string(nComp) + ext);
      ASSERT_TRUE(Write(image, file)) << file;
      ExpectSameImage(image, Read(file));
    }
  }
}

TEST(OIIOImageIO, SixteenBitPngAndTiffRoundTrip)
{
  const fs::path dir = mesolight_test::TestDirectory();
  for (const char* ext : { ".png", ".tiff" })
  {
    for (int nComp : { 1, 4 })
    {
      auto image = Pattern<vtkUnsignedShortArray>(29, 19, nComp, 65535);
      const fs::path file = dir / ("u16_" + std::to_string(nComp) + ext);
      ASSERT_TRUE(Write(image, file, vtkOIIOImageWriter::AUTO, 16)) << file;
      ExpectSameImage(image, Read(file));
    }
  }
}

TEST(OIIOImageIO, FloatToIntegerQuantization)
{
  const fs::path dir = mesolight_test::TestDirectory();
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(6, 1, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfTuples(6);
  const float in[6] = { 0.f, 0.5f, 1.f, 1.5f, -0.25f, std::numeric_limits<float>::quiet_NaN() };
  for (int k = 0; k < 6; ++k)
  {
    values->SetValue(k, in[k]);
  }
  image->GetPointData()->SetScalars(values);

  ASSERT_TRUE(Write(image, dir / "q8.png"));
  auto q8 = Read(dir / "q8.png");
  const double expected8[6] = { 0, 128, 255, 255, 0, 0 };
  ASSERT_EQ(q8->GetScalarType(), VTK_UNSIGNED_CHAR);
  for (int k = 0; k < 6; ++k)
  {
    EXPECT_EQ(q8->GetPointData()->GetScalars()->GetComponent(k, 0), expected8[k]) << k;
  }
  ASSERT_TRUE(Write(image, dir / "q16.png", vtkOIIOImageWriter::UNSIGNED_SHORT));
  auto q16 = Read(dir / "q16.png");
  const double expected16[6] = { 0, 32768, 65535, 65535, 0, 0 };
  ASSERT_EQ(q16->GetScalarType(), VTK_UNSIGNED_SHORT);
  for (int k = 0; k < 6; ++k)
  {
    EXPECT_EQ(q16->GetPointData()->GetScalars()->GetComponent(k, 0), expected16[k]) << k;
  }
}

TEST(OIIOImageIO, SignedSixteenBitElevationsAreReadAsStored)
{
  // An int16 GeoTIFF DEM as GDAL writes one: metres, below sea level too, and -32768 where
  // there is no data. The reader keeps them (VTK_SHORT), so a no-data value means what gdalinfo
  // says; as floats OpenImageIO would have scaled them by 1/32767.
  const fs::path file = mesolight_test::TestDirectory() / "dem_i16.tif";
  const std::vector<std::int16_t> rows = { -32768, -120, 0, 547, 8848, 32767 }; // file order
  {
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(file.string(), OIIO::ImageSpec(3, 2, 1, OIIO::TypeDesc::INT16)));
    ASSERT_TRUE(out->write_image(OIIO::TypeDesc::INT16, rows.data()));
    ASSERT_TRUE(out->close());
  }
  auto image = Read(file);
  ASSERT_EQ(image->GetScalarType(), VTK_SHORT);
  // VTK row 0 is the file's last row.
  const double expected[6] = { 547, 8848, 32767, -32768, -120, 0 };
  for (int k = 0; k < 6; ++k)
  {
    EXPECT_EQ(image->GetPointData()->GetScalars()->GetComponent(k, 0), expected[k]) << k;
  }
}

TEST(OIIOImageIO, ThirtyTwoBitIntegersAreReadAsStored)
{
  // int32 elevations (centimetres, say) and uint32 samples keep their type: as floats
  // OpenImageIO would scale them by 1 / 2^31 and 1 / 2^32, and a DEM in centimetres would
  // look like a depth map of tiny values instead of being refused without NormalizeRange.
  const fs::path dir = mesolight_test::TestDirectory();
  const std::vector<std::int32_t> signedRows = { -999999, -12000, 0, 54700, 884800, 2147483647 };
  const std::vector<std::uint32_t> unsignedRows = { 0, 1, 65536, 100000, 4000000000u, 4294967295u };
  const auto write = [&](const fs::path& file, OIIO::TypeDesc type, const void* data)
  {
    auto out = OIIO::ImageOutput::create(file.string());
    ASSERT_TRUE(out);
    ASSERT_TRUE(out->open(file.string(), OIIO::ImageSpec(3, 2, 1, type)));
    ASSERT_TRUE(out->write_image(type, data));
    ASSERT_TRUE(out->close());
  };
  write(dir / "i32.tif", OIIO::TypeDesc::INT32, signedRows.data());
  write(dir / "u32.tif", OIIO::TypeDesc::UINT32, unsignedRows.data());
  auto image = Read(dir / "i32.tif");
  ASSERT_EQ(image->GetScalarType(), VTK_INT);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  // VTK row 0 is the file's last row.
  EXPECT_EQ(scalars->GetComponent(0, 0), 54700.0);
  EXPECT_EQ(scalars->GetComponent(3, 0), -999999.0);
  EXPECT_EQ(scalars->GetComponent(5, 0), 0.0);
  image = Read(dir / "u32.tif");
  ASSERT_EQ(image->GetScalarType(), VTK_UNSIGNED_INT);
  scalars = image->GetPointData()->GetScalars();
  EXPECT_EQ(scalars->GetComponent(1, 0), 4000000000.0);
  EXPECT_EQ(scalars->GetComponent(4, 0), 1.0);
}

TEST(OIIOImageIO, GeoTiffNoDataValueComesWithTheImage)
{
  // GDAL names a DEM's no-data value in the GDAL_NODATA tag: the reader gives it, and passes it
  // downstream as field data (vtkReliefTextureFilter applies it); a file without it has none.
  const fs::path file = mesolight_test::TestDirectory() / "dem_nodata.tif";
  ASSERT_TRUE(mesolight_test::WriteInt16Tiff(file.string(), 2, 2, { -9999, 141, 547, 300 }));
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  EXPECT_FALSE(reader->GetHasNoDataValue());
  EXPECT_EQ(reader->GetOutput()->GetFieldData()->GetArray("MesolightNoDataValue"), nullptr);

  ASSERT_TRUE(mesolight_test::AddGdalNoDataTag(file.string(), "-9999"));
  reader->Modified();
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_TRUE(reader->GetHasNoDataValue());
  EXPECT_EQ(reader->GetNoDataValue(), -9999.0);
  vtkDataArray* noData = reader->GetOutput()->GetFieldData()->GetArray("MesolightNoDataValue");
  ASSERT_NE(noData, nullptr);
  ASSERT_EQ(noData->GetNumberOfTuples(), 1);
  EXPECT_EQ(noData->GetComponent(0, 0), -9999.0);
  // The pixels are the same (file row 0 is VTK row 1).
  EXPECT_EQ(reader->GetOutput()->GetPointData()->GetScalars()->GetComponent(2, 0), -9999.0);
  EXPECT_EQ(reader->GetOutput()->GetPointData()->GetScalars()->GetComponent(1, 0), 300.0);
}

TEST(OIIOImageIO, SrtmHeightTilesAreReadWithTheirVoids)
{
  // An SRTM tile (.hgt: N x N big-endian int16 metres, the northernmost row first, -32768 for
  // voids), which OpenImageIO does not read: metres kept as VTK_SHORT, north at the top, and the
  // voids' value passed on as the no-data value a GeoTIFF names.
  const fs::path file = mesolight_test::TestDirectory() / "N00E000.hgt";
  {
    // 2 x 2: north row -32768, 300; south row 141, -5 (below sea level).
    std::ofstream out(file, std::ios::binary);
    const unsigned char bytes[8] = { 0x80, 0x00, 0x01, 0x2c, 0x00, 0x8d, 0xff, 0xfb };
    out.write(reinterpret_cast<const char*>(bytes), 8);
  }
  vtkNew<vtkOIIOImageReader> reader;
  EXPECT_TRUE(reader->CanReadFile(file.string().c_str()));
  reader->SetFileName(file.string().c_str());
  reader->Update();
  ASSERT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  vtkImageData* image = reader->GetOutput();
  ASSERT_EQ(image->GetScalarType(), VTK_SHORT);
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 2);
  EXPECT_EQ(dims[1], 2);
  vtkDataArray* metres = image->GetPointData()->GetScalars();
  EXPECT_EQ(metres->GetComponent(0, 0), 141.0); // VTK row 0: the south row
  EXPECT_EQ(metres->GetComponent(1, 0), -5.0);
  EXPECT_EQ(metres->GetComponent(2, 0), -32768.0);
  EXPECT_EQ(metres->GetComponent(3, 0), 300.0);
  EXPECT_TRUE(reader->GetHasNoDataValue());
  EXPECT_EQ(reader->GetNoDataValue(), -32768.0);
  vtkDataArray* noData = image->GetFieldData()->GetArray("MesolightNoDataValue");
  ASSERT_NE(noData, nullptr);
  EXPECT_EQ(noData->GetComponent(0, 0), -32768.0);
  // A tile spans a degree (N00: 0-1 degrees north): 2 x 2 heights are a degree apart, measured
  // at 0.5 degrees north.
  const double degree = 6371008.8 * 3.14159265358979323846 / 180.0;
  EXPECT_TRUE(reader->GetHasPixelSize());
  EXPECT_NEAR(
    reader->GetPixelSize()[0], degree * std::cos(0.5 * 3.14159265358979323846 / 180.0), 1e-6);
  EXPECT_NEAR(reader->GetPixelSize()[1], degree, 1e-6);
  vtkDataArray* pixelSize = image->GetFieldData()->GetArray("MesolightPixelSize");
  ASSERT_NE(pixelSize, nullptr);
  EXPECT_EQ(pixelSize->GetNumberOfComponents(), 2);
  EXPECT_EQ(pixelSize->GetComponent(0, 1), reader->GetPixelSize()[1]);

  // A size that is no tile's: an error naming the sizes expected, no image.
  {
    std::ofstream out(file, std::ios::binary);
    out.write("abc", 3);
  }
  vtkNew<mesolight_test::MessageCapture> capture;
  capture->Watch(reader);
  reader->Modified();
  reader->Update();
  EXPECT_NE(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_TRUE(capture->HasError("an SRTM height tile ('.hgt') holds N x N big-endian"))
    << capture->AllErrors();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_FALSE(reader->CanReadFile(file.string().c_str()));
}

TEST(OIIOImageIO, GeoTiffPixelSizeComesWithTheImage)
{
  // A GeoTIFF's georeference (a projection in metres, 30 x 25 m pixels): the reader gives a
  // pixel's size on the ground and passes it downstream as field data; a file without it has none.
  const fs::path file = mesolight_test::TestDirectory() / "dem_utm.tif";
  ASSERT_TRUE(mesolight_test::WriteInt16Tiff(file.string(), 2, 2, { 100, 141, 547, 300 }));
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(file.string().c_str());
  reader->Update();
  EXPECT_FALSE(reader->GetHasPixelSize());
  EXPECT_EQ(reader->GetOutput()->GetFieldData()->GetArray("MesolightPixelSize"), nullptr);
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(
    file.string(), 30.0, 25.0, 500000.0, 5000000.0, { { 1024, 1 }, { 3076, 9001 } }));
  reader->Modified();
  reader->Update();
  ASSERT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_TRUE(reader->GetHasPixelSize());
  EXPECT_EQ(reader->GetPixelSize()[0], 30.0);
  EXPECT_EQ(reader->GetPixelSize()[1], 25.0);
  vtkDataArray* pixelSize = reader->GetOutput()->GetFieldData()->GetArray("MesolightPixelSize");
  ASSERT_NE(pixelSize, nullptr);
  EXPECT_EQ(pixelSize->GetComponent(0, 0), 30.0);
  EXPECT_EQ(pixelSize->GetComponent(0, 1), 25.0);
  double spacing[3];
  reader->GetOutput()->GetSpacing(spacing);
  EXPECT_EQ(spacing[0], 1.0); // the image itself is unchanged
  // No vertical unit named: none passed on (metres are assumed downstream).
  EXPECT_FALSE(reader->GetHasElevationUnit());
  EXPECT_EQ(reader->GetOutput()->GetFieldData()->GetArray("MesolightElevationUnit"), nullptr);
  // Elevations in feet (VerticalUnitsGeoKey 9002).
  ASSERT_TRUE(mesolight_test::AddGeoTiffTags(file.string(), 30.0, 25.0, 500000.0, 5000000.0,
    { { 1024, 1 }, { 3076, 9001 }, { 4099, 9002 } }));
  reader->Modified();
  reader->Update();
  EXPECT_TRUE(reader->GetHasElevationUnit());
  EXPECT_EQ(reader->GetElevationUnit(), 0.3048);
  vtkDataArray* unit = reader->GetOutput()->GetFieldData()->GetArray("MesolightElevationUnit");
  ASSERT_NE(unit, nullptr);
  EXPECT_EQ(unit->GetComponent(0, 0), 0.3048);
}

TEST(OIIOImageIO, RowOrderBottomRowIsLastInFile)
{
  const fs::path dir = mesolight_test::TestDirectory();
  const int w = 4;
  const int h = 3;
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 1);
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer());
  for (int k = 0; k < w * h; ++k)
  {
    p[k] = 10;
  }
  p[0] = 200; // VTK (i=0, j=0): bottom-left texel
  const fs::path file = dir / "rows.png";
  ASSERT_TRUE(Write(image, file));

  // Through the reader: back at VTK row 0.
  auto back = Read(file);
  EXPECT_EQ(back->GetScalarComponentAsDouble(0, 0, 0, 0), 200.0);
  EXPECT_EQ(back->GetScalarComponentAsDouble(0, h - 1, 0, 0), 10.0);

  // In the file (top row first): the LAST scanline.
  auto in = OIIO::ImageInput::open(file.string());
  ASSERT_TRUE(in);
  std::vector<unsigned char> pixels(w * h);
  ASSERT_TRUE(in->read_image(0, 0, 0, 1, OIIO::TypeDesc::UINT8, pixels.data()));
  in->close();
  EXPECT_EQ(pixels[(h - 1) * w + 0], 200);
  EXPECT_EQ(pixels[0], 10);
}

TEST(OIIOImageIO, ReaderReportsBadFiles)
{
  const fs::path dir = mesolight_test::TestDirectory();

  {
    vtkNew<MessageCapture> capture;
    EXPECT_EQ(ReadError(dir / "missing.png", capture), vtkErrorCode::FileNotFoundError);
    EXPECT_TRUE(capture->HasError("not found"));
  }
  {
    vtkNew<MessageCapture> capture;
    fs::create_directories(dir / "folder.png");
    EXPECT_EQ(ReadError(dir / "folder.png", capture), vtkErrorCode::CannotOpenFileError);
    EXPECT_TRUE(capture->HasError("directory"));
  }
  {
    vtkNew<MessageCapture> capture;
    std::vector<unsigned char> garbage(1000);
    for (size_t k = 0; k < garbage.size(); ++k)
    {
      garbage[k] = static_cast<unsigned char>((k * 7919u + 13u) & 0xffu);
    }
    WriteBytes(dir / "garbage.png", garbage);
    EXPECT_EQ(ReadError(dir / "garbage.png", capture), vtkErrorCode::FileFormatError);
    EXPECT_TRUE(capture->HasError("OpenImageIO:")) << capture->AllErrors();
  }
  {
    vtkNew<MessageCapture> capture;
    WriteBytes(dir / "garbage.notanimage", std::vector<unsigned char>(100, 0x42));
    EXPECT_EQ(
      ReadError(dir / "garbage.notanimage", capture), vtkErrorCode::UnrecognizedFileTypeError);
  }
  {
    vtkNew<MessageCapture> capture;
    WriteBytes(dir / "empty.png", {});
    EXPECT_NE(ReadError(dir / "empty.png", capture), vtkErrorCode::NoError);
  }
  {
    // A PNG whose header announces a 0 x 4 image (valid signature and CRC).
    std::vector<unsigned char> png = { 0x89, 'P', 'N', 'G', 0x0d, 0x0a, 0x1a, 0x0a, // signature
      0, 0, 0, 13, 'I', 'H', 'D', 'R',                    // IHDR chunk, 13 bytes
      0, 0, 0, 0, 0, 0, 0, 4, 8, 0, 0, 0, 0 };            // width 0, height 4, 8-bit grey
    const std::uint32_t crc = Crc32(png.data() + 12, 17); // over type + data
    for (int s = 24; s >= 0; s -= 8)
    {
      png.push_back(static_cast<unsigned char>((crc >> s) & 0xffu));
    }
    WriteBytes(dir / "zero.png", png);
    vtkNew<MessageCapture> capture;
    EXPECT_EQ(ReadError(dir / "zero.png", capture), vtkErrorCode::FileFormatError);
  }
  {
    // Truncated PNG: a valid file cut in the middle of its pixel data.
    auto image = Pattern<vtkUnsignedCharArray>(64, 64, 3, 255);
    ASSERT_TRUE(Write(image, dir / "full.png"));
    std::vector<unsigned char> bytes = ReadBytes(dir / "full.png");
    ASSERT_GT(bytes.size(), 200u);
    bytes.resize(bytes.size() / 2);
    WriteBytes(dir / "truncated.png", bytes);
    vtkNew<MessageCapture> capture;
    vtkNew<vtkOIIOImageReader> reader;
    capture->Watch(reader);
    reader->SetFileName((dir / "truncated.png").string().c_str());
    reader->Update();
    EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::FileFormatError);
    EXPECT_TRUE(capture->HasError("truncated.png")) << capture->AllErrors();
    EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    vtkNew<MessageCapture> capture;
    vtkNew<vtkOIIOImageReader> reader;
    capture->Watch(reader);
    reader->Update();
    EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoFileNameError);
  }
}

TEST(OIIOImageIO, CanReadFileAndHeaderInformation)
{
  const fs::path dir = mesolight_test::TestDirectory();
  auto image = Pattern<vtkUnsignedShortArray>(8, 5, 2, 65535);
  ASSERT_TRUE(Write(image, dir / "info.tif", vtkOIIOImageWriter::AUTO, 16));
  EXPECT_TRUE(vtkOIIOImageReader::CanReadFile((dir / "info.tif").string().c_str()));
  EXPECT_FALSE(vtkOIIOImageReader::CanReadFile(nullptr));
  EXPECT_FALSE(vtkOIIOImageReader::CanReadFile(dir.string().c_str()));
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName((dir / "info.tif").string().c_str());
  reader->UpdateInformation();
  EXPECT_EQ(reader->GetImageSize()[0], 8);
  EXPECT_EQ(reader->GetImageSize()[1], 5);
  EXPECT_EQ(reader->GetNumberOfChannelsInFile(), 2);
  EXPECT_STREQ(reader->GetFormatName(), "tiff");
}

TEST(OIIOImageIO, WriterReportsErrorsAndNeverLeavesBrokenFiles)
{
  const fs::path dir = mesolight_test::TestDirectory();
  auto image = Pattern<vtkUnsignedCharArray>(8, 8, 3, 255);

  const auto writeExpectingError = [&](vtkImageData* input, const fs::path& file)
  {
    vtkNew<vtkOIIOImageWriter> writer;
    vtkNew<MessageCapture> capture;
    capture->Watch(writer);
    if (input)
    {
      writer->SetInputData(input);
    }
    writer->SetFileName(file.string().c_str());
    EXPECT_FALSE(writer->Write()) << file;
    EXPECT_FALSE(capture->Errors.empty()) << file;
    EXPECT_TRUE(capture->HasError(file.string())) << capture->AllErrors();
    return writer->GetErrorCode();
  };

  EXPECT_EQ(writeExpectingError(nullptr, dir / "noinput.png"), vtkErrorCode::UserError);
  EXPECT_EQ(
    writeExpectingError(image, dir / "image.unknownext"), vtkErrorCode::UnrecognizedFileTypeError);
  EXPECT_EQ(writeExpectingError(image, dir / "no_such_dir" / "image.png"),
    vtkErrorCode::CannotOpenFileError);
  WriteBytes(dir / "afile", { 1, 2, 3 });
  EXPECT_EQ(
    writeExpectingError(image, dir / "afile" / "image.png"), vtkErrorCode::CannotOpenFileError);
  vtkNew<vtkImageData> empty;
  EXPECT_EQ(writeExpectingError(empty, dir / "empty.png"), vtkErrorCode::UserError);
  auto fiveComponents = Pattern<vtkUnsignedCharArray>(4, 4, 5, 255);
  EXPECT_EQ(writeExpectingError(fiveComponents, dir / "five.png"), vtkErrorCode::UserError);

  // A write that fails must leave an existing target untouched, and no temporary file.
  // Radiance HDR stores RGB only: OpenImageIO refuses 1-channel images when opening.
  ASSERT_TRUE(Write(image, dir / "target.png"));
  const std::vector<unsigned char> before = ReadBytes(dir / "target.png");
  EXPECT_EQ(writeExpectingError(fiveComponents, dir / "target.png"), vtkErrorCode::UserError);
  EXPECT_EQ(ReadBytes(dir / "target.png"), before);
  auto oneChannel = Pattern<vtkUnsignedCharArray>(8, 8, 1, 255);
  ASSERT_TRUE(Write(image, dir / "target.hdr"));
  const std::vector<unsigned char> hdrBefore = ReadBytes(dir / "target.hdr");
  EXPECT_EQ(writeExpectingError(oneChannel, dir / "target.hdr"), vtkErrorCode::CannotOpenFileError);
  EXPECT_EQ(ReadBytes(dir / "target.hdr"), hdrBefore);
  auto other = Pattern<vtkUnsignedCharArray>(8, 8, 1, 255);
  ASSERT_TRUE(Write(other, dir / "target.png"));
  ExpectSameImage(other, Read(dir / "target.png"));
  for (const auto& entry : fs::directory_iterator(dir))
  {
    EXPECT_EQ(entry.path().filename().string().find(".tmp-"), std::string::npos)
      << "temporary file left behind: " << entry.path();
  }
}

TEST(OIIOImageIO, ReaderRefusesPixelsBeyondItsBudgetAndCountsNonFiniteValues)
{
  const fs::path dir = mesolight_test::TestDirectory();
  auto image = Pattern<vtkFloatArray>(16, 8, 1, 1.0);
  image->GetPointData()->GetScalars()->SetComponent(3, 0, std::nan(""));
  image->GetPointData()->GetScalars()->SetComponent(5, 0, -HUGE_VAL);
  ASSERT_TRUE(Write(image, dir / "budget.tif", vtkOIIOImageWriter::FLOAT));

  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName((dir / "budget.tif").string().c_str());
  // A float TIFF: the pixels are all the budget counts (an OpenEXR also counts its line buffers).
  reader->SetMemoryBudget(16 * 8 * 4); // exactly the pixels
  reader->Update();
  EXPECT_EQ(reader->GetErrorCode(), vtkErrorCode::NoError);
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 16 * 8);
  EXPECT_EQ(reader->GetNumberOfNonFiniteValues(), 2);

  vtkNew<MessageCapture> capture;
  capture->Watch(reader);
  reader->SetMemoryBudget(16 * 8 * 4 - 1);
  reader->Update();
  EXPECT_EQ(reader->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_TRUE(capture->HasError("16 x 8 pixels")) << capture->AllErrors();
  EXPECT_TRUE(capture->HasError("more than the")) << capture->AllErrors();
}
