// SPDX-License-Identifier: BSD-3-Clause
// ReliefSurface (core, no VTK): the texture frame of the plane rule on the published Cornell box
// (docs/vlf.md gives the back wall's frame in millimetres), the probes' places, and the refusals;
// the emitter lights' factors at the probes (ReliefOcclusion).
#include "ReliefSurface.h"

#include "EmbreeScene.h"
#include "EmitterLights.h"
#include "EmitterTestFields.h"
#include "LightField.h"
#include "PatchComparison.h" // ToWorld
#include "ReliefOcclusion.h" // EmitterLightFactors
#include "SurfaceRelief.h"   // SurfacePlaneOf
#include "WalkthroughTestFields.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

namespace
{
using namespace mesolight;
namespace vlf = mesolight::vlf;

glm::vec3 World(const vlf::LightField& field, const glm::dvec3& unit)
{
  return vlf::ToWorld(field, glm::vec3(unit));
}
} // namespace

TEST(ReliefSurface, BackWallFrameIsThePlaneRuleInMillimetres)
{
  const vlf::LightField& field = walkthroughtest::PlainCornellField(129);
  const vlf::ReliefSurface back = vlf::FindReliefSurface(field, "back");
  EXPECT_FALSE(back.SceneTextureCoordinates);
  // u = 0 at x = 556 mm, 1 at x = 0; v = 0 at y = 0, 1 at y = 548.8; the wall at z = 559.2.
  const glm::vec3 origin = World(field, back.Point(0.0, 0.0));
  const glm::vec3 far = World(field, back.Point(1.0, 1.0));
  EXPECT_NEAR(origin.x, 556.0f, 1.0f);
  EXPECT_NEAR(origin.y, 0.0f, 1.0f);
  EXPECT_NEAR(origin.z, 559.2f, 1.0f);
  EXPECT_NEAR(far.x, 0.0f, 1.0f);
  EXPECT_NEAR(far.y, 548.8f, 1.0f);
  EXPECT_NEAR(back.Normal.z, -1.0, 1e-3); // facing into the room
  // Texture coordinates of a point of the plane invert Point.
  const glm::dvec3 uvw = back.TextureOf(back.Point(0.25, 0.75));
  EXPECT_NEAR(uvw.x, 0.25, 1e-9);
  EXPECT_NEAR(uvw.y, 0.75, 1e-9);
  EXPECT_NEAR(uvw.z, 0.0, 1e-9);
  // Probes stand in front of the wall over its texture.
  const glm::vec3 p = vlf::ReliefProbePoint(back, 0, 1, 2, 2);
  const glm::dvec3 t = back.TextureOf(glm::dvec3(p));
  EXPECT_NEAR(t.x, 0.25, 1e-5);
  EXPECT_NEAR(t.y, 0.75, 1e-5);
  EXPECT_NEAR(t.z, 1e-3, 1e-5);
}

TEST(ReliefSurface, FrameIsTheDenseMeshReferencesOnTheRedWall)
{
  // The red wall is 0.2% off its plane: taken by both, with one frame, so `vlf render --relief`
  // and `trace --relief` (SurfacePlaneOf on the world scene) put the image at the same place.
  const vlf::LightField& field = walkthroughtest::PlainCornellField(129);
  const vlf::ReliefSurface left = vlf::FindReliefSurface(field, "left");
  const TriangleScene box = MakeCornellBox();
  const SurfacePlane plane = SurfacePlaneOf(box, SurfaceTriangles(box, "left"), "left");
  for (const glm::dvec2 uv : { glm::dvec2(0.0), glm::dvec2(1.0, 0.0), glm::dvec2(0.0, 1.0),
         glm::dvec2(1.0), glm::dvec2(0.3, 0.6) })
  {
    const glm::vec3 expected = plane.Origin + static_cast<float>(uv.x) * plane.AxisU +
      static_cast<float>(uv.y) * plane.AxisV;
    EXPECT_LT(glm::distance(World(field, left.Point(uv.x, uv.y)), expected), 0.01f)
      << uv.x << ", " << uv.y;
  }
  EXPECT_GT(glm::dot(glm::vec3(left.Normal), plane.Normal), 0.999999f);
}

TEST(ReliefSurface, RefusesWhatCannotCarryARelief)
{
  const vlf::LightField& plain = walkthroughtest::PlainCornellField(129);
  try
  {
    vlf::FindReliefSurface(plain, "tall");
    ADD_FAILURE() << "a block was taken";
  }
  catch (const vlf::ReliefSurfaceError& e)
  {
    EXPECT_NE(std::string(e.what()).find("is not planar"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("`g` names"), std::string::npos) << e.what();
  }
  try
  {
    vlf::FindReliefSurface(plain, "wall");
    ADD_FAILURE() << "an unknown name was taken";
  }
  catch (const vlf::ReliefSurfaceError& e)
  {
    EXPECT_NE(std::string(e.what()).find("floor, ceiling, back"), std::string::npos) << e.what();
  }
  // The mirror box's left wall is its mirror.
  EXPECT_THROW(vlf::FindReliefSurface(walkthroughtest::MirrorCornellField(129), "left"),
    vlf::ReliefSurfaceError);
  const vlf::ReliefSurface back = vlf::FindReliefSurface(plain, "back");
  EXPECT_THROW(vlf::ReliefSurfaceProbes(plain, back, 0, 2), std::invalid_argument);
  // A stop asked through progress.
  EXPECT_THROW(
    vlf::ReliefSurfaceProbes(plain, back, 2, 2, [](double) { return false; }), vlf::AbortedError);
}

TEST(ReliefSurface, TrianglesOfItsOwnOnTheBackWallAreTheBackWall)
{
  // The named wall's own triangles given as plain triangles: the same frame, field surface, Kd
  // and probes as the named wall (what ParaView's Relief Surface gathers on a patch).
  const vlf::LightField& field = walkthroughtest::PlainCornellField(129);
  const vlf::ReliefSurface back = vlf::FindReliefSurface(field, "back");
  const TriangleScene& scene = field.Scene();
  std::vector<glm::vec3> positions;
  std::vector<glm::uvec3> triangles;
  for (const std::size_t t : back.Triangles)
  {
    const auto first = static_cast<unsigned>(positions.size());
    for (int c = 0; c < 3; ++c)
    {
      positions.push_back(scene.Vertex(t, c));
    }
    triangles.emplace_back(first, first + 1, first + 2);
  }
  const vlf::ReliefSurface own =
    vlf::ReliefSurfaceFromTriangles(field, positions, {}, triangles, "patch");
  EXPECT_EQ(own.FieldSurface, back.FieldSurface);
  EXPECT_EQ(own.Diffuse, back.Diffuse);
  EXPECT_LT(glm::length(own.Origin - back.Origin), 1e-6);
  EXPECT_LT(glm::length(own.AxisU - back.AxisU), 1e-6);
  EXPECT_LT(glm::length(own.AxisV - back.AxisV), 1e-6);
  const std::vector<SH9> a = vlf::ReliefSurfaceProbes(field, back, 2, 2);
  const std::vector<SH9> b = vlf::ReliefSurfaceProbes(field, own, 2, 2);
  for (std::size_t p = 0; p < a.size(); ++p)
  {
    for (int k = 0; k < 9; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_NEAR(a[p].L[k][c], b[p].L[k][c], 1e-9) << "probe " << p << " coefficient " << k;
      }
    }
  }

  // A patch with texture coordinates of its own, mounted 2% of the radius in front of the wall:
  // still on the wall, its frame from the coordinates. 10% in front: in the room, no wall.
  const glm::vec3 n(back.Normal);
  const auto patch = [&](float off, std::vector<glm::vec2>& tcoords)
  {
    tcoords = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } };
    std::vector<glm::vec3> corners;
    for (const glm::vec2& t : tcoords)
    {
      corners.push_back(glm::vec3(back.Point(0.2 + 0.5 * t.x, 0.3 + 0.4 * t.y)) + off * n);
    }
    return corners;
  };
  std::vector<glm::vec2> tcoords;
  const std::vector<glm::uvec3> quad = { { 0, 1, 2 }, { 0, 2, 3 } };
  const vlf::ReliefSurface mounted =
    vlf::ReliefSurfaceFromTriangles(field, patch(0.02f, tcoords), tcoords, quad, "patch");
  EXPECT_EQ(mounted.FieldSurface, back.FieldSurface);
  EXPECT_NEAR(mounted.Normal.z, -1.0, 1e-6);
  const glm::dvec3 corner = mounted.Point(1.0, 1.0);
  const glm::dvec3 expected = back.Point(0.7, 0.7) + 0.02 * glm::dvec3(n);
  EXPECT_LT(glm::length(corner - expected), 1e-5);
  const vlf::ReliefSurface floating =
    vlf::ReliefSurfaceFromTriangles(field, patch(0.1f, tcoords), tcoords, quad, "patch");
  EXPECT_EQ(floating.FieldSurface, vlf::NoSurface);

  // Refusals: no triangles, a bent surface, a triangle naming a missing point.
  EXPECT_THROW(
    vlf::ReliefSurfaceFromTriangles(field, positions, {}, {}, "patch"), vlf::ReliefSurfaceError);
  std::vector<glm::vec3> bent = patch(0.0f, tcoords);
  bent[3] += 0.2f * n;
  EXPECT_THROW(
    vlf::ReliefSurfaceFromTriangles(field, bent, {}, quad, "patch"), vlf::ReliefSurfaceError);
  EXPECT_THROW(vlf::ReliefSurfaceFromTriangles(field, bent, {}, { { 0, 1, 9 } }, "patch"),
    std::invalid_argument);
}

// A patch on a two-tone wall (a user's red wall with a blue dado) takes one albedo, the one
// under its centre: ReliefSurfaceFromTriangles names the other materials it lies on, so the
// user is told (vtkLightFieldReliefSurface warns), and names none for a patch on one of them.
TEST(ReliefSurface, APatchAcrossTwoMaterialsNamesTheOther)
{
  // The published box with its back wall's second triangle red: the wall split along a diagonal.
  TriangleScene scene = MakeCornellBox();
  const std::vector<std::size_t> back = SurfaceTriangles(scene, "back");
  ASSERT_EQ(back.size(), 2u);
  const auto red = std::find_if(scene.Materials.begin(), scene.Materials.end(),
    [](const SceneMaterial& m) { return m.Name == "red"; });
  ASSERT_NE(red, scene.Materials.end());
  scene.MaterialIds[back[1]] = static_cast<std::uint32_t>(red - scene.Materials.begin());
  vlf::LightFieldSettings settings;
  settings.Directions = 33;
  settings.RaysPerSide = 4;
  const std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(scene, settings);
  // Patches 1% of the radius in front of the wall, in the wall's own frame: across the diagonal,
  // and in a corner of the first triangle only.
  const vlf::ReliefSurface wall = vlf::FindReliefSurface(*field, "back");
  const glm::vec3 n(wall.Normal);
  const auto patch = [&](double u0, double v0, double size)
  {
    std::vector<glm::vec3> corners;
    for (const glm::dvec2 t :
      { glm::dvec2(0, 0), glm::dvec2(1, 0), glm::dvec2(1, 1), glm::dvec2(0, 1) })
    {
      corners.push_back(glm::vec3(wall.Point(u0 + size * t.x, v0 + size * t.y)) + 0.01f * n);
    }
    return corners;
  };
  const std::vector<glm::uvec3> quad = { { 0, 1, 2 }, { 0, 2, 3 } };
  const vlf::ReliefSurface across =
    vlf::ReliefSurfaceFromTriangles(*field, patch(0.3, 0.3, 0.4), {}, quad, "patch");
  ASSERT_NE(across.FieldSurface, vlf::NoSurface);
  const std::string under = field->MaterialOf(across.FieldSurface).Name;
  ASSERT_EQ(across.OtherMaterials.size(), 1u);
  EXPECT_EQ(across.OtherMaterials[0], under == "red" ? "white" : "red");
  // Each corner patch lies on one triangle's side of the diagonal; at least one of the two is
  // wholly on one material (which corner depends on how the wall's quad was split).
  const vlf::ReliefSurface a =
    vlf::ReliefSurfaceFromTriangles(*field, patch(0.02, 0.02, 0.15), {}, quad, "patch");
  const vlf::ReliefSurface b =
    vlf::ReliefSurfaceFromTriangles(*field, patch(0.83, 0.02, 0.15), {}, quad, "patch");
  EXPECT_TRUE(a.OtherMaterials.empty() || b.OtherMaterials.empty());
  // The plain box's wall: one material, nothing named.
  const vlf::LightField& plain = walkthroughtest::PlainCornellField(129);
  const vlf::ReliefSurface plainBack = vlf::FindReliefSurface(plain, "back");
  std::vector<glm::vec3> corners;
  for (const glm::dvec2 t :
    { glm::dvec2(0.3, 0.3), glm::dvec2(0.7, 0.3), glm::dvec2(0.7, 0.7), glm::dvec2(0.3, 0.7) })
  {
    corners.push_back(glm::vec3(plainBack.Point(t.x, t.y)) + 0.01f * glm::vec3(plainBack.Normal));
  }
  EXPECT_TRUE(
    vlf::ReliefSurfaceFromTriangles(plain, corners, {}, quad, "patch").OtherMaterials.empty());
}

// The relief mapper's point lights times their factors (EmitterLightFactors) deliver the lamps'
// irradiance: twelve 0.2 x 0.2 lamps under a box's ceiling merged to the shader's 8 lights, at
// 6 x 6 probes of a plane 1.5 below them (the box has nothing in between), against the exact
// integral over every lamp. The negative case is the merged point lights alone (factor 1, what
// an unoccluded light got when the factor was the scene's visibility): the merge's error.
TEST(ReliefSurface, EmitterLightFactorsMakeMergedLightsDeliverTheLampsIrradiance)
{
  const std::vector<emittertest::Lamp> lamps = emittertest::TwelveLamps();
  const std::unique_ptr<vlf::LightField> field = emittertest::BoxWithLamps(lamps);
  vlf::EmitterLightOptions options;
  options.MaxLights = 8;
  const std::vector<vlf::EmitterLight> lights = vlf::EstimateEmitterLights(*field, options).Lights;
  ASSERT_EQ(lights.size(), 8u);
  const double scale = field->NormalizationScale();
  const glm::dvec3 centre(field->NormalizationCentre());
  vlf::ReliefSurface plane; // world x, z in [-0.9, 0.9] at y = -0.5, facing up
  plane.Origin = (glm::dvec3(-0.9, -0.5, -0.9) - centre) * scale;
  plane.AxisU = glm::dvec3(1.8 * scale, 0.0, 0.0);
  plane.AxisV = glm::dvec3(0.0, 0.0, 1.8 * scale);
  plane.Normal = glm::dvec3(0.0, 1.0, 0.0);
  const int n = 6;
  const EmbreeScene embree(field->Scene());
  const std::vector<float> factors = vlf::EmitterLightFactors(*field, embree, plane, lights, n, n);
  ASSERT_EQ(factors.size(), static_cast<std::size_t>(n * n) * lights.size());
  double worst = 0.0, worstPoints = 0.0;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const glm::dvec3 p(vlf::ReliefProbePoint(plane, i, j, n, n));
      double exact = 0.0;
      for (const emittertest::Lamp& l : lamps)
      {
        exact += l.Emission.x *
          emittertest::RectangleIrradiance(glm::vec3(p / scale + centre), glm::vec3(plane.Normal),
            l.X0, l.X1, l.Z0, l.Z1, emittertest::LampHeight);
      }
      // Irradiance is the same in unit-sphere and world units (a solid angle).
      double delivered = 0.0, points = 0.0;
      for (std::size_t k = 0; k < lights.size(); ++k)
      {
        const glm::dvec3 d = glm::dvec3(lights[k].Position) - p;
        const double d2 = glm::dot(d, d);
        const glm::dvec3 l = d / std::sqrt(d2);
        const double point = lights[k].Intensity().x *
          std::max(0.0, -glm::dot(glm::dvec3(lights[k].Normal), l)) *
          std::max(0.0, glm::dot(plane.Normal, l)) / d2;
        const float factor = factors[(static_cast<std::size_t>(j) * n + i) * lights.size() + k];
        EXPECT_GE(factor, 0.0f);
        EXPECT_LE(factor, vlf::MaxEmitterLightFactor);
        delivered += factor * point;
        points += point;
      }
      worst = std::max(worst, std::abs(delivered - exact) / exact);
      worstPoints = std::max(worstPoints, std::abs(points - exact) / exact);
    }
  }
  std::cout << "[ figures  ] twelve lamps as 8 lights at " << n * n
            << " probes: worst irradiance error with the factors " << 100.0 * worst
            << "%, the point lights alone " << 100.0 * worstPoints << "%\n";
  EXPECT_LT(worst, 0.01);
  EXPECT_GT(worstPoints, 4.0 * worst);
}
