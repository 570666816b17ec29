// SPDX-License-Identifier: BSD-3-Clause
// vtkReliefTextureFilter: conversions, options, and errors on bad input.
#include "SobelNormals.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefTextureFilter.h"

#include "MesolightTestUtilities.h"

#include "vtkCellData.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"
#include "vtkUnsignedShortArray.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

using mesolight_test::MessageCapture;

namespace
{
template <typename ArrayT>
vtkSmartPointer<vtkImageData> MakeImage(
  int w, int h, int nComp, const std::vector<typename ArrayT::ValueType>& values)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<ArrayT> scalars;
  scalars->SetNumberOfComponents(nComp);
  scalars->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (size_t k = 0; k < values.size(); ++k)
  {
    scalars->SetValue(static_cast<vtkIdType>(k), values[k]);
  }
  image->GetPointData()->SetScalars(scalars);
  return image;
}

vtkFloatArray* Relief(vtkReliefTextureFilter* filter)
{
  return vtkFloatArray::SafeDownCast(filter->GetOutput()->GetPointData()->GetScalars());
}
}

TEST(vtkReliefTextureFilter, MatchesCoreAndStoresDepthScale)
{
  vtkNew<vtkProceduralReliefSource> source;
  source->SetPatternToHemisphereTorus();
  source->SetResolution(200, 150);
  vtkNew<vtkReliefTextureFilter> filter;
  filter->SetInputConnection(source->GetOutputPort(0));
  filter->SetDepthScale(0.2);
  filter->SetBorderModeToWrap();
  filter->Update();

  vtkFloatArray* relief = Relief(filter);
  ASSERT_NE(relief, nullptr);
  EXPECT_STREQ(relief->GetName(), "Relief");
  EXPECT_EQ(relief->GetNumberOfComponents(), 4);
  ASSERT_EQ(relief->GetNumberOfTuples(), 200 * 150);
  int dims[3];
  filter->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 200);
  EXPECT_EQ(dims[1], 150);

  vtkDataArray* scale = filter->GetOutput()->GetFieldData()->GetArray("MesolightDepthScale");
  ASSERT_NE(scale, nullptr);
  EXPECT_EQ(scale->GetDataType(), VTK_FLOAT);
  EXPECT_EQ(scale->GetNumberOfTuples(), 1);
  EXPECT_FLOAT_EQ(static_cast<float>(scale->GetComponent(0, 0)), 0.2f);

  // The parallel VTK wrapper gives exactly the serial core result.
  auto* depth =
    static_cast<float*>(source->GetDepthOutput()->GetPointData()->GetScalars()->GetVoidPointer(0));
  std::vector<float> expected(4 * 200 * 150);
  mesolight::ComputeReliefTexture(
    depth, 200, 150, 0.2f, mesolight::BorderMode::Wrap, expected.data());
  EXPECT_TRUE(std::equal(expected.begin(), expected.end(), relief->GetPointer(0)));
}

// The depth scale as vtkReliefProperty takes it (common/DepthScaleSetting.h): NaN refused and the
// value kept, out-of-range values clamped and said.
TEST(vtkReliefTextureFilter, DepthScaleOutOfRangeIsSaid)
{
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->SetDepthScale(0.1);
  EXPECT_TRUE(capture->AllWarnings().empty() && capture->AllErrors().empty());
  filter->SetDepthScale(std::nan(""));
  EXPECT_EQ(filter->GetDepthScale(), 0.1);
  EXPECT_TRUE(capture->HasError("NaN is not a depth scale; keeping 0.1")) << capture->AllErrors();
  filter->SetDepthScale(-0.04);
  EXPECT_EQ(filter->GetDepthScale(), 0.0);
  EXPECT_TRUE(capture->HasWarning("Invert Input")) << capture->AllWarnings();
  // The mapper's own limit (it used to clamp a texture's scale above 10 without a word).
  filter->SetDepthScale(50.0);
  EXPECT_EQ(filter->GetDepthScale(), 10.0);
  EXPECT_TRUE(capture->HasWarning("clamped to 10 ")) << capture->AllWarnings();
}

TEST(vtkReliefTextureFilter, IntegerInputsAreNormalised)
{
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture; // these tiny images warn about 1-texel dimensions
  capture->Watch(filter);
  filter->SetInputData(MakeImage<vtkUnsignedCharArray>(2, 1, 1, { 51, 255 }));
  filter->Update();
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 3), 0.2f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 3), 1.f);

  filter->SetInputData(MakeImage<vtkUnsignedShortArray>(2, 1, 1, { 0, 65535 }));
  filter->Update();
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 3), 0.f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 3), 1.f);

  // RGB: luminance 0.2126 R + 0.7152 G + 0.0722 B; 2 components: the first one.
  filter->SetInputData(MakeImage<vtkUnsignedCharArray>(1, 1, 3, { 255, 0, 0 }));
  filter->Update();
  EXPECT_NEAR(Relief(filter)->GetComponent(0, 3), 0.2126, 1e-6);
  filter->SetInputData(MakeImage<vtkUnsignedCharArray>(1, 1, 2, { 0, 255 }));
  filter->Update();
  EXPECT_EQ(Relief(filter)->GetComponent(0, 3), 0.0);
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
}

TEST(vtkReliefTextureFilter, InvertAndNormalize)
{
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);

  // Height map: white = high = depth 0.
  filter->SetInputData(MakeImage<vtkFloatArray>(3, 1, 1, { 0.f, 0.25f, 1.f }));
  filter->InvertInputOn();
  filter->Update();
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 3), 1.f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 3), 0.75f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(2, 3), 0.f);
  filter->InvertInputOff();

  // Refused with an error that points at NormalizeRange (and says `what`), drawn with it.
  const auto refusedWithoutNormalizeRange = [&](vtkImageData* image, const char* what)
  {
    filter->SetInputData(image);
    filter->NormalizeRangeOff();
    filter->Update();
    EXPECT_TRUE(capture->HasError("NormalizeRange")) << capture->AllErrors();
    EXPECT_TRUE(capture->HasError(what)) << capture->AllErrors();
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
    capture->Errors.clear();
    filter->NormalizeRangeOn();
    filter->Update();
    EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  };
  // Out-of-range floats.
  refusedWithoutNormalizeRange(MakeImage<vtkFloatArray>(3, 1, 1, { 10.f, 15.f, 20.f }), "[10, 20]");
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 3), 0.f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 3), 0.5f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(2, 3), 1.f);
  // Signed integers hold measurements: int16 elevations (141-547 m, as in r-cran-terra's
  // elev.tif) lie in [0, 32767] and as fractions of it would draw a flat wall (unsigned ones are
  // fractions: the test above).
  refusedWithoutNormalizeRange(MakeImage<vtkShortArray>(3, 1, 1, { 141, 344, 547 }),
    "signed integers (short, stored values [141, 547])");
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 3), 0.5f);
}

namespace
{
/// The elevations of the no-data tests: -100..300 m, two texels holding `none`.
vtkSmartPointer<vtkImageData> NoDataDem(short none)
{
  return MakeImage<vtkShortArray>(3, 2, 1, { -100, 0, none, 300, none, 200 });
}

/// An elevation map's settings: a height map in metres.
void SetElevations(vtkReliefTextureFilter* filter, vtkImageData* dem)
{
  filter->SetInputData(dem);
  filter->InvertInputOn();
  filter->NormalizeRangeOn();
}
} // namespace

TEST(vtkReliefTextureFilter, ElevationsWithNoDataAreNormalisedWithoutIt)
{
  // An int16 DEM as GDAL writes one: elevations in metres, some below sea level, and -32768
  // where there is no data. Height map (white = high): depth = 1 - normalised elevation.
  const short none = -32768;
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  SetElevations(filter, NoDataDem(none));
  filter->SetNoDataValue(none);
  filter->UseNoDataValueOn();
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  // The range of the elevations alone, -100..300 m, signed values unclamped; no data: the
  // lowest ground (depth 1).
  const std::vector<float> expected = { 1.f, 0.75f, 1.f, 0.f, 1.f, 0.25f };
  for (vtkIdType k = 0; k < 6; ++k)
  {
    EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(k, 3), expected[k]) << "texel " << k;
  }

  // Without UseNoDataValue -32768 is an elevation: it stretches the range and the elevations
  // all land within 1.3% of the top (the negative case).
  filter->UseNoDataValueOff();
  filter->Update();
  EXPECT_NEAR(Relief(filter)->GetComponent(3, 3), 0.f, 1e-6);
  EXPECT_LT(Relief(filter)->GetComponent(0, 3), 0.013f);
  EXPECT_LT(Relief(filter)->GetComponent(5, 3), 0.013f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(2, 3), 1.f);

  // Without NormalizeRange the elevations are out of range: the error gives the stored values
  // too, the units of a no-data value.
  filter->NormalizeRangeOff();
  filter->Update();
  EXPECT_TRUE(capture->HasError("stored values [-32768, 300]")) << capture->AllErrors();
  capture->Errors.clear();
  filter->NormalizeRangeOn();

  // A depth map (not inverted): no data takes the deepest value of the others; NaN as the
  // no-data value marks NaN texels, which are otherwise an error.
  const float nan = std::numeric_limits<float>::quiet_NaN();
  filter->SetInputData(MakeImage<vtkFloatArray>(3, 1, 1, { 0.2f, nan, 0.6f }));
  filter->InvertInputOff();
  filter->NormalizeRangeOff();
  filter->Update();
  EXPECT_TRUE(capture->HasError("NaN")) << capture->AllErrors();
  capture->Errors.clear();
  filter->SetNoDataValue(nan);
  filter->UseNoDataValueOn();
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 3), 0.6f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 3), 0.2f);

  // A float DEM's no-data value as gdalinfo prints it, -9999.9, is not a float: it is compared
  // as the stored float (with doubles the holes would be elevations, the negative case).
  filter->SetInputData(MakeImage<vtkFloatArray>(3, 1, 1, { 0.2f, -9999.9f, 0.6f }));
  filter->SetNoDataValue(-9999.9);
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_EQ(filter->GetNumberOfNoDataTexels(), 1);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 3), 0.6f);

  // Nothing but no data: an error, no output.
  filter->SetInputData(MakeImage<vtkShortArray>(2, 1, 1, { none, none }));
  filter->SetNoDataValue(none);
  filter->Update();
  EXPECT_TRUE(capture->HasError("Every texel holds the no-data value")) << capture->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(vtkReliefTextureFilter, TheImagesOwnNoDataValueAppliesByDefault)
{
  // vtkOIIOImageReader passes a GeoTIFF's GDAL_NODATA on as field data "MesolightNoDataValue".
  const short none = -9999;
  const auto dem = NoDataDem(none);
  vtkNew<vtkDoubleArray> named;
  named->SetName("MesolightNoDataValue");
  named->InsertNextValue(none);
  dem->GetFieldData()->AddArray(named);
  vtkNew<vtkReliefTextureFilter> filter;
  SetElevations(filter, dem);
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  EXPECT_TRUE(filter->GetUseInputNoDataValue()); // the default
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_TRUE(filter->GetAppliedNoData());
  EXPECT_EQ(filter->GetAppliedNoDataValue(), -9999.0);
  EXPECT_EQ(filter->GetNumberOfNoDataTexels(), 2);
  const std::vector<float> expected = { 1.f, 0.75f, 1.f, 0.f, 1.f, 0.25f };
  for (vtkIdType k = 0; k < 6; ++k)
  {
    EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(k, 3), expected[k]) << "texel " << k;
  }

  // Turned off, -9999 is an elevation again (the negative case): the others crowd at the top.
  filter->UseInputNoDataValueOff();
  filter->Update();
  EXPECT_FALSE(filter->GetAppliedNoData());
  EXPECT_EQ(filter->GetNumberOfNoDataTexels(), 0);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(2, 3), 1.f);
  EXPECT_LT(Relief(filter)->GetComponent(0, 3), 0.05f);

  // A value set on the filter wins over the image's: 0 m is the hole now, -9999 the lowest
  // ground measured.
  filter->UseInputNoDataValueOn();
  filter->SetNoDataValue(0);
  filter->UseNoDataValueOn();
  filter->Update();
  EXPECT_EQ(filter->GetAppliedNoDataValue(), 0.0);
  EXPECT_EQ(filter->GetNumberOfNoDataTexels(), 1);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(2, 3), 1.f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 3), 1.f);
  EXPECT_LT(Relief(filter)->GetComponent(0, 3), 0.05f);
}

TEST(vtkReliefTextureFilter, PixelsAsCellsAreReadAtTheirCorners)
{
  // GDAL Raster Reader's output as the filter meets it in ParaView: a grid one point larger than
  // the raster, the pixels as cells, the cells without data hidden (blanked). Each texel (a
  // point) is the mean of the cells around it that have data.
  const int cw = 3;
  const int ch = 2;
  const std::vector<float> elevations = { 10, 20, 30, 40, 50, 60 }; // row 0 first
  vtkNew<vtkImageData> raster;
  raster->SetDimensions(cw + 1, ch + 1, 1);
  vtkNew<vtkFloatArray> cellValues;
  cellValues->SetName("Elevation");
  for (const float e : elevations)
  {
    cellValues->InsertNextValue(e);
  }
  cellValues->SetValue(5, -9999.f); // the top right cell: no data, hidden
  raster->GetCellData()->SetScalars(cellValues);
  raster->AllocateCellGhostArray();
  raster->GetCellGhostArray()->SetValue(5, vtkDataSetAttributes::HIDDENCELL);

  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->SetInputData(raster);
  filter->NormalizeRangeOn(); // a depth map in metres: 10 m at the top, 50 m the deepest
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  int dims[3];
  filter->GetOutput()->GetDimensions(dims);
  ASSERT_EQ(dims[0], cw + 1);
  ASSERT_EQ(dims[1], ch + 1);
  // Corner means by hand (points row by row, bottom first); the top right point has only the
  // hidden cell: no data, the deepest depth of the others.
  const std::vector<double> corners = { 10, 15, 25, 30, 25, 30, 100.0 / 3.0, 30, 40, 45, 50, -1 };
  EXPECT_EQ(filter->GetNumberOfNoDataTexels(), 1);
  for (vtkIdType k = 0; k < 12; ++k)
  {
    const double expected = corners[k] < 0 ? 1.0 : (corners[k] - 10.0) / 40.0;
    EXPECT_NEAR(Relief(filter)->GetComponent(k, 3), expected, 1e-6) << "texel " << k;
  }
  // The blanking is the input's own marking: with UseInputNoDataValue off, -9999 is terrain (the
  // negative case) and pulls the corners around it towards the top.
  filter->UseInputNoDataValueOff();
  filter->Update();
  EXPECT_EQ(filter->GetNumberOfNoDataTexels(), 0);
  EXPECT_NEAR(Relief(filter)->GetComponent(11, 3), 0.0, 1e-6);

  // A plain image (not georeferenced) through GDAL Raster Reader comes top row first, marked by
  // an empty MAP_PROJECTION (common/vtkRasterRowOrder.h): the texels' rows are turned around, so
  // the picture's bottom row is texel row 0 as from every other reader.
  filter->UseInputNoDataValueOn();
  vtkNew<vtkStringArray> projection;
  projection->SetName("MAP_PROJECTION");
  projection->InsertNextValue("");
  raster->GetFieldData()->AddArray(projection);
  filter->Update();
  for (vtkIdType k = 0; k < 12; ++k)
  {
    const vtkIdType mirrored = (2 - k / 4) * 4 + k % 4;
    const double expected = corners[mirrored] < 0 ? 1.0 : (corners[mirrored] - 10.0) / 40.0;
    EXPECT_NEAR(Relief(filter)->GetComponent(k, 3), expected, 1e-6) << "texel " << k;
  }
}

TEST(vtkReliefTextureFilter, TrueDepthScaleOfAGeoreferencedElevationMap)
{
  // 4 x 3 elevations, 100-400 m, pixels 50 m wide on the ground: the map is 200 m wide and 300 m
  // deep, so its true depth scale is 1.5, and the relief baked with it is the one baked with
  // DepthScale 1.5 (times the exaggeration), normals included.
  auto dem = MakeImage<vtkShortArray>(
    4, 3, 1, { 100, 150, 200, 250, 120, 180, 260, 300, 100, 250, 400, 350 });
  vtkNew<vtkDoubleArray> pixelSize;
  pixelSize->SetName("MesolightPixelSize");
  pixelSize->SetNumberOfComponents(2);
  pixelSize->InsertNextTuple2(50.0, 70.0);
  dem->GetFieldData()->AddArray(pixelSize);

  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->SetInputData(dem);
  filter->InvertInputOn();
  filter->NormalizeRangeOn();
  filter->Update();
  EXPECT_NEAR(filter->GetTrueDepthScale(), 1.5, 1e-12);
  EXPECT_EQ(filter->GetAppliedDepthScale(), 0.05); // off by default: DepthScale
  vtkDataArray* trueScale =
    filter->GetOutput()->GetFieldData()->GetArray("MesolightTrueDepthScale");
  ASSERT_NE(trueScale, nullptr);
  EXPECT_NEAR(trueScale->GetComponent(0, 0), 1.5, 1e-12);

  vtkNew<vtkReliefTextureFilter> byHand;
  byHand->SetInputData(dem);
  byHand->InvertInputOn();
  byHand->NormalizeRangeOn();
  for (const double exaggeration : { 1.0, 0.2 })
  {
    filter->UseTrueDepthScaleOn();
    filter->SetVerticalExaggeration(exaggeration);
    filter->Update();
    ASSERT_TRUE(capture->Errors.empty()) << capture->AllErrors();
    EXPECT_NEAR(filter->GetAppliedDepthScale(), 1.5 * exaggeration, 1e-12);
    EXPECT_NEAR(
      filter->GetOutput()->GetFieldData()->GetArray("MesolightDepthScale")->GetComponent(0, 0),
      1.5 * exaggeration, 1e-6);
    byHand->SetDepthScale(1.5 * exaggeration);
    byHand->Update();
    for (vtkIdType k = 0; k < 12; ++k)
    {
      for (int c = 0; c < 4; ++c)
      {
        EXPECT_NEAR(Relief(filter)->GetComponent(k, c), Relief(byHand)->GetComponent(k, c), 1e-6)
          << "texel " << k << ", component " << c;
      }
    }
  }
  // Elevations in feet (the file's vertical unit, MesolightElevationUnit): 300 ft over 200 m.
  vtkNew<vtkDoubleArray> feet;
  feet->SetName("MesolightElevationUnit");
  feet->InsertNextValue(0.3048);
  dem->GetFieldData()->AddArray(feet);
  dem->Modified();
  filter->SetVerticalExaggeration(1.0);
  filter->Update();
  ASSERT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_NEAR(filter->GetTrueDepthScale(), 1.5 * 0.3048, 1e-12);
  EXPECT_NEAR(filter->GetAppliedDepthScale(), 1.5 * 0.3048, 1e-12);
  // A unit that is neither metres nor feet (the reader gives 0): refused, naming it.
  feet->SetValue(0, 0.0);
  dem->Modified();
  filter->Update();
  EXPECT_TRUE(capture->HasError("elevations in metres or feet")) << capture->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  capture->Errors.clear();
  dem->GetFieldData()->RemoveArray("MesolightElevationUnit");
  dem->Modified();
  filter->SetVerticalExaggeration(0.2);
  filter->Update();
  ASSERT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  // The negative case: the default depth scale gives other normals.
  byHand->SetDepthScale(0.05);
  byHand->Update();
  EXPECT_GT(
    std::abs(Relief(filter)->GetComponent(5, 0) - Relief(byHand)->GetComponent(5, 0)), 0.01);

  // Refused, naming what is missing: without NormalizeRange (depths in [0, 1] are no metres),
  // and without a pixel size.
  auto unit = MakeImage<vtkFloatArray>(2, 2, 1, { 0.f, 0.5f, 0.25f, 1.f });
  unit->GetFieldData()->AddArray(pixelSize);
  filter->SetInputData(unit);
  filter->NormalizeRangeOff();
  filter->Update();
  EXPECT_TRUE(capture->HasError("needs NormalizeRange on")) << capture->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  filter->SetInputData(dem);
  filter->NormalizeRangeOn();
  dem->GetFieldData()->RemoveArray("MesolightPixelSize");
  dem->Modified();
  capture->Errors.clear();
  filter->Update();
  EXPECT_TRUE(capture->HasError("carries its pixel size on the ground")) << capture->AllErrors();
  EXPECT_EQ(filter->GetTrueDepthScale(), 0.0);
  // A corrupt pixel size: not finite, or so small that the relief would be hundreds of times
  // deeper than wide. Refused, no output.
  for (const double bad : { std::numeric_limits<double>::infinity(), 1e-6 })
  {
    vtkNew<vtkDoubleArray> corrupt;
    corrupt->SetName("MesolightPixelSize");
    corrupt->SetNumberOfComponents(2);
    corrupt->InsertNextTuple2(bad, bad);
    dem->GetFieldData()->AddArray(corrupt);
    dem->Modified();
    capture->Errors.clear();
    filter->Update();
    EXPECT_FALSE(capture->Errors.empty()) << bad;
    EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0) << bad;
  }
  EXPECT_TRUE(capture->HasError("above 10,")) << capture->AllErrors();
}

// A flat elevation map (a lake or sea tile) is the surface's plane: depth 0 with InvertInput
// too (it was depth 1, the relief sunk to its deepest), and at its true vertical scale a depth
// scale of 0 (it was refused: "needs elevations that vary").
TEST(vtkReliefTextureFilter, ConstantElevationsAreTheFlatPlane)
{
  auto lake = MakeImage<vtkShortArray>(3, 2, 1, { 12, 12, 12, 12, 12, 12 });
  vtkNew<vtkDoubleArray> pixelSize;
  pixelSize->SetName("MesolightPixelSize");
  pixelSize->SetNumberOfComponents(2);
  pixelSize->InsertNextTuple2(30.0, 30.0);
  lake->GetFieldData()->AddArray(pixelSize);
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->SetInputData(lake);
  filter->InvertInputOn();
  filter->NormalizeRangeOn();
  filter->UseTrueDepthScaleOn();
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_TRUE(capture->HasWarning("mapped to depth 0"));
  EXPECT_EQ(filter->GetAppliedDepthScale(), 0.0);
  ASSERT_EQ(filter->GetOutput()->GetNumberOfPoints(), 6);
  for (vtkIdType k = 0; k < 6; ++k)
  {
    EXPECT_EQ(Relief(filter)->GetComponent(k, 3), 0.0f) << "texel " << k;
  }
}

// An int16 DEM whose holes hold -32768 without a no-data value set spans 36 km of "elevation":
// the refusal says which value looks like no-data and how to name it.
TEST(vtkReliefTextureFilter, ANoDataLookingMinimumIsNamed)
{
  auto dem = MakeImage<vtkShortArray>(4, 1, 1, { -32768, 0, 2000, 4000 });
  vtkNew<vtkDoubleArray> pixelSize;
  pixelSize->SetName("MesolightPixelSize");
  pixelSize->SetNumberOfComponents(2);
  pixelSize->InsertNextTuple2(250.0, 250.0);
  dem->GetFieldData()->AddArray(pixelSize);
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->SetInputData(dem);
  filter->NormalizeRangeOn();
  filter->UseTrueDepthScaleOn();
  filter->Update();
  EXPECT_TRUE(capture->HasError("-32768, looks like a no-data value")) << capture->AllErrors();
  EXPECT_TRUE(capture->HasError("--no-data=-32768")) << capture->AllErrors();
  // Named, the holes are left out: 4 km over 1 km is refused no more.
  capture->Errors.clear();
  filter->UseNoDataValueOn();
  filter->SetNoDataValue(-32768);
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_NEAR(filter->GetAppliedDepthScale(), 4.0, 1e-12);
}

TEST(vtkReliefTextureFilter, NonFiniteValuesAreRejected)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> values(4 * 3, 0.5f);
  values[2 * 4 + 3] = nan; // texel (i=3, j=2)
  values[2 * 4 + 1] = inf;
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->SetInputData(MakeImage<vtkFloatArray>(4, 3, 1, values));
  filter->NormalizeRangeOn(); // must not hide NaNs
  filter->Update();
  ASSERT_FALSE(capture->Errors.empty());
  EXPECT_TRUE(capture->HasError("2 NaN or infinite")) << capture->AllErrors();
  EXPECT_TRUE(capture->HasError("(i=1, j=2)")) << capture->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(vtkReliefTextureFilter, EmptyAndMissingInput)
{
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->Update();
  EXPECT_TRUE(capture->HasError("No input")) << capture->AllErrors();

  capture->Errors.clear();
  vtkNew<vtkImageData> empty;
  filter->SetInputData(empty);
  filter->Update();
  EXPECT_TRUE(capture->HasError("empty")) << capture->AllErrors();

  capture->Errors.clear();
  vtkNew<vtkImageData> noScalars;
  noScalars->SetDimensions(4, 4, 1);
  filter->SetInputData(noScalars);
  filter->Update();
  EXPECT_TRUE(capture->HasError("no point or cell scalars")) << capture->AllErrors();

  // Cells one point wide: no 2D cell to read depths from.
  capture->Errors.clear();
  vtkNew<vtkImageData> line;
  line->SetDimensions(4, 1, 1);
  vtkNew<vtkFloatArray> lineDepth;
  lineDepth->SetNumberOfTuples(line->GetNumberOfCells());
  lineDepth->FillValue(0.5f);
  line->GetCellData()->SetScalars(lineDepth);
  filter->SetInputData(line);
  filter->Update();
  EXPECT_TRUE(capture->HasError("no 2D cell")) << capture->AllErrors();

  capture->Errors.clear();
  vtkNew<vtkImageData> volume;
  volume->SetDimensions(4, 4, 2);
  volume->AllocateScalars(VTK_FLOAT, 1);
  filter->SetInputData(volume);
  filter->Update();
  EXPECT_TRUE(capture->HasError("2D image")) << capture->AllErrors();
}

TEST(vtkReliefTextureFilter, DegenerateSizesWarnAndAreFlat)
{
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->SetDepthScale(1.0);

  filter->SetInputData(MakeImage<vtkFloatArray>(1, 1, 1, { 0.4f }));
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_TRUE(capture->HasWarning("1-texel")) << "expected a warning";
  ASSERT_EQ(Relief(filter)->GetNumberOfTuples(), 1);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 0), 0.5f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 1), 0.5f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 2), 1.f);
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(0, 3), 0.4f);

  // 1 x 4 column with a slope along j: x stays flat, y tilts.
  capture->Warnings.clear();
  filter->SetInputData(MakeImage<vtkFloatArray>(1, 4, 1, { 0.f, 0.1f, 0.2f, 0.3f }));
  filter->Update();
  EXPECT_TRUE(capture->HasWarning("flat along x"));
  EXPECT_FLOAT_EQ(Relief(filter)->GetComponent(1, 0), 0.5f);
  // Slope 0.1 per texel, W = 1, DepthScale 1: n = normalize(0, 0.1, 1).
  EXPECT_NEAR(2 * Relief(filter)->GetComponent(1, 1) - 1, 0.1 / std::sqrt(1.01), 1e-6);
}

// The working memory is estimated before allocating: above MemoryBudget the filter refuses with
// the size it needs (28 bytes per texel: 64 x 32 texels need 56 KiB) instead of allocating.
TEST(vtkReliefTextureFilter, MemoryBudgetRefusesBeforeAllocating)
{
  vtkNew<vtkReliefTextureFilter> filter;
  vtkNew<MessageCapture> capture;
  capture->Watch(filter);
  filter->SetInputData(MakeImage<vtkFloatArray>(64, 32, 1, std::vector<float>(64 * 32, 0.5f)));
  filter->SetMemoryBudget(50 * 1024);
  filter->Update();
  EXPECT_TRUE(capture->HasError("64 x 32 relief texture needs about 56 KiB"))
    << capture->AllErrors();
  EXPECT_TRUE(capture->HasError("budget of 50 KiB")) << capture->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  filter->SetMemoryBudget(64 * 1024);
  capture->Errors.clear();
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 64 * 32);
}
