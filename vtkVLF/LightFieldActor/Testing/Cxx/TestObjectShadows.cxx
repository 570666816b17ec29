// SPDX-License-Identifier: BSD-3-Clause
// Shadows of a movable object (ObjectShadows, Wither 2005 ch. 4): map placement and fill against
// analytic depths, back projection removed (and present with the removal off), and the floor of
// the Cornell box under a cube against the path tracer with the cube in the scene (the field is
// propagated without it): mean relative error per mode, field-derived darkening best; at 513
// directions the umbra without the direction aliasing's stripes and tint (the subtraction of the
// blocked direct light the negative case); the cost of filling and looking up maps per
// resolution. `ctest -R ShadowMap`.
#include "EmitterTestFields.h"
#include "ObjectShadows.h"
#include "WalkthroughTestFields.h"

#include "EmbreeScene.h"
#include "Lookup.h"
#include "MathConstants.h"
#include "ParallelFor.h"
#include "PatchComparison.h"
#include "PathTracer.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <map>
#include <memory>
#include <vector>

namespace mesolight
{
namespace
{
using vlf::ShadowMode;

// A one-sample emitter at `position` facing `normal` (for synthetic set-ups).
vlf::ShadowEmitter PointEmitter(const glm::vec3& position, const glm::vec3& normal)
{
  vlf::ShadowEmitter emitter;
  emitter.Light.Position = position;
  emitter.Light.Normal = normal;
  emitter.Light.Radiance = glm::vec3(1.0f);
  emitter.Light.Area = 1e-3;
  emitter.Samples.emplace_back(position, 1e-3f);
  return emitter;
}

float Mean(const glm::vec3& v)
{
  return (v.x + v.y + v.z) / 3.0f;
}

// The Cornell box test cube (millimetres): side 90, centred 120 above the floor in the free
// front-right quarter, so its shadow falls on open floor.
const glm::vec3 CubeCentre(400.0f, 120.0f, 150.0f);
constexpr float CubeSide = 90.0f;

vlf::ObjectMesh WorldCube()
{
  return vlf::TransformMesh(vlf::MakeCube(CubeSide), glm::translate(glm::mat4(1.0f), CubeCentre));
}
} // namespace

TEST(ShadowMapCore, PlacementFitsTheObjectAndDepthsAreExact)
{
  // A unit-sphere-sized set-up: a cube of side 0.2 at the origin, a light 0.8 above it.
  const vlf::ObjectMesh cube = vlf::MakeCube(0.2f);
  vlf::ShadowSettings settings;
  settings.Resolution = 128;
  vlf::ObjectShadows shadows;
  ASSERT_EQ(
    shadows.Build(
      { PointEmitter(glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0.0f, -1.0f, 0.0f)) }, cube, settings),
    "");
  ASSERT_EQ(shadows.Maps().size(), 1u);
  const vlf::ShadowMap& map = shadows.Maps()[0];
  EXPECT_NEAR(glm::length(map.AxisZ - glm::vec3(0.0f, -1.0f, 0.0f)), 0.0f, 1e-6f);
  // Frustum tangent to the bounding sphere (radius 0.1 sqrt 3), planes around it.
  const float r = 0.1f * std::sqrt(3.0f);
  EXPECT_NEAR(map.Near, 0.8f - r, 2e-3f);
  EXPECT_NEAR(map.Far, 0.8f + r, 1e-5f);
  // Every covered texel holds the top face's depth (0.7) or the sides' (larger); the centre
  // texel exactly 0.7; the covered fraction matches the top face's projected square.
  const int res = map.Resolution;
  EXPECT_NEAR(map.Depth[(res / 2) * res + res / 2], 0.7f, 1e-5f);
  int covered = 0;
  for (const float d : map.Depth)
  {
    if (d < vlf::ShadowMap::EmptyDepth)
    {
      ++covered;
      EXPECT_GE(d, 0.7f - 1e-5f);
      EXPECT_LE(d, 0.9f + 1e-5f);
    }
  }
  // The footprint is the top face's square (the nearest, so the widest, at depth 0.7): half
  // side 0.1 / 0.7 / tan.
  const float half = 0.1f / 0.7f / map.TanHalfAngle;
  const float expected = half * half * res * res;
  EXPECT_NEAR(covered / expected, 1.0f, 0.05f);
  // A point under the cube is blocked, one beside it is not.
  EXPECT_EQ(vlf::ShadowMapBlocked(
              map, glm::vec3(0.0f, -0.5f, 0.0f), glm::vec3(0, 1, 0), 1, settings.DepthBias, true),
    1.0f);
  EXPECT_EQ(vlf::ShadowMapBlocked(
              map, glm::vec3(0.5f, -0.5f, 0.0f), glm::vec3(0, 1, 0), 1, settings.DepthBias, true),
    0.0f);
  // The cube's own top face (a receiver touching the caster) is not self-shadowed.
  EXPECT_EQ(vlf::ShadowMapBlocked(
              map, glm::vec3(0.0f, 0.1f, 0.0f), glm::vec3(0, 1, 0), 1, settings.DepthBias, true),
    0.0f);
  // Bad settings and meshes are named, never used.
  settings.Resolution = 8;
  EXPECT_NE(
    shadows
      .Build({ PointEmitter(glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0, -1, 0)) }, cube, settings)
      .find("resolution 8"),
    std::string::npos);
  EXPECT_TRUE(shadows.Empty());
  settings.Resolution = 64;
  EXPECT_NE(shadows.Build(std::vector<vlf::ShadowEmitter>(), cube, settings).find("no emitter"),
    std::string::npos);
  EXPECT_NE(shadows
              .Build({ PointEmitter(glm::vec3(0.0f, 0.8f, 0.0f), glm::vec3(0, -1, 0)) },
                vlf::ObjectMesh(), settings)
              .find("no triangles"),
    std::string::npos);
  EXPECT_EQ(shadows.Shade(
              glm::vec3(1.0f), glm::vec3(0.0f, -0.5f, 0.0f), glm::vec3(0, 1, 0), glm::vec3(0.5f)),
    glm::vec3(1.0f));
}

TEST(ShadowMapCore, BackProjectionRemovedAndPresentWithoutRemoval)
{
  // Light at the origin facing down, a cube below it. Receivers: under the cube facing the light
  // (a real shadow), behind the light facing it (the object's image mirrored through the centre
  // of projection), under the cube facing away from the light.
  const vlf::ObjectMesh cube = vlf::TransformMesh(
    vlf::MakeCube(0.2f), glm::translate(glm::mat4(1.0f), glm::vec3(0, -0.4f, 0)));
  const std::vector<vlf::ShadowEmitter> light = { PointEmitter(
    glm::vec3(0.0f), glm::vec3(0, -1, 0)) };
  const glm::vec3 up(0, 1, 0), down(0, -1, 0);
  for (const bool removal : { true, false })
  {
    vlf::ShadowSettings settings;
    settings.Mode = ShadowMode::Black;
    settings.RemoveBackProjection = removal;
    vlf::ObjectShadows shadows;
    ASSERT_EQ(shadows.Build(light, cube, settings), "");
    SCOPED_TRACE(removal ? "removal on" : "removal off");
    EXPECT_EQ(shadows.Visibility(glm::vec3(0.0f, -0.8f, 0.0f), up), 0.0f); // real shadow
    const float behind = shadows.Visibility(glm::vec3(0.0f, 0.5f, 0.0f), down);
    const float away = shadows.Visibility(glm::vec3(0.0f, -0.8f, 0.0f), down);
    if (removal)
    {
      EXPECT_EQ(behind, 1.0f) << "a receiver behind the light is shadowed";
      EXPECT_EQ(away, 1.0f) << "a receiver facing away from the light is shadowed";
    }
    else
    {
      // Negative test: without the removal the plain depth test shadows both.
      EXPECT_EQ(behind, 0.0f);
      EXPECT_EQ(away, 0.0f);
    }
  }
}

TEST(ShadowMapCore, SeveralEmittersEachCastTheirOwnShadow)
{
  // The Cornell box with a second, weaker ceiling light (a third of the main one's power) over
  // the back-left corner and a third one too weak to matter; the cube hangs under the second.
  TriangleScene scene = MakeCornellBox();
  for (const float le : { 5.0f, 0.02f })
  {
    SceneMaterial light;
    light.Name = "extra light";
    light.Diffuse = glm::vec3(0.78f);
    light.Emission = glm::vec3(le);
    const float x = le > 1.0f ? 50.0f : 400.0f;
    scene.AddPolygon({ { x, 548.7f, 400.0f }, { x + 100.0f, 548.7f, 400.0f },
                       { x + 100.0f, 548.7f, 500.0f }, { x, 548.7f, 500.0f } },
      scene.AddMaterial(light));
  }
  vlf::LightFieldSettings fieldSettings;
  fieldSettings.Directions = 33;
  fieldSettings.RaysPerSide = 8;
  fieldSettings.TilesPerSide = 2;
  const std::unique_ptr<vlf::LightField> field = vlf::LightField::CreateEmpty(scene, fieldSettings);
  vlf::ShadowSettings settings;
  std::vector<vlf::ShadowEmitter> emitters = vlf::SignificantEmitters(*field, settings);
  ASSERT_EQ(emitters.size(), 2u); // the third is below MinimumPowerFraction
  const float main = 11.0f * 130.0f * 105.0f, second = 5.0f * 100.0f * 100.0f;
  EXPECT_NEAR(emitters[0].PowerWeight, main / (main + second), 0.01f);
  EXPECT_NEAR(emitters[1].PowerWeight, second / (main + second), 0.01f);
  for (const vlf::ShadowEmitter& e : emitters)
  {
    ASSERT_EQ(e.Samples.size(), 9u);
    float area = 0.0f;
    for (const glm::vec4& sample : e.Samples)
    {
      EXPECT_NEAR(glm::dot(glm::vec3(sample) - e.Light.Position, e.Light.Normal), 0.0f, 1e-5f);
      area += sample.w;
    }
    EXPECT_NEAR(area, static_cast<float>(e.Light.Area), 1e-6f);
  }
  // The second light's samples lie on its quad (world x in [50, 150], z in [400, 500]).
  for (const glm::vec4& sample : emitters[1].Samples)
  {
    const glm::vec3 world = vlf::ToWorld(*field, glm::vec3(sample));
    EXPECT_TRUE(world.x > 50.0f && world.x < 150.0f && world.z > 400.0f && world.z < 500.0f)
      << world.x << ", " << world.z;
  }
  // Packed into floats (ParaView's Light Field Gather puts them in its output for the Light
  // Field representation's shadows) and back: the same emitters; a cut list is refused.
  const std::vector<float> packed = vlf::PackEmitters(emitters);
  std::vector<vlf::ShadowEmitter> unpacked;
  ASSERT_TRUE(vlf::UnpackEmitters(packed.data(), packed.size(), unpacked));
  ASSERT_EQ(unpacked.size(), emitters.size());
  for (std::size_t e = 0; e < emitters.size(); ++e)
  {
    EXPECT_EQ(unpacked[e].Light.Surface, emitters[e].Light.Surface);
    EXPECT_EQ(unpacked[e].Light.Position, emitters[e].Light.Position);
    EXPECT_EQ(unpacked[e].Light.Normal, emitters[e].Light.Normal);
    EXPECT_EQ(unpacked[e].Light.Radiance, emitters[e].Light.Radiance);
    EXPECT_FLOAT_EQ(
      static_cast<float>(unpacked[e].Light.Area), static_cast<float>(emitters[e].Light.Area));
    EXPECT_EQ(unpacked[e].PowerWeight, emitters[e].PowerWeight);
    EXPECT_EQ(unpacked[e].Samples, emitters[e].Samples);
    EXPECT_EQ(unpacked[e].Lamps, emitters[e].Lamps);
  }
  EXPECT_FALSE(vlf::UnpackEmitters(packed.data(), packed.size() - 1, unpacked));
  EXPECT_TRUE(unpacked.empty());
  EXPECT_FALSE(vlf::UnpackEmitters(packed.data(), 5, unpacked));
  settings.MaximumEmitters = 1;
  EXPECT_EQ(vlf::SignificantEmitters(*field, settings).size(), 1u);
  settings.MaximumEmitters = 4;

  const vlf::ObjectMesh cube =
    vlf::TransformMesh(vlf::TransformMesh(vlf::MakeCube(60.0f),
                         glm::translate(glm::mat4(1.0f), glm::vec3(100.0f, 400.0f, 450.0f))),
      vlf::WorldToUnitSphere(*field));
  const glm::vec3 p = vlf::ToUnit(*field, glm::vec3(100.0f, 0.0f, 450.0f));
  const glm::vec3 up(0.0f, 1.0f, 0.0f), kd(0.7f), total(1.0f);
  for (const ShadowMode mode : { ShadowMode::Field, ShadowMode::Soft })
  {
    settings.Mode = mode;
    vlf::ObjectShadows shadows;
    ASSERT_EQ(shadows.Build(*field, cube, settings), "");
    EXPECT_EQ(shadows.Maps().size(), mode == ShadowMode::Soft ? 20u : 2u);
    EXPECT_EQ(shadows.BlockedFraction(0, p, up), 0.0f); // the main light sees p
    EXPECT_GT(shadows.BlockedFraction(1, p, up), mode == ShadowMode::Soft ? 0.7f : 0.99f);
    // Only the second light's direct light is lost: the field's value keeps the share of the
    // lighting (ambient A + direct E / pi) the object leaves.
    ASSERT_TRUE(shadows.HasAmbient()); // the field overload sets it (0 for this empty field)
    const glm::vec3 a = shadows.Ambient();
    const glm::vec3 e0 = shadows.DirectIrradiance(0, p, up),
                    e1 = shadows.DirectIrradiance(1, p, up);
    const float b1 = shadows.BlockedFraction(1, p, up);
    const glm::vec3 share = (a + (e0 + (1.0f - b1) * e1) / Pi<float>) / (a + (e0 + e1) / Pi<float>);
    const glm::vec3 shaded = shadows.Shade(total, p, up, kd);
    EXPECT_NEAR(shaded.x, total.x * share.x, 1e-4f);
    EXPECT_LT(shaded.x, total.x);
    // A field darker than the blocked direct light (its own error) keeps the same share.
    const glm::vec3 lost = kd / Pi<float> * b1 * e1;
    EXPECT_NEAR(shadows.Shade(0.5f * lost, p, up, kd).x, 0.5f * lost.x * share.x, 1e-6f);
    // Without an ambient term: the subtraction of the blocked direct light, clamped at 0.
    shadows.ClearAmbient();
    EXPECT_NEAR(shadows.Shade(total, p, up, kd).x, total.x - lost.x, 1e-3f * lost.x + 1e-6f);
    EXPECT_EQ(shadows.Shade(0.5f * lost, p, up, kd), glm::vec3(0.0f));
    // Both emitters' maps fit the shader's arrays.
    const vlf::ShadowGpuData gpu = vlf::PackShadowsForGpu(shadows);
    EXPECT_EQ(gpu.EmitterCount, 2);
    EXPECT_EQ(gpu.MapPosition.size(), shadows.Maps().size());
  }
  settings.Mode = ShadowMode::Black;
  vlf::ObjectShadows black;
  ASSERT_EQ(black.Build(*field, cube, settings), "");
  EXPECT_NEAR(black.Visibility(p, up), 1.0f - emitters[1].PowerWeight, 1e-5f);
}

namespace
{
struct FloorReceivers
{
  std::vector<glm::vec3> World, Unit;
  std::vector<glm::vec3> Reference; // path tracer, cube in the scene
  std::vector<glm::vec3> Field;     // the field's diffuse radiance (propagated without the cube)
  std::uint32_t Surface = 0;
  glm::vec3 Kd{ 0.0f };
};

// An n x n grid of floor points around the cube's shadow, their path-traced radiance with the
// cube in the scene (cached per process) and the field's.
const FloorReceivers& Receivers(const vlf::LightField& field)
{
  static std::unique_ptr<FloorReceivers> cached;
  if (cached)
  {
    return *cached;
  }
  cached.reset(new FloorReceivers);
  FloorReceivers& r = *cached;
  TriangleScene scene = MakeCornellBox();
  const std::size_t floorTriangles = scene.TriangleCount();
  const vlf::ObjectMesh cube = WorldCube();
  SceneMaterial material;
  material.Name = "object";
  material.Diffuse = cube.Diffuse;
  const std::uint32_t id = scene.AddMaterial(material);
  for (const glm::uvec3& t : cube.Triangles)
  {
    scene.AddPolygon({ cube.Positions[t.x], cube.Positions[t.y], cube.Positions[t.z] }, id);
  }
  const EmbreeScene embree(scene);
  const PathTracer tracer(embree);
  constexpr int n = 14;
  for (int b = 0; b < n; ++b)
  {
    for (int a = 0; a < n; ++a)
    {
      const glm::vec3 p(340.0f + 200.0f * (a + 0.5f) / n, 0.0f, 10.0f + 200.0f * (b + 0.5f) / n);
      // The floor triangle under p (the box's floor: y = 0, facing up).
      std::size_t triangle = floorTriangles;
      for (std::size_t t = 0; t < floorTriangles; ++t)
      {
        const glm::vec3 fn = glm::normalize(scene.FaceNormal(t));
        if (fn.y < 0.99f || std::abs(scene.Vertex(t, 0).y) > 1.0f)
        {
          continue;
        }
        const glm::vec3 v0 = scene.Vertex(t, 0), v1 = scene.Vertex(t, 1), v2 = scene.Vertex(t, 2);
        const float w0 = glm::dot(glm::cross(v2 - v1, p - v1), fn);
        const float w1 = glm::dot(glm::cross(v0 - v2, p - v2), fn);
        const float w2 = glm::dot(glm::cross(v1 - v0, p - v0), fn);
        if (w0 >= 0.0f && w1 >= 0.0f && w2 >= 0.0f)
        {
          triangle = t;
          break;
        }
      }
      if (triangle == floorTriangles)
      {
        ADD_FAILURE() << "no floor under " << p.x << ", " << p.z;
        continue;
      }
      r.Surface = field.SurfaceOfTriangle(triangle);
      r.World.push_back(p);
      r.Unit.push_back(vlf::ToUnit(field, p));
    }
  }
  r.Kd = field.MaterialOf(r.Surface).Diffuse;
  r.Reference.resize(r.World.size());
  r.Field.resize(r.World.size());
  const vlf::Lookup lookup(field);
  for (std::size_t i = 0; i < r.World.size(); ++i)
  {
    r.Field[i] = lookup.DiffuseRadiance(r.Surface, r.Unit[i]);
  }
  // The floor triangle of each point again inside the tracer (DiffuseRadianceLeaving wants one).
  ParallelFor(0, r.World.size(), 1,
    [&](std::size_t i0, std::size_t i1)
    {
      for (std::size_t i = i0; i < i1; ++i)
      {
        std::size_t triangle = 0;
        for (std::size_t t = 0; t < floorTriangles; ++t)
        {
          if (field.SurfaceOfTriangle(t) == r.Surface)
          {
            triangle = t;
            break;
          }
        }
        r.Reference[i] = tracer.DiffuseRadianceLeaving(
          static_cast<std::uint32_t>(triangle), r.World[i], 4096, 1000 + i);
      }
    });
  return r;
}

struct ModeError
{
  double All = 0.0, Shadowed = 0.0, Lit = 0.0;
  int ShadowedCount = 0;
};

// Mean relative error (mean of RGB) over all receivers and over those the soft shadow touches.
ModeError Errors(
  const FloorReceivers& r, const vlf::ObjectShadows& shadows, const vlf::ObjectShadows& soft)
{
  ModeError e;
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  for (std::size_t i = 0; i < r.Unit.size(); ++i)
  {
    const glm::vec3 shaded = shadows.Shade(r.Field[i], r.Unit[i], up, r.Kd);
    const double error = std::abs(Mean(shaded) - Mean(r.Reference[i])) / Mean(r.Reference[i]);
    e.All += error;
    if (soft.BlockedFraction(0, r.Unit[i], up) > 0.0f)
    {
      e.Shadowed += error;
      ++e.ShadowedCount;
    }
    else
    {
      e.Lit += error;
    }
  }
  e.All /= static_cast<double>(r.Unit.size());
  e.Shadowed /= std::max(1, e.ShadowedCount);
  e.Lit /= std::max(1, static_cast<int>(r.Unit.size()) - e.ShadowedCount);
  return e;
}
} // namespace

TEST(ShadowMapCore, EachLampCastsFromItsOwnArea)
{
  // Lamps of one material on one plane are one field surface but separate lights: each shadow
  // emitter's samples lie on its own lamp (sampled over the whole surface, the two emitters
  // would each spread over both lamps, and a lamp's shadow map would stand for the other's light).
  using emittertest::Lamp;
  const std::vector<Lamp> two = { { -0.8f, -0.4f, -0.2f, 0.2f, glm::vec3(2.0f) },
    { 0.4f, 0.6f, -0.1f, 0.1f, glm::vec3(2.0f) } };
  const std::unique_ptr<vlf::LightField> field = emittertest::BoxWithLamps(two);
  const vlf::ShadowSettings settings;
  const std::vector<vlf::ShadowEmitter> emitters = vlf::SignificantEmitters(*field, settings);
  ASSERT_EQ(emitters.size(), 2u);
  for (std::size_t e = 0; e < 2; ++e)
  {
    const Lamp& lamp = two[e]; // the larger lamp is the brighter light, first
    float area = 0.0f;
    EXPECT_EQ(emitters[e].Samples.size(), 9u);
    for (const glm::vec4& sample : emitters[e].Samples)
    {
      const glm::vec3 world = vlf::ToWorld(*field, glm::vec3(sample));
      EXPECT_TRUE(world.x > lamp.X0 && world.x < lamp.X1 && world.z > lamp.Z0 && world.z < lamp.Z1)
        << "emitter " << e << " sample at " << world.x << ", " << world.z;
      area += sample.w;
    }
    EXPECT_NEAR(area, static_cast<float>(emitters[e].Light.Area), 1e-6f);
  }

  // The emitters' samples give the direct irradiance the shadows take their share of: 0.8 below
  // the small lamp against the exact integral over both lamps.
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  const auto sampled = [&up](const vlf::LightField& f, const std::vector<vlf::ShadowEmitter>& list,
                         const glm::vec3& world)
  {
    double e = 0.0;
    for (const vlf::ShadowEmitter& emitter : list)
    {
      for (const glm::vec4& sample : emitter.Samples)
      {
        e += vlf::SampleIrradiance(
          emitter.Light.Radiance, emitter.Light.Normal, sample, vlf::ToUnit(f, world), up)
               .x;
      }
    }
    return e;
  };
  const auto exact = [&up](const std::vector<Lamp>& lamps, const glm::vec3& world)
  {
    double e = 0.0;
    for (const Lamp& l : lamps)
    {
      e += l.Emission.x *
        emittertest::RectangleIrradiance(
          world, up, l.X0, l.X1, l.Z0, l.Z1, emittertest::LampHeight);
    }
    return e;
  };
  const glm::vec3 belowSmall(0.5f, emittertest::LampHeight - 0.8f, 0.0f);
  const double twoError =
    std::abs(sampled(*field, emitters, belowSmall) / exact(two, belowSmall) - 1.0);
  std::printf("[ figures  ] two lamps: the emitters' direct irradiance 0.8 below the small lamp "
              "%.1f%% off the exact\n",
    100.0 * twoError);
  EXPECT_LT(twoError, 0.03);

  // Twelve lamps and at most 4 shadow emitters: merged to 4, their samples on the lamps and
  // their areas all twelve lamps' (the 4 brightest alone would leave 8 lamps' light unshadowed).
  const std::vector<Lamp> twelve = emittertest::TwelveLamps();
  const std::unique_ptr<vlf::LightField> room = emittertest::BoxWithLamps(twelve);
  const std::vector<vlf::ShadowEmitter> merged = vlf::SignificantEmitters(*room, settings);
  ASSERT_EQ(merged.size(), 4u);
  const double scale2 = room->NormalizationScale() * room->NormalizationScale();
  double area = 0.0;
  for (const vlf::ShadowEmitter& e : merged)
  {
    area += e.Light.Area / scale2;
    // A sample on each of its lamps, and no more samples than one lamp gets (3 x 3).
    const std::size_t lamps = vlf::LampsOf(room->Scene(), e.Light.Triangles).size();
    EXPECT_GE(lamps, 1u);
    EXPECT_GE(e.Samples.size(), lamps);
    EXPECT_LE(e.Samples.size(), 9u);
    for (const glm::vec4& sample : e.Samples)
    {
      const glm::vec3 world = vlf::ToWorld(*room, glm::vec3(sample));
      EXPECT_TRUE(std::any_of(twelve.begin(), twelve.end(),
        [&world](const Lamp& l)
        { return world.x > l.X0 && world.x < l.X1 && world.z > l.Z0 && world.z < l.Z1; }))
        << world.x << ", " << world.z;
    }
  }
  EXPECT_NEAR(area, 12 * 0.04, 1e-5);
  // An emitter of merged lamps gets a map per sample in Field mode (the default) as in Soft: one
  // hard map at the lamps' centroid would cast a shadow none of them casts. A single lamp keeps
  // its one map.
  const vlf::ObjectMesh cube =
    vlf::TransformMesh(vlf::MakeCube(0.2f), vlf::WorldToUnitSphere(*room));
  vlf::ObjectShadows fieldShadows;
  ASSERT_EQ(fieldShadows.Build(*room, cube, settings), "");
  for (std::size_t e = 0; e < merged.size(); ++e)
  {
    EXPECT_GT(merged[e].Lamps, 1u);
    EXPECT_EQ(fieldShadows.MapsOf(e).size(), 1 + merged[e].Samples.size());
  }
  vlf::ObjectShadows single;
  ASSERT_EQ(single.Build(*field, cube, settings), "");
  EXPECT_EQ(single.MapsOf(0).size(), 1u);
  double worst = 0.0;
  for (const glm::vec3 world :
    { glm::vec3(0.0f, 0.0f, 0.0f), glm::vec3(-0.6f, -0.9f, 0.4f), glm::vec3(0.7f, -0.5f, -0.5f) })
  {
    worst = std::max(worst, std::abs(sampled(*room, merged, world) / exact(twelve, world) - 1.0));
  }
  std::printf("[ figures  ] twelve lamps, 4 emitters: their direct irradiance 1-2 below the "
              "ceiling at most %.1f%% off the exact\n",
    100.0 * worst);
  EXPECT_LT(worst, 0.05);
}

TEST(ShadowMapCore, FloorAgainstPathTracerFieldDerivedBest)
{
  // 2049 directions: at 513 the small light reaches each floor texel along a handful of
  // directions, and that aliasing (about 10% in the lit floor) is what the field-derived
  // subtraction leaves in the umbra.
  const vlf::LightField& field = walkthroughtest::PlainCornellField(2049);
  const FloorReceivers& r = Receivers(field);
  ASSERT_EQ(r.World.size(), 14u * 14u);
  const vlf::ObjectMesh cube = vlf::TransformMesh(WorldCube(), vlf::WorldToUnitSphere(field));
  vlf::ShadowSettings softSettings;
  softSettings.Mode = ShadowMode::Soft;
  vlf::ObjectShadows soft;
  ASSERT_EQ(soft.Build(field, cube, softSettings), "");
  ASSERT_EQ(soft.Emitters().size(), 1u); // the Cornell box has one light
  EXPECT_EQ(soft.Emitters()[0].Samples.size(), 9u);

  const ShadowMode modes[] = { ShadowMode::None, ShadowMode::Black, ShadowMode::Blend,
    ShadowMode::Field, ShadowMode::PCF, ShadowMode::Soft };
  std::map<int, ModeError> at256;
  for (const int resolution : { 128, 256, 512, 1024 })
  {
    for (const ShadowMode mode : modes)
    {
      vlf::ShadowSettings settings;
      settings.Mode = mode;
      settings.Resolution = resolution;
      vlf::ObjectShadows shadows;
      ASSERT_EQ(shadows.Build(field, cube, settings), "");
      const ModeError e = Errors(r, shadows, soft);
      if (resolution == 256)
      {
        at256[static_cast<int>(mode)] = e;
      }
      std::printf("[ figures  ] shadows %-5s %4d^2: mean relative error %.1f%% over %zu floor "
                  "points, %.1f%% over the %d in or near the shadow\n",
        vlf::ShadowModeName(mode), resolution, 100.0 * e.All, r.Unit.size(), 100.0 * e.Shadowed,
        e.ShadowedCount);
    }
  }
  // The field's own error on the lit floor sets the floor of every mode's error.
  const ModeError none = at256[static_cast<int>(ShadowMode::None)];
  const ModeError black = at256[static_cast<int>(ShadowMode::Black)];
  const ModeError blend = at256[static_cast<int>(ShadowMode::Blend)];
  const ModeError fieldDerived = at256[static_cast<int>(ShadowMode::Field)];
  const ModeError pcf = at256[static_cast<int>(ShadowMode::PCF)];
  const ModeError softError = at256[static_cast<int>(ShadowMode::Soft)];
  std::printf("[ figures  ] shadows: the field's own error on the %d lit floor points (no shadow "
              "there): %.1f%%\n",
    static_cast<int>(r.Unit.size()) - none.ShadowedCount, 100.0 * none.Lit);
  EXPECT_GT(fieldDerived.ShadowedCount, 40);
  EXPECT_LT(fieldDerived.All, blend.All);
  EXPECT_LT(fieldDerived.All, black.All);
  EXPECT_LT(fieldDerived.All, none.All);
  EXPECT_LT(fieldDerived.Shadowed, blend.Shadowed);
  EXPECT_LT(fieldDerived.Shadowed, black.Shadowed);
  // The penumbra: filtering and the area samples do better than the hard edge.
  EXPECT_LT(softError.All, fieldDerived.All);
  EXPECT_LT(pcf.All, blend.All);
}

namespace
{
// The Cornell floor inside the cube's umbra (every emitter sample blocked): the path-traced
// radiance with the cube in the scene and the field-derived shading of a 513-direction field.
struct UmbraFigures
{
  int Points = 0;
  double Stripes = 0.0;   // mean |ratio step| between grid neighbours (ratio: shaded / reference)
  double Spread = 0.0;    // standard deviation of the ratio
  double Tint = 0.0;      // mean |log((R/G) shaded / (R/G) reference)|
  double MeanRatio = 0.0; // mean ratio
};

UmbraFigures MeasureUmbra(const vlf::ObjectShadows& shadows, const vlf::ObjectShadows& soft,
  const std::vector<glm::vec3>& unit, const std::vector<glm::vec3>& reference,
  const std::vector<glm::vec3>& total, const glm::vec3& kd, int n)
{
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  std::vector<double> ratio(unit.size(), -1.0);
  UmbraFigures f;
  double sum = 0.0, sum2 = 0.0, tint = 0.0;
  for (std::size_t i = 0; i < unit.size(); ++i)
  {
    if (soft.BlockedFraction(0, unit[i], up) < 0.999f)
    {
      continue; // penumbra or lit
    }
    const glm::vec3 shaded = shadows.Shade(total[i], unit[i], up, kd);
    ratio[i] = Mean(shaded) / Mean(reference[i]);
    sum += ratio[i];
    sum2 += ratio[i] * ratio[i];
    tint += std::abs(std::log(
      (std::max(shaded.x, 1e-6f) / std::max(shaded.y, 1e-6f)) / (reference[i].x / reference[i].y)));
    ++f.Points;
  }
  if (f.Points == 0)
  {
    return f;
  }
  f.MeanRatio = sum / f.Points;
  f.Spread = std::sqrt(std::max(0.0, sum2 / f.Points - f.MeanRatio * f.MeanRatio));
  f.Tint = tint / f.Points;
  int steps = 0;
  for (int b = 0; b < n; ++b)
  {
    for (int a = 0; a < n; ++a)
    {
      const std::size_t i = static_cast<std::size_t>(b) * n + a;
      for (const std::size_t j : { i + 1, i + static_cast<std::size_t>(n) })
      {
        if ((j == i + 1 && a + 1 >= n) || j >= unit.size() || ratio[i] < 0.0 || ratio[j] < 0.0)
        {
          continue;
        }
        f.Stripes += std::abs(ratio[j] - ratio[i]);
        ++steps;
      }
    }
  }
  f.Stripes /= std::max(1, steps);
  return f;
}
} // namespace

TEST(ShadowMapCore, UmbraAt513DirectionsWithoutStripesAgainstPathTracer)
{
  // At 513 directions the small light reaches each floor texel along a handful of directions:
  // the field's lit floor carries about 10% of aliasing stripes. Subtracting the exact blocked
  // direct light from it (the field-derived shadow before the ratio) leaves that absolute error
  // on the umbra's indirect light alone, several times larger relative to it, clamped per
  // channel at 0 where the field is darker: red and dark stripes. The ratio keeps the field's
  // relative error. Reference: the path tracer with the cube in the scene.
  const vlf::LightField& field = walkthroughtest::PlainCornellField(513);
  TriangleScene scene = MakeCornellBox();
  const std::size_t staticTriangles = scene.TriangleCount();
  const vlf::ObjectMesh worldCube = WorldCube();
  SceneMaterial material;
  material.Name = "object";
  material.Diffuse = worldCube.Diffuse;
  const std::uint32_t id = scene.AddMaterial(material);
  for (const glm::uvec3& t : worldCube.Triangles)
  {
    scene.AddPolygon(
      { worldCube.Positions[t.x], worldCube.Positions[t.y], worldCube.Positions[t.z] }, id);
  }
  const EmbreeScene embree(scene);
  const PathTracer tracer(embree);
  const vlf::ObjectMesh cube = vlf::TransformMesh(worldCube, vlf::WorldToUnitSphere(field));
  vlf::ShadowSettings softSettings;
  softSettings.Mode = ShadowMode::Soft;
  vlf::ObjectShadows soft;
  ASSERT_EQ(soft.Build(field, cube, softSettings), "");
  // The floor triangle (y = 0, facing up) and its surface.
  std::uint32_t floorTriangle = 0;
  for (std::size_t t = 0; t < staticTriangles; ++t)
  {
    if (glm::normalize(scene.FaceNormal(t)).y > 0.99f && std::abs(scene.Vertex(t, 0).y) < 1.0f)
    {
      floorTriangle = static_cast<std::uint32_t>(t);
      break;
    }
  }
  const std::uint32_t surface = field.SurfaceOfTriangle(floorTriangle);
  const glm::vec3 kd = field.MaterialOf(surface).Diffuse;
  // A 28 x 28 grid (5 mm apart) over the cube's shadow; the umbra's points are compared.
  constexpr int n = 28;
  std::vector<glm::vec3> world, unit, total, reference;
  for (int b = 0; b < n; ++b)
  {
    for (int a = 0; a < n; ++a)
    {
      world.emplace_back(395.0f + 5.0f * a, 0.0f, 40.0f + 5.0f * b);
      unit.push_back(vlf::ToUnit(field, world.back()));
    }
  }
  const vlf::Lookup lookup(field);
  const glm::vec3 up(0.0f, 1.0f, 0.0f);
  reference.assign(world.size(), glm::vec3(0.0f));
  for (const glm::vec3& u : unit)
  {
    total.push_back(lookup.DiffuseRadiance(surface, u));
  }
  ParallelFor(0, world.size(), 1,
    [&](std::size_t i0, std::size_t i1)
    {
      for (std::size_t i = i0; i < i1; ++i)
      {
        if (soft.BlockedFraction(0, unit[i], up) >= 0.999f)
        {
          reference[i] = tracer.DiffuseRadianceLeaving(floorTriangle, world[i], 2048, 7000 + i);
        }
      }
    });
  vlf::ShadowSettings settings; // the default: field-derived
  ASSERT_EQ(settings.Mode, ShadowMode::Field);
  vlf::ObjectShadows shadows;
  ASSERT_EQ(shadows.Build(field, cube, settings), "");
  const UmbraFigures ratio = MeasureUmbra(shadows, soft, unit, reference, total, kd, n);
  // The umbra's indirect light per unit reflectance: the estimate and the path tracer's mean.
  glm::vec3 traced(0.0f);
  {
    glm::dvec3 sum(0.0);
    int umbra = 0;
    for (std::size_t i = 0; i < unit.size(); ++i)
    {
      if (reference[i] != glm::vec3(0.0f))
      {
        sum += glm::dvec3(reference[i] / kd);
        ++umbra;
      }
    }
    traced = glm::vec3(sum / static_cast<double>(std::max(1, umbra)));
    const glm::vec3 a = shadows.Ambient();
    const glm::vec3 mean = vlf::EstimateEmitterLights(field).Ambient;
    const auto start = std::chrono::steady_clock::now();
    vlf::EstimateShadowIndirect(field, soft.Emitters(), cube);
    std::printf("[ figures  ] EstimateShadowIndirect: %.1f ms (%zu triangles)\n",
      1e3 * std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count(),
      field.Scene().TriangleCount());
    std::printf("[ figures  ] umbra indirect per unit Kd: estimate %.4f %.4f %.4f, path tracer "
                "%.4f %.4f %.4f, the field's mean radiance %.4f %.4f %.4f\n",
      a.x, a.y, a.z, traced.x, traced.y, traced.z, mean.x, mean.y, mean.z);
  }
  shadows.ClearAmbient(); // the negative case: the subtraction
  const UmbraFigures subtraction = MeasureUmbra(shadows, soft, unit, reference, total, kd, n);
  for (const auto& [name, f] :
    { std::make_pair("ratio", ratio), std::make_pair("subtraction", subtraction) })
  {
    std::printf("[ figures  ] umbra at 513 directions, %-11s: %d points, shaded / path tracer "
                "mean %.3f, spread %.3f, neighbour step %.3f, R/G tint %.3f\n",
      name, f.Points, f.MeanRatio, f.Spread, f.Stripes, f.Tint);
  }
  ASSERT_GT(ratio.Points, 60);
  // Measured (shaded / path tracer): ratio mean 1.12, neighbour step 0.071 (6% of the mean),
  // spread 0.171, R/G tint 0.148; subtraction mean 1.055, step 0.138 (13%), spread 0.395, tint
  // 0.799 (the clamped green and blue). The reference's own noise (2048 paths) is in the steps.
  auto stripes = [](const UmbraFigures& f) { return f.Stripes / f.MeanRatio; };
  auto spread = [](const UmbraFigures& f) { return f.Spread / f.MeanRatio; };
  EXPECT_LT(stripes(ratio), 0.09);
  EXPECT_LT(spread(ratio), 0.25);
  EXPECT_LT(ratio.Tint, 0.3);
  EXPECT_GT(ratio.MeanRatio, 0.8);
  EXPECT_LT(ratio.MeanRatio, 1.35);
  // The negative case, the subtraction, fails each of them but the mean.
  EXPECT_GT(stripes(subtraction), 0.09);
  EXPECT_GT(spread(subtraction), 0.25);
  EXPECT_GT(subtraction.Tint, 0.3);
  // The estimate of the umbra's indirect light against the path tracer's (per unit Kd).
  EXPECT_NEAR(Mean(shadows.Ambient()), Mean(traced), 0.3 * Mean(traced));
}

TEST(ShadowMapCore, CostPerResolution)
{
  const vlf::LightField& field = walkthroughtest::PlainCornellField(2049);
  const vlf::ObjectMesh sphere =
    vlf::TransformMesh(vlf::TransformMesh(vlf::MakeSphere(0.5f * CubeSide, 24, 48),
                         glm::translate(glm::mat4(1.0f), CubeCentre)),
      vlf::WorldToUnitSphere(field));
  // Receivers: a grid over the floor's unit-sphere bounds.
  const glm::vec3 lower = vlf::ToUnit(field, glm::vec3(0.0f, 0.0f, 0.0f));
  const glm::vec3 upper = vlf::ToUnit(field, glm::vec3(550.0f, 0.0f, 550.0f));
  std::vector<glm::vec3> points;
  for (int b = 0; b < 256; ++b)
  {
    for (int a = 0; a < 256; ++a)
    {
      points.push_back(glm::vec3(lower.x + (upper.x - lower.x) * (a + 0.5f) / 256.0f, lower.y,
        lower.z + (upper.z - lower.z) * (b + 0.5f) / 256.0f));
    }
  }
  struct ShadowFigures
  {
    int Resolution;
    ShadowMode Mode;
    double Darkness, Area;
  };
  std::vector<ShadowFigures> results;
  for (const int resolution : { 128, 256, 512, 1024 })
  {
    for (const ShadowMode mode : { ShadowMode::Field, ShadowMode::PCF, ShadowMode::Soft })
    {
      vlf::ShadowSettings settings;
      settings.Mode = mode;
      settings.Resolution = resolution;
      vlf::ObjectShadows shadows;
      double fill = 1e30;
      for (int repeat = 0; repeat < 3; ++repeat) // best of three, one thread
      {
        ASSERT_EQ(shadows.Build(field, sphere, settings, 1), "");
        fill = std::min(fill, shadows.FillSeconds());
      }
      const auto start = std::chrono::steady_clock::now();
      glm::vec3 sum(0.0f);
      std::vector<float> shade(points.size());
      for (std::size_t i = 0; i < points.size(); ++i)
      {
        const glm::vec3 s =
          shadows.Shade(glm::vec3(1.0f), points[i], glm::vec3(0.0f, 1.0f, 0.0f), glm::vec3(0.7f));
        shade[i] = Mean(s);
        sum += s;
      }
      const double lookup =
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
      // The timings are figures; what is checked is that every resolution and mode darkens the
      // same floor: the shadow's darkness (1 - mean shade; the emitter's direct share of a total
      // of 1) and its area (receivers darkened by 1% or more) within a margin of the finest hard
      // map's.
      const double darkness = 1.0 - Mean(sum) / static_cast<double>(points.size());
      const double area = static_cast<double>(std::count_if(
                            shade.begin(), shade.end(), [](float v) { return v < 0.99f; })) /
        static_cast<double>(points.size());
      std::printf("[ figures  ] shadow maps %-5s %4d^2: %zu map(s) of a %zu-triangle sphere "
                  "filled in %.2f ms (one thread); lookup %.0f ns per receiver; darkness %.4f, "
                  "area %.4f\n",
        vlf::ShadowModeName(mode), resolution, shadows.Maps().size(), sphere.Triangles.size(),
        1e3 * fill, 1e9 * lookup / points.size(), darkness, area);
      results.push_back({ resolution, mode, darkness, area });
    }
  }
  const ShadowFigures* finest = nullptr;
  for (const ShadowFigures& r : results)
  {
    finest = r.Resolution == 1024 && r.Mode == ShadowMode::Field ? &r : finest;
  }
  ASSERT_NE(finest, nullptr);
  EXPECT_GT(finest->Darkness, 0.001);
  EXPECT_GT(finest->Area, 0.01);
  // Measured: darkness 0.0030 everywhere; area 0.038 (field, PCF), 0.053 (soft: its penumbra
  // reaches further).
  for (const ShadowFigures& r : results)
  {
    EXPECT_NEAR(r.Darkness, finest->Darkness, 0.1 * finest->Darkness)
      << vlf::ShadowModeName(r.Mode) << " " << r.Resolution;
    if (r.Mode == ShadowMode::Soft)
    {
      EXPECT_GT(r.Area, finest->Area) << r.Resolution;
      EXPECT_LT(r.Area, 1.6 * finest->Area) << r.Resolution;
    }
    else
    {
      EXPECT_NEAR(r.Area, finest->Area, 0.1 * finest->Area)
        << vlf::ShadowModeName(r.Mode) << " " << r.Resolution;
    }
  }
}

} // namespace mesolight
