// SPDX-License-Identifier: BSD-3-Clause
/**
 * HeightFieldTracer: the exact CPU reference that GPU ray-marched relief mapping is measured
 * against. Plain C++17 + GLM, no VTK types, so it unit-tests fast and reads like the math.
 *
 * Conventions (shared with the relief shaders):
 *  - Texture space (u, v, d): u, v in [0, 1] across the map; d is depth, 0 = the top surface (the
 *    mesh), 1 = deepest. A ray going into the surface has increasing d.
 *  - A height field is W x H depth samples, row-major; row j = 0 is v near 0, column i = 0 is u
 *    near 0. Sample (i, j) sits at the texel centre ((i + 0.5) / W, (j + 0.5) / H).
 *  - The continuous surface is exactly GL_LINEAR + GL_CLAMP_TO_EDGE sampling of that texture
 *    (in exact arithmetic): bilinear between the four nearest texel centres, constant extension
 *    outside the centre grid (u < 0.5 / W uses column 0, and so on, also outside [0, 1]).
 *  - A point (u, v, d) is "on or below" the surface when d >= depth(u, v).
 *  - The edge rule (HeightField::Edge): Clamped (the default) continues the surface beyond
 *    [0, 1]^2 as above, the sampler's own extension (a tiled or cut-out relief never sees it);
 *    Walled is a relief recessed into a wall: outside [0, 1]^2 the solid reaches the surface
 *    (depth 0), so a ray below the surface that reaches the texture rectangle's border meets a
 *    side wall there (RayHit::Wall), as it meets the side walls of the dense displaced mesh
 *    (vtkScene/core/SurfaceRelief.h) and the relief shader's (mlOutsideWalledRelief).
 */

#ifndef mesolight_HeightFieldTracer_h
#define mesolight_HeightFieldTracer_h

#include "MesolightReliefCoreModule.h" // for the export macro

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <optional>
#include <vector>

namespace mesolight
{

/** W x H depth samples and the continuous bilinear, clamp-to-edge surface through them. */
class MESOLIGHTRELIEFCORE_EXPORT HeightField
{
public:
  /** What lies beyond the texture rectangle [0, 1]^2 (see the conventions above). */
  enum class Edge
  {
    Clamped, // the clamp-to-edge surface continues
    Walled   // the solid reaches the surface: depth 0, side walls at the rectangle's border
  };

  /**
   * depth holds w * h samples, row-major, row 0 at v ~ 0. Throws std::invalid_argument when
   * w < 1, h < 1, depth.size() != w * h, or a sample is not finite (the message names it).
   */
  HeightField(int w, int h, std::vector<float> depth, Edge edge = Edge::Clamped);

  int Width() const { return this->W; }
  int Height() const { return this->H; }
  Edge EdgeRule() const { return this->Border; }
  void SetEdgeRule(Edge edge) { this->Border = edge; }
  /** True when the edge is Walled and (u, v) lies outside [0, 1]^2 (the border itself inside). */
  bool OutsideWall(double u, double v) const;

  /** Sample at column i, row j (0 <= i < W, 0 <= j < H; not range-checked). */
  float Texel(int i, int j) const { return this->Depth[static_cast<std::size_t>(j) * this->W + i]; }

  /** Texel with both indices clamped into range: the clamp-to-edge extension of the samples. */
  double ClampedTexel(int i, int j) const;

  /**
   * Surface depth at (u, v): GL_LINEAR + GL_CLAMP_TO_EDGE, evaluated exactly in double; 0 outside
   * [0, 1]^2 when the edge is Walled.
   */
  double DepthAt(double u, double v) const;

  /**
   * (d depth / du, d depth / dv) of the bilinear surface. Zero across a clamp band. On a cell
   * boundary (a crease of the surface) this is the derivative of the cell on the +u / +v side.
   * Zero outside a Walled field's rectangle.
   */
  glm::dvec2 GradientAt(double u, double v) const;

private:
  int W;
  int H;
  std::vector<float> Depth;
  Edge Border = Edge::Clamped;
};

struct RayHit
{
  double t;         // ray parameter: point = origin + t * dir
  glm::dvec3 point; // (u, v, d) of the hit
  // Zero on the height field; on a Walled field's side wall, the wall's unit normal in (u, v),
  // pointing back into the rectangle (e.g. (0, -1) on the wall along v = 1).
  glm::dvec2 wall{ 0.0, 0.0 };
};

/**
 * Exact first intersection of the ray origin + t * dir, t in [0, tMax], with the surface: the
 * smallest t at which the ray goes from above to on/below (t = 0 if the origin is already on or
 * below). dir need not be normalized; any dir.z works (down, horizontal, up). Cost is
 * O(texel cells crossed). Returns nullopt on a miss, tMax < 0, or any non-finite input
 * (tMax included: pass a finite bound). The returned t is the upper end of a bracket of width
 * <= 1e-12 * max(1, t) around the first sign change of (ray d - surface depth) as evaluated in
 * double: the point at t is on or below, just before it the ray is above.
 */
MESOLIGHTRELIEFCORE_EXPORT std::optional<RayHit> IntersectFirst(
  const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tMax);

/**
 * True when the ray from point (on the surface) toward the light reaches d <= 0 (leaves the top
 * of the height field) without passing strictly below the surface. toLight.z < 0 points up; a
 * light at or below the horizon (toLight.z >= 0) gives false, as does any non-finite input. The
 * ray starts epsilon along normalize(toLight) from point, to avoid self-intersection.
 */
MESOLIGHTRELIEFCORE_EXPORT bool Visible(
  const HeightField& hf, const glm::dvec3& point, const glm::dvec3& toLight, double epsilon = 1e-6);

/** Visible's answer and, when its march was stopped by the surface, where. */
struct Visibility
{
  bool Visible = false;
  // Where the ray first passed strictly below the surface (a side wall's point on a Walled
  // field; t is measured from the ray's start, epsilon along normalize(toLight) from the point,
  // in that unit direction); empty when Visible, and when not Visible without a march (a light
  // at or below the horizon, non-finite input).
  std::optional<RayHit> Blocker;
};

/**
 * Visible, with the point that blocks the ray: one march for a caller that needs both whether a
 * direction leaves the relief and, if not, what it meets (the relief's seen shares). The blocker
 * is IntersectFirst's hit for the same ray except where the ray only touches the surface before
 * it (on-or-below there, strictly below here).
 */
MESOLIGHTRELIEFCORE_EXPORT Visibility VisibleOrBlocker(
  const HeightField& hf, const glm::dvec3& point, const glm::dvec3& toLight, double epsilon = 1e-6);

/**
 * How many cells of the texel-centre grid the ray origin + t * dir, t in [0, tEnd], reaches at
 * or below the cell's shallowest corner (the bound a maximum mipmap keeps for it; Tevs, Ihrke
 * and Seidel, "Maximum Mipmaps for Fast, Accurate, and Scalable Dynamic Height Field
 * Rendering"). With tEnd the exact first hit (IntersectFirst), it is the fewest patch tests any
 * exact traversal of per-cell depth bounds can make (max mipmaps, quadtree displacement mapping):
 * every coarser bound is at most as deep, so none of them rules such a cell out, and its four
 * corners must be read. The hit's own cell counts. 0 for non-finite input or tEnd < 0. Clamped
 * edge rule (the bands count as cells).
 */
MESOLIGHTRELIEFCORE_EXPORT int CountBoundReachingCells(
  const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tEnd);

/**
 * TEST ORACLE ONLY: dense uniform sampling of [0, tMax] at `samples` steps, then bisection on the
 * first on/below sample. Independent of IntersectFirst's cell logic (it only uses DepthAt), but it
 * can miss features thinner than a step, so it may report a later hit or none; never an earlier
 * one. Throws std::invalid_argument if samples < 1.
 */
MESOLIGHTRELIEFCORE_EXPORT std::optional<RayHit> IntersectFirstBruteForce(
  const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tMax, int samples);

} // namespace mesolight

#endif
