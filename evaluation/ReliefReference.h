// SPDX-License-Identifier: BSD-3-Clause
// The exact per-pixel answer of an ideal relief renderer, computed on the CPU.
//
// For a relief scene (a wall at z = 0 drawn by vtkReliefMapper, see ReliefScene.h) every pixel
// centre's view ray is intersected with the wall's plane; where it enters the wall (the coarse
// mesh's footprint) it is continued into texture space (u, v, d) and traced to its exact first hit
// with the bilinear height field of the relief texture's depth (mesolight::IntersectFirst, the same
// GL_LINEAR + CLAMP_TO_EDGE surface the GPU samples). With silhouettes on, a pixel is covered when
// the hit lies inside the texel-centre domain (the extent of the dense reference mesh). At the hit,
// the first light's visibility is traced too (mesolight::Visible).
//
// Conventions: the wall is z = 0 with world x = u and world y = v * H / W (W x H texels), facing
// +z; depth d in [0, 1] lies at world z = -d * DepthScale (the wall is one world unit per u unit).
// Pixels are numbered like mesolight::Frame: row 0 is the bottom row.
#ifndef mesolight_ReliefReference_h
#define mesolight_ReliefReference_h

#include "MesolightEvaluationModule.h" // for the export macro

#include <cstddef>
#include <string>
#include <vector>

class vtkCamera;
class vtkImageData;
class vtkRenderer;

namespace mesolight
{
struct Frame;
struct ReliefScene;
struct ReliefSceneOptions;

/** What the reference is computed from; the world geometry follows the conventions above. */
struct ReliefReferenceInput
{
  vtkCamera* Camera = nullptr;
  int Width = 0; // window size in pixels
  int Height = 0;
  vtkImageData* Relief = nullptr; // relief texture: depth in the last (4th) scalar component
  double DepthScale = 0.04;
  // The first light, in world coordinates. Directional: the direction toward the light.
  // Positional: the light's position. No light: HasLight = false (every hit is then unlit).
  bool HasLight = false;
  bool LightPositional = false;
  double Light[3] = { 0.0, 0.0, 1.0 };
  // Also count, per pixel, what exact bound traversals must fetch (BoundReachingCells and the
  // oracle's counts below): for `bench relief`; off, those stay -1 and cost nothing.
  bool CountTraversalFetches = false;
};

/** Per-pixel result. Fields other than State are meaningful only for covered pixels. */
struct MESOLIGHTEVALUATION_EXPORT ReliefReference
{
  enum PixelState : unsigned char
  {
    OutsideFootprint = 0, // the ray misses the wall: the relief cannot draw here
    Uncovered = 1,        // inside the footprint, but the hit leaves the texel-centre domain
    Covered = 2
  };

  int Width = 0;
  int Height = 0;
  int TextureWidth = 0; // texels
  int TextureHeight = 0;
  double WallHeight = 1.0; // for a width of 1 (the texture's ground proportions)
  double DepthScale = 0.0;
  std::vector<unsigned char> State;
  std::vector<double> HitU; // texture coordinates of the first hit
  std::vector<double> HitV;
  std::vector<double> HitD;     // depth of the hit, 0 = surface, 1 = deepest
  std::vector<double> EyeDepth; // distance of the hit from the eye plane (cf. Frame::EyeDepth)
  // The first light reaches the hit without passing below the height field (Visible).
  std::vector<unsigned char> Unshadowed;
  // The bilinear surface at the hit faces the first light (n . l > 0).
  std::vector<unsigned char> FacesLight;
  // Cells whose depth bound the ray reaches before its hit (CountBoundReachingCells): the fewest
  // patch tests, so texture fetches, of any exact traversal of per-cell bounds; -1 where the
  // pixel is not covered (or ReliefReferenceInput::CountTraversalFetches is off).
  std::vector<int> BoundReachingCells;
  // The fewest fetches of such a traversal told the right level at every step
  // (BoundTraversalOracle): over the pyramid levels the compact storage keeps
  // (vtkMinDepthPyramidTexture), and over every level; -1 as above.
  std::vector<int> OracleFetchesStoredLevels;
  std::vector<int> OracleFetchesAllLevels;
  double Seconds = 0.0; // time taken to compute it

  bool InFootprint(size_t p) const { return this->State[p] != OutsideFootprint; }
  bool IsCovered(size_t p) const { return this->State[p] == Covered; }
  /** What vtkReliefMapper's LightVisibilityOutput shows: facing the first light, not shadowed. */
  bool LightVisible(size_t p) const { return this->Unshadowed[p] && this->FacesLight[p]; }
  /** World position of a covered pixel's hit. */
  void HitPosition(size_t p, double position[3]) const;
  long long CountFootprint() const;
  long long CountCovered() const;
};

/**
 * Computes the reference. Rows are traced in parallel (vtkSMPTools). False with a message when
 * the input is unusable (no camera, empty size, a relief texture without a depth channel, a
 * non-positive depth scale).
 */
MESOLIGHTEVALUATION_EXPORT bool ComputeReliefReference(
  const ReliefReferenceInput& input, ReliefReference& reference, std::string& error);

/**
 * The input for a built relief scene: its renderer's active camera and first light, its relief
 * texture, the options' window size and depth scale (or depthScale when it is positive, e.g. to
 * compute a deliberately wrong reference).
 */
MESOLIGHTEVALUATION_EXPORT ReliefReferenceInput MakeReliefReferenceInput(
  const ReliefScene& scene, const ReliefSceneOptions& options, double depthScale = 0.0);

/** A GPU render's hit coordinates (HitUOutput, HitVOutput frames) against the reference. */
struct HitComparison
{
  double MeanTexels = 0.0; // |uv_gpu - uv_cpu| * (W, H), Euclidean, over pixels covered in both
  double P99Texels = 0.0;  // 99th percentile of the same
  double MaxTexels = 0.0;
  double SilhouetteMismatch = 0.0; // % of footprint pixels covered by exactly one of GPU and CPU
  long long CoveredBoth = 0;
  long long Footprint = 0;
};

/** Compares decoded hit coordinates; the frames must have the reference's size. */
MESOLIGHTEVALUATION_EXPORT HitComparison CompareHits(
  const ReliefReference& reference, const Frame& hitU, const Frame& hitV);

/**
 * % of the pixels covered in both where vtkReliefMapper's LightVisibilityOutput (white = lit)
 * disagrees with ReliefReference::LightVisible. coveredBoth receives the pixel count.
 */
MESOLIGHTEVALUATION_EXPORT double CompareLightVisibility(
  const ReliefReference& reference, const Frame& visibility, long long* coveredBoth = nullptr);

} // namespace mesolight

#endif
