// SPDX-License-Identifier: BSD-3-Clause
// The movable object in the walkthrough's plain C++ cores (Wither 2005, "Interactive dynamic
// objects in a virtual light field"): the instanced object of EmbreeScene (hits, moves, clears,
// packets), and WalkthroughTracer's occlusion and reflections in every specular quality against
// an independent ray cast of one merged triangle scene; without the object the masks fail.
#include "ObjectTestReference.h"
#include "WalkthroughTestFields.h"

#include "ObjectMesh.h"
#include "TriangleScene.h"
#include "WalkthroughTracer.h"

#include <gtest/gtest.h>

#include <glm/gtc/matrix_transform.hpp>

#include <chrono>
#include <cmath>
#include <iostream>

namespace mesolight
{
namespace
{
using namespace objecttest;
using walkthroughtest::MirrorCornellField;

TEST(WalkthroughObject, EmbreeInstanceHitsMovesAndClears)
{
  TriangleScene floor;
  floor.Materials.push_back(SceneMaterial{});
  floor.Positions = { { -10, -10, -5 }, { 10, -10, -5 }, { 0, 10, -5 } };
  floor.Triangles = { { 0, 1, 2 } };
  floor.MaterialIds = { 0 };
  EmbreeScene scene(floor);
  const vlf::ObjectMesh cube = vlf::MakeCube(1.0f);
  SceneRay ray;
  ray.Origin = glm::vec3(0.0f, 0.0f, 10.0f);
  ray.Direction = glm::vec3(0.0f, 0.0f, -1.0f);
  EXPECT_EQ(scene.Intersect(ray).Triangle, 0u); // the static triangle only
  scene.SetObject(cube.Positions, cube.Triangles);
  ASSERT_TRUE(scene.HasObject());
  SceneHit hit = scene.Intersect(ray);
  EXPECT_NE(hit.ObjectTriangle, SceneHit::None);
  EXPECT_EQ(hit.Triangle, SceneHit::None);
  EXPECT_NEAR(hit.T, 9.5f, 1e-4f); // the cube's top face at z = 0.5
  // The barycentrics give the hit point on the object's own triangle.
  const glm::uvec3 t = cube.Triangles[hit.ObjectTriangle];
  const glm::vec3 p = (1.0f - hit.U - hit.V) * cube.Positions[t.x] + hit.U * cube.Positions[t.y] +
    hit.V * cube.Positions[t.z];
  EXPECT_NEAR(p.x, 0.0f, 1e-4f);
  EXPECT_NEAR(p.y, 0.0f, 1e-4f);
  EXPECT_NEAR(p.z, 0.5f, 1e-4f);
  // Moved (scaled by 2 and shifted): only the instance transform changes.
  scene.SetObjectTransform(
    glm::scale(glm::translate(glm::mat4(1.0f), glm::vec3(0, 0, 1)), glm::vec3(2.0f)));
  EXPECT_NEAR(scene.Intersect(ray).T, 8.0f, 1e-4f); // top face at 1 + 2 x 0.5
  scene.SetObjectTransform(glm::translate(glm::mat4(1.0f), glm::vec3(5, 0, 0)));
  EXPECT_EQ(scene.Intersect(ray).Triangle, 0u); // moved aside: the floor again
  // Packets agree with single rays, object hits included.
  SceneRay rays[16];
  SceneHit hits[16];
  for (int i = 0; i < 16; ++i)
  {
    rays[i].Origin = glm::vec3(3.1f + 0.25f * i, 0.1f, 10.0f); // no ray on an edge
    rays[i].Direction = glm::vec3(0.0f, 0.0f, -1.0f);
  }
  scene.Intersect16(rays, hits, 16);
  int objectHits = 0;
  for (int i = 0; i < 16; ++i)
  {
    const SceneHit single = scene.Intersect(rays[i]);
    EXPECT_EQ(single.ObjectTriangle, hits[i].ObjectTriangle) << i;
    EXPECT_EQ(single.Triangle, hits[i].Triangle) << i;
    if (single.Hit())
    {
      EXPECT_NEAR(single.T, hits[i].T, 1e-4f) << i;
    }
    objectHits += hits[i].ObjectTriangle != SceneHit::None ? 1 : 0;
  }
  EXPECT_GT(objectHits, 0);
  EXPECT_LT(objectHits, 16);
  scene.ClearObject();
  EXPECT_FALSE(scene.HasObject());
  EXPECT_EQ(scene.Intersect(ray).Triangle, 0u);
}

// Moving the object commits only the instance: with a large static scene a move must cost a
// small fraction of building that scene (were the static BVH rebuilt, the two would be alike).
TEST(WalkthroughObject, MovingTheInstanceDoesNotRebuildTheStaticScene)
{
  TriangleScene grid;
  grid.Materials.push_back(SceneMaterial{});
  const int n = 400; // 2 x 400 x 400 = 320,000 static triangles
  for (int y = 0; y <= n; ++y)
  {
    for (int x = 0; x <= n; ++x)
    {
      grid.Positions.emplace_back(x / float(n), y / float(n), 0.01f * std::sin(0.3f * (x + y)));
    }
  }
  for (int y = 0; y < n; ++y)
  {
    for (int x = 0; x < n; ++x)
    {
      const auto v = static_cast<unsigned>(y * (n + 1) + x);
      grid.Triangles.emplace_back(v, v + 1, v + n + 2);
      grid.Triangles.emplace_back(v, v + n + 2, v + n + 1);
      grid.MaterialIds.push_back(0);
      grid.MaterialIds.push_back(0);
    }
  }
  using Clock = std::chrono::steady_clock;
  Clock::time_point start = Clock::now();
  EmbreeScene scene(grid);
  const double build = std::chrono::duration<double>(Clock::now() - start).count();
  const vlf::ObjectMesh sphere = vlf::MakeSphere(0.05f, 16, 32);
  scene.SetObject(sphere.Positions, sphere.Triangles);
  const int moves = 20;
  start = Clock::now();
  for (int m = 0; m < moves; ++m)
  {
    scene.SetObjectTransform(
      glm::translate(glm::mat4(1.0f), glm::vec3(0.02f * m + 0.3f, 0.5f, 0.1f)));
  }
  const double move = std::chrono::duration<double>(Clock::now() - start).count() / moves;
  SceneRay ray;
  ray.Origin = glm::vec3(0.02f * (moves - 1) + 0.3f, 0.5f, 1.0f);
  ray.Direction = glm::vec3(0.0f, 0.0f, -1.0f);
  EXPECT_NE(scene.Intersect(ray).ObjectTriangle, SceneHit::None); // it did move
  std::cout << "static scene of " << grid.TriangleCount() << " triangles built in "
            << 1000.0 * build << " ms; moving the instanced object: " << 1000.0 * move
            << " ms per move\n";
  EXPECT_LT(move, 0.25 * build);
}

// A sphere above the tall block, seen directly and in the mirror wall from the Cornell camera.
vlf::ObjectMesh TestSphere()
{
  return vlf::MakeSphere(0.5f, 16, 32);
}
glm::mat4 TestPlacement(const vlf::LightField& field, const glm::vec3& world)
{
  return vlf::WorldToUnitSphere(field) *
    glm::scale(glm::translate(glm::mat4(1.0f), world), glm::vec3(110.0f));
}

struct MaskScore
{
  std::size_t Object = 0, ObjectDark = 0;        // object pixels, those without a screen value
  std::size_t Reflection = 0, ReflectionRed = 0; // object-in-mirror pixels, those showing it
  std::size_t Mirror = 0, MirrorRed = 0;         // other mirror pixels, those showing it
};

// The object's radiance is a pure red no field surface has: where the screen image is that red,
// the object was reflected there.
constexpr float ObjectRed = 40.0f;
bool IsObjectRed(const float* rgba)
{
  return rgba[3] > 0.0f && rgba[0] > 0.5f * ObjectRed && rgba[1] < 1e-3f && rgba[2] < 1e-3f;
}

MaskScore Score(const std::vector<std::uint8_t>& interior, const std::vector<float>& screen)
{
  MaskScore s;
  for (std::size_t i = 0; i < interior.size(); ++i)
  {
    const float* rgba = screen.data() + 4 * i;
    switch (interior[i])
    {
      case Object:
        ++s.Object;
        s.ObjectDark += rgba[3] == 0.0f ? 1 : 0;
        break;
      case ObjectInMirror:
        ++s.Reflection;
        s.ReflectionRed += IsObjectRed(rgba) ? 1 : 0;
        break;
      case Mirror:
        ++s.Mirror;
        s.MirrorRed += IsObjectRed(rgba) ? 1 : 0;
        break;
      default:
        break;
    }
  }
  return s;
}

TEST(WalkthroughObject, TracerMasksAgainstRayCastInEveryQuality)
{
  const vlf::LightField& field = MirrorCornellField(513);
  const int size = 96;
  const CornellCamera camera;
  vlf::ViewFrame view;
  ASSERT_TRUE(vlf::ViewFrame::Make(vlf::WorldToUnitSphere(field) * glm::vec4(camera.Position, 1),
    vlf::WorldToUnitSphere(field) * glm::vec4(camera.FocalPoint, 1), camera.ViewUp,
    camera.ViewAngleDegrees, size, size, view));
  const vlf::ObjectMesh sphere = TestSphere();
  // Where the mirror is without the object: the pixels the object must hide in mirror modes.
  const std::vector<vlf::PixelClass> classes = vlf::WalkthroughTracer(field).ClassifyView(view);
  const vlf::PixelRect all{ 0, 0, size, size };
  struct Case
  {
    const char* Name;
    bool Tiles, AllSurfaces;
    vlf::SpecularQuality Quality;
  };
  const Case cases[] = { { "raytrace", true, true, vlf::SpecularQuality::Raytrace },
    { "moving", true, false, vlf::SpecularQuality::Moving },
    { "traced rows (at rest)", false, false, vlf::SpecularQuality::Traced },
    { "traced packets (coherent)", true, false, vlf::SpecularQuality::Traced } };
  // Above the tall block, reflected in the mirror wall; and in front of the mirror wall.
  const glm::vec3 places[] = { { 470.0f, 400.0f, 380.0f }, { 480.0f, 200.0f, 100.0f } };
  for (int place = 0; place < 2; ++place)
  {
    const glm::mat4 placement = TestPlacement(field, places[place]);
    const std::vector<std::uint8_t> interior =
      Interior(ReferenceMasks(field, vlf::TransformMesh(sphere, placement), view), size, size);
    std::size_t overMirror = 0;
    for (std::size_t i = 0; i < interior.size(); ++i)
    {
      overMirror += interior[i] == Object && classes[i] == vlf::PixelClass::Mirror ? 1 : 0;
    }
    vlf::WalkthroughTracer tracer(field);
    tracer.SetObject(sphere);
    tracer.SetObjectPlacement(placement);
    tracer.SetObjectRadiance(
      std::vector<glm::vec3>(sphere.Positions.size(), glm::vec3(ObjectRed, 0.0f, 0.0f)));
    for (const bool withObject : { true, false })
    {
      if (!withObject)
      {
        tracer.ClearObject(); // the negative test: the same masks must now fail
      }
      for (const Case& c : cases)
      {
        std::vector<float> screen(all.Pixels() * 4, -1.0f);
        if (c.Tiles)
        {
          tracer.ShadeTiles(view, all, c.AllSurfaces, c.Quality, vlf::TraceOptions{}, 0,
            vlf::WalkthroughTracer::TileCount(all), screen.data());
        }
        else
        {
          tracer.ShadeRows(
            view, all, c.AllSurfaces, c.Quality, vlf::TraceOptions{}, 0, size, screen.data());
        }
        const MaskScore s = Score(interior, screen);
        std::size_t overMirrorValued = 0;
        for (std::size_t i = 0; i < interior.size(); ++i)
        {
          overMirrorValued += interior[i] == Object && classes[i] == vlf::PixelClass::Mirror &&
              screen[4 * i + 3] > 0.0f
            ? 1
            : 0;
        }
        std::cout << "place " << place << (withObject ? " object    " : " no object ") << c.Name
                  << ": occluded " << s.ObjectDark << "/" << s.Object << " (over the mirror "
                  << overMirror - overMirrorValued << "/" << overMirror << "), reflected "
                  << s.ReflectionRed << "/" << s.Reflection << ", spurious " << s.MirrorRed << "/"
                  << s.Mirror << "\n";
        ASSERT_GT(s.Object, 50u);
        ASSERT_GT(s.Mirror, 200u);
        if (place == 0)
        {
          ASSERT_GT(s.Reflection, 40u);
        }
        else
        {
          ASSERT_GT(overMirror, 50u);
        }
        if (withObject)
        {
          EXPECT_EQ(s.ObjectDark, s.Object) << c.Name;
          EXPECT_EQ(s.ReflectionRed, s.Reflection) << c.Name;
          EXPECT_EQ(s.MirrorRed, 0u) << c.Name;
        }
        else if (place == 0)
        {
          EXPECT_LT(s.ReflectionRed, s.Reflection / 10) << c.Name; // no object in the mirror
        }
        else
        {
          // The mirror behind the object gets a value (would be overlaid on it).
          EXPECT_GT(overMirrorValued, overMirror * 9 / 10) << c.Name;
        }
      }
    }
  }
}

TEST(WalkthroughObject, ReflectionRadianceInterpolatesTheObjectsPoints)
{
  const vlf::LightField& field = MirrorCornellField(513);
  vlf::WalkthroughTracer tracer(field);
  const vlf::ObjectMesh sphere = TestSphere();
  tracer.SetObject(sphere);
  const glm::mat4 placement = TestPlacement(field, glm::vec3(470.0f, 400.0f, 380.0f));
  tracer.SetObjectPlacement(placement);
  // Radiance = the unit-sphere height of each point: the interpolated value must match the
  // height of the hit point (linear along every triangle).
  const vlf::ObjectMesh unit = vlf::TransformMesh(sphere, placement);
  std::vector<glm::vec3> radiance;
  for (const glm::vec3& p : unit.Positions)
  {
    radiance.emplace_back(p.y + 2.0f);
  }
  tracer.SetObjectRadiance(radiance);
  glm::vec3 lower, upper;
  unit.Bounds(lower, upper);
  const glm::vec3 centre = 0.5f * (lower + upper);
  int checked = 0;
  for (int i = 0; i < 50; ++i)
  {
    SceneRay ray;
    ray.Origin = centre + glm::vec3(0.01f * (i % 7 - 3), 0.01f * (i / 7 - 3), -1.0f);
    ray.Direction = glm::vec3(0.0f, 0.0f, 1.0f);
    const SceneHit hit = tracer.Embree().Intersect(ray);
    if (hit.ObjectTriangle == SceneHit::None)
    {
      continue;
    }
    const glm::vec3 p = ray.Origin + hit.T * ray.Direction;
    EXPECT_NEAR(tracer.ObjectRadiance(hit).x, p.y + 2.0f, 1e-4f);
    EXPECT_NEAR(tracer.RaytraceRadiance(ray).x, p.y + 2.0f, 1e-4f);
    ++checked;
  }
  EXPECT_GT(checked, 20);
  // Packets and single rays trace the same reflections of the object.
  const CornellCamera camera;
  vlf::ViewFrame view;
  ASSERT_TRUE(vlf::ViewFrame::Make(vlf::WorldToUnitSphere(field) * glm::vec4(camera.Position, 1),
    vlf::WorldToUnitSphere(field) * glm::vec4(camera.FocalPoint, 1), camera.ViewUp,
    camera.ViewAngleDegrees, 64, 64, view));
  for (int y = 0; y < 64; y += 4)
  {
    SceneRay rays[16];
    glm::vec3 packet[16];
    for (int x = 0; x < 16; ++x)
    {
      rays[x] = view.Ray(4.0f * x + 0.5f, y + 0.5f);
    }
    tracer.TracedRadiance16(rays, 16, vlf::TraceOptions{}, packet);
    for (int x = 0; x < 16; ++x)
    {
      const glm::vec3 single = tracer.TracedRadiance(rays[x], vlf::TraceOptions{});
      EXPECT_NEAR(glm::length(single - packet[x]), 0.0f, 1e-3f * (1.0f + glm::length(single)));
    }
  }
}

TEST(WalkthroughObject, BadObjectsAreRefused)
{
  const vlf::LightField& field = MirrorCornellField(513);
  vlf::WalkthroughTracer tracer(field);
  vlf::ObjectMesh flat;
  flat.Positions = { { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } };
  flat.Triangles = { { 0, 1, 2 } };
  EXPECT_THROW(tracer.SetObject(flat), std::invalid_argument);
  EXPECT_THROW(tracer.SetObject(vlf::ObjectMesh{}), std::invalid_argument);
  EXPECT_FALSE(tracer.HasObject());
  // A radiance of the wrong size is black, not a read past the end.
  tracer.SetObject(TestSphere());
  tracer.SetObjectRadiance({ glm::vec3(1.0f) });
  SceneHit hit;
  hit.ObjectTriangle = 0;
  EXPECT_EQ(tracer.ObjectRadiance(hit), glm::vec3(0.0f));
}

} // namespace
} // namespace mesolight
