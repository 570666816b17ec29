// SPDX-License-Identifier: BSD-3-Clause
// Tests of the shared triangle scene and its Embree queries: the Cornell box against its
// published data, scene checks on bad input, and Embree hits against analytic ray/plane
// intersections (single rays and 16-ray packets agree).
#include "EmbreeScene.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <random>
#include <string>

namespace
{
using mesolight::EmbreeScene;
using mesolight::SceneRay;
using mesolight::TriangleScene;

TEST(CornellBox, MatchesPublishedDimensions)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  glm::vec3 lower, upper;
  ASSERT_TRUE(mesolight::SceneBounds(box, lower, upper));
  EXPECT_NEAR(lower.x, 0.0f, 1e-4f);
  EXPECT_NEAR(upper.x, 556.0f, 1e-3f);
  EXPECT_NEAR(upper.y, 548.8f, 1e-3f);
  EXPECT_NEAR(upper.z, 559.2f, 1e-3f);
  // 5 walls + light (2 triangles each) + 2 blocks of 5 quads.
  EXPECT_EQ(box.TriangleCount(), 6u * 2u + 2u * 5u * 2u);
  const auto check = mesolight::CheckScene(box, true);
  EXPECT_TRUE(check.Ok());
  EXPECT_TRUE(check.Warnings.empty());
  // The light: 130 x 105 mm, facing down.
  float lightArea = 0.0f;
  for (std::size_t t = 0; t < box.TriangleCount(); ++t)
  {
    if (box.MaterialOf(t).Name == "light")
    {
      lightArea += box.Area(t);
      EXPECT_LT(box.FaceNormal(t).y, 0.0f);
    }
  }
  EXPECT_NEAR(lightArea, 130.0f * 105.0f, 0.5f);
}

TEST(CornellBox, FacesPointIntoTheRoomAndOutOfTheBlocks)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  const EmbreeScene embree(box);
  // From a point in the open air of the room, every hit face is seen from its front.
  std::mt19937 random(7);
  std::uniform_real_distribution<float> unit(-1.0f, 1.0f);
  const glm::vec3 eye(150.0f, 450.0f, 450.0f); // above the short block, below the ceiling
  int hits = 0;
  for (int i = 0; i < 2000; ++i)
  {
    glm::vec3 d(unit(random), unit(random), unit(random));
    if (glm::length(d) < 1e-3f)
    {
      continue;
    }
    const auto hit = embree.Intersect(SceneRay{ eye, glm::normalize(d) });
    if (hit.Hit())
    {
      ++hits;
      EXPECT_LT(glm::dot(box.FaceNormal(hit.Triangle), d), 0.0f) << "triangle " << hit.Triangle;
    }
  }
  // The box is open only at z = 0: most directions hit something.
  EXPECT_GT(hits, 1500);
}

TEST(TriangleScene, ChecksReportBadInput)
{
  TriangleScene empty;
  EXPECT_FALSE(mesolight::CheckScene(empty, false).Ok());

  TriangleScene scene;
  mesolight::SceneMaterial grey;
  const auto id = scene.AddMaterial(grey);
  scene.AddPolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 } }, id);
  scene.AddPolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } }, id); // collinear: degenerate
  auto check = mesolight::CheckScene(scene, false);
  EXPECT_TRUE(check.Ok());
  EXPECT_EQ(check.DegenerateTriangles, 1u);
  EXPECT_FALSE(check.Warnings.empty());
  // No emitter is an error only when one is required.
  EXPECT_FALSE(mesolight::CheckScene(scene, true).Ok());
  EXPECT_EQ(mesolight::RemoveDegenerateTriangles(scene), 1u);
  EXPECT_EQ(scene.TriangleCount(), 1u);

  scene.Positions[0].x = std::nanf("");
  EXPECT_FALSE(mesolight::CheckScene(scene, false).Ok());
}

// A few small triangles far from the rest make the light field, scaled to the whole bounding
// box, coarser and darker for everything else (3000-10000 mm beside the Cornell box: 730 texels
// became 19 and the image half as bright, with exit 0): the scene check warns, and ordinary
// scenes (the box; one large quad, whose triangles' centroids lie well inside it) do not.
TEST(TriangleScene, FarTrianglesAreWarnedAbout)
{
  const auto warned = [](const mesolight::SceneCheck& check)
  {
    for (const std::string& w : check.Warnings)
    {
      if (w.find("bounding box is") != std::string::npos)
      {
        return true;
      }
    }
    return false;
  };
  TriangleScene box = mesolight::MakeCornellBox();
  EXPECT_LT(mesolight::FarGeometryRatio(box), 1.1f);
  EXPECT_FALSE(warned(mesolight::CheckScene(box, true)));
  TriangleScene quad;
  const auto grey = quad.AddMaterial(mesolight::SceneMaterial{});
  quad.AddPolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, grey);
  EXPECT_NEAR(mesolight::FarGeometryRatio(quad), 1.0f, 1e-6f);
  for (const float x : { 3000.0f, 10000.0f })
  {
    TriangleScene far = box;
    far.AddPolygon({ { x, 0, 0 }, { x + 50, 0, 0 }, { x, 50, 0 } }, 0);
    const float ratio = mesolight::FarGeometryRatio(far);
    std::cout << "[far] a triangle at x = " << x << " mm: ratio " << ratio << "\n";
    EXPECT_GT(ratio, mesolight::FarGeometryWarningRatio) << x;
    const mesolight::SceneCheck check = mesolight::CheckScene(far, true);
    EXPECT_TRUE(check.Ok());
    EXPECT_TRUE(warned(check)) << x;
  }
}

// Degenerate is judged per triangle at float precision. The limit used to be relative to the
// scene's bounding box (1e-12 x diagonal^2): a ground plane +-1e6 m around a room in metres made
// every room triangle "degenerate" and the propagation said "no emitter"; at +-1e30 every triangle
// was. A tiny but well-shaped triangle in a large scene is kept; a sliver thinner than float
// resolution at its coordinates is not.
TEST(TriangleScene, DegenerateIsJudgedPerTriangle)
{
  TriangleScene room = mesolight::MakeCornellBox();
  for (glm::vec3& p : room.Positions)
  {
    p *= 0.001f; // metres
  }
  const auto ground = room.AddMaterial(mesolight::SceneMaterial{});
  for (const float half : { 1e6f, 1e30f })
  {
    TriangleScene scene = room;
    scene.AddPolygon({ { -half, -0.01f, -half }, { half, -0.01f, -half }, { half, -0.01f, half },
                       { -half, -0.01f, half } },
      ground);
    const mesolight::SceneCheck check = mesolight::CheckScene(scene, true);
    EXPECT_TRUE(check.Ok()) << half << ": " << (check.Errors.empty() ? "" : check.Errors[0]);
    EXPECT_EQ(check.DegenerateTriangles, 0u) << half;
  }

  TriangleScene scene;
  const auto grey = scene.AddMaterial(mesolight::SceneMaterial{});
  scene.AddPolygon({ { -1000, 0, 0 }, { 1000, 0, 0 }, { 0, 1000, 0 } }, grey);
  scene.AddPolygon({ { 0, 0, 1 }, { 1e-4f, 0, 1 }, { 0, 1e-4f, 1 } }, grey);      // tiny, kept
  scene.AddPolygon({ { 500, 0, 0 }, { 501, 0, 0 }, { 500.5f, 1e-5f, 0 } }, grey); // sliver
  const mesolight::SceneCheck check = mesolight::CheckScene(scene, false);
  EXPECT_TRUE(check.Ok());
  EXPECT_EQ(check.DegenerateTriangles, 1u);
  EXPECT_EQ(mesolight::RemoveDegenerateTriangles(scene), 1u);
  EXPECT_EQ(scene.TriangleCount(), 2u);
}

TEST(TriangleScene, NormalizesIntoTheUnitSphere)
{
  TriangleScene box = mesolight::MakeCornellBox();
  mesolight::NormalizeToUnitSphere(box);
  glm::vec3 lower, upper;
  ASSERT_TRUE(mesolight::SceneBounds(box, lower, upper));
  EXPECT_NEAR(glm::length(upper - lower), 2.0f, 1e-4f);
  EXPECT_NEAR(glm::length(upper + lower), 0.0f, 1e-4f);
}

TEST(EmbreeScene, HitsMatchAnalyticPlaneAndPacketsMatchSingleRays)
{
  TriangleScene scene;
  const auto id = scene.AddMaterial({});
  // The plane z = 2 over [-1,1]^2.
  scene.AddPolygon({ { -1, -1, 2 }, { 1, -1, 2 }, { 1, 1, 2 }, { -1, 1, 2 } }, id);
  const EmbreeScene embree(scene);
  std::mt19937 random(3);
  std::uniform_real_distribution<float> unit(-1.5f, 1.5f);
  SceneRay rays[16];
  for (int i = 0; i < 16; ++i)
  {
    rays[i].Origin = glm::vec3(unit(random), unit(random), 0.0f);
    rays[i].Direction = glm::vec3(0.1f * unit(random), 0.1f * unit(random), 1.0f);
  }
  mesolight::SceneHit packet[16];
  embree.Intersect16(rays, packet, 16);
  for (int i = 0; i < 16; ++i)
  {
    const auto single = embree.Intersect(rays[i]);
    const glm::vec3 onPlane = rays[i].Origin + 2.0f * rays[i].Direction;
    const bool inside = std::abs(onPlane.x) < 1.0f && std::abs(onPlane.y) < 1.0f;
    if (std::abs(std::abs(onPlane.x) - 1.0f) < 1e-4f ||
      std::abs(std::abs(onPlane.y) - 1.0f) < 1e-4f)
    {
      continue; // on the edge: either answer is right
    }
    EXPECT_EQ(single.Hit(), inside);
    EXPECT_EQ(packet[i].Hit(), inside);
    EXPECT_EQ(embree.Occluded(rays[i]), inside);
    if (inside)
    {
      EXPECT_NEAR(single.T, 2.0f, 1e-5f);
      EXPECT_NEAR(packet[i].T, single.T, 1e-6f);
      EXPECT_EQ(packet[i].Triangle, single.Triangle);
    }
  }
  // TFar before the plane: no hit.
  SceneRay shortRay{ glm::vec3(0.0f), glm::vec3(0, 0, 1), 0.0f, 1.9f };
  EXPECT_FALSE(embree.Intersect(shortRay).Hit());
  EXPECT_FALSE(embree.Occluded(shortRay));
}

} // namespace
