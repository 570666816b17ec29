// SPDX-License-Identifier: BSD-3-Clause
// TextureProportions: how many times as tall as wide a flat surface draws a unit square of its
// texture coordinates, against the analytic value of rectangles, tiled, rotated and sheared
// coordinates; curved and degenerate input are told apart.
#include "TextureProportions.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
using glm::dvec2;
using glm::dvec3;

// A w x h rectangle in the z = 0 plane, facing +z, texture coordinates t(corner) at its corners
// (corners (0,0), (1,0), (1,1), (0,1) of the unit square scaled to w x h), as two triangles.
template <typename TCoord>
void AddRectangle(mesolight::TextureProportions& proportions, double w, double h, TCoord t)
{
  const dvec3 p[4] = { { 0, 0, 0 }, { w, 0, 0 }, { w, h, 0 }, { 0, h, 0 } };
  const dvec2 c[4] = { t(dvec2(0, 0)), t(dvec2(1, 0)), t(dvec2(1, 1)), t(dvec2(0, 1)) };
  proportions.AddTriangle(p[0], p[1], p[2], c[0], c[1], c[2]);
  proportions.AddTriangle(p[0], p[2], p[3], c[0], c[2], c[3]);
}

dvec2 Unit(dvec2 c)
{
  return c;
}
} // namespace

TEST(TextureProportions, UnitCoordinatesOnARectangleGiveItsProportions)
{
  for (double h : { 1.0, 0.5, 2.0, 1e-3, 1e3 })
  {
    mesolight::TextureProportions proportions;
    AddRectangle(proportions, 1.0, h, Unit);
    EXPECT_TRUE(proportions.IsFlat());
    EXPECT_NEAR(proportions.GetHeightOverWidth(), h, 1e-12 * h);
    EXPECT_NEAR(proportions.GetArea(), h, 1e-12 * h);
  }
}

TEST(TextureProportions, TiledRotatedAndShearedCoordinates)
{
  // A 4 x 1 wall tiled four times along u: each tile is square.
  mesolight::TextureProportions tiled;
  AddRectangle(tiled, 4.0, 1.0, [](dvec2 c) { return dvec2(4.0 * c.x, c.y); });
  EXPECT_NEAR(tiled.GetHeightOverWidth(), 1.0, 1e-12);

  // Coordinates turned a quarter on a 2 x 1 rectangle: u runs up it (1 long), v across it (2
  // long), so a unit square of the texture is drawn twice as tall (along v) as wide.
  mesolight::TextureProportions turned;
  AddRectangle(turned, 2.0, 1.0, [](dvec2 c) { return dvec2(c.y, 1.0 - c.x); });
  EXPECT_NEAR(turned.GetHeightOverWidth(), 2.0, 1e-12);

  // Sheared coordinates u = x + y, v = y on a unit square: dP/du = (1, 0), dP/dv = (-1, 1).
  mesolight::TextureProportions sheared;
  AddRectangle(sheared, 1.0, 1.0, [](dvec2 c) { return dvec2(c.x + c.y, c.y); });
  EXPECT_NEAR(sheared.GetHeightOverWidth(), std::sqrt(2.0), 1e-12);

  // Mirrored coordinates (v = 1 - y) keep the proportions.
  mesolight::TextureProportions mirrored;
  AddRectangle(mirrored, 3.0, 1.0, [](dvec2 c) { return dvec2(c.x, 1.0 - c.y); });
  EXPECT_NEAR(mirrored.GetHeightOverWidth(), 1.0 / 3.0, 1e-12);
  EXPECT_TRUE(mirrored.IsFlat());
}

TEST(TextureProportions, CurvedSurfacesAreNotFlat)
{
  // A half cylinder of 32 facets, u around it and v along it.
  mesolight::TextureProportions cylinder;
  const int n = 32;
  const double pi = std::acos(-1.0);
  for (int i = 0; i < n; ++i)
  {
    const double a0 = pi * i / n, a1 = pi * (i + 1) / n;
    const dvec3 p00(std::cos(a0), 0, std::sin(a0)), p10(std::cos(a1), 0, std::sin(a1));
    const dvec3 p01 = p00 + dvec3(0, 1, 0), p11 = p10 + dvec3(0, 1, 0);
    const dvec2 t00(double(i) / n, 0), t10(double(i + 1) / n, 0);
    const dvec2 t01 = t00 + dvec2(0, 1), t11 = t10 + dvec2(0, 1);
    cylinder.AddTriangle(p00, p10, p11, t00, t10, t11);
    cylinder.AddTriangle(p00, p11, p01, t00, t11, t01);
  }
  EXPECT_GT(cylinder.GetArea(), 0.0);
  EXPECT_FALSE(cylinder.IsFlat());
  // Two facets 3 degrees apart are not flat either; 0.5 degree apart they are.
  for (double degrees : { 3.0, 0.5 })
  {
    const double a = degrees * pi / 180.0;
    mesolight::TextureProportions hinge;
    const dvec3 tilted(std::cos(a), 0, std::sin(a));
    hinge.AddTriangle(
      dvec3(0, 0, 0), dvec3(-1, 0, 0), dvec3(0, 1, 0), dvec2(0.5, 0), dvec2(0, 0), dvec2(0.5, 1));
    hinge.AddTriangle(
      dvec3(0, 0, 0), dvec3(0, 1, 0), tilted, dvec2(0.5, 0), dvec2(0.5, 1), dvec2(1, 0));
    EXPECT_EQ(hinge.IsFlat(), degrees < 1.0) << degrees << " degrees";
  }
}

TEST(TextureProportions, DegenerateAndNonFiniteTrianglesAreSkipped)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  mesolight::TextureProportions proportions;
  // Zero world area, coordinates on a line, repeated coordinates, NaN coordinates and points.
  proportions.AddTriangle(
    dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(2, 0, 0), dvec2(0, 0), dvec2(1, 0), dvec2(0, 1));
  proportions.AddTriangle(
    dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), dvec2(0, 0), dvec2(1, 1), dvec2(2, 2));
  proportions.AddTriangle(dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), dvec2(0.3, 0.3),
    dvec2(0.3, 0.3), dvec2(0.3, 0.3));
  proportions.AddTriangle(
    dvec3(0, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), dvec2(nan, 0), dvec2(1, 0), dvec2(0, 1));
  proportions.AddTriangle(
    dvec3(nan, 0, 0), dvec3(1, 0, 0), dvec3(0, 1, 0), dvec2(0, 0), dvec2(1, 0), dvec2(0, 1));
  EXPECT_EQ(proportions.GetArea(), 0.0);
  EXPECT_FALSE(proportions.IsFlat());
  EXPECT_EQ(proportions.GetHeightOverWidth(), 0.0);
  // They do not spoil a good triangle beside them.
  proportions.AddTriangle(
    dvec3(0, 0, 0), dvec3(2, 0, 0), dvec3(0, 1, 0), dvec2(0, 0), dvec2(1, 0), dvec2(0, 1));
  EXPECT_TRUE(proportions.IsFlat());
  EXPECT_NEAR(proportions.GetHeightOverWidth(), 0.5, 1e-12);
}
