// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ConeMapBounds.h
 * @brief The cone map definitions as code (plain C++17, internal to Mesolight::Filters): texel
 *        access, the per-texel ratio, falling edges and the bilinear-safe cell-pair bound that
 *        the fast searches (ConeMaps.cxx) and the brute-force oracle (ConeMapOracle.cxx) both
 *        evaluate, so that they agree bit for bit. ConeMaps.h states the definitions.
 */
#ifndef mesolight_ConeMapBounds_h
#define mesolight_ConeMapBounds_h

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace mesolight
{
namespace conemaps
{

/// Depth of texel (i, j), indices clamped into the image (CLAMP_TO_EDGE).
inline float At(const float* depth, int w, int h, int i, int j)
{
  i = std::min(std::max(i, 0), w - 1);
  j = std::min(std::max(j, 0), h - 1);
  return depth[static_cast<std::size_t>(j) * w + i];
}

// The ratio a texel q (offset di, dj from the apex, depth dq < dp) allows. Written once so the
// fast search and the oracle compute bit-identical values; every operation is monotone, so a
// lower bound computed with the same formula from smaller offsets / depths is a true bound.
inline double Ratio(long long di2dj2, int w, double dp, double dq)
{
  return std::sqrt(static_cast<double>(di2dj2)) / w / (dp - dq);
}

// The 4 corner depths of cell (ci, cj) of the texel-centre grid (ConeMapBounds.cxx explains
// the cells and the bound).
struct CellCorners
{
  double D[4]; // (ci-1, cj-1), (ci, cj-1), (ci-1, cj), (ci, cj)

  CellCorners(const float* depth, int w, int h, int ci, int cj)
  {
    this->D[0] = At(depth, w, h, ci - 1, cj - 1);
    this->D[1] = At(depth, w, h, ci, cj - 1);
    this->D[2] = At(depth, w, h, ci - 1, cj);
    this->D[3] = At(depth, w, h, ci, cj);
  }
  double Min() const { return std::min(std::min(D[0], D[1]), std::min(D[2], D[3])); }
  double Max() const { return std::max(std::max(D[0], D[1]), std::max(D[2], D[3])); }
  // Largest gradient norm on the cell (per grid unit): d/du ranges over D1 - D0 .. D3 - D2
  // (linearly in v), d/dv over D2 - D0 .. D3 - D1; the norm is largest at a corner.
  double GradientNorm() const
  {
    const double gx = std::max(std::abs(D[1] - D[0]), std::abs(D[3] - D[2]));
    const double gy = std::max(std::abs(D[2] - D[0]), std::abs(D[3] - D[1]));
    return std::sqrt(gx * gx + gy * gy);
  }
  // Sign of the largest derivative along (vx, vy) anywhere on the cell.
  int MaxSlopeSign(double vx, double vy) const
  {
    const double gx0 = D[1] - D[0], gx1 = D[3] - D[2];
    const double gy0 = D[2] - D[0], gy1 = D[3] - D[1];
    const double m = vx * (vx > 0.0 ? std::max(gx0, gx1) : std::min(gx0, gx1)) +
      vy * (vy > 0.0 ? std::max(gy0, gy1) : std::min(gy0, gy1));
    return m > 0.0 ? 1 : (m == 0.0 ? 0 : -1);
  }
  double Twist() const { return D[3] - D[2] - D[1] + D[0]; }
};

// Can the cell contain a falling point along some direction of the convex cone spanned by the
// n vectors g? Along direction t the cell's depth is d0 + s (t . grad) + s^2 tx ty twist; any
// direction of the cone is a non-negative combination of the g's, so its slope is positive
// somewhere only if some g's is, and zero at best only if some g's is zero at best (then the
// second-order term decides; we accept any non-zero twist).
bool CellMayFall(const CellCorners& c, const double (*g)[2], int n);

/**
 * The cell-pair bound of the bilinear-safe cones (ConeMapOptions::BilinearSafe): per cell the
 * largest gradient norm and gradient spread around it, and PairBound.
 */
class CellPairBounds
{
public:
  CellPairBounds(const float* depth, int w, int h, bool relaxed);

  // Lower bound (texture widths per unit depth) of the cone ratio at every apex of cell X over
  // the surface of cell Y; +inf when Y cannot constrain X.
  // Pairs that cannot go below `cutoff` may return +inf early (the minimum is unchanged).
  double PairBound(int xi, int xj, const CellCorners& cx, int yi, int yj, double cutoff) const;

protected:
  // min over corner pairs (k, l) with D_k > D_l of ((y_l - x_k).n) / (D_k - D_l), grid units.
  static double ProjectedBound(
    const CellCorners& cx, const CellCorners& cy, double nx, double ny, int dx, int dy);

  const float* Depth;
  int W;
  int H;
  int CW; // cells per row: w + 1
  int CH; // cells per column: h + 1
  bool Relaxed;
  std::vector<float> Lipschitz;
  std::vector<float> Variation;
};

// Largest float not above x (the stored cone is never wider than the computed bound).
float TruncateToFloat(double x);

// Per texel: the minimum of R_X over the (up to) 4 cells the texel is a corner of.
std::vector<float> TexelsFromCells(const std::vector<double>& cells, int w, int h);

} // namespace conemaps
} // namespace mesolight

#endif
