// SPDX-License-Identifier: BSD-3-Clause
// Tests of the light field's direction set (Wither 2005 §2.4.1.1): counts, constant-time nearest
// direction against brute force, interpolation weights, solid angles against Monte Carlo and
// analytic integrals. Prints the solid-angle spread and lookup timings (docs/vlf.md).
#include "DirectionSet.h"
#include "MathConstants.h"
#include "ParallelFor.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <random>
#include <stdexcept>
#include <vector>

namespace
{
using mesolight::vlf::DirectionSet;

std::vector<glm::vec3> RandomDirections(std::size_t count, unsigned seed)
{
  std::mt19937 random(seed);
  std::normal_distribution<float> normal;
  std::vector<glm::vec3> directions;
  directions.reserve(count);
  while (directions.size() < count)
  {
    const glm::vec3 v(normal(random), normal(random), normal(random));
    const float length = glm::length(v);
    if (length > 1e-6f)
    {
      directions.push_back(v / length);
    }
  }
  return directions;
}

// Runs body(begin, end) over [0, count) on mesolight::ParallelFor (every item is computed alone).
template <typename Body>
void ParallelFor(std::size_t count, Body body)
{
  mesolight::ParallelFor(0, count, 1, body);
}

struct SolidAngleSpread
{
  double Min, Max, Mean, StdDev, Sum;
};
SolidAngleSpread Spread(const std::vector<double>& values)
{
  SolidAngleSpread s{ values[0], values[0], 0.0, 0.0, 0.0 };
  for (const double v : values)
  {
    s.Min = std::min(s.Min, v);
    s.Max = std::max(s.Max, v);
    s.Sum += v;
  }
  s.Mean = s.Sum / values.size();
  for (const double v : values)
  {
    s.StdDev += (v - s.Mean) * (v - s.Mean);
  }
  s.StdDev = std::sqrt(s.StdDev / values.size());
  return s;
}

class DirectionSetSizes : public ::testing::TestWithParam<int>
{
};

TEST(DirectionSet, CountsAndBadArguments)
{
  EXPECT_EQ(DirectionSet(16).Size(), 513u);
  EXPECT_EQ(DirectionSet(32).Size(), 2049u);
  EXPECT_EQ(DirectionSet(64).Size(), 8193u);
  EXPECT_EQ(DirectionSet(1).Size(), 3u);
  EXPECT_EQ(DirectionSet::WithCount(2049).Subdivisions(), 32);
  EXPECT_EQ(DirectionSet::WithCount(51).Size(), 51u); // n = 5
  EXPECT_THROW(DirectionSet::WithCount(514), std::invalid_argument);
  EXPECT_THROW(DirectionSet::WithCount(0), std::invalid_argument);
  EXPECT_THROW(DirectionSet::WithCount(2), std::invalid_argument);
  EXPECT_THROW(DirectionSet(0), std::invalid_argument);
  EXPECT_THROW(DirectionSet(-3), std::invalid_argument);
  const DirectionSet set(16);
  EXPECT_THROW(set.Nearest(glm::vec3(0.0f)), std::invalid_argument);
  EXPECT_THROW(set.Nearest(glm::vec3(NAN, 0.0f, 1.0f)), std::invalid_argument);
  EXPECT_THROW(set.Interpolate(glm::vec3(INFINITY, 0.0f, 1.0f)), std::invalid_argument);
  // Not unit: normalised.
  EXPECT_EQ(set.Nearest(glm::vec3(0.0f, 0.0f, 7.0f)), set.Nearest(glm::vec3(0.0f, 0.0f, 1.0f)));
}

TEST(DirectionSet, EquatorMapRoundTrip)
{
  // The map and its inverse agree everywhere in the diamond, including the equator and the pole.
  std::mt19937 random(3);
  std::uniform_real_distribution<double> uniform(-1.0, 1.0);
  for (int k = 0; k < 100000; ++k)
  {
    glm::dvec2 p(uniform(random), uniform(random));
    if (std::abs(p.x) + std::abs(p.y) > 1.0)
    {
      continue;
    }
    const glm::dvec3 d = DirectionSet::DiamondToHemisphere(p);
    ASSERT_NEAR(glm::length(d), 1.0, 1e-12);
    ASSERT_GE(d.z, 0.0);
    const glm::dvec2 q = DirectionSet::HemisphereToDiamond(d);
    ASSERT_NEAR(q.x, p.x, 1e-9);
    ASSERT_NEAR(q.y, p.y, 1e-9);
  }
}

TEST_P(DirectionSetSizes, UnitUpperHemisphereAndHalfEquator)
{
  const DirectionSet set(GetParam());
  const int n = set.Subdivisions();
  std::vector<glm::vec3> equator;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const glm::vec3& d = set.Direction(i);
    ASSERT_NEAR(glm::length(d), 1.0f, 1e-6f);
    ASSERT_GE(d.z, 0.0f);
    if (d.z == 0.0f)
    {
      equator.push_back(d);
    }
  }
  ASSERT_EQ(equator.size(), 2u * n);
  // No direction is kept together with its antipode, and none twice.
  for (std::size_t a = 0; a < equator.size(); ++a)
  {
    for (std::size_t b = a + 1; b < equator.size(); ++b)
    {
      ASSERT_LT(std::abs(glm::dot(equator[a], equator[b])), 1.0f - 1e-6f);
    }
  }
}

TEST_P(DirectionSetSizes, EachDirectionIsItsOwnNearest)
{
  const DirectionSet set(GetParam());
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    bool flipped = true;
    ASSERT_EQ(set.Nearest(set.Direction(i), &flipped), i);
    ASSERT_FALSE(flipped);
    ASSERT_EQ(set.Nearest(-set.Direction(i), &flipped), i);
    ASSERT_TRUE(flipped);
  }
}

// Nearest against brute force over all 4n^2+2 signed directions +-d on 10^6 random directions;
// also measures the nearest-direction (Voronoi) cells' solid angles by counting. A plausible wrong
// method, the largest interpolation weight, must fail the same check.
TEST_P(DirectionSetSizes, NearestAgreesWithBruteForce)
{
  const DirectionSet set(GetParam());
  constexpr std::size_t Block = 16;
  const std::size_t count = 1000000; // a multiple of Block
  const std::vector<glm::vec3> samples = RandomDirections(count, 17u + GetParam());
  std::vector<float> xs, ys, zs;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    xs.push_back(set.Direction(i).x);
    ys.push_back(set.Direction(i).y);
    zs.push_back(set.Direction(i).z);
  }
  std::vector<std::size_t> nearest(count);
  std::vector<float> errors(count), naiveErrors(count);
  std::vector<char> signOk(count);
  const auto start = std::chrono::steady_clock::now();
  std::vector<float> bruteForce(count, 0.0f); // max over k of |dot(u, d_k)|
  ParallelFor(count / Block,
    [&](std::size_t beginBlock, std::size_t endBlock)
    {
      // Blocks of samples against every direction: the inner loop over samples vectorizes.
      for (std::size_t block = beginBlock; block < endBlock; ++block)
      {
        float ux[Block], uy[Block], uz[Block], best[Block];
        for (std::size_t b = 0; b < Block; ++b)
        {
          const glm::vec3& u = samples[block * Block + b];
          ux[b] = u.x;
          uy[b] = u.y;
          uz[b] = u.z;
          best[b] = 0.0f;
        }
        for (std::size_t k = 0; k < xs.size(); ++k)
        {
          for (std::size_t b = 0; b < Block; ++b)
          {
            const float d = std::abs(xs[k] * ux[b] + ys[k] * uy[b] + zs[k] * uz[b]);
            best[b] = d > best[b] ? d : best[b];
          }
        }
        std::copy(best, best + Block, bruteForce.begin() + block * Block);
      }
    });
  ParallelFor(count,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t s = begin; s < end; ++s)
      {
        const glm::vec3& u = samples[s];
        const float best = bruteForce[s];
        bool flipped = false;
        nearest[s] = set.Nearest(u, &flipped);
        const float dot = glm::dot(set.Direction(nearest[s]), u);
        errors[s] = best - std::abs(dot);
        signOk[s] = std::abs(dot) < 1e-6f || ((dot < 0.0f) == flipped);
        const DirectionSet::Interpolation in = set.Interpolate(u);
        const int largest = static_cast<int>(
          std::max_element(in.Weight.begin(), in.Weight.end()) - in.Weight.begin());
        naiveErrors[s] = best - std::abs(glm::dot(set.Direction(in.Index[largest]), u));
      }
    });
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::size_t wrong = 0, wrongSign = 0, naiveWrong = 0;
  float worst = 0.0f;
  for (std::size_t s = 0; s < count; ++s)
  {
    wrong += errors[s] > 1e-6f;
    worst = std::max(worst, errors[s]);
    wrongSign += !signOk[s];
    naiveWrong += naiveErrors[s] > 1e-6f;
  }
  EXPECT_EQ(wrong, 0u) << "worst dot-product shortfall " << worst;
  EXPECT_EQ(wrongSign, 0u);
  EXPECT_GT(naiveWrong, count / 1000) << "the largest interpolation weight is not the nearest";

  // Nearest-direction cells by Monte Carlo (a uniform sample lands in cell i with probability
  // area_i / 4 pi; a cell is the union of +-d's regions: half of it is the per-direction solid
  // angle).
  std::vector<double> cells(set.Size(), 0.0);
  for (const std::size_t i : nearest)
  {
    cells[i] += 2.0 * mesolight::Pi<double> / count;
  }
  const SolidAngleSpread voronoi = Spread(cells);
  std::printf("[ figures  ] %zu directions: nearest-direction cells (Monte Carlo, 10^6 samples): "
              "min %.3g max %.3g mean %.3g stddev %.3g sr (max/min %.2f, stddev/mean %.1f%%); "
              "%.2f s for brute force + lookups on 2 threads; naive nearest wrong in %.2f%%\n",
    set.Size(), voronoi.Min, voronoi.Max, voronoi.Mean, voronoi.StdDev, voronoi.Max / voronoi.Min,
    100.0 * voronoi.StdDev / voronoi.Mean, seconds, 100.0 * naiveWrong / count);
}

TEST_P(DirectionSetSizes, InterpolationWeights)
{
  const DirectionSet set(GetParam());
  const int n = set.Subdivisions();
  // Vertices are reproduced.
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const DirectionSet::Interpolation in = set.Interpolate(set.Direction(i));
    float onSelf = 0.0f;
    for (int k = 0; k < 3; ++k)
    {
      if (in.Index[k] == i && !in.VertexFlipped[k])
      {
        onSelf += in.Weight[k];
      }
    }
    ASSERT_NEAR(onSelf, 1.0f, 1e-5f) << "direction " << i;
    ASSERT_FALSE(in.Flipped);
  }
  // Random directions: non-negative weights summing to 1; the three signed vertices are around u
  // (within two lattice steps, ~2.9/n rad) and their weighted sum points back at u.
  const std::vector<glm::vec3> samples = RandomDirections(200000, 5u + n);
  for (const glm::vec3& u : samples)
  {
    const DirectionSet::Interpolation in = set.Interpolate(u);
    float sum = 0.0f;
    glm::vec3 blended(0.0f);
    for (int k = 0; k < 3; ++k)
    {
      ASSERT_LT(in.Index[k], set.Size());
      ASSERT_GE(in.Weight[k], 0.0f);
      sum += in.Weight[k];
      const glm::vec3 d =
        in.VertexFlipped[k] ? -set.Direction(in.Index[k]) : set.Direction(in.Index[k]);
      ASSERT_GT(glm::dot(d, u), std::cos(2.9f / n));
      blended += in.Weight[k] * d;
    }
    ASSERT_NEAR(sum, 1.0f, 1e-6f);
    ASSERT_GT(glm::dot(glm::normalize(blended), u), std::cos(0.5f / n));
    if (std::abs(u.z) > 2.0f / n) // above the last ring (z ~ 2/n - 1/n^2) all share u's side
    {
      for (int k = 0; k < 3; ++k)
      {
        ASSERT_EQ(in.VertexFlipped[k], u.z < 0.0f);
      }
    }
  }
}

// The solid angles against an independent Monte Carlo estimate of the same quantity (the integral
// of each direction's interpolation weight over uniformly random directions), and as quadrature
// weights against analytic hemisphere integrals.
TEST_P(DirectionSetSizes, SolidAnglesAgainstMonteCarloAndIntegrals)
{
  const DirectionSet set(GetParam());
  std::vector<double> weights(set.Size());
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    weights[i] = set.SolidAngle(i);
  }
  const SolidAngleSpread spread = Spread(weights);
  EXPECT_NEAR(spread.Sum, 2.0 * mesolight::Pi<double>, 1e-5);
  std::printf("[ figures  ] %zu directions: solid-angle weights min %.4g max %.4g mean %.4g "
              "stddev %.3g sr (max/min %.3f, stddev/mean %.2f%%), sum %.7f (2 pi = %.7f)\n",
    set.Size(), spread.Min, spread.Max, spread.Mean, spread.StdDev, spread.Max / spread.Min,
    100.0 * spread.StdDev / spread.Mean, spread.Sum, 2.0 * mesolight::Pi<double>);

  const std::size_t count = 2000000;
  const std::vector<glm::vec3> samples = RandomDirections(count, 99u);
  std::vector<double> estimate(set.Size(), 0.0);
  for (const glm::vec3& u : samples)
  {
    const DirectionSet::Interpolation in = set.Interpolate(u);
    for (int k = 0; k < 3; ++k)
    {
      estimate[in.Index[k]] += in.Weight[k] * (2.0 * mesolight::Pi<double> / count);
    }
  }
  double sumSquares = 0.0, sumEstimate = 0.0;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    sumSquares += std::pow(estimate[i] / weights[i] - 1.0, 2);
    sumEstimate += estimate[i];
  }
  const double rms = std::sqrt(sumSquares / set.Size());
  // Expected Monte Carlo noise: about 1/sqrt(samples per direction) (~3% for 8193 directions).
  const double samplesPerDirection = double(count) / set.Size();
  EXPECT_LT(rms, 2.0 / std::sqrt(samplesPerDirection)) << "rms relative error " << rms;
  EXPECT_NEAR(sumEstimate, 2.0 * mesolight::Pi<double>, 1e-6);

  // Quadrature of even functions over the hemisphere (the set stands for lines, so each direction
  // carries d and -d): integral of |z| = pi, z^2 = 2 pi / 3, x^2 y^2 = 2 pi / 15.
  double integralAbsZ = 0.0, integralZ2 = 0.0, integralX2Y2 = 0.0;
  for (std::size_t i = 0; i < set.Size(); ++i)
  {
    const glm::dvec3 d(set.Direction(i));
    integralAbsZ += weights[i] * std::abs(d.z);
    integralZ2 += weights[i] * d.z * d.z;
    integralX2Y2 += weights[i] * d.x * d.x * d.y * d.y;
  }
  const double tolerance = 2.0 / (set.Subdivisions() * set.Subdivisions());
  EXPECT_NEAR(integralAbsZ / mesolight::Pi<double>, 1.0, tolerance);
  EXPECT_NEAR(integralZ2 / (2.0 * mesolight::Pi<double> / 3.0), 1.0, tolerance);
  EXPECT_NEAR(integralX2Y2 / (2.0 * mesolight::Pi<double> / 15.0), 1.0, 4.0 * tolerance);
  // Negative check: equal weights 2 pi / size (ignoring the variation) are measurably worse on
  // |z| at the smallest set.
  if (set.Size() == 513)
  {
    double equal = 0.0;
    for (std::size_t i = 0; i < set.Size(); ++i)
    {
      equal += (2.0 * mesolight::Pi<double> / set.Size()) * std::abs(set.Direction(i).z);
    }
    EXPECT_GT(std::abs(equal / mesolight::Pi<double> - 1.0),
      std::abs(integralAbsZ / mesolight::Pi<double> - 1.0));
  }
  std::printf("[ figures  ] %zu directions: quadrature relative errors |z| %.2e, z^2 %.2e, "
              "x^2y^2 %.2e; Monte Carlo rms %.2f%%\n",
    set.Size(), integralAbsZ / mesolight::Pi<double> - 1.0,
    integralZ2 / (2.0 * mesolight::Pi<double> / 3.0) - 1.0,
    integralX2Y2 / (2.0 * mesolight::Pi<double> / 15.0) - 1.0, 100.0 * rms);
}

// The lookup is O(1): Nearest compares a fixed neighbourhood of lattice points whatever the
// set's size (a search over all directions, or one growing with n, fails), on 10^5 random
// directions and at the poles and the equator. The times are printed as figures only.
TEST_P(DirectionSetSizes, NearestExaminesAFixedNumberOfDirections)
{
  const DirectionSet set(GetParam());
  std::vector<glm::vec3> samples = RandomDirections(100000, 7u);
  samples.push_back(glm::vec3(0.0f, 0.0f, 1.0f));
  samples.push_back(glm::vec3(0.0f, 0.0f, -1.0f));
  samples.push_back(glm::vec3(1.0f, 0.0f, 0.0f));
  samples.push_back(glm::vec3(0.0f, -1.0f, 0.0f));
  std::size_t most = 0, total = 0;
  for (const glm::vec3& u : samples)
  {
    std::size_t examined = 0;
    set.Nearest(u, nullptr, &examined);
    most = std::max(most, examined);
    total += examined;
  }
  auto start = std::chrono::steady_clock::now();
  std::size_t checksum = 0;
  for (const glm::vec3& u : samples)
  {
    checksum += set.Nearest(u);
  }
  const double nearest =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  start = std::chrono::steady_clock::now();
  for (const glm::vec3& u : samples)
  {
    checksum += set.Interpolate(u).Index[0];
  }
  const double interpolate =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::printf("[ figures  ] %zu directions: Nearest compares %.2f lattice points on average, %zu "
              "at most; %.0f ns per call, Interpolate %.0f ns (10^5 calls, one thread; checksum "
              "%zu)\n",
    set.Size(), static_cast<double>(total) / samples.size(), most, 1e9 * nearest / samples.size(),
    1e9 * interpolate / samples.size(), checksum);
  EXPECT_GE(most, 4u);
  EXPECT_LE(most, 16u);
}

INSTANTIATE_TEST_SUITE_P(Sizes, DirectionSetSizes, ::testing::Values(16, 32, 64),
  [](const ::testing::TestParamInfo<int>& param)
  { return std::to_string(2 * param.param * param.param + 1); });

} // namespace
