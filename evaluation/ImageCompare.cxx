// SPDX-License-Identifier: BSD-3-Clause
#include "ImageCompare.h"

#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkRendererCollection.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>
#include <cstring>

namespace mesolight
{

//------------------------------------------------------------------------------
double Frame::EyeDepth(size_t pixel) const
{
  const double z = this->Depth[pixel];
  if (this->Parallel)
  {
    return this->Near + z * (this->Far - this->Near);
  }
  // Inverse of the perspective depth mapping with glDepthRange(0, 1).
  const double ndc = 2.0 * z - 1.0;
  return 2.0 * this->Near * this->Far / (this->Far + this->Near - ndc * (this->Far - this->Near));
}

//------------------------------------------------------------------------------
Frame CaptureFrame(vtkRenderWindow* window)
{
  window->Render();
  Frame frame;
  const int* size = window->GetSize();
  frame.Width = size[0];
  frame.Height = size[1];
  vtkNew<vtkUnsignedCharArray> rgb;
  window->GetPixelData(0, 0, size[0] - 1, size[1] - 1, 0, rgb, 0);
  frame.Rgb.assign(rgb->GetPointer(0), rgb->GetPointer(0) + 3 * size_t(size[0]) * size[1]);

  vtkNew<vtkFloatArray> depth;
  window->GetZbufferData(0, 0, size[0] - 1, size[1] - 1, depth);
  frame.Depth.assign(depth->GetPointer(0), depth->GetPointer(0) + size_t(size[0]) * size[1]);
  vtkRenderer* renderer = window->GetRenderers()->GetFirstRenderer();
  if (renderer)
  {
    double range[2];
    renderer->GetActiveCamera()->GetClippingRange(range);
    frame.Near = range[0];
    frame.Far = range[1];
    frame.Parallel = renderer->GetActiveCamera()->GetParallelProjection() != 0;
  }
  return frame;
}

//------------------------------------------------------------------------------
CoverageDifference CompareCoverage(const Frame& a, const Frame& b, int margin)
{
  CoverageDifference c;
  if (a.Depth.size() != b.Depth.size() ||
    a.Depth.size() != static_cast<size_t>(a.Width) * static_cast<size_t>(a.Height))
  {
    c.Mismatched = c.Either = static_cast<long long>(std::max(a.Depth.size(), b.Depth.size()));
    return c;
  }
  int x0 = a.Width, x1 = -1, y0 = a.Height;
  for (int y = 0; y < a.Height; ++y)
  {
    for (int x = 0; x < a.Width; ++x)
    {
      const size_t p = static_cast<size_t>(y) * a.Width + x;
      if (a.Covered(p) || b.Covered(p))
      {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
      }
    }
  }
  margin = std::max(0, margin);
  for (int y = y0 + margin; y < a.Height; ++y)
  {
    for (int x = x0 + margin; x <= x1 - margin; ++x)
    {
      const size_t p = static_cast<size_t>(y) * a.Width + x;
      const bool ca = a.Covered(p), cb = b.Covered(p);
      c.Mismatched += ca != cb ? 1 : 0;
      c.Either += ca || cb ? 1 : 0;
    }
  }
  return c;
}

//------------------------------------------------------------------------------
FrameDifference CompareFrames(
  const Frame& a, const Frame& b, double depthTolerance, const Frame* footprint)
{
  FrameDifference d;
  if (a.Width != b.Width || a.Height != b.Height || a.Depth.empty())
  {
    d.SilhouetteMismatch = 100.0;
    return d;
  }
  const size_t pixels = size_t(a.Width) * a.Height;
  long long either = 0, onlyOne = 0, depthOff = 0;
  double absSum = 0.0, sqSum = 0.0, depthSum = 0.0;
  const bool useFootprint = footprint && footprint->Depth.size() == pixels;
  for (size_t p = 0; p < pixels; ++p)
  {
    if (useFootprint && !footprint->Covered(p))
    {
      continue;
    }
    const bool ca = a.Covered(p), cb = b.Covered(p);
    if (ca || cb)
    {
      ++either;
    }
    if (ca != cb)
    {
      ++onlyOne;
      continue;
    }
    if (!ca)
    {
      continue;
    }
    ++d.CoveredBoth;
    for (int c = 0; c < 3; ++c)
    {
      const double diff = double(a.Rgb[3 * p + c]) - double(b.Rgb[3 * p + c]);
      absSum += std::abs(diff);
      sqSum += diff * diff;
    }
    const double dz = std::abs(a.EyeDepth(p) - b.EyeDepth(p));
    depthSum += dz;
    if (dz > depthTolerance)
    {
      ++depthOff;
    }
  }
  if (d.CoveredBoth > 0)
  {
    d.MeanColorError = absSum / (3.0 * d.CoveredBoth);
    d.RmsColorError = std::sqrt(sqSum / (3.0 * d.CoveredBoth));
    d.MeanDepthError = depthSum / d.CoveredBoth;
    d.DepthMismatch = 100.0 * double(depthOff) / d.CoveredBoth;
  }
  d.Psnr = d.RmsColorError > 0.0 ? 20.0 * std::log10(255.0 / d.RmsColorError) : 99.0;
  d.SilhouetteMismatch = either > 0 ? 100.0 * double(onlyOne) / either : 0.0;
  return d;
}

//------------------------------------------------------------------------------
bool DecodeHitCoordinate(const Frame& frame, size_t pixel, double& coordinate)
{
  if (!frame.Covered(pixel))
  {
    return false;
  }
  const unsigned char* c = &frame.Rgb[3 * pixel];
  coordinate = (65536.0 * c[0] + 256.0 * c[1] + c[2]) / 16777215.0;
  return true;
}

//------------------------------------------------------------------------------
bool DecodeSampleCount(const Frame& frame, size_t pixel, int& count)
{
  if (!frame.Covered(pixel))
  {
    return false;
  }
  const unsigned char* c = &frame.Rgb[3 * pixel];
  count = 256 * c[0] + c[1];
  return true;
}

//------------------------------------------------------------------------------
double MeanCount(const std::vector<int>& counts)
{
  double sum = 0.0;
  long long n = 0;
  for (int count : counts)
  {
    if (count >= 0)
    {
      sum += count;
      ++n;
    }
  }
  return n > 0 ? sum / n : 0.0;
}

//------------------------------------------------------------------------------
namespace
{
// The frame's decoded counts, -1 for background pixels.
std::vector<int> DecodeSampleCounts(const Frame& frame)
{
  std::vector<int> counts(frame.Depth.size(), -1);
  for (size_t p = 0; p < counts.size(); ++p)
  {
    int count = 0;
    if (DecodeSampleCount(frame, p, count))
    {
      counts[p] = count;
    }
  }
  return counts;
}
} // namespace

//------------------------------------------------------------------------------
double MeanSampleCount(const Frame& frame)
{
  return MeanCount(DecodeSampleCounts(frame));
}

//------------------------------------------------------------------------------
double MeanLockStepCount(
  const std::vector<int>& counts, int width, int height, int groupWidth, int groupHeight)
{
  if (groupWidth < 1 || groupHeight < 1 || width < 1 || height < 1 ||
    counts.size() != static_cast<size_t>(width) * height)
  {
    return 0.0;
  }
  double sum = 0.0;
  long long n = 0;
  for (int y0 = 0; y0 < height; y0 += groupHeight)
  {
    for (int x0 = 0; x0 < width; x0 += groupWidth)
    {
      int largest = 0;
      long long covered = 0;
      for (int y = y0; y < std::min(y0 + groupHeight, height); ++y)
      {
        for (int x = x0; x < std::min(x0 + groupWidth, width); ++x)
        {
          const int count = counts[static_cast<size_t>(y) * width + x];
          if (count >= 0)
          {
            largest = std::max(largest, count);
            ++covered;
          }
        }
      }
      sum += static_cast<double>(largest) * covered;
      n += covered;
    }
  }
  return n > 0 ? sum / n : 0.0;
}

//------------------------------------------------------------------------------
double MeanLockStepSampleCount(const Frame& frame, int groupWidth, int groupHeight)
{
  if (frame.Width < 1 || frame.Height < 1)
  {
    return 0.0;
  }
  return MeanLockStepCount(
    DecodeSampleCounts(frame), frame.Width, frame.Height, groupWidth, groupHeight);
}

//------------------------------------------------------------------------------
bool WritePng(const Frame& frame, const char* fileName)
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(frame.Width, frame.Height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::memcpy(image->GetScalarPointer(), frame.Rgb.data(), frame.Rgb.size());
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(fileName);
  writer->Write();
  return writer->GetErrorCode() == 0;
}

} // namespace mesolight
