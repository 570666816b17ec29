// SPDX-License-Identifier: BSD-3-Clause
#include "CornellRegions.h"

#include "EmbreeScene.h"
#include "PinholeCamera.h"
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"

#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkSmartPointer.h>

#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <iomanip>
#include <iostream>
#include <map>
#include <vector>

namespace mesolight
{

//------------------------------------------------------------------------------
bool CompareCornellRegions(
  const TriangleScene& box, const RgbImage& ours, const RgbImage& theirs, double tolerance)
{
  if (ours.Width != theirs.Width || ours.Height != theirs.Height)
  {
    std::cerr << "compare: image sizes differ (" << ours.Width << "x" << ours.Height << " vs "
              << theirs.Width << "x" << theirs.Height << ")\n";
    return false;
  }
  const EmbreeScene embree(box);
  const PinholeCamera camera{ CornellCamera{} };
  const int w = ours.Width, h = ours.Height;
  std::vector<int> region(static_cast<std::size_t>(w) * h, -1);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const SceneHit hit = embree.Intersect(camera.Ray(i + 0.5f, j + 0.5f, w, h));
      region[static_cast<std::size_t>(j) * w + i] =
        hit.Hit() ? static_cast<int>(hit.Triangle / 2) : -1;
    }
  }
  const char* names[] = { "floor", "ceiling", "back wall", "red wall", "green wall", "light" };
  std::map<int, std::pair<glm::dvec3, glm::dvec3>> sums;
  std::map<int, int> counts;
  for (int j = 1; j + 1 < h; ++j)
  {
    for (int i = 1; i + 1 < w; ++i)
    {
      const int r = region[static_cast<std::size_t>(j) * w + i];
      bool interior = r >= 0;
      for (int b = -1; b <= 1 && interior; ++b)
      {
        for (int a = -1; a <= 1; ++a)
        {
          interior = interior && region[static_cast<std::size_t>(j + b) * w + i + a] == r;
        }
      }
      if (!interior)
      {
        continue;
      }
      const float* x = ours.Pixel(i, j);
      const float* y = theirs.Pixel(i, j);
      sums[r].first += glm::dvec3(x[0], x[1], x[2]);
      sums[r].second += glm::dvec3(y[0], y[1], y[2]);
      ++counts[r];
    }
  }
  bool agree = true;
  std::cout << std::left << std::setw(16) << "region" << std::right << std::setw(8) << "pixels"
            << std::setw(30) << "mesolight (R G B)" << std::setw(30) << "other (R G B)"
            << std::setw(10) << "max err"
            << "\n";
  for (const auto& entry : sums)
  {
    const int r = entry.first;
    if (counts[r] < 30)
    {
      continue;
    }
    const glm::dvec3 a = entry.second.first / static_cast<double>(counts[r]);
    const glm::dvec3 b = entry.second.second / static_cast<double>(counts[r]);
    double worst = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      if (std::max(a[c], b[c]) > 0.02)
      {
        worst = std::max(worst, std::abs(a[c] - b[c]) / std::max(a[c], b[c]));
      }
    }
    agree = agree && worst <= tolerance;
    const std::string name = r < 6
      ? names[r]
      : (r < 11 ? "short block " : "tall block ") + std::to_string(r < 11 ? r - 5 : r - 10);
    std::cout << std::left << std::setw(16) << name << std::right << std::setw(8) << counts[r]
              << std::fixed << std::setprecision(4) << std::setw(10) << a.x << std::setw(10) << a.y
              << std::setw(10) << a.z << std::setw(10) << b.x << std::setw(10) << b.y
              << std::setw(10) << b.z << std::setw(9) << std::setprecision(1) << 100.0 * worst
              << "%\n";
  }
  std::cout << (agree ? "regions agree" : "REGIONS DIFFER") << " (tolerance " << 100.0 * tolerance
            << "%)\n";
  return agree;
}

//------------------------------------------------------------------------------
bool WriteLinearImage(const RgbImage& image, const std::string& fileName, std::string& error)
{
  auto result = vtkSmartPointer<vtkImageData>::New();
  result->SetDimensions(image.Width, image.Height, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(image.Width) * image.Height);
  std::copy(image.Rgb.begin(), image.Rgb.end(), values->GetPointer(0));
  result->GetPointData()->SetScalars(values);
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(result);
  writer->SetFileName(fileName.c_str());
  if (!writer->Write())
  {
    error = "cannot write " + fileName;
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
bool ReadLinearImage(const std::string& fileName, RgbImage& image, std::string& error)
{
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(fileName.c_str());
  reader->Update();
  vtkImageData* other = reader->GetOutput();
  int dims[3];
  other->GetDimensions(dims);
  vtkDataArray* values = other->GetPointData()->GetScalars();
  if (!values || dims[0] < 1 || values->GetNumberOfComponents() < 3)
  {
    error = "cannot read an RGB image from " + fileName;
    return false;
  }
  image = RgbImage(dims[0], dims[1]);
  for (int j = 0; j < dims[1]; ++j)
  {
    for (int i = 0; i < dims[0]; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        image.Pixel(i, j)[c] =
          static_cast<float>(values->GetComponent(static_cast<vtkIdType>(j) * dims[0] + i, c));
      }
    }
  }
  return true;
}

} // namespace mesolight
