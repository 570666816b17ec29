// SPDX-License-Identifier: BSD-3-Clause
// ReliefSurface (core, no VTK): the texture frame of the plane rule on the published Cornell box
// (docs/vlf.md gives the back wall's frame in millimetres), the probes' places, and the refusals.
#include "ReliefSurface.h"

#include "LightField.h"
#include "PatchComparison.h" // ToWorld
#include "SurfaceRelief.h" // SurfacePlaneOf
#include "WalkthroughTestFields.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

namespace
{
using namespace mesolight;
namespace vlf = mesolight::vlf;

glm::vec3 World(const vlf::LightField& field, const glm::dvec3& unit)
{
  return vlf::ToWorld(field, glm::vec3(unit));
}
} // namespace

TEST(ReliefSurface, BackWallFrameIsThePlaneRuleInMillimetres)
{
  const vlf::LightField& field = walkthroughtest::PlainCornellField(129);
  const vlf::ReliefSurface back = vlf::FindReliefSurface(field, "back");
  EXPECT_FALSE(back.SceneTextureCoordinates);
  // u = 0 at x = 556 mm, 1 at x = 0; v = 0 at y = 0, 1 at y = 548.8; the wall at z = 559.2.
  const glm::vec3 origin = World(field, back.Point(0.0, 0.0));
  const glm::vec3 far = World(field, back.Point(1.0, 1.0));
  EXPECT_NEAR(origin.x, 556.0f, 1.0f);
  EXPECT_NEAR(origin.y, 0.0f, 1.0f);
  EXPECT_NEAR(origin.z, 559.2f, 1.0f);
  EXPECT_NEAR(far.x, 0.0f, 1.0f);
  EXPECT_NEAR(far.y, 548.8f, 1.0f);
  EXPECT_NEAR(back.Normal.z, -1.0, 1e-3); // facing into the room
  // Texture coordinates of a point of the plane invert Point.
  const glm::dvec3 uvw = back.TextureOf(back.Point(0.25, 0.75));
  EXPECT_NEAR(uvw.x, 0.25, 1e-9);
  EXPECT_NEAR(uvw.y, 0.75, 1e-9);
  EXPECT_NEAR(uvw.z, 0.0, 1e-9);
  // Probes stand in front of the wall over its texture.
  const glm::vec3 p = vlf::ReliefProbePoint(back, 0, 1, 2, 2);
  const glm::dvec3 t = back.TextureOf(glm::dvec3(p));
  EXPECT_NEAR(t.x, 0.25, 1e-5);
  EXPECT_NEAR(t.y, 0.75, 1e-5);
  EXPECT_NEAR(t.z, 1e-3, 1e-5);
}

TEST(ReliefSurface, FrameIsTheDenseMeshReferencesOnTheRedWall)
{
  // The red wall is 0.2% off its plane: taken by both, with one frame, so `vlf render --relief`
  // and `trace --relief` (SurfacePlaneOf on the world scene) put the image at the same place.
  const vlf::LightField& field = walkthroughtest::PlainCornellField(129);
  const vlf::ReliefSurface left = vlf::FindReliefSurface(field, "left");
  const TriangleScene box = MakeCornellBox();
  const SurfacePlane plane = SurfacePlaneOf(box, SurfaceTriangles(box, "left"), "left");
  for (const glm::dvec2 uv : { glm::dvec2(0.0), glm::dvec2(1.0, 0.0), glm::dvec2(0.0, 1.0),
         glm::dvec2(1.0), glm::dvec2(0.3, 0.6) })
  {
    const glm::vec3 expected = plane.Origin + static_cast<float>(uv.x) * plane.AxisU +
      static_cast<float>(uv.y) * plane.AxisV;
    EXPECT_LT(glm::distance(World(field, left.Point(uv.x, uv.y)), expected), 0.01f)
      << uv.x << ", " << uv.y;
  }
  EXPECT_GT(glm::dot(glm::vec3(left.Normal), plane.Normal), 0.999999f);
}

TEST(ReliefSurface, RefusesWhatCannotCarryARelief)
{
  const vlf::LightField& plain = walkthroughtest::PlainCornellField(129);
  try
  {
    vlf::FindReliefSurface(plain, "tall");
    ADD_FAILURE() << "a block was taken";
  }
  catch (const vlf::ReliefSurfaceError& e)
  {
    EXPECT_NE(std::string(e.what()).find("is not planar"), std::string::npos) << e.what();
    EXPECT_NE(std::string(e.what()).find("`g` names"), std::string::npos) << e.what();
  }
  try
  {
    vlf::FindReliefSurface(plain, "wall");
    ADD_FAILURE() << "an unknown name was taken";
  }
  catch (const vlf::ReliefSurfaceError& e)
  {
    EXPECT_NE(std::string(e.what()).find("floor, ceiling, back"), std::string::npos) << e.what();
  }
  // The mirror box's left wall is its mirror.
  EXPECT_THROW(vlf::FindReliefSurface(walkthroughtest::MirrorCornellField(129), "left"),
    vlf::ReliefSurfaceError);
  const vlf::ReliefSurface back = vlf::FindReliefSurface(plain, "back");
  EXPECT_THROW(vlf::ReliefSurfaceProbes(plain, back, 0, 2), std::invalid_argument);
  // A stop asked through progress.
  EXPECT_THROW(vlf::ReliefSurfaceProbes(plain, back, 2, 2, [](double) { return false; }),
    vlf::AbortedError);
}
