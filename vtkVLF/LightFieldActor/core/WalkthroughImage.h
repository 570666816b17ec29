// SPDX-License-Identifier: BSD-3-Clause
// WalkthroughImage: the display transform of every walkthrough mode on RGB (common/
// DisplayTransform.h per channel; glsl/vtkLightFieldFS.glsl is its GPU twin) and the per-pixel
// error measures the tests and benchmark compare modes with. Plain C++ (GLM, no VTK types).
#ifndef mesolight_vlf_WalkthroughImage_h
#define mesolight_vlf_WalkthroughImage_h

#include "DisplayTransform.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mesolight
{
namespace vlf
{

using mesolight::ToneMapOperator;

// Display value in [0, 1] (sRGB-encoded) of a linear radiance.
glm::vec3 ToneMap(const glm::vec3& radiance, float exposure, ToneMapOperator op);
// Linear radiance of a display value (the inverse; 1 maps to the clipping point for Clamp).
glm::vec3 InverseToneMap(const glm::vec3& display, float exposure, ToneMapOperator op);

// Log-average luminance (Rec. 709 weights) of the RGBA texels with positive, finite luminance,
// 0 when there are none: the automatic exposure 0.18 / this (Reinhard et al., "Photographic tone
// reproduction for digital images") of ParaView's Light Field representation, for the scene's
// atlas and for surfaces shaded by Light Field Gather alike.
double LogAverageLuminance(const float* rgba, std::size_t texels);

struct ErrorStatistics
{
  std::size_t Pixels = 0;
  double Mean = 0.0;         // mean relative error
  double Percentile95 = 0.0; // 95th percentile of the relative error
};

// Per-pixel relative error sum_c |a_c - r_c| / max(sum_c r_c, floor) over the pixels whose
// mask value is `which` (images and mask of equal length).
ErrorStatistics RelativeError(const std::vector<glm::vec3>& image,
  const std::vector<glm::vec3>& reference, const std::vector<std::uint8_t>& mask,
  std::uint8_t which, float floor = 1e-3f);

} // namespace vlf
} // namespace mesolight

#endif
