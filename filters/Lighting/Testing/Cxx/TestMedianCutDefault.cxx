// SPDX-License-Identifier: BSD-3-Clause
// The default median cut (MedianCutOptions{}: 64 lights, variance-minimizing cuts) on real HDR
// environments: mean irradiance error <= 1% against exact integration of the map
// (ExactIrradiance) on each of Blender's eight CC0 studio-light worlds (Debian's blender-data),
// where even-energy cuts miss that bound (courtyard: 2.1%); and on a map large enough that
// the variance cuts work on cells of 2 x 2 pixels, with every pixel's light still counted.
#include "EnvironmentMaps.h"
#include "MathConstants.h"
#include "MedianCut.h"
#include "ParallelFor.h"
#include "ProceduralEnvironments.h"
#include "vtkOIIOImageReader.h"

#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdio>
#include <filesystem>
#include <string>
#include <vector>

using mesolight::MedianCutLight;
using mesolight::MedianCutOptions;
using mesolight::RgbImage;

namespace
{

const char* const BlenderWorlds = "/usr/share/blender/datafiles/studiolights/world";

/// A lat-long EXR in VTK row order (vtkOIIOImageReader), or an empty image.
RgbImage ReadMap(const std::string& file)
{
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(file.c_str());
  reader->Update();
  vtkDataArray* scalars = reader->GetOutput()->GetPointData()->GetScalars();
  int dims[3] = { 0, 0, 0 };
  reader->GetOutput()->GetDimensions(dims);
  if (reader->GetErrorCode() != 0 || !scalars || scalars->GetNumberOfComponents() < 3)
  {
    return {};
  }
  RgbImage map(dims[0], dims[1]);
  for (vtkIdType k = 0; k < static_cast<vtkIdType>(dims[0]) * dims[1]; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      map.Rgb[3 * k + c] = static_cast<float>(scalars->GetComponent(k, c));
    }
  }
  return map;
}

/// Mean relative irradiance error (luminance) of the lights against exact integration, over
/// 300 Fibonacci normals whose exact irradiance is above 1e-4 of the largest.
double MeanError(const RgbImage& map, const std::vector<MedianCutLight>& lights)
{
  const mesolight::ExactIrradiance exact(map);
  const int n = 300;
  const double golden = mesolight::Pi<double> * (3.0 - std::sqrt(5.0));
  std::vector<std::array<double, 2>> values(n); // exact, approximate
  mesolight::ParallelFor(0, n, 1,
    [&](std::size_t k0, std::size_t k1)
    {
      for (std::size_t k = k0; k < k1; ++k)
      {
        const double z = 1.0 - (k + 0.5) * 2.0 / n;
        const double r = std::sqrt(1.0 - z * z);
        const double normal[3] = { r * std::cos(golden * k), r * std::sin(golden * k), z };
        double e[3];
        double a[3];
        exact.Evaluate(normal, e);
        mesolight::IrradianceFromLights(lights, normal, a);
        values[k] = { mesolight::Luminance(e[0], e[1], e[2]),
          mesolight::Luminance(a[0], a[1], a[2]) };
      }
    });
  double largest = 0.0;
  for (const auto& v : values)
  {
    largest = std::max(largest, v[0]);
  }
  double sum = 0.0;
  int used = 0;
  for (const auto& v : values)
  {
    if (v[0] > 1e-4 * largest)
    {
      sum += std::abs(v[1] - v[0]) / v[0];
      ++used;
    }
  }
  return sum / std::max(1, used);
}

std::vector<MedianCutLight> Cut(const RgbImage& map, const MedianCutOptions& options)
{
  std::vector<MedianCutLight> lights;
  EXPECT_NO_THROW(
    lights = mesolight::ComputeMedianCut(map.Rgb.data(), 3, map.Width, map.Height, options));
  return lights;
}

} // namespace

TEST(MedianCutDefault, WithinOnePercentOnRealMaps)
{
  const std::vector<std::string> worlds = { "city", "courtyard", "forest", "interior", "night",
    "studio", "sunrise", "sunset" };
  if (!std::filesystem::is_directory(BlenderWorlds))
  {
    GTEST_SKIP() << BlenderWorlds << " is missing (Debian's blender-data, scripts/install-deps.sh)";
  }
  const MedianCutOptions defaults;
  EXPECT_EQ(defaults.NumberOfLights, 64);
  for (const std::string& world : worlds)
  {
    const RgbImage map = ReadMap(std::string(BlenderWorlds) + "/" + world + ".exr");
    ASSERT_GT(map.Width, 0) << world;
    const double error = MeanError(map, Cut(map, defaults));
    std::printf("%-10s default cut, %d lights: mean irradiance error %.3f%%\n", world.c_str(),
      defaults.NumberOfLights, 100.0 * error);
    EXPECT_LE(error, 0.01) << world;
    if (world == "courtyard")
    {
      // The former default, even-energy cuts, misses the bound on this map.
      MedianCutOptions plain;
      plain.VarianceMinimization = false;
      const double plainError = MeanError(map, Cut(map, plain));
      std::printf("%-10s even-energy cuts: %.3f%%\n", world.c_str(), 100.0 * plainError);
      EXPECT_GT(plainError, 0.01);
    }
  }
}

TEST(MedianCutDefault, CellsOfLargeMaps)
{
  // 2048 x 1024: the variance cuts compare cells of 2 x 2 pixels (MedianCut.h); the lights
  // still carry every pixel's light and cover the sphere, and the error stays within 1%.
  mesolight::SkyParameters p;
  p.Sun = true;
  p.Window = true;
  const RgbImage map = mesolight::MakeSkyMap(2048, 1024, p);
  const std::vector<MedianCutLight> lights = Cut(map, MedianCutOptions{});
  ASSERT_EQ(lights.size(), 64u);
  double sum = 0.0;
  double area = 0.0;
  for (const auto& l : lights)
  {
    sum += l.Rgb[1];
    area += l.SolidAngle;
    EXPECT_EQ(l.Column0 % 2, 0);
    EXPECT_EQ(l.Row0 % 2, 0);
  }
  double check = 0.0;
  for (int j = 0; j < map.Height; ++j)
  {
    for (int i = 0; i < map.Width; ++i)
    {
      check += map.Pixel(i, j)[1] * mesolight::PixelSolidAngle(j, map.Width, map.Height);
    }
  }
  EXPECT_NEAR(sum, check, 1e-9 * check);
  EXPECT_NEAR(area, 4 * mesolight::Pi<double>, 1e-9);
  const double error = MeanError(map, lights);
  std::printf("SunSky 2048x1024, default cut: mean irradiance error %.3f%%\n", 100.0 * error);
  EXPECT_LE(error, 0.01);
}
