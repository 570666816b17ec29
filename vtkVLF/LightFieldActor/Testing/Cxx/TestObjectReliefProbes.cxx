// SPDX-License-Identifier: BSD-3-Clause
// ObjectReliefProbes: a textured movable object split into charts, and the SH9 probes of each
// chart against the field's own incident irradiance at the surface point under the probe
// (FieldIrradiance's IncidentRadianceSamples and IncidentIrradiance, the exact sum over the
// field's directions, at a point computed here from the cube's faces, not from the
// rasterization), for the surface normal and tilted normals. Negative cases: probes gathered at
// another placement, and the emitters' own radiance counted, fail the same threshold.
#include "EnvironmentMaps.h"
#include "FieldIrradiance.h"
#include "LightField.h"
#include "ObjectMesh.h"
#include "ObjectReliefProbes.h"
#include "WalkthroughTestFields.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <limits>
#include <string>
#include <vector>

using namespace mesolight;
using namespace mesolight::vlf;

namespace
{
// A 120 mm cube in the Cornell box, turned 30 degrees about the vertical, above the tall block,
// its top 90 mm below the ceiling and in the light's view.
constexpr float Side = 120.0f;

glm::mat4 Placement(const LightField& field, const glm::vec3& centre = { 300.0f, 400.0f, 250.0f })
{
  return WorldToUnitSphere(field) * glm::translate(glm::mat4(1.0f), centre) *
    glm::rotate(glm::mat4(1.0f), glm::radians(30.0f), glm::vec3(0, 1, 0)) *
    glm::scale(glm::mat4(1.0f), glm::vec3(Side));
}

// The surface point of the unit cube's face (axis, sign) at texture coordinates (u, v), and its
// normal, derived from the face's axes (u x v = n), independently of the probes' rasterization.
void FacePoint(int axis, int sign, float u, float v, glm::vec3& point, glm::vec3& normal)
{
  glm::vec3 n(0.0f), a(0.0f), b(0.0f);
  n[axis] = static_cast<float>(sign);
  a[(axis + 1) % 3] = 1.0f;
  b[(axis + 2) % 3] = 1.0f;
  if (glm::dot(glm::cross(a, b), n) < 0.0f)
  {
    std::swap(a, b);
  }
  point = 0.5f * n + (u - 0.5f) * a + (v - 0.5f) * b;
  normal = n;
}

glm::vec3 ShIrradiance(const SH9& sh, const glm::vec3& n)
{
  const double d[3] = { n.x, n.y, n.z };
  double e[3];
  IrradianceSH9(sh, d, e);
  return glm::vec3(static_cast<float>(e[0]), static_cast<float>(e[1]), static_cast<float>(e[2]));
}

// The normals a relief's perturbed normal takes: the surface's, and tilted 30 and 50 degrees.
std::vector<glm::vec3> TestNormals(const glm::vec3& n)
{
  const glm::vec3 helper = std::abs(n.y) < 0.9f ? glm::vec3(0, 1, 0) : glm::vec3(1, 0, 0);
  const glm::vec3 t = glm::normalize(glm::cross(helper, n));
  const glm::vec3 s = glm::cross(n, t);
  const float c30 = std::cos(glm::radians(30.0f)), s30 = std::sin(glm::radians(30.0f));
  const float c50 = std::cos(glm::radians(50.0f)), s50 = std::sin(glm::radians(50.0f));
  return { n, c30 * n + s30 * t, c30 * n - s30 * s, c50 * n + s50 * glm::normalize(t + s) };
}

struct Comparison
{
  double WorstRelative = 0.0; // |SH - exact| over the chart's mean exact irradiance, worst case
  int Compared = 0;
};

// Probes of the cube at `gathered` against the exact irradiance at `placement`; emission: the
// expectation counts the emitters' own radiance (a negative case).
Comparison Compare(const LightField& field, const ObjectReliefProbes& probes,
  const glm::mat4& placement, bool emission = false)
{
  Comparison result;
  const glm::mat3 normals = glm::transpose(glm::inverse(glm::mat3(placement)));
  for (std::size_t c = 0; c < probes.Charts().size(); ++c)
  {
    const ObjectChart& chart = probes.Charts()[c];
    // The face of this chart: its probes' model normal.
    const glm::vec3 faceNormal = chart.Normals[0];
    int axis = 0;
    for (int a = 1; a < 3; ++a)
    {
      axis = std::abs(faceNormal[a]) > std::abs(faceNormal[axis]) ? a : axis;
    }
    const int sign = faceNormal[axis] > 0.0f ? 1 : -1;
    struct Case
    {
      glm::vec3 Exact, Sh;
    };
    std::vector<Case> cases;
    double sum = 0.0;
    for (const auto& ij : { std::make_pair(1, 1), std::make_pair(4, 6), std::make_pair(6, 2) })
    {
      const float u = (ij.first + 0.5f) / chart.ProbesU, v = (ij.second + 0.5f) / chart.ProbesV;
      glm::vec3 point, normal;
      FacePoint(axis, sign, u, v, point, normal);
      const glm::vec3 p = glm::vec3(placement * glm::vec4(point, 1.0f));
      const glm::vec3 n = glm::normalize(normals * normal);
      IncidentOptions options;
      options.Emission = emission;
      std::vector<IncidentSample> samples = IncidentRadianceSamples(field, p + 1e-3f * n, options);
      for (IncidentSample& s : samples)
      {
        if (glm::dot(s.Direction, n) < 0.0f)
        {
          s.Radiance = glm::vec3(0.0f);
        }
      }
      const SH9& sh =
        probes.Probes()[c][static_cast<std::size_t>(ij.second * chart.ProbesU + ij.first)];
      for (const glm::vec3& m : TestNormals(n))
      {
        const Case k{ IncidentIrradiance(samples, m), ShIrradiance(sh, m) };
        sum += k.Exact.x + k.Exact.y + k.Exact.z;
        cases.push_back(k);
      }
    }
    const double mean = sum / static_cast<double>(cases.size());
    for (const Case& k : cases)
    {
      const glm::vec3 d = glm::abs(k.Sh - k.Exact);
      result.WorstRelative =
        std::max(result.WorstRelative, (d.x + d.y + d.z) / std::max(mean, 1e-9));
      ++result.Compared;
    }
  }
  return result;
}
} // namespace

TEST(ObjectReliefProbesCore, CubeChartsAreItsFacesWithProbesOnThem)
{
  const ObjectMesh cube = MakeCube(1.0f);
  ASSERT_EQ(cube.TextureCoordinates.size(), cube.Positions.size());
  const std::vector<ObjectChart> charts = SplitIntoCharts(cube, 8, 8);
  ASSERT_EQ(charts.size(), 6u);
  for (const ObjectChart& chart : charts)
  {
    EXPECT_EQ(chart.Triangles.size(), 2u);
    EXPECT_EQ(chart.OverlappingProbes, 0u);
    ASSERT_EQ(chart.Positions.size(), 64u);
    const glm::vec3 n = chart.Normals[0];
    int axis = 0;
    for (int a = 1; a < 3; ++a)
    {
      axis = std::abs(n[a]) > std::abs(n[axis]) ? a : axis;
    }
    for (int j = 0; j < 8; ++j)
    {
      for (int i = 0; i < 8; ++i)
      {
        const std::size_t q = static_cast<std::size_t>(j * 8 + i);
        EXPECT_EQ(chart.Inside[q], 1) << "the face covers the whole texture square";
        glm::vec3 point, normal;
        FacePoint(
          axis, n[axis] > 0.0f ? 1 : -1, (i + 0.5f) / 8.0f, (j + 0.5f) / 8.0f, point, normal);
        EXPECT_LT(glm::length(chart.Positions[q] - point), 1e-5f) << "probe " << i << "," << j;
        EXPECT_LT(glm::length(chart.Normals[q] - normal), 1e-5f);
      }
    }
  }
}

TEST(ObjectReliefProbesCore, OverlappingTextureIsSplitIntoPlanarCharts)
{
  // Two quads sharing an edge (and its points), folded at 90 degrees, both mapping [0,1]^2: one
  // connected piece whose texture overlaps itself, so two charts.
  ObjectMesh book;
  book.Positions = { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 0, 1 }, { 0, 1, 1 } };
  book.TextureCoordinates = { { 0, 0 }, { 0, 1 }, { 1, 0 }, { 1, 1 }, { 1, 0 }, { 1, 1 } };
  book.Triangles = { { 0, 2, 3 }, { 0, 3, 1 }, { 0, 1, 5 }, { 0, 5, 4 } };
  const std::vector<ObjectChart> charts = SplitIntoCharts(book, 4, 4);
  ASSERT_EQ(charts.size(), 2u);
  for (const ObjectChart& chart : charts)
  {
    EXPECT_EQ(chart.Triangles.size(), 2u);
    EXPECT_EQ(chart.OverlappingProbes, 0u);
  }
  // A half-covered texture: probes outside take the nearest inside one's point.
  ObjectMesh half;
  half.Positions = { { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } };
  half.TextureCoordinates = { { 0, 0 }, { 1, 0 }, { 0, 1 } };
  half.Triangles = { { 0, 1, 2 } };
  const ObjectChart chart = SplitIntoCharts(half, 4, 4).at(0);
  EXPECT_EQ(chart.Inside[3 * 4 + 3], 0); // (3.5/4, 3.5/4) lies beyond the hypotenuse
  EXPECT_EQ(chart.Inside[0], 1);
  const glm::vec3 corner = chart.Positions[3 * 4 + 3];
  EXPECT_NEAR(corner.x + corner.y, 1.0f, 0.3f) << "the nearest probe inside, by the hypotenuse";
}

TEST(ObjectReliefProbesCore, BadInputIsRefused)
{
  ObjectMesh sphere = MakeSphere(0.5f, 8, 16);
  try
  {
    SplitIntoCharts(sphere, 8, 8);
    FAIL() << "a mesh without texture coordinates was accepted";
  }
  catch (const ObjectChartError& e)
  {
    EXPECT_NE(std::string(e.what()).find("texture coordinates"), std::string::npos) << e.what();
  }
  ObjectMesh cube = MakeCube(1.0f);
  EXPECT_THROW(SplitIntoCharts(cube, 0, 8), std::invalid_argument);
  cube.TextureCoordinates[3].x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(SplitIntoCharts(cube, 8, 8), ObjectChartError);
}

TEST(ObjectReliefProbesCore, ProbesMatchTheFieldsIrradianceAtTheSurface)
{
  const LightField& field = walkthroughtest::PlainCornellField(129);
  ObjectReliefProbes probes(field);
  probes.SetMesh(MakeCube(1.0f), 8);
  ASSERT_EQ(probes.Charts().size(), 6u);
  const glm::mat4 placement = Placement(field);
  EXPECT_EQ(probes.Gather(placement), 6u * 64u);
  const Comparison right = Compare(field, probes, placement);
  std::printf("SH9 probes against the exact irradiance: worst %.1f%% of the face's mean over %d "
              "cases\n",
    100.0 * right.WorstRelative, right.Compared);
  EXPECT_EQ(right.Compared, 6 * 3 * 4);
  // Nine coefficients hold a clamped cosine's irradiance to a few per cent (Ramamoorthi and
  // Hanrahan); the tilted normals see the surface's blocked half at its edge.
  EXPECT_LT(right.WorstRelative, 0.10);

  // Negative: the probes of another placement (the object moved, not regathered).
  ObjectReliefProbes moved(field);
  moved.SetMesh(MakeCube(1.0f), 8);
  moved.Gather(Placement(field, { 150.0f, 250.0f, 420.0f }));
  const Comparison stale = Compare(field, moved, placement);
  std::printf("probes of another placement: worst %.1f%%\n", 100.0 * stale.WorstRelative);
  EXPECT_GT(stale.WorstRelative, 0.10);
  // Negative: the emitters' own radiance belongs to the lights, not to the probes.
  const Comparison emitters = Compare(field, probes, placement, true);
  std::printf(
    "against an expectation with the emitters: worst %.1f%%\n", 100.0 * emitters.WorstRelative);
  EXPECT_GT(emitters.WorstRelative, 0.10);
}

TEST(ObjectReliefProbesCore, BackOfTheSurfaceIsBlocked)
{
  // The field does not know the object: the whole sphere's projection (FieldIrradiance as a
  // static wall's probes use it) lets the light behind a face through the object, which tilted
  // normals then receive. The probes leave it out; the whole-sphere projection is off.
  const LightField& field = walkthroughtest::PlainCornellField(129);
  const glm::mat4 placement = Placement(field);
  const glm::mat3 normals = glm::transpose(glm::inverse(glm::mat3(placement)));
  double worstProbe = 0.0, worstSphere = 0.0;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (const int sign : { -1, 1 })
    {
      glm::vec3 point, normal;
      FacePoint(axis, sign, 0.5f, 0.5f, point, normal);
      const glm::vec3 n = glm::normalize(normals * normal);
      const glm::vec3 p = glm::vec3(placement * glm::vec4(point, 1.0f)) + 1e-3f * n;
      IncidentOptions options;
      options.Emission = false;
      const std::vector<IncidentSample> all = IncidentRadianceSamples(field, p, options);
      std::vector<IncidentSample> front = all;
      for (IncidentSample& s : front)
      {
        s.Radiance = glm::dot(s.Direction, n) < 0.0f ? glm::vec3(0.0f) : s.Radiance;
      }
      const SH9 probe = ProbeRadianceSH9(field, p, n);
      const SH9 sphere = ProjectIncidentSH9(all);
      const glm::vec3 m = TestNormals(n)[3]; // tilted 50 degrees
      const glm::vec3 exact = IncidentIrradiance(front, m);
      const double scale = std::max(1e-9, static_cast<double>(exact.x + exact.y + exact.z));
      const glm::vec3 a = glm::abs(ShIrradiance(probe, m) - exact);
      const glm::vec3 b = glm::abs(ShIrradiance(sphere, m) - exact);
      worstProbe = std::max(worstProbe, (a.x + a.y + a.z) / scale);
      worstSphere = std::max(worstSphere, (b.x + b.y + b.z) / scale);
    }
  }
  std::printf("at normals tilted 50 degrees: probes %.1f%%, whole-sphere projection %.1f%%\n",
    100.0 * worstProbe, 100.0 * worstSphere);
  EXPECT_LT(worstProbe, 0.10);
  EXPECT_GT(worstSphere, 0.10);
}

TEST(ObjectReliefProbesCore, ConcaveObjectBlocksItsOwnLight)
{
  // An L: a floor quad A (z = 0, facing +z) and a wall quad B (x = 0, facing +x) along its edge,
  // 150 mm a side, turned so that A faces up and B the box's right wall: B stands between A's
  // points near the fold and the ceiling light. The expectation blocks the directions whose ray
  // from the point meets B, found here by the ray against B's plane in model coordinates; the
  // probes find them by rays against the object's mesh. Without the object's occlusion the
  // probes see the light through B.
  ObjectMesh ell;
  ell.Positions = { { 0, 0, 0 }, { 0, 1, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 0, 1 }, { 0, 1, 1 } };
  ell.TextureCoordinates = { { 0, 0 }, { 0, 1 }, { 1, 0 }, { 1, 1 }, { 1, 0 }, { 1, 1 } };
  ell.Triangles = { { 0, 2, 3 }, { 0, 3, 1 }, { 0, 1, 5 }, { 0, 5, 4 } };
  const LightField& field = walkthroughtest::PlainCornellField(129);
  const glm::mat4 model = glm::translate(glm::mat4(1.0f), glm::vec3(330.0f, 380.0f, 200.0f)) *
    glm::rotate(glm::mat4(1.0f), glm::radians(-90.0f), glm::vec3(1, 0, 0)) *
    glm::scale(glm::mat4(1.0f), glm::vec3(150.0f));
  const glm::mat4 placement = WorldToUnitSphere(field) * model;
  ObjectReliefProbes probes(field);
  probes.SetMesh(ell, 8);
  ASSERT_EQ(probes.Charts().size(), 2u);
  ReliefProbeSettings settings;
  probes.Gather(placement, settings);
  ObjectReliefProbes open(field);
  open.SetMesh(ell, 8);
  settings.ObjectOcclusion = false;
  open.Gather(placement, settings);
  // The chart of A: its probes face model +z.
  const std::size_t a = probes.Charts()[0].Normals[0].z > 0.5f ? 0 : 1;
  const glm::mat4 unitToModel = glm::inverse(placement);
  double worstBlocked = 0.0, worstOpen = 0.0;
  for (const int i : { 0, 1, 2 }) // the columns nearest the fold (u = x)
  {
    for (const int j : { 2, 5 })
    {
      const std::size_t q = static_cast<std::size_t>(j * 8 + i);
      const glm::vec3 point((i + 0.5f) / 8.0f, (j + 0.5f) / 8.0f, 0.0f);
      ASSERT_LT(glm::length(probes.Charts()[a].Positions[q] - point), 1e-5f);
      const glm::vec3 p = glm::vec3(placement * glm::vec4(point, 1.0f));
      const glm::vec3 n = probes.NormalOf(a, q);
      IncidentOptions options;
      options.Emission = false;
      std::vector<IncidentSample> samples = IncidentRadianceSamples(field, p + 1e-3f * n, options);
      std::size_t blocked = 0;
      for (IncidentSample& s : samples)
      {
        const glm::vec3 d = glm::vec3(unitToModel * glm::vec4(s.Direction, 0.0f));
        bool hitsWall = false;
        if (d.x < 0.0f)
        {
          const float t = -point.x / d.x;
          const glm::vec3 h = point + t * d;
          hitsWall = h.y >= 0.0f && h.y <= 1.0f && h.z >= 0.0f && h.z <= 1.0f;
        }
        // The points of the fold are shared, so the probes' normals (the mesh's, interpolated)
        // lean toward B: directions below A's own plane enter A and are blocked too.
        // (Directions in A's plane graze it: the probes' rays start just above it and pass.)
        hitsWall = hitsWall || glm::normalize(d).z < -1e-4f;
        if (glm::dot(s.Direction, n) < 0.0f || hitsWall)
        {
          blocked += hitsWall && glm::dot(s.Direction, n) >= 0.0f;
          s.Radiance = glm::vec3(0.0f);
        }
      }
      EXPECT_GT(blocked, 0u);
      // Through the same nine coefficients (their accuracy is the cube's test above), so that
      // only which directions the object blocks is compared.
      const glm::vec3 exact = ShIrradiance(ProjectIncidentSH9(samples), n);
      const double scale = std::max(1e-9, static_cast<double>(exact.x + exact.y + exact.z));
      const glm::vec3 withSelf = glm::abs(ShIrradiance(probes.Probes()[a][q], n) - exact);
      const glm::vec3 without = glm::abs(ShIrradiance(open.Probes()[a][q], n) - exact);
      worstBlocked = std::max(worstBlocked, (withSelf.x + withSelf.y + withSelf.z) / scale);
      worstOpen = std::max(worstOpen, (without.x + without.y + without.z) / scale);
    }
  }
  std::printf("an L's floor near its wall: probes %.1f%%, without the object's occlusion %.1f%%\n",
    100.0 * worstBlocked, 100.0 * worstOpen);
  EXPECT_LT(worstBlocked, 0.01);
  EXPECT_GT(worstOpen, 0.10);
}

TEST(ObjectReliefProbesCore, LineCacheGivesTheLookupsValues)
{
  const LightField& field = walkthroughtest::PlainCornellField(129);
  ObjectReliefProbes cached(field), looked(field);
  cached.SetMesh(MakeCube(1.0f), 8);
  looked.SetMesh(MakeCube(1.0f), 8);
  ReliefProbeSettings settings;
  settings.Threads = 1; // the figures printed below: one thread each, the same run
  auto start = std::chrono::steady_clock::now();
  cached.Gather(Placement(field), settings);
  const double cachedMs =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  settings.UseLineCache = false;
  start = std::chrono::steady_clock::now();
  looked.Gather(Placement(field), settings);
  const double lookupMs =
    std::chrono::duration<double, std::milli>(std::chrono::steady_clock::now() - start).count();
  std::printf("384 probes at %zu directions, one thread: line cache %.1f ms, lookup %.1f ms\n",
    field.SubfieldCount(), cachedMs, lookupMs);
  double largest = 0.0, worst = 0.0;
  for (std::size_t c = 0; c < 6; ++c)
  {
    for (std::size_t q = 0; q < 64; ++q)
    {
      for (int k = 0; k < 9; ++k)
      {
        for (int channel = 0; channel < 3; ++channel)
        {
          const double a = cached.Probes()[c][q].L[k][channel];
          const double b = looked.Probes()[c][q].L[k][channel];
          largest = std::max(largest, std::abs(b));
          worst = std::max(worst, std::abs(a - b));
        }
      }
    }
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LE(worst, 1e-5 * largest);
}

TEST(ObjectReliefProbesCore, CacheKeepsProbesThatDidNotMove)
{
  const LightField& field = walkthroughtest::PlainCornellField(129);
  ObjectReliefProbes probes(field);
  probes.SetMesh(MakeCube(1.0f), 4);
  const glm::mat4 placement = Placement(field);
  EXPECT_EQ(probes.Gather(placement), 96u);
  EXPECT_EQ(probes.Gather(placement), 0u);
  const glm::mat4 nudged = glm::translate(glm::mat4(1.0f), glm::vec3(1e-5f, 0, 0)) * placement;
  EXPECT_EQ(probes.Gather(nudged), 0u);
  const glm::mat4 turned =
    Placement(field) * glm::rotate(glm::mat4(1.0f), glm::radians(20.0f), glm::vec3(0, 1, 0));
  // The four side faces turned; the probes of the top and bottom near the axis moved too little.
  const std::size_t regathered = probes.Gather(turned);
  EXPECT_GE(regathered, 64u);
  EXPECT_LT(regathered, 96u);
  // The same mesh again keeps the charts and the cache; another probe count starts over.
  probes.SetMesh(MakeCube(1.0f), 4);
  EXPECT_EQ(probes.Gather(turned), 0u);
  probes.SetMesh(MakeCube(1.0f), 2);
  EXPECT_EQ(probes.Gather(turned), 24u);
}
