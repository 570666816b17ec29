// SPDX-License-Identifier: BSD-3-Clause
// The light field's automatic resolution (AutomaticSettings.h).
// 1. SmallFeatureWidth against the exact value of a made scene: a 1 x 1 floor (triangle widths
//    0.707) and twenty 1 x 0.01 strips on it (widths 0.01, 17% of the area): the area-weighted
//    10th percentile is the strips' width. Without the strips (the negative) it is the emitter's.
// 2. The strips ask for many lines; the line cap and a small memory budget each bring the choice
//    down, and say so; the floor alone gets the preferred 2049 x 64 x 64. Where the features ask
//    for twice the lines taken (with 2049 directions) the texels are half the cell side, else
//    (513 directions, big faces, lines given) the cell side. Given values are kept.
#include "AutomaticSettings.h"

#include <gtest/gtest.h>

#include <cmath>

namespace
{
using namespace mesolight;
using namespace mesolight::vlf;

TriangleScene Strips(bool withStrips)
{
  TriangleScene scene;
  SceneMaterial grey;
  grey.Diffuse = glm::vec3(0.5f);
  const std::uint32_t g = scene.AddMaterial(grey);
  SceneMaterial lamp = grey;
  lamp.Emission = glm::vec3(1.0f);
  const std::uint32_t l = scene.AddMaterial(lamp);
  scene.AddPolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, g);
  // The emitter: a 0.5 x 0.5 square above the floor, facing it.
  scene.AddPolygon({ { 0.25f, 0.25f, 0.5f }, { 0.25f, 0.75f, 0.5f }, { 0.75f, 0.75f, 0.5f },
                     { 0.75f, 0.25f, 0.5f } },
    l);
  for (int i = 0; withStrips && i < 20; ++i)
  {
    const float y = 0.025f + 0.05f * static_cast<float>(i);
    scene.AddPolygon(
      { { 0, y, 0.01f }, { 1, y, 0.01f }, { 1, y + 0.01f, 0.01f }, { 0, y + 0.01f, 0.01f } }, g);
  }
  return scene;
}
} // namespace

TEST(VLFAutomaticSettings, SmallFeatureWidthIsTheAreaWeightedTenthPercentile)
{
  // 2 area / longest edge of a 1 x 0.01 half: 0.01 / sqrt(1 + 1e-4).
  EXPECT_NEAR(SmallFeatureWidth(Strips(true)), 0.01 / std::sqrt(1.0001), 1e-5);
  // Without the strips, the emitter (0.25 of the area 1.25) holds the 10th percentile: its
  // halves' width 0.5 / sqrt(2).
  EXPECT_NEAR(SmallFeatureWidth(Strips(false)), 0.5 / std::sqrt(2.0), 1e-4);
  EXPECT_EQ(SmallFeatureWidth(TriangleScene()), 0.0f);
}

TEST(VLFAutomaticSettings, FeaturesAskCapsLimit)
{
  const TriangleScene strips = Strips(true);
  AutomaticLimits limits;
  limits.MaxLines = std::uint64_t(1) << 40; // no line cap
  limits.MaxRaysPerSide = 4096;
  limits.MemoryBudget = std::uint64_t(1)
    << 40; // nor a memory limit (the estimate allocates nothing)
  AutomaticChoice c = ChooseAutomaticSettings(strips, limits);
  // diameter sqrt(1 + 1 + 0.25) = 1.5, 2 lines per 0.01: 300, rounded up to a multiple of 8.
  EXPECT_EQ(c.WantedRaysPerSide, 304) << c.Describe();
  EXPECT_EQ(c.Settings.RaysPerSide, 304) << c.Describe();
  EXPECT_EQ(c.Limit, "features");
  EXPECT_EQ(c.Settings.Directions, 8193u);
  EXPECT_EQ(c.Settings.TilesPerSide, 38);
  EXPECT_TRUE(c.Settings.Validate().empty());

  c = ChooseAutomaticSettings(strips); // default line cap: 2049 x 96^2
  EXPECT_EQ(c.Limit, "line cap") << c.Describe();
  EXPECT_LE(static_cast<std::uint64_t>(c.Settings.Directions) * c.Settings.RaysPerSide *
      c.Settings.RaysPerSide,
    AutomaticLimits().MaxLines);
  // The line cap lowers the lines per side, never the directions.
  EXPECT_EQ(c.Settings.RaysPerSide, 96);
  EXPECT_EQ(c.Settings.Directions, 2049u);
  // The strips ask for 256 (the cap of lines per side), over twice the 96 taken: texels of a
  // quarter of the cell side with the final gather, half without.
  EXPECT_FLOAT_EQ(c.Settings.TexelSize, 0.25f * c.Settings.CellSize()) << c.Describe();
  EXPECT_NE(c.Describe().find("texels a quarter of the line spacing"), std::string::npos);
  AutomaticLimits gatherless;
  gatherless.FineTexelRatio = GatherlessFineTexelRatio;
  gatherless.MaxTexelHalvings = 1;
  const AutomaticChoice half = ChooseAutomaticSettings(strips, gatherless);
  EXPECT_FLOAT_EQ(half.Settings.TexelSize, 0.5f * half.Settings.CellSize()) << half.Describe();
  EXPECT_NE(half.Describe().find("texels half the line spacing"), std::string::npos);
  AutomaticLimits noFine;
  noFine.FineTexelRatio = 0.0;
  EXPECT_EQ(ChooseAutomaticSettings(strips, noFine).Settings.TexelSize, 0.0f);
  // With the final gather (the default) any ask beyond the lines taken gets half texels;
  // without it only twice the lines: the strips asking 1.5 times the lines of a lower cap.
  AutomaticLimits lowCap;
  lowCap.MaxRaysPerSide = 4096;
  lowCap.MaxLines = std::uint64_t(1) << 40;
  lowCap.MemoryBudget = std::uint64_t(1) << 40;
  lowCap.MaxLines = static_cast<std::uint64_t>(8193) * 200 * 200;
  const AutomaticChoice capped = ChooseAutomaticSettings(strips, lowCap);
  ASSERT_GT(capped.WantedRaysPerSide, capped.Settings.RaysPerSide) << capped.Describe();
  ASSERT_LT(capped.WantedRaysPerSide, 2 * capped.Settings.RaysPerSide) << capped.Describe();
  EXPECT_GT(capped.Settings.TexelSize, 0.0f) << capped.Describe();
  lowCap.FineTexelRatio = GatherlessFineTexelRatio;
  EXPECT_EQ(ChooseAutomaticSettings(strips, lowCap).Settings.TexelSize, 0.0f);

  // A budget between what 513 and 2049 directions at 96 lines need: 513 x 96 (memory lowers the
  // directions first at the same lines).
  LightFieldSettings at96 = c.Settings;
  at96.TexelSize = 0.0f;
  const std::uint64_t many = EstimateMemory(strips, at96).TotalBytes;
  at96.Directions = 513;
  const std::uint64_t few = EstimateMemory(strips, at96).TotalBytes;
  ASSERT_LT(few, many);
  limits = AutomaticLimits();
  limits.MemoryBudget = few + many; // BudgetShare 0.5: the estimate may use (few + many) / 2
  c = ChooseAutomaticSettings(strips, limits);
  EXPECT_EQ(c.Limit, "memory budget") << c.Describe();
  EXPECT_EQ(c.Settings.RaysPerSide, 96);
  EXPECT_EQ(c.Settings.Directions, 513u);
  EXPECT_EQ(c.Settings.TexelSize, 0.0f); // 513 directions: too few lines for half texels

  // A budget whose half just holds 513 x 32 x 32: only the minimum fits.
  LightFieldSettings minimum;
  minimum.Directions = 513;
  minimum.RaysPerSide = 32;
  minimum.TilesPerSide = 4;
  limits = AutomaticLimits();
  limits.MemoryBudget = 2 * EstimateMemory(strips, minimum).TotalBytes * 21 / 20;
  c = ChooseAutomaticSettings(strips, limits);
  EXPECT_EQ(c.Limit, "memory budget") << c.Describe();
  EXPECT_EQ(c.Settings.RaysPerSide, 32);
  EXPECT_EQ(c.Settings.Directions, 513u);

  // The negative: big faces ask for nothing beyond the preferred lines.
  c = ChooseAutomaticSettings(Strips(false));
  EXPECT_EQ(c.Limit, "the preferred minimum") << c.Describe();
  EXPECT_EQ(c.Settings.RaysPerSide, 64);
  EXPECT_EQ(c.Settings.Directions, 2049u);
  EXPECT_EQ(c.Settings.TexelSize, 0.0f); // nothing asks for finer texels

  EXPECT_THROW(ChooseAutomaticSettings(TriangleScene()), std::invalid_argument);
}

TEST(VLFAutomaticSettings, GivenValuesAreKept)
{
  LightFieldSettings given;
  given.Directions = 0;
  given.RaysPerSide = 40;
  given.TilesPerSide = 0;
  AutomaticChoice c = ResolveAutomaticSettings(Strips(true), given);
  EXPECT_EQ(c.Limit, "given");
  EXPECT_EQ(c.Settings.RaysPerSide, 40);
  EXPECT_EQ(c.Settings.Directions, 513u);
  EXPECT_EQ(c.Settings.TilesPerSide, 5);
  given.Directions = 2049;
  given.RaysPerSide = 0;
  given.TilesPerSide = 0;
  c = ResolveAutomaticSettings(Strips(true), given);
  EXPECT_EQ(c.Settings.Directions, 2049u);
  EXPECT_GT(c.Settings.RaysPerSide, 32);
  EXPECT_EQ(c.Settings.TilesPerSide, c.Settings.RaysPerSide / 8);
  // All automatic: the choice's finer texels (a quarter of the cell with the final gather, half
  // without); lines given: the cell side.
  given.Directions = 0;
  EXPECT_FLOAT_EQ(ResolveAutomaticSettings(Strips(true), given).Settings.TexelSize,
    0.25f * ResolveAutomaticSettings(Strips(true), given).Settings.CellSize());
  EXPECT_FLOAT_EQ(ResolveAutomaticSettings(Strips(true), given, false).Settings.TexelSize,
    0.5f * ResolveAutomaticSettings(Strips(true), given, false).Settings.CellSize());
  given.RaysPerSide = 96;
  EXPECT_EQ(ResolveAutomaticSettings(Strips(true), given).Settings.TexelSize, 0.0f);
}
