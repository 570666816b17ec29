// SPDX-License-Identifier: BSD-3-Clause
// The movable object beyond the first mirror bounce, and its shadows seen in mirrors (Wither
// 2005 ch. 4), in the tracer's four qualities. References are independent ray casts of one merged
// triangle scene (the field's triangles and the placed object, no instancing, no
// WalkthroughTracer):
// - two facing mirrors (the Cornell box's red and green walls): the pixels whose mirror chain
//   meets the object at the second (or later) bounce must show the object in the field-lookup
//   qualities too (raytrace, progressive while moving), not only in the traced ones;
// - a mirror that sees the floor the object shadows: the mirror's pixels whose reflection lands
//   on the shadow must be darkened as the directly seen floor is there (ObjectShadows::Shade at
//   the landing point, the darkening the raytrace mode applies on the CPU and the GPU's twin
//   shader applies to diffuse fragments).
// Negative tests: the object looked for at the first bounce only, the shadows switched off.
#include "ObjectShadows.h"
#include "ObjectTestReference.h"
#include "WalkthroughTestFields.h"

#include "EmbreeScene.h"
#include "Lookup.h"
#include "ObjectMesh.h"
#include "TriangleScene.h"
#include "WalkthroughTracer.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <vector>

using namespace mesolight;

namespace
{
// The Cornell box with both side walls mirrors (Ks 0.9, Kd 0), facing each other.
TriangleScene MakeTwoMirrorCornellBox()
{
  TriangleScene scene = MakeCornellBoxWithMirror();
  std::uint32_t mirror = 0;
  for (std::uint32_t m = 0; m < scene.Materials.size(); ++m)
  {
    mirror = scene.Materials[m].Name == "mirror" ? m : mirror;
  }
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    if (scene.Materials[scene.MaterialIds[t]].Name == "green")
    {
      scene.MaterialIds[t] = mirror;
    }
  }
  return scene;
}

const vlf::LightField& TwoMirrorField()
{
  static std::unique_ptr<vlf::LightField> field;
  if (!field)
  {
    vlf::LightFieldSettings settings;
    settings.Directions = 513;
    settings.RaysPerSide = 16;
    settings.TilesPerSide = 4;
    field = vlf::LightField::Build(MakeTwoMirrorCornellBox(), settings);
    vlf::Propagate(*field, 3);
  }
  return *field;
}

vlf::ViewFrame View(const vlf::LightField& field, glm::vec3 eye, glm::vec3 focal, int size)
{
  const glm::mat4 unit = vlf::WorldToUnitSphere(field);
  vlf::ViewFrame view;
  EXPECT_TRUE(vlf::ViewFrame::Make(glm::vec3(unit * glm::vec4(eye, 1.0f)),
    glm::vec3(unit * glm::vec4(focal, 1.0f)), glm::vec3(0.0f, 1.0f, 0.0f), 50.0f, size, size,
    view));
  return view;
}

// The reference: per pixel, the merged scene's ray followed through mirrors (up to 8 bounces).
struct Landing
{
  int Bounces = -1;    // mirror reflections before the end; -1: the pixel sees no mirror
  bool Object = false; // the chain ends on the object
  std::uint32_t Surface = vlf::NoSurface; // else the field surface it ends on (front side)
  glm::vec3 Point{ 0.0f };
};

std::vector<Landing> CastReference(
  const vlf::LightField& field, const vlf::ObjectMesh& unitObject, const vlf::ViewFrame& view)
{
  const std::size_t staticTriangles = field.Scene().TriangleCount();
  const EmbreeScene embree(objecttest::MergedScene(field, unitObject));
  std::vector<Landing> out(static_cast<std::size_t>(view.Width) * view.Height);
  for (int y = 0; y < view.Height; ++y)
  {
    for (int x = 0; x < view.Width; ++x)
    {
      SceneRay ray = view.Ray(x + 0.5f, y + 0.5f);
      Landing& l = out[static_cast<std::size_t>(y) * view.Width + x];
      for (int bounce = 0; bounce <= 8; ++bounce)
      {
        const SceneHit hit = embree.Intersect(ray);
        if (hit.Triangle == SceneHit::None)
        {
          break;
        }
        if (hit.Triangle >= staticTriangles)
        {
          l.Object = bounce > 0;
          break;
        }
        const std::uint32_t s = field.SurfaceOfTriangle(hit.Triangle);
        const glm::vec3 d = glm::normalize(ray.Direction);
        if (s == vlf::NoSurface || !(glm::dot(field.Surfaces()[s].Normal, d) < 0.0f))
        {
          break;
        }
        const glm::vec3 p = ray.Origin + hit.T * ray.Direction;
        if (glm::length(field.MaterialOf(s).Specular) <= 0.0f)
        {
          if (bounce > 0)
          {
            l.Surface = s;
            l.Point = p;
          }
          break;
        }
        l.Bounces = bounce + 1;
        const glm::vec3 n = field.Surfaces()[s].Normal;
        ray.Origin = p + 1e-4f * n;
        ray.Direction = d - 2.0f * glm::dot(d, n) * n;
      }
      if (!l.Object && l.Surface == vlf::NoSurface)
      {
        l.Bounces = l.Bounces > 0 && !l.Object ? -2 : l.Bounces; // a mirror chain to nowhere
      }
    }
  }
  return out;
}

// Pixels whose 8 neighbours end the same way (rasterised edges may differ by a pixel).
bool Interior(const std::vector<Landing>& l, int w, int h, int x, int y)
{
  if (x < 1 || y < 1 || x + 1 >= w || y + 1 >= h)
  {
    return false;
  }
  const Landing& c = l[static_cast<std::size_t>(y) * w + x];
  for (int dy = -1; dy <= 1; ++dy)
  {
    for (int dx = -1; dx <= 1; ++dx)
    {
      const Landing& o = l[static_cast<std::size_t>(y + dy) * w + x + dx];
      if (o.Object != c.Object || o.Bounces != c.Bounces || o.Surface != c.Surface)
      {
        return false;
      }
    }
  }
  return true;
}

struct Quality
{
  const char* Name;
  bool Tiles;
  vlf::SpecularQuality Value;
};
const Quality Qualities[] = { { "raytrace", true, vlf::SpecularQuality::Raytrace },
  { "moving", true, vlf::SpecularQuality::Moving },
  { "traced rows (at rest)", false, vlf::SpecularQuality::Traced },
  { "traced packets (coherent)", true, vlf::SpecularQuality::Traced } };

std::vector<float> Shade(
  const vlf::WalkthroughTracer& tracer, const vlf::ViewFrame& view, const Quality& q)
{
  const vlf::PixelRect all{ 0, 0, view.Width, view.Height };
  std::vector<float> screen(all.Pixels() * 4, 0.0f);
  if (q.Tiles)
  {
    tracer.ShadeTiles(view, all, false, q.Value, vlf::TraceOptions{}, 0,
      vlf::WalkthroughTracer::TileCount(all), screen.data());
  }
  else
  {
    tracer.ShadeRows(view, all, false, q.Value, vlf::TraceOptions{}, 0, view.Height, screen.data());
  }
  return screen;
}

constexpr float ObjectRed = 40.0f;
bool IsObjectRed(const float* rgba)
{
  return rgba[3] > 0.0f && rgba[0] > 0.3f * ObjectRed && rgba[1] < 1e-3f && rgba[2] < 1e-3f;
}

float Sum(const glm::vec3& v)
{
  return v.x + v.y + v.z;
}
} // namespace

TEST(ObjectMirrors, ObjectInTheSecondReflectionInEveryQuality)
{
  const vlf::LightField& field = TwoMirrorField();
  const int size = 96;
  // Inside the box near the green wall, looking at the red mirror across the room: a sphere
  // between the two, above the tall block, is seen in the red mirror and, smaller, in the red
  // mirror's image of the green mirror.
  const vlf::ViewFrame view =
    View(field, glm::vec3(120.0f, 330.0f, 60.0f), glm::vec3(550.0f, 400.0f, 330.0f), size);
  const vlf::ObjectMesh sphere = vlf::MakeSphere(0.5f, 16, 32);
  const glm::mat4 placement = vlf::WorldToUnitSphere(field) *
    glm::scale(
      glm::translate(glm::mat4(1.0f), glm::vec3(300.0f, 430.0f, 330.0f)), glm::vec3(90.0f));
  const std::vector<Landing> reference =
    CastReference(field, vlf::TransformMesh(sphere, placement), view);
  vlf::WalkthroughTracer tracer(field);
  tracer.SetObject(sphere);
  tracer.SetObjectPlacement(placement);
  tracer.SetObjectRadiance(
    std::vector<glm::vec3>(sphere.Positions.size(), glm::vec3(ObjectRed, 0, 0)));
  for (const bool firstBounceOnly : { false, true })
  {
    tracer.SetFirstBounceObjectOnlyForTesting(firstBounceOnly);
    for (const Quality& q : Qualities)
    {
      const std::vector<float> screen = Shade(tracer, view, q);
      std::size_t first = 0, firstRed = 0, deeper = 0, deeperRed = 0, other = 0, otherRed = 0;
      for (int y = 0; y < size; ++y)
      {
        for (int x = 0; x < size; ++x)
        {
          const std::size_t i = static_cast<std::size_t>(y) * size + x;
          const Landing& l = reference[i];
          if (l.Bounces < 1 || !Interior(reference, size, size, x, y))
          {
            continue;
          }
          const bool red = IsObjectRed(&screen[4 * i]);
          if (l.Object && l.Bounces == 1)
          {
            ++first;
            firstRed += red;
          }
          else if (l.Object)
          {
            ++deeper;
            deeperRed += red;
          }
          else
          {
            ++other;
            otherRed += red;
          }
        }
      }
      std::printf("[ figures  ] %s%s: object at the first bounce %zu/%zu, deeper %zu/%zu, "
                  "spurious %zu/%zu\n",
        q.Name, firstBounceOnly ? " (first bounce only)" : "", firstRed, first, deeperRed, deeper,
        otherRed, other);
      ASSERT_GT(first, 30u);
      ASSERT_GT(deeper, 15u);
      ASSERT_GT(other, 500u);
      EXPECT_EQ(firstRed, first) << q.Name;
      EXPECT_EQ(otherRed, 0u) << q.Name;
      const bool traced = q.Value == vlf::SpecularQuality::Traced;
      if (!firstBounceOnly || traced)
      {
        EXPECT_EQ(deeperRed, deeper) << q.Name;
      }
      else
      {
        EXPECT_LT(deeperRed, deeper / 10) << q.Name; // the negative test: only the first bounce
      }
    }
  }
}

TEST(ObjectMirrors, ShadowOnTheFloorSeenInTheMirror)
{
  const vlf::LightField& field = walkthroughtest::MirrorCornellField(513);
  const int size = 96;
  // A cube above the floor in the front-right part of the box: its shadow falls on the floor
  // around (438, 0, 96) mm, which the camera sees in the mirror wall (x = 550).
  const vlf::ObjectMesh cube = vlf::MakeCube(1.0f);
  const glm::mat4 placement = vlf::WorldToUnitSphere(field) *
    glm::scale(
      glm::translate(glm::mat4(1.0f), glm::vec3(400.0f, 130.0f, 140.0f)), glm::vec3(90.0f));
  const vlf::ObjectMesh unitCube = vlf::TransformMesh(cube, placement);
  const vlf::ViewFrame view =
    View(field, glm::vec3(150.0f, 280.0f, 30.0f), glm::vec3(662.0f, 0.0f, 96.0f), size);
  const std::vector<Landing> reference = CastReference(field, unitCube, view);
  vlf::ObjectShadows shadows;
  ASSERT_EQ(shadows.Build(field, unitCube, vlf::ShadowSettings{}), "");
  vlf::WalkthroughTracer tracer(field);
  tracer.SetObject(cube);
  tracer.SetObjectPlacement(placement);
  tracer.SetObjectRadiance(std::vector<glm::vec3>(cube.Positions.size(), glm::vec3(0.5f)));
  const vlf::Lookup lookup(field);
  for (const Quality& q : Qualities)
  {
    tracer.SetShadows(nullptr);
    const std::vector<float> unshadowed = Shade(tracer, view, q);
    tracer.SetShadows(&shadows);
    const std::vector<float> shadowed = Shade(tracer, view, q);
    // Over the mirror pixels whose reflection lands on the floor in the shadow (the directly
    // seen floor loses at least 30% there): the mirror's darkening against the floor's.
    std::size_t count = 0;
    double error = 0.0, errorOff = 0.0, darkening = 0.0;
    for (int y = 0; y < size; ++y)
    {
      for (int x = 0; x < size; ++x)
      {
        const std::size_t i = static_cast<std::size_t>(y) * size + x;
        const Landing& l = reference[i];
        if (l.Bounces != 1 || l.Object || l.Surface == vlf::NoSurface ||
          !Interior(reference, size, size, x, y))
        {
          continue;
        }
        const glm::vec3 n = field.Surfaces()[l.Surface].Normal;
        const glm::vec3 floor = lookup.DiffuseRadiance(l.Surface, l.Point);
        const glm::vec3 direct =
          shadows.Shade(floor, l.Point, n, field.MaterialOf(l.Surface).Diffuse);
        const float directRatio = Sum(direct) / Sum(floor);
        if (!(directRatio < 0.7f))
        {
          continue;
        }
        const float with = shadowed[4 * i] + shadowed[4 * i + 1] + shadowed[4 * i + 2];
        const float without = unshadowed[4 * i] + unshadowed[4 * i + 1] + unshadowed[4 * i + 2];
        ASSERT_GT(without, 0.0f);
        // The mirror shows Ks x the floor: its ratio with/without is the floor's darkening.
        error += std::abs(with / without - directRatio);
        errorOff += std::abs(1.0f - directRatio);
        darkening += 1.0 - with / without;
        ++count;
      }
    }
    ASSERT_GT(count, 40u) << q.Name;
    std::printf("[ figures  ] %s: %zu mirror pixels see the shadow; mean darkening %.3f, "
                "|mirror - direct| ratio error %.4f (shadows off: %.4f)\n",
      q.Name, count, darkening / count, error / count, errorOff / count);
    // The traced qualities read the floor's texture where the reflection lands; the field-lookup
    // ones keep the field's mirror value and take off Ks x what the shadow takes off the floor
    // there, so their ratio differs by the field's own error at that point.
    const bool traced = q.Value == vlf::SpecularQuality::Traced;
    const double bound = traced ? 0.01 : 0.2;
    EXPECT_LT(error / count, bound) << q.Name;
    EXPECT_GT(errorOff / count, bound) << q.Name; // the negative test: no shadow in the mirror
  }
  // A figure, not a check: the CPU pass's cost of the shadow in the mirror, one thread, 400 x 400
  // of the same view (fastest of 3 runs), each quality with and without the shadows.
  const vlf::ViewFrame large =
    View(field, glm::vec3(150.0f, 280.0f, 30.0f), glm::vec3(662.0f, 0.0f, 96.0f), 400);
  for (const Quality& q : Qualities)
  {
    double seconds[2] = { 1e30, 1e30 };
    for (int run = 0; run < 6; ++run)
    {
      tracer.SetShadows(run % 2 ? &shadows : nullptr);
      const auto start = std::chrono::steady_clock::now();
      Shade(tracer, large, q);
      seconds[run % 2] = std::min(seconds[run % 2],
        std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    }
    std::printf("[ figures  ] %s, 400 x 400, one thread: %.1f ms without the shadows, %.1f ms "
                "with them\n",
      q.Name, 1e3 * seconds[0], 1e3 * seconds[1]);
  }
}
