// SPDX-License-Identifier: BSD-3-Clause
// ReliefShading on a walled relief (HeightField::Edge::Walled, a relief on a wall whose border
// meets the wall's plane in side walls) against exact CPU evaluations: the indirect light in the
// slot along its top edge against Monte-Carlo paths bouncing in it (the negative case, the series
// at the shaded point's own share, is off by twice as much), the seen-share map against the marched
// seen share (reading the side walls' shares too), the maps split by rows between processes
// against the whole maps, and the side walls' map against the analytic view factor of a slot's
// wall (the negative case, the border texel's share). The open relief's tests are in
// TestReliefShading.cxx.
#include "ReliefShadingTestScene.h"

#include "MathConstants.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <iostream>
#include <stdexcept>
#include <vector>

namespace
{
using mesolight::HeightField;
using mesolight::ReliefFrame;
using mesolight::ReliefLighting;
using namespace mesolight::test; // Square, UniformLighting, PathTracedIrradiance

// The slot along the top edge of scripts/bench-vlf-relief.sh's procedural brick map, walled as a
// relief on a wall is: 3 of 64 texels at depth 1 along v = 1, a bevel of 6 texels up to the
// bricks at depth 0.05; as deep as in that bench, 4.3 times as deep as wide at the bottom.
HeightField WalledSlot()
{
  const int n = 64;
  std::vector<float> depth;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const int below = n - 1 - j; // texels below the top row
      depth.push_back(below < 3 ? 1.0f
          : below < 9           ? static_cast<float>(0.05 + 0.95 * (1.0 - (below - 2) / 7.0))
                                : 0.05f);
    }
  }
  return HeightField(n, n, depth, HeightField::Edge::Walled);
}

// The walled slot's maps as the relief mapper's set-up makes them (depth scale 0.2, 32
// directions): the visible-share map and the seen-share map read from it, on a w x h grid.
struct SlotMaps
{
  HeightField Field;
  ReliefFrame Frame;
  int W;
  int H;
  int Count;
  std::vector<float> Share;
  std::vector<float> Seen;
};

SlotMaps MakeSlotMaps(int w, int h)
{
  ReliefFrame frame = Square();
  frame.DepthScale = 0.2;
  const int count = 32;
  const HeightField hf = WalledSlot();
  std::vector<float> share = mesolight::ReliefVisibleShareMap(hf, frame, w, h, count);
  std::vector<float> seen = mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count);
  return { hf, frame, w, h, count, std::move(share), std::move(seen) };
}

// The slot seen from below and in front, as the bench's camera sees the top edge: its side wall,
// its bottom and the bevel. The indirect irradiance under uniform light by the method (the
// multi-bounce series at the seen relief's visible share) and by the series at the shaded point's
// own share, against paths bouncing in the walled slot: mean relative errors and ratios.
void WalledSlotErrors(double& seen, double& own, double& seenRatio, double& ownRatio, int& walls)
{
  const HeightField hf = WalledSlot();
  ReliefFrame frame = Square();
  frame.DepthScale = 0.2;
  const double radiance = 1.0, albedo = 0.7;
  ReliefLighting lighting = UniformLighting(radiance, albedo);
  const glm::dvec3 eye(0.5, 0.6, 1.0);
  const double flat = mesolight::Pi<double> * radiance; // the flat wall's irradiance
  unsigned state = 4321u;
  seen = own = seenRatio = ownRatio = 0.0;
  walls = 0;
  int hits = 0;
  for (int k = 0; k < 24; ++k)
  {
    const glm::dvec3 target(0.5, 0.86 + 0.14 * (k + 0.5) / 24.0, 0.0);
    const auto shade =
      mesolight::ShadeReliefRay(hf, frame, lighting, eye, glm::normalize(target - eye));
    if (!shade || shade->Texture.z < 0.3)
    {
      continue; // the slot and the lower bevel only
    }
    const glm::dvec2 wall(0.0, shade->Texture.y >= 1.0 ? -1.0 : 0.0);
    walls += wall.y != 0.0 ? 1 : 0;
    const double reference =
      PathTracedIrradiance(hf, frame, shade->Texture, radiance, albedo, 4000, state, wall);
    // With uniform light the radiance-weighted share is the cosine-weighted V.
    const double v = shade->IndirectVisible;
    const double ownSeries = shade->Indirect.x - shade->InterReflected.x +
      mesolight::ReliefInterReflected(
        mesolight::ReliefInterReflection::MultiBounce, v, glm::dvec3(albedo), glm::dvec3(flat))
        .x;
    seen += std::abs(shade->Indirect.x - reference) / reference;
    own += std::abs(ownSeries - reference) / reference;
    seenRatio += shade->Indirect.x / reference;
    ownRatio += ownSeries / reference;
    ++hits;
  }
  EXPECT_GT(hits, 12);
  seen /= hits;
  own /= hits;
  seenRatio /= hits;
  ownRatio /= hits;
}
} // namespace

// The walled slot along a relief's top edge (scripts/bench-vlf-relief.sh's procedural map): its
// bottom and side wall see mostly the slot's own walls, deeper and more enclosed than themselves.
// The multi-bounce series at the seen relief's visible share (ReliefSeenShare) against paths
// bouncing in the slot; the negative case, the series at the shaded point's own share (the
// relief seen taken to be occluded like the shaded point), is off by twice as much.
TEST(ReliefShading, InterReflectionInAWalledSlotAgainstPathTracing)
{
  double seen = 0.0, own = 0.0, seenRatio = 0.0, ownRatio = 0.0;
  int walls = 0;
  WalledSlotErrors(seen, own, seenRatio, ownRatio, walls);
  std::cout << "indirect light in a walled slot (albedo 0.7, " << walls
            << " points on its side wall), mean relative error against path tracing (mean "
               "ratio): seen share "
            << seen << " (" << seenRatio << "), the shaded point's own share " << own << " ("
            << ownRatio << ")\n";
  EXPECT_GT(walls, 2);
  EXPECT_LT(seen, 0.08); // measured 0.056
  EXPECT_GT(own, 0.1);   // measured 0.124: too bright on the bottom, too dark on the wall
  EXPECT_GT(own, 1.8 * seen);
}

// The relief mapper's seen-share map (ReliefSeenShareMap: the seen points' shares read from the
// visible-share map) against ReliefSeenShare marched at every seen point, over the walled slot's
// rows: close, and far from the cells' own share (the negative case, what the map held before).
TEST(ReliefShading, SeenShareMapFollowsTheMarchedSeenShare)
{
  const auto [hf, frame, w, h, count, share, seen] = MakeSlotMaps(8, 64);
  ASSERT_EQ(seen.size(), static_cast<std::size_t>(w * h));
  double sumError = 0.0, sumOwn = 0.0;
  int cells = 0;
  for (int j = h - 12; j < h; ++j) // the slot and its bevel
  {
    for (int i = 0; i < w; ++i)
    {
      const double u = (i + 0.5) / w, v = (j + 0.5) / h;
      const glm::dvec3 hit(u, v, hf.DepthAt(u, v));
      const double marched = mesolight::ReliefSeenShare(
        hf, frame, hit, mesolight::ReliefNormalAt(hf, frame, u, v), count);
      if (share[2 * (j * w + i)] >= 1.0f)
      {
        EXPECT_EQ(seen[j * w + i], 1.0f); // nothing occluded: nothing seen
        continue;
      }
      sumError += std::abs(seen[j * w + i] - marched);
      sumOwn += std::abs(share[2 * (j * w + i)] - marched);
      ++cells;
    }
  }
  ASSERT_GT(cells, 40);
  std::cout << "seen share over " << cells << " cells of a walled slot: map against marched, mean "
            << "|error| " << sumError / cells << "; the cells' own share (negative) "
            << sumOwn / cells << "\n";
  EXPECT_LT(sumError / cells, 0.03);
  EXPECT_GT(sumOwn / cells, 3.0 * sumError / cells);
  EXPECT_THROW(
    mesolight::ReliefSeenShareMap(hf, frame, share, w + 1, h, count), std::invalid_argument);
}

// The seen-share map reading what each direction met from the visible-share map's pass
// (ReliefDirectionHits, what the relief's map set-up does) instead of marching the directions
// again: the visible-share map bit for bit; the seen shares within float rounding of the marched
// ones, whole and split by rows; the noted directions are the share's; hits noted wrongly (every
// direction leaving; every surface point moved to the shaded cell itself: the negative cases)
// change the map; hits of the wrong size are refused.
TEST(ReliefShading, SeenShareMapReadsTheFirstPassHits)
{
  using mesolight::ReliefDirectionHits;
  const auto [hf, frame, w, h, count, share, seen] = MakeSlotMaps(8, 37);
  ReliefDirectionHits hits;
  ASSERT_EQ(mesolight::ReliefVisibleShareMap(hf, frame, w, h, count, {}, {}, &hits), share);
  ASSERT_EQ(hits.Kinds.size(), static_cast<std::size_t>(w * h * count));
  ASSERT_EQ(hits.Where.size(), 2 * hits.Kinds.size());
  std::size_t left = 0, walls = 0, surface = 0;
  for (std::uint8_t kind : hits.Kinds)
  {
    left += kind == ReliefDirectionHits::Leaves ? 1 : 0;
    surface += kind == ReliefDirectionHits::Surface ? 1 : 0;
    walls += kind >= ReliefDirectionHits::WallU0 && kind <= ReliefDirectionHits::WallV1 ? 1 : 0;
  }
  double meanShare = 0.0;
  for (int c = 0; c < w * h; ++c)
  {
    meanShare += share[2 * c];
  }
  // The noted directions are the share's: V is the share of the count directions that leave.
  EXPECT_NEAR(static_cast<double>(left) / (w * h * count), meanShare / (w * h), 1e-6);
  EXPECT_GT(walls, 100u); // the slot's wall
  EXPECT_GT(surface, 100u);
  const auto largestChange = [](const std::vector<float>& a, const std::vector<float>& b)
  {
    double largest = 0.0;
    for (std::size_t c = 0; c < a.size(); ++c)
    {
      largest = std::max(largest, std::abs(static_cast<double>(a[c]) - b[c]));
    }
    return largest;
  };
  const std::vector<float> read =
    mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, {}, &hits);
  std::cout << "seen shares read from the first pass's hits against marched again: largest "
            << "change " << largestChange(read, seen) << "\n";
  EXPECT_LT(largestChange(read, seen), 1e-5);
  for (int processes = 2; processes <= 3; ++processes)
  {
    for (int p = 0; p < processes; ++p)
    {
      const mesolight::GridRows rows{ p, processes };
      ReliefDirectionHits ownHits;
      mesolight::ReliefVisibleShareMap(hf, frame, w, h, count, {}, rows, &ownHits);
      EXPECT_LT(largestChange(
                  mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, rows, &ownHits),
                  mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, rows)),
        1e-5);
    }
  }
  ReliefDirectionHits allLeave = hits;
  std::fill(allLeave.Kinds.begin(), allLeave.Kinds.end(), ReliefDirectionHits::Leaves);
  const std::vector<float> wrong =
    mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, {}, &allLeave);
  EXPECT_EQ(*std::min_element(wrong.begin(), wrong.end()), 1.0f); // nothing occluded, as noted
  ReliefDirectionHits ownCell = hits;
  for (std::size_t d = 0; d < ownCell.Kinds.size(); ++d)
  {
    const std::size_t cell = d / static_cast<std::size_t>(count);
    ownCell.Kinds[d] = ownCell.Kinds[d] == ReliefDirectionHits::Leaves
      ? ReliefDirectionHits::Leaves
      : ReliefDirectionHits::Surface;
    ownCell.Where[2 * d] = static_cast<float>((cell % w + 0.5) / w);
    ownCell.Where[2 * d + 1] = static_cast<float>((cell / w + 0.5) / h);
  }
  EXPECT_GT(largestChange(
              mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, {}, &ownCell), seen),
    0.1);
  ReliefDirectionHits tooShort = hits;
  tooShort.Kinds.pop_back();
  EXPECT_THROW(mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, {}, &tooShort),
    std::invalid_argument);
  tooShort = hits;
  tooShort.Where.pop_back();
  EXPECT_THROW(mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, {}, &tooShort),
    std::invalid_argument);
}

// The seen-share map reading the side walls' shares (ReliefWallVisibleShareMap, what the relief
// mapper reads for a pixel on a wall) for the directions that meet a wall, instead of marching
// each such point's directions: close to the map that marches them and, in the slot, as close to
// the marched seen share; walls read as black (the negative case) darken the slot's seen shares.
// The walls' shares are ReliefWallShareMap's first two values, which takes them in place of its
// own march; split by rows they sum to the whole; a wrong size is refused.
TEST(ReliefShading, SeenShareMapReadsTheSideWallsShares)
{
  const auto [hf, frame, w, h, count, share, seen] = MakeSlotMaps(8, 64);
  const int levels = 8;
  const std::vector<float> walls =
    mesolight::ReliefWallVisibleShareMap(hf, frame, w, levels, count);
  ASSERT_EQ(walls.size(), static_cast<std::size_t>(2 * w * 4 * levels));
  const std::vector<float> full =
    mesolight::ReliefWallShareMap(hf, frame, share, w, h, levels, count);
  const std::vector<float> reusing = mesolight::ReliefWallShareMap(
    hf, frame, share, w, h, levels, count, {}, {}, {}, nullptr, &walls);
  double wallSeenChange = 0.0;
  for (std::size_t c = 0; c < walls.size() / 2; ++c)
  {
    ASSERT_EQ(full[4 * c], walls[2 * c]);
    ASSERT_EQ(full[4 * c + 1], walls[2 * c + 1]);
    ASSERT_EQ(reusing[4 * c], walls[2 * c]);
    ASSERT_EQ(reusing[4 * c + 1], walls[2 * c + 1]);
    wallSeenChange += std::abs(reusing[4 * c + 2] - full[4 * c + 2]) / (walls.size() / 2);
  }
  const mesolight::ReliefWallShares read{ &walls, levels };
  const std::vector<float> seenRead =
    mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, {}, nullptr, read);
  const std::vector<float> black(walls.size(), 0.0f);
  const std::vector<float> seenBlack = mesolight::ReliefSeenShareMap(
    hf, frame, share, w, h, count, {}, {}, nullptr, mesolight::ReliefWallShares{ &black, levels });
  double change = 0.0, blackChange = 0.0, readError = 0.0, marchedError = 0.0;
  int cells = 0;
  for (int j = h - 12; j < h; ++j) // the slot and its bevel
  {
    for (int i = 0; i < w; ++i)
    {
      const std::size_t c = static_cast<std::size_t>(j) * w + i;
      if (share[2 * c] >= 1.0f)
      {
        continue;
      }
      const double u = (i + 0.5) / w, v = (j + 0.5) / h;
      const double marched = mesolight::ReliefSeenShare(hf, frame,
        glm::dvec3(u, v, hf.DepthAt(u, v)), mesolight::ReliefNormalAt(hf, frame, u, v), count);
      change += std::abs(seenRead[c] - seen[c]);
      blackChange += std::abs(seenBlack[c] - seen[c]);
      readError += std::abs(seenRead[c] - marched);
      marchedError += std::abs(seen[c] - marched);
      ++cells;
    }
  }
  ASSERT_GT(cells, 40);
  std::cout << "seen shares over " << cells << " cells of a walled slot, the walls' shares read "
            << "against marched: mean change " << change / cells << " (walls read as black, "
            << "negative: " << blackChange / cells << "); against the marched seen share "
            << readError / cells << " (walls marched: " << marchedError / cells
            << "); the walls' own seen shares change by " << wallSeenChange << " on average\n";
  EXPECT_LT(change / cells, 0.01);
  EXPECT_LT(readError / cells, 0.03);
  EXPECT_GT(blackChange / cells, 5.0 * change / cells);
  EXPECT_LT(wallSeenChange, 0.01);
  for (int processes = 2; processes <= 3; ++processes)
  {
    std::vector<float> sum(walls.size(), 0.0f);
    for (int p = 0; p < processes; ++p)
    {
      const std::vector<float> part = mesolight::ReliefWallVisibleShareMap(
        hf, frame, w, levels, count, {}, mesolight::GridRows{ p, processes });
      for (std::size_t k = 0; k < part.size(); ++k)
      {
        sum[k] += part[k];
      }
    }
    EXPECT_EQ(sum, walls) << processes << " processes";
  }
  const std::vector<float> tooShort(walls.size() - 1, 1.0f);
  EXPECT_THROW(mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, {}, nullptr,
                 mesolight::ReliefWallShares{ &tooShort, levels }),
    std::invalid_argument);
  EXPECT_THROW(mesolight::ReliefWallShareMap(
                 hf, frame, share, w, h, levels, count, {}, {}, {}, nullptr, &tooShort),
    std::invalid_argument);
  EXPECT_THROW(mesolight::ReliefWallVisibleShareMap(hf, frame, w, 0, count), std::invalid_argument);
}

// The maps split by rows between processes (GridRows, what MPI ranks compute): the shares of 1,
// 2 and 3 processes summed equal the one-process maps bit for bit, each share holds its rows
// only, and the sum without one share (a rank's rows left 0, the negative case) does not.
TEST(ReliefShading, ShareMapsSplitByRowsSumToTheWholeMap)
{
  // 37 rows: not a multiple of the process counts.
  const auto [hf, frame, w, h, count, share, seen] = MakeSlotMaps(8, 37);
  for (int processes = 2; processes <= 3; ++processes)
  {
    std::vector<float> shareSum(share.size(), 0.0f), seenSum(seen.size(), 0.0f);
    std::vector<float> lastShareMissing;
    for (int p = 0; p < processes; ++p)
    {
      const mesolight::GridRows rows{ p, processes };
      const std::vector<float> part =
        mesolight::ReliefVisibleShareMap(hf, frame, w, h, count, {}, rows);
      // The seen share reads the whole visible-share map (cells in any row).
      const std::vector<float> partSeen =
        mesolight::ReliefSeenShareMap(hf, frame, share, w, h, count, {}, rows);
      ASSERT_EQ(part.size(), share.size());
      for (int j = 0; j < h; ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          const std::size_t c = static_cast<std::size_t>(j) * w + i;
          if (j % processes != p)
          {
            ASSERT_EQ(part[2 * c], 0.0f) << "row " << j << " is another process's";
            ASSERT_EQ(partSeen[c], 0.0f);
          }
        }
      }
      if (p == processes - 1)
      {
        lastShareMissing = shareSum;
      }
      for (std::size_t k = 0; k < share.size(); ++k)
      {
        shareSum[k] += part[k];
      }
      for (std::size_t k = 0; k < seen.size(); ++k)
      {
        seenSum[k] += partSeen[k];
      }
    }
    EXPECT_EQ(shareSum, share) << processes << " processes";
    EXPECT_EQ(seenSum, seen) << processes << " processes";
    EXPECT_NE(lastShareMissing, share) << "the sum without the last process's rows";
  }
  EXPECT_THROW(
    mesolight::ReliefVisibleShareMap(hf, frame, w, h, count, {}, mesolight::GridRows{ 2, 2 }),
    std::invalid_argument);
}

// The side walls' map (ReliefWallShareMap, the relief mapper's wall rows) against the analytic
// view factor: a flat-bottomed slot 16 of 256 texels wide and twice as deep along the walled top
// edge (v = 1). In the cross-section a point of the wall y below the lip, facing -v, sees the room
// through the mouth, from the lip straight above (sin 1) to the far edge (sin y / sqrt(s^2 +
// y^2)): V = (1 - y / sqrt(s^2 + y^2)) / 2 (crossed strings), 0.5 at the lip, 0.05 at the foot.
// The negative case is what the mapper read on a wall before: the border texel row's share (the
// slot bottom's, the same all down the wall). Also: the map split by rows between processes sums
// to the whole map bit for bit (GridRows), and a wall where the border is at the surface is 1.
TEST(ReliefShading, WallShareMapIsTheSlotWallsViewFactor)
{
  const int n = 256, slot = 16;
  std::vector<float> depth;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      depth.push_back(j >= n - slot ? 1.0f : 0.0f);
    }
  }
  const HeightField hf(n, n, depth, HeightField::Edge::Walled);
  ReliefFrame frame = Square();
  frame.DepthScale = 2.0 * slot / n; // world depth 0.125: twice the slot's width
  const double w = frame.WorldDepth();
  // The mouth's width: the step's ramp runs between the texel centres either side of it, and the
  // wall sees its top.
  const double s = (slot + 0.5) / n;
  const int count = 256, levels = 8, width = 64;
  const std::vector<float> share = mesolight::ReliefVisibleShareMap(hf, frame, width, n, count);
  const std::vector<float> walls =
    mesolight::ReliefWallShareMap(hf, frame, share, width, n, levels, count);
  ASSERT_EQ(walls.size(), static_cast<std::size_t>(4 * width * 4 * levels));
  const auto cell = [&](int wall, int level, int i)
  { return &walls[4 * ((static_cast<std::size_t>(wall) * levels + level) * width + i)]; };
  double sumError = 0.0, sumBorderError = 0.0, worst = 0.0;
  int cells = 0;
  for (int i = 0; i < width; ++i)
  {
    const double u = (i + 0.5) / width;
    if (std::abs(u - 0.5) > 0.1)
    {
      continue; // away from the walls at u = 0 and 1, where the slot is not infinitely long
    }
    const float border = share[2 * (static_cast<std::size_t>(n - 1) * width + i)];
    for (int level = 0; level < levels; ++level)
    {
      const double y = w * (level + 0.5) / levels;
      const double analytic = 0.5 * (1.0 - y / std::sqrt(s * s + y * y));
      const float* v = cell(3, level, i); // the wall at v = 1
      const double error = std::abs(v[0] - analytic);
      EXPECT_NEAR(v[1], std::min(1.0, v[0] / 0.5), 0.05) << "half its hemisphere is behind";
      EXPECT_EQ(v[3], 1.0f) << "no emitter samples: unshadowed";
      sumError += error;
      worst = std::max(worst, error);
      sumBorderError += std::abs(border - analytic);
      ++cells;
    }
  }
  ASSERT_GT(cells, 40);
  std::cout << "side wall of a slot twice as deep as wide, " << cells
            << " cells: mean |V - view factor| " << sumError / cells << ", worst " << worst
            << "; the border texel's share (negative) " << sumBorderError / cells << "\n";
  EXPECT_LT(sumError / cells, 0.015);
  EXPECT_LT(worst, 0.04);
  EXPECT_GT(sumBorderError / cells, 5.0 * sumError / cells);
  // The wall at u = 0 beside the flat surface (depth 0 at its border): no wall, all 1.
  EXPECT_EQ(cell(0, 2, width / 4)[0], 1.0f);
  EXPECT_EQ(cell(2, 5, width / 2)[2], 1.0f);

  // Split by rows (GridRows) over 2 and 3 processes: the sum is the whole map; without one
  // process's rows (the negative case) it is not.
  const int few = 32; // directions: the split is what is checked here
  const std::vector<float> fewShare = mesolight::ReliefVisibleShareMap(hf, frame, 8, 16, few);
  const std::vector<float> whole =
    mesolight::ReliefWallShareMap(hf, frame, fewShare, 8, 16, 3, few);
  for (int processes = 2; processes <= 3; ++processes)
  {
    std::vector<float> sum(whole.size(), 0.0f), withoutLast;
    for (int p = 0; p < processes; ++p)
    {
      if (p == processes - 1)
      {
        withoutLast = sum;
      }
      const std::vector<float> part = mesolight::ReliefWallShareMap(
        hf, frame, fewShare, 8, 16, 3, few, {}, {}, mesolight::GridRows{ p, processes });
      ASSERT_EQ(part.size(), whole.size());
      for (std::size_t k = 0; k < part.size(); ++k)
      {
        sum[k] += part[k];
      }
    }
    EXPECT_EQ(sum, whole) << processes << " processes";
    EXPECT_NE(withoutLast, whole);
  }
  EXPECT_THROW(
    mesolight::ReliefWallShareMap(hf, frame, fewShare, 9, 16, 3, few), std::invalid_argument);
}
