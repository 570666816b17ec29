// SPDX-License-Identifier: BSD-3-Clause
#include "ConeMaps.h"

#include "MinDepthPyramid.h"
#include "ParallelFor.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <limits>
#include <utility>

namespace mesolight
{
bool IsFallingEdgeNear(const float* depth, int w, int h, int pi, int pj, int qi, int qj);
namespace
{

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

// Min-depth tiles over TEXELS (not cells) for pruning the search: level 0 = kTile x kTile
// texels, each next level the minimum of 2 x 2 children (ceil halving). `candidate` says
// which texels may constrain a cone at all (all texels; or, for relaxed cones, texels with a
// strictly deeper 8-neighbour, the only possible falling edges); others count as depth +inf.
constexpr int kTile = 8;
constexpr float kNone = std::numeric_limits<float>::infinity();

using TileLevel = MinPyramidLevel; // one channel: the minimum candidate depth

bool HasDeeperNeighbour(const float* depth, int w, int h, int i, int j)
{
  const float d = depth[static_cast<std::size_t>(j) * w + i];
  for (int dj = -1; dj <= 1; ++dj)
  {
    for (int di = -1; di <= 1; ++di)
    {
      if ((di != 0 || dj != 0) && At(depth, w, h, i + di, j + dj) > d)
      {
        return true;
      }
    }
  }
  return false;
}

std::vector<TileLevel> BuildTiles(const float* depth, int w, int h, bool fallingOnly)
{
  std::vector<TileLevel> levels;
  TileLevel base{ (w + kTile - 1) / kTile, (h + kTile - 1) / kTile, kTile, {} };
  base.Min.assign(static_cast<std::size_t>(base.W) * base.H, kNone);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      if (fallingOnly && !HasDeeperNeighbour(depth, w, h, i, j))
      {
        continue;
      }
      float& m = base.Min[static_cast<std::size_t>(j / kTile) * base.W + i / kTile];
      m = std::min(m, depth[static_cast<std::size_t>(j) * w + i]);
    }
  }
  levels.push_back(std::move(base));
  AddMinPyramidLevels(levels, 1, PyramidHalving::RoundUp);
  return levels;
}

// The (up to 4) children of node (ti, tj) in the child level of w x h nodes with their bounds
// (bound(ci, cj, gap) returns a child's bound and sets its gap), nearest first: an insertion
// sort of <= 4, so equal bounds keep the row-major order. Both searches descend with it.
struct NodeChild
{
  double B;
  double Gap;
  int I;
  int J;
};
template <class BoundFunction>
int ChildrenNearestFirst(int w, int h, int ti, int tj, BoundFunction bound, NodeChild (&children)[4])
{
  int n = 0;
  for (int cj = 2 * tj; cj <= 2 * tj + 1 && cj < h; ++cj)
  {
    for (int ci = 2 * ti; ci <= 2 * ti + 1 && ci < w; ++ci)
    {
      double gap = 0.0;
      const double b = bound(ci, cj, gap);
      children[n++] = { b, gap, ci, cj };
    }
  }
  for (int a = 1; a < n; ++a)
  {
    for (int c = a; c > 0 && children[c].B < children[c - 1].B; --c)
    {
      std::swap(children[c], children[c - 1]);
    }
  }
  return n;
}

// Distance in texels (per axis) from texel index p to the index range [lo, hi].
inline int AxisGap(int p, int lo, int hi)
{
  return p < lo ? lo - p : (p > hi ? p - hi : 0);
}

// Exact cone search for one apex texel with a branch-and-bound descent of the tile pyramid,
// nearest nodes first (the maximum-mipmap idea of Tevs et al. 2008 applied to the search):
// a node is skipped when even its nearest texel at its shallowest candidate depth cannot give
// a narrower cone than the best so far.
class ConeSearch
{
public:
  ConeSearch(const float* depth, int w, int h, bool relaxed, double maxRatio)
    : Depth(depth)
    , W(w)
    , H(h)
    , Relaxed(relaxed)
    , MaxRatio(maxRatio)
    , Levels(BuildTiles(depth, w, h, relaxed))
  {
  }

  float Run(int pi, int pj) const
  {
    const double dp = this->Depth[static_cast<std::size_t>(pj) * this->W + pi];
    double best = this->MaxRatio;
    const int top = static_cast<int>(this->Levels.size()) - 1;
    this->Visit(top, 0, 0, pi, pj, dp, best);
    return static_cast<float>(best);
  }

private:
  double Bound(int level, int ti, int tj, int pi, int pj, double dp) const
  {
    const TileLevel& L = this->Levels[level];
    const float m = L.Min[static_cast<std::size_t>(tj) * L.W + ti];
    if (!(m < dp))
    {
      return std::numeric_limits<double>::infinity();
    }
    const int x0 = ti * L.Size;
    const int y0 = tj * L.Size;
    const long long gx = AxisGap(pi, x0, std::min(this->W, x0 + L.Size) - 1);
    const long long gy = AxisGap(pj, y0, std::min(this->H, y0 + L.Size) - 1);
    return Ratio(gx * gx + gy * gy, this->W, dp, m);
  }

  void Visit(int level, int ti, int tj, int pi, int pj, double dp, double& best) const
  {
    if (this->Bound(level, ti, tj, pi, pj, dp) >= best)
    {
      return;
    }
    if (level == 0)
    {
      this->Scan(ti, tj, pi, pj, dp, best);
      return;
    }
    const TileLevel& C = this->Levels[level - 1];
    NodeChild children[4];
    const int n = ChildrenNearestFirst(C.W, C.H, ti, tj,
      [&](int ci, int cj, double&) { return this->Bound(level - 1, ci, cj, pi, pj, dp); }, children);
    for (int k = 0; k < n; ++k)
    {
      if (children[k].B >= best)
      {
        break;
      }
      this->Visit(level - 1, children[k].I, children[k].J, pi, pj, dp, best);
    }
  }

  void Scan(int ti, int tj, int pi, int pj, double dp, double& best) const
  {
    const int x1 = std::min(this->W, (ti + 1) * kTile);
    const int y1 = std::min(this->H, (tj + 1) * kTile);
    for (int qj = tj * kTile; qj < y1; ++qj)
    {
      const float* row = this->Depth + static_cast<std::size_t>(qj) * this->W;
      const long long dj = qj - pj;
      for (int qi = ti * kTile; qi < x1; ++qi)
      {
        const double dq = row[qi];
        if (!(dq < dp))
        {
          continue;
        }
        const long long di = qi - pi;
        const double r = Ratio(di * di + dj * dj, this->W, dp, dq);
        if (r < best &&
          (!this->Relaxed || IsFallingEdgeNear(this->Depth, this->W, this->H, pi, pj, qi, qj)))
        {
          best = r;
        }
      }
    }
  }

  const float* Depth;
  int W;
  int H;
  bool Relaxed;
  double MaxRatio;
  std::vector<TileLevel> Levels;
};

// The rows [rowBegin, rowEnd) on mesolight::ParallelFor: every row's cones are computed alone,
// so the split does not matter.
void RunRows(const ConeMapOptions& options, int rowBegin, int rowEnd,
  const std::function<void(int, int)>& body)
{
  ParallelFor(static_cast<std::size_t>(rowBegin), static_cast<std::size_t>(rowEnd), 1,
    [&](std::size_t begin, std::size_t end) { body(static_cast<int>(begin), static_cast<int>(end)); },
    options.Threads);
}

// ---------------------------------------------------------------------------------------------
// Cones that are provably valid on the bilinear surface (ConeMapOptions::BilinearSafe).
//
// Grid coordinates: texel centres on the integers. Cell (ci, cj), ci in [0, w], cj in [0, h],
// is the square [ci - 1, ci] x [cj - 1, cj] with corner texels (ci - 1 | ci, cj - 1 | cj),
// clamped into the image (the same cells as ComputeMinDepthPyramid). The GL_LINEAR surface is
// bilinear on each cell; the clamp bands outside the outermost centres are covered by the
// border cells (treated as whole squares, which only enlarges the sets the bounds cover).
//
// Per apex cell X we compute R_X <= the exact cone ratio R*(x) at EVERY apex position x in X,
// and store at texel t the minimum of R_X over the 4 cells t is a corner of. A ratio read with
// bilinear filtering at x in cell X is a convex combination of its 4 corner texels' values,
// each <= R_X <= R*(x): the interpolated cone is valid (Ban et al. 2024, sec. on bilinear
// interpolation; here with the bound below instead of a per-texel cone).
//
// R_X is the minimum over cells Y of a lower bound of |y - x| / (D(x) - D(y)) over x in X and
// y in Y with D(y) < D(x) (conservative: any such y; relaxed: y a falling point, see
// ConeMaps.h, along y - x, which Y can only contain if CellMayFall()):
//  - Y at Chebyshev distance >= 2: with n the unit vector between the cell centres,
//    |y - x| >= (y - x).n >= 0, and (y - x).n - r (D(x) - D(y)) is multi-affine in
//    (x_u, x_v, y_u, y_v), so its minimum over the box X x Y is at one of the 16 corner pairs:
//    r = min over corner pairs (k, l) with D_k > D_l of ((y_l - x_k).n) / (D_k - D_l) bounds
//    every pair of the cells;
//    (any unit n with (y - x).n >= 0 on all 16 pairs works; the axis is also tried when the
//    cells are 2 or more apart along it);
//  - Y equal or adjacent to X: D(x) - D(y) <= G |x - y| with G the largest gradient norm of the
//    3 x 3 cells around X (the segment stays in them), so r = 1 / G; for relaxed cones also
//    r = 1 / V with V the diameter of the box of gradients there (see the constructor).
// A falling point y is counted in the cell its one-sided derivative is taken from (the cell
// the ray enters leaving y), so every falling point is covered by exactly the cell whose
// gradient range CellMayFall() tests. Everything is in grid units; ratios are divided by w
// (horizontal unit: texture widths). The bounds are evaluated in double from the float depths
// and truncated to float, so rounding can only narrow them (up to double round-off, 1e-16).

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
bool CellMayFall(const CellCorners& c, const double (*g)[2], int n)
{
  bool zero = false;
  for (int k = 0; k < n; ++k)
  {
    const int s = c.MaxSlopeSign(g[k][0], g[k][1]);
    if (s > 0)
    {
      return true;
    }
    zero = zero || s == 0;
  }
  return zero && c.Twist() != 0.0;
}

// Octant s of directions: angles [45 s, 45 (s + 1)] degrees, spanned by kOctant[s], [s + 1].
constexpr double kOctant[9][2] = { { 1, 0 }, { 1, 1 }, { 0, 1 }, { -1, 1 }, { -1, 0 },
  { -1, -1 }, { 0, -1 }, { 1, -1 }, { 1, 0 } };

// Monotone pseudo-angle of a non-zero vector in [0, 8): octant s covers [s, s + 1] (the octant
// boundaries, multiples of 45 degrees, map to integers).
inline double OctantAngle(double x, double y)
{
  // Diamond angle in [0, 4) (90 degrees per unit, 45 degrees at each half), times 2.
  double a;
  if (y >= 0.0)
  {
    a = x >= 0.0 ? y / (x + y) : 1.0 - x / (-x + y);
  }
  else
  {
    a = x < 0.0 ? 2.0 - y / (-x - y) : 3.0 + x / (x - y);
  }
  return 2.0 * a;
}

// Bit s set when octant s may meet the box of vectors [ax, bx] x [ay, by]. A box that does not
// contain the origin spans less than 180 degrees, between two of its corners: the octants from
// the first corner's to the last corner's. A box touching the origin meets every octant.
unsigned OctantsMeetingBox(double ax, double bx, double ay, double by)
{
  if (ax <= 0.0 && bx >= 0.0 && ay <= 0.0 && by >= 0.0)
  {
    return 0xFFu;
  }
  double angle[4] = { OctantAngle(ax, ay), OctantAngle(bx, ay), OctantAngle(ax, by),
    OctantAngle(bx, by) };
  double lo = *std::min_element(angle, angle + 4);
  double hi = *std::max_element(angle, angle + 4);
  if (hi - lo > 4.0) // the span wraps through angle 0
  {
    for (double& a : angle)
    {
      a = a < 4.0 ? a + 8.0 : a;
    }
    lo = *std::min_element(angle, angle + 4);
    hi = *std::max_element(angle, angle + 4);
  }
  unsigned mask = 0;
  // A corner exactly on a boundary counts on both sides (floor and ceil - 1).
  for (int s = static_cast<int>(std::ceil(lo)) - 1; s <= static_cast<int>(std::floor(hi)); ++s)
  {
    mask |= 1u << (((s % 8) + 8) % 8);
  }
  return mask;
}

// Octants along which the cell may contain a falling point.
unsigned FallingOctants(const CellCorners& c)
{
  unsigned mask = 0;
  for (int s = 0; s < 8; ++s)
  {
    mask |= CellMayFall(c, &kOctant[s], 2) ? (1u << s) : 0u;
  }
  return mask;
}

constexpr int kCellTile = 4; // cells per side of a leaf node
constexpr int kNearRing = 3; // cells (Chebyshev distance) searched directly around the apex
constexpr int kAllCells = 8; // node value index: minimum over all cells (conservative cones)

// Cell-pair bound and its branch-and-bound search. The oracle calls PairBound for every pair.
class CellConeSearch
{
public:
  CellConeSearch(const float* depth, int w, int h, bool relaxed, double maxRatio, double tolerance)
    : Depth(depth)
    , W(w)
    , H(h)
    , CW(w + 1)
    , CH(h + 1)
    , Relaxed(relaxed)
    , MaxRatio(maxRatio)
    , Tolerance(tolerance)
  {
    // Over the 3 x 3 cells around each cell: the largest gradient norm G (Lipschitz constant)
    // and, for relaxed cones, the diameter V of the box of gradients. A falling point y has
    // t . grad D(y) >= 0 along t = (y - x) / |y - x|, so along the segment
    // D(x) - D(y) = -|y - x| avg(t . grad D) <= |y - x| max |grad D(y) - grad D(z)| <= V |y - x|:
    // on smooth surfaces V is much smaller than G (a plane has V = 0: no bound at all).
    const std::size_t cells = static_cast<std::size_t>(this->CW) * this->CH;
    std::vector<float> g(cells);
    std::vector<std::array<float, 4>> box(cells); // gx min, gx max, gy min, gy max
    for (int cj = 0; cj < this->CH; ++cj)
    {
      for (int ci = 0; ci < this->CW; ++ci)
      {
        const CellCorners c(depth, w, h, ci, cj);
        const std::size_t k = static_cast<std::size_t>(cj) * this->CW + ci;
        g[k] = static_cast<float>(c.GradientNorm());
        const double gx0 = c.D[1] - c.D[0], gx1 = c.D[3] - c.D[2];
        const double gy0 = c.D[2] - c.D[0], gy1 = c.D[3] - c.D[1];
        box[k] = { static_cast<float>(std::min(gx0, gx1)), static_cast<float>(std::max(gx0, gx1)),
          static_cast<float>(std::min(gy0, gy1)), static_cast<float>(std::max(gy0, gy1)) };
      }
    }
    this->Lipschitz.assign(cells, 0.0f);
    this->Variation.assign(cells, 0.0f);
    for (int cj = 0; cj < this->CH; ++cj)
    {
      for (int ci = 0; ci < this->CW; ++ci)
      {
        float m = 0.0f;
        std::array<double, 4> b{ 1e30, -1e30, 1e30, -1e30 };
        for (int bj = std::max(0, cj - 1); bj <= std::min(this->CH - 1, cj + 1); ++bj)
        {
          for (int bi = std::max(0, ci - 1); bi <= std::min(this->CW - 1, ci + 1); ++bi)
          {
            const std::size_t k = static_cast<std::size_t>(bj) * this->CW + bi;
            m = std::max(m, g[k]);
            b[0] = std::min<double>(b[0], box[k][0]);
            b[1] = std::max<double>(b[1], box[k][1]);
            b[2] = std::min<double>(b[2], box[k][2]);
            b[3] = std::max<double>(b[3], box[k][3]);
          }
        }
        const std::size_t k = static_cast<std::size_t>(cj) * this->CW + ci;
        // One float step up: values rounded to float, 1 / G and 1 / V must stay lower bounds.
        // (The per-cell box ends were rounded to float too: widen V by a relative 1e-6.)
        this->Lipschitz[k] =
          m > 0.0f ? std::nextafter(m, std::numeric_limits<float>::infinity()) : 0.0f;
        const double v = std::hypot(b[1] - b[0], b[3] - b[2]) * (1.0 + 1e-6) +
          1e-7 * (std::abs(b[0]) + std::abs(b[1]) + std::abs(b[2]) + std::abs(b[3]));
        this->Variation[k] = static_cast<float>(v) < v
          ? std::nextafter(static_cast<float>(v), std::numeric_limits<float>::infinity())
          : static_cast<float>(v);
      }
    }
  }

  // Node pyramid over cells: level 0 = kCellTile^2 cells per node; values per node: minimum
  // corner depth over the cells that may fall in octant s (s < 8), and over all cells (8).
  void BuildPyramid()
  {
    Level base{ (this->CW + kCellTile - 1) / kCellTile, (this->CH + kCellTile - 1) / kCellTile,
      kCellTile, {} };
    base.Min.assign(static_cast<std::size_t>(base.W) * base.H * 9, kNone);
    this->CellMin.assign(static_cast<std::size_t>(this->CW) * this->CH, kNone);
    for (int cj = 0; cj < this->CH; ++cj)
    {
      for (int ci = 0; ci < this->CW; ++ci)
      {
        const CellCorners c(this->Depth, this->W, this->H, ci, cj);
        const float lo = static_cast<float>(c.Min());
        this->CellMin[static_cast<std::size_t>(cj) * this->CW + ci] = lo;
        float* m =
          &base.Min[(static_cast<std::size_t>(cj / kCellTile) * base.W + ci / kCellTile) * 9];
        m[kAllCells] = std::min(m[kAllCells], lo);
        if (this->Relaxed)
        {
          const unsigned octants = FallingOctants(c);
          for (int s = 0; s < 8; ++s)
          {
            if (octants & (1u << s))
            {
              m[s] = std::min(m[s], lo);
            }
          }
        }
      }
    }
    this->Levels.push_back(std::move(base));
    AddMinPyramidLevels(this->Levels, 9, PyramidHalving::RoundUp);
  }

  // Lower bound (texture widths per unit depth) of the cone ratio at every apex of cell X over
  // the surface of cell Y; +inf when Y cannot constrain X.
  // Pairs that cannot go below `cutoff` may return +inf early (the minimum is unchanged).
  double PairBound(int xi, int xj, const CellCorners& cx, int yi, int yj, double cutoff) const
  {
    const CellCorners cy(this->Depth, this->W, this->H, yi, yj);
    const double dX = cx.Max();
    const double minY = cy.Min();
    if (!(minY < dX))
    {
      return std::numeric_limits<double>::infinity();
    }
    const int dx = yi - xi;
    const int dy = yj - xj;
    const bool near = std::abs(dx) <= 1 && std::abs(dy) <= 1;
    const double len = std::sqrt(static_cast<double>(dx) * dx + static_cast<double>(dy) * dy);
    // Every corner pair has (y_l - x_k).n >= len - sqrt(2) and D_k - D_l <= dX - minY.
    if (!near && (len - std::sqrt(2.0)) / this->W / (dX - minY) * (1.0 - 1e-9) >= cutoff)
    {
      return std::numeric_limits<double>::infinity();
    }
    if (this->Relaxed)
    {
      // Directions from X to Y: the box (dx, dy) + [-1, 1]^2, spanned by its corners (or, when
      // it contains 0, every direction, spanned by the axes).
      static const double axes[4][2] = { { 1, 0 }, { 0, 1 }, { -1, 0 }, { 0, -1 } };
      const double corners[4][2] = { { dx - 1.0, dy - 1.0 }, { dx + 1.0, dy - 1.0 },
        { dx - 1.0, dy + 1.0 }, { dx + 1.0, dy + 1.0 } };
      if (!CellMayFall(cy, near ? axes : corners, 4))
      {
        return std::numeric_limits<double>::infinity();
      }
    }
    if (near)
    {
      const std::size_t k = static_cast<std::size_t>(xj) * this->CW + xi;
      double g = this->Lipschitz[k];
      if (this->Relaxed)
      {
        g = std::min<double>(g, this->Variation[k]);
      }
      return g > 0.0 ? 1.0 / (g * this->W) : std::numeric_limits<double>::infinity();
    }
    // Any unit n with (y - x).n >= 0 on all corner pairs gives a valid bound; take the best of
    // the direction between the centres and, when the cells are 2 or more apart along an axis,
    // that axis (tighter for cells nearly in line with an axis).
    double bound = ProjectedBound(cx, cy, dx / len, dy / len, dx, dy);
    if (std::abs(dx) >= 2)
    {
      bound = std::max(bound, ProjectedBound(cx, cy, dx > 0 ? 1.0 : -1.0, 0.0, dx, dy));
    }
    if (std::abs(dy) >= 2)
    {
      bound = std::max(bound, ProjectedBound(cx, cy, 0.0, dy > 0 ? 1.0 : -1.0, dx, dy));
    }
    return bound / this->W;
  }

  // min over corner pairs (k, l) with D_k > D_l of ((y_l - x_k).n) / (D_k - D_l), grid units.
  static double ProjectedBound(
    const CellCorners& cx, const CellCorners& cy, double nx, double ny, int dx, int dy)
  {
    static const double ox[4] = { -0.5, 0.5, -0.5, 0.5 };
    static const double oy[4] = { -0.5, -0.5, 0.5, 0.5 };
    const double base = dx * nx + dy * ny;
    double best = std::numeric_limits<double>::infinity();
    for (int k = 0; k < 4; ++k)
    {
      for (int l = 0; l < 4; ++l)
      {
        const double m = cx.D[k] - cy.D[l];
        if (m > 0.0)
        {
          const double n = base + (ox[l] - ox[k]) * nx + (oy[l] - oy[k]) * ny;
          best = std::min(best, n / m);
        }
      }
    }
    return best;
  }

  // R_X by branch and bound, nearest nodes first. With Tolerance > 0 a node is also skipped
  // when its bound is within that factor of the best so far; the skipped bounds are kept, so the
  // result is still a lower bound, at most (1 + Tolerance) below the exact minimum.
  double Run(int xi, int xj) const
  {
    const CellCorners cx(this->Depth, this->W, this->H, xi, xj);
    State st{ xi, xj, &cx, cx.Max(), this->MaxRatio, std::numeric_limits<double>::infinity() };
    // The cells within kNearRing first, directly (a ring search, as Ban et al. 2024 do); on
    // rough and flat maps the cone is often settled there: every cell further out is at least
    // kNearRing + 1 away, so none can go below (kNearRing + 1 - sqrt 2) / (w (dX - lowest)).
    // Ring by ring (Chebyshev distance 0 .. kNearRing), so that the nearest, usually binding,
    // cells lower Best first and the quick rejection of PairBound drops most of the others.
    for (int ring = 0; ring <= kNearRing; ++ring)
    {
      for (int yj = std::max(0, xj - ring); yj <= std::min(this->CH - 1, xj + ring); ++yj)
      {
        const bool edgeRow = std::abs(yj - xj) == ring;
        for (int yi = std::max(0, xi - ring); yi <= std::min(this->CW - 1, xi + ring); ++yi)
        {
          if (!edgeRow && std::abs(yi - xi) != ring)
          {
            continue; // inside the ring: done before
          }
          if (this->CellMin[static_cast<std::size_t>(yj) * this->CW + yi] < st.DX)
          {
            st.Best = std::min(st.Best, this->PairBound(xi, xj, cx, yi, yj, st.Best));
          }
        }
      }
    }
    const int top = static_cast<int>(this->Levels.size()) - 1;
    const float* rootMin = this->Levels[top].Min.data();
    const double lowest = this->Relaxed ? *std::min_element(rootMin, rootMin + 8) : rootMin[kAllCells];
    if (lowest < st.DX &&
      (kNearRing + 1 - std::sqrt(2.0)) / this->W / (st.DX - lowest) < st.Best * (1.0 + 1e-9))
    {
      this->Visit(top, 0, 0, st);
    }
    return std::min(st.Best, st.Skipped * (1.0 - 1e-9));
  }

  int CellsW() const { return this->CW; }
  int CellsH() const { return this->CH; }

private:
  using Level = MinPyramidLevel; // 9 channels: per octant (0-7) and all cells (kAllCells)
  struct State
  {
    int Xi;
    int Xj;
    const CellCorners* Cx;
    double DX;
    double Best;
    double Skipped;
  };

  // gap receives the lower bound of (y - x).n used (grid units).
  double NodeBound(int level, int ti, int tj, const State& st, double& gap) const
  {
    gap = 0.0;
    const Level& L = this->Levels[level];
    const float* m = &L.Min[(static_cast<std::size_t>(tj) * L.W + ti) * 9];
    const int x0 = ti * L.Size;
    const int y0 = tj * L.Size;
    const int x1 = std::min(this->CW, x0 + L.Size) - 1;
    const int y1 = std::min(this->CH, y0 + L.Size) - 1;
    double lo = m[kAllCells];
    if (this->Relaxed)
    {
      const unsigned octants =
        OctantsMeetingBox(x0 - st.Xi - 1.0, x1 - st.Xi + 1.0, y0 - st.Xj - 1.0, y1 - st.Xj + 1.0);
      lo = kNone;
      for (int s = 0; s < 8; ++s)
      {
        if (octants & (1u << s))
        {
          lo = std::min<double>(lo, m[s]);
        }
      }
    }
    if (!(lo < st.DX))
    {
      return std::numeric_limits<double>::infinity();
    }
    const double gx = AxisGap(st.Xi, x0, x1);
    const double gy = AxisGap(st.Xj, y0, y1);
    // Cells within kNearRing of X were searched before: the rest are at least kNearRing + 1 away.
    gap = std::max(std::sqrt(gx * gx + gy * gy), kNearRing + 1.0) - std::sqrt(2.0);
    return gap / this->W / (st.DX - lo);
  }

  // True when the node need not be searched (recording a tolerance skip).
  bool Prune(double bound, State& st) const
  {
    if (bound >= st.Best * (1.0 + 1e-9))
    {
      return true;
    }
    if (this->Tolerance > 0.0 && bound * (1.0 + this->Tolerance) >= st.Best)
    {
      st.Skipped = std::min(st.Skipped, bound);
      return true;
    }
    return false;
  }

  void Visit(int level, int ti, int tj, State& st) const
  {
    if (level == 0)
    {
      const int x0 = ti * kCellTile;
      const int y0 = tj * kCellTile;
      const int x1 = std::min(this->CW, x0 + kCellTile);
      const int y1 = std::min(this->CH, y0 + kCellTile);
      // Quick rejection without divisions: a cell at centre distance len cannot go below
      // (len - sqrt 2) / (w (dX - min)) (see PairBound); skip it when that is >= Best (with a
      // relative margin far above the rounding of this test).
      const double reach = st.Best * this->W * (1.0 + 1e-6);
      for (int yj = y0; yj < y1; ++yj)
      {
        const float* cellMin = &this->CellMin[static_cast<std::size_t>(yj) * this->CW];
        const double dy = yj - st.Xj;
        for (int yi = x0; yi < x1; ++yi)
        {
          const double depthGap = st.DX - cellMin[yi];
          if (!(depthGap > 0.0) ||
            (std::abs(yi - st.Xi) <= kNearRing && std::abs(yj - st.Xj) <= kNearRing))
          {
            continue;
          }
          const double dx = yi - st.Xi;
          const double r = reach * depthGap + std::sqrt(2.0);
          if (dx * dx + dy * dy >= r * r && (std::abs(dx) > 1.0 || std::abs(dy) > 1.0))
          {
            continue;
          }
          st.Best = std::min(st.Best, this->PairBound(st.Xi, st.Xj, *st.Cx, yi, yj, st.Best));
        }
      }
      return;
    }
    const Level& C = this->Levels[level - 1];
    NodeChild children[4];
    const int n = ChildrenNearestFirst(C.W, C.H, ti, tj,
      [&](int ci, int cj, double& gap) { return this->NodeBound(level - 1, ci, cj, st, gap); },
      children);
    // A node small against its distance is not opened: its bound (its shallowest candidate
    // depth at its nearest distance) is taken as is, as the quick cone map generation of Valasek
    // & Ban (2022) takes a coarse max-mipmap texel. Still a lower bound; narrower than the cell
    // search by at most the distance error, a factor 1 + Tolerance on the node's own cells.
    const double acceptSize = C.Size * std::sqrt(2.0);
    for (int k = 0; k < n; ++k)
    {
      if (!std::isfinite(children[k].B) || this->Prune(children[k].B, st))
      {
        continue;
      }
      if (this->Tolerance > 0.0 && acceptSize <= this->Tolerance * children[k].Gap)
      {
        st.Best = std::min(st.Best, children[k].B);
        continue;
      }
      this->Visit(level - 1, children[k].I, children[k].J, st);
    }
  }

  const float* Depth;
  int W;
  int H;
  int CW;
  int CH;
  bool Relaxed;
  double MaxRatio;
  double Tolerance;
  std::vector<float> Lipschitz;
  std::vector<float> Variation;
  std::vector<float> CellMin; // minimum corner depth per cell (float, as in the pyramid)
  std::vector<Level> Levels;
};

// Largest float not above x (the stored cone is never wider than the computed bound).
float TruncateToFloat(double x)
{
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x)
  {
    f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  }
  return f;
}

// Per texel: the minimum of R_X over the (up to) 4 cells the texel is a corner of.
std::vector<float> TexelsFromCells(const std::vector<double>& cells, int w, int h)
{
  std::vector<float> out(static_cast<std::size_t>(w) * h);
  const int cw = w + 1;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const std::size_t c = static_cast<std::size_t>(j) * cw + i;
      out[static_cast<std::size_t>(j) * w + i] = TruncateToFloat(
        std::min({ cells[c], cells[c + 1], cells[c + cw], cells[c + cw + 1] }));
    }
  }
  return out;
}

std::vector<float> ComputeCellBound(
  const float* depth, int w, int h, const ConeMapOptions& options, bool relaxed, bool bruteForce)
{
  CellConeSearch search(depth, w, h, relaxed, static_cast<double>(options.MaxRatio),
    bruteForce ? 0.0 : std::max(0.0, static_cast<double>(options.Tolerance)));
  const int cw = w + 1;
  const int ch = h + 1;
  std::vector<double> cells(static_cast<std::size_t>(cw) * ch);
  if (bruteForce)
  {
    for (int xj = 0; xj < ch; ++xj)
    {
      for (int xi = 0; xi < cw; ++xi)
      {
        const CellCorners cx(depth, w, h, xi, xj);
        double best = options.MaxRatio;
        for (int yj = 0; yj < ch; ++yj)
        {
          for (int yi = 0; yi < cw; ++yi)
          {
            best = std::min(best, search.PairBound(xi, xj, cx, yi, yj, best));
          }
        }
        cells[static_cast<std::size_t>(xj) * cw + xi] = best;
      }
    }
    return TexelsFromCells(cells, w, h);
  }
  search.BuildPyramid();
  if (options.Progress && !options.Progress(0.02))
  {
    return {};
  }
  const int chunks = std::max(1, std::min(ch, 64));
  for (int c = 0; c < chunks; ++c)
  {
    const int rowBegin = static_cast<int>(static_cast<long long>(ch) * c / chunks);
    const int rowEnd = static_cast<int>(static_cast<long long>(ch) * (c + 1) / chunks);
    RunRows(options, rowBegin, rowEnd, [&](int begin, int end) {
      for (int xj = begin; xj < end; ++xj)
      {
        for (int xi = 0; xi < cw; ++xi)
        {
          cells[static_cast<std::size_t>(xj) * cw + xi] = search.Run(xi, xj);
        }
      }
    });
    if (options.Progress && !options.Progress(0.02 + 0.97 * (c + 1) / chunks))
    {
      return {};
    }
  }
  return TexelsFromCells(cells, w, h);
}

std::vector<float> ComputeFast(
  const float* depth, int w, int h, const ConeMapOptions& options, bool relaxed)
{
  if (!depth || w < 1 || h < 1)
  {
    return {};
  }
  if (options.Progress && !options.Progress(0.0))
  {
    return {};
  }
  if (options.BilinearSafe)
  {
    std::vector<float> ratio = ComputeCellBound(depth, w, h, options, relaxed, false);
    if (ratio.empty() || (options.Progress && !options.Progress(1.0)))
    {
      return {};
    }
    return ratio;
  }
  const ConeSearch search(depth, w, h, relaxed, static_cast<double>(options.MaxRatio));
  std::vector<float> ratio(static_cast<std::size_t>(w) * h);
  float* out = ratio.data();
  const int chunks = std::max(1, std::min(h, 64));
  for (int c = 0; c < chunks; ++c)
  {
    const int rowBegin = static_cast<int>(static_cast<long long>(h) * c / chunks);
    const int rowEnd = static_cast<int>(static_cast<long long>(h) * (c + 1) / chunks);
    RunRows(options, rowBegin, rowEnd, [&](int begin, int end) {
      for (int j = begin; j < end; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          out[static_cast<std::size_t>(j) * w + i] = search.Run(i, j);
        }
      }
    });
    if (options.Progress && !options.Progress(0.99 * (c + 1) / chunks))
    {
      return {};
    }
  }
  if (options.Progress && !options.Progress(1.0))
  {
    return {};
  }
  return ratio;
}

std::vector<float> ComputeBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options, bool relaxed)
{
  if (!depth || w < 1 || h < 1)
  {
    return {};
  }
  if (options.BilinearSafe)
  {
    return ComputeCellBound(depth, w, h, options, relaxed, true);
  }
  std::vector<float> ratio(static_cast<std::size_t>(w) * h);
  for (int pj = 0; pj < h; ++pj)
  {
    for (int pi = 0; pi < w; ++pi)
    {
      const double dp = depth[static_cast<std::size_t>(pj) * w + pi];
      double best = options.MaxRatio;
      for (int qj = 0; qj < h; ++qj)
      {
        for (int qi = 0; qi < w; ++qi)
        {
          const double dq = depth[static_cast<std::size_t>(qj) * w + qi];
          if (!(dq < dp) || (relaxed && !IsFallingEdgeNear(depth, w, h, pi, pj, qi, qj)))
          {
            continue;
          }
          const long long di = qi - pi;
          const long long dj = qj - pj;
          best = std::min(best, Ratio(di * di + dj * dj, w, dp, dq));
        }
      }
      ratio[static_cast<std::size_t>(pj) * w + pi] = static_cast<float>(best);
    }
  }
  return ratio;
}


} // namespace

namespace
{
// Falling-edge test of texel q along the direction (a, b) (texel units, not both 0): the
// bilinear patch q lies on when leaving it along (a, b) is the quadrant's cell, and along
// q + t (a, b) its depth is d00 + t (|a| dx + |b| dy) + t^2 |a| |b| dxy. A zero component
// still picks a quadrant by its sign bit (+0 / -0), so directions just off an axis can be
// tested on both sides.
bool FallingAlong(const float* depth, int w, int h, int qi, int qj, double a, double b)
{
  const int sx = std::signbit(a) ? -1 : 1;
  const int sy = std::signbit(b) ? -1 : 1;
  const double d00 = At(depth, w, h, qi, qj);
  const double d10 = At(depth, w, h, qi + sx, qj);
  const double d01 = At(depth, w, h, qi, qj + sy);
  const double d11 = At(depth, w, h, qi + sx, qj + sy);
  const double aa = std::abs(a);
  const double ab = std::abs(b);
  const double slope = aa * (d10 - d00) + ab * (d01 - d00);
  if (slope != 0.0)
  {
    return slope > 0.0;
  }
  return aa * ab * (d11 - d10 - d01 + d00) > 0.0;
}

// The first-order term alone for a direction infinitesimally off an axis: (0+, b) falls if
// dy > 0, or dy == 0 and dx > 0 on that side.
bool FallingJustOffAxis(const float* depth, int w, int h, int qi, int qj, bool alongX,
  int sign)
{
  const double d00 = At(depth, w, h, qi, qj);
  for (int side : { -1, 1 })
  {
    const double along = alongX ? At(depth, w, h, qi + sign, qj) : At(depth, w, h, qi, qj + sign);
    const double across = alongX ? At(depth, w, h, qi, qj + side) : At(depth, w, h, qi + side, qj);
    if (along - d00 > 0.0 || (along - d00 == 0.0 && across - d00 > 0.0))
    {
      return true;
    }
  }
  return false;
}
} // namespace

bool IsFallingEdge(const float* depth, int w, int h, int pi, int pj, int qi, int qj)
{
  return FallingAlong(depth, w, h, qi, qj, qi - pi, qj - pj);
}

bool IsFallingEdgeNear(const float* depth, int w, int h, int pi, int pj, int qi, int qj)
{
  // Directions from every apex position in the square [pi - 1, pi + 1] x [pj - 1, pj + 1]
  // (the cells whose bilinear lookups read texel p's ratio) toward q form a convex set; the
  // falling condition is linear in the direction within a quadrant, so it holds for some
  // direction of the set iff it holds for an extreme one: a corner direction, or an axis
  // direction where the set crosses into another quadrant.
  for (int cy : { -1, 1 })
  {
    for (int cx : { -1, 1 })
    {
      const double a = qi - (pi + cx);
      const double b = qj - (pj + cy);
      if ((a != 0.0 || b != 0.0) && FallingAlong(depth, w, h, qi, qj, a, b))
      {
        return true;
      }
    }
  }
  const int di = qi - pi;
  const int dj = qj - pj;
  if (std::abs(di) <= 1 && dj != 0 && FallingJustOffAxis(depth, w, h, qi, qj, false, dj > 0 ? 1 : -1))
  {
    return true;
  }
  if (std::abs(dj) <= 1 && di != 0 && FallingJustOffAxis(depth, w, h, qi, qj, true, di > 0 ? 1 : -1))
  {
    return true;
  }
  return false;
}

std::vector<float> ComputeConservativeConeMap(
  const float* depth, int w, int h, const ConeMapOptions& options)
{
  return ComputeFast(depth, w, h, options, false);
}

std::vector<float> ComputeRelaxedConeMap(
  const float* depth, int w, int h, const ConeMapOptions& options)
{
  return ComputeFast(depth, w, h, options, true);
}

std::vector<float> ComputeConeMap(
  ConeType type, const float* depth, int w, int h, const ConeMapOptions& options)
{
  return type == ConeType::Relaxed ? ComputeRelaxedConeMap(depth, w, h, options)
                                   : ComputeConservativeConeMap(depth, w, h, options);
}

std::vector<float> ComputeConservativeConeMapBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options)
{
  return ComputeBruteForce(depth, w, h, options, false);
}

std::vector<float> ComputeRelaxedConeMapBruteForce(
  const float* depth, int w, int h, const ConeMapOptions& options)
{
  return ComputeBruteForce(depth, w, h, options, true);
}

std::uint8_t EncodeConeRatio8(float ratio)
{
  if (!(ratio > 0.0f))
  {
    return 0;
  }
  if (std::isinf(ratio))
  {
    return 255;
  }
  const double c = ratio;
  int code = static_cast<int>(std::floor(c / (1.0 + c) * 255.0));
  code = std::min(255, std::max(0, code));
  // Rounding in either direction: take the largest code whose decoded (float) ratio does not
  // exceed the input, so the decoded cone is never wider.
  while (code < 254 && DecodeConeRatio8(static_cast<std::uint8_t>(code + 1)) <= ratio)
  {
    ++code;
  }
  while (code > 0 && DecodeConeRatio8(static_cast<std::uint8_t>(code)) > ratio)
  {
    --code;
  }
  return static_cast<std::uint8_t>(code);
}

float DecodeConeRatio8(std::uint8_t code)
{
  if (code == 255)
  {
    return std::numeric_limits<float>::infinity();
  }
  const float x = static_cast<float>(code) / 255.0f;
  return x / (1.0f - x); // the same float arithmetic as the shader
}

} // namespace mesolight
