// SPDX-License-Identifier: BSD-3-Clause
// ReliefShading against exact CPU evaluations: the SH-probe irradiance at the relief's perturbed
// normal against the exact integral of the same incident radiance (a smooth environment sampled
// at 16384 directions, its clamped-cosine sum at that normal); the negative case, the flat wall's
// normal, fails the same check on a relief with slopes. Direct light: an unshadowed flat relief
// gives the analytic point-light irradiance, and a grazing light leaves the valleys of a sloped
// relief in its own shadow, point by point as a dense independent march says. Inter-reflection:
// the indirect light in a V-groove against Monte-Carlo paths bouncing inside it on the exact
// intersector; the negative case, the occluded directions as black, is too dark. The relief's
// maps (visible share, emitter shadows) against analytic view factors and dense marches. The
// walled relief (its slot and side walls) is tested in TestReliefShadingWalls.cxx.
#include "ReliefShadingTestScene.h"

#include "MathConstants.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace
{
using mesolight::HeightField;
using mesolight::ReliefFrame;
using mesolight::ReliefLighting;
using mesolight::ReliefNormal;
using namespace mesolight::test; // Square, UniformLighting, PathTracedIrradiance

struct Sample
{
  glm::dvec3 Direction;
  double SolidAngle;
  glm::dvec3 Radiance;
};

// A smooth sky-and-ground environment with a broad warm lobe to one side: every order of it
// matters, none is a delta (the SH9 of such light is accurate, Ramamoorthi and Hanrahan §3).
glm::dvec3 Environment(const glm::dvec3& w)
{
  const double lobe = std::max(0.0, glm::dot(w, glm::normalize(glm::dvec3(1.0, 0.3, 0.6))));
  return glm::dvec3(0.3, 0.35, 0.5) * (1.0 + 0.6 * w.z) + glm::dvec3(1.2, 0.8, 0.4) * lobe * lobe;
}

// Fibonacci sphere: equal solid angles 4 pi / n.
std::vector<Sample> SampledEnvironment(int n)
{
  std::vector<Sample> samples;
  const double golden = mesolight::Pi<double> * (3.0 - std::sqrt(5.0));
  for (int i = 0; i < n; ++i)
  {
    const double z = 1.0 - (2.0 * i + 1.0) / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const glm::dvec3 w(r * std::cos(golden * i), r * std::sin(golden * i), z);
    samples.push_back({ w, 4.0 * mesolight::Pi<double> / n, Environment(w) });
  }
  return samples;
}

mesolight::SH9 Project(const std::vector<Sample>& samples)
{
  mesolight::SH9 sh;
  for (const Sample& s : samples)
  {
    const double d[3] = { s.Direction.x, s.Direction.y, s.Direction.z };
    double y[9];
    mesolight::EvaluateSHBasis(d, y);
    for (int k = 0; k < 9; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        sh.L[k][c] += s.SolidAngle * s.Radiance[c] * y[k];
      }
    }
  }
  return sh;
}

glm::dvec3 ExactIrradiance(const std::vector<Sample>& samples, const glm::dvec3& n)
{
  glm::dvec3 e(0.0);
  for (const Sample& s : samples)
  {
    e += s.Radiance * (s.SolidAngle * std::max(0.0, glm::dot(n, s.Direction)));
  }
  return e;
}

// Sloped ridges: depth 0.5 + 0.45 sin(2 pi 3 u) cos(2 pi 2 v), 64 x 64.
HeightField Ridges()
{
  const int n = 64;
  std::vector<float> depth;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double u = (i + 0.5) / n, v = (j + 0.5) / n;
      depth.push_back(static_cast<float>(0.5 +
        0.45 * std::sin(2.0 * mesolight::Pi<double> * 3.0 * u) *
          std::cos(2.0 * mesolight::Pi<double> * 2.0 * v)));
    }
  }
  return HeightField(n, n, depth);
}

// The largest relative error (per pixel, luminance-like sum over channels, against the exact
// irradiance) of the indirect term over a grid of rays from a camera above the square.
double WorstIndirectError(ReliefNormal normal, double* slope = nullptr)
{
  const HeightField hf = Ridges();
  const ReliefFrame frame = Square();
  const std::vector<Sample> environment = SampledEnvironment(16384);
  ReliefLighting lighting;
  lighting.Probes = { Project(environment) };
  lighting.OcclusionDirections = 0; // the SH irradiance alone, against the unoccluded integral
  const glm::dvec3 eye(0.5, -0.6, 1.4);
  double worst = 0.0, steepest = 0.0;
  for (int y = 0; y < 24; ++y)
  {
    for (int x = 0; x < 24; ++x)
    {
      const glm::dvec3 target((x + 0.5) / 24.0, (y + 0.5) / 24.0, 0.0);
      const auto shade =
        mesolight::ShadeReliefRay(hf, frame, lighting, eye, glm::normalize(target - eye), normal);
      if (!shade)
      {
        continue;
      }
      // The reference is always at the displaced surface's true normal.
      const glm::dvec3 n = mesolight::ReliefNormalAt(hf, frame, shade->Texture.x, shade->Texture.y);
      steepest = std::max(steepest, std::acos(std::min(1.0, n.z)));
      const glm::dvec3 exact = ExactIrradiance(environment, n);
      const double sum = exact.x + exact.y + exact.z;
      const glm::dvec3 diff = shade->Indirect - exact;
      worst = std::max(worst, (std::abs(diff.x) + std::abs(diff.y) + std::abs(diff.z)) / sum);
    }
  }
  if (slope)
  {
    *slope = steepest;
  }
  return worst;
}

TEST(ReliefShading, ShIrradianceAtThePerturbedNormalMatchesExactIntegration)
{
  double steepest = 0.0;
  const double error = WorstIndirectError(ReliefNormal::Perturbed, &steepest);
  std::cout << "SH9 at the perturbed normal: worst relative error " << error << " (steepest slope "
            << steepest * 180.0 / mesolight::Pi<double> << " degrees)\n";
  EXPECT_GT(steepest, 0.5); // the relief has slopes steeper than about 30 degrees
  EXPECT_LT(error, 0.03);
}

TEST(ReliefShading, FlatNormalFailsTheCheck)
{
  const double error = WorstIndirectError(ReliefNormal::Flat);
  std::cout << "flat wall's normal: worst relative error " << error << "\n";
  EXPECT_GT(error, 0.1);
}

// The relief's occlusion of the indirect light against the exact integral with visibility: every
// environment sample marched through the height field from the hit (deep ridges, 0.4 of the
// width). Returns the mean relative error over the hits, and their mean visible share.
double OccludedIndirectError(int occlusionDirections, double* meanVisible = nullptr)
{
  const HeightField hf = Ridges();
  ReliefFrame frame = Square();
  frame.DepthScale = 0.4;
  const std::vector<Sample> environment = SampledEnvironment(2048);
  ReliefLighting lighting;
  lighting.Probes = { Project(environment) };
  lighting.OcclusionDirections = occlusionDirections;
  const glm::dvec3 eye(0.5, 0.2, 2.0);
  double sumError = 0.0, sumVisible = 0.0;
  int hits = 0;
  for (int y = 0; y < 12; ++y)
  {
    for (int x = 0; x < 12; ++x)
    {
      const glm::dvec3 target((x + 0.5) / 12.0, (y + 0.5) / 12.0, 0.0);
      const auto shade =
        mesolight::ShadeReliefRay(hf, frame, lighting, eye, glm::normalize(target - eye));
      if (!shade)
      {
        continue;
      }
      glm::dvec3 exact(0.0);
      for (const Sample& s : environment)
      {
        const double c = glm::dot(shade->Normal, s.Direction);
        if (c > 0.0 && s.Direction.z > 0.0 &&
          mesolight::Visible(hf, shade->Texture, frame.ToTexture(s.Direction), 1e-6))
        {
          exact += s.Radiance * (s.SolidAngle * c);
        }
      }
      const glm::dvec3 diff = shade->Indirect - exact;
      sumError += (std::abs(diff.x) + std::abs(diff.y) + std::abs(diff.z)) /
        (exact.x + exact.y + exact.z + 1e-9);
      sumVisible += shade->IndirectVisible;
      ++hits;
    }
  }
  if (meanVisible)
  {
    *meanVisible = sumVisible / hits;
  }
  return sumError / hits;
}

TEST(ReliefShading, IndirectOcclusionAgainstExactIntegrationWithVisibility)
{
  double visible = 1.0;
  const double occluded = OccludedIndirectError(32, &visible);
  const double unoccluded = OccludedIndirectError(0);
  std::cout << "indirect light in deep ridges, mean relative error: occluded (32 directions) "
            << occluded << ", unoccluded " << unoccluded << " (mean visible share " << visible
            << ")\n";
  EXPECT_LT(visible, 0.95); // the ridges do hide part of the room
  EXPECT_LT(occluded, 0.08);
  // Negative case: the SH irradiance without the relief's occlusion is off by more.
  EXPECT_GT(unoccluded, 2.0 * occluded);
}

TEST(ReliefShading, UniformLightGivesPiL)
{
  // SH9 of a uniform radiance L: L00 = 2 sqrt(pi) L, irradiance pi L at every normal.
  ReliefLighting lighting;
  mesolight::SH9 sh;
  sh.L[0] = { 2.0 * std::sqrt(mesolight::Pi<double>), 0.0, 1.0 };
  lighting.Probes = { sh };
  const glm::dvec3 e =
    mesolight::ProbeIrradiance(lighting, 0.3, 0.7, glm::normalize(glm::dvec3(1.0, -2.0, 0.5)));
  EXPECT_NEAR(e.x, mesolight::Pi<double>, 1e-5); // the basis constants have 6 digits
  EXPECT_NEAR(e.y, 0.0, 1e-12);
}

TEST(ReliefShading, DirectOnAFlatReliefIsThePointLightLaw)
{
  const HeightField flat(2, 2, { 0.0f, 0.0f, 0.0f, 0.0f });
  const ReliefFrame frame = Square();
  ReliefLighting lighting;
  mesolight::ReliefEmitterSample light;
  light.Position = glm::dvec3(0.9, 0.2, 0.8);
  light.Normal = glm::normalize(glm::dvec3(-0.2, 0.1, -1.0));
  light.RadianceArea = glm::dvec3(2.0, 1.0, 0.5);
  lighting.Emitters = { light };
  const glm::dvec3 eye(0.5, 0.5, 2.0);
  const auto shade =
    mesolight::ShadeReliefRay(flat, frame, lighting, eye, glm::dvec3(-0.1, 0.05, -1.0));
  ASSERT_TRUE(shade);
  const glm::dvec3 toLight = light.Position - shade->Point;
  const double r2 = glm::dot(toLight, toLight);
  const glm::dvec3 l = toLight / std::sqrt(r2);
  const double expected = l.z * -glm::dot(light.Normal, l) / r2;
  EXPECT_NEAR(shade->Direct.x, 2.0 * expected, 1e-9);
  EXPECT_NEAR(shade->Direct.z, 0.5 * expected, 1e-9);
  EXPECT_NEAR(shade->Point.z, 0.0, 1e-12);
  // The scene's visibility callback is asked, from the macro surface to the light.
  lighting.SceneVisible = [](const glm::dvec3&, const glm::dvec3&) { return false; };
  EXPECT_EQ(
    mesolight::ShadeReliefRay(flat, frame, lighting, eye, glm::dvec3(-0.1, 0.05, -1.0))->Direct.x,
    0.0);
}

TEST(ReliefShading, GrazingLightSelfShadowsLikeADenseMarch)
{
  const HeightField hf = Ridges();
  const ReliefFrame frame = Square();
  ReliefLighting lighting;
  mesolight::ReliefEmitterSample light;
  light.Position = glm::dvec3(-30.0, 0.5, 6.0); // far, low, along -u: the ridges cast shadows
  light.Normal = glm::normalize(glm::dvec3(0.5, 0.0, 0.0) - light.Position);
  light.RadianceArea = glm::dvec3(1000.0);
  lighting.Emitters = { light };
  const glm::dvec3 eye(0.5, 0.5, 3.0);
  int lit = 0, shadowed = 0, disagree = 0;
  for (int y = 0; y < 32; ++y)
  {
    for (int x = 0; x < 32; ++x)
    {
      const glm::dvec3 target((x + 0.5) / 32.0, (y + 0.5) / 32.0, 0.0);
      const auto shade =
        mesolight::ShadeReliefRay(hf, frame, lighting, eye, glm::normalize(target - eye));
      ASSERT_TRUE(shade);
      // Independent: march toward the light in 4000 steps of the height field's DepthAt.
      const glm::dvec3 l = frame.ToTexture(glm::normalize(light.Position - shade->Point));
      const double tTop = shade->Texture.z / -l.z;
      bool blocked = false;
      for (int s = 1; s <= 4000 && !blocked; ++s)
      {
        const glm::dvec3 q = shade->Texture + (tTop * s / 4000.0) * l;
        blocked = q.z > hf.DepthAt(q.x, q.y) + 1e-4;
      }
      const bool facing = glm::dot(shade->Normal, light.Position - shade->Point) > 0.0;
      const bool expectLit = facing && !blocked;
      const bool isLit = shade->Direct.x > 0.0;
      (isLit ? lit : shadowed)++;
      disagree += isLit != expectLit ? 1 : 0;
    }
  }
  EXPECT_GT(lit, 100);
  EXPECT_GT(shadowed, 100);
  EXPECT_LE(disagree, 10) << "of 1024 (grazing points may differ by the march's step)";
}

} // namespace

namespace
{
// A V-groove across u (infinite along v by the clamp-to-edge extension), 0.2 wide and 0.4 deep
// on the unit square, flat (depth 0) outside it: its walls see each other over most of their
// hemisphere.
HeightField VGroove()
{
  const int w = 256, h = 4;
  std::vector<float> depth;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const double u = (i + 0.5) / w;
      depth.push_back(static_cast<float>(std::max(0.0, 1.0 - std::abs(u - 0.5) / 0.1)));
    }
  }
  return HeightField(w, h, depth);
}

// The indirect irradiance in the groove by the method with the given inter-reflection model,
// against the path-traced reference: mean relative error over pixels across the groove, and the
// mean ratio method / reference.
double GrooveError(
  mesolight::ReliefInterReflection model, double depthScale, double* ratio = nullptr)
{
  const HeightField hf = VGroove();
  ReliefFrame frame = Square();
  frame.DepthScale = depthScale;
  const double radiance = 1.0, albedo = 0.7;
  ReliefLighting lighting = UniformLighting(radiance, albedo);
  lighting.InterReflection = model;
  const glm::dvec3 eye(0.5, 0.5, 2.0);
  unsigned state = 12345u;
  double sumError = 0.0, sumRatio = 0.0;
  int hits = 0;
  for (int x = 0; x < 14; ++x)
  {
    const glm::dvec3 target(0.43 + 0.14 * (x + 0.5) / 14.0, 0.5, 0.0);
    const auto shade =
      mesolight::ShadeReliefRay(hf, frame, lighting, eye, glm::normalize(target - eye));
    if (!shade || shade->Texture.z < 0.05)
    {
      continue; // the groove's walls only
    }
    const double reference =
      PathTracedIrradiance(hf, frame, shade->Texture, radiance, albedo, 4000, state);
    sumError += std::abs(shade->Indirect.x - reference) / reference;
    sumRatio += shade->Indirect.x / reference;
    ++hits;
  }
  EXPECT_GT(hits, 8);
  if (ratio)
  {
    *ratio = sumRatio / hits;
  }
  return sumError / hits;
}
} // namespace

TEST(ReliefShading, InterReflectionInAGrooveAgainstPathTracing)
{
  // Grooves half as deep as wide and as deep as wide (one twice as deep as wide leaves the
  // multi-bounce series about 15% dark, 19% mean error: the seen walls' visible share then varies
  // more with depth than the shaded point's own stands for).
  for (const double depth : { 0.1, 0.2 })
  {
    double multiRatio = 0.0, oneRatio = 0.0, noneRatio = 0.0;
    const double multi =
      GrooveError(mesolight::ReliefInterReflection::MultiBounce, depth, &multiRatio);
    const double one = GrooveError(mesolight::ReliefInterReflection::OneBounce, depth, &oneRatio);
    const double none = GrooveError(mesolight::ReliefInterReflection::None, depth, &noneRatio);
    std::cout << "indirect light in a V-groove " << depth / 0.2
              << " times as deep as wide (albedo 0.7), mean relative error against path tracing "
                 "(mean ratio): multi-bounce "
              << multi << " (" << multiRatio << "), one bounce " << one << " (" << oneRatio
              << "), none " << none << " (" << noneRatio << ")\n";
    EXPECT_LT(multi, 0.06);
    EXPECT_LT(multi, one); // one bounce of the flat wall's light overestimates a deep groove
    // Negative case: the occluded directions as black leave the groove too dark.
    EXPECT_LT(noneRatio, 0.8);
    EXPECT_GT(none, 2.0 * multi);
  }
}

// The relief mapper's visible-share map (ReliefVisibleShareMap) against the analytic view factor
// of a V-groove as deep as wide, infinitely long (the height field's clamp extends it along v):
// from a point of a wall, the cosine-weighted share of the hemisphere leaving through the
// opening is (sin b - sin a) / 2, a and b the signed angles from the wall's normal to the
// opening's edges in the groove's cross-section (the crossed-strings view factor of a strip;
// Hottel, "Radiant heat transmission"). The negative case, the share around the wall's macro
// normal instead of the relief's, misses it by far more.
TEST(ReliefShading, VisibleShareMapOfAGrooveIsTheAnalyticViewFactor)
{
  const HeightField hf = VGroove(); // opening u in [0.4, 0.6], bottom at u = 0.5, depth 1
  ReliefFrame frame = Square();
  frame.DepthScale = 0.2; // world depth W = 0.2: as deep as wide
  const double w = frame.WorldDepth();
  const int cells = 500;
  const std::vector<float> share = mesolight::ReliefVisibleShareMap(hf, frame, cells, 2, 256);
  ASSERT_EQ(share.size(), static_cast<std::size_t>(2 * 2 * cells));
  double sumError = 0.0, worst = 0.0, sumFlatError = 0.0;
  int count = 0;
  for (int i = 0; i < cells; ++i)
  {
    const double u = (i + 0.5) / cells;
    const double offset = std::abs(u - 0.5);
    if (offset < 0.01 || offset > 0.09)
    {
      if (offset > 0.11)
      {
        EXPECT_EQ(share[2 * i], 1.0f)
          << "the flat wall beside the groove sees the whole hemisphere";
      }
      continue; // the crease at the bottom and the edges: no single wall plane
    }
    // In the cross-section (x along u, z up), mirrored onto the left wall.
    const glm::dvec2 p(0.5 - offset, -w * (1.0 - offset / 0.1));
    const glm::dvec2 normal = glm::normalize(glm::dvec2(w, 0.1));
    const glm::dvec2 tangent = glm::normalize(glm::dvec2(0.1, -w)); // toward the far edge
    const glm::dvec2 nearEdge(0.4, 0.0), farEdge(0.6, 0.0);
    const double sinA = glm::dot(glm::normalize(nearEdge - p), tangent);
    const double sinB = glm::dot(glm::normalize(farEdge - p), tangent);
    ASSERT_GT(glm::dot(farEdge - p, normal), 0.0);
    const double analytic = 0.5 * (sinB - sinA);
    const double error = std::abs(share[2 * i] - analytic);
    EXPECT_GE(share[2 * i + 1], share[2 * i]); // V over the share above the plane
    sumError += error;
    worst = std::max(worst, error);
    const glm::dvec3 hit(u, 0.25, hf.DepthAt(u, 0.25));
    sumFlatError +=
      std::abs(mesolight::ReliefVisibleShare(hf, frame, hit, frame.Normal, 256) - analytic);
    ++count;
  }
  ASSERT_GT(count, 60);
  std::cout << "visible share in a V-groove as deep as wide, " << count << " cells: mean |error| "
            << sumError / count << ", worst " << worst << "; around the macro normal (negative) "
            << sumFlatError / count << "\n";
  EXPECT_LT(sumError / count, 0.015);
  EXPECT_LT(worst, 0.04);
  EXPECT_GT(sumFlatError / count, 5.0 * sumError / count);
  EXPECT_GT(sumFlatError / count, 0.05);
}

// The relief mapper's shadow map of an area light (ReliefEmitterShadowMap) against an
// independent reference: per cell of a V-groove as deep as wide, the share of a square emitter's
// direct irradiance (cos cos_e / r^2) that reaches the cell, over 32 x 32 points of the emitter,
// each tested by a dense march of the height field's DepthAt (not the intersector the map uses).
// The emitter stands to the side above the groove, so its far wall lies in the lip's penumbra.
// The negative case is what the relief mapper did before: one hard shadow ray to the emitter's
// centre (a point light), lit or not.
TEST(ReliefShading, EmitterShadowMapIsTheAreaLightsPenumbra)
{
  const HeightField hf = VGroove(); // opening u in [0.4, 0.6], bottom at u = 0.5, depth 1
  ReliefFrame frame = Square();
  frame.DepthScale = 0.2;                                   // as deep as wide
  const glm::dvec3 lo(-0.1, 0.1, 0.35), hi(0.3, 0.4, 0.35); // the emitter, facing down
  const glm::dvec3 down(0.0, 0.0, -1.0);
  auto emitterPoint = [&](double s, double t)
  { return glm::dvec3(lo.x + s * (hi.x - lo.x), lo.y + t * (hi.y - lo.y), lo.z); };
  std::vector<mesolight::ReliefEmitterSample> samples;
  const int side = 6; // the map's samples, about the CPU renderer's 2 x 4 x 4 per emitter
  for (int a = 0; a < side; ++a)
  {
    for (int b = 0; b < side; ++b)
    {
      mesolight::ReliefEmitterSample e;
      e.Position = emitterPoint((a + 0.5) / side, (b + 0.5) / side);
      e.Normal = down;
      e.RadianceArea = glm::dvec3(1.0);
      samples.push_back(e);
    }
  }
  const int cells = 500;
  const std::vector<float> map = mesolight::ReliefEmitterShadowMap(
    hf, frame, samples, std::vector<int>(samples.size(), 0), 1, cells, 2);
  ASSERT_EQ(map.size(), static_cast<std::size_t>(2 * cells));
  // Lit or not along the straight segment from texture point p toward world direction dir.
  auto reaches = [&](const glm::dvec3& p, const glm::dvec3& dir)
  {
    const glm::dvec3 l = frame.ToTexture(dir);
    if (!(l.z < 0.0))
    {
      return false;
    }
    const double tTop = p.z / -l.z;
    for (int k = 1; k <= 1000; ++k)
    {
      const glm::dvec3 q = p + (tTop * k / 1000.0) * l;
      if (q.z > hf.DepthAt(q.x, q.y) + 1e-4)
      {
        return false;
      }
    }
    return true;
  };
  double mapError = 0.0, hardError = 0.0, penumbraMap = 0.0, penumbraHard = 0.0;
  int count = 0, penumbra = 0;
  for (int i = 0; i < cells; ++i)
  {
    const double u = (i + 0.5) / cells, v = 0.25;
    const double offset = std::abs(u - 0.5);
    if (offset < 0.01 || offset > 0.09)
    {
      continue; // the crease and the edges: no single wall plane
    }
    const glm::dvec3 texture(u, v, hf.DepthAt(u, v));
    const glm::dvec3 point = frame.Point(u, v, texture.z);
    const glm::dvec3 normal = mesolight::ReliefNormalAt(hf, frame, u, v);
    double all = 0.0, lit = 0.0;
    for (int a = 0; a < 32; ++a)
    {
      for (int b = 0; b < 32; ++b)
      {
        const glm::dvec3 toLight = emitterPoint((a + 0.5) / 32, (b + 0.5) / 32) - point;
        const double r2 = glm::dot(toLight, toLight);
        const glm::dvec3 l = toLight / std::sqrt(r2);
        const double weight = glm::dot(normal, l) * -glm::dot(down, l) / r2;
        if (!(weight > 0.0))
        {
          continue;
        }
        all += weight;
        lit += reaches(texture, l) ? weight : 0.0;
      }
    }
    if (!(all > 0.0))
    {
      continue;
    }
    const double reference = lit / all;
    const glm::dvec3 centre = emitterPoint(0.5, 0.5) - point;
    // Where the centre does not face the cell a point light there brings nothing at all: no
    // shadow share to compare (counted as right).
    const double hard = glm::dot(normal, centre) <= 0.0
      ? reference
      : (reaches(texture, glm::normalize(centre)) ? 1.0 : 0.0);
    const double value = map[static_cast<std::size_t>(i)];
    mapError += std::abs(value - reference);
    hardError += std::abs(hard - reference);
    ++count;
    if (reference > 0.05 && reference < 0.95)
    {
      penumbraMap += std::abs(value - reference);
      penumbraHard += std::abs(hard - reference);
      ++penumbra;
    }
  }
  ASSERT_GT(count, 60) << "the emitter lights the groove's far wall";
  ASSERT_GT(penumbra, 10) << "the emitter must cast a penumbra in the groove";
  std::cout << "area light's shadow in a V-groove, " << count << " cells (" << penumbra
            << " in the penumbra): map mean |error| " << mapError / count << " ("
            << penumbraMap / penumbra << " in the penumbra); one hard ray to the centre (negative) "
            << hardError / count << " (" << penumbraHard / penumbra << ")\n";
  EXPECT_LT(mapError / count, 0.03);
  EXPECT_LT(penumbraMap / penumbra, 0.06);
  EXPECT_GT(penumbraHard / penumbra, 0.2);
  EXPECT_GT(penumbraHard / penumbra, 4.0 * penumbraMap / penumbra);
  EXPECT_THROW(mesolight::ReliefEmitterShadowMap(hf, frame, samples, { 0 }, 1, cells, 2),
    std::invalid_argument);
}

// The inter-reflection formula both relief renderers share: one bounce adds (1 - V) a E, multi-
// bounce (1 - V) a V E / (1 - a (1 - V)), none nothing; V = 1 adds nothing.
TEST(ReliefShading, InterReflectedFormula)
{
  using mesolight::ReliefInterReflection;
  const glm::dvec3 e(2.0, 1.0, 0.5), a(0.5, 0.8, 0.0);
  const glm::dvec3 one =
    mesolight::ReliefInterReflected(ReliefInterReflection::OneBounce, 0.6, a, e);
  const glm::dvec3 multi =
    mesolight::ReliefInterReflected(ReliefInterReflection::MultiBounce, 0.6, a, e);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(one[c], 0.4 * a[c] * e[c], 1e-12);
    EXPECT_NEAR(multi[c], 0.4 * a[c] * 0.6 * e[c] / (1.0 - a[c] * 0.4), 1e-12);
  }
  EXPECT_EQ(
    mesolight::ReliefInterReflected(ReliefInterReflection::None, 0.6, a, e), glm::dvec3(0.0));
  EXPECT_EQ(mesolight::ReliefInterReflected(ReliefInterReflection::MultiBounce, 1.0, a, e),
    glm::dvec3(0.0));
  // The series at the seen relief's share Vs: (1 - V) a Vs E / (1 - a (1 - Vs)); Vs = V is the
  // four-argument form.
  const glm::dvec3 seen =
    mesolight::ReliefInterReflected(ReliefInterReflection::MultiBounce, 0.6, 0.3, a, e);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(seen[c], 0.4 * a[c] * 0.3 * e[c] / (1.0 - a[c] * 0.7), 1e-12);
  }
  EXPECT_EQ(
    mesolight::ReliefInterReflected(ReliefInterReflection::MultiBounce, 0.6, 0.6, a, e), multi);
}

// The emitter sample's geometric factor, cos cos_e / r^2, against the point-light law, and zero
// wherever either face turns away: also where both do, where the product of the two cosines alone
// is positive (the negative case a product-only weight passes).
TEST(ReliefShading, EmitterSampleGeometryNeedsBothFacesTurnedToEachOther)
{
  mesolight::ReliefEmitterSample e;
  e.Position = glm::dvec3(0.0, 0.0, 2.0);
  e.Normal = glm::dvec3(0.0, 0.0, -1.0); // faces down, at the point below
  const glm::dvec3 point(0.0), up(0.0, 0.0, 1.0);
  glm::dvec3 l;
  double r2 = 0.0;
  EXPECT_NEAR(mesolight::EmitterSampleGeometry(e, point, up, l, r2), 0.25, 1e-15);
  EXPECT_NEAR(r2, 4.0, 1e-15);
  EXPECT_NEAR(l.z, 1.0, 1e-15);
  // Off to the side, facing down: 45 degrees from both normals, cos 45 cos 45 / r^2.
  e.Position = glm::dvec3(1.0, 0.0, 1.0);
  e.Normal = glm::dvec3(0.0, 0.0, -1.0);
  EXPECT_NEAR(mesolight::EmitterSampleGeometry(e, point, up, l, r2), 0.5 / 2.0, 1e-12);
  // The point turned away (the sample below its plane), the sample still facing it.
  e.Position = glm::dvec3(0.0, 0.0, -2.0);
  e.Normal = glm::dvec3(0.0, 0.0, 1.0);
  EXPECT_EQ(mesolight::EmitterSampleGeometry(e, point, up, l, r2), 0.0);
  // Both turned away: the cosines' product is positive, the sample still delivers nothing.
  e.Normal = glm::dvec3(0.0, 0.0, -1.0);
  const double product = glm::dot(up, l) * -glm::dot(e.Normal, l);
  EXPECT_GT(product, 0.0) << "the negative case: a product-only weight counts this sample";
  EXPECT_EQ(mesolight::EmitterSampleGeometry(e, point, up, l, r2), 0.0);
  // At the point: no direction, nothing.
  e.Position = point;
  EXPECT_EQ(mesolight::EmitterSampleGeometry(e, point, up, l, r2), 0.0);
}
