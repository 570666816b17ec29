// SPDX-License-Identifier: BSD-3-Clause
// Tests of the Wavefront OBJ + MTL reader and writer: every supported statement, errors with
// file:line, missing MTL and materials, scene checks (no emitter, degenerate and non-manifold
// triangles), and the Cornell box written, read back and compared with the built-in one.
#include "ObjScene.h"
#include "SceneTestUtilities.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cstdio>
#include <fstream>
#include <sstream>
#include <string>
#include <utility>

namespace
{
using mesolight::ObjReadOptions;
using mesolight::ObjSceneError;
using mesolight::ObjSceneRead;
using mesolight::ReadObjScene;
using mesolight::TriangleScene;
using mesolight::vlftest::ExpectSameScene;

std::string TempPath(const std::string& name)
{
  return std::string(MESOLIGHT_TEST_TEMP_DIR) + "/" + name;
}

std::string WriteText(const std::string& name, const std::string& text)
{
  const std::string path = TempPath(name);
  std::ofstream(path, std::ios::binary) << text;
  return path;
}

// The message of the ObjSceneError that reading `path` throws ("" if none).
std::string ReadError(const std::string& path, const ObjReadOptions& options = {})
{
  try
  {
    ReadObjScene(path, options);
  }
  catch (const ObjSceneError& error)
  {
    return error.what();
  }
  return "";
}

const char* const LampMtl =
  "newmtl lamp\nKd 0.1 0.2 0.3\nKe 5 4 3\n"
  "newmtl mirror # a comment\nKd 0\nKs 0.9 0.9 0.9\nNs 200\nKa 0.1 0.1 0.1\n"
  "illum 3\nmap_Kd -bm 1 textures/wood.png\nmap_Ks shiny.png\n";

TEST(ObjScene, ReadsEveryStatement)
{
  WriteText("every.mtl", LampMtl);
  const std::string path = WriteText("every.obj",
    "# comment\r\nmtllib every.mtl\r\no thing\ng group\ns off\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0.5 1.5 \\\n 0\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 1\n"
    "vn 0 0 2\n"
    "usemtl lamp\n"
    "f 1/1/1 2/2/1 3/3/1 5/5/1 4/4/1\n" // a pentagon: three triangles
    "usemtl mirror\n"
    "f -4/-4/-1 -3/-3/-1 -1/-1/-1\n"); // negative indices: vertices 2, 3, 5
  const ObjSceneRead read = ReadObjScene(path);
  const TriangleScene& scene = read.Scene;
  EXPECT_EQ(read.ObjVertices, 5u);
  EXPECT_EQ(read.ObjFaces, 2u);
  ASSERT_EQ(scene.TriangleCount(), 4u);
  ASSERT_EQ(scene.Materials.size(), 2u);
  EXPECT_EQ(scene.Materials[0].Name, "lamp");
  EXPECT_EQ(scene.Materials[0].Diffuse, glm::vec3(0.1f, 0.2f, 0.3f));
  EXPECT_EQ(scene.Materials[0].Emission, glm::vec3(5.0f, 4.0f, 3.0f));
  EXPECT_EQ(scene.Materials[1].Diffuse, glm::vec3(0.0f)); // "Kd 0" is grey 0
  EXPECT_EQ(scene.Materials[1].Specular, glm::vec3(0.9f));
  EXPECT_EQ(scene.Materials[1].Ambient, glm::vec3(0.1f));
  EXPECT_EQ(scene.Materials[1].Shininess, 200.0f);
  EXPECT_EQ(read.TextureMaps[1].at("map_Kd"), "textures/wood.png");
  EXPECT_EQ(read.TextureMaps[1].at("map_Ks"), "shiny.png");
  EXPECT_TRUE(read.TextureMaps[0].empty());
  EXPECT_EQ(scene.MaterialIds, (std::vector<std::uint32_t>{ 0, 0, 0, 1 }));
  // The continued line is vertex 5; the fan starts at the first corner.
  EXPECT_EQ(scene.Vertex(1, 2), glm::vec3(0.5f, 1.5f, 0.0f));
  EXPECT_EQ(scene.Vertex(3, 0), glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(scene.Vertex(3, 1), glm::vec3(1.0f, 1.0f, 0.0f));
  EXPECT_EQ(scene.Vertex(3, 2), glm::vec3(0.5f, 1.5f, 0.0f));
  // Per-vertex attributes, normals normalised.
  ASSERT_EQ(scene.Normals.size(), scene.Positions.size());
  ASSERT_EQ(scene.TextureCoordinates.size(), scene.Positions.size());
  EXPECT_EQ(scene.Normals[0], glm::vec3(0.0f, 0.0f, 1.0f));
  EXPECT_EQ(scene.TextureCoordinates[scene.Triangles[1][2]], glm::vec2(0.5f, 1.0f));
  EXPECT_EQ(read.NonManifoldEdges, 0u);
  EXPECT_EQ(read.DegenerateTriangles, 0u);
  EXPECT_TRUE(read.Warnings.empty()) << read.Warnings.front();
}

// OBJ lines "v i i^2 1" for the first `count` vertices.
std::string SquareVertices(int count)
{
  std::string lines;
  for (int v = 0; v < count; ++v)
  {
    lines += "v " + std::to_string(v) + " " + std::to_string(v * v) + " 1\n";
  }
  return lines;
}

TEST(ObjScene, ErrorsNameFileAndLine)
{
  const std::string vertices = SquareVertices(31);
  // Line 12 of a file whose vertex 40 does not exist (31 vertices).
  std::string text = SquareVertices(11);
  text += "f 1 2 40\n";
  for (int v = 11; v < 31; ++v)
  {
    text += "v " + std::to_string(v) + " 0 1\n";
  }
  std::string path = WriteText("scene.obj", text);
  EXPECT_EQ(ReadError(path), path + ":12: face refers to vertex 40 of 11");

  const auto errorOf = [&](const std::string& body)
  { return ReadError(WriteText("bad.obj", vertices + body)); };
  const std::string bad = TempPath("bad.obj");
  // Each body after the 31 vertices (its statement on line 32) and the error it must give.
  const std::pair<std::string, std::string> cases[] = {
    { "f 1 2 40\n", ":32: face refers to vertex 40 of 31" },
    { "f 1 2 0\n", ":32: face refers to vertex 0 of 31" },
    { "f 1 2 -32\n", ":32: face refers to vertex -32 of 31" },
    { "f 1 2\n", ":32: a face needs at least 3 vertices, got 2" },
    { "f 1 2 x\n", ":32: cannot read 'x' as a vertex index" },
    { "f 1/5 2/5 3/5\n", ":32: face refers to texture coordinate 5 of 0" },
    { "f 1//2 2//2 3//2\n", ":32: face refers to normal 2 of 0" },
    { "v 1 2\n", ":32: 'v' needs 3 numbers, got 2" },
    { "v 1 2 zz\n", ":32: cannot read 'zz' as a number" },
    { "v 1 nan 3\n", ":32: 'nan' is not a finite number" },
    { "v 1 1e39 3\n", ":32: cannot read '1e39' as a number" },
    { "usemtl\n", ":32: usemtl needs a material name" },
    { "", ": no faces" },
  };
  for (const auto& c : cases)
  {
    EXPECT_EQ(errorOf(c.first), bad + c.second) << c.first;
  }
  EXPECT_EQ(ReadError(TempPath("does-not-exist.obj")),
    TempPath("does-not-exist.obj") + ": cannot open the file");
  // Not an OBJ at all: binary data, or text without any OBJ statement.
  EXPECT_EQ(ReadError(WriteText("binary.obj", std::string("v 1 2 3\n\x89PNG\0\0\0", 15))),
    TempPath("binary.obj") + ":2: binary data: this is not a text Wavefront file");
  std::string prose;
  for (int k = 0; k < 30; ++k)
  {
    prose += "Lorem ipsum dolor sit amet\n";
  }
  EXPECT_EQ(ReadError(WriteText("prose.obj", prose)),
    TempPath("prose.obj") +
      ":21: no Wavefront OBJ statement in the first 20 lines: this is not an "
      "OBJ file");
  // MTL errors name the MTL file and its line.
  WriteText("bad.mtl", "newmtl a\nKd 0.5 0.5 0.5\nKe 1 x 1\n");
  EXPECT_EQ(
    errorOf("mtllib bad.mtl\nf 1 2 3\n"), TempPath("bad.mtl") + ":3: cannot read 'x' as a number");
  WriteText("bad2.mtl", "Kd 0.5 0.5 0.5\n");
  EXPECT_EQ(
    errorOf("mtllib bad2.mtl\nf 1 2 3\n"), TempPath("bad2.mtl") + ":1: 'Kd' before any newmtl");
  // A material with a negative colour is refused by the scene check.
  WriteText("negative.mtl", "newmtl a\nKd -0.5 0.5 0.5\n");
  EXPECT_EQ(errorOf("mtllib negative.mtl\nusemtl a\nf 1 2 3\n"),
    bad + ": material 'a' has a negative value");
}

TEST(ObjScene, MissingMtlGivesGreyAndAWarning)
{
  const std::string path = WriteText(
    "missing.obj", "mtllib nowhere.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lamp\nf 1 2 3\n");
  const ObjSceneRead read = ReadObjScene(path);
  ASSERT_EQ(read.Scene.Materials.size(), 1u);
  EXPECT_EQ(read.Scene.Materials[0].Diffuse, glm::vec3(0.5f));
  EXPECT_EQ(read.Scene.Materials[0].Name, "lamp");
  ASSERT_GE(read.Warnings.size(), 2u);
  EXPECT_NE(read.Warnings[0].find(path + ":1: mtllib 'nowhere.mtl' not found"), std::string::npos);
  EXPECT_NE(
    read.Warnings[1].find(path + ":5: material 'lamp' is not in any MTL file"), std::string::npos);
  // Faces before any usemtl get the default grey too, without a warning of their own.
  const ObjSceneRead plain =
    ReadObjScene(WriteText("plain.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n"));
  ASSERT_EQ(plain.Scene.Materials.size(), 1u);
  EXPECT_EQ(plain.Scene.Materials[0].Name, "default-grey");
}

// Texture coordinates on some faces only (a user who gave one wall vt): the scene keeps them for
// all triangles or none, so they are dropped, and the reader says so instead of a relief on that
// wall silently taking its plane's coordinates. On every face they are kept, without a word.
TEST(ObjScene, TextureCoordinatesOnSomeFacesOnlyAreDroppedWithAWarning)
{
  const std::string vertices = "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\nvt 0 0\nvt 2 0\nvt 0 2\n";
  const ObjSceneRead some =
    ReadObjScene(WriteText("some-vt.obj", vertices + "f 1/1 2/2 3/3\nf 2 4 3\n"));
  EXPECT_TRUE(some.Scene.TextureCoordinates.empty());
  bool said = false;
  for (const std::string& warning : some.Warnings)
  {
    said = said || warning.find("1 of 2 triangles have texture coordinates") != std::string::npos;
  }
  EXPECT_TRUE(said) << "no warning about the dropped texture coordinates";
  const ObjSceneRead all =
    ReadObjScene(WriteText("all-vt.obj", vertices + "f 1/1 2/2 3/3\nf 2/2 1/1 3/3\n"));
  EXPECT_EQ(all.Scene.TextureCoordinates.size(), all.Scene.Positions.size());
  for (const std::string& warning : all.Warnings)
  {
    EXPECT_EQ(warning.find("texture coordinates"), std::string::npos) << warning;
  }
}

// An MTL that is a device or a FIFO is not read: /dev/zero is one endless line (memory without
// bound), /dev/stdin waits forever.
TEST(ObjScene, MtllibOfADeviceIsIgnored)
{
  const std::string path =
    WriteText("device.obj", "mtllib /dev/zero\nv 0 0 0\nv 1 0 0\nv 0 1 0\nusemtl lamp\nf 1 2 3\n");
  const ObjSceneRead read = ReadObjScene(path);
  ASSERT_EQ(read.Scene.Materials.size(), 1u);
  EXPECT_EQ(read.Scene.Materials[0].Diffuse, glm::vec3(0.5f));
  ASSERT_FALSE(read.Warnings.empty());
  EXPECT_NE(
    read.Warnings[0].find(path + ":1: mtllib '/dev/zero' is not a regular file"), std::string::npos)
    << read.Warnings[0];
}

TEST(ObjScene, NoEmitter)
{
  const std::string path = WriteText("dark.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  ObjReadOptions strict;
  strict.RequireEmitter = true;
  EXPECT_EQ(ReadError(path, strict),
    path + ": the scene has no emitter (no material with emission Ke > 0)");
  const ObjSceneRead read = ReadObjScene(path);
  ASSERT_FALSE(read.Warnings.empty());
  EXPECT_NE(read.Warnings.back().find("no emitter"), std::string::npos);
  // With an emitter, the strict read passes.
  WriteText("lamp.mtl", LampMtl);
  const std::string lit =
    WriteText("lit.obj", "mtllib lamp.mtl\nusemtl lamp\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  EXPECT_EQ(ReadError(lit, strict), "");
  // Its material file missing, the refusal gives the first warning: the cause.
  const std::string unlit =
    WriteText("unlit.obj", "mtllib gone.mtl\nusemtl lamp\nv 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n");
  const std::string error = ReadError(unlit, strict);
  EXPECT_NE(error.find("the scene has no emitter"), std::string::npos) << error;
  EXPECT_NE(
    error.find("the first: " + unlit + ":1: mtllib 'gone.mtl' not found"), std::string::npos)
    << error;
}

TEST(ObjScene, DegenerateAndNonManifoldTriangles)
{
  // Three triangles on one edge (1-2), one zero-area triangle (collinear), one repeated vertex.
  const std::string path = WriteText("fins.obj",
    "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0 0 1\nv 2 0 0\n"
    "f 1 2 3\nf 2 1 4\nf 1 2 5\nf 1 2 6\nf 3 3 5\n");
  const ObjSceneRead read = ReadObjScene(path);
  EXPECT_EQ(read.DegenerateTriangles, 2u);
  EXPECT_EQ(read.Scene.TriangleCount(), 3u); // removed
  EXPECT_EQ(read.NonManifoldEdges, 1u);      // edge 1-2 is used four times
  bool warnedNonManifold = false, warnedDegenerate = false;
  for (const std::string& w : read.Warnings)
  {
    warnedNonManifold = warnedNonManifold || w.find("1 non-manifold edges") != std::string::npos;
    warnedDegenerate = warnedDegenerate || w.find("2 degenerate") != std::string::npos;
  }
  EXPECT_TRUE(warnedNonManifold);
  EXPECT_TRUE(warnedDegenerate);
  ObjReadOptions keep;
  keep.RemoveDegenerateTriangles = false;
  EXPECT_EQ(ReadObjScene(path, keep).Scene.TriangleCount(), 5u);
  // Only degenerate triangles: an error.
  EXPECT_EQ(ReadError(WriteText("flat.obj", "v 0 0 0\nv 1 0 0\nv 2 0 0\nf 1 2 3\n")),
    TempPath("flat.obj") + ": every triangle of the scene is degenerate (zero area)");
  // Two triangles on edge 1-2 and a zero-area one along it: the degenerate triangle is dropped,
  // so the edge is not reported as non-manifold (it was, blaming the user's file for a fold).
  const ObjSceneRead sliver = ReadObjScene(WriteText(
    "sliver.obj", "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 -1 0\nv 0.5 0 0\nf 1 2 3\nf 2 1 4\nf 1 5 2\n"));
  EXPECT_EQ(sliver.DegenerateTriangles, 1u);
  EXPECT_EQ(sliver.NonManifoldEdges, 0u);
  // A closed manifold (tetrahedron) has none.
  EXPECT_EQ(
    mesolight::CountNonManifoldEdges({ { 0, 1, 2 }, { 0, 3, 1 }, { 1, 3, 2 }, { 2, 3, 0 } }), 0u);
}

// N-gons are ear-clipped (TriangulatePolygon): an L-shaped roof keeps its notch, and a square
// with its edges' midpoints is read without the "degenerate" and "non-manifold" warnings that
// the fan's zero-area triangles caused.
TEST(ObjScene, ConcaveAndEdgeMidpointFacesAreReadAsDrawn)
{
  const ObjSceneRead l = ReadObjScene(
    WriteText("roof.obj", "v 2 0 0\nv 2 0 1\nv 1 0 1\nv 1 0 2\nv 0 0 2\nv 0 0 0\nf 1 2 3 4 5 6\n"));
  double area = 0.0;
  for (std::size_t t = 0; t < l.Scene.TriangleCount(); ++t)
  {
    area += l.Scene.Area(t);
  }
  EXPECT_NEAR(area, 3.0, 1e-6);
  EXPECT_EQ(l.DegenerateTriangles, 0u);
  const ObjSceneRead square = ReadObjScene(WriteText("midpoints.obj",
    "v 0 0 0\nv 1 0 0\nv 2 0 0\nv 2 1 0\nv 2 2 0\nv 1 2 0\nv 0 2 0\nv 0 1 0\n"
    "f 1 2 3 4 5 6 7 8\n"));
  EXPECT_EQ(square.Scene.TriangleCount(), 6u);
  EXPECT_EQ(square.DegenerateTriangles, 0u);
  EXPECT_EQ(square.NonManifoldEdges, 0u);
  for (const std::string& w : square.Warnings)
  {
    EXPECT_EQ(w.find("degenerate"), std::string::npos) << w;
    EXPECT_EQ(w.find("non-manifold"), std::string::npos) << w;
  }
}

TEST(ObjScene, CornellBoxRoundTripAndNoOverwrite)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  const std::string path = TempPath("cornell-roundtrip.obj");
  std::remove(path.c_str());
  std::remove(TempPath("cornell-roundtrip.mtl").c_str());
  mesolight::WriteObjScene(box, path, false, "The Cornell box");
  ObjReadOptions strict;
  strict.RequireEmitter = true;
  const ObjSceneRead read = ReadObjScene(path, strict);
  EXPECT_TRUE(read.Warnings.empty());
  ExpectSameScene(box, read.Scene);
  // A second write refuses and leaves the file alone.
  std::ifstream before(path);
  const std::string original((std::istreambuf_iterator<char>(before)), {});
  EXPECT_THROW(mesolight::WriteObjScene(TriangleScene(box), path), ObjSceneError);
  std::ifstream after(path);
  EXPECT_EQ(original, std::string((std::istreambuf_iterator<char>(after)), {}));
  EXPECT_NO_THROW(mesolight::WriteObjScene(box, path, true));
  // Writing into a folder that does not exist fails cleanly.
  EXPECT_THROW(mesolight::WriteObjScene(box, TempPath("no/such/dir/box.obj")), ObjSceneError);
}

// The committed example data (examples/data/cornell-box.obj/.mtl) is the built-in box.
TEST(ObjScene, CommittedCornellBoxMatchesBuiltIn)
{
  ObjReadOptions strict;
  strict.RequireEmitter = true;
  const ObjSceneRead read =
    ReadObjScene(std::string(MESOLIGHT_SOURCE_DIR) + "/examples/data/cornell-box.obj", strict);
  EXPECT_TRUE(read.Warnings.empty());
  ExpectSameScene(mesolight::MakeCornellBox(), read.Scene);
}

} // namespace
