// SPDX-License-Identifier: BSD-3-Clause
#include "HeightFieldTracer.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <sstream>
#include <stdexcept>

namespace mesolight
{
namespace
{

// Grid coordinates put texel centres on the integers: x = u * W - 0.5, so texel i sits at x = i.
double ToGrid(double u, int n)
{
  return u * n - 0.5;
}

bool IsFinite(const glm::dvec3& p)
{
  return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z);
}

// Where a grid coordinate falls along one axis: the two texels it blends, the weight of the upper
// one, and d(weight)/dx (0 in a clamp band, where the surface is constant along this axis).
struct AxisSample
{
  int Lower;
  int Upper;
  double Weight;
  double Rate;
};

AxisSample SampleAxis(double x, int n)
{
  const double last = n - 1;
  const double clamped = std::clamp(x, 0.0, last);
  const int lower = static_cast<int>(std::floor(clamped));
  const int upper = std::min(lower + 1, n - 1);
  // Half-open cells [i, i + 1): at x = n - 1 we are already in the upper band.
  const bool inBand = x < 0.0 || x >= last;
  return { lower, upper, clamped - lower, inBand ? 0.0 : 1.0 };
}

// a + w (b - a) is exact at w = 0 (texel centres; w < 1 always) and wherever a == b, so the
// surface passes exactly through every sample and is exactly flat on flat regions and in bands.
double Lerp(double a, double b, double w)
{
  return a + w * (b - a);
}

// One cell of the texel-centre grid: the bilinear patch through its four corner samples, in the
// polynomial form depth = D00 + Du fx + Dv fy + Duv fx fy with (fx, fy) the position in the cell.
struct Patch
{
  double D00;
  double Du;
  double Dv;
  double Duv;
  double Shallowest; // a bilinear patch takes its extremes at the corners
  double Deepest;

  double At(double fx, double fy) const { return D00 + Du * fx + Dv * fy + Duv * fx * fy; }
};

Patch MakePatch(const HeightField& hf, int i0, int i1, int j0, int j1)
{
  const double d00 = hf.ClampedTexel(i0, j0);
  const double d10 = hf.ClampedTexel(i1, j0);
  const double d01 = hf.ClampedTexel(i0, j1);
  const double d11 = hf.ClampedTexel(i1, j1);
  return { d00, d10 - d00, d01 - d00, d11 - d10 - d01 + d00, std::min({ d00, d10, d01, d11 }),
    std::max({ d00, d10, d01, d11 }) };
}

// DDA state along one grid axis. Cells are -1 .. n-1: cell k spans [k, k + 1] between texel
// centres, except the clamp bands -1 = (-inf, 0] and n-1 = [n-1, +inf), which have no outer edge.
class AxisWalk
{
public:
  AxisWalk(double x0, double rate, int n)
    : X0(x0)
    , Rate(rate)
    , N(n)
    , Cell(static_cast<int>(std::clamp(std::floor(x0), -1.0, n - 1.0)))
  {
  }

  bool InBand() const { return this->Cell < 0 || this->Cell >= this->N - 1; }
  int Lower() const { return std::clamp(this->Cell, 0, this->N - 1); }
  int Upper() const { return std::clamp(this->Cell + 1, 0, this->N - 1); }

  // Ray parameter at which the ray leaves the current cell along this axis. Computed from X0 each
  // time (not accumulated), so crossings stay accurate and monotone over long walks.
  double NextCrossing() const
  {
    if (this->Rate > 0.0 && this->Cell < this->N - 1)
    {
      return (this->Cell + 1 - this->X0) / this->Rate;
    }
    if (this->Rate < 0.0 && this->Cell >= 0)
    {
      return (this->Cell - this->X0) / this->Rate;
    }
    return std::numeric_limits<double>::infinity();
  }

  void Step() { this->Cell += this->Rate > 0.0 ? 1 : -1; }

  // Position inside the patch at ray parameter t, and its rate; both 0 in a band, where the
  // surface does not vary along this axis.
  double Fraction(double t) const
  {
    return this->InBand() ? 0.0 : this->X0 + t * this->Rate - this->Cell;
  }
  double FractionRate() const { return this->InBand() ? 0.0 : this->Rate; }

private:
  double X0;
  double Rate;
  int N;
  int Cell;
};

// Which points count as a hit: IntersectFirst wants on-or-below, Visible only blocks on strictly
// below (so a shadow ray may graze or leave along the surface).
enum class Contact
{
  OnOrBelow,
  StrictlyBelow
};

// f = ray depth - surface depth; the contact predicate on f.
bool Touches(double f, Contact contact)
{
  return contact == Contact::OnOrBelow ? f >= 0.0 : f > 0.0;
}

// f(s) = A s^2 + B s + C along the ray inside one cell (s = t - tEnter).
struct Quadratic
{
  double A;
  double B;
  double C;

  double operator()(double s) const { return (this->A * s + this->B) * s + this->C; }
};

// A root of f in [lo, hi], where f is monotone: the numerically stable quadratic formula
// (q = -(B + sign(B) sqrt(disc)) / 2, roots q / A and C / q). C / q stays accurate as A -> 0, where
// it tends to the linear root -C / B; q / A is then huge and simply falls outside the bracket.
double MonotoneRoot(const Quadratic& f, double lo, double hi)
{
  const double disc = std::max(0.0, f.B * f.B - 4.0 * f.A * f.C); // a root exists: clamp rounding
  const double q = -0.5 * (f.B + std::copysign(std::sqrt(disc), f.B));
  for (double r : { q != 0.0 ? f.C / q : lo - 1.0, f.A != 0.0 ? q / f.A : lo - 1.0 })
  {
    if (r >= lo && r <= hi)
    {
      return r;
    }
  }
  return 0.5 * (lo + hi); // degenerate (near-constant f): let the bisection do it
}

// Given a bracket where f does not touch at lo and touches at hi, returns a touching s within
// tol of the first contact. The analytic root r is exact up to rounding, so probing a few widths
// that grow from a few ulps around r usually closes the bracket at once; bisection then
// guarantees the result whatever rounding did to the formula. `ulp` ~ the spacing of t values.
double PolishRoot(const Quadratic& f, double lo, double hi, Contact contact, double ulp, double tol)
{
  const double r = MonotoneRoot(f, lo, hi);
  const bool rTouches = Touches(f(r), contact);
  (rTouches ? hi : lo) = r;
  for (double width = 4.0 * ulp; hi - lo > tol; width *= 32.0)
  {
    // Probe away from r on the side where the other end of the bracket lies.
    const double probe = rTouches ? r - width : r + width;
    if (probe <= lo || probe >= hi)
    {
      break;
    }
    (Touches(f(probe), contact) ? hi : lo) = probe;
  }
  while (hi - lo > tol)
  {
    const double mid = lo + 0.5 * (hi - lo);
    if (mid <= lo || mid >= hi)
    {
      break; // no representable midpoint left
    }
    (Touches(f(mid), contact) ? hi : lo) = mid;
  }
  return hi;
}

// Smallest s in [0, length] where f touches. Splitting at the stationary point -B / 2A makes each
// piece monotone, so a sign test at a piece's end decides exactly whether it holds a root, and
// tangential (double-root) contacts are not lost to a negative discriminant.
std::optional<double> FirstContact(
  const Quadratic& f, double length, Contact contact, double ulp, double tol)
{
  if (Touches(f(0.0), contact))
  {
    return 0.0;
  }
  double ends[2] = { length, length };
  if (f.A != 0.0)
  {
    const double turn = -f.B / (2.0 * f.A);
    if (turn > 0.0 && turn < length)
    {
      ends[0] = turn;
    }
  }
  double start = 0.0;
  for (double end : ends)
  {
    if (end > start && Touches(f(end), contact))
    {
      return PolishRoot(f, start, end, contact, ulp, tol);
    }
    start = end;
  }
  return std::nullopt;
}

// Bracket width on the returned t, relative to max(1, |t|), and the relative spacing of doubles.
constexpr double kTolerance = 1e-12;
constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

// First contact inside the current cell, for t in [tEnter, tExit].
std::optional<double> FirstContactInCell(const HeightField& hf, const AxisWalk& x,
  const AxisWalk& y, double oz, double dz, double tEnter, double tExit, Contact contact)
{
  const Patch patch = MakePatch(hf, x.Lower(), x.Upper(), y.Lower(), y.Upper());
  const double dEnter = oz + tEnter * dz;
  const double dExit = oz + tExit * dz;
  // The ray is linear in d: its deepest point here is an end. If even that is shallower than the
  // patch's shallowest corner, no contact is possible in this cell.
  if (!Touches(std::max(dEnter, dExit) - patch.Shallowest, contact))
  {
    return std::nullopt;
  }
  // Along the ray fx = fx0 + gx s and fy = fy0 + gy s, so the bilinear depth is quadratic in s
  // (the s^2 term is Duv gx gy), while the ray's d = dEnter + dz s is linear.
  const double fx0 = x.Fraction(tEnter);
  const double fy0 = y.Fraction(tEnter);
  const double gx = x.FractionRate();
  const double gy = y.FractionRate();
  const Quadratic f{ -patch.Duv * gx * gy,
    dz - (patch.Du * gx + patch.Dv * gy + patch.Duv * (fx0 * gy + fy0 * gx)),
    dEnter - patch.At(fx0, fy0) };
  const double scale = std::max(1.0, std::abs(tExit));
  const std::optional<double> s =
    FirstContact(f, tExit - tEnter, contact, kEpsilon * scale, kTolerance * scale);
  if (!s)
  {
    return std::nullopt;
  }
  return std::min(tEnter + *s, tExit);
}

// 2D DDA over the cells of the texel-centre grid (bands included), from t = 0 to tMax: calls
// cell(x, y, tEnter, tExit) for each crossed cell in order until it returns true. Visits each
// crossed cell once: at most W + H + 1 cells per ray. False for input it cannot walk.
template <typename CellVisitor>
bool WalkCells(const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tMax,
  CellVisitor&& cell)
{
  if (!IsFinite(origin) || !IsFinite(dir) || !std::isfinite(tMax) || tMax < 0.0)
  {
    return false;
  }
  const glm::dvec2 grid0(ToGrid(origin.x, hf.Width()), ToGrid(origin.y, hf.Height()));
  const glm::dvec2 gridRate(dir.x * hf.Width(), dir.y * hf.Height());
  if (!std::isfinite(grid0.x) || !std::isfinite(grid0.y) || !std::isfinite(gridRate.x) ||
    !std::isfinite(gridRate.y))
  {
    return false; // finite in texture space but overflows in grid units
  }
  AxisWalk x(grid0.x, gridRate.x, hf.Width());
  AxisWalk y(grid0.y, gridRate.y, hf.Height());
  double tEnter = 0.0;
  for (;;)
  {
    const double crossX = x.NextCrossing();
    const double crossY = y.NextCrossing();
    const double tExit = std::max(tEnter, std::min({ crossX, crossY, tMax }));
    if (cell(static_cast<const AxisWalk&>(x), static_cast<const AxisWalk&>(y), tEnter, tExit) ||
      tExit >= tMax)
    {
      return true;
    }
    // tExit < tMax, so at least one axis crosses here (both at a cell corner).
    if (crossX <= tExit)
    {
      x.Step();
    }
    if (crossY <= tExit)
    {
      y.Step();
    }
    tEnter = tExit;
  }
}

// The first contact along the walk, solving each cell exactly.
std::optional<RayHit> Trace(const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir,
  double tMax, Contact contact)
{
  std::optional<RayHit> hit;
  WalkCells(hf, origin, dir, tMax,
    [&](const AxisWalk& x, const AxisWalk& y, double tEnter, double tExit)
    {
      if (auto t = FirstContactInCell(hf, x, y, origin.z, dir.z, tEnter, tExit, contact))
      {
        hit = RayHit{ *t, origin + *t * dir };
        return true;
      }
      return false;
    });
  return hit;
}

// The ray's parameter interval inside the texture rectangle [0, 1]^2 (slab clipping), and the
// wall it leaves through: false when it misses the rectangle.
struct RectangleSpan
{
  double In;
  double Out;
  glm::dvec2 Wall; // the inward normal of the border crossed at Out
};

bool ClipToRectangle(const glm::dvec3& origin, const glm::dvec3& dir, RectangleSpan& span)
{
  span = { -std::numeric_limits<double>::infinity(), std::numeric_limits<double>::infinity(),
    glm::dvec2(0.0) };
  for (int a = 0; a < 2; ++a)
  {
    if (dir[a] == 0.0)
    {
      if (origin[a] < 0.0 || origin[a] > 1.0)
      {
        return false;
      }
      continue;
    }
    double t0 = (0.0 - origin[a]) / dir[a];
    double t1 = (1.0 - origin[a]) / dir[a];
    // Leaving through u = 1 (v = 1) the wall faces -u (-v), through 0 it faces +u (+v).
    const double inward = dir[a] > 0.0 ? -1.0 : 1.0;
    if (t0 > t1)
    {
      std::swap(t0, t1);
    }
    span.In = std::max(span.In, t0);
    if (t1 < span.Out)
    {
      span.Out = t1;
      span.Wall = glm::dvec2(0.0);
      span.Wall[a] = inward;
    }
  }
  return span.In <= span.Out;
}

// First contact with the plane d = 0 (the solid outside a walled rectangle) for t in [t0, t1].
std::optional<double> PlaneContact(double oz, double dz, double t0, double t1, Contact contact)
{
  if (!(t1 >= t0))
  {
    return std::nullopt;
  }
  if (Touches(oz + t0 * dz, contact))
  {
    return t0;
  }
  if (dz > 0.0)
  {
    const double t = std::max(t0, -oz / dz);
    if (t <= t1 && (contact == Contact::OnOrBelow || t < t1))
    {
      return t;
    }
  }
  return std::nullopt;
}

// The edge rule on top of Trace: a Walled field is Trace's surface inside [0, 1]^2 and the solid
// below d = 0 outside it, so the ray meets, in order, the plane before the rectangle, the surface
// inside it, the side wall where it leaves below d = 0, and the plane after it.
std::optional<RayHit> TraceEdge(const HeightField& hf, const glm::dvec3& origin,
  const glm::dvec3& dir, double tMax, Contact contact)
{
  if (hf.EdgeRule() == HeightField::Edge::Clamped)
  {
    return Trace(hf, origin, dir, tMax, contact);
  }
  if (!IsFinite(origin) || !IsFinite(dir) || !std::isfinite(tMax) || tMax < 0.0)
  {
    return std::nullopt;
  }
  const auto plane = [&](double t0, double t1) -> std::optional<RayHit>
  {
    if (auto t = PlaneContact(origin.z, dir.z, t0, t1, contact))
    {
      return RayHit{ *t, origin + *t * dir };
    }
    return std::nullopt;
  };
  RectangleSpan span;
  if (!ClipToRectangle(origin, dir, span) || span.Out < 0.0 || span.In > tMax)
  {
    return plane(0.0, tMax);
  }
  const double tIn = std::max(0.0, span.In);
  if (tIn > 0.0)
  {
    if (auto hit = plane(0.0, tIn))
    {
      return hit;
    }
  }
  const double tOut = std::min(span.Out, tMax);
  const glm::dvec3 entry = origin + tIn * dir;
  if (auto hit = Trace(hf, entry, dir, tOut - tIn, contact))
  {
    hit->t += tIn;
    return hit;
  }
  if (span.Out > tMax)
  {
    return std::nullopt;
  }
  // Leaving the rectangle: below d = 0 the side wall stops the ray at the border.
  const double dOut = origin.z + tOut * dir.z;
  if (Touches(dOut, contact))
  {
    RayHit hit{ tOut, origin + tOut * dir };
    hit.point = glm::dvec3(glm::clamp(glm::dvec2(hit.point), 0.0, 1.0), hit.point.z);
    hit.wall = span.Wall;
    return hit;
  }
  return plane(tOut, tMax);
}

} // namespace

HeightField::HeightField(int w, int h, std::vector<float> depth, Edge edge)
  : W(w)
  , H(h)
  , Depth(std::move(depth))
  , Border(edge)
{
  if (w < 1 || h < 1)
  {
    std::ostringstream msg;
    msg << "HeightField: size must be at least 1 x 1, got " << w << " x " << h;
    throw std::invalid_argument(msg.str());
  }
  const size_t expected = static_cast<size_t>(w) * static_cast<size_t>(h);
  if (this->Depth.size() != expected)
  {
    std::ostringstream msg;
    msg << "HeightField: " << w << " x " << h << " needs " << expected << " depth samples, got "
        << this->Depth.size();
    throw std::invalid_argument(msg.str());
  }
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      if (!std::isfinite(this->Texel(i, j)))
      {
        std::ostringstream msg;
        msg << "HeightField: non-finite depth " << this->Texel(i, j) << " at texel (i=" << i
            << ", j=" << j << "), index " << static_cast<size_t>(j) * w + i;
        throw std::invalid_argument(msg.str());
      }
    }
  }
}

double HeightField::ClampedTexel(int i, int j) const
{
  return this->Texel(std::clamp(i, 0, this->W - 1), std::clamp(j, 0, this->H - 1));
}

bool HeightField::OutsideWall(double u, double v) const
{
  return this->Border == Edge::Walled && (u < 0.0 || u > 1.0 || v < 0.0 || v > 1.0);
}

double HeightField::DepthAt(double u, double v) const
{
  if (std::isnan(u) || std::isnan(v))
  {
    return std::numeric_limits<double>::quiet_NaN();
  }
  if (this->OutsideWall(u, v))
  {
    return 0.0;
  }
  const AxisSample x = SampleAxis(ToGrid(u, this->W), this->W);
  const AxisSample y = SampleAxis(ToGrid(v, this->H), this->H);
  const double bottom =
    Lerp(this->Texel(x.Lower, y.Lower), this->Texel(x.Upper, y.Lower), x.Weight);
  const double top = Lerp(this->Texel(x.Lower, y.Upper), this->Texel(x.Upper, y.Upper), x.Weight);
  return Lerp(bottom, top, y.Weight);
}

glm::dvec2 HeightField::GradientAt(double u, double v) const
{
  if (std::isnan(u) || std::isnan(v))
  {
    return glm::dvec2(std::numeric_limits<double>::quiet_NaN());
  }
  if (this->OutsideWall(u, v))
  {
    return glm::dvec2(0.0);
  }
  const AxisSample x = SampleAxis(ToGrid(u, this->W), this->W);
  const AxisSample y = SampleAxis(ToGrid(v, this->H), this->H);
  const double d00 = this->Texel(x.Lower, y.Lower);
  const double d10 = this->Texel(x.Upper, y.Lower);
  const double d01 = this->Texel(x.Lower, y.Upper);
  const double d11 = this->Texel(x.Upper, y.Upper);
  // Chain rule: d/du = d/dx * W (x = u W - 0.5); Rate zeroes the clamped axis.
  const double ddx = Lerp(d10 - d00, d11 - d01, y.Weight) * x.Rate;
  const double ddy = Lerp(d01 - d00, d11 - d10, x.Weight) * y.Rate;
  return { ddx * this->W, ddy * this->H };
}

std::optional<RayHit> IntersectFirst(
  const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tMax)
{
  return TraceEdge(hf, origin, dir, tMax, Contact::OnOrBelow);
}

bool Visible(
  const HeightField& hf, const glm::dvec3& point, const glm::dvec3& toLight, double epsilon)
{
  return VisibleOrBlocker(hf, point, toLight, epsilon).Visible;
}

Visibility VisibleOrBlocker(
  const HeightField& hf, const glm::dvec3& point, const glm::dvec3& toLight, double epsilon)
{
  if (!IsFinite(point) || !IsFinite(toLight) || !std::isfinite(epsilon) || !(toLight.z < 0.0))
  {
    return {};
  }
  const glm::dvec3 dir =
    toLight / std::sqrt(toLight.x * toLight.x + toLight.y * toLight.y + toLight.z * toLight.z);
  const glm::dvec3 start = point + epsilon * dir;
  if (start.z <= 0.0)
  {
    return { true, std::nullopt }; // already at or above the top of the height field
  }
  const double tTop = -start.z / dir.z; // where the ray reaches d = 0
  Visibility result;
  result.Blocker = TraceEdge(hf, start, dir, tTop, Contact::StrictlyBelow);
  result.Visible = !result.Blocker;
  return result;
}

int CountBoundReachingCells(
  const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tEnd)
{
  int count = 0;
  WalkCells(hf, origin, dir, tEnd,
    [&](const AxisWalk& x, const AxisWalk& y, double tEnter, double tExit)
    {
      const Patch patch = MakePatch(hf, x.Lower(), x.Upper(), y.Lower(), y.Upper());
      const double deepest = std::max(origin.z + tEnter * dir.z, origin.z + tExit * dir.z);
      // The tolerance keeps the hit's own cell when tEnd comes from IntersectFirst, whose
      // bracket is evaluated in the cell's own polynomial, not at origin + tEnd dir.
      count += deepest >= patch.Shallowest - 1e-9 ? 1 : 0;
      return false;
    });
  return count;
}

std::optional<RayHit> IntersectFirstBruteForce(
  const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tMax, int samples)
{
  if (samples < 1)
  {
    throw std::invalid_argument("IntersectFirstBruteForce: samples must be at least 1");
  }
  if (!IsFinite(origin) || !IsFinite(dir) || !std::isfinite(tMax) || tMax < 0.0)
  {
    return std::nullopt;
  }
  // Scalar arithmetic: the oracle runs ~10^7 times per test, often in unoptimized builds.
  const auto below = [&](double t)
  { return origin.z + t * dir.z >= hf.DepthAt(origin.x + t * dir.x, origin.y + t * dir.y); };
  if (below(0.0))
  {
    return RayHit{ 0.0, origin };
  }
  double lo = 0.0;
  for (int k = 1; k <= samples; ++k)
  {
    double hi = tMax * k / samples;
    if (below(hi))
    {
      for (int iter = 0; iter < 200 && hi - lo > 1e-15 * std::max(1.0, hi); ++iter)
      {
        const double mid = lo + 0.5 * (hi - lo);
        if (mid <= lo || mid >= hi)
        {
          break;
        }
        (below(mid) ? hi : lo) = mid;
      }
      return RayHit{ hi, origin + hi * dir };
    }
    lo = hi;
  }
  return std::nullopt;
}

} // namespace mesolight
