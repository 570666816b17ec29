// SPDX-License-Identifier: BSD-3-Clause
// Texels per surface from the field's own light (AdaptiveTexels.h,
// LightFieldSettings::SurfaceTexelLevels) against independent references:
// 1. The variation measure on textures set by hand: a 5:1 step and stripes are refined, flat and
//    linearly varying light coarsened (bilinear reads hold a linear gradient at any texel size),
//    a surface too small to coarsen keeps its texels; noise of two independent estimates is not
//    read as variation (the negative: one estimate alone refines it).
// 2. The levels set the texels (twice / half the side per level), the estimate follows, and a
//    field file keeps them; levels for another surface count are refused.
// 3. Shadows of floating plates under a small emitter, read on the floor the way a pixel reads
//    them (bilinear between texel centres, within 1.5 texels of the shadow edges), against the
//    path tracer: the gathered field at the scene's uniform texels (the negative) fails the
//    error bound the adaptive texels meet, and the plates' flat-lit tops get fewer texels.
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
    return ChooseTexelLevels(*field, v);
  };

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
  const LightFieldSettings adaptiveSettings = ChooseAdaptiveTexels(scene, settings, {}, &report);
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
  std::printf("floor defect %.2f%% -> level %d, the plates' tops %.2f%% -> level %d\n",
    100.0 * report.Variation[0].Defect, adaptiveSettings.SurfaceTexelLevels[0],
    100.0 * report.Variation[tops].Defect, adaptiveSettings.SurfaceTexelLevels[tops]);
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

} // namespace
