// SPDX-License-Identifier: BSD-3-Clause
#include "DirectionSet.h"

#include "MathConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <string>

namespace mesolight
{
namespace vlf
{

namespace
{

// How far around the lattice square holding a direction Nearest looks (lattice steps before the
// square's lower corner and after its upper corner). The map is equal-area but not conformal, so
// the nearest direction by angle is often not a corner of the subdivision triangle holding the
// direction (7.5% of random directions). The square's four corners (ring 0) agreed with brute
// force on 10^6 random directions for n = 16, 32, 64; one more ring (16 candidates) is a margin.
constexpr int NearestRing = 1;

// The lattice points kept on the equator |i| + |j| = n: azimuth in [0, pi), i.e. j > 0, or j == 0
// and i > 0. The others are the antipodes of kept points.
bool KeptOnEquator(int i, int j)
{
  return j > 0 || (j == 0 && i > 0);
}
} // namespace

glm::dvec2 DirectionSet::HemisphereToDiamond(const glm::dvec3& unit)
{
  // r = sqrt(1 - z), written without the cancellation of 1 - z near the pole.
  const double rho2 = unit.x * unit.x + unit.y * unit.y;
  const double r = std::sqrt(rho2 / (1.0 + std::max(unit.z, 0.0)));
  const double phi = std::atan2(std::abs(unit.y), std::abs(unit.x)); // [0, pi/2]
  const double ay = std::min(r * phi * (2.0 / Pi<double>), r);
  const double ax = r - ay;
  return { std::copysign(ax, unit.x), std::copysign(ay, unit.y) };
}

glm::dvec3 DirectionSet::DiamondToHemisphere(const glm::dvec2& diamond)
{
  const double ax = std::abs(diamond.x);
  const double ay = std::abs(diamond.y);
  const double r = std::min(ax + ay, 1.0);
  if (r <= 0.0)
  {
    return { 0.0, 0.0, 1.0 };
  }
  // Equal area: the L1 ring of radius r (area 4r dr) maps to the zone of height dz = 2r dr
  // (solid angle 4 pi r dr), and azimuth is linear along the ring.
  const double phi = (Pi<double> / 2.0) * std::min(ay / r, 1.0);
  const double z = 1.0 - r * r;
  const double s = r * std::sqrt(std::max(2.0 - r * r, 0.0));
  return { std::copysign(std::cos(phi) * s, diamond.x), std::copysign(std::sin(phi) * s, diamond.y),
    z };
}

DirectionSet::DirectionSet(int n)
{
  if (n < 1 || n > 4096)
  {
    throw std::invalid_argument(
      "DirectionSet: subdivisions must be in [1, 4096], got " + std::to_string(n));
  }
  this->N = n;
  const std::size_t side = 2 * static_cast<std::size_t>(n) + 1;
  this->Lattice.assign(side * side, LatticePoint{});

  // Kept points first, row by row (j ascending, then i ascending).
  for (int j = -n; j <= n; ++j)
  {
    const int width = n - std::abs(j);
    for (int i = -width; i <= width; ++i)
    {
      const bool onEquator = std::abs(i) + std::abs(j) == n;
      if (onEquator && !KeptOnEquator(i, j))
      {
        continue;
      }
      glm::dvec3 d = DiamondToHemisphere({ double(i) / n, double(j) / n });
      if (onEquator)
      {
        d.z = 0.0; // exactly on the equator, so -d is exactly in the set's antipodal half
      }
      d = glm::normalize(d);
      LatticePoint& point =
        this->Lattice[static_cast<std::size_t>(j + n) * side + static_cast<std::size_t>(i + n)];
      point.Direction = glm::vec3(d);
      point.Index = static_cast<std::uint32_t>(this->Directions.size());
      point.Flipped = false;
      point.Valid = true;
      this->Directions.push_back(point.Direction);
    }
  }
  // Dropped equator points stand for their kept antipodes, read backwards.
  for (int j = -n; j <= n; ++j)
  {
    const int width = n - std::abs(j);
    for (const int i : { -width, width })
    {
      if (KeptOnEquator(i, j))
      {
        continue;
      }
      const LatticePoint& antipode = this->At(-i, -j);
      LatticePoint& point =
        this->Lattice[static_cast<std::size_t>(j + n) * side + static_cast<std::size_t>(i + n)];
      point.Direction = -antipode.Direction;
      point.Index = antipode.Index;
      point.Flipped = true;
      point.Valid = true;
    }
  }

  // Solid angles: every subdivision triangle covers pi / (2 n^2) (the map is equal-area; the
  // diamond of area 2 holds 4 n^2 lattice triangles and maps onto the hemisphere, 2 pi), a third
  // of it per corner. Triangles are enumerated per quadrant as Interpolate() finds them.
  std::vector<double> weights(this->Directions.size(), 0.0);
  const double third = Pi<double> / (2.0 * n * n) / 3.0;
  const auto credit = [&](int i, int j) { weights[this->At(i, j).Index] += third; };
  for (const int sx : { 1, -1 })
  {
    for (const int sy : { 1, -1 })
    {
      for (int b = 0; b < n; ++b)
      {
        for (int a = 0; a + b < n; ++a)
        {
          credit(sx * a, sy * b); // lower triangle (a,b) (a+1,b) (a,b+1)
          credit(sx * (a + 1), sy * b);
          credit(sx * a, sy * (b + 1));
          if (a + b + 2 <= n) // upper triangle (a+1,b+1) (a,b+1) (a+1,b)
          {
            credit(sx * (a + 1), sy * (b + 1));
            credit(sx * a, sy * (b + 1));
            credit(sx * (a + 1), sy * b);
          }
        }
      }
    }
  }
  this->SolidAngles.assign(weights.begin(), weights.end());
}

namespace
{
// n with count = 2 n^2 + 1, or 0 when there is none.
std::size_t SetOrder(std::size_t count)
{
  if (count >= 3 && (count - 1) % 2 == 0)
  {
    const auto n = static_cast<std::size_t>(std::llround(std::sqrt(double(count - 1) / 2.0)));
    if (n >= 1 && 2 * n * n + 1 == count)
    {
      return n;
    }
  }
  return 0;
}
} // namespace

bool DirectionSet::IsCount(std::size_t count, std::string* why)
{
  if (SetOrder(count) > 0)
  {
    return true;
  }
  if (why)
  {
    *why = std::to_string(count) +
      " directions: a direction set holds 2n^2+1 for some whole n >= 1 (3, 9, 19, 33, 51, ..., "
      "129, 513, 2049, 8193, ...)";
  }
  return false;
}

DirectionSet DirectionSet::WithCount(std::size_t count)
{
  std::string why;
  if (!IsCount(count, &why))
  {
    throw std::invalid_argument(why);
  }
  return DirectionSet(static_cast<int>(SetOrder(count)));
}

bool DirectionSet::ToUpperHemisphere(const glm::vec3& unit, glm::dvec3& upper)
{
  glm::dvec3 d(unit);
  const double length = glm::length(d);
  if (!std::isfinite(length) || length <= 0.0)
  {
    throw std::invalid_argument("DirectionSet: direction is zero or not finite");
  }
  d /= length;
  const bool negated = d.z < 0.0;
  upper = negated ? -d : d;
  return negated;
}

std::size_t DirectionSet::Nearest(const glm::vec3& unit, bool* flipped, std::size_t* examined) const
{
  glm::dvec3 u;
  const bool negated = ToUpperHemisphere(unit, u);
  // For z >= 0 the nearest signed direction has z >= 0 too (mirroring a lower one in the equator
  // only brings it closer), so the upper lattice, whose equator holds both signs, suffices.
  const glm::dvec2 p = HemisphereToDiamond(u) * double(this->N);
  const int i0 = static_cast<int>(std::floor(p.x));
  const int j0 = static_cast<int>(std::floor(p.y));
  const glm::vec3 uf(u);
  float best = -2.0f;
  const LatticePoint* bestPoint = nullptr;
  std::size_t compared = 0;
  for (int j = std::max(j0 - NearestRing, -this->N); j <= std::min(j0 + 1 + NearestRing, this->N);
       ++j)
  {
    const int width = this->N - std::abs(j);
    for (int i = std::max(i0 - NearestRing, -width); i <= std::min(i0 + 1 + NearestRing, width);
         ++i)
    {
      const LatticePoint& point = this->At(i, j);
      const float d = glm::dot(point.Direction, uf);
      ++compared;
      if (d > best)
      {
        best = d;
        bestPoint = &point;
      }
    }
  }
  if (bestPoint == nullptr) // unreachable: the cell's own corners are always in the diamond
  {
    bestPoint = &this->At(0, 0);
  }
  if (flipped)
  {
    *flipped = bestPoint->Flipped != negated;
  }
  if (examined)
  {
    *examined = compared;
  }
  return bestPoint->Index;
}

DirectionSet::Interpolation DirectionSet::Interpolate(const glm::vec3& unit) const
{
  glm::dvec3 u;
  const bool negated = ToUpperHemisphere(unit, u);
  const glm::dvec2 p = HemisphereToDiamond(u) * double(this->N);
  // Work in the quadrant of p, where cells are split along their anti-diagonal (as the octahedron
  // face's hypotenuse |x| + |y| = 1).
  const int sx = p.x < 0.0 ? -1 : 1;
  const int sy = p.y < 0.0 ? -1 : 1;
  double ax = std::abs(p.x);
  double ay = std::abs(p.y);
  if (ax + ay > this->N) // rounding on the equator
  {
    const double scale = this->N / (ax + ay);
    ax *= scale;
    ay *= scale;
  }
  int a = std::min(static_cast<int>(ax), this->N - 1);
  int b = std::min(static_cast<int>(ay), this->N - 1);
  if (a + b > this->N - 1)
  {
    (a > 0 ? a : b) -= 1;
  }
  const double fa = ax - a;
  const double fb = ay - b;
  std::array<int, 6> corners; // (i, j) pairs
  std::array<double, 3> weights;
  if (fa + fb <= 1.0)
  {
    corners = { a, b, a + 1, b, a, b + 1 };
    weights = { 1.0 - fa - fb, fa, fb };
  }
  else
  {
    corners = { a + 1, b + 1, a, b + 1, a + 1, b };
    weights = { fa + fb - 1.0, 1.0 - fa, 1.0 - fb };
  }
  Interpolation result{};
  double sum = 0.0;
  for (double& w : weights)
  {
    w = std::clamp(w, 0.0, 1.0);
    sum += w;
  }
  int largest = 0;
  for (int k = 0; k < 3; ++k)
  {
    const LatticePoint& point = this->At(sx * corners[2 * k], sy * corners[2 * k + 1]);
    result.Index[k] = point.Index;
    result.Weight[k] = static_cast<float>(weights[k] / sum);
    result.VertexFlipped[k] = point.Flipped != negated;
    if (weights[k] > weights[largest])
    {
      largest = k;
    }
  }
  result.Flipped = result.VertexFlipped[largest];
  return result;
}

} // namespace vlf
} // namespace mesolight
