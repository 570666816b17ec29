// SPDX-License-Identifier: BSD-3-Clause
// Tests of the Ahern 1999 ray tracer core against analytic answers: Lambert shading of a sphere
// under one directional light, shadows, mirrors and the recursion limit, glossy reflection of an
// edge, bilinear vs nearest texture lookups, bump maps with a known slope, tangent frames on a
// sphere (continuous where Ahern's [1 0 0] x N breaks), adaptive supersampling and
// progressive refinement (rays counted: no pixel traced twice), and bad input.
#include "MathConstants.h"
#include "TexturedRayTracer.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <memory>
#include <stdexcept>

namespace
{
using mesolight::PinholeCamera;
using mesolight::RandomSequence;
using mesolight::RayCounts;
using mesolight::RayTracerSettings;
using mesolight::RgbImage;
using mesolight::SceneLightSource;
using mesolight::SceneRay;
using mesolight::TexturedMaterial;
using mesolight::TexturedRayTracer;
using mesolight::TexturedScene;
using mesolight::TexturedSphere;
using mesolight::TextureFilter;

TexturedMaterial Matte(const glm::vec3& kd, const glm::vec3& ka = glm::vec3(0.0f))
{
  TexturedMaterial m;
  m.Diffuse = kd;
  m.Ambient = ka;
  return m;
}

SceneLightSource Sun(const glm::vec3& travel, const glm::vec3& colour = glm::vec3(1.0f))
{
  SceneLightSource light;
  light.Direction = travel;
  light.Colour = colour;
  return light;
}

// A square in the plane z = h, [-r, r]^2, facing +z, texture coordinates s = (x + r) / 2r,
// t = (y + r) / 2r.
void AddSquare(TexturedScene& scene, float r, float h, std::uint32_t material)
{
  auto& mesh = scene.Mesh;
  const auto first = static_cast<std::uint32_t>(mesh.Positions.size());
  const bool withTCoords = mesh.Positions.empty() || !mesh.TextureCoordinates.empty();
  mesh.Positions.insert(
    mesh.Positions.end(), { { -r, -r, h }, { r, -r, h }, { r, r, h }, { -r, r, h } });
  if (withTCoords)
  {
    mesh.TextureCoordinates.insert(
      mesh.TextureCoordinates.end(), { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 } });
  }
  mesh.Triangles.emplace_back(first, first + 1, first + 2);
  mesh.Triangles.emplace_back(first, first + 2, first + 3);
  mesh.MaterialIds.insert(mesh.MaterialIds.end(), { material, material });
}

glm::vec3 TraceOne(
  const TexturedRayTracer& tracer, const glm::vec3& origin, const glm::vec3& direction)
{
  RandomSequence rng(1);
  RayCounts counts;
  SceneRay ray;
  ray.Origin = origin;
  ray.Direction = glm::normalize(direction);
  return tracer.Trace(ray, 0, rng, counts);
}

TEST(EmbreeSpheres, AnalyticHitsInSingleRaysAndPackets)
{
  mesolight::TriangleScene none;
  const mesolight::EmbreeScene embree(none,
    { mesolight::SceneSphere{ glm::vec3(1.0f, 2.0f, 3.0f), 0.5f },
      mesolight::SceneSphere{ glm::vec3(0.0f), -1.0f } });
  SceneRay rays[16];
  mesolight::SceneHit packet[16];
  for (int i = 0; i < 16; ++i)
  {
    rays[i].Origin = glm::vec3(1.0f + 0.05f * (i - 8), 2.0f, -10.0f);
    rays[i].Direction = glm::vec3(0.0f, 0.0f, 1.0f);
  }
  embree.Intersect16(rays, packet, 16);
  for (int i = 0; i < 16; ++i)
  {
    const mesolight::SceneHit single = embree.Intersect(rays[i]);
    const float x = 0.05f * (i - 8);
    const bool inside = std::abs(x) < 0.5f;
    ASSERT_EQ(single.Hit(), inside) << i;
    ASSERT_EQ(packet[i].Hit(), inside) << i;
    if (inside)
    {
      EXPECT_EQ(single.Sphere, 0u);
      EXPECT_EQ(single.Triangle, mesolight::SceneHit::None);
      EXPECT_NEAR(single.T, 13.0f - std::sqrt(0.25f - x * x), 1e-4f);
      EXPECT_NEAR(packet[i].T, single.T, 1e-5f);
    }
  }
  // From inside the sphere the far side is hit; occlusion sees the sphere.
  SceneRay inside;
  inside.Origin = glm::vec3(1.0f, 2.0f, 3.0f);
  EXPECT_NEAR(embree.Intersect(inside).T, 0.5f, 1e-5f);
  EXPECT_TRUE(embree.Occluded(inside));
  inside.TFar = 0.4f;
  EXPECT_FALSE(embree.Occluded(inside));
}

TEST(TexturedRayTracer, SphereUnderADirectionalLightIsLambertian)
{
  TexturedScene scene;
  scene.Materials.push_back(Matte(glm::vec3(0.8f, 0.5f, 0.2f)));
  scene.Spheres.push_back(TexturedSphere{});
  const glm::vec3 travel = glm::normalize(glm::vec3(-1.0f, 0.0f, -1.0f));
  scene.Lights.push_back(Sun(travel, glm::vec3(0.9f)));
  const TexturedRayTracer tracer(scene);
  for (const glm::vec2 xy : { glm::vec2(0.0f, 0.0f), glm::vec2(0.5f, 0.2f), glm::vec2(-0.3f, 0.6f),
         glm::vec2(-0.8f, 0.1f) })
  {
    const float z = std::sqrt(1.0f - glm::dot(xy, xy));
    const glm::vec3 n(xy.x, xy.y, z);
    const float expected = 0.9f * 0.8f * std::max(0.0f, glm::dot(n, -travel));
    const glm::vec3 seen = TraceOne(tracer, glm::vec3(xy, 5.0f), glm::vec3(0, 0, -1));
    EXPECT_NEAR(seen.x, expected, 1e-4f) << xy.x << ", " << xy.y;
    EXPECT_NEAR(seen.z, expected / 0.8f * 0.2f, 1e-4f);
  }
  // Through the camera: the pixel whose centre ray hits the sphere at a known normal.
  PinholeCamera camera;
  camera.Position = glm::vec3(0.0f, 0.0f, 6.0f);
  camera.FocalPoint = glm::vec3(0.0f);
  camera.ViewAngleDegrees = 30.0f;
  const RgbImage image = tracer.Render(camera, 41, 31);
  ASSERT_EQ(image.Width, 41);
  for (const glm::ivec2 pixel : { glm::ivec2(20, 15), glm::ivec2(27, 18), glm::ivec2(14, 10) })
  {
    const SceneRay ray = camera.Ray(pixel.x + 0.5f, pixel.y + 0.5f, 41, 31);
    // Analytic ray/sphere hit.
    const float b = glm::dot(ray.Origin, ray.Direction);
    const float t = -b - std::sqrt(b * b - glm::dot(ray.Origin, ray.Origin) + 1.0f);
    const glm::vec3 n = glm::normalize(ray.Origin + t * ray.Direction);
    EXPECT_NEAR(
      image.Pixel(pixel.x, pixel.y)[0], 0.9f * 0.8f * std::max(0.0f, glm::dot(n, -travel)), 1e-4f);
  }
  EXPECT_EQ(tracer.LastCounts().Primary, 41u * 31u);
}

TEST(TexturedRayTracer, ShadowsAreCastAndCanBeSwitchedOff)
{
  TexturedScene scene;
  scene.Materials.push_back(Matte(glm::vec3(0.5f), glm::vec3(0.1f)));
  AddSquare(scene, 10.0f, 0.0f, 0);
  TexturedSphere blocker;
  blocker.Geometry.Center = glm::vec3(0.0f, 0.0f, 2.0f);
  scene.Spheres.push_back(blocker);
  scene.Lights.push_back(Sun(glm::vec3(0, 0, -1)));
  const TexturedRayTracer tracer(scene);
  // Straight below the sphere: ambient only. Beside it: ambient + Kd.
  EXPECT_NEAR(TraceOne(tracer, glm::vec3(0.5f, 0.0f, 0.5f), glm::vec3(0.1f, 0, -1)).x, 0.1f, 1e-5f);
  EXPECT_NEAR(TraceOne(tracer, glm::vec3(3.0f, 0.0f, 0.5f), glm::vec3(0, 0, -1)).x, 0.6f, 1e-5f);
  RayTracerSettings noShadows;
  noShadows.Shadows = false;
  const TexturedRayTracer unshadowed(scene, noShadows);
  EXPECT_NEAR(
    TraceOne(unshadowed, glm::vec3(0.5f, 0.0f, 0.5f), glm::vec3(0.1f, 0, -1)).x, 0.6f, 1e-5f);
}

TEST(TexturedRayTracer, MirrorReflectsAKnownColourUpToTheDepthLimit)
{
  TexturedScene scene;
  TexturedMaterial mirror = Matte(glm::vec3(0.0f));
  mirror.Specular = glm::vec3(0.9f);
  scene.Materials.push_back(mirror);
  scene.Materials.push_back(
    Matte(glm::vec3(0.0f), glm::vec3(0.2f, 0.4f, 0.6f))); // unlit: ambient only
  AddSquare(scene, 10.0f, 0.0f, 0);
  TexturedSphere ball;
  ball.Geometry.Center = glm::vec3(2.0f, 0.0f, 2.0f);
  ball.Material = 1;
  scene.Spheres.push_back(ball);
  scene.Background = glm::vec3(0.05f);
  const TexturedRayTracer tracer(scene);
  // From (-2, 0, 2) toward the origin the mirror sends the ray to (2, 0, 2): the ball.
  const glm::vec3 seen = TraceOne(tracer, glm::vec3(-2.0f, 0.0f, 2.0f), glm::vec3(1, 0, -1));
  EXPECT_NEAR(seen.x, 0.9f * 0.2f, 1e-5f);
  EXPECT_NEAR(seen.z, 0.9f * 0.6f, 1e-5f);
  // Aimed past the ball: the background.
  EXPECT_NEAR(
    TraceOne(tracer, glm::vec3(-2.0f, 0.0f, 2.0f), glm::vec3(1, 3, -1)).y, 0.9f * 0.05f, 1e-5f);
  // Negative: no recursion, no reflection.
  RayTracerSettings flat;
  flat.MaxDepth = 0;
  const TexturedRayTracer noReflections(scene, flat);
  EXPECT_NEAR(
    TraceOne(noReflections, glm::vec3(-2.0f, 0.0f, 2.0f), glm::vec3(1, 0, -1)).x, 0.0f, 1e-6f);
}

TEST(TexturedRayTracer, RoughnessBlursAReflectedEdge)
{
  // A mirror floor and, above it, an ambient-white ceiling over x > 0 only (black elsewhere).
  // The mirror point whose reflection looks exactly at the ceiling's edge is 0 or 1 for a
  // perfect mirror; rough, the conical distribution straddles the edge: about one half.
  auto makeScene = [](float roughness)
  {
    TexturedScene scene;
    TexturedMaterial mirror = Matte(glm::vec3(0.0f));
    mirror.Specular = glm::vec3(1.0f);
    mirror.Roughness = roughness;
    scene.Materials.push_back(mirror);
    scene.Materials.push_back(Matte(glm::vec3(0.0f), glm::vec3(1.0f)));
    AddSquare(scene, 10.0f, 0.0f, 0);
    auto& mesh = scene.Mesh;
    const auto first = static_cast<std::uint32_t>(mesh.Positions.size());
    mesh.Positions.insert(
      mesh.Positions.end(), { { 0, -10, 2 }, { 10, -10, 2 }, { 10, 10, 2 }, { 0, 10, 2 } });
    mesh.TextureCoordinates.insert(mesh.TextureCoordinates.end(), 4, glm::vec2(0.0f));
    mesh.Triangles.emplace_back(first, first + 2, first + 1);
    mesh.Triangles.emplace_back(first, first + 3, first + 2);
    mesh.MaterialIds.insert(mesh.MaterialIds.end(), { 1, 1 });
    return scene;
  };
  RayTracerSettings settings;
  settings.GlossySamples = 400;
  const TexturedRayTracer rough(makeScene(0.3f), settings);
  // From (-1, 0, 1) along (1/3, 0, -1) the ray hits the mirror at (-2/3, 0, 0) and reflects
  // along (1/3, 0, 1), reaching z = 2 at x = 0: the ceiling's edge.
  const glm::vec3 origin(-1.0f, 0.0f, 1.0f);
  const glm::vec3 direction(1.0f / 3.0f, 0.0f, -1.0f);
  const float blurred = TraceOne(rough, origin, direction).x;
  EXPECT_GT(blurred, 0.3f);
  EXPECT_LT(blurred, 0.7f);
  const TexturedRayTracer sharp(makeScene(0.0f), settings);
  // Well inside either side: the perfect mirror is exactly 1 or 0.
  EXPECT_NEAR(TraceOne(sharp, origin, glm::vec3(0.7f, 0, -1)).x, 1.0f, 1e-5f);
  EXPECT_NEAR(TraceOne(sharp, origin, glm::vec3(0.3f, 0, -1)).x, 0.0f, 1e-5f);
  // Far from the edge the rough mirror is still white.
  EXPECT_NEAR(TraceOne(rough, origin, glm::vec3(1.5f, 0, -1)).x, 1.0f, 1e-5f);
}

RgbImage TwoByTwo()
{
  RgbImage image(2, 2);
  const float values[4] = { 0.0f, 1.0f, 0.25f, 0.5f }; // (0,0) (1,0) (0,1) (1,1)
  for (int j = 0; j < 2; ++j)
  {
    for (int i = 0; i < 2; ++i)
    {
      float* p = image.Pixel(i, j);
      p[0] = p[1] = p[2] = values[j * 2 + i];
    }
  }
  return image;
}

TEST(TextureMaps, BilinearAndNearestLookupsAtKnownCoordinates)
{
  const RgbImage image = TwoByTwo();
  using mesolight::SampleTexture;
  // Texel centres: both filters give the texel.
  EXPECT_FLOAT_EQ(SampleTexture(image, { 0.25f, 0.25f }, TextureFilter::Bilinear).x, 0.0f);
  EXPECT_FLOAT_EQ(SampleTexture(image, { 0.75f, 0.25f }, TextureFilter::Nearest).x, 1.0f);
  EXPECT_FLOAT_EQ(SampleTexture(image, { 0.25f, 0.75f }, TextureFilter::Bilinear).x, 0.25f);
  // The middle: the mean of four texels against the texel the point falls in.
  EXPECT_FLOAT_EQ(SampleTexture(image, { 0.5f, 0.5f }, TextureFilter::Bilinear).x, 0.4375f);
  EXPECT_FLOAT_EQ(SampleTexture(image, { 0.5f, 0.5f }, TextureFilter::Nearest).x, 0.5f);
  // A quarter of the way between the first two texel centres.
  EXPECT_FLOAT_EQ(SampleTexture(image, { 0.375f, 0.25f }, TextureFilter::Bilinear).x, 0.25f);
  EXPECT_FLOAT_EQ(SampleTexture(image, { 0.375f, 0.25f }, TextureFilter::Nearest).x, 0.0f);
  // Repeat wrapping: s = 1.25 is s = 0.25; the corner blends the four wrapped texels.
  EXPECT_FLOAT_EQ(SampleTexture(image, { 1.25f, -0.75f }, TextureFilter::Bilinear).x, 0.0f);
  EXPECT_FLOAT_EQ(SampleTexture(image, { 0.0f, 0.0f }, TextureFilter::Bilinear).x, 0.4375f);
  // Missing map reads white.
  EXPECT_EQ(SampleTexture(RgbImage(), { 0.3f, 0.3f }, TextureFilter::Bilinear), glm::vec3(1.0f));
}

TEST(TexturedRayTracer, DiffuseMapIsLookedUpAtInterpolatedCoordinates)
{
  TexturedScene scene;
  TexturedMaterial material = Matte(glm::vec3(0.0f), glm::vec3(1.0f)); // ambient shows the map
  material.AmbientMap = std::make_shared<RgbImage>(TwoByTwo());
  scene.Materials.push_back(material);
  AddSquare(scene, 1.0f, 0.0f, 0); // s = (x + 1) / 2
  RayTracerSettings nearest;
  nearest.Filter = TextureFilter::Nearest;
  const TexturedRayTracer bilinear(scene);
  const TexturedRayTracer blocky(scene, nearest);
  // (x, y) = (0, 0) is (s, t) = (0.5, 0.5); (0.1, 0.1) is (0.55, 0.55), inside the last texel
  // (the exact middle is a tie for the nearest filter, which the hit's last bit decides:
  // Embree's kernels differ in it between processors); (-0.25, -0.5) is (0.375, 0.25).
  EXPECT_NEAR(TraceOne(bilinear, glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)).x, 0.4375f, 1e-5f);
  EXPECT_NEAR(TraceOne(blocky, glm::vec3(0.1f, 0.1f, 1), glm::vec3(0, 0, -1)).x, 0.5f, 1e-5f);
  EXPECT_NEAR(TraceOne(bilinear, glm::vec3(-0.25f, -0.5f, 1), glm::vec3(0, 0, -1)).x, 0.25f, 1e-5f);
  EXPECT_NEAR(TraceOne(blocky, glm::vec3(-0.25f, -0.5f, 1), glm::vec3(0, 0, -1)).x, 0.0f, 1e-5f);
}

TEST(TexturedRayTracer, BumpMapWithAKnownSlopeTiltsTheNormal)
{
  // A constant bump map (0.75, 0.5) with scale 1 tilts the normal of the plane z = 0 (s along
  // +x) to normalize(0.5, 0, 1). Under a light from straight above, N.L = 1 / sqrt(1.25).
  TexturedScene scene;
  TexturedMaterial material = Matte(glm::vec3(1.0f));
  auto bump = std::make_shared<RgbImage>(1, 1);
  bump->Rgb = { 0.75f, 0.5f, 1.0f };
  material.BumpMap = bump;
  scene.Materials.push_back(material);
  AddSquare(scene, 1.0f, 0.0f, 0);
  scene.Lights.push_back(Sun(glm::vec3(0, 0, -1)));
  const TexturedRayTracer tracer(scene);
  EXPECT_NEAR(TraceOne(tracer, glm::vec3(0.2f, 0.1f, 1), glm::vec3(0, 0, -1)).x,
    1.0f / std::sqrt(1.25f), 1e-5f);
  // A light from the side the normal tilts toward sees it brighter than one from the other side.
  TexturedScene left = scene, right = scene;
  left.Lights = { Sun(glm::normalize(glm::vec3(-1, 0, -1))) }; // light arriving from +x
  right.Lights = { Sun(glm::normalize(glm::vec3(1, 0, -1))) }; // from -x
  const glm::vec3 n = glm::normalize(glm::vec3(0.5f, 0.0f, 1.0f));
  EXPECT_NEAR(TraceOne(TexturedRayTracer(left), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)).x,
    glm::dot(n, glm::normalize(glm::vec3(1, 0, 1))), 1e-5f);
  EXPECT_NEAR(TraceOne(TexturedRayTracer(right), glm::vec3(0, 0, 1), glm::vec3(0, 0, -1)).x,
    glm::dot(n, glm::normalize(glm::vec3(-1, 0, 1))), 1e-5f);
}

TEST(TextureMaps, TriangleTangentFrameFollowsTextureCoordinates)
{
  const glm::vec3 p[3] = { { 0, 0, 0 }, { 2, 0, 0 }, { 0, 3, 0 } };
  const glm::vec2 st[3] = { { 0, 0 }, { 0, 1 }, { 1, 0 } }; // s along +y, t along +x
  const auto frame = mesolight::TriangleTangentFrame(glm::vec3(0, 0, 1), p, st);
  EXPECT_NEAR(frame.Tangent.y, 1.0f, 1e-6f);
  EXPECT_NEAR(frame.Bitangent.x, 1.0f, 1e-6f); // mirrored mapping keeps B along +t
  // Degenerate coordinates fall back to a valid frame.
  const glm::vec2 same[3] = { { 0.5f, 0.5f }, { 0.5f, 0.5f }, { 0.5f, 0.5f } };
  const auto fallback = mesolight::TriangleTangentFrame(glm::vec3(0, 0, 1), p, same);
  EXPECT_NEAR(glm::length(fallback.Tangent), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::dot(fallback.Tangent, glm::vec3(0, 0, 1)), 0.0f, 1e-6f);
}

TEST(TextureMaps, SphereTangentFrameIsStableAndFollowsTheCoordinates)
{
  const glm::vec3 axis(0, 0, 1), meridian(1, 0, 0);
  const float h = 1e-3f;
  int checked = 0;
  for (int a = 1; a < 60; ++a)
  {
    for (int b = 0; b < 120; ++b)
    {
      const float theta = mesolight::Pi<float> * a / 60.0f;
      const float phi = 2.0f * mesolight::Pi<float> * b / 120.0f + 0.001f;
      const glm::vec3 n(
        std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      const auto frame = mesolight::SphereTangentFrame(n, axis, meridian);
      ASSERT_NEAR(glm::length(frame.Tangent), 1.0f, 1e-4f);
      ASSERT_NEAR(glm::dot(frame.Tangent, n), 0.0f, 1e-4f);
      ASSERT_NEAR(glm::dot(frame.Bitangent, n), 0.0f, 1e-4f);
      // Moving along T increases s, along B increases t (as the texture coordinates say).
      const glm::vec2 st = mesolight::SphereTextureCoordinates(n, axis, meridian);
      const glm::vec2 alongT =
        mesolight::SphereTextureCoordinates(glm::normalize(n + h * frame.Tangent), axis, meridian);
      const glm::vec2 alongB = mesolight::SphereTextureCoordinates(
        glm::normalize(n + h * frame.Bitangent), axis, meridian);
      if (st.x > 0.01f && st.x < 0.99f)
      {
        EXPECT_GT(alongT.x, st.x);
        EXPECT_NEAR(alongT.y, st.y, 1e-4f);
      }
      EXPECT_GT(alongB.y, st.y);
      // Continuity: a neighbouring point's tangent is close.
      const glm::vec3 next = glm::normalize(n + 0.01f * frame.Bitangent);
      EXPECT_GT(
        glm::dot(mesolight::SphereTangentFrame(next, axis, meridian).Tangent, frame.Tangent),
        0.99f);
      ++checked;
    }
  }
  EXPECT_EQ(checked, 59 * 120);
  // Negative: Ahern's frame S = [1 0 0] x N collapses where N crosses the x axis, where the
  // sphere frame (and the normal-only fallback) stays orthonormal.
  const glm::vec3 onXAxis(1.0f, 0.0f, 0.0f);
  EXPECT_LT(glm::length(glm::cross(glm::vec3(1, 0, 0), onXAxis)), 1e-6f);
  EXPECT_NEAR(
    glm::length(mesolight::SphereTangentFrame(onXAxis, axis, meridian).Tangent), 1.0f, 1e-5f);
  EXPECT_NEAR(glm::length(mesolight::FrameAroundNormal(onXAxis).Tangent), 1.0f, 1e-5f);
  // Sphere coordinates: the meridian is s = 0, the axis pole t = 0, east s = 1/4.
  EXPECT_NEAR(
    mesolight::SphereTextureCoordinates(glm::vec3(1, 0, 0), axis, meridian).x, 0.0f, 1e-6f);
  EXPECT_NEAR(
    mesolight::SphereTextureCoordinates(glm::vec3(0, 1, 0), axis, meridian).x, 0.25f, 1e-6f);
  EXPECT_NEAR(
    mesolight::SphereTextureCoordinates(glm::vec3(0, 0, 1), axis, meridian).y, 0.0f, 1e-6f);
  EXPECT_NEAR(
    mesolight::SphereTextureCoordinates(glm::vec3(0, 0, -1), axis, meridian).y, 1.0f, 1e-6f);
}

// A lit sphere in front of a dark background: a scene with hard edges.
TexturedScene EdgeScene()
{
  TexturedScene scene;
  scene.Materials.push_back(Matte(glm::vec3(0.9f)));
  scene.Spheres.push_back(TexturedSphere{});
  scene.Lights.push_back(Sun(glm::vec3(0, 0, -1)));
  return scene;
}

PinholeCamera FrontCamera()
{
  PinholeCamera camera;
  camera.Position = glm::vec3(0.0f, 0.0f, 5.0f);
  camera.FocalPoint = glm::vec3(0.0f);
  camera.ViewAngleDegrees = 40.0f;
  return camera;
}

TEST(TexturedRayTracer, AdaptiveSupersamplingRefinesOnlyEdgePixels)
{
  RayTracerSettings settings;
  settings.AdaptiveSupersampling = true;
  settings.AdaptiveThreshold = 0.2f;
  const TexturedRayTracer tracer(EdgeScene(), settings);
  const RayTracerSettings plainSettings;
  const TexturedRayTracer plain(EdgeScene(), plainSettings);
  const RgbImage first = plain.Render(FrontCamera(), 40, 30);
  const auto edges = TexturedRayTracer::EdgePixels(first, 0.2f);
  std::size_t edgeCount = 0;
  for (auto e : edges)
  {
    edgeCount += e;
  }
  const RgbImage image = tracer.Render(FrontCamera(), 40, 30);
  const RayCounts counts = tracer.LastCounts();
  EXPECT_GT(edgeCount, 20u);
  EXPECT_LT(edgeCount, 40u * 30u / 3u);
  EXPECT_EQ(counts.SupersampledPixels, edgeCount);
  EXPECT_EQ(counts.Primary, 40u * 30u + 8u * edgeCount); // the centre sample is reused
  // Edge pixels change (partial coverage), the others keep their single sample.
  int changed = 0;
  for (int j = 0; j < 30; ++j)
  {
    for (int i = 0; i < 40; ++i)
    {
      const bool differs = image.Pixel(i, j)[0] != first.Pixel(i, j)[0];
      if (!edges[j * 40 + i])
      {
        EXPECT_FALSE(differs);
      }
      changed += differs;
    }
  }
  EXPECT_GT(changed, 10);
  // Negative: a threshold above any difference refines nothing.
  settings.AdaptiveThreshold = 10.0f;
  const TexturedRayTracer never(EdgeScene(), settings);
  never.Render(FrontCamera(), 40, 30);
  EXPECT_EQ(never.LastCounts().SupersampledPixels, 0u);
}

TEST(TexturedRayTracer, ProgressiveRefinementTracesEveryPixelOnce)
{
  RayTracerSettings settings;
  settings.Progressive = true;
  const TexturedRayTracer progressive(EdgeScene(), settings);
  const TexturedRayTracer plain(EdgeScene());
  std::vector<int> levels;
  std::uint64_t raysAtLevel2 = 0;
  const RgbImage image = progressive.Render(FrontCamera(), 37, 23,
    [&](const RgbImage& partial, int block)
    {
      levels.push_back(block);
      if (block == 2)
      {
        // Every pixel of a 2 x 2 block shows the colour of its corner pixel.
        EXPECT_EQ(partial.Pixel(3, 5)[0], partial.Pixel(2, 4)[0]);
        raysAtLevel2 = 1;
      }
      return true;
    });
  EXPECT_EQ(levels, (std::vector<int>{ 64, 32, 16, 8, 4, 2, 1 }));
  EXPECT_EQ(raysAtLevel2, 1u);
  EXPECT_EQ(progressive.LastCounts().Primary, 37u * 23u) << "no pixel traced twice";
  // The final image is the plain one-ray-per-pixel image.
  const RgbImage reference = plain.Render(FrontCamera(), 37, 23);
  EXPECT_EQ(image.Rgb, reference.Rgb);
  // Stopping from the callback returns no image.
  const RgbImage stopped =
    progressive.Render(FrontCamera(), 37, 23, [](const RgbImage&, int block) { return block > 8; });
  EXPECT_EQ(stopped.Width, 0);
  EXPECT_LT(progressive.LastCounts().Primary, 37u * 23u);
}

TEST(TexturedRayTracer, BadInputIsReportedNotCrashed)
{
  EXPECT_THROW(TexturedRayTracer(TexturedScene{}), std::invalid_argument); // empty
  {
    TexturedScene scene = EdgeScene();
    scene.Materials[0].Diffuse = glm::vec3(-1.0f);
    EXPECT_THROW(TexturedRayTracer{ scene }, std::invalid_argument);
  }
  {
    TexturedScene scene = EdgeScene();
    scene.Spheres[0].Geometry.Radius = std::nanf("");
    EXPECT_THROW(TexturedRayTracer{ scene }, std::invalid_argument);
  }
  {
    TexturedScene scene = EdgeScene();
    scene.Spheres[0].Material = 7;
    EXPECT_THROW(TexturedRayTracer{ scene }, std::invalid_argument);
  }
  {
    RayTracerSettings settings;
    settings.MaxDepth = -1;
    EXPECT_THROW(TexturedRayTracer(EdgeScene(), settings), std::invalid_argument);
    settings.MaxDepth = 3;
    settings.GlossySamples = 0;
    EXPECT_THROW(TexturedRayTracer(EdgeScene(), settings), std::invalid_argument);
  }
  {
    // Degenerate triangles are dropped with a warning; an empty map is ignored with one;
    // roughness above 1 is clamped with one.
    TexturedScene scene = EdgeScene();
    AddSquare(scene, 1.0f, -3.0f, 0);
    scene.Mesh.Positions.push_back(glm::vec3(1.0f));
    scene.Mesh.TextureCoordinates.push_back(glm::vec2(0.0f));
    const auto last = static_cast<std::uint32_t>(scene.Mesh.Positions.size() - 1);
    scene.Mesh.Triangles.emplace_back(last, last, last);
    scene.Mesh.MaterialIds.push_back(0);
    scene.Materials[0].DiffuseMap = std::make_shared<RgbImage>();
    scene.Materials[0].Roughness = 5.0f;
    const TexturedRayTracer tracer(scene);
    EXPECT_EQ(tracer.Warnings().size(), 3u);
    EXPECT_EQ(tracer.Scene().Mesh.TriangleCount(), 2u);
    EXPECT_FALSE(tracer.Scene().Materials[0].DiffuseMap);
    EXPECT_EQ(tracer.Render(FrontCamera(), 8, 8).Width, 8);
    PinholeCamera broken = FrontCamera();
    broken.ViewUp = glm::vec3(0, 0, 1); // parallel to the view direction
    EXPECT_EQ(tracer.Render(broken, 8, 8).Width, 0);
    EXPECT_EQ(tracer.Render(FrontCamera(), -3, 8).Width, 0);
  }
  {
    TexturedScene scene = EdgeScene();
    scene.Mesh.Positions = { { 0, 0, 0 }, { 1, 0, 0 } };
    scene.Mesh.Triangles = { { 0, 1, 5 } };
    scene.Mesh.MaterialIds = { 0 };
    EXPECT_THROW(TexturedRayTracer{ scene }, std::invalid_argument);
  }
}

} // namespace

// Each material map multiplies its channel where the ray hits (Ahern 1999's texture-mapped
// material channels), checked at the four texel centres of TwoByTwo() (0, 1, 0.25, 0.5) on a
// square seen straight from above; without the map the same expectations fail (negative).
TEST(TexturedRayTracer, EachMaterialMapScalesItsChannel)
{
  // (x, y) of the texel centres on AddSquare(scene, 1, 0, ...), and the map's value there.
  const glm::vec2 centres[4] = { { -0.5f, -0.5f }, { 0.5f, -0.5f }, { -0.5f, 0.5f },
    { 0.5f, 0.5f } };
  const float values[4] = { 0.0f, 1.0f, 0.25f, 0.5f };
  const auto map = std::make_shared<RgbImage>(TwoByTwo());
  RayTracerSettings settings;
  settings.Filter = TextureFilter::Nearest;
  settings.Reflections = false;
  // The light of the Phong terms: straight down for diffuse and specular, oblique for shininess
  // (then the reflected light meets the view at cos = c < 1 and the term is c^power).
  const glm::vec3 oblique = glm::normalize(glm::vec3(-0.3f, 0.0f, -1.0f));
  const glm::vec3 toLight = -oblique;
  const float c = glm::dot(2.0f * toLight.z * glm::vec3(0, 0, 1) - toLight, glm::vec3(0, 0, 1));
  struct Channel
  {
    const char* Name;
    std::function<void(TexturedMaterial&, bool)> Set; // bool: with the map
    glm::vec3 Light;
    std::function<float(float)> Expected; // of the map value
  };
  const Channel channels[] = {
    { "diffuse",
      [&](TexturedMaterial& m, bool with)
      {
        m.Diffuse = glm::vec3(1.0f);
        m.DiffuseMap = with ? map : nullptr;
      },
      glm::vec3(0, 0, -1), [](float v) { return v; } },
    { "specular",
      [&](TexturedMaterial& m, bool with)
      {
        m.Diffuse = glm::vec3(0.0f);
        m.Specular = glm::vec3(1.0f);
        m.SpecularMap = with ? map : nullptr;
      },
      glm::vec3(0, 0, -1), [](float v) { return v; } },
    { "shininess",
      [&](TexturedMaterial& m, bool with)
      {
        m.Diffuse = glm::vec3(0.0f);
        m.Specular = glm::vec3(1.0f);
        m.SpecularPower = 8.0f;
        m.ShininessMap = with ? map : nullptr;
      },
      oblique, [&](float v) { return std::pow(c, 8.0f * v); } },
  };
  for (const Channel& channel : channels)
  {
    for (const bool with : { true, false })
    {
      TexturedScene scene;
      TexturedMaterial material;
      channel.Set(material, with);
      scene.Materials.push_back(material);
      scene.Lights.push_back(Sun(channel.Light));
      AddSquare(scene, 1.0f, 0.0f, 0);
      const TexturedRayTracer tracer(scene, settings);
      int matches = 0;
      for (int k = 0; k < 4; ++k)
      {
        const glm::vec3 at(centres[k], 1.0f);
        const float seen = TraceOne(tracer, at, glm::vec3(0, 0, -1)).x;
        const bool match = std::abs(seen - channel.Expected(values[k])) < 1e-4f;
        matches += match ? 1 : 0;
        if (with)
        {
          EXPECT_TRUE(match) << channel.Name << " at texel " << k << ": " << seen << " vs "
                             << channel.Expected(values[k]);
        }
      }
      if (!with)
      {
        EXPECT_LT(matches, 4) << channel.Name << ": the map's values without the map";
      }
    }
  }
}

// The roughness map scales the roughness where the mirror is hit: a mirror point whose
// reflection looks at a ceiling's edge is sharp (0 or 1) where the map is 0 and blurred (about
// one half) where it is 1; without the map both are blurred.
TEST(TexturedRayTracer, RoughnessMapScalesTheRoughness)
{
  // The mirror floor [-10, 10]^2 carries TwoByTwo(): value 0 for x < 0, 1 for x > 0 (y < 0).
  auto makeScene = [](float edge, bool withMap)
  {
    TexturedScene scene;
    TexturedMaterial mirror = Matte(glm::vec3(0.0f));
    mirror.Specular = glm::vec3(1.0f);
    mirror.Roughness = 0.3f;
    if (withMap)
    {
      mirror.RoughnessMap = std::make_shared<RgbImage>(TwoByTwo());
    }
    scene.Materials.push_back(mirror);
    scene.Materials.push_back(Matte(glm::vec3(0.0f), glm::vec3(1.0f)));
    AddSquare(scene, 10.0f, 0.0f, 0);
    auto& mesh = scene.Mesh; // an ambient-white ceiling at z = 2 over x > edge
    const auto first = static_cast<std::uint32_t>(mesh.Positions.size());
    mesh.Positions.insert(
      mesh.Positions.end(), { { edge, -10, 2 }, { 10, -10, 2 }, { 10, 10, 2 }, { edge, 10, 2 } });
    mesh.TextureCoordinates.insert(mesh.TextureCoordinates.end(), 4, glm::vec2(0.0f));
    mesh.Triangles.emplace_back(first, first + 2, first + 1);
    mesh.Triangles.emplace_back(first, first + 3, first + 2);
    mesh.MaterialIds.insert(mesh.MaterialIds.end(), { 1, 1 });
    return scene;
  };
  RayTracerSettings settings;
  settings.GlossySamples = 400;
  settings.Filter = TextureFilter::Nearest;
  // From (e - 1, -5, 1) along (1/3, 0, -1): the mirror at x = e - 2/3, the ceiling's edge at e.
  const glm::vec3 direction(1.0f / 3.0f, 0.0f, -1.0f);
  for (const bool withMap : { true, false })
  {
    const TexturedRayTracer smoothSide(makeScene(-2.0f, withMap), settings); // mirror x = -8/3
    const TexturedRayTracer roughSide(makeScene(2.0f, withMap), settings);   // mirror x = 4/3
    const float atZero = TraceOne(smoothSide, glm::vec3(-3.0f, -5.0f, 1.0f), direction).x;
    const float atOne = TraceOne(roughSide, glm::vec3(1.0f, -5.0f, 1.0f), direction).x;
    EXPECT_GT(atOne, 0.3f) << withMap;
    EXPECT_LT(atOne, 0.7f) << withMap;
    if (withMap)
    {
      EXPECT_TRUE(atZero < 1e-5f || atZero > 1.0f - 1e-5f) << atZero;
    }
    else
    {
      EXPECT_GT(atZero, 0.3f); // negative: without the map the mirror is rough everywhere
      EXPECT_LT(atZero, 0.7f);
    }
  }
}
