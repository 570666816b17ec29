// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldScreenImage
 * @brief   one frame's CPU radiance over a screen rectangle, handed to vtkLightFieldMapper
 *
 * Private to Mesolight::LightFieldActor (header not installed). RGBA floats over a rectangle
 * of viewport pixels (the whole viewport in raytrace mode, the mirrors' rectangle otherwise),
 * placed at a window pixel. Shade() fills it in one parallel pass over 4 x 4 pixel tiles
 * (primary rays in 16-ray Embree packets, Wither 2005 §2.4.2.2.4); Adopt() takes an image the
 * progressive worker traced. Alpha 1 marks pixels that have a value (the mapper composites by
 * it); the mapper may read the image only when IsValid().
 */
#ifndef vtkLightFieldScreenImage_h
#define vtkLightFieldScreenImage_h

#include "WalkthroughTracer.h" // For PixelRect, SpecularQuality

#include <cstddef>
#include <vector>

class vtkLightFieldScreenImage
{
public:
  /** A new frame: nothing to show until Place(). */
  void Clear();
  /**
   * Shades rect of view (all surfaces, or only mirrors, at quality) and returns the number of
   * pixels given a value. Dilate() then spreads mirror values over their edge pixels.
   */
  std::size_t Shade(const mesolight::vlf::WalkthroughTracer& tracer,
    const mesolight::vlf::ViewFrame& view, const mesolight::vlf::PixelRect& rect, bool all,
    mesolight::vlf::SpecularQuality quality, const mesolight::vlf::TraceOptions& options);
  void Dilate();
  /** Takes an image computed elsewhere; returns the number of pixels it gives a value. */
  std::size_t Adopt(std::vector<float> pixels, const mesolight::vlf::PixelRect& rect);
  /** Shows the image at window pixel (x, y) + the rectangle's corner this frame. */
  void Place(int x, int y, bool allScreen);

  bool IsValid() const { return this->Valid; }
  /** The raytrace mode: the image covers every pixel of the viewport. */
  bool IsAllScreen() const { return this->AllScreen; }
  const mesolight::vlf::PixelRect& GetRect() const { return this->Rect; }
  const int* GetOrigin() const { return this->Origin; }
  std::vector<float>& GetPixels() { return this->Pixels; }

private:
  mesolight::vlf::PixelRect Rect;
  int Origin[2] = { 0, 0 };
  std::vector<float> Pixels;
  bool AllScreen = false;
  bool Valid = false;
};

#endif
