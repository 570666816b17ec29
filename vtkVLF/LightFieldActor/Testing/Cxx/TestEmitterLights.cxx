// SPDX-License-Identifier: BSD-3-Clause
// EmitterLights (Wither 2005 ch. 4): the light estimated from the Cornell box's field against the
// published box (the light 130 x 105 mm at y = 548.7, centre (278, 548.7, 279.5), Le (17, 12, 4),
// facing down), several emitters sorted by power, large emitters split near the object (their
// irradiance against the exact integral over the rectangle), separate lamps of one material as
// separate lights, more lamps than the relief shader shades merged (Lightcuts' metric) against
// the exact irradiance, and the ambient term.
#include "EmitterLights.h"
#include "EmitterTestFields.h"
#include "MathConstants.h"
#include "WalkthroughTestFields.h"

#include <glm/geometric.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <memory>
#include <utility>
#include <vector>

using namespace mesolight;
using namespace mesolight::vlf;
using namespace mesolight::emittertest;

namespace
{
glm::vec3 ToWorld(const LightField& field, const glm::vec3& unit)
{
  return field.NormalizationCentre() + unit / field.NormalizationScale();
}
glm::vec3 ToUnit(const LightField& field, const glm::vec3& world)
{
  return (world - field.NormalizationCentre()) * field.NormalizationScale();
}

// The lights' summed area, radiant intensity (Le x area) and area-weighted world centroid, in
// world units.
struct WorldTotals
{
  double Area = 0.0;
  glm::dvec3 Intensity{ 0.0 };
  glm::dvec3 Centroid{ 0.0 };
};
WorldTotals Totals(const LightField& field, const std::vector<EmitterLight>& lights)
{
  const double scale2 = field.NormalizationScale() * field.NormalizationScale();
  WorldTotals t;
  glm::dvec3 moment(0.0);
  for (const EmitterLight& l : lights)
  {
    t.Area += l.Area / scale2;
    t.Intensity += glm::dvec3(l.Intensity()) / scale2;
    moment += l.Area / scale2 * glm::dvec3(ToWorld(field, l.Position));
  }
  t.Centroid = t.Area > 0.0 ? moment / t.Area : moment;
  return t;
}

// Exact irradiance at p (normal n) from the Cornell light (Le, a one-sided rectangle facing
// down), by a fine midpoint rule over the rectangle (world millimetres).
glm::vec3 ExactIrradiance(const glm::vec3& p, const glm::vec3& n)
{
  const int steps = 400;
  const glm::vec3 le(17.0f, 12.0f, 4.0f);
  double sum = 0.0;
  const double du = 130.0 / steps, dv = 105.0 / steps;
  for (int a = 0; a < steps; ++a)
  {
    for (int b = 0; b < steps; ++b)
    {
      const glm::dvec3 x(213.0 + (a + 0.5) * du, 548.7, 227.0 + (b + 0.5) * dv);
      const glm::dvec3 d = x - glm::dvec3(p);
      const double r2 = glm::dot(d, d);
      const glm::dvec3 w = d / std::sqrt(r2);
      const double cosLight = std::max(0.0, w.y); // the light faces -y: cos = -(-y) . w
      const double cosPoint = std::max(0.0, glm::dot(w, glm::dvec3(n)));
      sum += cosLight * cosPoint / r2 * du * dv;
    }
  }
  return le * static_cast<float>(sum);
}
// The two lamps of the tests below: 0.4 x 0.4 centred at (-0.6, h, 0) and 0.2 x 0.2 at (0.5, h,
// 0), of emission `dim` and `bright`.
std::unique_ptr<LightField> BoxWithTwoLamps(
  const glm::vec3& dimEmission, const glm::vec3& brightEmission)
{
  return BoxWithLamps(
    { { -0.8f, -0.4f, -0.2f, 0.2f, dimEmission }, { 0.4f, 0.6f, -0.1f, 0.1f, brightEmission } });
}

} // namespace

TEST(ObjectEmitterLights, CornellLightMatchesThePublishedBox)
{
  const LightField& field = walkthroughtest::DiffuseCornellField();
  const LightApproximation lights = EstimateEmitterLights(field);
  ASSERT_EQ(lights.Lights.size(), 1u);
  const EmitterLight& light = lights.Lights[0];
  const glm::vec3 position = ToWorld(field, light.Position);
  const double scale = field.NormalizationScale();
  const double area = light.Area / (scale * scale); // mm^2
  std::printf("[ figures  ] Cornell light: position %.2f %.2f %.2f mm, area %.1f mm^2, normal "
              "%.3f %.3f %.3f, intensity %.4g %.4g %.4g (world units)\n",
    position.x, position.y, position.z, area, light.Normal.x, light.Normal.y, light.Normal.z,
    light.Intensity().x / (scale * scale), light.Intensity().y / (scale * scale),
    light.Intensity().z / (scale * scale));
  EXPECT_LT(glm::length(position - glm::vec3(278.0f, 548.7f, 279.5f)), 0.05f);
  EXPECT_NEAR(area, 130.0 * 105.0, 1.0);
  EXPECT_LT(glm::length(light.Normal - glm::vec3(0.0f, -1.0f, 0.0f)), 1e-4f);
  EXPECT_LT(glm::length(light.Radiance - glm::vec3(17.0f, 12.0f, 4.0f)), 1e-5f);
  // Le x area: the radiant intensity along the normal.
  EXPECT_NEAR(light.Intensity().x / (scale * scale), 17.0 * 13650.0, 17.0 * 2.0);
  // The ambient term: a radiance between the darkest and brightest non-emitting texels.
  EXPECT_GT(lights.Ambient.x, 0.0f);
  EXPECT_LT(lights.Ambient.x, 1.0f);
  std::printf(
    "[ figures  ] Cornell ambient (mean radiance of the walls and blocks): %.4f %.4f %.4f\n",
    lights.Ambient.x, lights.Ambient.y, lights.Ambient.z);
}

TEST(ObjectEmitterLights, LargeEmittersAreSplitNearTheObject)
{
  const LightField& field = walkthroughtest::DiffuseCornellField();
  // A point 60 mm below the light's centre: the light (130 mm) is large at that distance.
  const glm::vec3 world(260.0f, 488.7f, 270.0f);
  const glm::vec3 p = ToUnit(field, world);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  EmitterLightOptions options;
  options.Split = true;
  options.ReferencePoint = p;
  const LightApproximation split = EstimateEmitterLights(field, options);
  const LightApproximation single = EstimateEmitterLights(field);
  EXPECT_GT(split.Lights.size(), 4u);
  EXPECT_LE(split.Lights.size(), 16u);
  // The pieces keep the area and the centroid.
  double area = 0.0;
  glm::dvec3 moment(0.0);
  for (const EmitterLight& l : split.Lights)
  {
    area += l.Area;
    moment += l.Area * glm::dvec3(l.Position);
  }
  EXPECT_NEAR(area / single.Lights[0].Area, 1.0, 1e-5);
  EXPECT_LT(glm::length(glm::vec3(moment / area) - single.Lights[0].Position), 1e-5f);
  // Irradiance (Kd = pi so the shading is E) against the exact integral: the split lights are
  // closer; far away both agree. Units: the field's unit sphere, so E scales by 1 (Le / area
  // ratios are scale-free: I / d^2 has area / length^2).
  const glm::vec3 kd(Pi<float>);
  const glm::vec3 exact = ExactIrradiance(world, up);
  const glm::vec3 one = ShadeWithLights(single, p, up, kd) - kd * single.Ambient;
  const glm::vec3 many = ShadeWithLights(split, p, up, kd) - kd * split.Ambient;
  const float errorOne = std::abs(one.x - exact.x) / exact.x;
  const float errorMany = std::abs(many.x - exact.x) / exact.x;
  std::printf("[ figures  ] 60 mm below the light: exact E %.3f, one light %.3f (%.1f%%), %zu "
              "lights %.3f (%.1f%%)\n",
    exact.x, one.x, 100.0f * errorOne, split.Lights.size(), many.x, 100.0f * errorMany);
  EXPECT_GT(errorOne, 0.1f);
  EXPECT_LT(errorMany, 0.05f);
  // On the floor (548 mm away) one light is enough: not split, within 2%.
  const glm::vec3 floorWorld(278.0f, 0.0f, 279.5f);
  options.ReferencePoint = ToUnit(field, floorWorld);
  EXPECT_EQ(EstimateEmitterLights(field, options).Lights.size(), 1u);
  const glm::vec3 floorExact = ExactIrradiance(floorWorld, up);
  const glm::vec3 floorOne =
    ShadeWithLights(single, ToUnit(field, floorWorld), up, kd) - kd * single.Ambient;
  EXPECT_LT(std::abs(floorOne.x - floorExact.x) / floorExact.x, 0.02f);
}

TEST(ObjectEmitterLights, SeveralEmittersBrightestFirst)
{
  // Two ceiling lamps of different power, each of its own material.
  const float h = LampHeight;
  const std::unique_ptr<LightField> field = BoxWithTwoLamps(glm::vec3(1.0f), glm::vec3(4.0f));
  const LightApproximation lights = EstimateEmitterLights(*field);
  ASSERT_EQ(lights.Lights.size(), 2u);
  // Powers Le x area: dim 1 x 0.16, bright 4 x 0.04 -> equal; the sort is by intensity sum, so
  // make the check on what each is.
  for (const EmitterLight& l : lights.Lights)
  {
    const glm::vec3 world = ToWorld(*field, l.Position);
    const double area = l.Area / (field->NormalizationScale() * field->NormalizationScale());
    if (l.Radiance.x > 2.0f)
    {
      EXPECT_LT(glm::length(world - glm::vec3(0.5f, h, 0.0f)), 1e-4f);
      EXPECT_NEAR(area, 0.04, 1e-5);
    }
    else
    {
      EXPECT_LT(glm::length(world - glm::vec3(-0.6f, h, 0.0f)), 1e-4f);
      EXPECT_NEAR(area, 0.16, 1e-5);
    }
    EXPECT_LT(glm::length(l.Normal - glm::vec3(0.0f, -1.0f, 0.0f)), 1e-4f);
  }
  const glm::vec3 i0 = lights.Lights[0].Intensity(), i1 = lights.Lights[1].Intensity();
  EXPECT_GE(i0.x + i0.y + i0.z, i1.x + i1.y + i1.z);
}

TEST(ObjectEmitterLights, SeparateLampsOfOneMaterialAreSeparateLights)
{
  // The same two lamps of one material: one field surface (one material, one plane), two lamps.
  // One light at the surface's centroid would stand at x = -0.38, between them, where no lamp is.
  const float h = LampHeight;
  const std::unique_ptr<LightField> field = BoxWithTwoLamps(glm::vec3(2.0f), glm::vec3(2.0f));
  const LightApproximation lights = EstimateEmitterLights(*field);
  ASSERT_EQ(lights.Lights.size(), 2u);
  EXPECT_EQ(lights.Lights[0].Surface, lights.Lights[1].Surface);
  const double scale2 = field->NormalizationScale() * field->NormalizationScale();
  // Brightest (largest) first.
  EXPECT_LT(
    glm::length(ToWorld(*field, lights.Lights[0].Position) - glm::vec3(-0.6f, h, 0.0f)), 1e-4f);
  EXPECT_NEAR(lights.Lights[0].Area / scale2, 0.16, 1e-5);
  EXPECT_LT(
    glm::length(ToWorld(*field, lights.Lights[1].Position) - glm::vec3(0.5f, h, 0.0f)), 1e-4f);
  EXPECT_NEAR(lights.Lights[1].Area / scale2, 0.04, 1e-5);
  // Irradiance 0.8 below the small lamp (Kd = pi so the shading is E) against the exact
  // integral over both lamps; the merged light (the negative case) misses it by far.
  const glm::vec3 world(0.5f, h - 0.8f, 0.0f), up(0.0f, 1.0f, 0.0f);
  const double exact = 2.0 *
    (RectangleIrradiance(world, up, -0.8, -0.4, -0.2, 0.2, h) +
      RectangleIrradiance(world, up, 0.4, 0.6, -0.1, 0.1, h));
  const glm::vec3 kd(Pi<float>), p = ToUnit(*field, world);
  const float two = (ShadeWithLights(lights, p, up, kd) - kd * lights.Ambient).x;
  LightApproximation merged = lights;
  merged.Lights.resize(1);
  merged.Lights[0].Area = lights.Lights[0].Area + lights.Lights[1].Area;
  merged.Lights[0].Position =
    glm::vec3((lights.Lights[0].Area * glm::dvec3(lights.Lights[0].Position) +
                lights.Lights[1].Area * glm::dvec3(lights.Lights[1].Position)) /
      merged.Lights[0].Area);
  const float one = (ShadeWithLights(merged, p, up, kd) - kd * merged.Ambient).x;
  const double errorTwo = std::abs(two - exact) / exact, errorOne = std::abs(one - exact) / exact;
  std::printf("[ figures  ] below the small lamp: exact E %.4f, a light per lamp %.4f (%.1f%%), "
              "one light at the surface's centroid %.4f (%.1f%%)\n",
    exact, two, 100.0 * errorTwo, one, 100.0 * errorOne);
  EXPECT_LT(errorTwo, 0.05);
  EXPECT_GT(errorOne, 0.2);
}

TEST(ObjectEmitterLights, ManyLampsOfOneSurfaceShareAGridOfLights)
{
  // 25 lamps of one material, 0.1 x 0.1 on a 0.3 pitch: more than a 4 x 4 grid has cells, so the
  // surface is cut into that grid, at most 16 lights, keeping the lamps' area and centroid.
  std::vector<Lamp> tiles;
  for (int i = 0; i < 5; ++i)
  {
    for (int j = 0; j < 5; ++j)
    {
      const float x = -0.65f + 0.3f * i, z = -0.65f + 0.3f * j;
      tiles.push_back({ x, x + 0.1f, z, z + 0.1f, glm::vec3(3.0f) });
    }
  }
  const float h = LampHeight;
  const std::unique_ptr<LightField> field = BoxWithLamps(tiles);
  const LightApproximation lights = EstimateEmitterLights(*field);
  EXPECT_GT(lights.Lights.size(), 4u);
  EXPECT_LE(lights.Lights.size(), 16u);
  const WorldTotals totals = Totals(*field, lights.Lights);
  EXPECT_NEAR(totals.Area, 25 * 0.01, 1e-5);
  EXPECT_LT(glm::length(glm::vec3(totals.Centroid) - glm::vec3(0.0f, h, 0.0f)), 1e-4f);
  // 1.5 below the grid's centre the lights give the exact irradiance of the 25 lamps.
  const glm::vec3 world(0.05f, h - 1.5f, 0.1f), up(0.0f, 1.0f, 0.0f);
  double exact = 0.0;
  for (const Lamp& t : tiles)
  {
    exact += 3.0 * RectangleIrradiance(world, up, t.X0, t.X1, t.Z0, t.Z1, h);
  }
  const glm::vec3 kd(Pi<float>);
  const float shaded =
    (ShadeWithLights(lights, ToUnit(*field, world), up, kd) - kd * lights.Ambient).x;
  std::printf("[ figures  ] 25 lamps of one surface: %zu lights; 1.5 below, exact E %.4f, the "
              "lights %.4f (%.1f%%)\n",
    lights.Lights.size(), exact, shaded, 100.0 * std::abs(shaded - exact) / exact);
  EXPECT_LT(std::abs(shaded - exact) / exact, 0.02);
}

namespace
{
EmitterLightOptions AtMost(std::size_t lights)
{
  EmitterLightOptions options;
  options.MaxLights = lights;
  return options;
}

// The largest relative error over `points` (world, each with its normal) of the lights'
// irradiance against the exact integral over the lamps.
double WorstIrradianceError(const LightField& field, const std::vector<Lamp>& lamps,
  const LightApproximation& lights, const std::vector<std::pair<glm::vec3, glm::vec3>>& points,
  const char* label)
{
  const glm::vec3 kd(Pi<float>);
  double worst = 0.0;
  for (const auto& [world, normal] : points)
  {
    double exact = 0.0;
    for (const Lamp& l : lamps)
    {
      exact +=
        l.Emission.x * RectangleIrradiance(world, normal, l.X0, l.X1, l.Z0, l.Z1, LampHeight);
    }
    const double shaded =
      (ShadeWithLights(lights, ToUnit(field, world), normal, kd) - kd * lights.Ambient).x;
    worst = std::max(worst, std::abs(shaded - exact) / exact);
  }
  std::printf("[ figures  ] %s: worst irradiance error %.1f%% over %zu points\n", label,
    100.0 * worst, points.size());
  return worst;
}
} // namespace

TEST(ObjectEmitterLights, MoreLampsThanTheShaderShadesMergeWithoutLosingLight)
{
  // The relief shader shades 8 lights. Twelve lamps give twelve lights; merged to 8 (Lightcuts'
  // metric: neighbours first) they keep the lamps' area and intensity, and at receivers 1 or 2
  // below the ceiling (two and four times the lamps' pitch) the irradiance stays near the exact
  // integral over all twelve lamps. Shading the first 8 of the twelve, as the shader did,
  // drops a third of the light.
  const std::vector<Lamp> lamps = TwelveLamps();
  const std::unique_ptr<LightField> field = BoxWithLamps(lamps);
  const LightApproximation all = EstimateEmitterLights(*field);
  ASSERT_EQ(all.Lights.size(), 12u);
  const LightApproximation merged = EstimateEmitterLights(*field, AtMost(8));
  ASSERT_EQ(merged.Lights.size(), 8u);
  for (const EmitterLight& light : merged.Lights)
  {
    EXPECT_GT(glm::dot(light.Normal, glm::vec3(0.0f, -1.0f, 0.0f)), 0.9999f);
  }
  const WorldTotals totals = Totals(*field, merged.Lights);
  EXPECT_NEAR(totals.Area, 12 * 0.04, 1e-5);
  EXPECT_NEAR(totals.Intensity.x, 4.0 * 12 * 0.04, 1e-4);
  std::vector<std::pair<glm::vec3, glm::vec3>> below;
  for (const float x : { -0.8f, -0.3f, 0.2f, 0.7f })
  {
    for (const float z : { -0.7f, 0.0f, 0.6f })
    {
      below.push_back({ glm::vec3(x, 0.0f, z), glm::vec3(0.0f, 1.0f, 0.0f) });
      below.push_back({ glm::vec3(x, -0.95f, z), glm::vec3(0.0f, 1.0f, 0.0f) });
    }
  }
  LightApproximation firstEight = all;
  firstEight.Lights.resize(8);
  EXPECT_LT(WorstIrradianceError(*field, lamps, all, below, "twelve lights"), 0.02);
  EXPECT_LT(WorstIrradianceError(*field, lamps, merged, below, "merged to 8"), 0.08);
  EXPECT_GT(WorstIrradianceError(*field, lamps, firstEight, below, "the first 8 of 12"), 0.2);
}

TEST(ObjectEmitterLights, LampsNearTheReceiversStaySeparate)
{
  // A relief on the wall x = -1, 0.15 from the nearest row of lamps and 0.4-1.0 below them:
  // merged by the plain metric, a merged pair of that row lights it from where no lamp is; told
  // the receivers, the merges go where they cost the wall least, and the wall's irradiance stays
  // near the twelve lights' (all within 3% of the exact one).
  const std::vector<Lamp> lamps = TwelveLamps();
  const std::unique_ptr<LightField> field = BoxWithLamps(lamps);
  std::vector<std::pair<glm::vec3, glm::vec3>> wall;
  for (const float y : { 0.0f, 0.3f, 0.6f })
  {
    for (const float z : { -0.6f, -0.2f, 0.2f, 0.6f })
    {
      wall.push_back({ glm::vec3(-0.999f, y, z), glm::vec3(1.0f, 0.0f, 0.0f) });
    }
  }
  EmitterLightOptions options = AtMost(8);
  options.ReceiverCorner = ToUnit(*field, glm::vec3(-1.0f, 0.0f, -0.6f));
  options.ReceiverEdgeU = ToUnit(*field, glm::vec3(-1.0f, 0.0f, 0.6f)) - options.ReceiverCorner;
  options.ReceiverEdgeV = ToUnit(*field, glm::vec3(-1.0f, 0.6f, -0.6f)) - options.ReceiverCorner;
  options.ReceiverNormal = glm::vec3(1.0f, 0.0f, 0.0f);
  const LightApproximation aware = EstimateEmitterLights(*field, options);
  ASSERT_EQ(aware.Lights.size(), 8u);
  const double plain = WorstIrradianceError(
    *field, lamps, EstimateEmitterLights(*field, AtMost(8)), wall, "wall, plain metric");
  const double near = WorstIrradianceError(*field, lamps, aware, wall, "wall, receivers known");
  EXPECT_LT(
    WorstIrradianceError(*field, lamps, EstimateEmitterLights(*field), wall, "wall, 12 lights"),
    0.04);
  EXPECT_LT(near, 0.08);
  EXPECT_GT(plain, 3.0 * near);
}

TEST(ObjectEmitterLights, LampsFacingThreeWaysMergeForTheReceivers)
{
  // An office (6 x 2.8 x 5, scaled by 1/4 into the unit sphere) with twelve ceiling lamps and four
  // on its side walls facing into the room, merged to 8 for a relief on its back wall: told the
  // wall, the merges keep the wall's irradiance within 7% of the sixteen lights' on average
  // (measured 3.8%), where the plain metric, not told, is at least 1.5 times as far off (11.3%).
  // Area and intensity are kept either way.
  const double scale = 0.25;
  const glm::dvec3 centre(3.0, 1.4, 2.5);
  const auto unit = [&](double x, double y, double z)
  { return glm::vec3((glm::dvec3(x, y, z) - centre) * scale); };
  std::vector<EmitterLight> lights;
  const auto lamp = [&](glm::vec3 position, glm::vec3 normal)
  {
    EmitterLight l;
    l.Position = position;
    l.Normal = normal;
    l.Radiance = glm::vec3(1.0f);
    l.Area = 0.245 * 0.245 * scale * scale;
    lights.push_back(l);
  };
  for (const double x : { 1.0, 2.3, 3.7, 5.0 })
  {
    for (const double z : { 1.0, 2.5, 4.0 })
    {
      lamp(unit(x, 2.799, z), glm::vec3(0.0f, -1.0f, 0.0f));
    }
  }
  for (const double z : { 1.5, 3.5 })
  {
    lamp(unit(0.001, 2.3, z), glm::vec3(1.0f, 0.0f, 0.0f));
    lamp(unit(5.999, 2.3, z), glm::vec3(-1.0f, 0.0f, 0.0f));
  }
  EmitterLightOptions told = AtMost(8);
  told.ReceiverCorner = unit(0.0, 0.0, 0.001);
  told.ReceiverEdgeU = unit(6.0, 0.0, 0.001) - told.ReceiverCorner;
  told.ReceiverEdgeV = unit(0.0, 2.8, 0.001) - told.ReceiverCorner;
  told.ReceiverNormal = glm::vec3(0.0f, 0.0f, 1.0f);
  const std::vector<EmitterLight> aware = MergeEmitterLights(lights, told);
  const std::vector<EmitterLight> plain = MergeEmitterLights(lights, AtMost(8));
  ASSERT_EQ(aware.size(), 8u);
  ASSERT_EQ(plain.size(), 8u);
  // The mean relative error on a 30 x 14 grid of the wall (not the merge's own 8 x 8 points).
  const auto wallError = [&](const std::vector<EmitterLight>& merged, const char* label)
  {
    const LightApproximation exact{ lights, glm::vec3(0.0f) }, approx{ merged, glm::vec3(0.0f) };
    const glm::vec3 normal(0.0f, 0.0f, 1.0f), kd(1.0f);
    double sum = 0.0;
    int count = 0;
    for (int i = 0; i < 30; ++i)
    {
      for (int j = 0; j < 14; ++j)
      {
        const glm::vec3 p = unit(0.1 + 0.2 * i, 0.1 + 0.2 * j, 0.001);
        const double want = ShadeWithLights(exact, p, normal, kd).x;
        sum += std::abs(ShadeWithLights(approx, p, normal, kd).x - want) / want;
        ++count;
      }
    }
    std::printf("[ figures  ] %s: mean irradiance error %.1f%% over the back wall\n", label,
      100.0 * sum / count);
    return sum / count;
  };
  const double near = wallError(aware, "merged for the back wall");
  const double far = wallError(plain, "merged by the plain metric");
  EXPECT_LT(near, 0.07);
  EXPECT_GT(far, 1.5 * near);
  for (const std::vector<EmitterLight>* merged : { &aware, &plain })
  {
    double area = 0.0, intensity = 0.0;
    for (const EmitterLight& l : *merged)
    {
      area += l.Area;
      intensity += l.Intensity().x;
    }
    EXPECT_NEAR(area, 16 * lights[0].Area, 1e-9);
    EXPECT_NEAR(intensity, 16 * lights[0].Intensity().x, 1e-6);
  }
}

TEST(ObjectEmitterLights, LightsFacingApartMergeLast)
{
  // Eight lights under a ceiling (facing down) and two on a wall (facing +x), merged to 8: the
  // two merges join ceiling lights, never a wall light with a ceiling one, whose mean normal
  // would light neither side right.
  std::vector<EmitterLight> lights;
  for (int i = 0; i < 8; ++i)
  {
    EmitterLight l;
    l.Position = glm::vec3(-0.7f + 0.2f * i, 0.9f, 0.0f);
    l.Normal = glm::vec3(0.0f, -1.0f, 0.0f);
    l.Radiance = glm::vec3(1.0f);
    l.Area = 0.01;
    lights.push_back(l);
  }
  for (const float y : { -0.2f, 0.2f })
  {
    EmitterLight l;
    l.Position = glm::vec3(-0.9f, y, 0.0f);
    l.Normal = glm::vec3(1.0f, 0.0f, 0.0f);
    l.Radiance = glm::vec3(1.0f);
    l.Area = 0.01;
    lights.push_back(l);
  }
  const std::vector<EmitterLight> merged = MergeEmitterLights(lights, AtMost(8));
  ASSERT_EQ(merged.size(), 8u);
  int wall = 0;
  double area = 0.0;
  for (const EmitterLight& l : merged)
  {
    const bool down = glm::dot(l.Normal, glm::vec3(0.0f, -1.0f, 0.0f)) > 0.9999f;
    const bool side = glm::dot(l.Normal, glm::vec3(1.0f, 0.0f, 0.0f)) > 0.9999f;
    EXPECT_TRUE(down || side) << "a light facing between the ceiling and the wall";
    wall += side ? 1 : 0;
    area += l.Area;
  }
  EXPECT_EQ(wall, 2);
  EXPECT_NEAR(area, 0.1, 1e-9);
  // Within the limit nothing changes; 0 is no limit.
  EXPECT_EQ(MergeEmitterLights(lights, AtMost(10)).size(), 10u);
  EXPECT_EQ(MergeEmitterLights(lights, AtMost(0)).size(), 10u);
  // Down to one: every light in it, facing the brightness-weighted mean of the normals.
  const std::vector<EmitterLight> one = MergeEmitterLights(lights, AtMost(1));
  ASSERT_EQ(one.size(), 1u);
  EXPECT_GT(glm::dot(one[0].Normal, glm::normalize(glm::vec3(2.0f, -8.0f, 0.0f))), 0.9999f);

  // Receivers no light reaches (the floor seen from below), a rectangle without area, or one
  // with a non-finite corner: merged as if no receivers were named.
  EmitterLightOptions away = AtMost(8);
  away.ReceiverCorner = glm::vec3(-1.0f, -1.0f, -1.0f);
  away.ReceiverEdgeU = glm::vec3(2.0f, 0.0f, 0.0f);
  away.ReceiverEdgeV = glm::vec3(0.0f, 0.0f, 2.0f);
  away.ReceiverNormal = glm::vec3(0.0f, -1.0f, 0.0f);
  EmitterLightOptions flat = away;
  flat.ReceiverEdgeV = glm::vec3(0.0f);
  EmitterLightOptions broken = away;
  broken.ReceiverNormal = glm::vec3(0.0f, 1.0f, 0.0f);
  broken.ReceiverCorner.x = std::numeric_limits<float>::quiet_NaN();
  for (const EmitterLightOptions* options : { &away, &flat, &broken })
  {
    const std::vector<EmitterLight> same = MergeEmitterLights(lights, *options);
    ASSERT_EQ(same.size(), merged.size());
    for (std::size_t k = 0; k < same.size(); ++k)
    {
      EXPECT_EQ(same[k].Position, merged[k].Position);
      EXPECT_EQ(same[k].Normal, merged[k].Normal);
    }
  }
}

TEST(ObjectEmitterLights, ACurvedLampsPiecesMergeKeepingItsPower)
{
  // A spherical lamp of 2000 facets (each facet of a curved lamp is a field surface of its own,
  // so a light), merged to 8: more than 256 lights are first gathered by position and normal.
  // The far field's radiant intensity, sum of I cos over the lights, against the facets' in
  // 2000 directions: the power (its mean) is kept and no direction is off by a third; the first 8
  // facets alone carry 0.4% of it.
  const int n = 2000;
  std::vector<EmitterLight> facets;
  const auto direction = [](int i, int count)
  {
    const double turn = 2.399963229728653 * i, z = 1.0 - 2.0 * (i + 0.5) / count;
    const double r = std::sqrt(1.0 - z * z);
    return glm::vec3(static_cast<float>(r * std::cos(turn)), static_cast<float>(r * std::sin(turn)),
      static_cast<float>(z));
  };
  for (int i = 0; i < n; ++i)
  {
    EmitterLight facet;
    facet.Normal = direction(i, n);
    facet.Position = 0.1f * facet.Normal;
    facet.Radiance = glm::vec3(1.0f);
    facet.Area = 4.0 * Pi<double> * 0.01 / n;
    facets.push_back(facet);
  }
  EmitterLightOptions options;
  options.MaxLights = 8;
  const std::vector<EmitterLight> merged = MergeEmitterLights(facets, options);
  ASSERT_EQ(merged.size(), 8u);
  const std::vector<EmitterLight> firstEight(facets.begin(), facets.begin() + 8);
  const auto intensity = [](const std::vector<EmitterLight>& lights, const glm::vec3& d)
  {
    double sum = 0.0;
    for (const EmitterLight& l : lights)
    {
      sum += l.Intensity().x * std::max(0.0f, glm::dot(l.Normal, d));
    }
    return sum;
  };
  double exactPower = 0.0, mergedPower = 0.0, droppedPower = 0.0, worst = 0.0;
  for (int j = 0; j < n; ++j)
  {
    const glm::vec3 d = direction(j, n);
    const double exact = intensity(facets, d), approx = intensity(merged, d);
    exactPower += exact;
    mergedPower += approx;
    droppedPower += intensity(firstEight, d);
    worst = std::max(worst, std::abs(approx / exact - 1.0));
  }
  std::printf("[ figures  ] a spherical lamp of %d facets as 8 lights: power %+.2f%%, worst "
              "direction %.1f%% off; its first 8 facets: %.2f%% of the power\n",
    n, 100.0 * (mergedPower / exactPower - 1.0), 100.0 * worst, 100.0 * droppedPower / exactPower);
  EXPECT_NEAR(mergedPower / exactPower, 1.0, 0.01);
  EXPECT_LT(worst, 0.35); // 8 cosine lobes for a sphere: 25% off between them
  EXPECT_LT(droppedPower / exactPower, 0.01);
}
