// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file CompactReliefStorage.h
 * @brief What the relief mapper uploads in its compact storage (plain C++17, no VTK types):
 *        depth in 16 bits, the min-depth pyramid of those depths (exact minima), and the test
 *        deciding whether a relief texture's normals can be derived from its depth in the
 *        shader (Sobel, as vtkReliefTextureFilter bakes them) instead of being uploaded.
 *
 * Values are unsigned normalised integers as OpenGL reads them: an 8-bit k is k / 255, a
 * 16-bit m is m / 65535.
 */
#ifndef mesolight_CompactReliefStorage_h
#define mesolight_CompactReliefStorage_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mesolight
{

/** Depth in [0, 1] rounded to the nearest 16-bit value (clamped). */
MESOLIGHTRELIEFTEXTURES_EXPORT std::uint16_t QuantizeDepth16(float depth);

/**
 * The min-depth pyramid (ComputeMinDepthPyramid's cells, from the 16-bit depths as uploaded) at
 * levels 1 and coarser, as 16-bit values: the exact minima. Level 0, each cell's four corner
 * depths, is not stored: the traversal reads the corners from the depth texture, which holds
 * exactly them. Returns the levels (row-major) and their sizes in levelSizes (w, h pairs).
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<std::vector<std::uint16_t>> CompactMinDepthPyramid(
  const std::uint16_t* depth16, int w, int h, std::vector<int>& levelSizes);

// 8-bit cone ratios: EncodeConeRatio8 / DecodeConeRatio8 in ConeMaps.h (rounded to narrower
// cones).

/**
 * How far stored normals are from the Sobel normals of the depth (core/SobelNormals.h, clamped
 * border) at the interior texels (the border depends on the bake's border mode): the largest
 * difference of a normal component. normalXY holds each texel's normal x and y (unpacked, in
 * [-1, 1]), interleaved. depthScale is the scale the normals were baked with (the shader
 * derives them with it). Returns a large value when nothing can be compared (a map narrower
 * than 3 texels, or no depth scale: the normals are then taken as baked with whatever depth
 * scale the renderer uses, which the depth alone cannot give).
 */
MESOLIGHTRELIEFTEXTURES_EXPORT float SobelNormalMismatch(
  const float* depth, const float* normalXY, int w, int h, double depthScale);

} // namespace mesolight

#endif
