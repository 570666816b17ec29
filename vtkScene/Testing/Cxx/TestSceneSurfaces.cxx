// SPDX-License-Identifier: BSD-3-Clause
// Tests of the scene's named surfaces: the Cornell box's names, SurfaceTriangles and its error,
// names kept one per triangle by AddPolygon, Append and RemoveDegenerateTriangles, and OBJ `g`/`o`
// statements read and written.
#include "ObjScene.h"
#include "TriangleScene.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using mesolight::SceneSurfaceError;
using mesolight::SurfaceTriangles;
using mesolight::TriangleScene;

std::string SurfaceError(const TriangleScene& scene, const std::string& name)
{
  try
  {
    SurfaceTriangles(scene, name);
  }
  catch (const SceneSurfaceError& error)
  {
    return error.what();
  }
  return "";
}

TEST(SceneSurfaces, CornellBoxNamesEveryTriangle)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  ASSERT_EQ(box.SurfaceIds.size(), box.TriangleCount());
  const std::vector<std::string> expected{ "floor", "ceiling", "back", "left", "right", "light",
    "short", "tall" };
  EXPECT_EQ(box.SurfaceNames, expected);
  // Triangle order: five walls and the light (two triangles each), then two blocks of five quads.
  EXPECT_EQ(SurfaceTriangles(box, "floor"), (std::vector<std::size_t>{ 0, 1 }));
  EXPECT_EQ(SurfaceTriangles(box, "back"), (std::vector<std::size_t>{ 4, 5 }));
  EXPECT_EQ(SurfaceTriangles(box, "light"), (std::vector<std::size_t>{ 10, 11 }));
  EXPECT_EQ(SurfaceTriangles(box, "short").size(), 10u);
  EXPECT_EQ(SurfaceTriangles(box, "tall").size(), 10u);
  // Each name's triangles have its wall's geometry and material: the back wall at z = 559.2 and
  // the red left wall at x = 550 (its corners range 549.6 .. 556).
  for (const std::size_t t : SurfaceTriangles(box, "back"))
  {
    EXPECT_FLOAT_EQ(box.Vertex(t, 0).z, 559.2f);
    EXPECT_FLOAT_EQ(box.Vertex(t, 1).z, 559.2f);
    EXPECT_FLOAT_EQ(box.Vertex(t, 2).z, 559.2f);
  }
  for (const std::size_t t : SurfaceTriangles(box, "left"))
  {
    EXPECT_EQ(box.MaterialOf(t).Name, "red");
    EXPECT_GT(box.Vertex(t, 0).x, 549.0f);
  }
  for (const std::size_t t : SurfaceTriangles(box, "right"))
  {
    EXPECT_EQ(box.MaterialOf(t).Name, "green");
  }
  EXPECT_EQ(box.SurfaceOf(0), "floor");
  // The mirror box keeps the names.
  EXPECT_EQ(mesolight::MakeCornellBoxWithMirror().SurfaceIds, box.SurfaceIds);
}

TEST(SceneSurfaces, UnknownNameListsTheScenesSurfaces)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  const std::string message = SurfaceError(box, "wall");
  EXPECT_NE(message.find("'wall'"), std::string::npos) << message;
  for (const char* name : { "floor", "ceiling", "back", "left", "right", "light", "short", "tall" })
  {
    EXPECT_NE(message.find(name), std::string::npos) << name << ": " << message;
  }
  // It is a std::runtime_error, so a caller catching those gets it.
  EXPECT_THROW(SurfaceTriangles(box, ""), std::runtime_error);
  // A scene without names says so.
  TriangleScene unnamed;
  unnamed.AddPolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, unnamed.AddMaterial({}));
  EXPECT_TRUE(unnamed.SurfaceIds.empty());
  EXPECT_NE(SurfaceError(unnamed, "floor").find("(none)"), std::string::npos);
}

TEST(SceneSurfaces, AddPolygonAndAppendKeepOneIdPerTriangle)
{
  TriangleScene scene;
  const std::uint32_t grey = scene.AddMaterial({});
  scene.AddPolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 1, 1, 0 }, { 0, 1, 0 } }, grey); // unnamed
  EXPECT_TRUE(scene.SurfaceIds.empty());
  scene.AddPolygon({ { 0, 0, 1 }, { 1, 0, 1 }, { 1, 1, 1 } }, grey, scene.AddSurface("lid"));
  ASSERT_EQ(scene.SurfaceIds.size(), 3u);
  EXPECT_EQ(scene.SurfaceOf(0), "");
  EXPECT_EQ(scene.SurfaceOf(1), "");
  EXPECT_EQ(scene.SurfaceOf(2), "lid");
  scene.AddPolygon({ { 0, 0, 2 }, { 1, 0, 2 }, { 1, 1, 2 } }, grey); // unnamed after named
  ASSERT_EQ(scene.SurfaceIds.size(), 4u);
  EXPECT_EQ(scene.SurfaceOf(3), "");

  // Appending the box: its names are added, and a name both have merges into one surface.
  TriangleScene box = mesolight::MakeCornellBox();
  box.SurfaceNames[box.SurfaceIds[0]] = "lid"; // the floor is called "lid" too
  scene.Append(box);
  ASSERT_EQ(scene.SurfaceIds.size(), scene.TriangleCount());
  EXPECT_EQ(SurfaceTriangles(scene, "lid"), (std::vector<std::size_t>{ 2, 4, 5 }));
  EXPECT_EQ(SurfaceTriangles(scene, "tall").size(), 10u);
  EXPECT_EQ(scene.SurfaceOf(4 + 4), "back"); // the box starts at triangle 4

  // An unnamed scene appended to a named one leaves its triangles unnamed.
  TriangleScene plain;
  plain.AddPolygon({ { 0, 0, 3 }, { 1, 0, 3 }, { 1, 1, 3 } }, plain.AddMaterial({}));
  const std::size_t before = scene.TriangleCount();
  scene.Append(plain);
  ASSERT_EQ(scene.SurfaceIds.size(), before + 1);
  EXPECT_EQ(scene.SurfaceOf(before), "");
  // And a named scene appended to an unnamed one is named.
  plain.Append(mesolight::MakeCornellBox());
  ASSERT_EQ(plain.SurfaceIds.size(), plain.TriangleCount());
  EXPECT_EQ(plain.SurfaceOf(0), "");
  EXPECT_EQ(SurfaceTriangles(plain, "floor"), (std::vector<std::size_t>{ 1, 2 }));
}

TEST(SceneSurfaces, RemovingDegenerateTrianglesKeepsTheNames)
{
  TriangleScene scene;
  const std::uint32_t grey = scene.AddMaterial({});
  scene.AddPolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 0, 1, 0 } }, grey, scene.AddSurface("a"));
  scene.AddPolygon({ { 0, 0, 0 }, { 1, 0, 0 }, { 2, 0, 0 } }, grey, scene.AddSurface("b"));
  scene.AddPolygon({ { 0, 0, 1 }, { 1, 0, 1 }, { 0, 1, 1 } }, grey, scene.AddSurface("c"));
  EXPECT_EQ(mesolight::RemoveDegenerateTriangles(scene), 1u);
  ASSERT_EQ(scene.SurfaceIds.size(), 2u);
  EXPECT_EQ(scene.SurfaceOf(0), "a");
  EXPECT_EQ(scene.SurfaceOf(1), "c");
  EXPECT_THROW(SurfaceTriangles(scene, "b"), SceneSurfaceError);
  EXPECT_EQ(mesolight::SurfaceNameList(scene), "a, c");
}

TEST(SceneSurfaces, ObjGroupsAndObjectsNameSurfaces)
{
  std::istringstream obj("v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
                         "f 1 2 3\n"                // before any name: unnamed
                         "o crate\nf 1 3 4\n"       // object name
                         "g wall left\nf 1 2 3 4\n" // several groups: joined
                         "g\nf 2 3 4\n"             // bare g: unnamed again
                         "g crate\nf 1 2 4\n");     // a name met again: the same surface
  const mesolight::ObjSceneRead read = mesolight::ParseObjScene(obj, "groups.obj", ".");
  const TriangleScene& scene = read.Scene;
  ASSERT_EQ(scene.SurfaceIds.size(), scene.TriangleCount());
  EXPECT_EQ(scene.SurfaceOf(0), "");
  EXPECT_EQ(SurfaceTriangles(scene, "crate"), (std::vector<std::size_t>{ 1, 5 }));
  EXPECT_EQ(SurfaceTriangles(scene, "wall left"), (std::vector<std::size_t>{ 2, 3 }));
  EXPECT_EQ(scene.SurfaceOf(4), "");

  // An OBJ without g/o names nothing.
  std::istringstream plain("v 0 0 0\nv 1 0 0\nv 1 1 0\nf 1 2 3\n");
  EXPECT_TRUE(mesolight::ParseObjScene(plain, "plain.obj", ".").Scene.SurfaceIds.empty());
}

TEST(SceneSurfaces, WrittenAndReadBack)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  const std::string path = std::string(MESOLIGHT_TEST_TEMP_DIR) + "/surfaces-roundtrip.obj";
  mesolight::WriteObjScene(box, path, true);
  const TriangleScene read = mesolight::ReadObjScene(path).Scene;
  EXPECT_EQ(read.SurfaceNames, box.SurfaceNames);
  EXPECT_EQ(read.SurfaceIds, box.SurfaceIds);
  // The committed example is the built-in box, names included.
  const TriangleScene committed =
    mesolight::ReadObjScene(std::string(MESOLIGHT_SOURCE_DIR) + "/examples/data/cornell-box.obj")
      .Scene;
  EXPECT_EQ(committed.SurfaceNames, box.SurfaceNames);
  EXPECT_EQ(committed.SurfaceIds, box.SurfaceIds);
}

} // namespace
