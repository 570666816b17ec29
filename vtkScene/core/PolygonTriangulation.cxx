// SPDX-License-Identifier: BSD-3-Clause
#include "PolygonTriangulation.h"

#include <glm/geometric.hpp>
#include <glm/vec2.hpp>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>

namespace mesolight
{

namespace
{
double Cross(const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// Whether p lies inside or on the counter-clockwise triangle abc.
bool InsideOrOn(const glm::dvec2& p, const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& c)
{
  return Cross(a, b, p) >= 0.0 && Cross(b, c, p) >= 0.0 && Cross(c, a, p) >= 0.0;
}
} // namespace

std::vector<glm::uvec3> TriangulatePolygon(const std::vector<glm::vec3>& corners)
{
  const std::size_t n = corners.size();
  std::vector<glm::uvec3> triangles;
  if (n < 3)
  {
    return triangles;
  }
  // Three corners, or a corner that is not finite: the fan, so that the scene check reports the
  // vertex instead of the face vanishing here without a word.
  const bool finite = std::all_of(corners.begin(), corners.end(),
    [](const glm::vec3& p)
    { return std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z); });
  if (n == 3 || !finite)
  {
    for (std::uint32_t k = 1; k + 1 < n; ++k)
    {
      triangles.emplace_back(0u, k, k + 1);
    }
    return triangles;
  }
  // Newell's normal picks the projection plane (drop its largest axis) and the winding.
  glm::dvec3 normal(0.0);
  for (std::size_t i = 0; i < n; ++i)
  {
    const glm::dvec3 p(corners[i]), q(corners[(i + 1) % n]);
    normal +=
      glm::dvec3((p.y - q.y) * (p.z + q.z), (p.z - q.z) * (p.x + q.x), (p.x - q.x) * (p.y + q.y));
  }
  const glm::dvec3 magnitude = glm::abs(normal);
  const int drop = magnitude.x >= magnitude.y && magnitude.x >= magnitude.z ? 0
    : magnitude.y >= magnitude.z                                            ? 1
                                                                            : 2;
  const int u = (drop + 1) % 3, v = (drop + 2) % 3;
  const double sign = normal[drop] >= 0.0 ? 1.0 : -1.0; // counter-clockwise in (u, v) when +
  std::vector<glm::dvec2> points(n);
  double size = 0.0;
  for (std::size_t i = 0; i < n; ++i)
  {
    points[i] = glm::dvec2(corners[i][u], sign * corners[i][v]);
    size = std::max({ size, std::abs(points[i].x), std::abs(points[i].y) });
  }
  // Float coordinates place a corner on a straight edge only to within a few roundings of the
  // largest coordinate: a turn (twice the area of abc) within that of zero is straight.
  const double rounding = 8.0 * std::numeric_limits<float>::epsilon() * size;
  const auto straight = [&](std::uint32_t a, std::uint32_t b, std::uint32_t c)
  {
    const double turn = Cross(points[a], points[b], points[c]);
    return !(
      turn > rounding * (glm::length(points[b] - points[a]) + glm::length(points[c] - points[b])));
  };

  std::vector<std::uint32_t> left(n);
  for (std::size_t i = 0; i < n; ++i)
  {
    left[i] = static_cast<std::uint32_t>(i);
  }
  // Tips tried from the second corner on, and after each clip from where it was, so a convex
  // polygon gets the fan it always got (0, k, k + 1) (the same diagonals, which matters for a
  // slightly non-planar quad) in one pass. Beyond MaximumEarClippedCorners the fan is kept: ear
  // clipping's cost grows as the cube of the corners in the worst case.
  std::size_t start = n > MaximumEarClippedCorners ? n : 1;
  while (left.size() > 3 && start < left.size())
  {
    const std::size_t m = left.size();
    bool clipped = false;
    for (std::size_t j = 0; j < m && !clipped; ++j)
    {
      const std::size_t i = (start + j) % m;
      const std::uint32_t a = left[(i + m - 1) % m], b = left[i], c = left[(i + 1) % m];
      if (straight(a, b, c))
      {
        continue; // reflex or straight
      }
      bool empty = true;
      for (std::size_t k = 0; k < m && empty; ++k)
      {
        const std::uint32_t p = left[k];
        if (p == a || p == b || p == c || points[p] == points[a] || points[p] == points[b] ||
          points[p] == points[c])
        {
          continue;
        }
        empty = !InsideOrOn(points[p], points[a], points[b], points[c]);
      }
      if (empty)
      {
        triangles.emplace_back(a, b, c);
        left.erase(left.begin() + static_cast<std::ptrdiff_t>(i));
        start = i < left.size() ? i : 0;
        clipped = true;
      }
    }
    if (!clipped)
    {
      break;
    }
  }
  // Three corners left, or no ear (all straight: nothing left to cover; self-intersecting: the
  // remainder is fanned as any polygon was before).
  double remainder = 0.0, perimeter = 0.0;
  for (std::size_t k = 0; k < left.size(); ++k)
  {
    const std::uint32_t p = left[k], q = left[(k + 1) % left.size()];
    remainder += Cross(points[left[0]], points[p], points[q]);
    perimeter += glm::length(points[q] - points[p]);
  }
  if (std::abs(remainder) > rounding * perimeter)
  {
    for (std::size_t k = 1; k + 1 < left.size(); ++k)
    {
      triangles.emplace_back(left[0], left[k], left[k + 1]);
    }
  }
  return triangles;
}

} // namespace mesolight
