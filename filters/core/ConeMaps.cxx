// SPDX-License-Identifier: BSD-3-Clause
#include "ConeMaps.h"

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstddef>
#include <limits>
#include <thread>
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

struct TileLevel
{
  int W;
  int H;
  int Size; // texels per side of a node at this level
  std::vector<float> Min;
};

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
  while (levels.back().W > 1 || levels.back().H > 1)
  {
    const TileLevel& c = levels.back();
    TileLevel p{ (c.W + 1) / 2, (c.H + 1) / 2, c.Size * 2, {} };
    p.Min.assign(static_cast<std::size_t>(p.W) * p.H, kNone);
    for (int j = 0; j < c.H; ++j)
    {
      for (int i = 0; i < c.W; ++i)
      {
        float& m = p.Min[static_cast<std::size_t>(j / 2) * p.W + i / 2];
        m = std::min(m, c.Min[static_cast<std::size_t>(j) * c.W + i]);
      }
    }
    levels.push_back(std::move(p));
  }
  return levels;
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
    struct Child
    {
      double B;
      int I;
      int J;
    } children[4];
    int n = 0;
    for (int cj = 2 * tj; cj <= 2 * tj + 1 && cj < C.H; ++cj)
    {
      for (int ci = 2 * ti; ci <= 2 * ti + 1 && ci < C.W; ++ci)
      {
        children[n++] = { this->Bound(level - 1, ci, cj, pi, pj, dp), ci, cj };
      }
    }
    for (int a = 1; a < n; ++a) // nearest first (insertion sort of <= 4)
    {
      for (int b = a; b > 0 && children[b].B < children[b - 1].B; --b)
      {
        std::swap(children[b], children[b - 1]);
      }
    }
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

// Ban et al. 2024: a ratio read with bilinear filtering must not exceed what the nearby texels
// allow, so each texel takes the minimum of its 3 x 3 neighbourhood (clamped at the borders).
std::vector<float> NeighbourhoodMin(const std::vector<float>& in, int w, int h, float scale)
{
  std::vector<float> rowMin(in.size());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      rowMin[static_cast<std::size_t>(j) * w + i] = std::min(
        { At(in.data(), w, h, i - 1, j), At(in.data(), w, h, i, j), At(in.data(), w, h, i + 1, j) });
    }
  }
  std::vector<float> out(in.size());
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      out[static_cast<std::size_t>(j) * w + i] = scale *
        std::min({ At(rowMin.data(), w, h, i, j - 1), At(rowMin.data(), w, h, i, j),
          At(rowMin.data(), w, h, i, j + 1) });
    }
  }
  return out;
}

float SafetyScale(const ConeMapOptions& options, bool relaxed)
{
  return relaxed ? options.RelaxedSafetyScale : options.ConservativeSafetyScale;
}

void RunRows(const ConeMapOptions& options, int rowBegin, int rowEnd,
  const std::function<void(int, int)>& body)
{
  if (options.ParallelFor)
  {
    options.ParallelFor(rowBegin, rowEnd, body);
    return;
  }
  int threads = options.Threads > 0 ? options.Threads
                                    : static_cast<int>(std::thread::hardware_concurrency());
  threads = std::max(1, std::min(threads, rowEnd - rowBegin));
  if (threads == 1)
  {
    body(rowBegin, rowEnd);
    return;
  }
  // Rows one at a time from a shared counter: cost varies a lot between rows.
  std::atomic<int> next(rowBegin);
  auto work = [&]() {
    for (int row = next++; row < rowEnd; row = next++)
    {
      body(row, row + 1);
    }
  };
  std::vector<std::thread> pool;
  for (int t = 1; t < threads; ++t)
  {
    pool.emplace_back(work);
  }
  work();
  for (auto& t : pool)
  {
    t.join();
  }
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
  if (options.BilinearSafe)
  {
    ratio = NeighbourhoodMin(ratio, w, h, SafetyScale(options, relaxed));
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
  return options.BilinearSafe
    ? NeighbourhoodMin(ratio, w, h, SafetyScale(options, relaxed))
    : ratio;
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

bool MinDepthPyramidLevelSize(int w, int h, int level, int& lw, int& lh)
{
  if (w < 1 || h < 1 || level < 0)
  {
    return false;
  }
  lw = w + 1;
  lh = h + 1;
  for (int k = 0; k < level; ++k)
  {
    if (lw == 1 && lh == 1)
    {
      return false;
    }
    lw = std::max(1, lw / 2);
    lh = std::max(1, lh / 2);
  }
  return true;
}

std::vector<std::vector<float>> ComputeMinDepthPyramid(const float* depth, int w, int h)
{
  std::vector<std::vector<float>> levels;
  if (!depth || w < 1 || h < 1)
  {
    return levels;
  }
  int lw = w + 1;
  int lh = h + 1;
  std::vector<float> level0(static_cast<std::size_t>(lw) * lh);
  for (int cj = 0; cj < lh; ++cj)
  {
    for (int ci = 0; ci < lw; ++ci)
    {
      level0[static_cast<std::size_t>(cj) * lw + ci] = std::min(
        { At(depth, w, h, ci - 1, cj - 1), At(depth, w, h, ci, cj - 1), At(depth, w, h, ci - 1, cj),
          At(depth, w, h, ci, cj) });
    }
  }
  levels.push_back(std::move(level0));
  while (lw > 1 || lh > 1)
  {
    const std::vector<float>& c = levels.back();
    const int pw = std::max(1, lw / 2);
    const int ph = std::max(1, lh / 2);
    std::vector<float> p(static_cast<std::size_t>(pw) * ph, kNone);
    for (int j = 0; j < lh; ++j)
    {
      for (int i = 0; i < lw; ++i)
      {
        const int pi = std::min(i / 2, pw - 1), pj = std::min(j / 2, ph - 1);
        float& m = p[static_cast<std::size_t>(pj) * pw + pi];
        m = std::min(m, c[static_cast<std::size_t>(j) * lw + i]);
      }
    }
    levels.push_back(std::move(p));
    lw = pw;
    lh = ph;
  }
  return levels;
}

} // namespace mesolight
