// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file CompactReliefStorage.h
 * @brief What the relief mapper uploads in its compact storage (plain C++17, no VTK types):
 *        depth in 16 bits, the min-depth pyramid of those depths (exact minima), and the test
 *        deciding whether a relief texture's normals can be derived from its depth in the
 *        shader (Sobel, as vtkReliefTextureFilter bakes them) instead of being uploaded; the
 *        normal in 8-bit octahedral coordinates and the mip levels of its second moments that
 *        level of detail's visible normal filter reads (levels 2 and coarser: the finer ones
 *        follow from the normals themselves).
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

/**
 * The coarse part of the compact min-depth pyramid the maximum-mipmap traversal reads
 * (vtkReliefMaxMipmapFS.glsl): levels firstLevel and up of ComputeMinDepthPyramid's cells (of the
 * 16-bit depths as uploaded), each cell holding its 2 x 2 children's minima as PackChildMinima
 * packs them, every minimum rounded down to 8 bits (v / 257, which reads back as b / 255 <=
 * v / 65535): a bound never below the surface, so the traversal stays exact; it only descends a
 * little earlier. Levels that a small map lacks (past 1 x 1) are 1 x 1 copies of its apex, so
 * level firstLevel always exists. Level 0 (the cells' corners) and the levels between are not
 * stored: the traversal reads a level-0 cell's corners from the depth texture with one gather.
 * At firstLevel 2 (vtkMinDepthPyramidTexture's): 1/3 byte per texel; at 3, 1/12. Returns the levels
 * (RGBA, row-major) and their sizes in levelSizes ((w, h) pairs); empty for an empty map or
 * firstLevel < 1.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<std::vector<std::uint8_t>> CompactChildMinima8(
  const std::uint16_t* depth16, int w, int h, int firstLevel, std::vector<int>& levelSizes);

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

/**
 * The largest SobelNormalMismatch of normals that are their depth's own: about a degree, since
 * 8-bit baked normals are within 1/127 of the float ones.
 */
constexpr float SobelNormalTolerance = 0.02f;

/**
 * Whether a relief texture's normals are its depth's own (the Sobel normals
 * vtkReliefTextureFilter bakes at depthScale, SobelNormalMismatch within SobelNormalTolerance).
 * Such a texture is shaded with the gradient of the bilinear surface its depth defines, the
 * surface every renderer marches (the relief mapper, the exact CPU intersector, the path
 * tracer's dense mesh): the Sobel stencil spans three texels and flattens detail a texel or two
 * wide. Normals made apart (a normal map) are shaded as given.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT bool NormalsAreTheDepths(
  const float* depth, const float* normalXY, int w, int h, double depthScale);

/**
 * A unit normal (z >= 0, hemisphere) in hemispherical octahedral coordinates (Cigolle et al.,
 * "A Survey of Efficient Representations for Independent Unit Vectors", JCGT 2014) as signed
 * normalised 8-bit values, as GL_RG8_SNORM stores them: k / 127. x, y, z need not be unit.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT void EncodeOctahedral8(
  float x, float y, float z, std::int8_t& e0, std::int8_t& e1);

/** The unit normal of 8-bit octahedral coordinates (the shader's decoding, normalised). */
MESOLIGHTRELIEFTEXTURES_EXPORT void DecodeOctahedral8(std::int8_t e0, std::int8_t e1, float n[3]);

/**
 * The eight moments level of detail's visible normal filter reads, of a unit normal n weighted
 * by w = 1 / max(nz, 1/16), the texel's surface area over its base area (LEAN mapping, Olano and
 * Baker, "LEAN Mapping", I3D 2010, here with the 3D second-moment matrix): m[0..3] = w nx^2,
 * w ny^2, w nx ny, w nz^2 and m[4..7] = w nx nz, w ny nz, w nx, w ny (mlMomentTexture0 and 1).
 * n is normalised here (a zero vector is taken as (0, 0, 1)).
 */
constexpr int NormalMomentCount = 8;
MESOLIGHTRELIEFTEXTURES_EXPORT void NormalMoments(float x, float y, float z, float m[8]);

/**
 * The first mip level whose normal moments are uploaded. A moment is an average of per-texel
 * values, so level 0's are those of each texel's own normal (its outer product) and level 1's
 * the mean of four of them: the shader computes both from the stored normals (16 texels for a
 * bilinear lookup of level 1) and the texture starts at level 2, a sixteenth of level 0's texels.
 */
constexpr int NormalMomentFirstStoredLevel = 2;

/** Size of mip level `level` of a w x h texture, as OpenGL sizes it: max(1, floor(w / 2^l)). */
MESOLIGHTRELIEFTEXTURES_EXPORT int MipLevelSize(int size, int level);

/**
 * The moments (NormalMoments, NormalMomentCount floats a texel, row-major) of mip level `level`
 * of a w x h normal map, sized by MipLevelSize: each level's texel (i, j) is the mean of the
 * finer level's texels 2i, 2i + 1 by 2j, 2j + 1, clamped to that level (an odd last row or
 * column is left out, a size of 1 kept), as the shader's reconstruction of level 1 reads them.
 * Computed from level 0 directly, without the finer levels. normalXY holds each texel's normal
 * x, y interleaved; normalZ its z, or null to rebuild it as sqrt(1 - x^2 - y^2).
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> NormalMomentLevel(
  const float* normalXY, const float* normalZ, int w, int h, int level);

/**
 * NormalMomentLevel of the surface a depth map defines rather than of stored normals: each
 * level-0 texel's moments are the mean of those of the bilinear surface's normal over the texel
 * (one sample at the centre of each quarter, each in one cell of the surface), with the normal
 * convention of NormalFromGradient at depthScale. What a footprint of the surface the relief
 * mapper shades up close (NormalsAreTheDepths) holds, the spread inside each texel included.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> SurfaceNormalMomentLevel(
  const float* depth, int w, int h, double depthScale, int level);

} // namespace mesolight

#endif
