// SPDX-License-Identifier: BSD-3-Clause
#include "ConeMapBounds.h"

#include "ConeMaps.h"

#include <array>
#include <limits>

namespace mesolight
{
namespace conemaps
{

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

CellPairBounds::CellPairBounds(const float* depth, int w, int h, bool relaxed)
  : Depth(depth)
  , W(w)
  , H(h)
  , CW(w + 1)
  , CH(h + 1)
  , Relaxed(relaxed)
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

double CellPairBounds::PairBound(
  int xi, int xj, const CellCorners& cx, int yi, int yj, double cutoff) const
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

double CellPairBounds::ProjectedBound(
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

float TruncateToFloat(double x)
{
  float f = static_cast<float>(x);
  if (static_cast<double>(f) > x)
  {
    f = std::nextafter(f, -std::numeric_limits<float>::infinity());
  }
  return f;
}

std::vector<float> TexelsFromCells(const std::vector<double>& cells, int w, int h)
{
  std::vector<float> out(static_cast<std::size_t>(w) * h);
  const int cw = w + 1;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const std::size_t c = static_cast<std::size_t>(j) * cw + i;
      out[static_cast<std::size_t>(j) * w + i] =
        TruncateToFloat(std::min({ cells[c], cells[c + 1], cells[c + cw], cells[c + cw + 1] }));
    }
  }
  return out;
}

} // namespace conemaps

namespace
{
using namespace conemaps;

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
bool FallingJustOffAxis(const float* depth, int w, int h, int qi, int qj, bool alongX, int sign)
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
  if (std::abs(di) <= 1 && dj != 0 &&
    FallingJustOffAxis(depth, w, h, qi, qj, false, dj > 0 ? 1 : -1))
  {
    return true;
  }
  if (std::abs(dj) <= 1 && di != 0 &&
    FallingJustOffAxis(depth, w, h, qi, qj, true, di > 0 ? 1 : -1))
  {
    return true;
  }
  return false;
}

} // namespace mesolight
