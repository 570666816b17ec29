// SPDX-License-Identifier: BSD-3-Clause
// vtkMedianCutLights and vtkProceduralEnvironmentSource: outputs, file row order, errors,
// CSV.
#include "MathConstants.h"
#include "vtkMedianCutLights.h"
#include "vtkOIIOImageReader.h"
#include "vtkProceduralEnvironmentSource.h"

#include "MesolightTestUtilities.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSmartPointer.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include <OpenImageIO/imageio.h>
#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <string>
#include <vector>

using mesolight_test::MessageCapture;

namespace
{

vtkSmartPointer<vtkImageData> Image(int w, int h, float value, int components = 3)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetExtent(0, w - 1, 0, h - 1, 0, 0);
  vtkNew<vtkFloatArray> a;
  a->SetNumberOfComponents(components);
  a->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  a->Fill(value);
  image->GetPointData()->SetScalars(a);
  return image;
}

double Degrees(const double a[3], const double b[3])
{
  const double c = a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
  return std::acos(std::max(-1.0, std::min(1.0, c))) * 180.0 / mesolight::Pi<double>;
}
} // namespace

TEST(MedianCutLights, OutputsOnTheSunSky)
{
  vtkNew<vtkProceduralEnvironmentSource> sky;
  sky->SetMapToSunSky();
  sky->SetResolution(256, 128);
  sky->SetSunElevation(30.0);
  sky->SetSunAzimuth(90.0); // +Y, 30 degrees up
  vtkNew<vtkMedianCutLights> lights;
  lights->SetInputConnection(sky->GetOutputPort());
  lights->SetNumberOfLights(32);
  lights->Update();
  vtkPolyData* out = lights->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), 32);
  EXPECT_EQ(out->GetNumberOfVerts(), 32);
  vtkDataArray* irradiance = out->GetPointData()->GetArray("Irradiance");
  vtkDataArray* uv = out->GetPointData()->GetArray("MapCoordinates");
  vtkDataArray* solidAngle = out->GetPointData()->GetArray("SolidAngle");
  ASSERT_TRUE(irradiance && uv && solidAngle);
  EXPECT_EQ(irradiance->GetNumberOfComponents(), 3);
  EXPECT_EQ(uv->GetNumberOfComponents(), 2);
  // The strongest light is the sun.
  double p[3];
  out->GetPoint(0, p);
  const double sun[3] = { 0.0, std::cos(mesolight::Pi<double> / 6),
    std::sin(mesolight::Pi<double> / 6) };
  EXPECT_LT(Degrees(p, sun), 1.0);
  EXPECT_NEAR(uv->GetComponent(0, 0), 0.25, 0.01);
  EXPECT_NEAR(uv->GetComponent(0, 1), 1.0 / 3.0, 0.01);
  double area = 0.0;
  for (vtkIdType k = 0; k < 32; ++k)
  {
    area += solidAngle->GetComponent(k, 0);
  }
  EXPECT_NEAR(area, 4 * mesolight::Pi<double>, 1e-4);

  // The light texture: N x 2, row 0 directions, row 1 irradiances.
  vtkImageData* texture = lights->GetLightTexture();
  ASSERT_TRUE(texture);
  int dims[3];
  texture->GetDimensions(dims);
  EXPECT_EQ(dims[0], 32);
  EXPECT_EQ(dims[1], 2);
  vtkDataArray* texels = texture->GetPointData()->GetScalars();
  ASSERT_TRUE(texels);
  EXPECT_EQ(texels->GetNumberOfComponents(), 4);
  EXPECT_NEAR(texels->GetComponent(0, 1), p[1], 1e-6);
  EXPECT_NEAR(texels->GetComponent(32, 0), irradiance->GetComponent(0, 0), 1e-3);

  // Even-energy cuts (variance minimization off) give the same count.
  lights->VarianceMinimizationOff();
  lights->SetNumberOfLights(7);
  lights->Update();
  EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 7);
}

// A raster given as the cells of a grid one point larger (ParaView's GDAL Raster Reader gives a
// float TIFF's RGB so, as a 3-component cell array) is read pixel for pixel: the same lights as
// the same pixels as point scalars; and a plain image's rows, which that reader gives top row
// first (its MAP_PROJECTION field data empty, origin 0 and pixels of 1), are turned around, a
// world file's raster (no projection, its ground origin and size) not. The negative case: those
// rows without the reader's mark (the sun below the horizon) move the strongest light by 60
// degrees.
TEST(MedianCutLights, PixelsGivenAsCellsAreThePixels)
{
  vtkNew<vtkProceduralEnvironmentSource> sky;
  sky->SetMapToSunSky();
  sky->SetResolution(128, 64);
  sky->SetSunElevation(30.0);
  sky->SetSunAzimuth(90.0);
  sky->Update();
  vtkDataArray* pixels = sky->GetOutput()->GetPointData()->GetScalars();
  const auto asCells = [&](bool flipRows, bool marked = false)
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    if (marked)
    {
      vtkNew<vtkStringArray> projection; // what GDAL Raster Reader attaches to a plain image
      projection->SetName("MAP_PROJECTION");
      projection->InsertNextValue("");
      image->GetFieldData()->AddArray(projection);
    }
    image->SetExtent(0, 128, 0, 64, 0, 0);
    vtkNew<vtkFloatArray> cells;
    cells->SetNumberOfComponents(3);
    cells->SetNumberOfTuples(128 * 64);
    for (vtkIdType j = 0; j < 64; ++j)
    {
      for (vtkIdType i = 0; i < 128; ++i)
      {
        const vtkIdType from = (flipRows ? 63 - j : j) * 128 + i;
        for (int c = 0; c < 3; ++c)
        {
          cells->SetComponent(j * 128 + i, c, pixels->GetComponent(from, c));
        }
      }
    }
    cells->SetName("Elevation"); // the GDAL reader's name for any raster
    image->GetCellData()->SetScalars(cells);
    return image;
  };
  const auto strongest = [](vtkImageData* image, std::vector<double>& irradiance)
  {
    vtkNew<vtkMedianCutLights> lights;
    vtkNew<MessageCapture> capture;
    capture->Watch(lights);
    lights->SetInputData(image);
    lights->SetNumberOfLights(16);
    lights->Update();
    EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
    EXPECT_FALSE(capture->HasWarning("not 2:1")) << "the cells are 128 x 64";
    vtkPolyData* out = lights->GetOutput();
    EXPECT_EQ(out->GetNumberOfPoints(), 16);
    irradiance.clear();
    for (vtkIdType k = 0; k < out->GetNumberOfPoints(); ++k)
    {
      irradiance.push_back(out->GetPointData()->GetArray("Irradiance")->GetComponent(k, 0));
    }
    std::vector<double> p(3, 0.0);
    if (out->GetNumberOfPoints() > 0)
    {
      out->GetPoint(0, p.data());
    }
    return p;
  };
  std::vector<double> fromPoints, fromCells, fromFlipped;
  const std::vector<double> sun = strongest(sky->GetOutput(), fromPoints);
  EXPECT_EQ(strongest(asCells(false), fromCells), sun);
  EXPECT_EQ(fromCells, fromPoints);
  EXPECT_EQ(strongest(asCells(true, true), fromFlipped), sun);
  EXPECT_EQ(fromFlipped, fromPoints);
  // A raster georeferenced by a world file has no map projection either, but GDAL gives it north
  // up, at its ground origin and pixel size: its rows stay as they are.
  vtkSmartPointer<vtkImageData> world = asCells(false, true);
  world->SetOrigin(1000.0, 1936.0, 0.0);
  world->SetSpacing(0.5, 0.5, 1.0);
  std::vector<double> fromWorld;
  EXPECT_EQ(strongest(world, fromWorld), sun);
  EXPECT_EQ(fromWorld, fromPoints);
  const std::vector<double> below = strongest(asCells(true), fromFlipped);
  EXPECT_GT(Degrees(below.data(), sun.data()), 59.0);
}

TEST(MedianCutLights, FileRowOrderZenithOnTop)
{
  // An EXR whose FIRST file row (the top of the picture) is bright must give a light at the
  // zenith: vtkOIIOImageReader flips rows, the filter reads row H-1 as v ~ 0.
  const auto dir = mesolight_test::TestDirectory();
  const std::string file = (dir / "zenith.exr").string();
  const int w = 64;
  const int h = 32;
  std::vector<float> pixels(static_cast<size_t>(w) * h * 3, 0.01f);
  for (int i = 0; i < 3 * w; ++i)
  {
    pixels[i] = 1000.0f; // file row 0
  }
  auto out = OIIO::ImageOutput::create(file);
  ASSERT_TRUE(out);
  ASSERT_TRUE(out->open(file, OIIO::ImageSpec(w, h, 3, OIIO::TypeDesc::FLOAT)));
  ASSERT_TRUE(out->write_image(OIIO::TypeDesc::FLOAT, pixels.data()));
  out->close();
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(file.c_str());
  vtkNew<vtkMedianCutLights> lights;
  lights->SetInputConnection(reader->GetOutputPort());
  lights->SetNumberOfLights(4);
  lights->Update();
  ASSERT_EQ(lights->GetOutput()->GetNumberOfPoints(), 4);
  double p[3];
  lights->GetOutput()->GetPoint(0, p);
  EXPECT_GT(p[2], 0.99);
}

TEST(MedianCutLights, BadInput)
{
  auto expectError = [](vtkImageData* image, int count, const std::string& needle)
  {
    vtkNew<vtkMedianCutLights> lights;
    vtkNew<MessageCapture> capture;
    capture->Watch(lights);
    lights->SetInputData(image);
    lights->SetNumberOfLights(count);
    lights->Update();
    EXPECT_TRUE(capture->HasError(needle))
      << "expected \"" << needle << "\", got: " << capture->AllErrors();
    EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 0);
  };
  auto nan = Image(16, 8, 1.0f);
  vtkFloatArray::SafeDownCast(nan->GetPointData()->GetScalars())
    ->SetComponent(2 * 16 + 5, 1, std::nanf(""));
  vtkFloatArray::SafeDownCast(nan->GetPointData()->GetScalars())
    ->SetComponent(7 * 16 + 1, 0, INFINITY);
  expectError(nan, 4, "contains 2 NaN or infinite value(s)");
  expectError(nan, 4, "(i=5, j=2");
  expectError(Image(16, 8, 0.0f), 4, "no light");
  {
    // Below 1: said and clamped at the setter (it was stored and refused at Update).
    vtkNew<vtkMedianCutLights> lights;
    vtkNew<MessageCapture> capture;
    capture->Watch(lights);
    lights->SetNumberOfLights(0);
    EXPECT_TRUE(capture->HasWarning("SetNumberOfLights: 0 is outside [1,"))
      << capture->AllWarnings();
    EXPECT_EQ(lights->GetNumberOfLights(), 1);
  }
  expectError(Image(16, 8, 1.0f), 129, "it is 129");
  auto short_ = Image(16, 8, 1.0f);
  short_->GetPointData()->GetScalars()->SetNumberOfTuples(100);
  expectError(short_, 4, "must be one per pixel, grey or RGB first; it has 100 values");
  // A grey map (one component, or grey and alpha) lights as the same map in RGB.
  {
    auto lightsOf = [](vtkImageData* image)
    {
      vtkNew<vtkMedianCutLights> lights;
      lights->SetInputData(image);
      lights->SetNumberOfLights(4);
      lights->Update();
      return vtkSmartPointer<vtkDataArray>(lights->GetLightTexture()->GetPointData()->GetScalars());
    };
    auto grey = Image(16, 8, 0.0f, 1);
    auto rgb = Image(16, 8, 0.0f, 3);
    for (vtkIdType p = 0; p < 128; ++p)
    {
      const float v = 0.1f + 0.01f * static_cast<float>((p * 7) % 13);
      grey->GetPointData()->GetScalars()->SetComponent(p, 0, v);
      for (int c = 0; c < 3; ++c)
      {
        rgb->GetPointData()->GetScalars()->SetComponent(p, c, v);
      }
    }
    const auto fromGrey = lightsOf(grey);
    const auto fromRgb = lightsOf(rgb);
    ASSERT_EQ(fromGrey->GetNumberOfTuples(), fromRgb->GetNumberOfTuples());
    ASSERT_GT(fromGrey->GetNumberOfTuples(), 0);
    for (vtkIdType t = 0; t < fromGrey->GetNumberOfTuples(); ++t)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(fromGrey->GetComponent(t, c), fromRgb->GetComponent(t, c)) << t << " " << c;
      }
    }
  }
  {
    vtkNew<vtkMedianCutLights> lights;
    vtkNew<MessageCapture> capture;
    capture->Watch(lights);
    lights->Update();
    EXPECT_TRUE(capture->HasError("No input image")) << capture->AllErrors();
  }

  // Warnings: not 2:1, negative values (clamped); the output is still produced.
  auto odd = Image(30, 10, 1.0f);
  vtkFloatArray::SafeDownCast(odd->GetPointData()->GetScalars())->SetComponent(3, 0, -2.0f);
  vtkNew<vtkMedianCutLights> lights;
  vtkNew<MessageCapture> capture;
  capture->Watch(lights);
  lights->SetInputData(odd);
  lights->SetNumberOfLights(5);
  lights->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_TRUE(capture->HasWarning("not 2:1"));
  EXPECT_TRUE(capture->HasWarning("1 negative value(s)"));
  EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 5);

  // Unsigned char input works (divided by 255).
  auto bytes = vtkSmartPointer<vtkImageData>::New();
  bytes->SetExtent(0, 15, 0, 7, 0, 0);
  bytes->AllocateScalars(VTK_UNSIGNED_CHAR, 4);
  vtkUnsignedCharArray::SafeDownCast(bytes->GetPointData()->GetScalars())->Fill(255);
  vtkNew<vtkMedianCutLights> fromBytes;
  fromBytes->SetInputData(bytes);
  fromBytes->SetNumberOfLights(1);
  fromBytes->Update();
  ASSERT_EQ(fromBytes->GetOutput()->GetNumberOfPoints(), 1);
  EXPECT_NEAR(fromBytes->GetOutput()->GetPointData()->GetArray("Irradiance")->GetComponent(0, 0),
    4 * mesolight::Pi<double>, 1e-4);
}

// An 8-bit map (a JPEG or PNG panorama) is sRGB-encoded and clipped: its lights come with a
// warning that says so; a float map of the same values gets none.
TEST(MedianCutLights, EightBitMapsAreWarnedAbout)
{
  const auto warned = [](vtkImageData* image)
  {
    vtkNew<vtkMedianCutLights> lights;
    vtkNew<MessageCapture> capture;
    capture->Watch(lights);
    lights->SetInputData(image);
    lights->SetNumberOfLights(4);
    lights->Update();
    EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 4);
    return capture->HasWarning("The environment map is 8-bit");
  };
  auto bytes = vtkSmartPointer<vtkImageData>::New();
  bytes->SetDimensions(16, 8, 1);
  bytes->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  vtkDataArray* values = bytes->GetPointData()->GetScalars();
  for (vtkIdType k = 0; k < values->GetNumberOfValues(); ++k)
  {
    values->SetVariantValue(k, static_cast<unsigned char>(40 + k % 200));
  }
  EXPECT_TRUE(warned(bytes));
  EXPECT_FALSE(warned(Image(16, 8, 1.0f)));
}

TEST(MedianCutLights, Abort)
{
  vtkNew<vtkProceduralEnvironmentSource> sky;
  vtkNew<vtkMedianCutLights> lights;
  lights->SetInputConnection(sky->GetOutputPort());
  // Abort from a progress observer, as a GUI would.
  vtkNew<vtkCallbackCommand> abort;
  abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
    { static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1); });
  lights->AddObserver(vtkCommand::ProgressEvent, abort);
  lights->Update();
  EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 0);
  lights->RemoveAllObservers();
  lights->Modified();
  lights->Update();
  EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 64);
}

TEST(MedianCutLights, CsvHeaderAndRows)
{
  const auto dir = mesolight_test::TestDirectory();
  vtkNew<vtkProceduralEnvironmentSource> sky;
  sky->SetResolution(128, 64);
  vtkNew<vtkMedianCutLights> lights;
  lights->SetInputConnection(sky->GetOutputPort());
  lights->SetNumberOfLights(12);
  lights->Update();
  std::string error;
  const std::string file = (dir / "lights.csv").string();
  ASSERT_TRUE(vtkMedianCutLights::WriteCsv(lights->GetOutput(), file, error)) << error;
  std::ifstream in(file);
  std::string line;
  std::getline(in, line);
  EXPECT_EQ(line, "u,v,x,y,z,r,g,b");
  int rows = 0;
  while (std::getline(in, line))
  {
    int commas = 0;
    for (char c : line)
    {
      commas += c == ',' ? 1 : 0;
    }
    EXPECT_EQ(commas, 7);
    ++rows;
  }
  EXPECT_EQ(rows, 12);
  EXPECT_FALSE(
    vtkMedianCutLights::WriteCsv(lights->GetOutput(), (dir / "no" / "x.csv").string(), error));
  vtkNew<vtkPolyData> empty;
  EXPECT_FALSE(vtkMedianCutLights::WriteCsv(empty, file, error));
}

TEST(ProceduralEnvironmentSource, SunAtItsDirection)
{
  vtkNew<vtkProceduralEnvironmentSource> sky;
  sky->SetMapToSunSky();
  sky->SetResolution(512, 256);
  sky->SetSunElevation(0.0);
  sky->SetSunAzimuth(0.0);
  sky->Update();
  vtkImageData* image = sky->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  EXPECT_EQ(dims[0], 512);
  EXPECT_EQ(dims[1], 256);
  vtkDataArray* radiance = image->GetPointData()->GetArray("Radiance");
  ASSERT_TRUE(radiance);
  // Sun on the +X horizon: u = 0 (the left/right edges), v = 0.5 (rows 127 and 128).
  double best = -1.0;
  int bi = -1;
  int bj = -1;
  double top = 0.0;
  double bottom = 0.0;
  for (int j = 0; j < 256; ++j)
  {
    for (int i = 0; i < 512; ++i)
    {
      const double r = radiance->GetComponent(j * 512 + i, 0);
      if (r > best)
      {
        best = r;
        bi = i;
        bj = j;
      }
    }
  }
  top = radiance->GetComponent(255 * 512, 2);
  bottom = radiance->GetComponent(0, 2);
  EXPECT_TRUE(bi <= 2 || bi >= 509) << bi;
  EXPECT_TRUE(bj == 127 || bj == 128) << bj;
  EXPECT_GT(top, 5 * bottom); // sky (blue) on top in VTK row order, ground at row 0
}

// Above MemoryBudget the median cut is refused before anything is allocated: 256 x 128 pixels at
// 28 bytes (RGB floats, one summed-area table, energies) need 896 KiB.
TEST(MedianCutLights, MemoryBudgetRefusesBeforeAllocating)
{
  vtkNew<vtkProceduralEnvironmentSource> sky;
  sky->SetResolution(256, 128);
  vtkNew<vtkMedianCutLights> lights;
  lights->SetInputConnection(sky->GetOutputPort());
  lights->SetNumberOfLights(8);
  lights->SetMemoryBudget(1024 * 1024);
  vtkNew<MessageCapture> capture;
  capture->Watch(lights);
  lights->Update();
  // Variance-minimizing cuts (the default): five tables and the cell energies, in double.
  EXPECT_TRUE(capture->HasError("256 x 128 environment needs about 2 MiB")) << capture->AllErrors();
  EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 0);
  // Even-energy cuts need one table.
  lights->VarianceMinimizationOff();
  lights->SetMemoryBudget(512 * 1024);
  capture->Errors.clear();
  lights->Update();
  EXPECT_TRUE(capture->HasError("256 x 128 environment needs about 896 KiB"))
    << capture->AllErrors();
  lights->SetMemoryBudget(1024 * 1024);
  capture->Errors.clear();
  lights->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 8);
}

// Finite values near FLT_MAX overflow single-precision shading (a black wall): refused with an
// error; a bright but summable map still gives lights.
TEST(MedianCutLights, EnvironmentsTooBrightToShadeAreRefused)
{
  for (const float value : { 3e38f, 1e30f })
  {
    vtkNew<vtkMedianCutLights> lights;
    vtkNew<MessageCapture> capture;
    capture->Watch(lights);
    lights->SetInputData(Image(16, 8, value));
    lights->SetNumberOfLights(4);
    lights->Update();
    EXPECT_TRUE(capture->HasError("single-precision shading")) << value << capture->AllErrors();
    EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 0);
  }
  vtkNew<vtkMedianCutLights> lights;
  vtkNew<MessageCapture> capture;
  capture->Watch(lights);
  lights->SetInputData(Image(16, 8, 1e20f));
  lights->SetNumberOfLights(4);
  lights->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_EQ(lights->GetOutput()->GetNumberOfPoints(), 4);
}
