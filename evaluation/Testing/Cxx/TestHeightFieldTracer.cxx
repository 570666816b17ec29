// SPDX-License-Identifier: BSD-3-Clause
// Unit tests for mesolight::HeightFieldTracer, the exact reference for GPU relief marching.
// Texture space is (u, v, d), d = depth, 0 = top; see HeightFieldTracer.h.

#include "HeightFieldTracer.h"

#include "MathConstants.h"
#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <functional>
#include <limits>
#include <optional>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using mesolight::HeightField;
using mesolight::IntersectFirst;
using mesolight::IntersectFirstBruteForce;
using mesolight::RayHit;
using mesolight::Visible;

constexpr double kInf = std::numeric_limits<double>::infinity();
constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();

HeightField MakeField(int w, int h, const std::function<float(int, int)>& depth,
  HeightField::Edge edge = HeightField::Edge::Clamped)
{
  std::vector<float> samples;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      samples.push_back(depth(i, j));
    }
  }
  return HeightField(w, h, samples, edge);
}

HeightField RandomField(
  int w, int h, unsigned seed, HeightField::Edge edge = HeightField::Edge::Clamped)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  return MakeField(
    w, h, [&](int, int) { return depth(rng); }, edge);
}

// Unit direction at angle `theta` from straight down (+d) and azimuth `phi`.
glm::dvec3 DownDirection(double theta, double phi)
{
  return { std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) };
}

// Draws u, then v: function arguments have no evaluation order, so drawing both inside one
// constructor call would give compiler-dependent rays.
template <typename Rng, typename U, typename V>
glm::dvec2 DrawUV(Rng& rng, U& u, V& v)
{
  const double pu = u(rng);
  return { pu, v(rng) };
}

// A light direction (toward the light, d up) at an elevation between 1 and 1 + span degrees above
// the horizon and any azimuth: elevation drawn first, then azimuth.
template <typename Rng, typename U>
glm::dvec3 DrawToLight(Rng& rng, U& unit, double spanDegrees)
{
  const double elevation = (1.0 + spanDegrees * unit(rng)) * mesolight::Pi<double> / 180.0;
  const double phi = unit(rng) * 2 * mesolight::Pi<double>;
  return { std::cos(elevation) * std::cos(phi), std::cos(elevation) * std::sin(phi),
    -std::sin(elevation) };
}

// Every reported hit must be on or below the surface and lie on the ray at its t.
void ExpectValidHit(const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir,
  double tMax, const RayHit& hit)
{
  EXPECT_GE(hit.t, 0.0);
  EXPECT_LE(hit.t, tMax);
  const glm::dvec3 expected = origin + hit.t * dir;
  EXPECT_DOUBLE_EQ(hit.point.x, expected.x);
  EXPECT_DOUBLE_EQ(hit.point.y, expected.y);
  EXPECT_DOUBLE_EQ(hit.point.z, expected.z);
  EXPECT_GE(hit.point.z, hf.DepthAt(hit.point.x, hit.point.y) - 1e-12);
}

// A typical GPU linear search (N uniform steps) plus 8 bisection steps: used only to show that
// the spike test can tell an exact method from a too-coarse one.
std::optional<double> CoarseMarch(
  const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tMax, int steps)
{
  const auto below = [&](double t)
  {
    const glm::dvec3 p = origin + t * dir;
    return p.z >= hf.DepthAt(p.x, p.y);
  };
  double lo = 0.0;
  for (int k = 1; k <= steps; ++k)
  {
    double hi = tMax * k / steps;
    if (below(hi))
    {
      for (int i = 0; i < 8; ++i)
      {
        const double mid = 0.5 * (lo + hi);
        (below(mid) ? hi : lo) = mid;
      }
      return hi;
    }
    lo = hi;
  }
  return std::nullopt;
}

// Compares IntersectFirst with the brute-force oracle on one ray. Returns true when they agree to
// 1e-6 in t; otherwise checks the first-hit property (the oracle may only be late or miss).
bool CompareWithOracle(
  const HeightField& hf, const glm::dvec3& origin, const glm::dvec3& dir, double tMax, int samples)
{
  const std::optional<RayHit> exact = IntersectFirst(hf, origin, dir, tMax);
  const std::optional<RayHit> oracle = IntersectFirstBruteForce(hf, origin, dir, tMax, samples);
  if (exact)
  {
    ExpectValidHit(hf, origin, dir, tMax, *exact);
  }
  if (!exact)
  {
    EXPECT_FALSE(oracle) << "oracle found a hit the tracer missed at t=" << oracle->t;
    return !oracle;
  }
  if (oracle && std::abs(oracle->t - exact->t) <= 1e-6)
  {
    return true;
  }
  if (oracle)
  {
    EXPECT_GT(oracle->t, exact->t) << "oracle found an EARLIER hit: tracer is not first-hit";
  }
  return false;
}

// --- HeightField -------------------------------------------------------------------------------

TEST(HeightField, TexelLayoutRowZeroIsBottomAndCentresAreExact)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> depth(0.0f, 1.0f);
  std::vector<float> samples(5 * 3);
  for (float& s : samples)
  {
    s = depth(rng);
  }
  const HeightField hf(5, 3, samples);
  EXPECT_EQ(hf.Width(), 5);
  EXPECT_EQ(hf.Height(), 3);
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 5; ++i)
    {
      EXPECT_EQ(hf.Texel(i, j), samples[j * 5 + i]);
      // The surface passes exactly through each sample at its texel centre.
      EXPECT_EQ(hf.DepthAt((i + 0.5) / 5, (j + 0.5) / 3), static_cast<double>(hf.Texel(i, j)));
    }
  }
  // Halfway between two centres is their average.
  EXPECT_NEAR(hf.DepthAt(1.0 / 5, 0.5 / 3), 0.5 * (double(hf.Texel(0, 0)) + hf.Texel(1, 0)), 1e-15);

  // Rows: 0 at the bottom (v ~ 0), 1 at the top.
  const HeightField rows = MakeField(2, 2, [](int, int j) { return j == 0 ? 0.0f : 1.0f; });
  EXPECT_EQ(rows.DepthAt(0.5, 0.01), 0.0);
  EXPECT_EQ(rows.DepthAt(0.5, 0.99), 1.0);
  EXPECT_DOUBLE_EQ(rows.DepthAt(0.5, 0.5), 0.5);
}

TEST(HeightField, ClampToEdgeBandsAreConstant)
{
  // Column depths 1, 0, 0, 0: a step down at the left border.
  const HeightField hf = MakeField(4, 2, [](int i, int) { return i == 0 ? 1.0f : 0.0f; });
  // u < 0.5 / W uses column 0 only (GL_REPEAT would blend in column 3 and give 0.7 at u = 0.05).
  for (double u : { -7.0, 0.0, 0.05, 0.124, 0.125 })
  {
    EXPECT_EQ(hf.DepthAt(u, 0.3), 1.0) << "u=" << u;
    EXPECT_EQ(hf.GradientAt(u, 0.3).x, u < 0.125 ? 0.0 : -4.0) << "u=" << u;
  }
  EXPECT_DOUBLE_EQ(hf.DepthAt(0.25, 0.5), 0.5); // ramp between centres 0.125 and 0.375
  EXPECT_EQ(hf.GradientAt(0.25, 0.5), glm::dvec2(-4.0, 0.0));
  for (double u : { 0.375, 0.6, 0.9, 1.0, 5.0 })
  {
    EXPECT_EQ(hf.DepthAt(u, 0.5), 0.0) << "u=" << u;
  }
  // Outside [0, 1] in v too, and in the corner bands.
  EXPECT_EQ(hf.DepthAt(-3.0, 4.0), 1.0);
  EXPECT_EQ(hf.GradientAt(0.25, -1.0), glm::dvec2(-4.0, 0.0));
}

TEST(HeightField, GradientMatchesFiniteDifferences)
{
  const HeightField hf = RandomField(9, 7, 99);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> coord(-0.2, 1.2);
  int checked = 0;
  while (checked < 500)
  {
    const double u = coord(rng);
    const double v = coord(rng);
    const double x = u * 9 - 0.5;
    const double y = v * 7 - 0.5;
    // Away from creases (cell edges), where the gradient is one-sided.
    if (std::abs(x - std::round(x)) < 1e-3 || std::abs(y - std::round(y)) < 1e-3)
    {
      continue;
    }
    const double h = 1e-7;
    const glm::dvec2 g = hf.GradientAt(u, v);
    EXPECT_NEAR(g.x, (hf.DepthAt(u + h, v) - hf.DepthAt(u - h, v)) / (2 * h), 1e-6);
    EXPECT_NEAR(g.y, (hf.DepthAt(u, v + h) - hf.DepthAt(u, v - h)) / (2 * h), 1e-6);
    ++checked;
  }
}

TEST(HeightField, RejectsInvalidInput)
{
  std::vector<float> samples(4 * 3, 0.5f);
  samples[1 * 4 + 2] = std::numeric_limits<float>::quiet_NaN();
  try
  {
    HeightField hf(4, 3, samples);
    FAIL() << "NaN sample accepted";
  }
  catch (const std::invalid_argument& e)
  {
    const std::string what = e.what();
    EXPECT_NE(what.find("non-finite"), std::string::npos) << what;
    EXPECT_NE(what.find("i=2, j=1"), std::string::npos) << what;
  }
  samples[1 * 4 + 2] = std::numeric_limits<float>::infinity();
  EXPECT_THROW(HeightField(4, 3, samples), std::invalid_argument);
  EXPECT_THROW(HeightField(0, 3, std::vector<float>()), std::invalid_argument);
  EXPECT_THROW(HeightField(3, -1, std::vector<float>()), std::invalid_argument);
  EXPECT_THROW(HeightField(4, 4, std::vector<float>(12, 0.5f)), std::invalid_argument);
  EXPECT_NO_THROW(HeightField(4, 3, std::vector<float>(12, 0.5f)));
}

// --- IntersectFirst ----------------------------------------------------------------------------

TEST(IntersectFirst, FlatMapHitsAtTheConstantDepth)
{
  const float c = 0.37f;
  const HeightField hf = MakeField(6, 5, [&](int, int) { return c; });
  std::mt19937 rng(1);
  std::uniform_real_distribution<double> uv(-1.0, 2.0), d0(-0.5, 0.0), unit(0.0, 1.0);
  for (int n = 0; n < 1000; ++n)
  {
    const glm::dvec2 start = DrawUV(rng, uv, uv);
    const glm::dvec3 origin(start, d0(rng));
    const double theta = unit(rng) * 89.0 * mesolight::Pi<double> / 180.0;
    const glm::dvec3 dir = DownDirection(theta, unit(rng) * 2 * mesolight::Pi<double>);
    const double tExpected = (c - origin.z) / dir.z;
    const double tMax = 2.0 * tExpected + 1.0;
    const std::optional<RayHit> hit = IntersectFirst(hf, origin, dir, tMax);
    ASSERT_TRUE(hit);
    ExpectValidHit(hf, origin, dir, tMax, *hit);
    EXPECT_EQ(hf.DepthAt(hit->point.x, hit->point.y), c); // exactly flat, bands included
    EXPECT_NEAR(hit->point.z, c, 1e-12);
    EXPECT_NEAR(hit->t, tExpected, 1e-10 * tExpected);
  }
  // Origin already below: t = 0. Not reaching the surface within tMax: miss.
  const std::optional<RayHit> below = IntersectFirst(hf, { 0.5, 0.5, 0.9 }, { 0, 0, 1 }, 1.0);
  ASSERT_TRUE(below);
  EXPECT_EQ(below->t, 0.0);
  EXPECT_FALSE(IntersectFirst(hf, { 0.5, 0.5, 0.0 }, { 0, 0, 1 }, 0.3));
  EXPECT_TRUE(IntersectFirst(hf, { 0.5, 0.5, 0.0 }, { 0, 0, 1 }, 0.38));
}

TEST(IntersectFirst, TiltedPlaneMatchesTheAnalyticHit)
{
  // depth = 1/8 + u/2 + v/4; the texel values are exact in float on this 8 x 4 grid, and bilinear
  // interpolation reproduces a plane exactly between the texel centres.
  const auto plane = [](double u, double v) { return 0.125 + 0.5 * u + 0.25 * v; };
  const HeightField hf = MakeField(
    8, 4, [&](int i, int j) { return static_cast<float>(plane((i + 0.5) / 8, (j + 0.5) / 4)); });
  std::mt19937 rng(2);
  std::uniform_real_distribution<double> inU(0.07, 0.93), inV(0.13, 0.87);
  for (int n = 0; n < 1000; ++n)
  {
    // Origin at the top, target on the plane, both inside the centre grid; dir is not normalized.
    const glm::dvec3 origin(DrawUV(rng, inU, inV), 0.0);
    const glm::dvec3 target(DrawUV(rng, inU, inV), 0.0);
    const glm::dvec3 onPlane(target.x, target.y, plane(target.x, target.y));
    EXPECT_NEAR(hf.DepthAt(target.x, target.y), onPlane.z, 1e-15);
    EXPECT_NEAR(hf.GradientAt(target.x, target.y).x, 0.5, 1e-12);
    EXPECT_NEAR(hf.GradientAt(target.x, target.y).y, 0.25, 1e-12);
    const glm::dvec3 dir = onPlane - origin;
    const std::optional<RayHit> hit = IntersectFirst(hf, origin, dir, 1.5);
    ASSERT_TRUE(hit);
    EXPECT_NEAR(hit->t, 1.0, 1e-10);
    EXPECT_NEAR(hit->point.x, onPlane.x, 1e-10);
    EXPECT_NEAR(hit->point.y, onPlane.y, 1e-10);
    EXPECT_NEAR(hit->point.z, onPlane.z, 1e-10);
  }
}

TEST(IntersectFirst, AgreesWithBruteForceOnRandomMapsForDownwardRays)
{
  const HeightField hf = RandomField(17, 13, 12345);
  std::mt19937 rng(4);
  std::uniform_real_distribution<double> uv(-0.1, 1.1), unit(0.0, 1.0);
  const int rays = 2000;
  int agree = 0;
  for (int n = 0; n < rays; ++n)
  {
    const glm::dvec3 origin(DrawUV(rng, uv, uv), 0.0);
    // Up to 89 degrees from vertical: the grazing rays are the hard ones.
    const double theta = unit(rng) * 89.0 * mesolight::Pi<double> / 180.0;
    const glm::dvec3 dir = DownDirection(theta, unit(rng) * 2 * mesolight::Pi<double>);
    const double tMax = 1.05 / dir.z; // reaches below the deepest sample: must hit
    ASSERT_TRUE(IntersectFirst(hf, origin, dir, tMax));
    agree += CompareWithOracle(hf, origin, dir, tMax, 10000);
  }
  // The oracle only misses features thinner than its step; that must stay rare.
  EXPECT_GE(agree, rays * 99 / 100) << agree << " of " << rays << " agree";
  std::printf("[          ] downward rays: %d of %d agree with the oracle to 1e-6\n", agree, rays);
}

TEST(IntersectFirst, AgreesWithBruteForceForUpwardAndHorizontalRays)
{
  const HeightField hf = RandomField(17, 13, 54321);
  std::mt19937 rng(5);
  std::uniform_real_distribution<double> uv(0.0, 1.0), unit(0.0, 1.0);
  const int rays = 500;
  int agree = 0;
  int hits = 0;
  for (int n = 0; n < rays; ++n)
  {
    const double u = uv(rng);
    const double v = uv(rng);
    const glm::dvec3 origin(u, v, hf.DepthAt(u, v) - 0.01 - 0.3 * unit(rng));
    // Elevation above the horizontal in [0, 60] degrees; every 4th ray exactly horizontal.
    const double elevation = n % 4 == 0 ? 0.0 : unit(rng) * 60.0 * mesolight::Pi<double> / 180.0;
    const double phi = unit(rng) * 2 * mesolight::Pi<double>;
    const glm::dvec3 dir(std::cos(elevation) * std::cos(phi), std::cos(elevation) * std::sin(phi),
      -std::sin(elevation));
    if (n % 4 == 0)
    {
      ASSERT_EQ(dir.z, 0.0);
    }
    // Up to 2 units, or until the ray rises above d = 0, the top of every sample.
    const double tMax = dir.z < 0.0 ? std::min(2.0, origin.z / -dir.z) : 2.0;
    hits += IntersectFirst(hf, origin, dir, tMax).has_value();
    agree += CompareWithOracle(hf, origin, dir, tMax, 10000);
  }
  EXPECT_GE(agree, rays * 99 / 100) << agree << " of " << rays << " agree";
  EXPECT_GT(hits, rays / 10); // the test must exercise bump sides, not only misses
  EXPECT_LT(hits, rays);      // and misses
  std::printf("[          ] up/horizontal rays: %d of %d agree, %d hit\n", agree, rays, hits);
}

// A 33 x 33 floor at depth 1 with one texel at depth 0 in the middle: a thin bilinear spike whose
// apex is at (0.5, 0.5, 0) and whose base spans one texel either side.
HeightField SpikeField()
{
  return MakeField(33, 33, [](int i, int j) { return i == 16 && j == 16 ? 0.0f : 1.0f; });
}

TEST(IntersectFirst, SpikeIsHitWhenAimedAtAndMissedBeside)
{
  const HeightField hf = SpikeField();
  // Straight down onto the apex.
  const std::optional<RayHit> apex = IntersectFirst(hf, { 0.5, 0.5, -0.25 }, { 0, 0, 1 }, 2.0);
  ASSERT_TRUE(apex);
  EXPECT_NEAR(apex->t, 0.25, 1e-12);
  EXPECT_NEAR(apex->point.z, 0.0, 1e-12);

  // Slanted ray u = 0.2 + 0.8 t, v = 0.5, d = t. On v = 0.5 the spike side at u = 0.5 - delta has
  // depth 33 delta, so the hit is at 0.3 - delta = 0.8 * 33 delta: delta = 0.3 / 27.4.
  const glm::dvec3 dir(0.8, 0.0, 1.0);
  const double delta = 0.3 / 27.4;
  const std::optional<RayHit> side = IntersectFirst(hf, { 0.2, 0.5, 0.0 }, dir, 2.0);
  ASSERT_TRUE(side);
  EXPECT_NEAR(side->t, (0.3 - delta) / 0.8, 1e-12);
  EXPECT_NEAR(side->point.x, 0.5 - delta, 1e-12);
  EXPECT_NEAR(side->point.z, 33 * delta, 1e-12);

  // The same ray shifted just past the spike's base (1.01 texels in v) reaches the floor at d = 1.
  const std::optional<RayHit> beside = IntersectFirst(hf, { 0.2, 0.5 + 1.01 / 33, 0.0 }, dir, 2.0);
  ASSERT_TRUE(beside);
  EXPECT_NEAR(beside->t, 1.0, 1e-12);
  EXPECT_NEAR(beside->point.z, 1.0, 1e-12);
}

TEST(IntersectFirst, CoarseMarcherMissesTheSpikeTheTracerHits)
{
  // Negative check: the spike test separates methods. 4 linear steps sample u = 0.4, 0.6, 0.8, 1.0
  // and straddle the spike, landing on the floor; the exact tracer and the dense oracle do not.
  const HeightField hf = SpikeField();
  const glm::dvec3 origin(0.2, 0.5, 0.0);
  const glm::dvec3 dir(0.8, 0.0, 1.0);
  const std::optional<RayHit> exact = IntersectFirst(hf, origin, dir, 1.0);
  const std::optional<RayHit> oracle = IntersectFirstBruteForce(hf, origin, dir, 1.0, 10000);
  const std::optional<double> coarse = CoarseMarch(hf, origin, dir, 1.0, 4);
  ASSERT_TRUE(exact && oracle && coarse);
  EXPECT_NEAR(oracle->t, exact->t, 1e-9);
  EXPECT_GT(*coarse - exact->t, 0.5);                 // far later: it went through the spike
  EXPECT_NEAR(origin.z + *coarse * dir.z, 1.0, 1e-2); // and stopped on the floor
  // With enough steps the same marcher does find the spike (so the marcher itself is sound).
  const std::optional<double> fine = CoarseMarch(hf, origin, dir, 1.0, 64);
  ASSERT_TRUE(fine);
  EXPECT_NEAR(*fine, exact->t, 1e-3);
}

TEST(IntersectFirst, RaysThroughTheClampBands)
{
  const HeightField hf = MakeField(4, 2, [](int i, int) { return i == 0 ? 1.0f : 0.0f; });
  // Horizontal ray at d = 0.5 from far left: above the band (depth 1) until the ramp, where
  // depth = 1 - (u - 0.125) * 4 = 0.5 at u = 0.25.
  const std::optional<RayHit> ramp = IntersectFirst(hf, { -2.0, 0.5, 0.5 }, { 1, 0, 0 }, 10.0);
  ASSERT_TRUE(ramp);
  EXPECT_NEAR(ramp->t, 2.25, 1e-12);
  EXPECT_NEAR(ramp->point.x, 0.25, 1e-12);
  // Straight down in the band u < 0.125: clamp gives depth 1 (GL_REPEAT would give 0.7).
  const std::optional<RayHit> band = IntersectFirst(hf, { 0.05, 0.5, 0.0 }, { 0, 0, 1 }, 2.0);
  ASSERT_TRUE(band);
  EXPECT_NEAR(band->point.z, 1.0, 1e-12);
  // Along v inside the band, below d = 1 never: a miss across all v cells and both v bands.
  EXPECT_FALSE(IntersectFirst(hf, { 0.05, -3.0, 0.9 }, { 0, 1, 0 }, 10.0));
  // Upward ray from inside the band hits nothing; from the deep band into the ramp it does.
  EXPECT_FALSE(IntersectFirst(hf, { 0.05, 0.5, 0.9 }, { 0, 0, -1 }, 5.0));
  const std::optional<RayHit> up = IntersectFirst(hf, { 0.05, 0.5, 0.9 }, { 1, 0, -0.1 }, 5.0);
  ASSERT_TRUE(up);
  EXPECT_NEAR(up->point.z, hf.DepthAt(up->point.x, up->point.y), 1e-12);
}

TEST(IntersectFirst, OneByOneMapIsConstantEverywhere)
{
  const HeightField hf(1, 1, { 0.25f });
  for (double u : { -5.0, 0.0, 0.3, 0.5, 1.0, 7.0 })
  {
    EXPECT_EQ(hf.DepthAt(u, 1.0 - u), 0.25);
    EXPECT_EQ(hf.GradientAt(u, u), glm::dvec2(0.0));
  }
  const glm::dvec3 dir = DownDirection(1.2, 0.7);
  const std::optional<RayHit> hit = IntersectFirst(hf, { 0.5, 0.5, 0.0 }, dir, 10.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.z, 0.25, 1e-12);
  EXPECT_FALSE(IntersectFirst(hf, { 0.5, 0.5, 0.2 }, { 1, 0, 0 }, 10.0));
  EXPECT_TRUE(IntersectFirst(hf, { 0.5, 0.5, 0.3 }, { 1, 0, 0 }, 10.0));
  EXPECT_TRUE(Visible(hf, { 0.5, 0.5, 0.25 }, { 1, 1, -0.01 }));
}

TEST(IntersectFirst, NonFiniteOrNegativeInputsMiss)
{
  const HeightField hf(2, 2, { 0.5f, 0.5f, 0.5f, 0.5f });
  const glm::dvec3 o(0.5, 0.5, 0.0);
  const glm::dvec3 d(0.0, 0.0, 1.0);
  EXPECT_TRUE(IntersectFirst(hf, o, d, 1.0));
  EXPECT_FALSE(IntersectFirst(hf, { kNaN, 0.5, 0.0 }, d, 1.0));
  EXPECT_FALSE(IntersectFirst(hf, o, { 0.0, kInf, 1.0 }, 1.0));
  EXPECT_FALSE(IntersectFirst(hf, o, d, kInf));
  EXPECT_FALSE(IntersectFirst(hf, o, d, kNaN));
  EXPECT_FALSE(IntersectFirst(hf, o, d, -1.0));
  EXPECT_FALSE(IntersectFirst(hf, o, { 0, 0, 0 }, 1.0)); // a point above the surface
  EXPECT_FALSE(Visible(hf, { kNaN, 0.5, 0.5 }, { 0, 0, -1 }));
  EXPECT_THROW(IntersectFirstBruteForce(hf, o, d, 1.0, 0), std::invalid_argument);
}

// --- Visible -----------------------------------------------------------------------------------

TEST(CountBoundReachingCells, FlatMapNeedsOnlyTheHitCell)
{
  // On a flat map the ray reaches the cells' bound (the constant depth) only where it hits.
  const float c = 0.37f;
  const HeightField hf = MakeField(16, 16, [&](int, int) { return c; });
  std::mt19937 rng(7);
  std::uniform_real_distribution<double> uv(0.0, 1.0), unit(0.0, 1.0);
  for (int n = 0; n < 500; ++n)
  {
    const glm::dvec3 origin(DrawUV(rng, uv, uv), 0.0);
    const double theta = unit(rng) * 89.0 * mesolight::Pi<double> / 180.0;
    const glm::dvec3 dir = DownDirection(theta, unit(rng) * 2 * mesolight::Pi<double>);
    const std::optional<RayHit> hit = IntersectFirst(hf, origin, dir, 100.0);
    ASSERT_TRUE(hit);
    EXPECT_EQ(mesolight::CountBoundReachingCells(hf, origin, dir, hit->t), 1);
  }
}

TEST(CountBoundReachingCells, RayPassingBesideASpikeCountsItsCellsWithoutHitting)
{
  // Depth 1 everywhere but texel (4, 4), at depth 0. A horizontal ray along grid y = 3.5 crosses
  // the two cells with the spike as a corner, where the bilinear surface's shallowest point on
  // that line is depth 0.5 (at the spike's column). At depth 0.4 the ray passes over it: no hit,
  // but both cells' bound (0) is reached, so an exact bound traversal must test both patches.
  const HeightField hf = MakeField(8, 8, [](int i, int j) { return i == 4 && j == 4 ? 0.f : 1.f; });
  const glm::dvec3 dir(1.0, 0.0, 0.0);
  const glm::dvec3 over((0.5 + 0.5) / 8, (3.5 + 0.5) / 8, 0.4);
  const double tEnd = 6.5 / 8; // to grid x = 7
  EXPECT_FALSE(IntersectFirst(hf, over, dir, tEnd));
  EXPECT_EQ(mesolight::CountBoundReachingCells(hf, over, dir, tEnd), 2);
  // Above every bound: nothing to test.
  EXPECT_EQ(mesolight::CountBoundReachingCells(hf, over - glm::dvec3(0, 0, 0.5), dir, tEnd), 0);
  // At depth 0.5 the ray touches the patch at the spike's column: the hit ends the count there.
  const glm::dvec3 touching(over.x, over.y, 0.5);
  const std::optional<RayHit> hit = IntersectFirst(hf, touching, dir, tEnd);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.x, 4.5 / 8, 1e-9);
  EXPECT_EQ(mesolight::CountBoundReachingCells(hf, touching, dir, hit->t), 1);
  // Bad input counts nothing.
  EXPECT_EQ(mesolight::CountBoundReachingCells(hf, over, dir, -1.0), 0);
  EXPECT_EQ(mesolight::CountBoundReachingCells(hf, over, glm::dvec3(kNaN, 0, 0), tEnd), 0);
}

// 16 x 4: floor at depth 1 for columns 0..9, a wall with its top at depth 0 for columns 10..15.
// The wall face ramps between the centres of columns 9 and 10 (u = 9.5/16 .. 10.5/16).
HeightField WallField()
{
  return MakeField(16, 4, [](int i, int) { return i >= 10 ? 0.0f : 1.0f; });
}

TEST(Visible, FloorInFrontOfAWall)
{
  const HeightField hf = WallField();
  const glm::dvec3 floorPoint(0.4, 0.5, 1.0);
  ASSERT_EQ(hf.DepthAt(floorPoint.x, floorPoint.y), 1.0);
  const double low = 20.0 * mesolight::Pi<double> / 180.0;
  // Low light behind the wall: the ray rises only 0.36 in d per unit u and meets the wall face.
  EXPECT_FALSE(Visible(hf, floorPoint, { std::cos(low), 0.0, -std::sin(low) }));
  // Same elevation, light in front (away from the wall): nothing in the way.
  EXPECT_TRUE(Visible(hf, floorPoint, { -std::cos(low), 0.0, -std::sin(low) }));
  // High light behind the wall: leaves the top at u = 0.5, before the face at u = 0.59375.
  EXPECT_TRUE(Visible(hf, floorPoint, { 0.1, 0.0, -1.0 }));
  // Lights at or below the horizon never reach the point.
  EXPECT_FALSE(Visible(hf, floorPoint, { 1.0, 0.0, 0.0 }));
  EXPECT_FALSE(Visible(hf, floorPoint, { -1.0, 0.0, 0.1 }));
  // Top of the wall: lit from any direction above the horizon.
  EXPECT_TRUE(Visible(hf, { 0.8, 0.5, 0.0 }, { 1.0, 0.0, -0.01 }));
  EXPECT_TRUE(Visible(hf, { 0.8, 0.5, 0.0 }, { -1.0, 0.0, -0.01 }));
  // Middle of the wall face (depth 0.5): lit from in front, self-shadowed from behind.
  const glm::dvec3 face(9.5 / 16 + 0.5 / 16, 0.5, 0.5);
  ASSERT_DOUBLE_EQ(hf.DepthAt(face.x, face.y), 0.5);
  EXPECT_TRUE(Visible(hf, face, { -1.0, 0.0, -1.0 }));
  EXPECT_FALSE(Visible(hf, face, { 1.0, 0.0, -0.2 }));
}

TEST(Visible, GrazingAlongTheSurfaceDoesNotShadowButIntersectFirstCountsContact)
{
  // A light ray lying exactly in the wall face: the face (u = 9.5/16 .. 10.5/16) has slope
  // d depth / du = -16 and toLight = (1/16, 0, -1) matches it. With power-of-two ratios every
  // quantity is exact, so the ray is exactly ON the face until it leaves the top at its upper edge.
  const HeightField hf = WallField();
  const glm::dvec3 face(0.625, 0.5, 0.5);
  const glm::dvec3 alongFace(1.0 / 16, 0.0, -1.0);
  ASSERT_EQ(hf.DepthAt(face.x, face.y), 0.5);
  // Visible blocks only strictly below: touching is not shadowing.
  EXPECT_TRUE(Visible(hf, face, alongFace, 0.0));
  // A slightly lower light goes into the wall.
  EXPECT_FALSE(Visible(hf, face, { 1.0 / 15, 0.0, -1.0 }, 0.0));
  // IntersectFirst counts "on" as a hit: a ray starting on the surface hits at t = 0.
  const std::optional<RayHit> on = IntersectFirst(hf, face, alongFace, 1.0);
  ASSERT_TRUE(on);
  EXPECT_EQ(on->t, 0.0);
}

TEST(Visible, AgreesWithBruteForceShadowRays)
{
  const HeightField hf = RandomField(17, 13, 777);
  std::mt19937 rng(6);
  std::uniform_real_distribution<double> uv(0.0, 1.0), unit(0.0, 1.0);
  const double epsilon = 1e-6;
  int agree = 0;
  int lit = 0;
  const int rays = 500;
  for (int n = 0; n < rays; ++n)
  {
    const glm::dvec3 point(DrawUV(rng, uv, uv), 0.0);
    const glm::dvec3 onSurface(point.x, point.y, hf.DepthAt(point.x, point.y));
    const glm::dvec3 toLight = DrawToLight(rng, unit, 80.0);
    const bool visible = Visible(hf, onSurface, toLight, epsilon);
    // Oracle: the same offset start, sampled up to where the ray leaves the top (d = 0).
    const glm::dvec3 start = onSurface + epsilon * toLight;
    const double tTop = -start.z / toLight.z;
    const bool oracleVisible = !IntersectFirstBruteForce(hf, start, toLight, tTop, 10000);
    lit += visible;
    if (visible == oracleVisible)
    {
      ++agree;
    }
    else
    {
      // The oracle may miss a thin occluder, never invent one.
      EXPECT_FALSE(visible) << "oracle found an occluder Visible() missed";
    }
  }
  EXPECT_GE(agree, rays * 99 / 100);
  EXPECT_GT(lit, rays / 10);
  EXPECT_LT(lit, rays * 9 / 10);
  std::printf("[          ] shadow rays: %d of %d agree, %d lit\n", agree, rays, lit);
}

// VisibleOrBlocker: Visible's answer on every ray, and where Visible is false after a march the
// point that stopped it, which is IntersectFirst's hit from the same start (the ray's first
// crossing) on these random rays; on a walled field the side wall's point and normal. The
// negative case: a blocker taken one cell further along the ray is not that hit.
TEST(Visible, VisibleOrBlockerKeepsWhereTheMarchStopped)
{
  for (const HeightField::Edge edge : { HeightField::Edge::Clamped, HeightField::Edge::Walled })
  {
    const HeightField hf = RandomField(17, 13, 778, edge);
    std::mt19937 rng(7);
    std::uniform_real_distribution<double> uv(0.0, 1.0), unit(0.0, 1.0);
    const double epsilon = 1e-6;
    int blocked = 0, walls = 0, farther = 0;
    for (int n = 0; n < 500; ++n)
    {
      const glm::dvec3 point(DrawUV(rng, uv, uv), 0.0);
      const glm::dvec3 onSurface(point.x, point.y, hf.DepthAt(point.x, point.y));
      const glm::dvec3 toLight = DrawToLight(rng, unit, 60.0);
      const mesolight::Visibility visibility =
        mesolight::VisibleOrBlocker(hf, onSurface, toLight, epsilon);
      ASSERT_EQ(visibility.Visible, Visible(hf, onSurface, toLight, epsilon));
      if (visibility.Visible)
      {
        EXPECT_FALSE(visibility.Blocker);
        continue;
      }
      ASSERT_TRUE(visibility.Blocker);
      ++blocked;
      const glm::dvec3 start = onSurface + epsilon * toLight;
      const std::optional<RayHit> first = IntersectFirst(hf, start, toLight, 4.0);
      ASSERT_TRUE(first);
      EXPECT_NEAR(glm::length(visibility.Blocker->point - first->point), 0.0, 1e-9);
      EXPECT_EQ(visibility.Blocker->wall, first->wall);
      walls += first->wall != glm::dvec2(0.0) ? 1 : 0;
      // Negative: the point a cell's width further along the ray is not the hit.
      const glm::dvec3 later = visibility.Blocker->point + (1.0 / 17) * toLight;
      farther += glm::length(later - first->point) > 1e-3 ? 1 : 0;
    }
    EXPECT_GT(blocked, 50);
    EXPECT_EQ(farther, blocked);
    if (edge == HeightField::Edge::Walled)
    {
      EXPECT_GT(walls, 0) << "some rays meet the side walls";
    }
    std::printf("[          ] %s: %d of 500 rays blocked, %d by a side wall\n",
      edge == HeightField::Edge::Walled ? "walled" : "clamped", blocked, walls);
  }
}

} // namespace
