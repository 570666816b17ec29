// SPDX-License-Identifier: BSD-3-Clause
#include "ConeMaps.h"

#include "ConeMapBounds.h"
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
namespace
{
using namespace conemaps;

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
int ChildrenNearestFirst(
  int w, int h, int ti, int tj, BoundFunction bound, NodeChild (&children)[4])
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
    const int n = ChildrenNearestFirst(
      C.W, C.H, ti, tj,
      [&](int ci, int cj, double&) { return this->Bound(level - 1, ci, cj, pi, pj, dp); },
      children);
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

// row(r) for every row r of [0, rows) on mesolight::ParallelFor, in up to 64 chunks of rows;
// after each chunk, progress reports begin + span * (chunks done) / chunks. Each row is computed
// alone, so the split does not matter. False when the progress callback aborted.
bool ForEachRow(const ConeMapOptions& options, int rows, double begin, double span,
  const std::function<void(int)>& row)
{
  const int chunks = std::max(1, std::min(rows, 64));
  for (int c = 0; c < chunks; ++c)
  {
    const int rowBegin = static_cast<int>(static_cast<long long>(rows) * c / chunks);
    const int rowEnd = static_cast<int>(static_cast<long long>(rows) * (c + 1) / chunks);
    ParallelFor(
      static_cast<std::size_t>(rowBegin), static_cast<std::size_t>(rowEnd), 1,
      [&](std::size_t first, std::size_t last)
      {
        for (std::size_t r = first; r < last; ++r)
        {
          row(static_cast<int>(r));
        }
      },
      options.Threads);
    if (!ReportProgress(options.Progress, begin + span * (c + 1) / chunks))
    {
      return false;
    }
  }
  return true;
}

// ---------------------------------------------------------------------------------------------
// The branch-and-bound search of the bilinear-safe cones (ConeMapOptions::BilinearSafe); the
// cell-pair bound it minimises, and why it holds, are in ConeMapBounds.
//
// Octant s of directions: angles [45 s, 45 (s + 1)] degrees, spanned by kOctant[s], [s + 1].
constexpr double kOctant[9][2] = { { 1, 0 }, { 1, 1 }, { 0, 1 }, { -1, 1 }, { -1, 0 }, { -1, -1 },
  { 0, -1 }, { 1, -1 }, { 1, 0 } };

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
class CellConeSearch : public CellPairBounds
{
public:
  CellConeSearch(const float* depth, int w, int h, bool relaxed, double maxRatio, double tolerance)
    : CellPairBounds(depth, w, h, relaxed)
    , MaxRatio(maxRatio)
    , Tolerance(tolerance)
  {
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
    const double lowest =
      this->Relaxed ? *std::min_element(rootMin, rootMin + 8) : rootMin[kAllCells];
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
    const int n = ChildrenNearestFirst(
      C.W, C.H, ti, tj,
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

  double MaxRatio;
  double Tolerance;
  std::vector<float> CellMin; // minimum corner depth per cell (float, as in the pyramid)
  std::vector<Level> Levels;
};

// The bilinear-safe cones by the branch-and-bound search (ConeMapOracle.cxx has the
// exhaustive one).
std::vector<float> ComputeCellBound(
  const float* depth, int w, int h, const ConeMapOptions& options, bool relaxed)
{
  CellConeSearch search(depth, w, h, relaxed, static_cast<double>(options.MaxRatio),
    std::max(0.0, static_cast<double>(options.Tolerance)));
  const int cw = w + 1;
  const int ch = h + 1;
  std::vector<double> cells(static_cast<std::size_t>(cw) * ch);
  search.BuildPyramid();
  if (!ReportProgress(options.Progress, 0.02))
  {
    return {};
  }
  const bool done = ForEachRow(options, ch, 0.02, 0.97,
    [&](int xj)
    {
      for (int xi = 0; xi < cw; ++xi)
      {
        cells[static_cast<std::size_t>(xj) * cw + xi] = search.Run(xi, xj);
      }
    });
  if (!done)
  {
    return {};
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
  if (!ReportProgress(options.Progress, 0.0))
  {
    return {};
  }
  if (options.BilinearSafe)
  {
    std::vector<float> ratio = ComputeCellBound(depth, w, h, options, relaxed);
    if (ratio.empty() || !ReportProgress(options.Progress, 1.0))
    {
      return {};
    }
    return ratio;
  }
  const ConeSearch search(depth, w, h, relaxed, static_cast<double>(options.MaxRatio));
  std::vector<float> ratio(static_cast<std::size_t>(w) * h);
  float* out = ratio.data();
  const bool done = ForEachRow(options, h, 0.0, 0.99,
    [&](int j)
    {
      for (int i = 0; i < w; ++i)
      {
        out[static_cast<std::size_t>(j) * w + i] = search.Run(i, j);
      }
    });
  if (!done)
  {
    return {};
  }
  if (!ReportProgress(options.Progress, 1.0))
  {
    return {};
  }
  return ratio;
}

} // namespace

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
