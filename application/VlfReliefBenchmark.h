// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench vlf-relief`: a relief lit by the light field measured against the truth, the
// path-traced dense displaced mesh of the same relief and camera (`trace --relief`), over the
// relief's pixels (`trace --relief-mask`); the negative cases (the relief lit by the flat wall's
// field value, by hand-placed VTK lights) are measured the same way, and the cost of a relief
// pixel is compared as a ratio of times measured in the same run. scripts/bench-vlf-relief.sh
// renders the images and calls it.
#ifndef mesolight_VlfReliefBenchmark_h
#define mesolight_VlfReliefBenchmark_h

#include "RgbImage.h"

#include <string>
#include <vector>

namespace mesolight
{

/** Mean relative luminance error per pixel of an image against a reference. */
struct MaskedError
{
  double MeanRelativeError = 0.0; // mean over the pixels of |Y - Yref| / Yref
  double MedianRelativeError = 0.0;
  double MeanRatio = 0.0; // sum Y / sum Yref over the pixels (a bias shows here)
  std::size_t Pixels = 0; // pixels counted: wholly on the relief, reference not black
};

/**
 * The error over the pixels whose mask value is at least `coverage` (the share of the pixel on
 * the relief, `trace --relief-mask`) and whose reference luminance exceeds `floor`. Throws
 * std::invalid_argument when the sizes differ.
 */
MaskedError MaskedRelativeError(const RgbImage& image, const RgbImage& reference,
  const RgbImage& mask, double coverage = 1.0, double floor = 1e-6);

int RunVlfReliefBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
