// SPDX-License-Identifier: BSD-3-Clause
// Tests of the light field structure (Wither 2005 §2.4.1): surface grouping, every line's crossings
// against brute-force intersection with all triangles, the memory estimate within 0.97-1.3 times
// what a propagating field holds (a small-box floor, a mirror; the negative: the earlier
// area + perimeter bound is far above it), refusals (budget, bad settings, no emitter), lookups on
// the tile lists.
#include "LightField.h"
#include "VLFTestScenes.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <random>
#include <string>

namespace
{
using namespace mesolight;
using namespace mesolight::vlf;

LightFieldSettings Small()
{
  LightFieldSettings s;
  s.Directions = 33; // n = 4
  s.RaysPerSide = 16;
  s.TilesPerSide = 4;
  return s;
}

// Möller-Trumbore, double precision: the independent reference for the crossings.
bool IntersectTriangle(const glm::dvec3& o, const glm::dvec3& d, const glm::dvec3& a,
  const glm::dvec3& b, const glm::dvec3& c, double& t)
{
  const glm::dvec3 e1 = b - a, e2 = c - a;
  const glm::dvec3 p = glm::cross(d, e2);
  const double det = glm::dot(e1, p);
  if (std::abs(det) < 1e-14)
  {
    return false;
  }
  const glm::dvec3 s = o - a;
  const double u = glm::dot(s, p) / det;
  const glm::dvec3 q = glm::cross(s, e1);
  const double v = glm::dot(d, q) / det;
  t = glm::dot(e2, q) / det;
  return u >= 0.0 && v >= 0.0 && u + v <= 1.0;
}

std::string MessageOf(const std::function<void()>& action)
{
  try
  {
    action();
  }
  catch (const std::exception& e)
  {
    return e.what();
  }
  return "";
}

TEST(VLFLightField, GroupsPlanarSurfaces)
{
  const TriangleScene cube = vlftest::MakeFurnaceCube(0.5f, 1.0f);
  std::vector<std::uint32_t> triangleSurface;
  const std::vector<Surface> surfaces = GroupSurfaces(cube, 0.1f, triangleSurface);
  ASSERT_EQ(surfaces.size(), 6u);
  for (const Surface& s : surfaces)
  {
    EXPECT_EQ(s.Triangles.size(), 2u);
    EXPECT_NEAR(s.Area, 4.0, 1e-5);
    // The texture rectangle fits the square face exactly: 2 / 0.1 = 20 texels.
    EXPECT_EQ(s.TextureWidth, 20);
    EXPECT_EQ(s.TextureHeight, 20);
    EXPECT_NEAR(s.TexelU * s.TextureWidth, 2.0f, 1e-5f);
    // Inward normals: the centre is in front of every face.
    EXPECT_GT(-s.Offset, 0.0f);
    // Texel centres lie on the plane.
    EXPECT_NEAR(glm::dot(s.Normal, s.TexelCentre(3, 7)), s.Offset, 1e-5f);
  }
}

TEST(VLFLightField, CrossingsMatchBruteForce)
{
  const TriangleScene cornell = MakeCornellBox();
  LightFieldSettings settings = Small();
  const std::unique_ptr<LightField> field = LightField::Build(cornell, settings);
  const TriangleScene& scene = field->Scene();
  const int n = settings.RaysPerSide;
  const float h = settings.CellSize();
  std::size_t lines = 0, crossings = 0;
  std::vector<Crossing> found;
  for (std::size_t k = 0; k < field->SubfieldCount(); k += 3)
  {
    const Subfield& f = field->GetSubfield(k);
    for (int j = 0; j < n; ++j)
    {
      for (int i = 0; i < n; ++i)
      {
        const float a = -1.0f + (i + 0.5f) * h, b = -1.0f + (j + 0.5f) * h;
        const glm::dvec3 origin =
          glm::dvec3(a * f.AxisU + b * f.AxisV) - 1.01 * glm::dvec3(f.Direction);
        // Brute force: every triangle; one crossing per surface (the nearest of its triangles).
        std::vector<std::pair<double, std::uint32_t>> expected;
        for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
        {
          double depth;
          if (IntersectTriangle(origin, glm::dvec3(f.Direction), glm::dvec3(scene.Vertex(t, 0)),
                glm::dvec3(scene.Vertex(t, 1)), glm::dvec3(scene.Vertex(t, 2)), depth) &&
            depth > 0.0)
          {
            const std::uint32_t s = field->SurfaceOfTriangle(t);
            auto same = std::find_if(expected.begin(), expected.end(),
              [&](const std::pair<double, std::uint32_t>& e) { return e.second == s; });
            if (same == expected.end())
            {
              expected.emplace_back(depth, s);
            }
          }
        }
        std::sort(expected.begin(), expected.end());
        field->LineCrossings(k, i, j, found);
        lines += found.empty() ? 0 : 1;
        crossings += found.size();
        ASSERT_EQ(found.size(), expected.size()) << "subfield " << k << " line " << i << "," << j;
        for (std::size_t q = 0; q < found.size(); ++q)
        {
          EXPECT_EQ(found[q].Surface, expected[q].second);
          EXPECT_NEAR(found[q].Depth, expected[q].first, 1e-4);
          EXPECT_EQ(
            field->FindCell(k, i, j, found[q].Surface), static_cast<std::int64_t>(found[q].Cell));
        }
      }
    }
  }
  EXPECT_GT(lines, 0u);
  EXPECT_GE(crossings, 2 * lines); // a line through the box crosses at least two surfaces
}

// A floor of 12 x 12 small boxes (a cell or two wide at 32 lines per side) under a light: faces
// whose projections are mostly perimeter, the case an area + perimeter bound overcounts.
TriangleScene BoxFloor()
{
  TriangleScene scene;
  SceneMaterial floor, box, lamp;
  floor.Diffuse = glm::vec3(0.6f);
  box.Diffuse = glm::vec3(0.7f, 0.5f, 0.3f);
  lamp.Diffuse = glm::vec3(0.5f);
  lamp.Emission = glm::vec3(5.0f);
  const std::uint32_t f = scene.AddMaterial(floor), b = scene.AddMaterial(box),
                      l = scene.AddMaterial(lamp);
  scene.AddPolygon({ { -3, 0, -3 }, { -3, 0, 3 }, { 3, 0, 3 }, { 3, 0, -3 } }, f);
  for (int i = 0; i < 12; ++i)
  {
    for (int j = 0; j < 12; ++j)
    {
      const float side = 0.05f + 0.01f * static_cast<float>((i * 7 + j * 3) % 10);
      // 1 cm above the floor: a bottom face coincident with it would lose crossings to the
      // tracing's step past each hit, which the count from the projections does not model.
      const glm::vec3 c(
        -2.75f + 0.5f * static_cast<float>(i), 0.01f, -2.75f + 0.5f * static_cast<float>(j));
      vlftest::AddBox(
        scene, c - glm::vec3(side, 0.0f, side), c + glm::vec3(side, 1.5f * side, side), b, false);
    }
  }
  scene.AddPolygon(
    { { -0.5f, 2, -0.5f }, { 0.5f, 2, -0.5f }, { 0.5f, 2, 0.5f }, { -0.5f, 2, 0.5f } }, l);
  return scene;
}

// What the field holds while it propagates: its structure plus one texture of flux per worker
// block (Propagation.cxx).
std::uint64_t PeakBytes(const LightField& field)
{
  return field.AllocatedBytes() +
    DefaultBlockCount(field.SubfieldCount()) * field.TexelCount() * sizeof(glm::vec3);
}

// The earlier estimate's crossing term: per direction and triangle, A + P + 1 lattice points
// (area and perimeter of the projection in cells), a float depth each.
std::uint64_t AreaPerimeterCrossingBytes(const LightField& field)
{
  const float h = field.Settings().CellSize();
  const TriangleScene& scene = field.Scene();
  double bound = 0.0;
  for (std::size_t k = 0; k < field.SubfieldCount(); ++k)
  {
    const glm::vec3 d = field.GetSubfield(k).Direction;
    for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
    {
      glm::vec3 p[3];
      for (int c = 0; c < 3; ++c)
      {
        p[c] = scene.Vertex(t, c) - glm::dot(scene.Vertex(t, c), d) * d; // projected
      }
      const double area = 0.5 * std::abs(glm::dot(glm::cross(p[1] - p[0], p[2] - p[0]), d));
      const double perimeter =
        glm::length(p[1] - p[0]) + glm::length(p[2] - p[1]) + glm::length(p[0] - p[2]);
      bound += area / (h * h) + perimeter / h + 1.0;
    }
  }
  return static_cast<std::uint64_t>(bound) * sizeof(float);
}

TEST(VLFLightField, EstimateMatchesTheAllocation)
{
  TriangleScene mirror = MakeCornellBox();
  mirror.Materials[0].Diffuse *= 0.5f;
  mirror.Materials[0].Specular = glm::vec3(0.4f);
  const struct
  {
    const char* Name;
    TriangleScene Scene;
    std::size_t Directions;
    int Rays;
    bool Negative;
  } cases[] = { { "cornell", MakeCornellBox(), 129, 32, false },
    { "mirror", mirror, 129, 32, false }, { "box floor", BoxFloor(), 129, 32, true },
    { "box floor", BoxFloor(), 33, 64, false } };
  for (const auto& c : cases)
  {
    LightFieldSettings settings = Small();
    settings.Directions = c.Directions;
    settings.RaysPerSide = c.Rays;
    settings.TilesPerSide = c.Rays / 8;
    const MemoryEstimate estimate = EstimateMemory(c.Scene, settings);
    const std::unique_ptr<LightField> field = LightField::Build(c.Scene, settings);
    const double peak = static_cast<double>(PeakBytes(*field));
    const double ratio = static_cast<double>(estimate.TotalBytes) / peak;
    std::printf("[ estimate ] %s %zu x %d: %s; allocated %s, peak %s: %.3f\n", c.Name, c.Directions,
      c.Rays, estimate.Describe().c_str(), FormatBytes(field->AllocatedBytes()).c_str(),
      FormatBytes(static_cast<std::uint64_t>(peak)).c_str(), ratio);
    EXPECT_EQ(field->Estimate().TotalBytes, estimate.TotalBytes);
    EXPECT_GE(ratio, 0.97) << c.Name;
    EXPECT_LE(ratio, 1.3) << c.Name;
    // The crossings themselves: each line's crossings counted by the field.
    std::uint64_t slots = 0;
    for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
    {
      slots += field->GetSubfield(k).Cells.Slots();
    }
    EXPECT_NEAR(static_cast<double>(estimate.MapCells), static_cast<double>(slots),
      0.01 * static_cast<double>(slots))
      << c.Name;
    if (c.Negative)
    {
      // Negative: the area + perimeter bound alone is far above the allocation.
      EXPECT_GT(static_cast<double>(AreaPerimeterCrossingBytes(*field)), 1.3 * peak);
    }
  }
}

TEST(VLFLightField, RefusesOverBudgetBeforeAllocating)
{
  const TriangleScene cornell = MakeCornellBox();
  LightFieldSettings settings = Small();
  settings.MemoryBudget = 1024; // 1 KiB
  const std::string message = MessageOf([&] { LightField::Build(cornell, settings); });
  EXPECT_NE(message.find("memory budget of 1 KiB"), std::string::npos) << message;
  EXPECT_THROW(LightField::Build(cornell, settings), MemoryBudgetError);
}

// A field far over its budget is estimated on 1 in 64 of its directions (and refused on that):
// the sample is within a few per cent of the exact count, and a field within the budget gets
// the exact count.
TEST(VLFLightField, FarOverBudgetIsEstimatedOnASampleOfDirections)
{
  const TriangleScene cornell = MakeCornellBox();
  LightFieldSettings settings;
  settings.Directions = 2049;
  settings.RaysPerSide = 64;
  settings.TilesPerSide = 4;
  const MemoryEstimate exact = EstimateMemory(cornell, settings);
  EXPECT_EQ(exact.SampleStride, 1u) << exact.Describe();
  settings.MemoryBudget = exact.TotalBytes / 4;
  const MemoryEstimate sampled = EstimateMemory(cornell, settings);
  EXPECT_EQ(sampled.SampleStride, 64u) << sampled.Describe();
  EXPECT_NEAR(static_cast<double>(sampled.TotalBytes), static_cast<double>(exact.TotalBytes),
    0.05 * static_cast<double>(exact.TotalBytes));
  EXPECT_NE(sampled.Describe().find("about"), std::string::npos) << sampled.Describe();
  const std::string message = MessageOf([&] { LightField::Build(cornell, settings); });
  EXPECT_NE(message.find("counted on 1 in 64 directions"), std::string::npos) << message;
  // Over the budget but not 1.5 times over it: the exact count decides.
  settings.MemoryBudget = exact.TotalBytes * 9 / 10;
  const MemoryEstimate near = EstimateMemory(cornell, settings);
  EXPECT_EQ(near.SampleStride, 1u);
  EXPECT_EQ(near.TotalBytes, exact.TotalBytes);
  EXPECT_THROW(LightField::Build(cornell, settings), MemoryBudgetError);
}

TEST(VLFLightField, RejectsBadSettingsAndScenes)
{
  const TriangleScene cornell = MakeCornellBox();
  LightFieldSettings s = Small();
  s.RaysPerSide = 30;
  EXPECT_NE(
    MessageOf([&] { LightField::Build(cornell, s); }).find("not a multiple"), std::string::npos);
  s = Small();
  s.Directions = 500;
  EXPECT_THROW(LightField::Build(cornell, s), std::invalid_argument);
  s = Small();
  s.RaysPerSide = 0;
  EXPECT_THROW(LightField::Build(cornell, s), std::invalid_argument);
  s = Small();
  s.TexelSize = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(LightField::Build(cornell, s), std::invalid_argument);

  TriangleScene dark = cornell;
  for (SceneMaterial& m : dark.Materials)
  {
    m.Emission = glm::vec3(0.0f);
  }
  EXPECT_NE(
    MessageOf([&] { LightField::Build(dark, Small()); }).find("emitter"), std::string::npos);

  TriangleScene bright = cornell;
  bright.Materials[0].Specular = glm::vec3(0.5f);
  EXPECT_NE(MessageOf([&] { LightField::Build(bright, Small()); }).find("reflects more light"),
    std::string::npos);

  TriangleScene broken = cornell;
  broken.Positions[0].x = std::numeric_limits<float>::quiet_NaN();
  EXPECT_THROW(LightField::Build(broken, Small()), std::invalid_argument);
  EXPECT_THROW(LightField::Build(TriangleScene(), Small()), std::invalid_argument);
}

TEST(VLFLightField, DegenerateTrianglesAreIgnored)
{
  TriangleScene cube = vlftest::MakeFurnaceCube(0.5f, 1.0f);
  cube.Positions.push_back(glm::vec3(0.0f));
  cube.Positions.push_back(glm::vec3(0.0f));
  cube.Positions.push_back(glm::vec3(0.0f));
  const std::uint32_t first = static_cast<std::uint32_t>(cube.Positions.size() - 3);
  cube.Triangles.emplace_back(first, first + 1, first + 2);
  cube.MaterialIds.push_back(0);
  const std::unique_ptr<LightField> field = LightField::Build(cube, Small());
  EXPECT_EQ(field->Surfaces().size(), 6u);
  EXPECT_EQ(field->SurfaceOfTriangle(12), NoSurface);
}

TEST(VLFLightField, ProgressIsMonotoneDeterministicAndAbortStops)
{
  const TriangleScene cornell = MakeCornellBox();
  double last = -1.0;
  bool monotone = true;
  std::size_t calls = 0;
  const ProgressCallback progress = [&](double p)
  {
    ++calls;
    monotone = monotone && p >= last;
    last = p;
    return true;
  };
  const std::unique_ptr<LightField> first = LightField::Build(cornell, Small(), progress);
  EXPECT_GT(calls, 2u);
  EXPECT_TRUE(monotone);
  EXPECT_NEAR(last, 1.0, 1e-9);
  // Work split over threads by vtkSMPTools: the same structure every time.
  const std::unique_ptr<LightField> second = LightField::Build(cornell, Small());
  EXPECT_EQ(first->Capacity, second->Capacity);

  // The first report that answers false stops the build.
  std::size_t reports = 0;
  const ProgressCallback abortAtOnce = [&](double)
  {
    ++reports;
    return false;
  };
  EXPECT_THROW(LightField::Build(cornell, Small(), abortAtOnce), AbortedError);
  EXPECT_EQ(reports, 1u);
  const ProgressCallback abortLater = [](double p) { return p < 0.5; };
  EXPECT_THROW(LightField::Build(cornell, Small(), abortLater), AbortedError);
}

} // namespace
