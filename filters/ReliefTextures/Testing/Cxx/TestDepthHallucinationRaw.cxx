// SPDX-License-Identifier: BSD-3-Clause
// Depth hallucination from RAW photographs: the same two photographs stored as linear DNG files
// (RAW, read by OpenImageIO's raw plugin) and as 16-bit PNG files (linear values) must give the
// same albedo and depth through vtkOIIOImageReader -> vtkDepthHallucinationFilter.
#include "vtkDepthHallucinationFilter.h"
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"

#include "LinearDngWriter.h"
#include "MesolightTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkErrorCode.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkUnsignedShortArray.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <filesystem>
#include <string>
#include <vector>

namespace fs = std::filesystem;

namespace
{
constexpr int N = 64;

// Overcast shading of a pit (dark in its middle) on a surface of two albedos; the flash adds
// the albedo (flash strength 0.4).
std::uint16_t Photo(int i, int j, int c, bool flash)
{
  const float r = std::hypot(i + 0.5f - 0.5f * N, j + 0.5f - 0.5f * N);
  const float shading = 0.7f - 0.4f * std::exp(-0.5f * (r / 6.0f) * (r / 6.0f));
  const float albedo = (i < N / 2 ? 0.6f : 0.35f) * (c == 2 ? 0.8f : 1.0f);
  const float value = albedo * (shading + (flash ? 0.4f : 0.0f));
  return static_cast<std::uint16_t>(std::lround(value * 65535.0f));
}

// Writes the photograph both ways; rows top first in the files.
void WriteBoth(bool flash, const fs::path& dng, const fs::path& png)
{
  std::vector<std::uint16_t> rgb;
  vtkNew<vtkUnsignedShortArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(N * N);
  for (int j = 0; j < N; ++j)
  {
    for (int i = 0; i < N; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        rgb.push_back(Photo(i, j, c, flash));
        values->SetTypedComponent((N - 1 - j) * N + i, c, Photo(i, j, c, flash));
      }
    }
  }
  ASSERT_TRUE(mesolight_test::WriteLinearDng(dng.string(), N, N, rgb));
  vtkNew<vtkImageData> image;
  image->SetDimensions(N, N, 1);
  image->GetPointData()->SetScalars(values);
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(png.string().c_str());
  writer->SetBitDepth(16);
  ASSERT_TRUE(writer->Write());
}

struct Result
{
  std::vector<double> Albedo, Depth;
};

Result Hallucinate(const fs::path& diffuse, const fs::path& flash)
{
  vtkNew<vtkOIIOImageReader> readDiffuse;
  readDiffuse->SetFileName(diffuse.string().c_str());
  vtkNew<vtkOIIOImageReader> readFlash;
  readFlash->SetFileName(flash.string().c_str());
  vtkNew<vtkDepthHallucinationFilter> filter;
  filter->SetDiffuseConnection(readDiffuse->GetOutputPort());
  filter->SetFlashConnection(readFlash->GetOutputPort());
  filter->Update();
  EXPECT_EQ(readDiffuse->GetErrorCode(), vtkErrorCode::NoError);
  Result result;
  vtkDataArray* albedo = filter->GetAlbedoOutput()->GetPointData()->GetScalars();
  vtkDataArray* depth = filter->GetDepthOutput()->GetPointData()->GetScalars();
  EXPECT_NE(albedo, nullptr);
  EXPECT_NE(depth, nullptr);
  if (albedo && depth)
  {
    for (vtkIdType p = 0; p < depth->GetNumberOfTuples(); ++p)
    {
      result.Albedo.push_back(albedo->GetComponent(p, 0));
      result.Depth.push_back(depth->GetComponent(p, 0));
    }
  }
  return result;
}

double MaxDifference(const std::vector<double>& a, const std::vector<double>& b)
{
  double worst = a.size() == b.size() ? 0.0 : 1e9;
  for (std::size_t k = 0; k < std::min(a.size(), b.size()); ++k)
  {
    worst = std::max(worst, std::abs(a[k] - b[k]));
  }
  return worst;
}
} // namespace

TEST(DepthHallucinationFilter, RawPhotographsGiveTheDepthOfLinearOnes)
{
  const fs::path dir = mesolight_test::TestDirectory();
  WriteBoth(false, dir / "diffuse.dng", dir / "diffuse.png");
  WriteBoth(true, dir / "flash.dng", dir / "flash.png");
  const Result raw = Hallucinate(dir / "diffuse.dng", dir / "flash.dng");
  const Result png = Hallucinate(dir / "diffuse.png", dir / "flash.png");
  ASSERT_EQ(raw.Depth.size(), static_cast<std::size_t>(N * N));
  // Albedo times the flash (no calibration image): 0.6 x 0.4 left, 0.35 x 0.4 right (red).
  EXPECT_NEAR(png.Albedo[N / 2 * N + 2], 0.6 * 0.4, 1e-4);
  EXPECT_NEAR(png.Albedo[N / 2 * N + N - 3], 0.35 * 0.4, 1e-4);
  // LibRaw rounds through its colour matrices (a code value or two of 65535).
  EXPECT_LT(MaxDifference(raw.Albedo, png.Albedo), 2e-3);
  EXPECT_LT(MaxDifference(raw.Depth, png.Depth), 2e-2);
  // The pit is deeper than the flat surround in both.
  EXPECT_GT(raw.Depth[N / 2 * N + N / 2], raw.Depth[2 * N + 2]);
}
