// SPDX-License-Identifier: BSD-3-Clause
// mesolight::BoundTraversalOracle: the fewest fetches of an exact traversal of per-cell depth
// bounds told the right level at every step, against the floor without navigation
// (CountBoundReachingCells) and a plain walk of every level-0 cell.
#include "BoundTraversalOracle.h"
#include "HeightFieldTracer.h"

#include "MathConstants.h"
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <optional>
#include <random>
#include <vector>

namespace
{
using mesolight::BoundTraversalOracle;
using mesolight::HeightField;

// Rolling terrain with noise: coarse cells are cleared high up, fine ones near the crests.
HeightField Terrain(int n, unsigned seed)
{
  std::mt19937 rng(seed);
  std::uniform_real_distribution<float> noise(0.0f, 0.08f);
  std::vector<float> depth;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double x = double(i) / n, y = double(j) / n;
      depth.push_back(static_cast<float>(0.5 + 0.2 * std::sin(9.0 * x) * std::cos(7.0 * y) +
                        0.15 * std::sin(31.0 * x + 17.0 * y)) +
        noise(rng));
    }
  }
  return HeightField(n, n, depth);
}

// Level-0 cells a walk of every cell visits from where the ray reaches the map's top to its hit.
int WalkedCells(const HeightField& hf, glm::dvec3 origin, glm::dvec3 dir, double tHit)
{
  float top = 1.0f;
  for (int j = 0; j < hf.Height(); ++j)
  {
    for (int i = 0; i < hf.Width(); ++i)
    {
      top = std::min(top, hf.Texel(i, j));
    }
  }
  const double t0 = std::max(0.0, (top - origin.z) / dir.z);
  const glm::dvec3 a = origin + t0 * dir, b = origin + tHit * dir;
  const double gx = std::abs(b.x - a.x) * hf.Width(), gy = std::abs(b.y - a.y) * hf.Height();
  return static_cast<int>(std::floor(gx) + std::floor(gy)) + 1;
}
} // namespace

TEST(BoundTraversalOracle, FlatMapFetchesOnlyTheHitCell)
{
  const HeightField hf(32, 32, std::vector<float>(32 * 32, 0.4f));
  const BoundTraversalOracle oracle(hf);
  const glm::dvec3 origin(0.3, 0.6, 0.0), dir(0.7, -0.2, 0.1);
  const auto hit = mesolight::IntersectFirst(hf, origin, dir, 100.0);
  ASSERT_TRUE(hit);
  EXPECT_EQ(oracle.Fetches(origin, dir, hit->t, 2), 1);
  EXPECT_EQ(oracle.Fetches(origin, dir, hit->t, 0), 1);
}

TEST(BoundTraversalOracle, BetweenTheFloorAndAWalkAndFewerWithMoreLevels)
{
  // Grazing rays (80-87 degrees from the wall's normal) over rolling terrain. Per ray: the floor
  // (the cells the ray must be shown to pass) <= the oracle <= a walk of every cell; summed over
  // the rays, storing every level saves fetches over storing levels 2 and up, and both save most of
  // the walk's.
  const HeightField hf = Terrain(128, 3);
  const BoundTraversalOracle oracle(hf);
  EXPECT_EQ(oracle.GetNumberOfLevels(), 8); // 129^2 cells: 129, 64, 32, 16, 8, 4, 2, 1
  std::mt19937 rng(11);
  std::uniform_real_distribution<double> unit(0.0, 1.0);
  long long floorSum = 0, storedSum = 0, allSum = 0, walkSum = 0;
  for (int n = 0; n < 400; ++n)
  {
    const double theta = (80.0 + 7.0 * unit(rng)) * mesolight::Pi<double> / 180.0;
    const double phi = 2.0 * mesolight::Pi<double> * unit(rng);
    // Texture space of a wall whose depth 1 lies 0.04 wall widths deep (bench relief's scale).
    const glm::dvec3 dir(
      std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta) / 0.04);
    const double u = unit(rng);
    const glm::dvec3 origin(u, unit(rng), 0.0);
    const auto hit = mesolight::IntersectFirst(hf, origin, dir, 100.0);
    ASSERT_TRUE(hit);
    const int floor = mesolight::CountBoundReachingCells(hf, origin, dir, hit->t);
    const int stored = oracle.Fetches(origin, dir, hit->t, 2);
    const int all = oracle.Fetches(origin, dir, hit->t, 0);
    const int walk = WalkedCells(hf, origin, dir, hit->t);
    EXPECT_GE(floor, 1) << n;
    EXPECT_GE(all, floor) << n;
    EXPECT_GE(stored, floor) << n;
    EXPECT_LE(stored, walk + 2) << n; // a cleared coarse cell costs at most the cells it skips
    floorSum += floor;
    storedSum += stored;
    allSum += all;
    walkSum += walk;
  }
  std::cout << "fetches over 400 rays: floor " << floorSum << ", oracle over every level " << allSum
            << ", over levels 2 and up " << storedSum << ", walk " << walkSum << std::endl;
  EXPECT_LT(allSum, storedSum);
  EXPECT_LT(2 * storedSum, walkSum);
}

TEST(BoundTraversalOracle, BadInputFetchesNothing)
{
  const HeightField hf(8, 8, std::vector<float>(64, 0.5f));
  const BoundTraversalOracle oracle(hf);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  EXPECT_EQ(oracle.Fetches({ 0.5, 0.5, 0.0 }, { 0.1, 0.0, 1.0 }, -1.0, 2), 0);
  EXPECT_EQ(oracle.Fetches({ 0.5, 0.5, 0.0 }, { 0.1, 0.0, 0.0 }, 1.0, 2), 0); // horizontal
  EXPECT_EQ(oracle.Fetches({ nan, 0.5, 0.0 }, { 0.1, 0.0, 1.0 }, 1.0, 2), 0);
  // A level past the top is the top; a negative one is every level.
  EXPECT_EQ(oracle.Fetches({ 0.5, 0.5, 0.0 }, { 0.1, 0.0, 1.0 }, 0.5, 99), 1);
  EXPECT_EQ(oracle.Fetches({ 0.5, 0.5, 0.0 }, { 0.1, 0.0, 1.0 }, 0.5, -3), 1);
}
