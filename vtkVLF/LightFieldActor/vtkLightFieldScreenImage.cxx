// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldScreenImage.h"

#include "ParallelFor.h"

#include <atomic>
#include <utility>

namespace vlf = mesolight::vlf;

//------------------------------------------------------------------------------
void vtkLightFieldScreenImage::Clear()
{
  this->Valid = false;
  this->AllScreen = false;
  this->Rect = vlf::PixelRect{};
}

//------------------------------------------------------------------------------
std::size_t vtkLightFieldScreenImage::Shade(const vlf::WalkthroughTracer& tracer,
  const vlf::ViewFrame& view, const vlf::PixelRect& rect, bool all, vlf::SpecularQuality quality,
  const vlf::TraceOptions& options)
{
  this->Rect = rect;
  this->Pixels.assign(rect.Pixels() * 4, 0.0f);
  float* out = this->Pixels.data();
  std::atomic<std::size_t> valued{ 0 };
  mesolight::ParallelFor(0, vlf::WalkthroughTracer::TileCount(rect), 16,
    [&](std::size_t t0, std::size_t t1)
    { valued += tracer.ShadeTiles(view, rect, all, quality, options, t0, t1, out); });
  return valued.load();
}

//------------------------------------------------------------------------------
void vtkLightFieldScreenImage::Dilate()
{
  vlf::WalkthroughTracer::DilateEdges(this->Rect, this->Pixels.data());
}

//------------------------------------------------------------------------------
std::size_t vtkLightFieldScreenImage::Adopt(std::vector<float> pixels, const vlf::PixelRect& rect)
{
  this->Pixels = std::move(pixels);
  this->Rect = rect;
  std::size_t valued = 0;
  for (std::size_t i = 0; i < this->Rect.Pixels(); ++i)
  {
    valued += this->Pixels[4 * i + 3] >= 1.0f ? 1 : 0;
  }
  return valued;
}

//------------------------------------------------------------------------------
void vtkLightFieldScreenImage::Place(int x, int y, bool allScreen)
{
  this->Origin[0] = x + this->Rect.X0;
  this->Origin[1] = y + this->Rect.Y0;
  this->AllScreen = allScreen;
  this->Valid = true;
}
