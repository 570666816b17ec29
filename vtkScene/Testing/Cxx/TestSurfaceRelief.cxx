// SPDX-License-Identifier: BSD-3-Clause
// Tests of DisplaceSurface, the dense displaced mesh of a relief on a planar surface (the path
// tracer's reference): vertices at the depth map's analytic heights, one vertex per texel, the
// plane texture rule, area and closure (every edge shared twice but the undisplaced boundary), and
// the refusals (unknown surface, non-planar surface, bad depth map).
#include "SurfaceRelief.h"
#include "TriangleScene.h"

#include <gtest/gtest.h>

#include <array>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <string>
#include <utility>
#include <vector>

namespace
{
using mesolight::DepthMap;
using mesolight::DisplaceSurface;
using mesolight::SurfaceReliefError;
using mesolight::SurfaceReliefResult;
using mesolight::SurfaceReliefSettings;
using mesolight::TriangleScene;

// A depth map linear in the texel indices, so that bilinear interpolation reproduces it exactly
// between texel centres; beyond the outer centres it is clamped.
constexpr int MapWidth = 12;
constexpr int MapHeight = 8;
double LinearDepth(double a, double b)
{
  return 0.1 + 0.6 * a + 0.25 * b; // a, b in [0, 1]
}
DepthMap LinearMap()
{
  DepthMap map;
  map.Width = MapWidth;
  map.Height = MapHeight;
  for (int j = 0; j < MapHeight; ++j)
  {
    for (int i = 0; i < MapWidth; ++i)
    {
      map.Depth.push_back(
        static_cast<float>(LinearDepth(i / (MapWidth - 1.0), j / (MapHeight - 1.0))));
    }
  }
  return map;
}
// The analytic depth at texture coordinate (u, v) (texel centres at (i + 0.5) / W, clamped).
double AnalyticDepth(double u, double v)
{
  const double a = std::min(std::max(u * MapWidth - 0.5, 0.0), MapWidth - 1.0) / (MapWidth - 1.0);
  const double b =
    std::min(std::max(v * MapHeight - 0.5, 0.0), MapHeight - 1.0) / (MapHeight - 1.0);
  return LinearDepth(a, b);
}

// A 3 x 2 rectangle in z = 0 facing +z, named "panel", beside an unnamed triangle.
TriangleScene Panel()
{
  TriangleScene scene;
  const std::uint32_t white = scene.AddMaterial({});
  scene.AddPolygon(
    { { 0.0f, 0.0f, 0.0f }, { 3.0f, 0.0f, 0.0f }, { 3.0f, 2.0f, 0.0f }, { 0.0f, 2.0f, 0.0f } },
    white, scene.AddSurface("panel"));
  scene.AddPolygon({ { 5.0f, 0.0f, 1.0f }, { 6.0f, 0.0f, 1.0f }, { 6.0f, 1.0f, 1.0f } }, white);
  return scene;
}

using Edge = std::pair<std::uint32_t, std::uint32_t>;
std::map<Edge, int> EdgeUse(const TriangleScene& scene, std::size_t first)
{
  std::map<Edge, int> use;
  for (std::size_t t = first; t < scene.TriangleCount(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const std::uint32_t a = scene.Triangles[t][c], b = scene.Triangles[t][(c + 1) % 3];
      ++use[{ std::min(a, b), std::max(a, b) }];
    }
  }
  return use;
}

std::string ReliefError(const TriangleScene& scene, const std::string& surface, const DepthMap& map)
{
  try
  {
    DisplaceSurface(scene, surface, map, SurfaceReliefSettings());
  }
  catch (const SurfaceReliefError& e)
  {
    return e.what();
  }
  return "";
}

TEST(SurfaceRelief, VerticesAtTheDepthMapsHeights)
{
  const TriangleScene scene = Panel();
  SurfaceReliefSettings settings;
  settings.DepthScale = 0.1f; // depth 1 is 0.1 of the panel's width (3): 0.3 deep
  const SurfaceReliefResult r = DisplaceSurface(scene, "panel", LinearMap(), settings);
  // The plane rule on a surface facing +z: V along +y, U = V x N = +x, over the bounding box.
  EXPECT_NEAR(glm::distance(r.Plane.Origin, glm::vec3(0.0f)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(r.Plane.AxisU, glm::vec3(3.0f, 0.0f, 0.0f)), 0.0f, 1e-5f);
  EXPECT_NEAR(glm::distance(r.Plane.AxisV, glm::vec3(0.0f, 2.0f, 0.0f)), 0.0f, 1e-5f);
  ASSERT_EQ(r.Scene.SurfaceIds.size(), r.Scene.TriangleCount());
  ASSERT_EQ(r.Scene.MaterialIds.size(), r.Scene.TriangleCount());
  // The unnamed triangle is kept, first; every new triangle is the panel's.
  EXPECT_EQ(r.Scene.SurfaceIds[0], TriangleScene::NoSurface);
  EXPECT_EQ(r.Scene.TriangleCount(), 1 + r.SurfaceTriangles + r.SideTriangles);
  EXPECT_EQ(
    mesolight::SurfaceTriangles(r.Scene, "panel").size(), r.SurfaceTriangles + r.SideTriangles);
  // (W + 1) x (H + 1) grid cells (texel centres and borders), those on the diagonal split.
  EXPECT_GE(r.SurfaceTriangles, 2u * (MapWidth + 1) * (MapHeight + 1));
  std::size_t texelCentres = 0, checked = 0;
  for (std::size_t t = 1; t < 1 + r.SurfaceTriangles; ++t)
  {
    // The displaced surface faces the way the panel did.
    EXPECT_GT(r.Scene.FaceNormal(t).z, 0.0f);
    for (int c = 0; c < 3; ++c)
    {
      const glm::vec3 p = r.Scene.Vertex(t, c);
      const double u = p.x / 3.0, v = p.y / 2.0;
      EXPECT_NEAR(p.z, -0.3 * AnalyticDepth(u, v), 1e-5) << "at u " << u << ", v " << v;
      ++checked;
      const double i = u * MapWidth - 0.5, j = v * MapHeight - 0.5;
      if (std::abs(i - std::round(i)) < 1e-4 && std::abs(j - std::round(j)) < 1e-4)
      {
        ++texelCentres;
      }
    }
  }
  EXPECT_GT(checked, 0u);
  // Every texel centre is a vertex (each counted once per corner it is of: at least once).
  EXPECT_GE(texelCentres, static_cast<std::size_t>(MapWidth * MapHeight));
}

TEST(SurfaceRelief, WrongRowOrderOrScaleWouldFail)
{
  // The negative case of the height check: the same map upside down (top row first, as image
  // files store it) moves the vertices by far more than the test's tolerance.
  const TriangleScene scene = Panel();
  DepthMap flipped = LinearMap();
  for (int j = 0; j < MapHeight / 2; ++j)
  {
    for (int i = 0; i < MapWidth; ++i)
    {
      std::swap(flipped.Depth[j * MapWidth + i], flipped.Depth[(MapHeight - 1 - j) * MapWidth + i]);
    }
  }
  SurfaceReliefSettings settings;
  settings.DepthScale = 0.1f;
  const SurfaceReliefResult r = DisplaceSurface(scene, "panel", flipped, settings);
  double largest = 0.0;
  for (std::size_t t = 1; t < 1 + r.SurfaceTriangles; ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const glm::vec3 p = r.Scene.Vertex(t, c);
      largest = std::max(largest, std::abs(p.z + 0.3 * AnalyticDepth(p.x / 3.0, p.y / 2.0)));
    }
  }
  EXPECT_GT(largest, 0.05);
}

// Area and closure on the Cornell box's back wall, a trapezoid (549.6 wide at the floor, 556 at
// the ceiling) of two triangles: the grid is clipped to it.
TEST(SurfaceRelief, CornellBackWallClosedAndAreaKept)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  DepthMap map;
  map.Width = 37;
  map.Height = 23;
  for (int j = 0; j < map.Height; ++j)
  {
    for (int i = 0; i < map.Width; ++i)
    {
      map.Depth.push_back(static_cast<float>(0.5 + 0.45 * std::sin(0.7 * i) * std::cos(0.9 * j)));
    }
  }
  SurfaceReliefSettings settings;
  settings.DepthScale = 0.05f;
  const SurfaceReliefResult r = DisplaceSurface(box, "back", map, settings);
  // The back wall faces the camera (-z); the plane rule gives V = +y and U = -x, so the image is
  // seen unmirrored through the published camera.
  EXPECT_NEAR(r.Plane.Normal.z, -1.0f, 1e-6f);
  EXPECT_NEAR(glm::normalize(r.Plane.AxisU).x, -1.0f, 1e-6f);
  EXPECT_NEAR(glm::normalize(r.Plane.AxisV).y, 1.0f, 1e-6f);
  EXPECT_NEAR(glm::length(r.Plane.AxisU), 556.0f, 1e-3f);
  EXPECT_NEAR(glm::length(r.Plane.AxisV), 548.8f, 1e-3f);

  const std::vector<std::size_t> wall = mesolight::SurfaceTriangles(box, "back");
  double originalArea = 0.0;
  for (std::size_t t : wall)
  {
    originalArea += box.Area(t);
  }
  const std::size_t first = box.TriangleCount() - wall.size();
  ASSERT_EQ(r.Scene.TriangleCount(), first + r.SurfaceTriangles + r.SideTriangles);
  // The displaced surface's area projected on the plane is the wall's, all of it facing front.
  double projected = 0.0;
  for (std::size_t t = first; t < first + r.SurfaceTriangles; ++t)
  {
    const double facing = -0.5 * r.Scene.FaceNormal(t).z;
    EXPECT_GT(facing, 0.0);
    projected += facing;
  }
  EXPECT_NEAR(projected, originalArea, 1e-5 * originalArea);
  // Closure: every edge of the new triangles is shared by two of them, except the wall's own
  // boundary at depth 0 (where the floor, ceiling and side walls meet it), whose length is the
  // trapezoid's perimeter.
  const std::map<Edge, int> use = EdgeUse(r.Scene, first);
  double openLength = 0.0;
  for (const auto& edge : use)
  {
    ASSERT_LE(edge.second, 2);
    if (edge.second == 1)
    {
      const glm::vec3 a = r.Scene.Positions[edge.first.first];
      const glm::vec3 b = r.Scene.Positions[edge.first.second];
      EXPECT_NEAR(a.z, 559.2f, 1e-3f);
      EXPECT_NEAR(b.z, 559.2f, 1e-3f);
      openLength += glm::distance(a, b);
    }
  }
  const double perimeter = 549.6 + 556.0 + 548.8 + std::hypot(556.0 - 549.6, 548.8);
  EXPECT_NEAR(openLength, perimeter, 1e-3 * perimeter);
  // The relief goes into the wall (z > 559.2), never into the room, and by no more than
  // DepthScale times the texture's width.
  for (std::size_t v = box.Positions.size(); v < r.Scene.Positions.size(); ++v)
  {
    EXPECT_GE(r.Scene.Positions[v].z, 559.2f - 1e-3f);
    EXPECT_LE(r.Scene.Positions[v].z, 559.2f + 0.05f * 556.0f + 1e-2f);
  }
  // A scene the path tracer takes.
  const mesolight::SceneCheck check = mesolight::CheckScene(r.Scene, true);
  EXPECT_TRUE(check.Ok());
}

TEST(SurfaceRelief, PlaneRuleOnFloorAndTilt)
{
  // The floor faces +y: V is world +z projected (|N.y| >= 0.9), U = V x N = -x, the whole floor.
  const TriangleScene box = mesolight::MakeCornellBox();
  const mesolight::SurfacePlane floor =
    mesolight::SurfacePlaneOf(box, mesolight::SurfaceTriangles(box, "floor"), "floor");
  EXPECT_NEAR(floor.Normal.y, 1.0f, 1e-6f);
  EXPECT_NEAR(glm::distance(glm::normalize(floor.AxisV), glm::vec3(0.0f, 0.0f, 1.0f)), 0.0f, 1e-6f);
  EXPECT_NEAR(
    glm::distance(glm::normalize(floor.AxisU), glm::vec3(-1.0f, 0.0f, 0.0f)), 0.0f, 1e-6f);
  EXPECT_NEAR(glm::length(floor.AxisU), 552.8f, 1e-3f);
  EXPECT_NEAR(glm::length(floor.AxisV), 559.2f, 1e-3f);
  // Its corners map to the bounding rectangle's corners.
  const glm::vec2 corner = floor.TextureCoordinate(glm::vec3(552.8f, 0.0f, 0.0f));
  EXPECT_NEAR(corner.x, 0.0f, 1e-6f);
  EXPECT_NEAR(corner.y, 0.0f, 1e-6f);
  // A ramp 20 degrees from horizontal (|N.y| = 0.94) is framed like the floor; one 30 degrees
  // from it (|N.y| = 0.87) like a wall, V up the slope.
  for (const double degrees : { 20.0, 30.0 })
  {
    const float c = static_cast<float>(std::cos(degrees * 3.14159265358979 / 180.0));
    const float s = static_cast<float>(std::sin(degrees * 3.14159265358979 / 180.0));
    TriangleScene ramp;
    ramp.AddPolygon(
      { { 0.0f, 0.0f, 0.0f }, { 1.0f, 0.0f, 0.0f }, { 1.0f, s, -c }, { 0.0f, s, -c } },
      ramp.AddMaterial({}));
    const mesolight::SurfacePlane plane = mesolight::SurfacePlaneOf(ramp, { 0, 1 }, "ramp");
    EXPECT_NEAR(plane.Normal.y, c, 1e-5f);
    const glm::vec3 v = glm::normalize(plane.AxisV);
    if (degrees < 25.0)
    {
      EXPECT_GT(v.z, 0.9f) << degrees;
    }
    else
    {
      EXPECT_GT(v.y, 0.4f) << degrees;
      EXPECT_LT(v.z, 0.0f) << degrees;
    }
  }
}

// A closed object (a cube, all six faces outward) has area but no side to take a plane from:
// "not planar", not "has no area" (what ParaView's Relief Surface said of an OBJ bracket), which
// its user knows to be wrong.
TEST(SurfaceRelief, AClosedObjectIsNotPlanarRatherThanWithoutArea)
{
  TriangleScene cube;
  const std::uint32_t material = cube.AddMaterial({});
  const glm::vec3 p[8] = { { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 }, { 0, 0, 1 },
    { 1, 0, 1 }, { 1, 1, 1 }, { 0, 1, 1 } };
  for (const auto& face : std::vector<std::array<int, 4>>{ { 0, 3, 2, 1 }, { 4, 5, 6, 7 },
         { 0, 1, 5, 4 }, { 2, 3, 7, 6 }, { 0, 4, 7, 3 }, { 1, 2, 6, 5 } })
  {
    cube.AddPolygon({ p[face[0]], p[face[1]], p[face[2]], p[face[3]] }, material);
  }
  std::vector<std::size_t> all(cube.TriangleCount());
  for (std::size_t t = 0; t < all.size(); ++t)
  {
    all[t] = t;
  }
  std::string said;
  try
  {
    mesolight::SurfacePlaneOf(cube, all, "the cube");
  }
  catch (const std::exception& e)
  {
    said = e.what();
  }
  EXPECT_NE(said.find("not planar"), std::string::npos) << said;
  EXPECT_EQ(said.find("no area"), std::string::npos) << said;
}

TEST(SurfaceRelief, ConstantDepthSideWallsArea)
{
  // A constant depth c sinks the whole panel by c K width; the side walls are the perimeter times
  // that depth.
  const TriangleScene scene = Panel();
  DepthMap map;
  map.Width = 5;
  map.Height = 4;
  map.Depth.assign(20, 0.5f);
  SurfaceReliefSettings settings;
  settings.DepthScale = 0.2f; // 0.5 * 0.2 * 3 = 0.3 deep
  const SurfaceReliefResult r = DisplaceSurface(scene, "panel", map, settings);
  double surfaceArea = 0.0, sideArea = 0.0;
  for (std::size_t t = 1; t < r.Scene.TriangleCount(); ++t)
  {
    (t < 1 + r.SurfaceTriangles ? surfaceArea : sideArea) += r.Scene.Area(t);
  }
  EXPECT_NEAR(surfaceArea, 6.0, 1e-5);
  EXPECT_NEAR(sideArea, 10.0 * 0.3, 1e-5);
  // Side walls face into the relief (towards the panel's centre).
  for (std::size_t t = 1 + r.SurfaceTriangles; t < r.Scene.TriangleCount(); ++t)
  {
    const glm::vec3 centre =
      (r.Scene.Vertex(t, 0) + r.Scene.Vertex(t, 1) + r.Scene.Vertex(t, 2)) / 3.0f;
    EXPECT_GT(glm::dot(r.Scene.FaceNormal(t), glm::vec3(1.5f, 1.0f, centre.z) - centre), 0.0f);
  }
}

TEST(SurfaceRelief, OwnTextureCoordinatesAreUsed)
{
  // With texture coordinates of its own (here the panel's u running along -x) the relief follows
  // them rather than the plane rule.
  TriangleScene scene = Panel();
  for (const glm::vec3& p : scene.Positions)
  {
    scene.TextureCoordinates.emplace_back(1.0f - p.x / 3.0f, p.y / 2.0f);
  }
  SurfaceReliefSettings settings;
  settings.DepthScale = 0.1f;
  const SurfaceReliefResult r = DisplaceSurface(scene, "panel", LinearMap(), settings);
  ASSERT_EQ(r.Scene.TextureCoordinates.size(), r.Scene.Positions.size());
  for (std::size_t t = 1; t < 1 + r.SurfaceTriangles; ++t)
  {
    EXPECT_GT(r.Scene.FaceNormal(t).z, 0.0f); // mirrored texture space, same front
    for (int c = 0; c < 3; ++c)
    {
      const glm::vec3 p = r.Scene.Vertex(t, c);
      EXPECT_NEAR(p.z, -0.3 * AnalyticDepth(1.0 - p.x / 3.0, p.y / 2.0), 1e-5);
    }
  }
}

TEST(SurfaceRelief, Refusals)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  DepthMap map;
  map.Width = 2;
  map.Height = 2;
  map.Depth.assign(4, 0.5f);
  // Unknown name: the message lists the surfaces there are.
  const std::string unknown = ReliefError(box, "window", map);
  EXPECT_NE(unknown.find("window"), std::string::npos) << unknown;
  EXPECT_NE(unknown.find("back"), std::string::npos) << unknown;
  // The published red wall is 0.2% off its plane (its corners' x run 549.6 .. 556): taken, as
  // `vlf render --relief` takes it; a panel folded 5% of its size is refused.
  EXPECT_EQ(ReliefError(box, "left", map), "");
  TriangleScene folded;
  folded.AddPolygon(
    { { 0.0f, 0.0f, 0.0f }, { 1.0f, 0.0f, 0.0f }, { 1.0f, 1.0f, 0.07f }, { 0.0f, 1.0f, 0.0f } },
    folded.AddMaterial({}), folded.AddSurface("folded"));
  EXPECT_NE(ReliefError(folded, "folded", map).find("not planar"), std::string::npos);
  // A block: five faces facing five ways.
  EXPECT_NE(ReliefError(box, "tall", map).find("not planar"), std::string::npos);
  // Depths outside [0, 1], and a map of the wrong size.
  DepthMap bad = map;
  bad.Depth[3] = 1.5f;
  EXPECT_NE(ReliefError(box, "back", bad).find("outside [0, 1]"), std::string::npos);
  bad.Depth.resize(3);
  EXPECT_NE(ReliefError(box, "back", bad).find("Width x Height"), std::string::npos);
  // A plane it accepts.
  EXPECT_EQ(ReliefError(box, "floor", map), "");
}

} // namespace
