// SPDX-License-Identifier: BSD-3-Clause
// The movable object's own occlusion in its gathered light (ObjectSelfOcclusion.h):
// a concave bracket gathered from the Cornell box's field against the path tracer with the
// bracket in place (ObjectReference.h, which knows the bracket blocks its own light), with the
// occlusion off as the negative test; convex objects cast no ray and keep their values.
#include "MathConstants.h"
#include "ObjectGatherer.h"
#include "ObjectReference.h"
#include "ObjectSelfOcclusion.h"
#include "WalkthroughTestFields.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <chrono>
#include <cstdio>

using namespace mesolight;
using namespace mesolight::vlf;

namespace
{
// A bracket 120 x 100 mm, bars 20 mm thick, 120 mm deep, open toward +x, floating in the free
// front-right part of the Cornell box (x 360-480, y 250-350, z 70-190 mm) below the light: its
// bottom bar's upper face lies under the top bar.
const glm::vec3 BracketCentre(420.0f, 300.0f, 130.0f);

ObjectMesh Bracket()
{
  ObjectMesh mesh = MakeBracket(120.0f, 100.0f, 20.0f, 120.0f);
  mesh.Diffuse = glm::vec3(0.7f);
  return mesh;
}

glm::mat4 Placement(const LightField& field)
{
  return WorldToUnitSphere(field) * glm::translate(glm::mat4(1.0f), BracketCentre);
}

struct Measured
{
  double All = 0.0;    // mean relative error over the reference points
  double Inside = 0.0; // over the points that face part of the bracket
  double MicrosecondsPerPoint = 0.0;
  std::size_t Facing = 0, Blocked = 0, Points = 0;
};

// The error of one gather against the reference, over all points and over the points of the
// slot (those that face part of the bracket: the ones the occlusion changes).
Measured Measure(const LightField& field, const GatherSettings& settings,
  const ObjectReference& reference, const std::vector<std::uint8_t>& inside)
{
  ObjectGatherer gatherer(field);
  const auto start = std::chrono::steady_clock::now();
  const ShadedObject& shaded = gatherer.Gather(Bracket(), Placement(field), settings);
  Measured m;
  m.MicrosecondsPerPoint = 1e6 *
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count() /
    static_cast<double>(shaded.GatheredPoints);
  m.All = MeanRelativeError(shaded.Radiance, reference);
  ObjectReference slot;
  for (std::size_t q = 0; q < reference.Points.size(); ++q)
  {
    if (inside[reference.Points[q]])
    {
      slot.Points.push_back(reference.Points[q]);
      slot.Radiance.push_back(reference.Radiance[q]);
    }
  }
  m.Inside = MeanRelativeError(shaded.Radiance, slot);
  m.Facing = shaded.SelfFacingPoints;
  m.Blocked = shaded.SelfBlockedRays;
  m.Points = shaded.GatheredPoints;
  return m;
}
} // namespace

TEST(ObjectSelfOcclusion, RaysHitTheOverhangAndConvexPointsCastNone)
{
  const ObjectMesh bracket = Bracket();
  ObjectSelfOcclusion self;
  self.Prepare(bracket, bracket.Positions, 1);
  self.Place(glm::mat4(1.0f));
  // The bottom bar's upper face (y = -30) under the top bar's underside (y = 30).
  const glm::vec3 p(12.0f, -30.0f, 5.0f), up(0.0f, 1.0f, 0.0f);
  EXPECT_TRUE(self.SeesItself(p, up));
  const glm::vec3 directions[3] = { up, glm::normalize(glm::vec3(1.0f, 1.0f, 0.0f)),
    glm::normalize(glm::vec3(-1.0f, 0.2f, 0.0f)) };
  const glm::vec3 origins[3] = { p, p, p }, normals[3] = { up, up, up };
  ObjectSelfHit hits[3];
  self.Trace16(origins, normals, directions, 3, hits);
  ASSERT_NE(hits[0].Triangle, ObjectSelfHit::None); // the top bar's underside
  const glm::uvec3 t = bracket.Triangles[hits[0].Triangle];
  EXPECT_NEAR(bracket.Positions[t.x].y, 30.0f, 1e-4f);
  EXPECT_EQ(bracket.Normals[t.x], -up);
  EXPECT_EQ(hits[1].Triangle, ObjectSelfHit::None); // out through the opening
  EXPECT_NE(hits[2].Triangle, ObjectSelfHit::None); // the back bar
  // Outer faces see nothing of the bracket (nothing above their planes).
  EXPECT_FALSE(self.SeesItself(glm::vec3(0.0f, 50.0f, 0.0f), up));
  EXPECT_FALSE(self.SeesItself(glm::vec3(-60.0f, 0.0f, 0.0f), glm::vec3(-1.0f, 0.0f, 0.0f)));
  // A mirroring placement keeps the front faces.
  self.Place(glm::scale(glm::mat4(1.0f), glm::vec3(-1.0f, 1.0f, 1.0f)));
  const glm::vec3 mirrored(-12.0f, -30.0f, 5.0f);
  const glm::vec3 mirroredOrigins[1] = { mirrored };
  self.Trace16(mirroredOrigins, normals, directions, 1, hits);
  EXPECT_NE(hits[0].Triangle, ObjectSelfHit::None);
  EXPECT_TRUE(hits[0].Front);
  // A ray into the back bar from the inner edge meets its inside.
  self.Place(glm::mat4(1.0f));
  const glm::vec3 edge[1] = { glm::vec3(-40.0f, -30.0f, 5.0f) };
  const glm::vec3 intoBar[1] = { glm::normalize(glm::vec3(-1.0f, 1.0f, 0.0f)) };
  self.Trace16(edge, normals, intoBar, 1, hits);
  EXPECT_NE(hits[0].Triangle, ObjectSelfHit::None);
  EXPECT_FALSE(hits[0].Front);
}

TEST(ObjectSelfOcclusion, ConvexObjectsCastNoRaysAndKeepTheirValues)
{
  const LightField& field = walkthroughtest::PlainCornellField(513);
  for (int which = 0; which < 2; ++which)
  {
    ObjectMesh object = which == 0 ? MakeSphere(40.0f, 8, 16) : MakeCube(80.0f);
    GatherSettings on, off;
    on.Subdivision = off.Subdivision = 1;
    off.ObjectOcclusion = false;
    ObjectGatherer a(field), b(field);
    const ShadedObject& with = a.Gather(object, Placement(field), on);
    const ShadedObject& without = b.Gather(object, Placement(field), off);
    EXPECT_EQ(with.SelfFacingPoints, 0u) << (which == 0 ? "sphere" : "cube");
    EXPECT_EQ(with.SelfBlockedRays, 0u);
    ASSERT_EQ(with.Radiance.size(), without.Radiance.size());
    for (std::size_t i = 0; i < with.Radiance.size(); ++i)
    {
      EXPECT_EQ(with.Radiance[i], without.Radiance[i]);
    }
  }
}

TEST(ObjectSelfOcclusion, ConcaveBracketAgainstThePathTracer)
{
  const LightField& field = walkthroughtest::PlainCornellField(2049);
  GatherSettings settings;
  settings.Subdivision = 2;
  settings.Threads = 1; // cost per point on one core (figures only, nothing timed is asserted)
  // The reference: the path tracer with the bracket in the box (it shadows itself and the scene).
  ObjectGatherer meshOnly(field);
  const ShadedObject& mesh = meshOnly.Gather(Bracket(), Placement(field), settings);
  ObjectReferenceSettings traced;
  traced.Samples = 4096;
  traced.MaxPoints = 160;
  const ObjectReference reference = TraceObjectReference(field, mesh.Mesh, traced);
  ObjectSelfOcclusion self;
  self.Prepare(mesh.Mesh, mesh.Mesh.Positions, 1);
  self.Place(glm::mat4(1.0f));
  std::vector<std::uint8_t> inside(mesh.Mesh.Positions.size(), 0);
  std::size_t insideReference = 0;
  for (std::size_t i = 0; i < inside.size(); ++i)
  {
    inside[i] = self.SeesItself(mesh.Mesh.Positions[i], mesh.Mesh.Normals[i]) ? 1 : 0;
  }
  for (const std::uint32_t i : reference.Points)
  {
    insideReference += inside[i];
  }

  GatherSettings off = settings;
  off.ObjectOcclusion = false;
  const Measured without = Measure(field, off, reference, inside);
  Measured with[3];
  for (int iterations = 0; iterations < 3; ++iterations)
  {
    GatherSettings on = settings;
    on.ObjectInterreflections = iterations;
    with[iterations] = Measure(field, on, reference, inside);
  }
  std::printf("[ figures  ] bracket, 2049 directions, subdivision 2: %zu points gathered, %zu "
              "face the bracket; %zu reference points (%zu of them facing it)\n",
    with[1].Points, with[1].Facing, reference.Points.size(), insideReference);
  std::printf("[ figures  ] mean relative error, all / facing points: no self-occlusion "
              "%.4f / %.4f; occlusion with 0 / 1 / 2 inter-reflection iterations %.4f / %.4f, "
              "%.4f / %.4f, %.4f / %.4f\n",
    without.All, without.Inside, with[0].All, with[0].Inside, with[1].All, with[1].Inside,
    with[2].All, with[2].Inside);
  std::printf("[ figures  ] one thread, us per gathered point: no self-occlusion %.1f, with it "
              "(2 iterations) %.1f; %zu rays blocked by the bracket\n",
    without.MicrosecondsPerPoint, with[2].MicrosecondsPerPoint, with[2].Blocked);
  EXPECT_GT(with[1].Facing, 0u);
  EXPECT_GT(insideReference, 10u);
  // With the object's own occlusion and two bounces on itself (the default) the slot is within
  // the bound; the field alone lights the slot through the top bar and exceeds it (the negative
  // test), and so does the occlusion without the inter-reflection.
  constexpr double bound = 0.20;
  EXPECT_LT(with[2].Inside, bound);
  EXPECT_GT(without.Inside, bound);
  EXPECT_GT(with[0].Inside, bound);
  EXPECT_LT(with[2].All, 0.5 * without.All);
  // Its inter-reflection matters: the slot's walls light each other.
  EXPECT_LT(with[1].Inside, with[0].Inside);
  EXPECT_LE(with[2].Inside, with[1].Inside);
}
