// SPDX-License-Identifier: BSD-3-Clause
// The per-vertex quadrics of relief mapping on curved meshes (Oliveira & Policarpo 2005, "An
// efficient representation for surface details") against analytic surfaces: a cylinder and a
// sphere have known normal curvature along the texture axes, a plane has none.
#include "SurfaceQuadrics.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <cmath>
#include <functional>

namespace
{
using namespace mesolight;

struct Mesh
{
  std::vector<glm::dvec3> Positions, Normals;
  std::vector<glm::dvec2> TCoords;
  std::vector<std::array<long long, 3>> Triangles;
};

// An n x n grid over [0, 1]^2 in texture coordinates, mapped by surface(u, v, normal).
Mesh Grid(int n, const std::function<glm::dvec3(double, double, glm::dvec3&)>& surface)
{
  Mesh m;
  for (int j = 0; j <= n; ++j)
  {
    for (int i = 0; i <= n; ++i)
    {
      const double u = double(i) / n, v = double(j) / n;
      glm::dvec3 normal;
      m.Positions.push_back(surface(u, v, normal));
      m.Normals.push_back(normal);
      m.TCoords.emplace_back(u, v);
    }
  }
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const long long a = j * (n + 1) + i, b = a + 1, c = a + n + 1, d = c + 1;
      m.Triangles.push_back({ a, b, d });
      m.Triangles.push_back({ a, d, c });
    }
  }
  return m;
}

constexpr double Pi = 3.14159265358979323846;

// The geometry image cylinder (docs/geometry-images.md): 120 degrees, arc length 1 across u.
glm::dvec3 Cylinder(double u, double v, glm::dvec3& n, double scale = 1.0)
{
  const double span = 2.0 * Pi / 3.0, r = scale / span, phi = (u - 0.5) * span;
  n = glm::dvec3(std::sin(phi), 0.0, std::cos(phi));
  return glm::dvec3(r * std::sin(phi), scale * v, r * std::cos(phi));
}

std::vector<glm::vec2> Quadrics(const Mesh& m)
{
  return ComputeSurfaceQuadrics(m.Positions, m.Normals, m.TCoords, m.Triangles);
}
} // namespace

TEST(SurfaceQuadrics, PlaneIsExactlyFlat)
{
  // A tilted plane, so rounding is not trivially zero.
  const glm::dvec3 nrm = glm::normalize(glm::dvec3(0.3, -0.2, 1.0));
  const glm::dvec3 t = glm::normalize(glm::cross(glm::dvec3(0.0, 1.0, 0.0), nrm));
  const glm::dvec3 b = glm::cross(nrm, t);
  const Mesh m = Grid(16,
    [&](double u, double v, glm::dvec3& n)
    {
      n = nrm;
      return glm::dvec3(0.1, 0.7, -0.3) + 1.7 * u * t + 0.9 * v * b;
    });
  const std::vector<glm::vec2> q = Quadrics(m);
  for (const glm::vec2& c : q)
  {
    ASSERT_EQ(c.x, 0.0f);
    ASSERT_EQ(c.y, 0.0f);
  }
  EXPECT_FALSE(AnySurfaceQuadric(q));
}

TEST(SurfaceQuadrics, CylinderCurvesAlongUOnly)
{
  // Depth below the tangent plane at offset du: kappa (s du)^2 / 2, kappa = 1 / r, s = 1 (arc
  // length 1 across): a' = kappa s / 2 = span / 2 everywhere, b' = 0 (the axis is straight).
  const double expected = 0.5 * (2.0 * Pi / 3.0);
  for (double scale : { 1.0, 40.0 })
  {
    const Mesh m =
      Grid(32, [&](double u, double v, glm::dvec3& n) { return Cylinder(u, v, n, scale); });
    const std::vector<glm::vec2> q = Quadrics(m);
    EXPECT_TRUE(AnySurfaceQuadric(q));
    for (size_t k = 0; k < q.size(); ++k)
    {
      ASSERT_NEAR(q[k].x, expected, 1e-3 * expected) << "vertex " << k << ", scale " << scale;
      ASSERT_NEAR(q[k].y, 0.0, 1e-5) << "vertex " << k;
    }
  }
}

TEST(SurfaceQuadrics, SphereCurvesAlongBothAxes)
{
  // A sphere patch of radius r parameterized by longitude (u) and latitude (v), 90 degrees each:
  // s_u = r cos(theta) span, s_v = r span; every normal curvature is 1 / r, so
  // a' = s_u / (2 r) and b' = s_v^2 / (2 r s_u).
  const double span = 0.5 * Pi, r = 1.0 / span;
  const Mesh m = Grid(32,
    [&](double u, double v, glm::dvec3& n)
    {
      const double phi = (u - 0.5) * span, theta = (v - 0.5) * span;
      n = glm::dvec3(
        std::cos(theta) * std::sin(phi), std::sin(theta), std::cos(theta) * std::cos(phi));
      return r * n;
    });
  const std::vector<glm::vec2> q = Quadrics(m);
  for (size_t k = 0; k < q.size(); ++k)
  {
    const double theta = (m.TCoords[k].y - 0.5) * span;
    const double su = r * std::cos(theta) * span, sv = r * span;
    const double a = su / (2.0 * r), b = sv * sv / (2.0 * r * su);
    // The lines of latitude are not geodesics and s_u changes with v: the one-ring sees slightly
    // different depths than the exact normal curvature (1% inside; 2% at the border, whose
    // one-sided rings see s_u change on one side only).
    const bool border = m.TCoords[k].x == 0.0 || m.TCoords[k].x == 1.0 || m.TCoords[k].y == 0.0 ||
      m.TCoords[k].y == 1.0;
    const double tolerance = border ? 0.02 : 0.01;
    ASSERT_NEAR(q[k].x, a, tolerance * a) << "vertex " << k;
    ASSERT_NEAR(q[k].y, b, tolerance * b) << "vertex " << k;
  }
}

TEST(SurfaceQuadrics, ConcaveSideIsNegative)
{
  // The same cylinder seen from inside (normals reversed): the surface bends toward the normal.
  Mesh m = Grid(16, [](double u, double v, glm::dvec3& n) { return Cylinder(u, v, n); });
  for (glm::dvec3& n : m.Normals)
  {
    n = -n;
  }
  const std::vector<glm::vec2> q = Quadrics(m);
  for (const glm::vec2& c : q)
  {
    ASSERT_LT(c.x, 0.0f);
  }
}

TEST(SurfaceQuadrics, BadInputThrows)
{
  Mesh m = Grid(2, [](double u, double v, glm::dvec3& n) { return Cylinder(u, v, n); });
  Mesh fewNormals = m;
  fewNormals.Normals.pop_back();
  EXPECT_THROW(Quadrics(fewNormals), SurfaceQuadricsError);
  Mesh badIndex = m;
  badIndex.Triangles.push_back({ 0, 1, 99 });
  try
  {
    Quadrics(badIndex);
    FAIL() << "no error";
  }
  catch (const SurfaceQuadricsError& e)
  {
    EXPECT_NE(std::string(e.what()).find("vertex 99 of 9"), std::string::npos) << e.what();
  }
  // Unused vertices and an empty mesh are not errors: they get 0.
  EXPECT_TRUE(ComputeSurfaceQuadrics({}, {}, {}, {}).empty());
}
