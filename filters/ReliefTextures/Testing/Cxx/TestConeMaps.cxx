// SPDX-License-Identifier: BSD-3-Clause
// Cone maps (core/ConeMaps.h): fast search == brute-force oracle, cone stepping with the maps
// never passes the exact first hit (reliefcore/core/HeightFieldTracer.h), the maps are not
// needlessly narrow, the 8-bit encoding never widens a cone, and the min-depth pyramid bounds
// the bilinear surface. The VTK filter: TestConeMapFilter.cxx.
#include "ConeMaps.h"
#include "MathConstants.h"

#include "HeightFieldTracer.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <functional>
#include <iostream>
#include <random>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using mesolight::ConeMapOptions;
using mesolight::HeightField;

struct Map
{
  std::string Name;
  int W;
  int H;
  std::vector<float> Depth;
};

float Clamp01(double x)
{
  return static_cast<float>(std::min(1.0, std::max(0.0, x)));
}

// Small test maps: white noise (worst case: every texel an edge), smooth noise, thin spikes on
// a deep floor, ridges, terraces, a pit, and one ramp with a diagonal gradient.
std::vector<Map> TestMaps()
{
  std::vector<Map> maps;
  std::mt19937 rng(12345);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  auto make = [&](const std::string& name, int w, int h, auto f)
  {
    Map m{ name, w, h, std::vector<float>(static_cast<size_t>(w) * h) };
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        m.Depth[static_cast<size_t>(j) * w + i] = Clamp01(f(i, j));
      }
    }
    maps.push_back(std::move(m));
  };
  make("noise16", 16, 16, [&](int, int) { return uni(rng); });
  make("noise24x17", 24, 17, [&](int, int) { return uni(rng); });
  std::vector<double> coarse(5 * 5);
  for (auto& c : coarse)
  {
    c = uni(rng);
  }
  make("smooth24x17", 24, 17,
    [&](int i, int j)
    {
      const double x = i / 23.0 * 4.0;
      const double y = j / 16.0 * 4.0;
      const int x0 = std::min(3, static_cast<int>(x));
      const int y0 = std::min(3, static_cast<int>(y));
      const double fx = x - x0;
      const double fy = y - y0;
      auto c = [&](int a, int b) { return coarse[static_cast<size_t>(b) * 5 + a]; };
      return (1 - fy) * ((1 - fx) * c(x0, y0) + fx * c(x0 + 1, y0)) +
        fy * ((1 - fx) * c(x0, y0 + 1) + fx * c(x0 + 1, y0 + 1));
    });
  make("spikes20", 20, 20,
    [&](int i, int j) { return ((i * 7 + j * 3) % 11 == 0) ? 0.05 + 0.2 * uni(rng) : 0.9; });
  make("ridges18x22", 18, 22,
    [&](int i, int j) { return (i % 6 == 2 || (i + j) % 9 == 0) ? 0.1 : 0.8 - 0.02 * j; });
  make("steps20x16", 20, 16, [&](int i, int j) { return 0.2 * ((i + j / 3) / 4); });
  make("pit16", 16, 16,
    [&](int i, int j)
    {
      const double r = std::hypot(i - 7.3, j - 8.1);
      return r < 4.0 ? 1.0 - 0.15 * r : 0.2;
    });
  make("ramp17x13", 17, 13, [&](int i, int j) { return 0.03 * i + 0.05 * j; });
  return maps;
}

// CPU relaxed / conservative cone stepping, as the GPU will do it: at p (above the surface),
// read the ratio c and the depth D bilinearly at p.xy, step dt = c (D - p.z) / (|s| + c) in
// depth (the ray moves |s| texture widths per unit depth), for up to `steps` steps; then a
// binary search between the last two points. Returns the final t (ray depth increment; the
// ray direction has z = 1). maxPenetration receives how far below the surface any stepping
// point got (0 if none).
double ConeStep(const HeightField& hf, const HeightField& cones, const glm::dvec3& origin,
  const glm::dvec3& dir, double speed, int steps, int binarySteps, double& maxPenetration)
{
  maxPenetration = 0.0;
  auto gap = [&](double t)
  {
    const glm::dvec3 p = origin + t * dir;
    return p.z - hf.DepthAt(p.x, p.y); // >= 0: on or below
  };
  double tPrev = 0.0;
  double t = 0.0;
  for (int k = 0; k < steps; ++k)
  {
    const glm::dvec3 p = origin + t * dir;
    const double d = hf.DepthAt(p.x, p.y);
    if (p.z >= d)
    {
      maxPenetration = std::max(maxPenetration, p.z - d);
      break;
    }
    const double c = cones.DepthAt(p.x, p.y);
    tPrev = t;
    t = std::min(1.0 - origin.z, t + c * (d - p.z) / (speed + c));
  }
  if (gap(t) < 0.0)
  {
    return t; // never reached the surface: stopped above it
  }
  double lo = tPrev;
  double hi = t;
  for (int k = 0; k < binarySteps; ++k)
  {
    const double mid = 0.5 * (lo + hi);
    (gap(mid) >= 0.0 ? hi : lo) = mid;
  }
  return hi;
}

struct PropertyResult
{
  int Rays = 0;
  int PastFirstHit = 0; // stepping + binary search ended after the exact first hit
  int WentBelow = 0;    // a stepping point was below the surface by more than the tolerance
  std::string FirstFailure;
};

constexpr double kTolerance = 1e-4;

PropertyResult CheckStepping(const Map& m, const std::vector<float>& ratios, double scale, int rays,
  unsigned seed, bool conservative)
{
  const HeightField hf(m.W, m.H, m.Depth);
  std::vector<float> scaled(ratios);
  for (float& c : scaled)
  {
    c = static_cast<float>(c * scale);
  }
  const HeightField cones(m.W, m.H, scaled);
  std::mt19937 rng(seed);
  std::uniform_real_distribution<double> uni(0.0, 1.0);
  PropertyResult result;
  for (int r = 0; r < rays; ++r)
  {
    const double angle = 2.0 * mesolight::Pi<double> * uni(rng);
    const double speed = std::exp(std::log(0.02) + uni(rng) * (std::log(4.0) - std::log(0.02)));
    const glm::dvec3 origin(uni(rng), uni(rng), 0.0);
    // speed texture widths per unit depth; v distances count H/W times their v extent.
    const glm::dvec3 dir(
      speed * std::cos(angle), speed * std::sin(angle) * m.W / static_cast<double>(m.H), 1.0);
    const auto hit = mesolight::IntersectFirst(hf, origin, dir, 1.0);
    if (!hit)
    {
      continue; // cannot happen: depth 1 is never above the surface
    }
    ++result.Rays;
    double penetration = 0.0;
    const double t = ConeStep(hf, cones, origin, dir, speed, 200, 40, penetration);
    const bool past = t > hit->t + kTolerance;
    // A conservative march only ever stops at (or, by round-off, a hair below) the surface.
    const bool below = conservative && penetration > kTolerance;
    result.PastFirstHit += past ? 1 : 0;
    result.WentBelow += below ? 1 : 0;
    if ((past || below) && result.FirstFailure.empty())
    {
      std::ostringstream os;
      os << m.Name << ": ray from (" << origin.x << ", " << origin.y << ") angle " << angle
         << " speed " << speed << ": stepping ended at t = " << t << ", first hit at " << hit->t
         << ", penetration " << penetration;
      result.FirstFailure = os.str();
    }
  }
  return result;
}

// A step of relaxed cone stepping for the cone of ratio cw at texel p that is below the surface
// just under texel q and above it just beyond q (so it crosses the surface twice).
bool ViolatesRelaxed(const HeightField& hf, int pi, int pj, int bi, int bj, double cw)
{
  const int w = hf.Width();
  const int h = hf.Height();
  const double dp = hf.Texel(pi, pj);
  const double dq = hf.Texel(bi, bj);
  const double rq = std::hypot(bi - pi, bj - pj) / w;
  // (u, v) per width unit along the direction p -> q; a v extent counts H / W times.
  const glm::dvec2 theta((bi - pi) / (rq * w), (bj - pj) / (rq * w) * w / static_cast<double>(h));
  const glm::dvec2 uvp((pi + 0.5) / w, (pj + 0.5) / h);
  for (double beta : { 1e-4, 1e-3, 1e-2, 1e-1, 1.0 }) // ray depth per width unit
  {
    for (double eps : { 1e-9, 1e-7, 1e-5 })
    {
      double z0 = dq + eps - beta * rq;
      if (z0 < 0.0) // enter at the top: the shallowest start
      {
        z0 = 0.0;
        beta = (dq + eps) / rq;
      }
      if (z0 >= dp)
      {
        continue;
      }
      const double rEnd = (dp - z0) / (beta + 1.0 / cw); // where the step meets the cone
      const glm::dvec2 uvq = uvp + rq * theta;
      if (z0 + beta * rq < hf.DepthAt(uvq.x, uvq.y))
      {
        continue; // not below at q
      }
      for (double delta : { 1e-6, 1e-5, 1e-4, 1e-3, 1e-2, 3e-2 })
      {
        const double r = rq + delta;
        const glm::dvec2 uv = uvp + r * theta;
        if (r <= rEnd && z0 + beta * r < hf.DepthAt(uv.x, uv.y))
        {
          return true;
        }
      }
    }
  }
  return false;
}

ConeMapOptions Serial()
{
  ConeMapOptions o;
  o.Threads = 1;
  return o;
}
} // namespace

TEST(ConeMaps, FastSearchEqualsBruteForceOracle)
{
  for (const Map& m : TestMaps())
  {
    for (bool safe : { false, true })
    {
      ConeMapOptions options;
      options.BilinearSafe = safe;
      options.Threads = 2;
      options.Tolerance = 0.0f; // exact search: bit-identical to the oracle
      const auto relaxed = mesolight::ComputeRelaxedConeMap(m.Depth.data(), m.W, m.H, options);
      const auto relaxedOracle =
        mesolight::ComputeRelaxedConeMapBruteForce(m.Depth.data(), m.W, m.H, options);
      const auto conservative =
        mesolight::ComputeConservativeConeMap(m.Depth.data(), m.W, m.H, options);
      const auto conservativeOracle =
        mesolight::ComputeConservativeConeMapBruteForce(m.Depth.data(), m.W, m.H, options);
      ASSERT_EQ(relaxed.size(), m.Depth.size());
      ASSERT_EQ(conservative.size(), m.Depth.size());
      EXPECT_EQ(relaxed, relaxedOracle) << m.Name;
      EXPECT_EQ(conservative, conservativeOracle) << m.Name;
      for (size_t k = 0; k < relaxed.size(); ++k)
      {
        // Relaxed cones are never narrower than conservative ones, both within [0, CMax].
        EXPECT_GE(relaxed[k], conservative[k]) << m.Name << " texel " << k;
        EXPECT_GE(conservative[k], 0.0f);
        EXPECT_LE(relaxed[k], mesolight::kConeMaxRatio);
      }
    }
  }
}

TEST(ConeMaps, ToleranceKeepsConesValidAndWithinTheFactor)
{
  // With the default tolerance the fast search may stop early, but only downward (narrower, still
  // valid) and by at most the factor: oracle / (1 + tol) <= fast <= oracle.
  const double tol = ConeMapOptions().Tolerance;
  ASSERT_GT(tol, 0.0);
  int narrower = 0;
  for (const Map& m : TestMaps())
  {
    for (bool relaxedType : { true, false })
    {
      const auto fast = relaxedType
        ? mesolight::ComputeRelaxedConeMap(m.Depth.data(), m.W, m.H)
        : mesolight::ComputeConservativeConeMap(m.Depth.data(), m.W, m.H);
      const auto oracle = relaxedType
        ? mesolight::ComputeRelaxedConeMapBruteForce(m.Depth.data(), m.W, m.H)
        : mesolight::ComputeConservativeConeMapBruteForce(m.Depth.data(), m.W, m.H);
      ASSERT_EQ(fast.size(), oracle.size());
      for (size_t k = 0; k < fast.size(); ++k)
      {
        EXPECT_LE(fast[k], oracle[k]) << m.Name << " texel " << k;
        EXPECT_GE(fast[k], oracle[k] / (1.0 + tol) * (1.0 - 1e-6)) << m.Name << " texel " << k;
        narrower += fast[k] < oracle[k] ? 1 : 0;
      }
    }
  }
  std::cout << "tolerance: " << narrower << " texels narrower than the oracle\n";
}

TEST(ConeMaps, KnownValues)
{
  // Flat: nothing shallower anywhere, every cone at the clamp.
  const std::vector<float> flat(9 * 7, 0.4f);
  for (float c : mesolight::ComputeRelaxedConeMap(flat.data(), 9, 7, Serial()))
  {
    EXPECT_EQ(c, mesolight::kConeMaxRatio);
  }
  // A 1D step in a 4 x 1 map: depths 0, 1, 1, 1. The texel next to the wall sees it one texel
  // (1/4 width) away and 1 deeper: c = 0.25. Seen from texel 3 the wall texel 0 is a falling
  // edge only if the surface gets deeper leaving it away from texel 3, i.e. toward -u, where
  // it is clamped flat: no falling edge, the relaxed cone is at the clamp.
  const std::vector<float> step{ 0.0f, 1.0f, 1.0f, 1.0f };
  ConeMapOptions raw = Serial();
  raw.BilinearSafe = false;
  const auto conservative = mesolight::ComputeConservativeConeMap(step.data(), 4, 1, raw);
  EXPECT_FLOAT_EQ(conservative[1], 0.25f);
  EXPECT_FLOAT_EQ(conservative[3], 0.75f);
  EXPECT_EQ(conservative[0], mesolight::kConeMaxRatio);
  const auto relaxed = mesolight::ComputeRelaxedConeMap(step.data(), 4, 1, raw);
  EXPECT_EQ(relaxed[3], mesolight::kConeMaxRatio);
  // A plateau between two pits: 1, 0, 0, 1 (plus padding). From texel 3 the falling edge is
  // texel 1? No: leaving texel 1 toward -u goes down into texel 0 -> it IS a falling edge for
  // apexes on its +u side, 2 texels from texel 3.
  const std::vector<float> plateau{ 1.0f, 0.0f, 0.0f, 1.0f };
  const auto relaxed2 = mesolight::ComputeRelaxedConeMap(plateau.data(), 4, 1, raw);
  EXPECT_FLOAT_EQ(relaxed2[3], 0.5f);
  EXPECT_FLOAT_EQ(relaxed2[0], 0.5f);
  // Bilinear-safe (cell bound, core/ConeMaps.cxx): texel 3 of the step map is a corner of cell
  // 3 (texels 2..3), whose nearest constraining cell is cell 1 (texels 0..1) two cells away: the
  // projected corner distance is 2 texels (2/4 width) over a depth difference of 1 -> 0.5.
  // Texel 0 is a corner of cell 1, which spans the wall: Lipschitz bound 1 / (1 * 4) = 0.25.
  // Relaxed: cell 1 rises toward -u, seen from texel 3 nothing can fall: the clamp.
  const auto safe = mesolight::ComputeConservativeConeMap(step.data(), 4, 1, Serial());
  EXPECT_FLOAT_EQ(safe[0], 0.25f);
  EXPECT_FLOAT_EQ(safe[3], 0.5f);
  const auto safeRelaxed = mesolight::ComputeRelaxedConeMap(step.data(), 4, 1, Serial());
  EXPECT_EQ(safeRelaxed[3], mesolight::kConeMaxRatio);
  EXPECT_FLOAT_EQ(safeRelaxed[0], 0.25f);
}

TEST(ConeMaps, SteppingNeverPassesTheFirstHit)
{
  for (const Map& m : TestMaps())
  {
    const auto relaxed = mesolight::ComputeRelaxedConeMap(m.Depth.data(), m.W, m.H, Serial());
    const PropertyResult r = CheckStepping(m, relaxed, 1.0, 3000, 7, false);
    EXPECT_GT(r.Rays, 2900);
    EXPECT_EQ(r.PastFirstHit, 0) << "relaxed: " << r.FirstFailure;

    const auto conservative =
      mesolight::ComputeConservativeConeMap(m.Depth.data(), m.W, m.H, Serial());
    const PropertyResult c = CheckStepping(m, conservative, 1.0, 3000, 8, true);
    EXPECT_EQ(c.PastFirstHit, 0) << "conservative: " << c.FirstFailure;
    EXPECT_EQ(c.WentBelow, 0) << "conservative: " << c.FirstFailure;
  }
}

TEST(ConeMaps, SteppingTestHasTeeth)
{
  // Negative tests: cones widened by a modest factor must make the stepping property fail for
  // some rays, and relaxed cones used as if they were conservative must dive below the surface.
  // The factor at which failures start is printed: how much room the provable bound leaves.
  const double scales[] = { 1.25, 1.5, 2.0, 3.0 };
  int relaxedFailures[4] = {};
  int conservativeFailures[4] = {};
  int relaxedAsConservative = 0;
  for (const Map& m : TestMaps())
  {
    const auto relaxed = mesolight::ComputeRelaxedConeMap(m.Depth.data(), m.W, m.H, Serial());
    const auto conservative =
      mesolight::ComputeConservativeConeMap(m.Depth.data(), m.W, m.H, Serial());
    for (int k = 0; k < 4; ++k)
    {
      relaxedFailures[k] += CheckStepping(m, relaxed, scales[k], 1000, 9, false).PastFirstHit;
      const PropertyResult c = CheckStepping(m, conservative, scales[k], 1000, 10, true);
      conservativeFailures[k] += c.PastFirstHit + c.WentBelow;
    }
  }
  // A smooth dome on a flat floor: relaxed cones reach over the dome, conservative ones cannot.
  Map dome{ "dome24", 24, 24, std::vector<float>(24 * 24) };
  for (int j = 0; j < 24; ++j)
  {
    for (int i = 0; i < 24; ++i)
    {
      const double r2 = (std::pow(i - 11.5, 2) + std::pow(j - 11.5, 2)) / 49.0;
      dome.Depth[static_cast<size_t>(j) * 24 + i] =
        Clamp01(0.9 - 0.8 * std::pow(std::max(0.0, 1.0 - r2), 2.0));
    }
  }
  const auto domeRelaxed =
    mesolight::ComputeRelaxedConeMap(dome.Depth.data(), dome.W, dome.H, Serial());
  const auto domeConservative =
    mesolight::ComputeConservativeConeMap(dome.Depth.data(), dome.W, dome.H, Serial());
  double widest = 0.0;
  for (size_t k = 0; k < domeRelaxed.size(); ++k)
  {
    widest = std::max(widest, static_cast<double>(domeRelaxed[k] / domeConservative[k]));
  }
  std::cout << "dome: relaxed cones up to " << widest << " x the conservative ones\n";
  EXPECT_EQ(CheckStepping(dome, domeRelaxed, 1.0, 3000, 12, false).PastFirstHit, 0);
  // The bilinear-safe relaxed cones are only modestly wider than conservative ones (printed
  // above), so the checker's ability to see a relaxed cone dive is shown with the wider
  // per-texel-sample relaxed cones.
  ConeMapOptions samples = Serial();
  samples.BilinearSafe = false;
  const auto domeSampleRelaxed =
    mesolight::ComputeRelaxedConeMap(dome.Depth.data(), dome.W, dome.H, samples);
  relaxedAsConservative += CheckStepping(dome, domeSampleRelaxed, 1.0, 3000, 11, true).WentBelow;
  for (int k = 0; k < 4; ++k)
  {
    std::cout << "cones x" << scales[k] << ": relaxed " << relaxedFailures[k]
              << " rays past the first hit, conservative " << conservativeFailures[k]
              << " rays past it or below the surface (of 8000 each)\n";
  }
  std::cout << "relaxed cones stepped as conservative: " << relaxedAsConservative
            << " rays below the surface\n";
  EXPECT_GT(relaxedFailures[1], 0); // 1.5x
  EXPECT_GT(conservativeFailures[1], 0);
  EXPECT_GT(relaxedAsConservative, 0);
}

TEST(ConeMaps, NotNeedlesslyNarrow)
{
  // On the raw maps (BilinearSafe off), a ratio 5% wider than computed must violate the
  // definition at texel p (a violating ray exists), unless it is at the clamp.
  ConeMapOptions raw = Serial();
  raw.BilinearSafe = false;
  int checkedConservative = 0;
  int checkedRelaxed = 0;
  int relaxedNeighbourBound = 0;
  std::mt19937 rng(5);
  for (const Map& m : TestMaps())
  {
    const HeightField hf(m.W, m.H, m.Depth);
    const auto cons = mesolight::ComputeConservativeConeMap(m.Depth.data(), m.W, m.H, raw);
    const auto relaxed = mesolight::ComputeRelaxedConeMap(m.Depth.data(), m.W, m.H, raw);
    for (int sample = 0; sample < 40; ++sample)
    {
      const int pi = static_cast<int>(rng() % m.W);
      const int pj = static_cast<int>(rng() % m.H);
      const size_t p = static_cast<size_t>(pj) * m.W + pi;
      const double dp = m.Depth[p];
      // Conservative: some surface sample lies strictly inside the 1.05x cone.
      const double wider = 1.05 * cons[p];
      if (cons[p] < mesolight::kConeMaxRatio)
      {
        bool inside = false;
        for (int qj = 0; qj < m.H && !inside; ++qj)
        {
          for (int qi = 0; qi < m.W && !inside; ++qi)
          {
            const double dq = hf.Texel(qi, qj);
            const double r = std::hypot(qi - pi, qj - pj) / m.W;
            inside = dq < dp && r < wider * (dp - dq);
          }
        }
        EXPECT_TRUE(inside) << m.Name << " conservative texel (" << pi << ", " << pj << ")";
        ++checkedConservative;
      }
      if (!(relaxed[p] < mesolight::kConeMaxRatio))
      {
        continue;
      }
      // Relaxed: for each binding texel q (ties included) that is a falling edge seen from p
      // itself (not only from a neighbouring apex position), build the violating step: a
      // segment from the axis above p that passes just below q, then comes out above the
      // surface beyond it, inside the 1.05x cone.
      bool anyBinding = false;
      bool fromP = false;
      bool violated = false;
      for (int bj = 0; bj < m.H; ++bj)
      {
        for (int bi = 0; bi < m.W; ++bi)
        {
          const double dq = hf.Texel(bi, bj);
          if (!(dq < dp) ||
            !mesolight::IsFallingEdgeNear(m.Depth.data(), m.W, m.H, pi, pj, bi, bj) ||
            static_cast<float>(std::hypot(bi - pi, bj - pj) / m.W / (dp - dq)) != relaxed[p])
          {
            continue;
          }
          anyBinding = true;
          if (!mesolight::IsFallingEdge(m.Depth.data(), m.W, m.H, pi, pj, bi, bj))
          {
            continue;
          }
          fromP = true;
          violated = violated || ViolatesRelaxed(hf, pi, pj, bi, bj, 1.05 * relaxed[p]);
        }
      }
      ASSERT_TRUE(anyBinding) << m.Name;
      if (!fromP)
      {
        ++relaxedNeighbourBound;
        continue;
      }
      ++checkedRelaxed;
      EXPECT_TRUE(violated) << m.Name << " relaxed texel (" << pi << ", " << pj << ") ratio "
                            << relaxed[p];
    }
  }
  EXPECT_GT(checkedConservative, 100);
  EXPECT_GT(checkedRelaxed, 50);
  std::cout << "narrowness: " << checkedConservative << " conservative, " << checkedRelaxed
            << " relaxed texels checked; " << relaxedNeighbourBound
            << " relaxed texels bound by an edge seen only from a neighbouring apex position\n";
}

TEST(ConeMaps, EightBitEncodingNeverWidens)
{
  EXPECT_EQ(mesolight::EncodeConeRatio8(0.0f), 0);
  EXPECT_EQ(mesolight::EncodeConeRatio8(std::nanf("")), 0);
  EXPECT_EQ(mesolight::EncodeConeRatio8(-1.0f), 0);
  EXPECT_EQ(mesolight::DecodeConeRatio8(0), 0.0f);
  EXPECT_FLOAT_EQ(mesolight::DecodeConeRatio8(mesolight::EncodeConeRatio8(1.0f)), 127.0f / 128.0f);
  EXPECT_LT(mesolight::EncodeConeRatio8(mesolight::kConeMaxRatio), 255);
  std::mt19937 rng(3);
  std::uniform_real_distribution<double> uni(-6.0, 3.5);
  int previous = 0;
  for (int k = 0; k < 200000; ++k)
  {
    const float c = static_cast<float>(std::pow(10.0, uni(rng)));
    const std::uint8_t code = mesolight::EncodeConeRatio8(c);
    EXPECT_LE(mesolight::DecodeConeRatio8(code), c) << c;
    if (code < 254)
    {
      EXPECT_GT(mesolight::DecodeConeRatio8(static_cast<std::uint8_t>(code + 1)), c) << c;
    }
  }
  for (int code = 0; code < 255; ++code)
  {
    // Exact codes round-trip, and the code grid is monotone.
    const float c = mesolight::DecodeConeRatio8(static_cast<std::uint8_t>(code));
    EXPECT_EQ(mesolight::EncodeConeRatio8(c), code);
    EXPECT_GE(code, previous);
    previous = code;
  }
}

TEST(ConeMaps, MinDepthPyramidBoundsTheBilinearSurface)
{
  for (const Map& m : TestMaps())
  {
    const HeightField hf(m.W, m.H, m.Depth);
    const auto pyramid = mesolight::ComputeMinDepthPyramid(m.Depth.data(), m.W, m.H);
    ASSERT_FALSE(pyramid.empty());
    int lw = 0;
    int lh = 0;
    for (size_t level = 0; level < pyramid.size(); ++level)
    {
      ASSERT_TRUE(mesolight::MinDepthPyramidLevelSize(m.W, m.H, static_cast<int>(level), lw, lh));
      EXPECT_EQ(pyramid[level].size(), static_cast<size_t>(lw) * lh) << m.Name << " " << level;
    }
    EXPECT_EQ(pyramid.back().size(), 1u);
    EXPECT_FALSE(
      mesolight::MinDepthPyramidLevelSize(m.W, m.H, static_cast<int>(pyramid.size()), lw, lh));
    EXPECT_EQ(pyramid[0].size(), static_cast<size_t>(m.W + 1) * (m.H + 1));
    // Level 0: every cell's value <= the surface anywhere in the cell (dense samples, band
    // cells sampled half a texel beyond the outermost centres), and attained at a corner.
    const int cw = m.W + 1;
    for (int cj = 0; cj <= m.H; ++cj)
    {
      for (int ci = 0; ci <= m.W; ++ci)
      {
        const float v = pyramid[0][static_cast<size_t>(cj) * cw + ci];
        double lowest = 2.0;
        for (int sy = 0; sy <= 8; ++sy)
        {
          for (int sx = 0; sx <= 8; ++sx)
          {
            const double gx = ci - 1 + sx / 8.0; // grid coordinate, texel centres on integers
            const double gy = cj - 1 + sy / 8.0;
            const double d = hf.DepthAt((gx + 0.5) / m.W, (gy + 0.5) / m.H);
            EXPECT_LE(v, d + 1e-7) << m.Name << " cell " << ci << ", " << cj;
            lowest = std::min(lowest, d);
          }
        }
        EXPECT_NEAR(v, lowest, 1e-6) << m.Name << " cell " << ci << ", " << cj;
      }
    }
    // Each coarser value is the minimum of its children.
    for (size_t level = 1; level < pyramid.size(); ++level)
    {
      int pw = 0, ph = 0, chw = 0, chh = 0;
      mesolight::MinDepthPyramidLevelSize(m.W, m.H, static_cast<int>(level), pw, ph);
      mesolight::MinDepthPyramidLevelSize(m.W, m.H, static_cast<int>(level - 1), chw, chh);
      for (int j = 0; j < ph; ++j)
      {
        for (int i = 0; i < pw; ++i)
        {
          // Children 2i, 2i+1; the last parent also takes the odd child left over.
          float expected = 2.0f;
          const int yEnd = (j == ph - 1) ? chh - 1 : 2 * j + 1;
          const int xEnd = (i == pw - 1) ? chw - 1 : 2 * i + 1;
          for (int y = 2 * j; y <= yEnd && y < chh; ++y)
          {
            for (int x = 2 * i; x <= xEnd && x < chw; ++x)
            {
              expected = std::min(expected, pyramid[level - 1][static_cast<size_t>(y) * chw + x]);
            }
          }
          EXPECT_EQ(pyramid[level][static_cast<size_t>(j) * pw + i], expected);
        }
      }
    }
  }
  EXPECT_TRUE(mesolight::ComputeMinDepthPyramid(nullptr, 0, 0).empty());
  int lw = 0, lh = 0;
  ASSERT_TRUE(mesolight::MinDepthPyramidLevelSize(5, 3, 1, lw, lh)); // 6 x 4 -> 3 x 2
  EXPECT_EQ(lw, 3);
  EXPECT_EQ(lh, 2);
}

TEST(ConeMaps, ProgressAndAbort)
{
  const Map m = TestMaps()[2];
  std::vector<double> reported;
  ConeMapOptions options;
  options.Progress = [&](double f)
  {
    reported.push_back(f);
    return true;
  };
  EXPECT_EQ(
    mesolight::ComputeRelaxedConeMap(m.Depth.data(), m.W, m.H, options).size(), m.Depth.size());
  ASSERT_GE(reported.size(), 2u);
  EXPECT_EQ(reported.front(), 0.0);
  EXPECT_EQ(reported.back(), 1.0);
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  int calls = 0;
  options.Progress = [&](double) { return ++calls < 3; };
  EXPECT_TRUE(mesolight::ComputeConservativeConeMap(m.Depth.data(), m.W, m.H, options).empty());
  EXPECT_EQ(calls, 3);
  // Rows on all of vtkSMPTools' threads or on the calling thread only: the same cones, for
  // both searches (the bilinear-safe and the per-texel one).
  for (bool safe : { true, false })
  {
    ConeMapOptions parallel;
    parallel.BilinearSafe = safe;
    ConeMapOptions serial = Serial();
    serial.BilinearSafe = safe;
    EXPECT_EQ(mesolight::ComputeRelaxedConeMap(m.Depth.data(), m.W, m.H, parallel),
      mesolight::ComputeRelaxedConeMap(m.Depth.data(), m.W, m.H, serial));
    EXPECT_EQ(mesolight::ComputeConservativeConeMap(m.Depth.data(), m.W, m.H, parallel),
      mesolight::ComputeConservativeConeMap(m.Depth.data(), m.W, m.H, serial));
  }
  EXPECT_TRUE(mesolight::ComputeRelaxedConeMap(m.Depth.data(), 0, 3).empty());
}
