// SPDX-License-Identifier: BSD-3-Clause
// The path tracer on scenes read from OBJ + MTL text (ObjScene.h), rendered as images through a
// pinhole camera, as `mesolight trace --scene FILE.obj` renders them:
// - the furnace read from OBJ: a closed room of one diffuse material of albedo a whose every face
//   emits Le (Ke) has radiance Le / (1 - a) in every direction, so every pixel of any view from
//   inside reads it, channel by channel (a coloured Le and Kd); cutting paths after two bounces
//   reads Le (1 + a + a^2) and must fail the same check;
// - a one-sided emitter (Ke) over a black floor: its back, seen from below, is black, its front
//   is Le, as the OBJ's face winding says.
#include "EmbreeScene.h"
#include "ObjScene.h"
#include "PathTracer.h"
#include "PinholeCamera.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <string>

namespace
{
using mesolight::EmbreeScene;
using mesolight::PathTracer;
using mesolight::PathTracerSettings;
using mesolight::PinholeCamera;
using mesolight::RgbImage;

// An OBJ room 4 x 2.5 x 3 (faces counter-clockwise seen from inside, their front inward) of one
// material with the given MTL statements.
mesolight::TriangleScene ReadRoom(const std::string& material)
{
  std::istringstream obj("v 0 0 0\nv 4 0 0\nv 4 2.5 0\nv 0 2.5 0\n"
                         "v 0 0 3\nv 4 0 3\nv 4 2.5 3\nv 0 2.5 3\n"
                         "usemtl room\n"
                         "f 1 5 6 2\nf 4 3 7 8\nf 1 2 3 4\nf 5 8 7 6\nf 1 4 8 5\nf 2 6 7 3\n");
  // The MTL is written beside the OBJ as the reader expects it: mtllib resolves in `directory`.
  const std::string directory = ::testing::TempDir();
  {
    const std::string path = directory + "/path-tracer-room.mtl";
    FILE* file = std::fopen(path.c_str(), "w");
    EXPECT_NE(file, nullptr);
    std::fputs(("newmtl room\n" + material).c_str(), file);
    std::fclose(file);
  }
  std::istringstream withLibrary("mtllib path-tracer-room.mtl\n" + obj.str());
  mesolight::ObjSceneRead read = mesolight::ParseObjScene(withLibrary, "room.obj", directory);
  EXPECT_TRUE(read.Warnings.empty()) << read.Warnings.front();
  return read.Scene;
}

PinholeCamera InsideView()
{
  PinholeCamera camera;
  camera.Position = glm::vec3(3.2f, 1.4f, 2.6f);
  camera.FocalPoint = glm::vec3(0.5f, 0.8f, 0.3f);
  camera.ViewAngleDegrees = 70.0f;
  return camera;
}

// Mean radiance of the image per channel.
glm::dvec3 ImageMean(const RgbImage& image)
{
  glm::dvec3 sum(0.0);
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      const float* p = image.Pixel(i, j);
      sum += glm::dvec3(p[0], p[1], p[2]);
    }
  }
  return sum / static_cast<double>(image.Width * image.Height);
}

// Whether the image mean is within `tolerance` (relative) of `expected` in every channel.
bool MeanAgrees(const RgbImage& image, const glm::dvec3& expected, double tolerance)
{
  const glm::dvec3 mean = ImageMean(image);
  for (int c = 0; c < 3; ++c)
  {
    if (!(std::abs(mean[c] - expected[c]) <= tolerance * expected[c]))
    {
      return false;
    }
  }
  return true;
}

const char* const FurnaceMaterial = "Kd 0.5 0.6 0.3\nKe 1 0.5 0.25\n";
const glm::dvec3 FurnaceRadiance(1.0 / 0.5, 0.5 / 0.4, 0.25 / 0.7); // Le / (1 - Kd)

TEST(PathTracerObjScene, FurnaceReadFromObjIsLeOverOneMinusAlbedoInEveryPixel)
{
  const mesolight::TriangleScene room = ReadRoom(FurnaceMaterial);
  const EmbreeScene embree(room);
  const PathTracer tracer(embree);
  const RgbImage image = tracer.RenderImage(InsideView(), 24, 16, 256, 7);
  ASSERT_EQ(image.Width, 24);
  const glm::dvec3 mean = ImageMean(image);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(mean[c], FurnaceRadiance[c], 0.015 * FurnaceRadiance[c]) << "channel " << c;
  }
  // Every pixel too (256 paths each: within 15%), corners and walls alike.
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        ASSERT_NEAR(image.Pixel(i, j)[c], FurnaceRadiance[c], 0.15 * FurnaceRadiance[c])
          << "pixel " << i << "," << j << " channel " << c;
      }
    }
  }
}

TEST(PathTracerObjSceneNegative, PathsCutAfterTwoBouncesFailTheFurnace)
{
  const mesolight::TriangleScene room = ReadRoom(FurnaceMaterial);
  const EmbreeScene embree(room);
  PathTracerSettings settings;
  settings.MaxDepth = 2;
  const PathTracer tracer(embree, settings);
  const RgbImage image = tracer.RenderImage(InsideView(), 24, 16, 32, 7);
  ASSERT_EQ(image.Width, 24);
  EXPECT_FALSE(MeanAgrees(image, FurnaceRadiance, 0.015)) << "a truncated path passes";
  // It reads the truncated series Le (1 + a + a^2) instead: the check sees the difference.
  const glm::dvec3 albedo(0.5, 0.6, 0.3), emission(1.0, 0.5, 0.25);
  EXPECT_TRUE(MeanAgrees(image, emission * (1.0 + albedo + albedo * albedo), 0.015));
}

TEST(PathTracerObjScene, EmitterIsOneSidedAsTheObjWindingSays)
{
  // A 2 x 2 emitter 1 above the origin, its front (counter-clockwise) facing down, Le 3; no
  // other surface.
  const std::string directory = ::testing::TempDir();
  {
    FILE* file = std::fopen((directory + "/path-tracer-lamp.mtl").c_str(), "w");
    ASSERT_NE(file, nullptr);
    std::fputs("newmtl lamp\nKd 0 0 0\nKe 3 3 3\n", file);
    std::fclose(file);
  }
  std::istringstream obj("mtllib path-tracer-lamp.mtl\nv -1 1 -1\nv 1 1 -1\nv 1 1 1\nv -1 1 1\n"
                         "usemtl lamp\nf 1 2 3 4\n");
  const mesolight::ObjSceneRead read = mesolight::ParseObjScene(obj, "lamp.obj", directory);
  const EmbreeScene embree(read.Scene);
  const PathTracer tracer(embree);
  PinholeCamera below, above;
  below.Position = glm::vec3(0.0f, -1.0f, 0.0f);
  below.FocalPoint = glm::vec3(0.0f, 1.0f, 0.0f);
  below.ViewUp = glm::vec3(0.0f, 0.0f, 1.0f);
  below.ViewAngleDegrees = 20.0f; // sees only the emitter
  above = below;
  above.Position = glm::vec3(0.0f, 3.0f, 0.0f);
  above.FocalPoint = glm::vec3(0.0f, 0.0f, 0.0f);
  EXPECT_TRUE(MeanAgrees(tracer.RenderImage(below, 8, 8, 2, 1), glm::dvec3(3.0), 1e-5));
  const glm::dvec3 back = ImageMean(tracer.RenderImage(above, 8, 8, 2, 1));
  EXPECT_EQ(back, glm::dvec3(0.0)) << "the emitter's back emits";
}

} // namespace
