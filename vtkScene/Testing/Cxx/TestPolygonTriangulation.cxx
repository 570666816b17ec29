// SPDX-License-Identifier: BSD-3-Clause
// Tests of TriangulatePolygon: concave faces covered exactly (the fan filled an L-shaped roof's
// notch with overlapping triangles), corners on straight edges give no zero-area triangles,
// convex polygons keep the fan's diagonals, the winding follows the polygon's, and zero-area or
// self-intersecting polygons end without a crash.
#include "PolygonTriangulation.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

namespace
{
using mesolight::TriangulatePolygon;

glm::vec3 Normal(const std::vector<glm::vec3>& p, const glm::uvec3& t)
{
  return glm::cross(p[t[1]] - p[t[0]], p[t[2]] - p[t[0]]);
}

// Sum of the triangles' areas, each counted positive; with `winding`, every triangle must face
// the same way as it.
double CoveredArea(const std::vector<glm::vec3>& p, const std::vector<glm::uvec3>& triangles,
  const glm::vec3& winding)
{
  double area = 0.0;
  for (const glm::uvec3& t : triangles)
  {
    const glm::vec3 n = Normal(p, t);
    EXPECT_GT(glm::dot(n, winding), 0.0f) << t[0] << " " << t[1] << " " << t[2];
    area += 0.5 * glm::length(n);
  }
  return area;
}

bool Covers(
  const std::vector<glm::vec3>& p, const std::vector<glm::uvec3>& triangles, const glm::vec3& point)
{
  for (const glm::uvec3& t : triangles)
  {
    const glm::vec3 n = Normal(p, t);
    bool inside = true;
    for (int e = 0; e < 3; ++e)
    {
      inside =
        inside && glm::dot(glm::cross(p[t[(e + 1) % 3]] - p[t[e]], point - p[t[e]]), n) > 0.0f;
    }
    if (inside)
    {
      return true;
    }
  }
  return false;
}

// The fan (0, k, k + 1): what faces were before.
std::vector<glm::uvec3> Fan(std::size_t n)
{
  std::vector<glm::uvec3> fan;
  for (unsigned k = 1; k + 1 < n; ++k)
  {
    fan.emplace_back(0u, k, k + 1);
  }
  return fan;
}
} // namespace

TEST(PolygonTriangulation, ConcaveLShapeIsCoveredExactly)
{
  // An L-shaped roof (area 3) started at a corner that does not see the whole L, in the xz plane
  // wound so that it faces -y, as an exported building footprint can be.
  const std::vector<glm::vec3> l = { { 2, 5, 0 }, { 2, 5, 1 }, { 1, 5, 1 }, { 1, 5, 2 },
    { 0, 5, 2 }, { 0, 5, 0 } };
  const glm::vec3 winding(0, -1, 0);
  const std::vector<glm::uvec3> triangles = TriangulatePolygon(l);
  EXPECT_EQ(triangles.size(), 4u);
  EXPECT_NEAR(CoveredArea(l, triangles, winding), 3.0, 1e-6);
  EXPECT_FALSE(Covers(l, triangles, { 1.2f, 5, 1.3f })); // the notch
  EXPECT_TRUE(Covers(l, triangles, { 0.3f, 5, 1.6f }));
  // The fan fills the notch: the check above can fail.
  EXPECT_TRUE(Covers(l, Fan(l.size()), { 1.2f, 5, 1.3f }));
}

TEST(PolygonTriangulation, CornersOnStraightEdgesGiveNoZeroAreaTriangles)
{
  // A square with its edges' midpoints (shared with neighbouring faces): the fan made two
  // zero-area triangles, which the scene check then reported as the user's degenerate faces.
  const std::vector<glm::vec3> square = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 2, 1, 0 },
    { 2, 2, 0 }, { 1, 2, 0 }, { 0, 2, 0 }, { 0, 1, 0 } };
  const std::vector<glm::uvec3> triangles = TriangulatePolygon(square);
  EXPECT_EQ(triangles.size(), 6u);
  for (const glm::uvec3& t : triangles)
  {
    EXPECT_GT(glm::length(Normal(square, t)), 1e-3f);
  }
  EXPECT_NEAR(CoveredArea(square, triangles, { 0, 0, 1 }), 4.0, 1e-6);
  bool fanHasZeroArea = false;
  for (const glm::uvec3& t : Fan(square.size()))
  {
    fanHasZeroArea = fanHasZeroArea || glm::length(Normal(square, t)) < 1e-6f;
  }
  EXPECT_TRUE(fanHasZeroArea);
}

TEST(PolygonTriangulation, ConvexPolygonsKeepTheFan)
{
  // A slightly non-planar quad (the Cornell box's walls are): the same diagonal as before.
  const std::vector<glm::vec3> quad = { { 552.8f, 0, 0 }, { 0, 0, 0 }, { 0, 0, 559.2f },
    { 549.6f, 0.5f, 559.2f } };
  EXPECT_EQ(TriangulatePolygon(quad), Fan(quad.size()));
  std::vector<glm::vec3> hexagon;
  for (int k = 0; k < 6; ++k)
  {
    const float a = static_cast<float>(k) * 1.0471976f;
    hexagon.emplace_back(std::cos(a), 0.0f, -std::sin(a)); // clockwise seen from +y
  }
  EXPECT_EQ(TriangulatePolygon(hexagon), Fan(hexagon.size()));
  EXPECT_EQ(TriangulatePolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }), Fan(3));
}

TEST(PolygonTriangulation, DegenerateAndSelfIntersectingPolygonsEnd)
{
  EXPECT_TRUE(TriangulatePolygon({ { 0, 0, 0 }, { 1, 0, 0 } }).empty());
  // All corners on one line: nothing to cover.
  EXPECT_TRUE(TriangulatePolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 }, { 3, 0, 0 } }).empty());
  // A bow tie has no ear everywhere; it ends with triangles over its corners.
  const std::vector<glm::vec3> bowTie = { { 0, 0, 0 }, { 2, 2, 0 }, { 2, 0, 0 }, { 0, 2, 0 } };
  for (const glm::uvec3& t : TriangulatePolygon(bowTie))
  {
    EXPECT_LT(t[0], 4u);
    EXPECT_LT(t[1], 4u);
    EXPECT_LT(t[2], 4u);
  }
  // A corner that is not finite keeps the fan, for the scene check to name the vertex (the
  // polygon must not vanish without a word).
  EXPECT_EQ(
    TriangulatePolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { std::nanf(""), 1, 0 }, { 0, 1, 0 } }), Fan(4));
  // Repeated corners (a face that visits a vertex twice) end too.
  EXPECT_LE(
    TriangulatePolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }).size(),
    3u);
}

TEST(PolygonTriangulation, LargeFacesStayCheap)
{
  // A concave star of 1000 corners (radius 1 and 0.5 alternately) is ear-clipped exactly: its
  // area is 1000 triangles of the two radii's half-angle wedge.
  std::vector<glm::vec3> star;
  const int corners = 1000;
  for (int k = 0; k < corners; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * k / corners;
    const double r = k % 2 ? 0.5 : 1.0;
    star.emplace_back(static_cast<float>(r * std::cos(a)), static_cast<float>(r * std::sin(a)), 0);
  }
  const double wedge = 0.5 * 1.0 * 0.5 * std::sin(2.0 * 3.14159265358979 / corners);
  const std::vector<glm::uvec3> triangles = TriangulatePolygon(star);
  EXPECT_EQ(triangles.size(), static_cast<std::size_t>(corners - 2));
  EXPECT_NEAR(CoveredArea(star, triangles, { 0, 0, 1 }), corners * wedge, 1e-4);
  // Beyond MaximumEarClippedCorners the fan is kept.
  std::vector<glm::vec3> circle;
  for (std::size_t k = 0; k < mesolight::MaximumEarClippedCorners + 1; ++k)
  {
    const double a = 2.0 * 3.14159265358979 * static_cast<double>(k) /
      static_cast<double>(mesolight::MaximumEarClippedCorners + 1);
    circle.emplace_back(static_cast<float>(std::cos(a)), static_cast<float>(std::sin(a)), 0);
  }
  EXPECT_EQ(TriangulatePolygon(circle), Fan(circle.size()));
}
