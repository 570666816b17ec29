// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file SobelNormals.h
 * @brief Depth-map derivatives and relief-texture packing (plain C++17, no VTK types).
 *
 * Reference: Méndez Fernández's thesis §3.2 "Sobel operator", eq. 2.
 *
 * Conventions shared with the rest of Mesolight:
 *  - a depth map is w*h floats, row-major, row j = 0 is the BOTTOM row, values in [0,1]
 *    (0 = top surface, 1 = deepest);
 *  - DepthScale = world depth of d = 1 divided by the world width (u extent) of the texture;
 *    texels are square, so a depth d is d * DepthScale * w texels deep;
 *  - the surface is z = -DepthScale * d(x, y) with x = u in [0,1] and y in the same units,
 *    hence its tangent-space normal is n = normalize(k dd/dx, k dd/dy, 1), k = DepthScale,
 *    dd/dx = w * dd/di and dd/dy = w * dd/dj.
 */
#ifndef mesolight_SobelNormals_h
#define mesolight_SobelNormals_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

namespace mesolight
{

/// How neighbours outside the image are addressed.
enum class BorderMode
{
  Clamp, ///< indices clamped into the image: one-sided differences at the borders
  Wrap   ///< periodic indices: for tileable textures
};

/**
 * Per-texel Sobel gradient (eq. 2 of the thesis, normalised to "depth units per texel"):
 *
 *   gi = [ (d(ip,j-1) + 2 d(ip,j) + d(ip,j+1)) - (d(im,j-1) + 2 d(im,j) + d(im,j+1)) ] / (4 (ip -
 * im))
 *
 * where ip/im are the column indices actually used (i+1 and i-1 in the interior, so the
 * divisor is 8). In Clamp mode the indices are clamped, and dividing by the real distance
 * ip - im turns the border stencil into a one-sided difference instead of halving the
 * slope. gj is the same along rows. A dimension of size 1 has derivative 0.
 *
 * @param depth   w*h depth values (row j = 0 first, i.e. bottom row).
 * @param gradOut 2*w*h floats, interleaved (gi, gj) per texel.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT void ComputeSobelGradient(
  const float* depth, int w, int h, BorderMode mode, float* gradOut);

/// Same as ComputeSobelGradient() but only for rows [rowBegin, rowEnd) (thread-parallel use).
/// gradOut still points to the whole 2*w*h output.
MESOLIGHTRELIEFTEXTURES_EXPORT void ComputeSobelGradientRows(
  const float* depth, int w, int h, BorderMode mode, int rowBegin, int rowEnd, float* gradOut);

/// One row of ComputeSobelGradient(): rowOut holds 2*w floats, (gi, gj) per texel of row `row`.
MESOLIGHTRELIEFTEXTURES_EXPORT void ComputeSobelGradientRow(
  const float* depth, int w, int h, BorderMode mode, int row, float* rowOut);

/// Tangent-space unit normal from a Sobel gradient (gi, gj in depth per texel) of a
/// w-texel-wide map: n = normalize(k w gi, k w gj, 1).
MESOLIGHTRELIEFTEXTURES_EXPORT void NormalFromGradient(
  float gi, float gj, int w, float depthScale, float n[3]);

/**
 * Relief texture (as in the thesis): per texel RGBA with RGB = (n + 1) / 2 (the tangent-space
 * normal packed to [0,1]) and A = depth (0 top, 1 deepest).
 *
 * @param rgbaOut 4*w*h floats.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT void ComputeReliefTexture(
  const float* depth, int w, int h, float depthScale, BorderMode mode, float* rgbaOut);

/// Same as ComputeReliefTexture() for rows [rowBegin, rowEnd) only. rgbaOut is the whole
/// 4*w*h output.
MESOLIGHTRELIEFTEXTURES_EXPORT void ComputeReliefTextureRows(const float* depth, int w, int h,
  float depthScale, BorderMode mode, int rowBegin, int rowEnd, float* rgbaOut);

} // namespace mesolight

#endif
