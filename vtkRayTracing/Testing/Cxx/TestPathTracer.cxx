// SPDX-License-Identifier: BSD-3-Clause
// Tests of the reference path tracer against analytic answers: the furnace (a closed box with
// uniform emission Le and albedo rho has radiance Le / (1 - rho) everywhere), a diffuse plane
// under a uniform and a cosine sky, a mirror, agreement of next-event estimation with plain
// BSDF sampling; negative tests (double-counted direct light, a missing 1/pi, a missing cosine
// must fail the same checks); determinism; bad input.
#include "EmbreeScene.h"
#include "EnvironmentMaps.h"
#include "MathConstants.h"
#include "PathTracer.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

namespace
{
using mesolight::EmbreeScene;
using mesolight::EnvironmentLight;
using mesolight::LightSampling;
using mesolight::PathTracer;
using mesolight::PathTracerSettings;
using mesolight::RandomSequence;
using mesolight::SceneMaterial;
using mesolight::SceneRay;
using mesolight::TriangleScene;

// The cube [-1,1]^3 with every face pointing inward, all of one material.
TriangleScene MakeClosedBox(const SceneMaterial& material)
{
  TriangleScene scene;
  const auto id = scene.AddMaterial(material);
  const glm::vec3 c[8] = { { -1, -1, -1 }, { 1, -1, -1 }, { 1, 1, -1 }, { -1, 1, -1 },
    { -1, -1, 1 }, { 1, -1, 1 }, { 1, 1, 1 }, { -1, 1, 1 } };
  // Counter-clockwise seen from inside.
  scene.AddPolygon({ c[0], c[1], c[2], c[3] }, id); // z = -1, normal +z
  scene.AddPolygon({ c[4], c[7], c[6], c[5] }, id); // z = +1, normal -z
  scene.AddPolygon({ c[0], c[4], c[5], c[1] }, id); // y = -1, normal +y
  scene.AddPolygon({ c[3], c[2], c[6], c[7] }, id); // y = +1, normal -y
  scene.AddPolygon({ c[0], c[3], c[7], c[4] }, id); // x = -1, normal +x
  scene.AddPolygon({ c[1], c[5], c[6], c[2] }, id); // x = +1, normal -x
  return scene;
}

// Mean radiance seen from the box centre over `count` directions (one path each).
glm::vec3 MeanRadianceFromCentre(const PathTracer& tracer, int count, std::uint64_t seed)
{
  glm::dvec3 sum(0.0);
  for (int i = 0; i < count; ++i)
  {
    RandomSequence rng(mesolight::SampleSeed(seed, 0, static_cast<std::uint64_t>(i)));
    const float z = 2.0f * rng.NextFloat() - 1.0f;
    const float phi = 2.0f * mesolight::Pi<float> * rng.NextFloat();
    const float r = std::sqrt(std::max(0.0f, 1.0f - z * z));
    SceneRay ray;
    ray.Origin = glm::vec3(0.1f, -0.2f, 0.05f);
    ray.Direction = glm::vec3(r * std::cos(phi), r * std::sin(phi), z);
    sum += glm::dvec3(tracer.Radiance(ray, rng));
  }
  return glm::vec3(sum / static_cast<double>(count));
}

// The furnace: the closed box of one diffuse material of this albedo, emitting 1 everywhere.
TriangleScene MakeFurnace(float albedo)
{
  SceneMaterial material;
  material.Diffuse = glm::vec3(albedo);
  material.Emission = glm::vec3(1.0f);
  return MakeClosedBox(material);
}

// Mean radiance seen from the furnace's centre over `count` paths of a tracer with `settings`.
glm::vec3 FurnaceReading(float albedo, const PathTracerSettings& settings, int count)
{
  const TriangleScene box = MakeFurnace(albedo);
  const EmbreeScene embree(box);
  const PathTracer tracer(embree, settings);
  return MeanRadianceFromCentre(tracer, count, 1);
}

struct FurnaceCase
{
  float Albedo;
  LightSampling Sampling;
};

class Furnace : public ::testing::TestWithParam<FurnaceCase>
{
};

TEST_P(Furnace, RadianceIsEmissionOverOneMinusAlbedo)
{
  const TriangleScene box = MakeFurnace(GetParam().Albedo);
  const EmbreeScene embree(box);
  PathTracerSettings settings;
  settings.Sampling = GetParam().Sampling;
  const PathTracer tracer(embree, settings);
  const float expected = 1.0f / (1.0f - GetParam().Albedo);
  const glm::vec3 seen = MeanRadianceFromCentre(tracer, 20000, 1);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(seen[c], expected, 0.015f * expected) << "channel " << c;
  }
  // Radiance leaving a wall point (what the light field compares with).
  const glm::vec3 leaving =
    tracer.DiffuseRadianceLeaving(0, glm::vec3(0.3f, -0.4f, -1.0f), 20000, 2);
  EXPECT_NEAR(leaving.x, expected, 0.015f * expected);
}

INSTANTIATE_TEST_SUITE_P(PathTracer, Furnace,
  ::testing::Values(FurnaceCase{ 0.5f, LightSampling::MultipleImportance },
    FurnaceCase{ 0.8f, LightSampling::MultipleImportance },
    FurnaceCase{ 0.5f, LightSampling::BsdfOnly }),
  [](const ::testing::TestParamInfo<FurnaceCase>& param)
  {
    return std::string(param.param.Sampling == LightSampling::BsdfOnly ? "Bsdf" : "Mis") +
      "Albedo" + std::to_string(static_cast<int>(param.param.Albedo * 100.0f + 0.5f));
  });

TEST(PathTracerNegative, DoubleCountedDirectLightFailsTheFurnace)
{
  PathTracerSettings settings;
  settings.Sampling = LightSampling::DoubleCounted;
  const glm::vec3 seen = FurnaceReading(0.5f, settings, 4000);
  EXPECT_GT(std::abs(seen.x - 2.0f), 0.1f * 2.0f) << "double counting must not pass the furnace";
}

TEST(PathTracerNegative, NoRussianRouletteCompensationWouldBias)
{
  // Truncating paths at a small depth (no roulette) loses the tail of the Neumann series:
  // with rho = 0.8 and 3 bounces the furnace reads 1 + .8 + .64 + .512 = 2.95, not 5.
  PathTracerSettings settings;
  settings.MaxDepth = 3;
  settings.RouletteDepth = 1000;
  const glm::vec3 seen = FurnaceReading(0.8f, settings, 2000);
  EXPECT_NEAR(seen.x, 2.952f, 0.03f);
  EXPECT_GT(std::abs(seen.x - 5.0f), 0.5f);
}

// A 2 x 2 diffuse square in z = 0 facing +z (the lat-long map's up axis).
TriangleScene MakeGround(float albedo)
{
  TriangleScene scene;
  SceneMaterial material;
  material.Diffuse = glm::vec3(albedo);
  const auto id = scene.AddMaterial(material);
  scene.AddPolygon({ { -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 } }, id);
  return scene;
}

TEST(PathTracerEnvironment, DiffusePlaneUnderUniformSkyHasAlbedoTimesSky)
{
  const TriangleScene ground = MakeGround(0.6f);
  const EmbreeScene embree(ground);
  PathTracer tracer(embree);
  const glm::vec3 sky(0.5f, 1.0f, 2.0f);
  tracer.SetEnvironment(EnvironmentLight::Uniform(sky));
  const glm::vec3 leaving = tracer.DiffuseRadianceLeaving(0, glm::vec3(0.0f), 64, 3);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(leaving[c], 0.6f * sky[c], 1e-3f * sky[c]);
  }
  // Seen by a camera from above: plane pixels rho * sky, the rest the sky itself.
  mesolight::PinholeCamera camera;
  camera.Position = glm::vec3(0.0f, 0.0f, 3.0f);
  camera.FocalPoint = glm::vec3(0.0f);
  camera.ViewUp = glm::vec3(0.0f, 1.0f, 0.0f);
  camera.ViewAngleDegrees = 60.0f;
  const mesolight::RgbImage image = tracer.RenderImage(camera, 16, 16, 4, 5);
  ASSERT_EQ(image.Width, 16);
  EXPECT_NEAR(image.Pixel(8, 8)[2], 0.6f * sky.z, 1e-3f);
  EXPECT_NEAR(image.Pixel(0, 0)[2], sky.z, 1e-3f);
}

// A sky of radiance max(0, cos theta) (theta from +z): the irradiance on an upward plane is
// the integral of cos^2 over the hemisphere, 2 pi / 3, so the radiance leaving is 2 rho / 3.
mesolight::RgbImage CosineSky(int height)
{
  mesolight::RgbImage map(2 * height, height);
  for (int j = 0; j < height; ++j)
  {
    const double v = mesolight::PixelCenterV(j, height);
    const float value = static_cast<float>(std::max(0.0, std::cos(mesolight::Pi<double> * v)));
    for (int i = 0; i < 2 * height; ++i)
    {
      float* p = map.Pixel(i, j);
      p[0] = p[1] = p[2] = value;
    }
  }
  return map;
}

TEST(PathTracerEnvironment, DiffusePlaneUnderCosineSkyMatchesTheIntegral)
{
  const float albedo = 0.7f;
  const TriangleScene ground = MakeGround(albedo);
  const EmbreeScene embree(ground);
  PathTracer tracer(embree);
  EnvironmentLight sky;
  sky.Map = CosineSky(256);
  tracer.SetEnvironment(sky);
  const glm::vec3 leaving = tracer.DiffuseRadianceLeaving(0, glm::vec3(0.2f, 0.1f, 0.0f), 40000, 4);
  const float expected = 2.0f * albedo / 3.0f;
  EXPECT_NEAR(leaving.x, expected, 0.01f * expected);
  // Negative: the same sky averaged without the cosine (rho * mean of cos over the hemisphere
  // = rho / 2), or the irradiance without 1/pi, are far outside that tolerance.
  EXPECT_GT(std::abs(albedo / 2.0f - expected), 0.05f * expected);
  EXPECT_GT(std::abs(expected * mesolight::Pi<float> - expected), 0.05f * expected);
}

TEST(PathTracerEnvironment, RotatedEnvironmentFollowsWorldToMap)
{
  // The same cosine sky with a y-up world: WorldToMap sends world +y to map +z.
  const float albedo = 0.5f;
  TriangleScene ground;
  SceneMaterial material;
  material.Diffuse = glm::vec3(albedo);
  const auto id = ground.AddMaterial(material);
  ground.AddPolygon({ { -1, 0, -1 }, { -1, 0, 1 }, { 1, 0, 1 }, { 1, 0, -1 } }, id); // faces +y
  const EmbreeScene embree(ground);
  PathTracer tracer(embree);
  EnvironmentLight sky;
  sky.Map = CosineSky(128);
  sky.WorldToMap =
    glm::mat3(glm::vec3(1, 0, 0), glm::vec3(0, 0, 1), glm::vec3(0, -1, 0)); // columns
  tracer.SetEnvironment(sky);
  const glm::vec3 leaving = tracer.DiffuseRadianceLeaving(0, glm::vec3(0.0f), 20000, 4);
  EXPECT_NEAR(leaving.x, 2.0f * albedo / 3.0f, 0.015f);
}

TEST(PathTracerSpecular, MirrorReflectsTheEmitterItFaces)
{
  // A mirror floor below a large emitting ceiling quad facing down: looking down at the
  // mirror shows the emitter's radiance (perfect specular, Ks = 1).
  TriangleScene scene;
  SceneMaterial mirror;
  mirror.Diffuse = glm::vec3(0.0f);
  mirror.Specular = glm::vec3(1.0f);
  SceneMaterial light;
  light.Diffuse = glm::vec3(0.0f);
  light.Emission = glm::vec3(3.0f, 2.0f, 1.0f);
  const auto mirrorId = scene.AddMaterial(mirror);
  const auto lightId = scene.AddMaterial(light);
  scene.AddPolygon({ { -1, -1, 0 }, { 1, -1, 0 }, { 1, 1, 0 }, { -1, 1, 0 } }, mirrorId);
  scene.AddPolygon({ { -10, -10, 2 }, { -10, 10, 2 }, { 10, 10, 2 }, { 10, -10, 2 } }, lightId);
  const EmbreeScene embree(scene);
  const PathTracer tracer(embree);
  RandomSequence rng(9);
  SceneRay ray;
  ray.Origin = glm::vec3(0.0f, 0.0f, 1.0f);
  ray.Direction = glm::normalize(glm::vec3(0.2f, 0.1f, -1.0f));
  const glm::vec3 seen = tracer.Radiance(ray, rng);
  EXPECT_NEAR(seen.x, 3.0f, 1e-4f);
  EXPECT_NEAR(seen.z, 1.0f, 1e-4f);
  // The emitter's back side emits nothing (one-sided).
  ray.Origin = glm::vec3(0.0f, 0.0f, 3.0f);
  ray.Direction = glm::vec3(0.0f, 0.0f, -1.0f);
  EXPECT_EQ(tracer.Radiance(ray, rng), glm::vec3(0.0f));
}

TEST(PathTracer, NextEventEstimationAgreesWithBsdfSampling)
{
  // A room lit by one emitting wall: the two estimators are independent; with MIS the
  // variance is lower, but both must converge to the same radiance.
  SceneMaterial grey;
  grey.Diffuse = glm::vec3(0.6f);
  TriangleScene room = MakeClosedBox(grey);
  SceneMaterial light;
  light.Diffuse = glm::vec3(0.3f);
  light.Emission = glm::vec3(4.0f);
  room.Materials.push_back(light);
  room.MaterialIds[2] = room.MaterialIds[3] = 1; // the z = +1 face emits
  const EmbreeScene embree(room);
  PathTracerSettings bsdf;
  bsdf.Sampling = LightSampling::BsdfOnly;
  const PathTracer mis(embree);
  const PathTracer plain(embree, bsdf);
  EXPECT_EQ(mis.EmitterCount(), 2u);
  const glm::vec3 point(0.2f, 0.3f, -1.0f); // on the floor z = -1 (triangle 0 or 1)
  const glm::vec3 a = mis.DiffuseRadianceLeaving(0, point, 20000, 11);
  const glm::vec3 b = plain.DiffuseRadianceLeaving(0, point, 40000, 12);
  EXPECT_GT(a.x, 0.1f);
  EXPECT_NEAR(a.x, b.x, 0.03f * a.x);
}

// Irradiance at p (normal n) from a uniformly emitting convex polygon of radiance 1 that is
// entirely above p's horizon and unoccluded: Lambert's formula, E = 1/2 sum theta_i n.Gamma_i.
float PolygonIrradiance(
  const std::vector<glm::vec3>& polygon, const glm::vec3& p, const glm::vec3& n)
{
  float sum = 0.0f;
  for (std::size_t i = 0; i < polygon.size(); ++i)
  {
    const glm::vec3 a = glm::normalize(polygon[i] - p);
    const glm::vec3 b = glm::normalize(polygon[(i + 1) % polygon.size()] - p);
    const float theta = std::acos(glm::clamp(glm::dot(a, b), -1.0f, 1.0f));
    sum += theta * glm::dot(n, glm::normalize(glm::cross(a, b)));
  }
  return 0.5f * std::abs(sum);
}

TEST(PathTracer, DirectLightFromAnEmitterMatchesLambertsFormula)
{
  // A small tilted emitting quad above a black-backed diffuse floor: no interreflection can
  // come back (the emitter's Kd is 0 and nothing else faces the floor), so the radiance
  // leaving the floor is Kd / pi * Le * E_Lambert exactly. Next-event estimation, plain BSDF
  // sampling and MIS must all agree with it.
  TriangleScene scene;
  SceneMaterial floor;
  floor.Diffuse = glm::vec3(0.5f);
  SceneMaterial light;
  light.Diffuse = glm::vec3(0.0f);
  light.Emission = glm::vec3(10.0f);
  const auto floorId = scene.AddMaterial(floor);
  const auto lightId = scene.AddMaterial(light);
  scene.AddPolygon({ { -5, -5, 0 }, { 5, -5, 0 }, { 5, 5, 0 }, { -5, 5, 0 } }, floorId);
  const std::vector<glm::vec3> quad = { { 0.5f, -0.5f, 1.2f }, { -0.5f, -0.5f, 1.0f },
    { -0.5f, 0.5f, 1.0f }, { 0.5f, 0.5f, 1.2f } }; // counter-clockwise seen from below
  scene.AddPolygon(quad, lightId);
  ASSERT_LT(scene.FaceNormal(2).z, 0.0f);
  const EmbreeScene embree(scene);
  const glm::vec3 p(0.3f, -0.2f, 0.0f);
  const float expected =
    0.5f / mesolight::Pi<float> * 10.0f * PolygonIrradiance(quad, p, glm::vec3(0, 0, 1));
  for (LightSampling sampling : { LightSampling::MultipleImportance, LightSampling::BsdfOnly })
  {
    PathTracerSettings settings;
    settings.Sampling = sampling;
    const PathTracer tracer(embree, settings);
    const glm::vec3 leaving = tracer.DiffuseRadianceLeaving(0, p, 40000, 5);
    EXPECT_NEAR(leaving.x, expected, 0.02f * expected) << "sampling " << static_cast<int>(sampling);
  }
  // Negative: light sampling that forgets the cosine at the emitter (the area pdf not turned
  // into a solid-angle pdf) estimates Kd/pi Le integral(cos_p / d^2 dA) instead; midpoint
  // quadrature shows that is far outside the 2% tolerance.
  double noCosine = 0.0;
  const int n = 200;
  const glm::vec3 e1 = quad[1] - quad[0], e2 = quad[3] - quad[0];
  const float cellArea = glm::length(glm::cross(e1, e2)) / (n * n);
  for (int i = 0; i < n; ++i)
  {
    for (int j = 0; j < n; ++j)
    {
      const glm::vec3 y = quad[0] + (i + 0.5f) / n * e1 + (j + 0.5f) / n * e2;
      const glm::vec3 d = y - p;
      noCosine += cellArea * (d.z / glm::length(d)) / glm::dot(d, d);
    }
  }
  const float wrong = static_cast<float>(0.5 / mesolight::Pi<float> * 10.0 * noCosine);
  EXPECT_GT(std::abs(wrong - expected), 0.05f * expected);
}

TEST(PathTracer, CornellBoxFloorCentreIsLitByDirectAndIndirectLight)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  const EmbreeScene embree(box);
  const PathTracer tracer(embree);
  EXPECT_EQ(tracer.EmitterCount(), 2u);
  // Floor triangle containing (278, 0, 280), below the light and clear of both blocks.
  const glm::vec3 p(278.0f, 0.0f, 280.0f);
  std::uint32_t floor = mesolight::SceneHit::None;
  for (std::uint32_t t = 0; t < box.TriangleCount(); ++t)
  {
    const glm::vec3 a = box.Vertex(t, 0), b = box.Vertex(t, 1), c = box.Vertex(t, 2);
    const glm::vec3 n = glm::cross(b - a, c - a);
    if (n.y > 0 && a.y < 1.0f && b.y < 1.0f && c.y < 1.0f &&
      glm::dot(glm::cross(b - a, p - a), n) >= 0 && glm::dot(glm::cross(c - b, p - b), n) >= 0 &&
      glm::dot(glm::cross(a - c, p - c), n) >= 0)
    {
      floor = t;
    }
  }
  ASSERT_NE(floor, mesolight::SceneHit::None);
  // Direct light alone (Lambert's formula for the light quad, red channel Le = 17) is a lower
  // bound; the interreflections of the box add a fraction of it.
  const std::vector<glm::vec3> light = { { 343.0f, 548.7f, 227.0f }, { 343.0f, 548.7f, 332.0f },
    { 213.0f, 548.7f, 332.0f }, { 213.0f, 548.7f, 227.0f } };
  const float direct =
    0.725f / mesolight::Pi<float> * 17.0f * PolygonIrradiance(light, p, glm::vec3(0, 1, 0));
  const glm::vec3 centre = tracer.DiffuseRadianceLeaving(floor, p, 4000, 1);
  EXPECT_GT(centre.x, direct);
  EXPECT_LT(centre.x, 2.0f * direct);
  EXPECT_GT(centre.x, centre.z); // the light is warm
}

TEST(PathTracer, ImagesAreDeterministic)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  const EmbreeScene embree(box);
  PathTracerSettings one;
  one.Threads = 1;
  PathTracerSettings two;
  two.Threads = 2;
  two.TileSize = 5;
  const PathTracer a(embree, one);
  const PathTracer b(embree, two);
  const mesolight::PinholeCamera camera{ mesolight::CornellCamera{} };
  const auto first = a.RenderImage(camera, 24, 24, 2, 42);
  const auto second = b.RenderImage(camera, 24, 24, 2, 42);
  const auto other = a.RenderImage(camera, 24, 24, 2, 43);
  ASSERT_EQ(first.Rgb.size(), 24u * 24u * 3u);
  EXPECT_EQ(first.Rgb, second.Rgb) << "same seed, other threads and tiles: same image";
  EXPECT_NE(first.Rgb, other.Rgb) << "another seed: another image";
}

TEST(PathTracer, BadInputIsRejected)
{
  TriangleScene empty;
  const EmbreeScene emptyEmbree(empty);
  EXPECT_THROW(PathTracer{ emptyEmbree }, std::invalid_argument);

  const TriangleScene box = mesolight::MakeCornellBox();
  const EmbreeScene embree(box);
  PathTracerSettings bad;
  bad.MaxDepth = 0;
  EXPECT_THROW(PathTracer(embree, bad), std::invalid_argument);
  const PathTracer tracer(embree);
  EXPECT_THROW(tracer.DiffuseRadianceLeaving(100000, glm::vec3(0.0f), 1, 0), std::invalid_argument);
  EXPECT_THROW(tracer.DiffuseRadianceLeaving(0, glm::vec3(0.0f), 0, 0), std::invalid_argument);
  mesolight::PinholeCamera degenerate;
  degenerate.FocalPoint = degenerate.Position;
  EXPECT_EQ(tracer.RenderImage(degenerate, 8, 8, 1).Width, 0);
  EXPECT_EQ(
    tracer.RenderImage(mesolight::PinholeCamera{ mesolight::CornellCamera{} }, 0, 8, 1).Width, 0);
  // Abort from the progress callback: no image.
  const auto aborted = tracer.RenderImage(mesolight::PinholeCamera{ mesolight::CornellCamera{} },
    64, 64, 1, 0, [](double) { return false; });
  EXPECT_EQ(aborted.Width, 0);
}

} // namespace
