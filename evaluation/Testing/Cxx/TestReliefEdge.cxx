// SPDX-License-Identifier: BSD-3-Clause
// The relief's edge rule against the dense displaced mesh (DisplaceSurface, the path tracer's
// reference): a relief recessed into a wall is closed at its texture rectangle's border by side
// walls, so a view ray that reaches the border below the surface meets the wall there, and a
// shadow ray that does is blocked. The walled height field (HeightField::Edge::Walled) must hit
// what a brute-force ray / triangle intersection of the mesh hits; the clamp-to-edge field, which
// continues a slot along the border past it, is the negative case.
#include "HeightFieldTracer.h"
#include "ReliefShading.h"
#include "SurfaceRelief.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <optional>
#include <vector>

namespace
{
using mesolight::DepthMap;
using mesolight::HeightField;
using mesolight::ReliefFrame;

// A 32 x 32 map: a 3-texel slot at depth 1 along the top edge (v = 1) over bricks at depth 0.05,
// as the procedural brick map of scripts/bench-vlf-relief.sh has one.
constexpr int Size = 32;
constexpr double Scale = 0.2; // world depth of depth 1 on the unit square
std::vector<float> SlotDepths()
{
  std::vector<float> depth;
  for (int j = 0; j < Size; ++j)
  {
    for (int i = 0; i < Size; ++i)
    {
      depth.push_back(j >= Size - 3 ? 1.0f : 0.05f);
    }
  }
  return depth;
}

// The unit square in z = 0 facing +z: the plane rule gives U = +x, V = +y.
struct Mesh
{
  mesolight::TriangleScene Scene;
  ReliefFrame Frame;
};
Mesh DenseMesh()
{
  mesolight::TriangleScene scene;
  scene.AddPolygon(
    { { 0.0f, 0.0f, 0.0f }, { 1.0f, 0.0f, 0.0f }, { 1.0f, 1.0f, 0.0f }, { 0.0f, 1.0f, 0.0f } },
    scene.AddMaterial({}), scene.AddSurface("wall"));
  DepthMap map;
  map.Width = Size;
  map.Height = Size;
  map.Depth = SlotDepths();
  mesolight::SurfaceReliefSettings settings;
  settings.DepthScale = static_cast<float>(Scale);
  const mesolight::SurfaceReliefResult relief =
    mesolight::DisplaceSurface(scene, "wall", map, settings);
  Mesh mesh{ relief.Scene, ReliefFrame() };
  mesh.Frame.Origin = glm::dvec3(relief.Plane.Origin);
  mesh.Frame.AxisU = glm::dvec3(relief.Plane.AxisU);
  mesh.Frame.AxisV = glm::dvec3(relief.Plane.AxisV);
  mesh.Frame.Normal = glm::dvec3(relief.Plane.Normal);
  mesh.Frame.DepthScale = Scale;
  return mesh;
}

struct MeshHit
{
  double T;
  glm::dvec3 Normal; // unit, facing the ray
};

// The first triangle of the mesh along the ray, t > tMin (Moeller and Trumbore, "Fast, minimum
// storage ray-triangle intersection"), in double precision over every triangle.
std::optional<MeshHit> FirstMeshHit(const mesolight::TriangleScene& scene, const glm::dvec3& origin,
  const glm::dvec3& dir, double tMin = 1e-9)
{
  std::optional<MeshHit> best;
  for (std::size_t k = 0; k < scene.TriangleCount(); ++k)
  {
    const glm::dvec3 a(scene.Vertex(k, 0)), b(scene.Vertex(k, 1)), c(scene.Vertex(k, 2));
    const glm::dvec3 e1 = b - a, e2 = c - a;
    const glm::dvec3 p = glm::cross(dir, e2);
    const double det = glm::dot(e1, p);
    if (std::abs(det) < 1e-18)
    {
      continue;
    }
    const glm::dvec3 s = origin - a;
    const double bu = glm::dot(s, p) / det;
    const glm::dvec3 q = glm::cross(s, e1);
    const double bv = glm::dot(dir, q) / det;
    const double t = glm::dot(e2, q) / det;
    const double slack = 1e-9;
    if (bu < -slack || bv < -slack || bu + bv > 1.0 + slack || !(t > tMin))
    {
      continue;
    }
    if (!best || t < best->T)
    {
      glm::dvec3 n = glm::normalize(glm::cross(e1, e2));
      best = MeshHit{ t, glm::dot(n, dir) > 0.0 ? -n : n };
    }
  }
  return best;
}

// View rays entering the slot near the top edge and going up into the wall: where each meets the
// relief, in world coordinates, by the height field with the given edge rule (via ShadeReliefRay,
// the CPU renderer's own path) and by the mesh.
struct Comparison
{
  int Rays = 0;
  int WallHits = 0;   // rays whose mesh hit is a side wall (its normal in the wall's plane)
  int Mismatches = 0; // hits farther apart than 1e-4 (world; the square is 1 wide)
  int NormalMismatches = 0;
  double Worst = 0.0;
};

Comparison CompareViewRays(const Mesh& mesh, HeightField::Edge edge)
{
  const HeightField hf(Size, Size, SlotDepths(), edge);
  mesolight::ReliefLighting lighting;
  lighting.OcclusionDirections = 0;
  Comparison c;
  for (double u : { 0.13, 0.5, 0.81 })
  {
    for (double v : { 0.935, 0.955, 0.975, 0.99 })
    {
      for (double rise : { 0.15, 0.4, 1.0, 2.5 })
      {
        for (double across : { -0.3, 0.0, 0.45 })
        {
          const glm::dvec3 dir = glm::normalize(glm::dvec3(across, rise, -1.0));
          const glm::dvec3 origin = mesh.Frame.Point(u, v, 0.0) - 2.0 * dir;
          const std::optional<MeshHit> truth = FirstMeshHit(mesh.Scene, origin, dir);
          const std::optional<mesolight::ReliefShade> shade =
            mesolight::ShadeReliefRay(hf, mesh.Frame, lighting, origin, dir);
          ++c.Rays;
          if (!truth || !shade)
          {
            ++c.Mismatches;
            continue;
          }
          const bool wall = std::abs(truth->Normal.z) < 1e-6;
          c.WallHits += wall ? 1 : 0;
          const double apart = glm::length(origin + truth->T * dir - shade->Point);
          c.Worst = std::max(c.Worst, apart);
          c.Mismatches += apart > 1e-4 ? 1 : 0;
          c.NormalMismatches += glm::dot(truth->Normal, shade->Normal) < 0.9999 ? 1 : 0;
        }
      }
    }
  }
  return c;
}

TEST(ReliefEdge, ViewRaysLeavingThroughTheBorderMeetTheDenseMeshSideWall)
{
  const Mesh mesh = DenseMesh();
  const Comparison walled = CompareViewRays(mesh, HeightField::Edge::Walled);
  const Comparison clamped = CompareViewRays(mesh, HeightField::Edge::Clamped);
  std::cout << "walled: " << walled.Mismatches << " of " << walled.Rays
            << " rays off the mesh's hit (worst " << walled.Worst << "), " << walled.WallHits
            << " on its side wall, " << walled.NormalMismatches
            << " normals off; clamped (negative): " << clamped.Mismatches << " off (worst "
            << clamped.Worst << ")" << std::endl;
  // The rays exercise the wall: a good share of them meet it on the mesh.
  EXPECT_GE(walled.WallHits, walled.Rays / 4);
  EXPECT_EQ(walled.Mismatches, 0);
  EXPECT_LT(walled.Worst, 1e-4);
  EXPECT_EQ(walled.NormalMismatches, 0); // the side wall's normal, not the slot bottom's
  // The clamp continues the slot past the border: every ray that meets the wall goes on.
  EXPECT_GE(clamped.Mismatches, walled.WallHits);
}

TEST(ReliefEdge, ShadowRaysThroughTheBorderAreBlockedAsByTheDenseMesh)
{
  const Mesh mesh = DenseMesh();
  const HeightField walled(Size, Size, SlotDepths(), HeightField::Edge::Walled);
  const HeightField clamped(Size, Size, SlotDepths(), HeightField::Edge::Clamped);
  int rays = 0, blocked = 0, walledOff = 0, clampedOff = 0;
  for (double u : { 0.2, 0.6 })
  {
    for (double v : { 0.94, 0.96, 0.98 })
    {
      for (double elevation : { 0.05, 0.3, 0.8, 1.2, 1.45, 1.52 }) // radians above the wall's plane
      {
        // Up the wall (+v) and out of it, as the Cornell box's lamp is from the back wall's top.
        const glm::dvec3 l(0.0, std::cos(elevation), std::sin(elevation));
        const glm::dvec3 point(u, v, walled.DepthAt(u, v));
        const glm::dvec3 world = mesh.Frame.Point(point.x, point.y, point.z);
        const bool meshLit = !FirstMeshHit(mesh.Scene, world, l, 1e-6);
        const glm::dvec3 toLight = mesh.Frame.ToTexture(l);
        ++rays;
        blocked += meshLit ? 0 : 1;
        walledOff += mesolight::Visible(walled, point, toLight) != meshLit ? 1 : 0;
        clampedOff += mesolight::Visible(clamped, point, toLight) != meshLit ? 1 : 0;
      }
    }
  }
  std::cout << rays << " shadow rays, " << blocked << " blocked on the mesh; walled off on "
            << walledOff << ", clamped (negative) on " << clampedOff << std::endl;
  EXPECT_GT(blocked, rays / 4);
  EXPECT_LT(blocked, rays); // some pass over the border above the surface
  EXPECT_EQ(walledOff, 0);
  EXPECT_GE(clampedOff, rays / 4);
}

TEST(ReliefEdge, WalledFieldIsTheSurfaceInsideAndTheWallOutside)
{
  const HeightField hf(Size, Size, SlotDepths(), HeightField::Edge::Walled);
  EXPECT_DOUBLE_EQ(hf.DepthAt(0.5, 0.999), 1.0);
  EXPECT_DOUBLE_EQ(hf.DepthAt(0.5, 1.0), 1.0); // the border belongs to the relief
  EXPECT_DOUBLE_EQ(hf.DepthAt(0.5, 1.001), 0.0);
  EXPECT_DOUBLE_EQ(hf.DepthAt(-0.001, 0.5), 0.0);
  // Leaving through v = 1 at depth 0.5: the wall at the border, facing -v.
  const std::optional<mesolight::RayHit> hit =
    mesolight::IntersectFirst(hf, { 0.5, 0.99, 0.4 }, { 0.0, 0.1, 1.0 }, 10.0);
  ASSERT_TRUE(hit);
  EXPECT_NEAR(hit->point.y, 1.0, 1e-12);
  EXPECT_NEAR(hit->point.z, 0.5, 1e-12);
  EXPECT_EQ(hit->wall, glm::dvec2(0.0, -1.0));
  // Above the surface outside the rectangle the ray meets the plane d = 0.
  const std::optional<mesolight::RayHit> outside =
    mesolight::IntersectFirst(hf, { 1.5, 0.5, -0.5 }, { 0.0, 0.0, 1.0 }, 10.0);
  ASSERT_TRUE(outside);
  EXPECT_NEAR(outside->t, 0.5, 1e-12);
  EXPECT_EQ(outside->wall, glm::dvec2(0.0));
  // The clamped field continues the slot: the same ray goes on to depth 1.
  const HeightField open(Size, Size, SlotDepths());
  const std::optional<mesolight::RayHit> on =
    mesolight::IntersectFirst(open, { 0.5, 0.99, 0.4 }, { 0.0, 0.1, 1.0 }, 10.0);
  ASSERT_TRUE(on);
  EXPECT_NEAR(on->point.z, 1.0, 1e-12);
}
} // namespace
