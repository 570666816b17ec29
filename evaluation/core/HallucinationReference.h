// SPDX-License-Identifier: BSD-3-Clause
// HallucinationReference: photographs of a known height field for depth hallucination
// (Glencross et al. 2008), made by the path tracer, and the measures a hallucinated depth map is
// judged by (plain C++, GLM, no VTK types).
//
// The scene: the height field as a dense mesh, one vertex per texel centre (texel width = 1
// world unit, z up, depth d at world z = -d * ReliefDepthTexels) plus a clamped border ring, so
// each pixel centre of the top-down camera lands on its texel's vertex. The camera is a narrow
// pinhole 20 image widths above the centre (nearly orthographic: parallax below 0.03 texel per
// texel of depth at the border). Three photographs, as a user takes them:
//  - Diffuse: the uniform overcast sky, radiance SkyRadiance over the upper hemisphere, black
//    below the horizon (the lower half of a lat-long map);
//  - Flash: the same sky plus a small square emitter (the flash) just above the camera, facing
//    down. The path tracer has no point lights, so the flash is a one-sided area light of side
//    FlashSizeTexels; light adds linearly, so Flash = Diffuse + the flash-only render;
//  - Calibration: the flash alone on a flat white card (Kd = 1) at depth 0.
// Diffuse reflection only, every bounce (interreflections included, as in a photograph).
#ifndef mesolight_HallucinationReference_h
#define mesolight_HallucinationReference_h

#include "Progress.h"
#include "RgbImage.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <vector>

namespace mesolight
{

struct HallucinationPhotoSettings
{
  float ReliefDepthTexels = 8.0f; // world depth of depth 1, in texel widths
  float SkyRadiance = 1.0f;
  // Samples per pixel, the same jittered positions in every photograph (as a camera on a tripod
  // integrates each pixel over the same area in both shots).
  int Samples = 32;
  float FlashSizeTexels = 2.0f;
  std::uint64_t Seed = 1;
};

struct HallucinationPhotographs
{
  RgbImage Diffuse, Flash, Calibration;
  RgbImage TrueAlbedo; // Kd seen by each pixel (averaged over the jittered primary rays)
};

// The test albedo: 16 x 16 texel cells of four colours in a fixed, hashed order (independent of
// the depth), so the flash pair has something to remove.
glm::vec3 HallucinationTestAlbedo(int i, int j);

// depth: w x h, 0 = top, 1 = deepest, VTK row order. albedo: w x h RGB per texel (empty: the
// test albedo). Returns empty images when progress aborts.
HallucinationPhotographs RenderHallucinationPhotographs(const std::vector<float>& depth, int w,
  int h, const std::vector<glm::vec3>& albedo, const HallucinationPhotoSettings& settings,
  const ProgressCallback& progress = {});

// Generated surfaces whose feature size the generator knows, depth 1 inside the features:
// "Panels": recessed panels 100 texels wide with frames 28 wide (period 128), 256 x 256, 16 texels
// deep; "Holes": a plate perforated with round holes 8 texels across on a 16-texel pitch,
// 128 x 128, 8 texels deep.
struct HallucinationTestSurface
{
  std::vector<float> Depth; // Side x Side, 0 = top, 1 = deepest
  int Side = 0;
  float ReliefTexels = 0.0f;
  float FeatureTexels = 0.0f; // panel width, hole diameter
};
HallucinationTestSurface MakeHallucinationTestSurface(bool panels);

// How well an estimate matches the truth after the best affine map a * estimate + b (least
// squares, a >= 0: an upside-down map is not rescued by a negative scale): Pearson correlation
// (the sign says whether deep came out deep), and the mean absolute error of the fitted
// estimate, in the truth's units. `margin` texels at each border are left out.
struct DepthAgreement
{
  double Correlation = 0.0;
  double MeanAbsoluteError = 0.0;
  double Scale = 0.0, Offset = 0.0;
  double TruthMeanAbsoluteDeviation = 0.0; // MAE of the best constant, for scale
};
DepthAgreement CompareDepth(const std::vector<float>& estimate, const std::vector<float>& truth,
  int w, int h, int margin = 0);

} // namespace mesolight

#endif
