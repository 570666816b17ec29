// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ConeMaps.h
 * @brief Cone maps (conservative and relaxed) and min-depth pyramids for relief ray marching
 *        (plain C++17, no VTK types).
 *
 * References:
 *  - J. Dummer, "Cone Step Mapping: An Iterative Ray-Heightfield Intersection Algorithm",
 *    2006 (conservative cones).
 *  - F. Policarpo, M. M. Oliveira, "Relaxed Cone Stepping for Relief Mapping", GPU Gems 3,
 *    ch. 18, 2007 (relaxed cones).
 *  - R. Ban, G. Valasek, C. Balint, V. A. Vad, "Robust Cone Step Mapping", EGSR 2024
 *    (exact relaxed cones from "falling edge" texels; neighbourhood minimum so that cones stay
 *    valid under bilinear filtering).
 *  - A. Tevs, I. Ihrke, H.-P. Seidel, "Maximum Mipmaps for Fast, Accurate, and Scalable
 *    Dynamic Height Field Rendering", I3D 2008 (the min-depth pyramid).
 *
 * Conventions (shared with reliefcore/core/HeightFieldTracer.h and the relief shaders):
 *  - texture space (u, v, d); d = depth in [0,1], 0 = top surface, 1 = deepest;
 *  - a depth map is w*h floats, row-major, row j = 0 at v ~ 0; sample (i, j) sits at the texel
 *    centre ((i + 0.5) / w, (j + 0.5) / h); the continuous surface is GL_LINEAR +
 *    CLAMP_TO_EDGE bilinear interpolation of the samples;
 *  - horizontal distances are in TEXTURE WIDTHS (u units). Texels are square, so texels
 *    (i, j) and (k, l) are hypot(k - i, l - j) / w apart;
 *  - a cone at texel p has its apex at the surface point (p, d_p) and opens upward (toward
 *    d = 0). Its ratio c = horizontal radius / vertical extent: at depth d < d_p its radius
 *    is c * (d_p - d). Ratios are clamped to [0, MaxRatio] (default kConeMaxRatio = 1e3,
 *    reached in flat areas and on the shallowest texels), stored as float.
 *
 * Cone definitions (stated for the continuous surface; evaluated as described below):
 *  - Conservative (Dummer): the widest cone containing no point of the height field, i.e.
 *    c_p = min over surface points q shallower than the apex of dist(p, q) / (d_p - d_q).
 *  - Relaxed (Policarpo; exact version after Ban et al.): the widest cone such that every
 *    straight ray segment that starts on the cone axis above the apex and goes down to the
 *    cone's side (that is, every step of relaxed cone stepping) crosses the surface at most
 *    once, from above to below, and never comes back above. Along one direction from p this
 *    is c_p <= r_q / (d_p - d_q) for every "falling edge" q at distance r_q, i.e. a point
 *    shallower than the apex behind which, seen from p, the surface gets deeper again (a ray
 *    that is below the surface at q would come out above it). The minimum over the falling
 *    edges is exact for that condition (take, for any violating pair of points, the last
 *    point at or above the shallower one's depth). Policarpo's original generator tests rays
 *    aimed at the apex only, which is not enough for a step that starts above the apex, and
 *    Ban et al. show its cones are too wide. A texel q is a falling edge for p when the
 *    bilinear surface, leaving q in the direction q - p, has a positive one-sided
 *    derivative (or a zero one and a positive second-order term).
 *  - Bilinear safety (default, ConeMapOptions::BilinearSafe): the renderer reads the depth AND
 *    the ratio with bilinear filtering at any point between texel centres. Ban et al. show
 *    that per-texel cones are then not enough. Here the cones are provably valid for every
 *    apex on the bilinear surface: for each cell X of the texel-centre grid a ratio R_X is
 *    computed that is <= the exact (continuous) cone ratio at every apex position in X, and
 *    each texel stores the minimum of R_X over the 4 cells it is a corner of, so any
 *    bilinearly interpolated ratio (a convex combination of a cell's 4 corners) is valid
 *    (the role of Ban et al.'s 3 x 3 minimum pass). R_X bounds |y - x| / (D(x) - D(y)) over
 *    the points y of every other cell Y that could violate the definition (conservative: any
 *    shallower point; relaxed: a falling point, detected from the cell's gradient range and
 *    the directions from X to Y), with
 *      far cells (2+ apart): (y - x).n - r (D(x) - D(y)) is multi-affine in the 4 coordinates,
 *        so its minimum over X x Y is at one of the 16 corner pairs (exact corner depths);
 *      near cells: D(x) - D(y) <= G |x - y| (G: largest gradient norm around X) and, for
 *        relaxed cones, <= V |x - y| (V: spread of the gradients around X; a falling point
 *        has a non-negative slope along the ray, so the drop before it is bounded by how much
 *        the gradient varies: planes get no bound at all).
 *    Details and proofs in ConeMapBounds.cxx. There is no empirical safety factor; the stored float
 *    is truncated toward zero (never wider than the bound).
 *    Cost: the fast search is a branch and bound over a min-depth pyramid of cells with
 *    per-octant minima over the cells that can fall in that octant (so that cells rising away
 *    from the apex are skipped), after a direct search of the cells within 3 of the apex (the
 *    ring search of Ban et al.), and a node is not opened when it is small against its
 *    distance (Valasek & Ban 2022's coarse max-mipmap texels): within ConeMapOptions::Tolerance.
 *  - BilinearSafe off: per-texel cones over the texel samples only (the definitions above
 *    with q ranging over texels and IsFallingEdgeNear); NOT valid under bilinear filtering
 *    (grazing rays pass the first hit); kept as a comparison (mesolight bench cones).
 *
 * Encodings of a ratio c:
 *  - float (e.g. the Float packing of vtkConeMapFilter): c itself, in [0, MaxRatio];
 *  - 8 bits: c' = c / (1 + c) in [0, 1) (monotone, no clamp needed), stored as
 *    floor(255 c') so the decoded cone is never wider than the computed one;
 *    decoding is c = c' / (1 - c') with c' = byte / 255 (GLSL: c = x / (1.0 - x)).
 */
#ifndef mesolight_ConeMaps_h
#define mesolight_ConeMaps_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

#include "MinDepthPyramid.h" // the min-depth pyramid (declared there)
#include "Progress.h"

#include <cstdint>
#include <functional>
#include <vector>

namespace mesolight
{

/// Largest stored cone ratio (flat areas, shallowest texels).
constexpr float kConeMaxRatio = 1000.0f;

enum class ConeType
{
  Relaxed,
  Conservative
};

struct ConeMapOptions
{
  /**
   * Rows run on mesolight::ParallelFor (vtkSMPTools). 1 computes on the calling thread only
   * (benchmarks, tests); any other value uses all of vtkSMPTools' threads. The result does not
   * depend on it.
   */
  int Threads = 0;
  /**
   * Called from the calling thread with the fraction done in [0,1] between chunks of rows;
   * returning false aborts and the function returns an empty vector (Progress.h).
   */
  ProgressCallback Progress;
  /**
   * Default on: cones valid on the bilinear surface, for every apex position and every read of
   * the ratio with bilinear filtering (the cell bound of the file comment; provable, no safety
   * factor). Off: the per-texel cones over the texel samples only (narrower definition of
   * validity, NOT safe under bilinear filtering; kept for comparison and tests).
   */
  bool BilinearSafe = true;
  /**
   * Relative tolerance of the fast bilinear-safe search: the result r satisfies
   * exact / (1 + Tolerance) <= r <= exact, where exact is what the brute-force oracle returns
   * (still a valid cone: it is never wider). 0 gives results bit-identical to the oracle.
   */
  float Tolerance = 0.25f;
  /// Clamp of the ratios (flat areas). Default kConeMaxRatio.
  float MaxRatio = kConeMaxRatio;
};

/**
 * Conservative cone ratios (Dummer 2006), w*h floats (same layout as depth). Empty on abort
 * or when w < 1 or h < 1. Depths are expected finite, in [0,1].
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> ComputeConservativeConeMap(
  const float* depth, int w, int h, const ConeMapOptions& options = ConeMapOptions());

/// Relaxed cone ratios (Policarpo & Oliveira 2007, exact per Ban et al. 2024). As above.
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> ComputeRelaxedConeMap(
  const float* depth, int w, int h, const ConeMapOptions& options = ConeMapOptions());

/// Dispatch on type.
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> ComputeConeMap(ConeType type, const float* depth,
  int w, int h, const ConeMapOptions& options = ConeMapOptions());

///@{
/**
 * TEST ORACLES: the same definitions by exhaustive O((w h)^2) search, single-threaded (only
 * Options.BilinearSafe and MaxRatio are used). The fast versions are bit-identical to them
 * with Tolerance 0, and within [oracle / (1 + Tolerance), oracle] otherwise.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> ComputeConservativeConeMapBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options = ConeMapOptions());
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> ComputeRelaxedConeMapBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options = ConeMapOptions());
///@}

/**
 * True when texel q = (qi, qj) is a falling edge seen from texel p = (pi, pj) (p != q): the
 * clamp-to-edge bilinear surface leaving q in the direction q - p gets deeper at once
 * (positive one-sided derivative, or zero and a positive second-order term).
 */
MESOLIGHTRELIEFTEXTURES_EXPORT bool IsFallingEdge(
  const float* depth, int w, int h, int pi, int pj, int qi, int qj);

/**
 * True when q is a falling edge along the direction toward q from SOME point of the square
 * [pi - 1, pi + 1] x [pj - 1, pj + 1]: the apex positions whose bilinear lookups read texel
 * p's ratio. The relaxed cone maps use this (a superset of IsFallingEdge) so that a ratio
 * stays valid for apexes between texel centres.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT bool IsFallingEdgeNear(
  const float* depth, int w, int h, int pi, int pj, int qi, int qj);

/// 8-bit ratio: floor(255 c / (1 + c)), never decoding to more than c. NaN or c <= 0 -> 0.
MESOLIGHTRELIEFTEXTURES_EXPORT std::uint8_t EncodeConeRatio8(float ratio);
/// Inverse of the 8-bit encoding: c' / (1 - c') with c' = code / 255 (255 -> infinity).
MESOLIGHTRELIEFTEXTURES_EXPORT float DecodeConeRatio8(std::uint8_t code);

} // namespace mesolight

#endif
