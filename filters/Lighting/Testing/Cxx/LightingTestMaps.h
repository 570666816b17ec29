// SPDX-License-Identifier: BSD-3-Clause
// Environment maps shared by the Lighting unit tests.
#ifndef mesolight_LightingTestMaps_h
#define mesolight_LightingTestMaps_h

#include "RgbImage.h"

namespace mesolight
{
namespace test
{

/** A w x h map of the same value in every channel of every texel. */
inline RgbImage Constant(int w, int h, float value)
{
  RgbImage map(w, h);
  for (float& x : map.Rgb)
  {
    x = value;
  }
  return map;
}

} // namespace test
} // namespace mesolight

#endif
