// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file RgbImage.h
 * @brief An RGB float image (plain C++17): environment maps, rendered and reference images.
 */
#ifndef mesolight_RgbImage_h
#define mesolight_RgbImage_h

#include <cstddef>
#include <vector>

namespace mesolight
{

/// An RGB float image, W x H, row-major, 3 floats per pixel, VTK row order (row 0 = bottom).
struct RgbImage
{
  int Width = 0;
  int Height = 0;
  std::vector<float> Rgb; ///< 3 * Width * Height values

  RgbImage() = default;
  RgbImage(int w, int h)
    : Width(w)
    , Height(h)
    , Rgb(static_cast<std::size_t>(w) * static_cast<std::size_t>(h) * 3, 0.0f)
  {
  }
  float* Pixel(int i, int j) { return Rgb.data() + 3 * (static_cast<std::size_t>(j) * Width + i); }
  const float* Pixel(int i, int j) const
  {
    return Rgb.data() + 3 * (static_cast<std::size_t>(j) * Width + i);
  }
};

} // namespace mesolight

#endif
