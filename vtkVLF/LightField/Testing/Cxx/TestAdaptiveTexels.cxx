// SPDX-License-Identifier: BSD-3-Clause
// Texels per surface from the field's own light (AdaptiveTexels.h,
// LightFieldSettings::SurfaceTexelLevels) against independent references:
// 1. The variation measure on textures set by hand: a 5:1 step and stripes are refined, flat and
//    linearly varying light coarsened where coarsening is asked for (bilinear reads hold a
//    linear gradient at any texel size; by default nothing is coarsened), a surface too small to
//    coarsen keeps its texels; noise of two independent estimates is not read as variation (the
//    negative: one estimate alone refines it); a steep fall-off in the border rows alone refines
//    (the negative: the first rule's interior rows do not see it).
// 2. The levels set the texels (twice / half the side per level), the estimate follows, and a
//    field file keeps them; levels for another surface count are refused.
// 3. Shadows of floating plates under a small emitter, read on the floor the way a pixel reads
//    them (bilinear between texel centres, within 1.5 texels of the shadow edges), against the
//    path tracer: the gathered field at the scene's uniform texels (the negative) fails the
//    error bound the adaptive texels meet, and the plates' flat-lit tops get fewer texels when
//    coarsening is asked for.
// 4. The contact shadow of a low box on a floor against the path tracer: the rule (refining on
//    top of the contact halvings) meets the bound; the first rule (the levels instead of the
//    contact halvings: the first pass's base texels do not show the shadow) is the negative.
// 5. The gather budget: by hand, the refinements with the best gain per added texel are taken
//    first up to the budget, coarsening pays for refining, and unbounded (the negative) the
//    measured levels exceed it; on the low box's scene no budget leaves the contact texels,
//    unbounded refines beyond them.
#include "AdaptiveTexels.h"
#include "FinalGather.h"
#include "PathTracedTexels.h"
#include "Propagation.h"
#include "Snapshot.h"
#include "TextureComparison.h"
#include "VLFTestScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace
{
using namespace mesolight;
using namespace mesolight::vlf;
using mesolight::vlftest::PathTraced;

// A 2 x 2 floor under a 0.4 emitter at height 1, at texels of 0.02 in unit-sphere units (the
// floor about 67 texels per side), few lines: only the structure is used.
std::unique_ptr<LightField> SmallField(const std::vector<std::int8_t>& levels = {})
{
  LightFieldSettings settings;
  settings.Directions = 33;
  settings.RaysPerSide = 16;
  settings.TilesPerSide = 2;
  settings.TexelSize = 0.02f;
  settings.SurfaceTexelLevels = levels;
  TriangleScene scene = MakeEmitterOverFloor(0.4f, 1.0f, 2.0f, 0.5f, 10.0f);
  // A small panel on the side, 0.2 x 0.2: about 7 texels per side, too small to coarsen.
  SceneMaterial grey;
  grey.Name = "panel";
  grey.Diffuse = glm::vec3(0.5f);
  scene.AddPolygon({ { -0.9f, -0.9f, 0.5f }, { -0.7f, -0.9f, 0.5f }, { -0.7f, -0.7f, 0.5f },
                     { -0.9f, -0.7f, 0.5f } },
    scene.AddMaterial(grey));
  return LightField::Build(scene, settings);
}

constexpr std::uint32_t Floor = 0, Panel = 2; // GroupSurfaces' order: floor, emitter, panel

// Fills surface s's texels with f(a, b).
template <typename F>
void Fill(LightField& field, std::vector<glm::vec3>& texels, std::uint32_t s, F f)
{
  const Surface& surface = field.Surfaces()[s];
  for (int b = 0; b < surface.TextureHeight; ++b)
  {
    for (int a = 0; a < surface.TextureWidth; ++a)
    {
      texels[surface.TexelOffset + static_cast<std::size_t>(b) * surface.TextureWidth + a] =
        glm::vec3(f(a, b));
    }
  }
}

TEST(VLFAdaptiveTexels, RefinesAStepCoarsensFlatLightAndIgnoresNoise)
{
  std::unique_ptr<LightField> field = SmallField();
  ASSERT_EQ(field->Surfaces().size(), 3u);
  const Surface& floor = field->Surfaces()[Floor];
  ASSERT_GE(std::min(floor.TextureWidth, floor.TextureHeight), 16);
  ASSERT_LT(field->Surfaces()[Panel].TextureWidth, 16);
  std::vector<glm::vec3> texels(field->TexelCount(), glm::vec3(1.0f));
  const int w = floor.TextureWidth;
  const auto levelsOf = [&](const std::vector<glm::vec3>& one, const std::vector<glm::vec3>& two)
  {
    const std::vector<SurfaceVariation> v = MeasureLightVariation(*field, one, two);
    std::printf("floor defect %.2f%% (noise %.2f%%), panel %.2f%%\n", 100.0 * v[Floor].Defect,
      100.0 * v[Floor].Noise, 100.0 * v[Panel].Defect);
    return ChooseTexelLevels(*field, v, FirstRuleAdaptiveTexelOptions());
  };

  // By default nothing is coarsened.
  EXPECT_EQ(ChooseTexelLevels(*field, MeasureLightVariation(*field, texels))[Floor], 0);
  // Flat light: doubled on the floor; the small panel keeps its texels.
  std::vector<std::int8_t> levels = levelsOf(texels, {});
  EXPECT_EQ(levels[Floor], 1);
  EXPECT_EQ(levels[1], 0); // the emitter
  EXPECT_EQ(levels[Panel], 0);
  // A linear gradient (bilinear reads hold it exactly): coarsened too.
  Fill(*field, texels, Floor, [&](int a, int) { return 0.2f + 1.6f * a / w; });
  EXPECT_EQ(levelsOf(texels, {})[Floor], 1);
  // A 5:1 shadow step across the floor every 4 texels: quartered.
  Fill(*field, texels, Floor, [](int a, int) { return (a / 4) % 2 == 0 ? 1.0f : 0.2f; });
  EXPECT_EQ(levelsOf(texels, {})[Floor], -2);
  // Three steps: halved (the mean defect, 3 x 2/3 x 0.8 / w, is what the pixels would gain).
  Fill(*field, texels, Floor, [&](int a, int) { return (4 * a / w) % 2 == 0 ? 1.0f : 0.2f; });
  EXPECT_EQ(levelsOf(texels, {})[Floor], -1);
  // One step across the whole surface: kept (its mean defect, 1%, is below Refine: it would
  // take 4 times the texels for what a few pixels along it gain).
  Fill(*field, texels, Floor, [&](int a, int) { return a < w / 2 ? 1.0f : 0.2f; });
  EXPECT_EQ(levelsOf(texels, {})[Floor], 0);

  // +-10% noise, independent in two estimates of flat light: not variation. The negative: one
  // estimate alone reads it as variation and refines the floor.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> noise(0.9f, 1.1f);
  std::vector<glm::vec3> second(texels.size(), glm::vec3(1.0f));
  Fill(*field, texels, Floor, [&](int, int) { return noise(random); });
  Fill(*field, second, Floor, [&](int, int) { return noise(random); });
  EXPECT_LT(levelsOf(texels, {})[Floor], 0);
  EXPECT_GE(levelsOf(texels, second)[Floor], 0);

  // Flat light falling to black in the outermost texels on all four borders (a wall's light
  // towards a corner): the border rows refine the floor; the interior rows (the first rule) see
  // only a small defect beside the borders and keep it.
  const int h = floor.TextureHeight;
  Fill(*field, texels, Floor,
    [&](int a, int b) {
      return std::min({ a, b, w - 1 - a, h - 1 - b }) == 0 ? 0.0f : 1.0f;
    });
  const std::vector<SurfaceVariation> border = MeasureLightVariation(*field, texels);
  const std::vector<SurfaceVariation> interior = MeasureLightVariation(*field, texels, {}, false);
  std::printf("fall-off in the border rows: defect %.2f%% with them, %.2f%% without\n",
    100.0 * border[Floor].Defect, 100.0 * interior[Floor].Defect);
  EXPECT_LT(ChooseTexelLevels(*field, border)[Floor], 0);
  EXPECT_EQ(ChooseTexelLevels(*field, interior)[Floor], 0); // the negative
}

TEST(VLFAdaptiveTexels, LevelsSetTheTexelsAndFieldFilesKeepThem)
{
  std::unique_ptr<LightField> base = SmallField();
  std::unique_ptr<LightField> levelled = SmallField({ -1, 0, 1 });
  const Surface& u = base->Surfaces()[Floor];
  const Surface& f = levelled->Surfaces()[Floor];
  EXPECT_NEAR(f.TexelU, 0.5f * u.TexelU, 0.05f * u.TexelU);
  EXPECT_GE(f.TexelCount(), 3 * u.TexelCount());
  // Doubled: 7 texels of 0.019 across the panel become 4 of 0.033 (whole texels span it).
  EXPECT_GT(levelled->Surfaces()[Panel].TexelU, 1.5f * base->Surfaces()[Panel].TexelU);
  EXPECT_LT(levelled->Surfaces()[Panel].TexelCount(), base->Surfaces()[Panel].TexelCount());
  EXPECT_EQ(base->Surfaces()[1].TexelCount(), levelled->Surfaces()[1].TexelCount());
  LightFieldSettings settings = levelled->Settings();
  EXPECT_EQ(EstimateMemory(base->Scene(), settings).Texels, levelled->TexelCount());

  PropagateToTolerance(*levelled, DefaultTolerance, DefaultMaxIterations);
  const std::string path = std::string(MESOLIGHT_TEST_TEMP_DIR) + "/adaptive-texels.vlf";
  WriteSnapshot(*levelled, path);
  std::unique_ptr<LightField> back = ReadSnapshot(path);
  EXPECT_EQ(back->Settings().SurfaceTexelLevels, settings.SurfaceTexelLevels);
  ASSERT_EQ(back->TexelCount(), levelled->TexelCount());
  EXPECT_EQ(back->TotalDiffuse, levelled->TotalDiffuse);

  settings.SurfaceTexelLevels = { -1, 0 }; // two levels for three surfaces
  EXPECT_THROW(LightField::Build(base->Scene(), settings), std::invalid_argument);
  settings.SurfaceTexelLevels = { 0, 0, static_cast<std::int8_t>(MinSurfaceTexelLevel - 1) };
  EXPECT_FALSE(settings.Validate().empty());
}

TEST(VLFAdaptiveTexels, ResolvesSharpShadowsWhereUniformTexelsDoNotAndCoarsensFlatLight)
{
  // A 2 x 2 floor under a 0.1 emitter at height 2; nine 0.3 x 0.3 plates, 0.02 thick, float
  // 0.1 above the floor: their shadows' penumbrae are 0.006 wide, their tops (one surface) lit
  // almost evenly.
  TriangleScene scene = MakeEmitterOverFloor(0.1f, 2.0f, 2.0f, 0.5f, 400.0f);
  SceneMaterial white;
  white.Name = "plates";
  white.Diffuse = glm::vec3(0.5f);
  const std::uint32_t plates = scene.AddMaterial(white);
  const float k = 2.0f / (2.0f - 0.12f);     // shadow of a top edge on the floor: x k
  std::vector<std::array<float, 4>> shadows; // x0, x1, y0, y1 on the floor
  for (int i = -1; i <= 1; ++i)
  {
    for (int j = -1; j <= 1; ++j)
    {
      const glm::vec3 lower(0.6f * i - 0.15f, 0.6f * j - 0.15f, 0.1f);
      vlftest::AddBox(scene, lower, lower + glm::vec3(0.3f, 0.3f, 0.02f), plates, false);
      shadows.push_back({ k * lower.x, k * (lower.x + 0.3f), k * lower.y, k * (lower.y + 0.3f) });
    }
  }
  LightFieldSettings settings;
  settings.Directions = 513;
  settings.RaysPerSide = 32;
  settings.TilesPerSide = 4;
  settings.TexelSize = 0.5f * settings.CellSize();
  AdaptiveTexelReport report;
  AdaptiveTexelOptions coarsening;
  coarsening.Coarsen = 0.004; // the first rule's
  // The measure and the levels, not the budget: the floor holds every shadow, and quartering it
  // costs 15 times its texels, beyond the default gather budget.
  coarsening.GatherBudget = -1.0;
  const LightFieldSettings adaptiveSettings =
    ChooseAdaptiveTexels(scene, settings, coarsening, &report);
  std::printf("%s\n", report.Describe().c_str());

  std::unique_ptr<LightField> uniform = LightField::Build(scene, settings);
  const Surface& floor = uniform->Surfaces()[0];
  ASSERT_GT(floor.Area, 1.0); // 4 world units, in the unit sphere
  const float texel = floor.TexelU / uniform->NormalizationScale();
  // The plates' tops: the surface facing up at z = 0.12.
  std::uint32_t tops = NoSurface;
  for (std::uint32_t s = 0; s < uniform->Surfaces().size(); ++s)
  {
    const Surface& surface = uniform->Surfaces()[s];
    const glm::vec3 corner =
      surface.Origin / uniform->NormalizationScale() + uniform->NormalizationCentre();
    if (surface.Normal.z > 0.99f && std::abs(corner.z - 0.12f) < 1e-3f)
    {
      tops = s;
    }
  }
  ASSERT_NE(tops, NoSurface);
  std::printf("floor defect %.2f%% -> level %d, the plates' tops %.2f%% (noise %.2f%%) -> level "
              "%d\n",
    100.0 * report.Variation[0].Defect, adaptiveSettings.SurfaceTexelLevels[0],
    100.0 * report.Variation[tops].Defect, 100.0 * report.Variation[tops].Noise,
    adaptiveSettings.SurfaceTexelLevels[tops]);
  EXPECT_LT(adaptiveSettings.SurfaceTexelLevels[0], 0);    // the shadows: finer
  EXPECT_GT(adaptiveSettings.SurfaceTexelLevels[tops], 0); // flat light: coarser

  // Floor points within 1.5 uniform texels of a shadow edge, on a grid of a fifth of a texel.
  std::vector<TexelPoint> points;
  for (float x = -0.95f; x <= 0.95f; x += 0.2f * texel)
  {
    for (float y = -0.95f; y <= 0.95f; y += 0.2f * texel)
    {
      float d = 1e9f;
      for (const auto& r : shadows)
      {
        const float dx = std::max({ r[0] - x, 0.0f, x - r[1] });
        const float dy = std::max({ r[2] - y, 0.0f, y - r[3] });
        const float outside = std::sqrt(dx * dx + dy * dy);
        const float inside = std::min({ x - r[0], r[1] - x, y - r[2], r[3] - y });
        d = std::min(d, outside > 0.0f ? outside : inside);
      }
      if (d < 1.5f * texel)
      {
        TexelPoint p;
        p.Surface = 0;
        p.Triangle = floor.Triangles[0];
        p.Unit =
          (glm::vec3(x, y, 0.0f) - uniform->NormalizationCentre()) * uniform->NormalizationScale();
        points.push_back(p);
      }
    }
  }
  // Every 8th: enough points, a shorter reference.
  std::vector<TexelPoint> sampled;
  for (std::size_t i = 0; i < points.size(); i += 8)
  {
    sampled.push_back(points[i]);
  }
  ASSERT_GT(sampled.size(), 300u);
  const std::vector<glm::vec3> reference = PathTraced(scene, *uniform, sampled, 1024, 11);
  double lit = 0.0;
  for (const glm::vec3& r : reference)
  {
    lit = std::max(lit, static_cast<double>(r.x + r.y + r.z));
  }
  // Mean |field - reference| relative to the lit floor's radiance (the umbra is nearly black).
  const auto meanError = [&](const LightField& field)
  {
    double sum = 0.0;
    for (std::size_t i = 0; i < sampled.size(); ++i)
    {
      const glm::vec3 v = field.SampleTexture(field.TotalDiffuse, 0, sampled[i].Unit);
      sum += std::abs(v.x + v.y + v.z - reference[i].x - reference[i].y - reference[i].z) / lit;
    }
    return sum / static_cast<double>(sampled.size());
  };
  PropagateToTolerance(*uniform, DefaultTolerance, DefaultMaxIterations);
  FinalGather(*uniform);
  const double uniformError = meanError(*uniform);
  std::unique_ptr<LightField> adaptive = LightField::Build(scene, adaptiveSettings);
  PropagateToTolerance(*adaptive, DefaultTolerance, DefaultMaxIterations);
  FinalGather(*adaptive);
  const double adaptiveError = meanError(*adaptive);
  std::printf("floor within 1.5 texels of the plates' shadow edges vs the path tracer (%zu "
              "points, relative to the lit floor): uniform texels %.2f%% (%zu texels), adaptive "
              "%.2f%% (%zu texels; the tops %zu -> %zu)\n",
    sampled.size(), 100.0 * uniformError, uniform->TexelCount(), 100.0 * adaptiveError,
    adaptive->TexelCount(), uniform->Surfaces()[tops].TexelCount(),
    adaptive->Surfaces()[tops].TexelCount());
  EXPECT_LT(adaptive->Surfaces()[tops].TexelCount(), uniform->Surfaces()[tops].TexelCount());
  // Measured: uniform 9.2% (3277 texels), adaptive 2.3% (25632; the floor quartered).
  EXPECT_LT(adaptiveError, 0.05);
  EXPECT_GT(uniformError, 0.05); // the negative: the shadow edges smeared over a texel
}

// 513 x 32 lines with the contact halving the automatic settings take with the gather (the low
// box's scene is 3 across: texels of 0.094).
LightFieldSettings LowBoxSettings()
{
  LightFieldSettings settings;
  settings.Directions = 513;
  settings.RaysPerSide = 32;
  settings.TilesPerSide = 4;
  settings.ContactTexelHalvings = 1;
  return settings;
}

TEST(VLFAdaptiveTexels, TheGatherBudgetTakesTheBestGainPerTexelFirst)
{
  // Four surfaces, texels on them at the base texels, measured defects and levels, contact
  // floors (by hand: a step from level L costs 3 x 4^-L x base texels and gains defect x 8^L per
  // texel):
  //   0: 100 texels, defect 10%, measured a quarter; steps 0 -> -1 (gain 0.10, 300 texels) and
  //      -1 -> -2 (0.0125, 1200)
  //   1: 1000 texels, defect 3%, measured a half; 0 -> -1 (0.03, 3000): the largest defect x
  //      area, but the least gain per texel of the halvings
  //   2: 400 texels, a contact surface (floor -1: 1600 texels), defect 9%, measured a quarter;
  //      -1 -> -2 (0.01125, 4800)
  //   3: an emitter (no texels measured)
  // The contact texels alone gather 100 + 1000 + 1600 = 2700 texels.
  const std::vector<std::size_t> base{ 100, 1000, 400, 0 };
  std::vector<SurfaceVariation> variation(4);
  const double defects[4] = { 0.10, 0.03, 0.09, 0.0 };
  for (std::size_t s = 0; s < 4; ++s)
  {
    variation[s].Defect = defects[s];
    variation[s].Samples = s < 3 ? 100 : 0;
  }
  const std::vector<std::int8_t> measured{ -2, -1, -2, 0 }, floor{ 0, 0, -1, 0 };
  const auto gathered = [&](const std::vector<std::int8_t>& levels)
  {
    double texels = 0.0;
    for (std::size_t s = 0; s < 4; ++s)
    {
      texels += std::ldexp(static_cast<double>(base[s]), -2 * levels[s]);
    }
    return texels;
  };
  // Half the contact texels' (1350 more): surface 0 halved (300); surface 1's halving (3000)
  // and surface 0's quartering (1500 in all) do not fit.
  const std::vector<std::int8_t> half = LimitRefinement(base, variation, measured, floor, 0.5);
  EXPECT_EQ(half, (std::vector<std::int8_t>{ -1, 0, -1, 0 }));
  EXPECT_LE(gathered(half), 1.5 * 2700.0);
  // 1.2 times as many again (3240 more): surface 0 quartered too (1500), surface 1 still not
  // (4500). Largest defect x area first (the wrong order) would take surface 1's halving (3000)
  // and leave no room for surface 0's (300), the largest defect.
  EXPECT_EQ(LimitRefinement(base, variation, measured, floor, 1.2),
    (std::vector<std::int8_t>{ -2, 0, -1, 0 }));
  // No budget: coarsening surface 1 (1000 -> 250 texels) pays for surface 0's halving.
  EXPECT_EQ(LimitRefinement(base, variation, { -2, 1, -2, 0 }, floor, 0.0),
    (std::vector<std::int8_t>{ -1, 1, -1, 0 }));
  EXPECT_EQ(LimitRefinement(base, variation, measured, floor, 0.0),
    (std::vector<std::int8_t>{ 0, 0, -1, 0 })); // no coarsening: nothing beyond the contact
  // The negative: unbounded, the measured levels gather 4.4 times the contact texels'.
  const std::vector<std::int8_t> unbounded =
    LimitRefinement(base, variation, measured, floor, -1.0);
  EXPECT_EQ(unbounded, measured);
  EXPECT_GT(gathered(unbounded), 1.5 * 2700.0);
}

TEST(VLFAdaptiveTexels, TheGatherBudgetLimitsTheRefinementOfAScene)
{
  // The low box of the next test: the rule refines box faces beyond the contact halving of the
  // floor. Without a budget for it only the contact texels remain; unbounded (the negative) it
  // gathers more than the contact texels.
  const TriangleScene scene =
    vlftest::MakeFloorWithBox(glm::vec3(0.3f, -0.06f, 0.0f), glm::vec3(0.42f, 0.06f, 0.08f));
  AdaptiveTexelOptions none, unbounded;
  none.GatherBudget = 0.0;
  unbounded.GatherBudget = -1.0;
  AdaptiveTexelReport noneReport, unboundedReport;
  const LightFieldSettings limited =
    ChooseAdaptiveTexels(scene, LowBoxSettings(), none, &noneReport);
  ChooseAdaptiveTexels(scene, LowBoxSettings(), unbounded, &unboundedReport);
  std::printf("no budget: %s\nunbounded: %s\n", noneReport.Describe().c_str(),
    unboundedReport.Describe().c_str());
  EXPECT_EQ(noneReport.BeyondContact, 0u);
  EXPECT_GE(noneReport.Limited, 1u);
  EXPECT_LE(noneReport.Gathered, noneReport.GatheredDefault * (1.0 + 1e-9));
  EXPECT_EQ(limited.SurfaceTexelLevels[0], -1); // the floor keeps its contact halving
  EXPECT_GE(unboundedReport.BeyondContact, 1u); // the negative
  EXPECT_EQ(unboundedReport.Limited, 0u);
  EXPECT_GT(unboundedReport.Gathered, unboundedReport.GatheredDefault * (1.0 + 1e-9));
}

TEST(VLFAdaptiveTexels, RefinesOnTopOfTheContactTexelsWhereTheFirstRuleMissedTheContactShadow)
{
  // TestContactTexels.cxx's low box on a floor under a 0.4 wide emitter at height 1: 0.12 wide
  // and 0.08 high, its contact shadow a strip of a few hundredths beside it, narrower than the
  // 0.094 texels of 513 x 32 lines (the scene is 3 across).
  const glm::vec3 lower(0.3f, -0.06f, 0.0f), upper(0.42f, 0.06f, 0.08f);
  const TriangleScene scene = vlftest::MakeFloorWithBox(lower, upper);
  const LightFieldSettings settings = LowBoxSettings();
  AdaptiveTexelReport ruleReport, firstReport;
  const LightFieldSettings rule = ChooseAdaptiveTexels(scene, settings, {}, &ruleReport);
  const LightFieldSettings first =
    ChooseAdaptiveTexels(scene, settings, FirstRuleAdaptiveTexelOptions(), &firstReport);
  std::printf("the rule: %s\nthe first rule: %s\nfloor defect %.2f%% (noise %.2f%%): level %d "
              "(the rule), %d (the first rule)\n",
    ruleReport.Describe().c_str(), firstReport.Describe().c_str(),
    100.0 * ruleReport.Variation[0].Defect, 100.0 * ruleReport.Variation[0].Noise,
    rule.SurfaceTexelLevels[0], first.SurfaceTexelLevels[0]);
  EXPECT_LE(rule.SurfaceTexelLevels[0], -1); // at least the contact halving
  EXPECT_EQ(ruleReport.Contact, 1u);

  std::unique_ptr<LightField> ruleField = LightField::Build(scene, rule);
  std::unique_ptr<LightField> firstField = LightField::Build(scene, first);
  // Points on the floor within 1.5 base texels of the box, not under it, on a grid of a tenth
  // of a texel: what the pixels beside the box read.
  const float texel = settings.CellSize() / ruleField->NormalizationScale();
  std::vector<TexelPoint> points;
  for (float x = lower.x - 1.5f * texel; x <= upper.x + 1.5f * texel; x += 0.1f * texel)
  {
    for (float y = lower.y - 1.5f * texel; y <= upper.y + 1.5f * texel; y += 0.1f * texel)
    {
      const float dx = std::max({ lower.x - x, 0.0f, x - upper.x });
      const float dy = std::max({ lower.y - y, 0.0f, y - upper.y });
      const float d = std::sqrt(dx * dx + dy * dy);
      if (!(d > 0.002f && d < 1.5f * texel))
      {
        continue;
      }
      TexelPoint p;
      p.Surface = 0;
      p.Triangle = ruleField->Surfaces()[0].Triangles[0];
      p.Unit = (glm::vec3(x, y, 0.0f) - ruleField->NormalizationCentre()) *
        ruleField->NormalizationScale();
      points.push_back(p);
    }
  }
  ASSERT_GT(points.size(), 100u);
  const std::vector<glm::vec3> reference = PathTraced(scene, *ruleField, points, 2048, 5);
  const auto meanError = [&](LightField& field)
  {
    PropagateToTolerance(field, DefaultTolerance, DefaultMaxIterations);
    FinalGather(field);
    double sum = 0.0;
    for (std::size_t i = 0; i < points.size(); ++i)
    {
      const double r = reference[i].x + reference[i].y + reference[i].z;
      const glm::vec3 v = field.SampleTexture(field.TotalDiffuse, 0, points[i].Unit);
      sum += std::abs(v.x + v.y + v.z - r) / r;
    }
    return sum / static_cast<double>(points.size());
  };
  const double ruleError = meanError(*ruleField);
  const double firstError = meanError(*firstField);
  std::printf("floor within 1.5 texels of a low box vs the path tracer (%zu points): the rule "
              "%.2f%% (%zu texels), the first rule %.2f%% (%zu texels)\n",
    points.size(), 100.0 * ruleError, ruleField->TexelCount(), 100.0 * firstError,
    firstField->TexelCount());
  // Measured: the rule 16.0% (floor halved: the contact halving; 1898 texels), the first rule
  // 29.0% (525).
  EXPECT_LT(ruleError, 0.2);
  EXPECT_LT(ruleError, 0.75 * firstError);
  EXPECT_GT(firstError, 0.25); // the negative: the contact shadow smeared over a base texel
}

} // namespace
