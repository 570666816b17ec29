// SPDX-License-Identifier: BSD-3-Clause
// vtkLightProbeToLatLong: a synthetic environment with bright spots at known directions, turned
// into an angular map and a mirror ball by the core's inverse mappings, comes back with the
// spots at the right lat-long pixels; a wrong probe frame must put them elsewhere.
#include "EnvironmentMaps.h"
#include "MessageCapture.h"
#include "vtkLightProbeToLatLong.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
using mesolight_test::MessageCapture;

// A dark map with two bright spots: the zenith and the +Y horizon.
mesolight::RgbImage SpotMap(int w, int h)
{
  mesolight::RgbImage map(w, h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      double d[3];
      mesolight::DirectionFromMapUV(
        mesolight::PixelCenterU(i, w), mesolight::PixelCenterV(j, h), d);
      const bool zenith = d[2] > std::cos(0.15);
      const bool plusY = d[1] > std::cos(0.15);
      float* px = map.Pixel(i, j);
      px[0] = px[1] = px[2] = zenith ? 50.0f : (plusY ? 20.0f : 0.1f);
    }
  }
  return map;
}

vtkSmartPointer<vtkImageData> ToImage(const mesolight::RgbImage& rgb)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(rgb.Width, rgb.Height, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(rgb.Width) * rgb.Height);
  std::copy(rgb.Rgb.begin(), rgb.Rgb.end(), values->GetPointer(0));
  image->GetPointData()->SetScalars(values);
  return image;
}

// Radiance of the lat-long output in a direction.
double Radiance(vtkImageData* map, const double d[3])
{
  int dims[3];
  map->GetDimensions(dims);
  double u, v;
  mesolight::MapUVFromDirection(d, u, v);
  const int i = std::min(dims[0] - 1, static_cast<int>(u * dims[0]));
  const int j = std::min(dims[1] - 1, static_cast<int>((1.0 - v) * dims[1])); // VTK row order
  return map->GetPointData()->GetScalars()->GetComponent(
    static_cast<vtkIdType>(j) * dims[0] + i, 0);
}
} // namespace

TEST(LightProbeToLatLong, SpotsComeBackWhereTheyWere)
{
  const mesolight::RgbImage map = SpotMap(256, 128);
  const mesolight::ProbeView view; // looking along +X, up +Z
  const double zenith[3] = { 0, 0, 1 };
  const double plusY[3] = { 0, 1, 0 };
  const double minusY[3] = { 0, -1, 0 };
  for (int type : { vtkLightProbeToLatLong::ANGULAR_MAP, vtkLightProbeToLatLong::MIRROR_BALL })
  {
    const mesolight::RgbImage probe = type == vtkLightProbeToLatLong::ANGULAR_MAP
      ? mesolight::LatLongToAngularMap(map, view, 256)
      : mesolight::LatLongToMirrorBall(map, view, 256);
    vtkNew<vtkLightProbeToLatLong> convert;
    convert->SetInputData(ToImage(probe));
    convert->SetProbeType(type);
    convert->SetOutputWidth(256);
    convert->Update();
    vtkImageData* out = convert->GetOutput();
    int dims[3];
    out->GetDimensions(dims);
    EXPECT_EQ(dims[0], 256);
    EXPECT_EQ(dims[1], 128);
    EXPECT_NEAR(Radiance(out, zenith), 50.0, 5.0) << type;
    EXPECT_NEAR(Radiance(out, plusY), 20.0, 2.0) << type;
    EXPECT_LT(Radiance(out, minusY), 1.0) << type;

    // Negative: reading the probe with the wrong frame (looking along -X) swaps +Y and -Y.
    convert->SetForward(-1.0, 0.0, 0.0);
    convert->Update();
    EXPECT_LT(convert->GetOutput() ? Radiance(convert->GetOutput(), plusY) : 0.0, 1.0) << type;
  }
}

TEST(LightProbeToLatLong, BadInputIsAnError)
{
  vtkNew<vtkImageData> tiny;
  tiny->SetDimensions(1, 1, 1);
  tiny->AllocateScalars(VTK_FLOAT, 3);
  vtkNew<vtkLightProbeToLatLong> convert;
  convert->SetInputData(tiny);
  vtkNew<MessageCapture> messages; // the error is expected: keep it off the console
  messages->Watch(convert);
  convert->Update();
  EXPECT_FALSE(messages->Errors.empty());
  EXPECT_EQ(convert->GetOutput()->GetNumberOfPoints(), 0);
}

// A 16-bit probe means [0, 1] as an 8-bit one does (it was read as 0..65535); the memory is
// estimated before converting: over MemoryBudget the filter refuses with the size needed.
TEST(LightProbeToLatLong, SixteenBitProbesAndMemoryBudget)
{
  auto probe = [](int type, double value)
  {
    auto image = vtkSmartPointer<vtkImageData>::New();
    image->SetDimensions(8, 8, 1);
    image->AllocateScalars(type, 3);
    vtkDataArray* values = image->GetPointData()->GetScalars();
    for (vtkIdType k = 0; k < values->GetNumberOfValues(); ++k)
    {
      values->SetComponent(k / 3, static_cast<int>(k % 3), value);
    }
    return image;
  };
  double results[2] = { 0.0, 0.0 };
  const int types[2] = { VTK_UNSIGNED_CHAR, VTK_UNSIGNED_SHORT };
  const double half[2] = { 255.0, 65535.0 };
  for (int t = 0; t < 2; ++t)
  {
    vtkNew<vtkLightProbeToLatLong> convert;
    convert->SetInputData(probe(types[t], half[t]));
    convert->SetOutputWidth(16);
    convert->Update();
    ASSERT_EQ(convert->GetOutput()->GetNumberOfPoints(), 16 * 8);
    results[t] = convert->GetOutput()->GetPointData()->GetScalars()->GetComponent(0, 0);
  }
  EXPECT_NEAR(results[0], 1.0, 1e-6);
  EXPECT_NEAR(results[1], 1.0, 1e-6);

  vtkNew<vtkLightProbeToLatLong> convert;
  convert->SetInputData(probe(VTK_UNSIGNED_CHAR, 255.0));
  convert->SetOutputWidth(4096); // 4096 x 2048: 192 MiB with its copy
  convert->SetMemoryBudget(64 << 20);
  vtkNew<MessageCapture> messages;
  messages->Watch(convert);
  convert->Update();
  EXPECT_TRUE(messages->HasError("4096 x 2048 lat-long map needs about 192 MiB"))
    << messages->AllErrors();
  EXPECT_EQ(convert->GetOutput()->GetNumberOfPoints(), 0);
}
