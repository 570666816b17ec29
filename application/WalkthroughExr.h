// SPDX-License-Identifier: BSD-3-Clause
// The linear radiance of a walkthrough frame drawn by vtkLightFieldActor, for `vlf render --mode M
// --exr`. The actor tone-maps in GLSL into an 8-bit sRGB window; its radiance is recovered by
// exposure bracketing (Debevec and Malik, "Recovering high dynamic range radiance maps from
// photographs"): the same frame drawn with the clamp operator at exposures a factor 4 apart, and
// each pixel and channel taken from the brightest exposure that does not clip it, decoded and
// divided by its exposure. Quantization then costs at most about 1% relative (a code of at least
// about 130 of 255) over radiance 2^-12 to 2^16; below it reads with less precision. The geometry
// mode draws no radiance (the materials under VTK's lights): its frame is written decoded from
// sRGB, as drawn.
#ifndef mesolight_WalkthroughExr_h
#define mesolight_WalkthroughExr_h

#include "RgbImage.h"

#include <string>

class vtkLightFieldActor;
class vtkRenderWindow;

namespace mesolight
{
/** Draws the window's current view at the bracketed exposures (restoring the actor's exposure and
 * tone map after) into `radiance` (row 0 at the bottom). With supersampling s > 1 the window is
 * s times the image per side and each s x s block's radiance is averaged into one pixel (a box
 * filter, in linear radiance). False with a message when the frame cannot be read. */
bool CaptureWalkthroughRadiance(vtkLightFieldActor* actor, vtkRenderWindow* window,
  RgbImage& radiance, std::string& error, int supersampling = 1);
} // namespace mesolight

#endif
