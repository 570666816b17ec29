// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MinDepthPyramid.h
 * @brief Min-depth pyramids (plain C++17, no VTK types): the one builder behind the
 *        maximum-mipmap pyramid the relief renderer traces and the node pyramids of the cone map
 *        searches (Tevs, Ihrke, Seidel, "Maximum Mipmaps for Fast, Accurate, and Scalable
 *        Dynamic Height Field Rendering", I3D 2008; our depth grows downward, so their maximum
 *        height is our minimum depth).
 */
#ifndef mesolight_MinDepthPyramid_h
#define mesolight_MinDepthPyramid_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

#include <cstdint>
#include <utility>
#include <vector>

namespace mesolight
{

/**
 * Min-depth pyramid for exact maximum-mipmap tracing (Tevs et al. 2008; our depth grows
 * downward, so their maximum height is our minimum depth).
 *
 * Level 0 has one value per CELL of the texel-centre grid, clamp-extension border included:
 * (w + 1) x (h + 1) values, row-major. Cell (ci, cj) covers grid x in [ci - 1, ci] and y in
 * [cj - 1, cj] (texel centres on the integers, x = u w - 0.5), i.e. the bilinear patch
 * between texels (ci - 1 .. ci, cj - 1 .. cj) with indices clamped into the image; cells 0
 * and w (rows 0 and h) are the clamp bands outside the outermost centres. Its value is the
 * minimum of the patch's 4 corner texels, which bounds the bilinear patch from above
 * (every point of the cell is at least that deep).
 *
 * Level k + 1 has max(1, W_k / 2) x max(1, H_k / 2) values (sizes halve rounding down, as a
 * complete OpenGL mipmap requires), each the minimum over its children 2i .. 2i + 1,
 * 2j .. 2j + 1; the last parent of a row or column also takes the odd child left over, so
 * child (i, j) belongs to parent (min(i / 2, W_{k+1} - 1), min(j / 2, H_{k+1} - 1)). The last
 * level is 1 x 1. Empty when w < 1 or h < 1. Level sizes: see MinDepthPyramidLevelSize().
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<std::vector<float>> ComputeMinDepthPyramid(
  const float* depth, int w, int h);

/// Size of pyramid level `level` for a w x h depth map: level 0 is (w + 1) x (h + 1), then
/// halving rounded down (at least 1). Returns false if the level does not exist.
MESOLIGHTRELIEFTEXTURES_EXPORT bool MinDepthPyramidLevelSize(
  int w, int h, int level, int& lw, int& lh);

/**
 * Levels 1 and up of a min-depth pyramid as RGBA, for the four-children traversal: a cell of
 * level l holds the minima of its children (2i, 2j), (2i+1, 2j), (2i, 2j+1), (2i+1, 2j+1) of
 * level l - 1 (channels 0..3), the odd child left over at a row's or column's end folded into
 * the last cell's second child; a missing child (a level one cell wide or high) repeats a
 * present one's bound, so the minimum of the four channels is the cell's own bound. `minima`
 * holds one value per cell per level (level 0 included, as ComputeMinDepthPyramid or the
 * 16-bit CompactMinDepthPyramid gives them), `sizes` each level's (w, h). Entry 0 of the result
 * is empty (level 0 holds corner depths, not children). Minima of 16-bit values are exact.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<std::vector<float>> PackChildMinima(
  const std::vector<std::vector<float>>& minima, const std::vector<std::pair<int, int>>& sizes);
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<std::vector<std::uint16_t>> PackChildMinima(
  const std::vector<std::vector<std::uint16_t>>& minima,
  const std::vector<std::pair<int, int>>& sizes);

/**
 * Levels firstLevel and up of the min-depth pyramid of a w x h depth map, packed as
 * PackChildMinima packs them (RGBA: each cell its 2 x 2 children's minima), for a traversal
 * that reads level 0's corners from the depth texture itself and stores no level between.
 * Levels a small map lacks (past 1 x 1) are 1 x 1 copies of its apex, so level firstLevel
 * always exists. levelSizes: (w, h) per returned level. Empty for an empty map or
 * firstLevel < 1.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<std::vector<float>> ChildMinimaFromLevel(
  const float* depth, int w, int h, int firstLevel, std::vector<int>& levelSizes);

/// One level of a min pyramid: W x H nodes of Channels floats each (node-major), a node
/// covering Size x Size base elements. Used inside Mesolight::Filters (not exported).
struct MinPyramidLevel
{
  int W;
  int H;
  int Size;
  std::vector<float> Min;
};

/// How a level's size halves: RoundUp (ceil, every parent has its children 2i, 2i + 1) or
/// RoundDown (floor, at least 1, the last parent of a row or column also takes the odd child
/// left over: a complete OpenGL mipmap).
enum class PyramidHalving
{
  RoundUp,
  RoundDown
};

/**
 * Appends to `levels` (holding at least the base level) the coarser levels up to 1 x 1, each
 * node the channel-wise minimum of its children (+infinity where none), children visited in
 * row-major order.
 */
void AddMinPyramidLevels(
  std::vector<MinPyramidLevel>& levels, int channels, PyramidHalving halving);

} // namespace mesolight

#endif
