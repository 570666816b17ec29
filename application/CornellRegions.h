// SPDX-License-Identifier: BSD-3-Clause
// The Cornell box compared region by region with another renderer's image of the same view
// (Blender Cycles: vtkRayTracing/Testing/Cycles), for `mesolight trace` and `mesolight vlf
// render`, and the linear float images (EXR) both exchange.
#ifndef mesolight_CornellRegions_h
#define mesolight_CornellRegions_h

#include "RgbImage.h"
#include "TriangleScene.h"

#include <string>

namespace mesolight
{
// Mean radiance per Cornell-box quad (two triangles each: floor, ceiling, back, red, green,
// light, block faces) over the pixels whose 3 x 3 neighbourhood sees only that quad through the
// Cornell camera, ours against another renderer's linear image. Prints a table; true when every
// region with enough pixels agrees within `tolerance` (relative, per channel above 0.02).
bool CompareCornellRegions(
  const TriangleScene& box, const RgbImage& ours, const RgbImage& theirs, double tolerance);
// Writes a linear float RGB image (EXR by the name's extension), row 0 at the bottom.
bool WriteLinearImage(const RgbImage& image, const std::string& fileName, std::string& error);
// Reads a linear RGB image (first three channels).
bool ReadLinearImage(const std::string& fileName, RgbImage& image, std::string& error);
} // namespace mesolight

#endif
