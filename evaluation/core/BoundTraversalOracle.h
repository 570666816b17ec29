// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file BoundTraversalOracle.h
 * @brief What an exact traversal of per-cell depth bounds (maximum mipmaps: Tevs, Ihrke and
 *        Seidel, "Maximum Mipmaps for Fast, Accurate, and Scalable Dynamic Height Field
 *        Rendering"; quadtree displacement mapping: Drobot) must fetch at the least along one
 *        ray, given the pyramid levels it stores. Plain C++17 + GLM, no VTK types.
 *
 * The oracle is told, at every point of the ray, the coarsest stored cell whose bound the ray
 * stays above until it leaves the cell, so it navigates for free; it still pays for the data:
 *  - a cleared cell of level L >= 1 costs one fetch of its parent's texel (the packed layout,
 *    where a texel holds its 2 x 2 children's bounds), unless the texel of that level last
 *    fetched is that parent already (one texel per level kept in registers);
 *  - a level-0 cell that no stored cleared cell covers costs one fetch, its four corners (it is
 *    either the hit cell or one the ray must be shown to pass).
 * A lower bound under this model: a traversal that reads only these bounds and the corners and
 * holds at most one texel per level fetches no less, since it also spends fetches finding the
 * cells. (One holding several texels per level could reuse more; none of the measured
 * traversals does.) HeightFieldTracer's CountBoundReachingCells is the floor without any
 * navigation.
 */
#ifndef mesolight_BoundTraversalOracle_h
#define mesolight_BoundTraversalOracle_h

#include "MesolightEvaluationModule.h" // for the export macro

#include <glm/vec3.hpp>

#include <vector>

namespace mesolight
{
class HeightField;

class MESOLIGHTEVALUATION_EXPORT BoundTraversalOracle
{
public:
  /** The min-depth pyramid of hf's cells (ComputeMinDepthPyramid: exact minima). */
  explicit BoundTraversalOracle(const HeightField& hf);

  /**
   * The fetches along origin + t dir (texture space, dir.z > 0) from where the ray reaches the
   * map's smallest depth to tHit, the exact first hit (IntersectFirst), when the bounds of levels
   * finestBoundLevel and coarser are stored (0: every level; the default's compact storage keeps
   * levels 2 and up: vtkMinDepthPyramidTexture::FirstLevel - 1). At least 1 (the hit cell);
   * 0 for non-finite input, dir.z <= 0 or tHit < 0.
   */
  int Fetches(
    const glm::dvec3& origin, const glm::dvec3& dir, double tHit, int finestBoundLevel) const;

  int GetNumberOfLevels() const { return static_cast<int>(this->Levels.size()); }

private:
  int W = 0;
  int H = 0;
  std::vector<std::vector<float>> Levels; // per level, row-major cell bounds
  std::vector<int> LevelWidth;
  std::vector<int> LevelHeight;
};

} // namespace mesolight

#endif
