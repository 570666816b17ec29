// SPDX-License-Identifier: BSD-3-Clause
// ObjectMesh: the generated objects are closed and face outward, normals follow a rotation and
// ignore a scale, bad meshes are named.
#include "ObjectMesh.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace mesolight::vlf;

namespace
{
// Every triangle faces away from the centre and the closed surface's enclosed volume
// (divergence theorem) matches the analytic one.
void ExpectClosedAndOutward(const ObjectMesh& mesh, double volume, double tolerance)
{
  double enclosed = 0.0;
  for (const glm::uvec3& t : mesh.Triangles)
  {
    const glm::vec3 a = mesh.Positions[t.x], b = mesh.Positions[t.y], c = mesh.Positions[t.z];
    const glm::vec3 n = glm::cross(b - a, c - a);
    EXPECT_GT(glm::dot(n, (a + b + c) / 3.0f), 0.0f);
    enclosed += glm::dot(a, glm::cross(b, c)) / 6.0;
  }
  EXPECT_NEAR(enclosed / volume, 1.0, tolerance);
  for (const glm::uvec3& t : mesh.Triangles) // points no triangle uses have no direction
  {
    for (int k = 0; k < 3; ++k)
    {
      EXPECT_GT(glm::dot(mesh.Normals[t[k]], mesh.Positions[t[k]]), 0.0f);
    }
  }
}
}

TEST(ObjectMesh, SphereAndCubeAreClosedAndFaceOutward)
{
  ExpectClosedAndOutward(MakeSphere(2.0f, 48, 96), 4.0 / 3.0 * M_PI * 8.0, 5e-3);
  ExpectClosedAndOutward(MakeCube(3.0f), 27.0, 1e-6);
  EXPECT_TRUE(MakeSphere(1.0f, 8, 16).Validate().empty());
  EXPECT_TRUE(MakeCube(1.0f).Validate().empty());
}

TEST(ObjectMesh, NormalsFollowRotationNotScale)
{
  const ObjectMesh cube = MakeCube(1.0f);
  glm::mat4 m = glm::translate(glm::mat4(1.0f), glm::vec3(5.0f, 0.0f, 0.0f));
  m = glm::rotate(m, 0.5f * float(M_PI), glm::vec3(0.0f, 0.0f, 1.0f));
  m = glm::scale(m, glm::vec3(4.0f, 1.0f, 1.0f));
  const ObjectMesh moved = TransformMesh(cube, m);
  for (std::size_t i = 0; i < cube.Positions.size(); ++i)
  {
    EXPECT_NEAR(glm::length(moved.Normals[i]), 1.0f, 1e-5f);
    // The face normal +X turns to +Y, +Y to -X; the non-uniform scale leaves them unit axes.
    const glm::vec3 expected(-cube.Normals[i].y, cube.Normals[i].x, cube.Normals[i].z);
    EXPECT_NEAR(glm::length(moved.Normals[i] - expected), 0.0f, 1e-5f);
  }
  EXPECT_NEAR(moved.Positions[0].x, 5.0f + 0.5f, 1e-5f);
}

TEST(ObjectMesh, BadMeshesAreNamed)
{
  ObjectMesh empty;
  EXPECT_NE(empty.Validate().find("no triangles"), std::string::npos);
  ObjectMesh outOfRange = MakeCube(1.0f);
  outOfRange.Triangles[0].x = 100;
  EXPECT_NE(outOfRange.Validate().find("refers to point 100"), std::string::npos);
  ObjectMesh nan = MakeCube(1.0f);
  nan.Positions[3].y = std::nanf("");
  EXPECT_NE(nan.Validate().find("finite"), std::string::npos);
  ObjectMesh flat;
  flat.Positions = { glm::vec3(0.0f), glm::vec3(1.0f, 0.0f, 0.0f), glm::vec3(2.0f, 0.0f, 0.0f) };
  flat.Triangles = { glm::uvec3(0, 1, 2) };
  EXPECT_EQ(flat.DegenerateTriangleCount(), 1u);
  EXPECT_NE(flat.Validate().find("zero area"), std::string::npos);
  flat.ComputeNormals(); // a degenerate triangle gives no direction: +Z, no NaN
  EXPECT_EQ(flat.Normals[0], glm::vec3(0.0f, 0.0f, 1.0f));
  ObjectMesh noNormals = MakeSphere(1.0f, 8, 16);
  noNormals.Normals.clear();
  noNormals.ComputeNormals();
  ExpectClosedAndOutward(noNormals, 4.0 / 3.0 * M_PI, 0.2);
}
