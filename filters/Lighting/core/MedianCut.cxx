// SPDX-License-Identifier: BSD-3-Clause
#include "MedianCut.h"

#include "EnvironmentMaps.h"
#include "MathConstants.h"
#include "ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numeric>
#include <queue>
#include <sstream>
#include <thread> // hardware_concurrency() only: fixes the number of bands/blocks (no thread started)

namespace mesolight
{

namespace
{
/// Number of row bands of the summed-area tables for n rows. The sums depend on where the
/// bands start, so their number stays what it always was (the hardware threads, at most one
/// per 16 rows), whatever runs them.
int BandsFor(int n)
{
  return std::max(
    1, std::min<int>(n / 16 + 1, static_cast<int>(std::thread::hardware_concurrency())));
}

/// fn(begin, end) for the band [n t / T, n (t + 1) / T) of each t < T = BandsFor(n), on
/// mesolight::ParallelFor.
template <typename Fn>
void ForEachBand(int n, Fn fn)
{
  const int bands = BandsFor(n);
  ParallelFor(0, static_cast<std::size_t>(bands), 1,
    [&](std::size_t t0, std::size_t t1)
    {
      for (std::size_t t = t0; t < t1; ++t)
      {
        const int begin =
          static_cast<int>(static_cast<long long>(n) * static_cast<long long>(t) / bands);
        const int end =
          static_cast<int>(static_cast<long long>(n) * static_cast<long long>(t + 1) / bands);
        fn(begin, end);
      }
    });
}

/// Side in pixels of the cells whose moments the variance-minimizing cuts compare: the
/// largest k that leaves a grid of at least 1024 x 512 cells and 16 cells per light. Five
/// double tables at full resolution took 4.5x the plain cut's time on a 4096 x 2048 map;
/// on the grid they cost little, and the lights are still integrated over the map's pixels.
int VarianceCellSize(int w, int h, int lights)
{
  int k = 1;
  while (w / (k + 1) >= 1024 && h / (k + 1) >= 512 &&
    static_cast<long long>(w / (k + 1)) * (h / (k + 1)) >= 16LL * lights)
  {
    ++k;
  }
  return k;
}

/// A (W+1) x (H+1) summed-area table in double; rows counted from the top of the map.
class Sat
{
public:
  Sat() = default;
  /// Allocates without initialising (every entry is written by the build); row 0 and
  /// column 0 are zero.
  void Resize(int w, int h)
  {
    this->W1 = w + 1;
    this->Table.reset(new double[static_cast<size_t>(w + 1) * static_cast<size_t>(h + 1)]);
    std::fill(this->Table.get(), this->Table.get() + w + 1, 0.0);
    for (int y = 1; y <= h; ++y)
    {
      this->Row(y)[0] = 0.0;
    }
  }
  double* Row(int y) { return this->Table.get() + static_cast<size_t>(y) * this->W1; }
  /// Sum over columns [x0, x1), rows [y0, y1).
  double Sum(int x0, int x1, int y0, int y1) const
  {
    const double* a = this->Table.get() + static_cast<size_t>(y0) * this->W1;
    const double* b = this->Table.get() + static_cast<size_t>(y1) * this->W1;
    return b[x1] - b[x0] - a[x1] + a[x0];
  }
  /// The table of value(x, y) over a w x h grid, serially (the variance cuts' grids are small).
  template <typename Value>
  void Build(int w, int h, Value value)
  {
    this->Resize(w, h);
    for (int y = 0; y < h; ++y)
    {
      const double* above = this->Row(y);
      double* row = this->Row(y + 1);
      double run = 0.0;
      for (int x = 0; x < w; ++x)
      {
        run += value(x, y);
        row[x + 1] = run + above[x + 1];
      }
    }
  }
  /**
   * Rows [yBegin, yEnd] hold per-row prefix sums plus the SAT row yBegin - 1 when built as
   * one band: add `offset` (the SAT row just above the band) to the band's rows.
   */
  void AddOffsetRow(int yBegin, int yEnd, const double* offset)
  {
    for (int y = yBegin; y <= yEnd; ++y)
    {
      double* cur = this->Row(y);
      for (int x = 1; x < this->W1; ++x)
      {
        cur[x] += offset[x];
      }
    }
  }

private:
  int W1 = 1;
  std::unique_ptr<double[]> Table;
};

struct Region
{
  int X0, X1, Y0, Y1; // columns [X0, X1), rows [Y0, Y1) from the top
  double Energy;
  double Priority;
};

struct RegionLess
{
  bool operator()(const Region& a, const Region& b) const
  {
    if (a.Priority != b.Priority)
    {
      return a.Priority < b.Priority;
    }
    const long long areaA = static_cast<long long>(a.X1 - a.X0) * (a.Y1 - a.Y0);
    const long long areaB = static_cast<long long>(b.X1 - b.X0) * (b.Y1 - b.Y0);
    return areaA < areaB;
  }
};

class Cutter
{
public:
  int W = 0;
  int H = 0;
  bool Variance = false;
  Sat E;                // e
  Sat Ex, Exx, Ey, Eyy; // e x, e x^2, e y, e y^2 (cell-centre coordinates), variance mode
  double DPhi = 0.0;    // 2 pi / W: a column's angle (a cell's in variance mode)
  double DTheta = 0.0;  // pi / H

  double SinThetaCentre(int y0, int y1) const { return std::sin(0.5 * (y0 + y1) * this->DTheta); }

  /// Energy-weighted angular variance sum e |p - mean|^2 of a region.
  double Inertia(int x0, int x1, int y0, int y1) const
  {
    const double e = this->E.Sum(x0, x1, y0, y1);
    if (!(e > 0.0))
    {
      return 0.0;
    }
    const double ex = this->Ex.Sum(x0, x1, y0, y1);
    const double exx = this->Exx.Sum(x0, x1, y0, y1);
    const double ey = this->Ey.Sum(x0, x1, y0, y1);
    const double eyy = this->Eyy.Sum(x0, x1, y0, y1);
    const double sx = this->DPhi * this->SinThetaCentre(y0, y1);
    const double vx = std::max(0.0, exx - ex * ex / e);
    const double vy = std::max(0.0, eyy - ey * ey / e);
    return sx * sx * vx + this->DTheta * this->DTheta * vy;
  }

  double PriorityOf(const Region& r) const
  {
    if ((r.X1 - r.X0) * static_cast<long long>(r.Y1 - r.Y0) < 2)
    {
      return -1.0; // cannot be cut
    }
    return this->Variance ? this->Inertia(r.X0, r.X1, r.Y0, r.Y1) : r.Energy;
  }

  Region Make(int x0, int x1, int y0, int y1) const
  {
    Region r{ x0, x1, y0, y1, this->E.Sum(x0, x1, y0, y1), 0.0 };
    r.Priority = this->PriorityOf(r);
    return r;
  }

  /// Cut r into a and b.
  void Cut(const Region& r, Region& a, Region& b) const
  {
    const int w = r.X1 - r.X0;
    const int h = r.Y1 - r.Y0;
    bool alongX = false; // true: cut at a column (split the width)
    int at = 0;
    if (this->Variance)
    {
      double best = -1.0;
      for (int c = r.X0 + 1; c < r.X1; ++c)
      {
        const double cost = this->Inertia(r.X0, c, r.Y0, r.Y1) + this->Inertia(c, r.X1, r.Y0, r.Y1);
        if (best < 0.0 || cost < best)
        {
          best = cost;
          alongX = true;
          at = c;
        }
      }
      for (int c = r.Y0 + 1; c < r.Y1; ++c)
      {
        const double cost = this->Inertia(r.X0, r.X1, r.Y0, c) + this->Inertia(r.X0, r.X1, c, r.Y1);
        if (best < 0.0 || cost < best)
        {
          best = cost;
          alongX = false;
          at = c;
        }
      }
      // A region without energy has zero cost everywhere: cut its longer side in the middle.
      if (!(r.Energy > 0.0))
      {
        this->LongerSide(r, alongX);
        at = alongX ? r.X0 + w / 2 : r.Y0 + h / 2;
      }
    }
    else
    {
      this->LongerSide(r, alongX);
      const int lo = alongX ? r.X0 + 1 : r.Y0 + 1;
      const int hi = alongX ? r.X1 - 1 : r.Y1 - 1;
      auto below = [&](int c)
      { return alongX ? this->E.Sum(r.X0, c, r.Y0, r.Y1) : this->E.Sum(r.X0, r.X1, r.Y0, c); };
      if (!(r.Energy > 0.0))
      {
        at = alongX ? r.X0 + w / 2 : r.Y0 + h / 2;
      }
      else
      {
        const double half = 0.5 * r.Energy;
        // Smallest c in [lo, hi] with below(c) >= half (hi if none).
        int first = lo;
        int last = hi;
        while (first < last)
        {
          const int mid = first + (last - first) / 2;
          if (below(mid) >= half)
          {
            last = mid;
          }
          else
          {
            first = mid + 1;
          }
        }
        at = first;
        if (at - 1 >= lo && std::abs(below(at - 1) - half) <= std::abs(below(at) - half))
        {
          at = at - 1;
        }
      }
    }
    if (alongX)
    {
      a = this->Make(r.X0, at, r.Y0, r.Y1);
      b = this->Make(at, r.X1, r.Y0, r.Y1);
    }
    else
    {
      a = this->Make(r.X0, r.X1, r.Y0, at);
      b = this->Make(r.X0, r.X1, at, r.Y1);
    }
  }

  /// The longer side measured in angle (width scaled by sin(theta) at the centre).
  void LongerSide(const Region& r, bool& alongX) const
  {
    const int w = r.X1 - r.X0;
    const int h = r.Y1 - r.Y0;
    const double width = w * this->DPhi * this->SinThetaCentre(r.Y0, r.Y1);
    const double height = h * this->DTheta;
    alongX = w >= 2 && (width >= height || h < 2);
  }
};
} // namespace

//------------------------------------------------------------------------------
std::vector<MedianCutLight> ComputeMedianCut(
  const float* pixels, int components, int width, int height, const MedianCutOptions& options)
{
  std::vector<MedianCutLight> lights;
  const long long count = static_cast<long long>(width) * static_cast<long long>(height);
  if (!pixels || width < 1 || height < 1 || components < 3)
  {
    throw MedianCutError("median cut needs a non-empty map with at least 3 components (RGB)");
  }
  const int n = options.NumberOfLights;
  if (n < 1 || n > count)
  {
    std::ostringstream os;
    os << "the number of lights must be between 1 and the number of pixels (" << count << "); got "
       << n;
    throw MedianCutError(os.str());
  }
  auto progress = [&](double f) { return ReportProgress(options.Progress, f); };

  const int w = width;
  const int h = height;
  Cutter cut;
  cut.Variance = options.VarianceMinimization;
  // Plain cuts work on pixels, variance cuts on cells of k x k pixels (VarianceCellSize).
  const int cell = cut.Variance ? VarianceCellSize(w, h, n) : 1;
  cut.W = (w + cell - 1) / cell;
  cut.H = (h + cell - 1) / cell;
  cut.DPhi = 2.0 * Pi<double> * cell / w;
  cut.DTheta = Pi<double> * cell / h;
  const double dPhi = 2.0 * Pi<double> / w; // a pixel column's angle

  // Per-row weights (rows from the top): pixel weight, moment factors.
  std::vector<double> rowWeight(static_cast<size_t>(h));
  std::vector<double> rowS(static_cast<size_t>(h));
  std::vector<double> rowZ(static_cast<size_t>(h));
  std::vector<double> colC(static_cast<size_t>(w));
  std::vector<double> colS(static_cast<size_t>(w));
  const double uniform = 4.0 * Pi<double> / static_cast<double>(count);
  for (int y = 0; y < h; ++y)
  {
    const int j = h - 1 - y; // VTK row
    if (options.SolidAngleWeighting)
    {
      double m[3];
      PixelMoment(0, j, w, h, m);
      rowWeight[y] = PixelSolidAngle(j, w, h);
      const double t0 = Pi<double> * y / h;
      const double t1 = Pi<double> * (y + 1) / h;
      rowS[y] = 0.5 * (t1 - t0) - 0.25 * (std::sin(2.0 * t1) - std::sin(2.0 * t0));
      rowZ[y] = m[2];
    }
    else
    {
      const double theta = Pi<double> * (y + 0.5) / h;
      rowWeight[y] = uniform;
      rowS[y] = uniform * std::sin(theta);
      rowZ[y] = uniform * std::cos(theta);
    }
  }
  for (int x = 0; x < w; ++x)
  {
    if (options.SolidAngleWeighting)
    {
      colC[x] = std::sin(dPhi * (x + 1)) - std::sin(dPhi * x);
      colS[x] = std::cos(dPhi * x) - std::cos(dPhi * (x + 1));
    }
    else
    {
      colC[x] = std::cos(dPhi * (x + 0.5));
      colS[x] = std::sin(dPhi * (x + 0.5));
    }
  }

  // 1. Energies and SATs (rows from the top). Non-finite values are errors.
  std::vector<long long> badPerRow(static_cast<size_t>(h), 0);
  std::vector<long long> firstBadPerRow(static_cast<size_t>(h), -1);
  // The energy e = Y dOmega of the pixel in row y (from the top); false if not finite.
  auto pixelEnergy = [&](const float* p, int x, int y, double& v)
  {
    const double r = p[0];
    const double g = p[1];
    const double b = p[2];
    if (!std::isfinite(r) || !std::isfinite(g) || !std::isfinite(b))
    {
      if (badPerRow[y]++ == 0)
      {
        firstBadPerRow[y] = x;
      }
      v = 0.0;
      return false;
    }
    v = Luminance(std::max(0.0, r), std::max(0.0, g), std::max(0.0, b)) * rowWeight[y];
    return true;
  };
  if (cut.Variance)
  {
    // Cell energies (bands of whole cell rows, so no two tasks add to one cell), then the five
    // tables over the cells.
    std::vector<double> cells(static_cast<size_t>(cut.W) * cut.H, 0.0);
    ForEachBand(cut.H,
      [&](int begin, int end)
      {
        for (int y = begin * cell; y < std::min(end * cell, h); ++y)
        {
          const float* p = pixels + static_cast<size_t>(h - 1 - y) * w * components;
          double* row = cells.data() + static_cast<size_t>(y / cell) * cut.W;
          for (int x = 0; x < w; ++x, p += components)
          {
            double v = 0.0;
            pixelEnergy(p, x, y, v);
            row[x / cell] += v;
          }
        }
      });
    const int cw = cut.W;
    auto at = [&](int x, int y) { return cells[static_cast<size_t>(y) * cw + x]; };
    cut.E.Build(cut.W, cut.H, at);
    cut.Ex.Build(cut.W, cut.H, [&](int x, int y) { return at(x, y) * (x + 0.5); });
    cut.Exx.Build(cut.W, cut.H, [&](int x, int y) { return at(x, y) * (x + 0.5) * (x + 0.5); });
    cut.Ey.Build(cut.W, cut.H, [&](int x, int y) { return at(x, y) * (y + 0.5); });
    cut.Eyy.Build(cut.W, cut.H, [&](int x, int y) { return at(x, y) * (y + 0.5) * (y + 0.5); });
  }
  else
  {
    cut.E.Resize(w, h);
    // Each task builds a band of rows: per-row prefix sums plus the band's rows above, in
    // one pass; the bands are then offset by the SAT row above them.
    ForEachBand(h,
      [&](int begin, int end)
      {
        for (int y = begin; y < end; ++y)
        {
          const float* p = pixels + static_cast<size_t>(h - 1 - y) * w * components;
          const bool above = y > begin;
          double* e = cut.E.Row(y + 1);
          const double* e0 = cut.E.Row(y);
          double run = 0.0;
          for (int x = 0; x < w; ++x, p += components)
          {
            double v = 0.0;
            pixelEnergy(p, x, y, v);
            run += v;
            e[x + 1] = run + (above ? e0[x + 1] : 0.0);
          }
        }
      });
  }
  long long bad = 0;
  for (int y = 0; y < h; ++y)
  {
    bad += badPerRow[y];
  }
  if (bad > 0)
  {
    for (int y = 0; y < h; ++y)
    {
      if (badPerRow[y] > 0)
      {
        std::ostringstream os;
        os << "the map has " << bad
           << " NaN or infinite pixel value(s); the first is at pixel (i=" << firstBadPerRow[y]
           << ", j=" << h - 1 - y << ") (VTK row order)";
        throw MedianCutError(os.str());
      }
    }
  }
  const int bands = cut.Variance ? 1 : BandsFor(h);
  for (int t = 1; t < bands; ++t)
  {
    const int begin = static_cast<int>(static_cast<long long>(h) * t / bands);
    const int end = static_cast<int>(static_cast<long long>(h) * (t + 1) / bands);
    // Table rows begin+1 .. end hold the band; table row `begin` is complete.
    const double* offset = cut.E.Row(begin);
    // Each row gets the same offset row: any split gives the same sums.
    ParallelFor(0, static_cast<std::size_t>(end - begin), 16,
      [&](std::size_t b, std::size_t e) {
        cut.E.AddOffsetRow(begin + 1 + static_cast<int>(b), begin + static_cast<int>(e), offset);
      });
  }
  const double total = cut.E.Sum(0, cut.W, 0, cut.H);
  if (!(total > 0.0))
  {
    throw MedianCutError("the map has no light: every pixel is black (or negative)");
  }
  if (!progress(0.3))
  {
    throw MedianCutAbortedError();
  }

  // 2. Split regions, the highest priority first.
  std::priority_queue<Region, std::vector<Region>, RegionLess> queue;
  std::vector<Region> done;
  queue.push(cut.Make(0, cut.W, 0, cut.H));
  int regions = 1;
  while (regions < n && !queue.empty())
  {
    const Region r = queue.top();
    queue.pop();
    if (r.Priority < 0.0)
    {
      done.push_back(r); // a single pixel; everything left in the queue is too
      continue;
    }
    Region a{};
    Region b{};
    cut.Cut(r, a, b);
    queue.push(a);
    queue.push(b);
    ++regions;
    if ((regions & 63) == 0 && !progress(0.3 + 0.5 * regions / n))
    {
      throw MedianCutAbortedError();
    }
  }
  while (!queue.empty())
  {
    done.push_back(queue.top());
    queue.pop();
  }
  if (!progress(0.8))
  {
    throw MedianCutAbortedError();
  }
  for (Region& r : done) // cells to pixels
  {
    r.X0 *= cell;
    r.X1 = std::min(r.X1 * cell, w);
    r.Y0 *= cell;
    r.Y1 = std::min(r.Y1 * cell, h);
  }

  // 3. One light per region: colour, energy centroid, solid angle.
  lights.resize(done.size());
  const int regionCount = static_cast<int>(done.size());
  // Largest regions first, handed out one at a time (region sizes differ by orders of
  // magnitude, so fixed bands of regions would leave a thread idle).
  std::vector<int> order(static_cast<size_t>(regionCount));
  std::iota(order.begin(), order.end(), 0);
  std::sort(order.begin(), order.end(),
    [&](int a, int b)
    {
      const long long areaA =
        static_cast<long long>(done[a].X1 - done[a].X0) * (done[a].Y1 - done[a].Y0);
      const long long areaB =
        static_cast<long long>(done[b].X1 - done[b].X0) * (done[b].Y1 - done[b].Y0);
      return areaA > areaB;
    });
  // One region per item, the largest first: each light is computed alone.
  ParallelFor(0, static_cast<std::size_t>(regionCount), 1,
    [&](std::size_t s0, std::size_t s1)
    {
      for (std::size_t slot = s0; slot < s1; ++slot)
      {
        const int k = order[slot];
        const Region& r = done[k];
        double rgb[3] = { 0.0, 0.0, 0.0 };
        double m[3] = { 0.0, 0.0, 0.0 };
        double energy = 0.0;
        double solidAngle = 0.0;
        for (int y = r.Y0; y < r.Y1; ++y)
        {
          const int j = h - 1 - y;
          const float* p = pixels + (static_cast<size_t>(j) * w + r.X0) * components;
          double sr = 0.0;
          double sg = 0.0;
          double sb = 0.0;
          double sy = 0.0;
          double syc = 0.0;
          double sys = 0.0;
          for (int x = r.X0; x < r.X1; ++x, p += components)
          {
            const double cr = std::max(0.0, static_cast<double>(p[0]));
            const double cg = std::max(0.0, static_cast<double>(p[1]));
            const double cb = std::max(0.0, static_cast<double>(p[2]));
            const double lum = Luminance(cr, cg, cb);
            sr += cr;
            sg += cg;
            sb += cb;
            sy += lum;
            syc += lum * colC[x];
            sys += lum * colS[x];
          }
          const double weight = rowWeight[y];
          rgb[0] += sr * weight;
          rgb[1] += sg * weight;
          rgb[2] += sb * weight;
          energy += sy * weight;
          solidAngle += weight * (r.X1 - r.X0);
          m[0] += rowS[y] * syc;
          m[1] += rowS[y] * sys;
          m[2] += rowZ[y] * sy;
        }
        MedianCutLight& light = lights[k];
        const double len = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
        if (len > 1e-9 * std::max(energy, 1e-300) && len > 0.0)
        {
          for (int c = 0; c < 3; ++c)
          {
            light.Direction[c] = m[c] / len;
          }
        }
        else
        {
          // No preferred direction (e.g. the whole uniform sphere): the region's centre.
          DirectionFromMapUV(0.5 * (r.X0 + r.X1) / w, 0.5 * (r.Y0 + r.Y1) / h, light.Direction);
        }
        MapUVFromDirection(light.Direction, light.U, light.V);
        for (int c = 0; c < 3; ++c)
        {
          light.Rgb[c] = rgb[c];
        }
        light.Energy = energy;
        light.SolidAngle = options.SolidAngleWeighting ? (2.0 * Pi<double> * (r.X1 - r.X0) / w) *
            (std::cos(Pi<double> * r.Y0 / h) - std::cos(Pi<double> * r.Y1 / h))
                                                       : solidAngle;
        light.Column0 = r.X0;
        light.Column1 = r.X1;
        light.Row0 = r.Y0;
        light.Row1 = r.Y1;
        light.U0 = static_cast<double>(r.X0) / w;
        light.U1 = static_cast<double>(r.X1) / w;
        light.V0 = static_cast<double>(r.Y0) / h;
        light.V1 = static_cast<double>(r.Y1) / h;
      }
    });
  std::stable_sort(lights.begin(), lights.end(),
    [](const MedianCutLight& a, const MedianCutLight& b) { return a.Energy > b.Energy; });
  if (!progress(1.0))
  {
    throw MedianCutAbortedError();
  }
  return lights;
}

//------------------------------------------------------------------------------
void IrradianceFromLights(const std::vector<MedianCutLight>& lights, const double n[3], double e[3])
{
  e[0] = e[1] = e[2] = 0.0;
  for (const auto& light : lights)
  {
    const double c =
      n[0] * light.Direction[0] + n[1] * light.Direction[1] + n[2] * light.Direction[2];
    if (c > 0.0)
    {
      e[0] += c * light.Rgb[0];
      e[1] += c * light.Rgb[1];
      e[2] += c * light.Rgb[2];
    }
  }
}

} // namespace mesolight
