// SPDX-License-Identifier: BSD-3-Clause
// Light behind solids (Propagation.h, LightField::Receiver): a surface's lines that run into a
// solid standing on it are not part of what the surface shows.
//  - a floor under boxes must equal the same floor cut out under the boxes (which has no such
//    lines), per region: the visible floor, the walls, the ceiling, the boxes' tops; with closed
//    boxes (a bottom face coincident with the floor) and open ones (like the Cornell box's
//    blocks); counting the hidden lines in the capacity dilutes the visible floor and loses the
//    flux shot into the boxes, and fails;
//  - ribs against the walls of a corridor lit from one end, against the walls cut out behind
//    them;
//  - the energy balance closes with no back-face term: emitted = absorbed + escaped + unshot;
//  - the tolerance stop reaches the tolerance and stops there; a fixed count does not.
#include "EmbreeScene.h"
#include "PathTracer.h"
#include "Propagation.h"
#include "VLFTestScenes.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <string>
#include <vector>

namespace
{
using namespace mesolight;
using namespace mesolight::vlf;

// An axis-aligned rectangle on the plane z = const, x in [x0, x1], y in [y0, y1].
struct Footprint
{
  float X0, X1, Y0, Y1;
  bool Contains(float x, float y) const { return x > X0 && x < X1 && y > Y0 && y < Y1; }
};

// Adds the pieces [us[a], us[a+1]] x [vs[b], vs[b+1]] of a plane that lie outside every hole
// (in the plane's (u, v)), mapped to 3D by `at` with fronts toward `normal`: a floor or wall cut
// out where solids touch it, on the same bounding rectangle (so the same texels) as the whole.
template <typename At>
void AddCutPlane(TriangleScene& scene, std::vector<float> us, std::vector<float> vs, At at,
  const glm::vec3& normal, const std::vector<Footprint>& holes, std::uint32_t material)
{
  for (const Footprint& h : holes)
  {
    us.push_back(h.X0);
    us.push_back(h.X1);
    vs.push_back(h.Y0);
    vs.push_back(h.Y1);
  }
  std::sort(us.begin(), us.end());
  std::sort(vs.begin(), vs.end());
  us.erase(std::unique(us.begin(), us.end()), us.end());
  vs.erase(std::unique(vs.begin(), vs.end()), vs.end());
  for (std::size_t a = 0; a + 1 < us.size(); ++a)
  {
    for (std::size_t b = 0; b + 1 < vs.size(); ++b)
    {
      const float cu = 0.5f * (us[a] + us[a + 1]), cv = 0.5f * (vs[b] + vs[b + 1]);
      if (std::any_of(
            holes.begin(), holes.end(), [&](const Footprint& h) { return h.Contains(cu, cv); }))
      {
        continue;
      }
      std::vector<glm::vec3> quad = { at(us[a], vs[b]), at(us[a + 1], vs[b]),
        at(us[a + 1], vs[b + 1]), at(us[a], vs[b + 1]) };
      if (glm::dot(glm::cross(quad[1] - quad[0], quad[2] - quad[0]), normal) < 0.0f)
      {
        std::swap(quad[1], quad[3]);
      }
      scene.AddPolygon(quad, material);
    }
  }
}

// A box's faces with fronts outward, without its bottom unless `closed`.
void AddSolid(TriangleScene& scene, const glm::vec3& lower, const glm::vec3& upper,
  std::uint32_t material, bool closed)
{
  TriangleScene box;
  box.Materials = scene.Materials;
  vlftest::AddBox(box, lower, upper, material, false);
  for (std::size_t t = 0; t < box.TriangleCount(); ++t)
  {
    const glm::vec3 a = box.Vertex(t, 0), b = box.Vertex(t, 1), c = box.Vertex(t, 2);
    if (!closed && a.z == lower.z && b.z == lower.z && c.z == lower.z)
    {
      continue;
    }
    scene.AddPolygon({ a, b, c }, box.MaterialIds[t]);
  }
}

// A 4 x 4 x 2.5 room (fronts inward), a 1 x 1 emitter under the ceiling, 5 x 5 boxes of side
// 0.2 (about one texel at 32 rays) and height 0.3 on the floor.
struct BoxRoom
{
  TriangleScene Scene;
  std::vector<Footprint> Boxes;
};

BoxRoom MakeBoxRoom(bool cutFloor, bool closedBoxes)
{
  BoxRoom room;
  TriangleScene& scene = room.Scene;
  SceneMaterial white;
  white.Diffuse = glm::vec3(0.7f);
  SceneMaterial light;
  light.Diffuse = glm::vec3(0.0f);
  light.Emission = glm::vec3(10.0f);
  const std::uint32_t whiteId = scene.AddMaterial(white);
  const std::uint32_t lightId = scene.AddMaterial(light);
  for (int a = 0; a < 5; ++a)
  {
    for (int b = 0; b < 5; ++b)
    {
      const float x = -1.4f + 0.7f * static_cast<float>(a) + 0.013f * static_cast<float>(b);
      const float y = -1.4f + 0.7f * static_cast<float>(b) + 0.021f * static_cast<float>(a);
      room.Boxes.push_back({ x - 0.1f, x + 0.1f, y - 0.1f, y + 0.1f });
    }
  }
  // Walls and ceiling: the room box without its floor, fronts inward.
  TriangleScene shell;
  shell.Materials = scene.Materials;
  vlftest::AddBox(shell, glm::vec3(-2.0f, -2.0f, 0.0f), glm::vec3(2.0f, 2.0f, 2.5f), whiteId, true);
  for (std::size_t t = 0; t < shell.TriangleCount(); ++t)
  {
    const glm::vec3 a = shell.Vertex(t, 0), b = shell.Vertex(t, 1), c = shell.Vertex(t, 2);
    if (a.z == 0.0f && b.z == 0.0f && c.z == 0.0f)
    {
      continue;
    }
    scene.AddPolygon({ a, b, c }, whiteId);
  }
  AddCutPlane(
    scene, { -2.0f, 2.0f }, { -2.0f, 2.0f }, [](float u, float v) { return glm::vec3(u, v, 0.0f); },
    glm::vec3(0.0f, 0.0f, 1.0f), cutFloor ? room.Boxes : std::vector<Footprint>(), whiteId);
  scene.AddPolygon({ { -0.5f, -0.5f, 2.49f }, { -0.5f, 0.5f, 2.49f }, { 0.5f, 0.5f, 2.49f },
                     { 0.5f, -0.5f, 2.49f } },
    lightId);
  for (const Footprint& f : room.Boxes)
  {
    AddSolid(scene, glm::vec3(f.X0, f.Y0, 0.0f), glm::vec3(f.X1, f.Y1, 0.3f), whiteId, closedBoxes);
  }
  return room;
}

LightFieldSettings SmallSettings()
{
  LightFieldSettings settings;
  settings.Directions = 129;
  settings.RaysPerSide = 32;
  settings.TilesPerSide = 4;
  return settings;
}

// Mean diffuse radiance (channels summed) of the field at world points, each on the surface of
// the scene triangle nearest in plane (the caller gives points on the surfaces).
double MeanRadiance(
  const LightField& field, const std::vector<glm::vec3>& points, const glm::vec3& normal)
{
  double sum = 0.0;
  for (const glm::vec3& world : points)
  {
    const glm::vec3 unit = (world - field.NormalizationCentre()) * field.NormalizationScale();
    std::uint32_t surface = NoSurface;
    for (std::uint32_t s = 0; s < field.Surfaces().size(); ++s)
    {
      const Surface& candidate = field.Surfaces()[s];
      if (glm::dot(candidate.Normal, normal) > 0.99f &&
        std::abs(glm::dot(candidate.Normal, unit) - candidate.Offset) < 1e-4f &&
        field.MaterialOf(s).Emission.x == 0.0f)
      {
        surface = s;
      }
    }
    EXPECT_NE(surface, NoSurface);
    if (surface == NoSurface)
    {
      return 0.0;
    }
    const glm::vec3 l = field.SampleTexture(field.TotalDiffuse, surface, unit);
    sum += static_cast<double>(l.x + l.y + l.z);
  }
  return sum / static_cast<double>(points.size());
}

struct Region
{
  std::string Name;
  glm::vec3 Normal;
  std::vector<glm::vec3> Points;
};

// The regions of the box room both variants show: the floor outside the boxes, the walls, the
// ceiling around the emitter, the boxes' tops.
std::vector<Region> BoxRoomRegions(const std::vector<Footprint>& boxes)
{
  std::vector<Region> regions(4);
  regions[0] = { "visible floor", { 0.0f, 0.0f, 1.0f }, {} };
  regions[1] = { "wall x=-2", { 1.0f, 0.0f, 0.0f }, {} };
  regions[2] = { "ceiling", { 0.0f, 0.0f, -1.0f }, {} };
  regions[3] = { "box tops", { 0.0f, 0.0f, 1.0f }, {} };
  for (int a = 0; a < 80; ++a)
  {
    for (int b = 0; b < 80; ++b)
    {
      const float x = -1.975f + 0.05f * static_cast<float>(a);
      const float y = -1.975f + 0.05f * static_cast<float>(b);
      if (std::none_of(
            boxes.begin(), boxes.end(), [&](const Footprint& f) { return f.Contains(x, y); }))
      {
        regions[0].Points.push_back({ x, y, 0.0f });
      }
      if (std::abs(x) > 0.55f || std::abs(y) > 0.55f)
      {
        regions[2].Points.push_back({ x, y, 2.5f });
      }
      regions[1].Points.push_back({ -2.0f, x, 1.25f + 0.6f * y });
    }
  }
  for (const Footprint& f : boxes)
  {
    for (int a = 0; a < 4; ++a)
    {
      for (int b = 0; b < 4; ++b)
      {
        regions[3].Points.push_back({ f.X0 + (0.125f + 0.25f * static_cast<float>(a)) * 0.2f,
          f.Y0 + (0.125f + 0.25f * static_cast<float>(b)) * 0.2f, 0.3f });
      }
    }
  }
  return regions;
}

// Worst relative difference over the regions of `whole` against `cut`, printed per region.
double WorstRegionDifference(const char* what, const LightField& whole, const LightField& cut,
  const std::vector<Region>& regions)
{
  double worst = 0.0;
  for (const Region& r : regions)
  {
    const double a = MeanRadiance(whole, r.Points, r.Normal);
    const double b = MeanRadiance(cut, r.Points, r.Normal);
    const double difference = (a - b) / b;
    std::printf("[ blocked  ] %s, %s: %.5g against the cut scene's %.5g (%+.2f%%)\n", what,
      r.Name.c_str(), a, b, 100.0 * difference);
    worst = std::max(worst, std::abs(difference));
  }
  return worst;
}

TEST(VLFBlockedLines, FloorUnderBoxesMatchesTheFloorCutOutUnderThem)
{
  for (const bool closed : { true, false })
  {
    const BoxRoom whole = MakeBoxRoom(false, closed);
    const BoxRoom cut = MakeBoxRoom(true, closed);
    std::unique_ptr<LightField> a = LightField::Build(whole.Scene, SmallSettings());
    std::unique_ptr<LightField> b = LightField::Build(cut.Scene, SmallSettings());
    Propagate(*a, 3);
    Propagate(*b, 3);
    const double worst = WorstRegionDifference(
      closed ? "closed boxes" : "open-bottom boxes", *a, *b, BoxRoomRegions(whole.Boxes));
    // The same lines leave every visible point in both scenes: equal to float summation order.
    EXPECT_LT(worst, 2e-3) << (closed ? "closed boxes" : "open-bottom boxes");
  }
}

// A corridor along x (8 x 2 x 2.5, fronts inward) lit by an emitter before its far end wall
// (x = 4), with ribs: closed boxes 0.2 wide, 0.25 deep, floor to ceiling, against both side
// walls every metre. When `cut`, the floor, ceiling and side walls are cut out where the ribs
// touch them (the ribs keep all six faces, their contact faces then face the void).
TriangleScene MakeRibbedCorridor(bool cut, std::vector<Footprint>& ribs)
{
  TriangleScene scene;
  SceneMaterial white;
  white.Diffuse = glm::vec3(0.7f);
  SceneMaterial light;
  light.Diffuse = glm::vec3(0.0f);
  light.Emission = glm::vec3(20.0f);
  const std::uint32_t whiteId = scene.AddMaterial(white);
  const std::uint32_t lightId = scene.AddMaterial(light);
  ribs.clear(); // x extent, and y extent on the wall y = -1 (mirrored on y = +1)
  for (int r = 0; r < 7; ++r)
  {
    const float x = -3.0f + static_cast<float>(r);
    ribs.push_back({ x - 0.1f, x + 0.1f, -1.0f, -0.75f });
  }
  std::vector<Footprint> floorHoles, wallHoles;
  for (const Footprint& r : ribs)
  {
    floorHoles.push_back(r);
    floorHoles.push_back({ r.X0, r.X1, 0.75f, 1.0f });
    wallHoles.push_back({ r.X0, r.X1, 0.0f, 2.5f });
  }
  const std::vector<Footprint> none;
  AddCutPlane(
    scene, { -4.0f, 4.0f }, { -1.0f, 1.0f }, [](float u, float v) { return glm::vec3(u, v, 0.0f); },
    glm::vec3(0.0f, 0.0f, 1.0f), cut ? floorHoles : none, whiteId);
  AddCutPlane(
    scene, { -4.0f, 4.0f }, { -1.0f, 1.0f }, [](float u, float v) { return glm::vec3(u, v, 2.5f); },
    glm::vec3(0.0f, 0.0f, -1.0f), cut ? floorHoles : none, whiteId);
  for (const float y : { -1.0f, 1.0f })
  {
    AddCutPlane(
      scene, { -4.0f, 4.0f }, { 0.0f, 2.5f }, [y](float u, float v) { return glm::vec3(u, y, v); },
      glm::vec3(0.0f, -y, 0.0f), cut ? wallHoles : none, whiteId);
  }
  for (const float x : { -4.0f, 4.0f })
  {
    AddCutPlane(
      scene, { -1.0f, 1.0f }, { 0.0f, 2.5f }, [x](float u, float v) { return glm::vec3(x, u, v); },
      glm::vec3(-x, 0.0f, 0.0f), none, whiteId);
  }
  scene.AddPolygon({ { 3.99f, -0.6f, 0.5f }, { 3.99f, -0.6f, 2.0f }, { 3.99f, 0.6f, 2.0f },
                     { 3.99f, 0.6f, 0.5f } },
    lightId); // facing -x, down the corridor
  for (const Footprint& r : ribs)
  {
    AddSolid(scene, glm::vec3(r.X0, -1.0f, 0.0f), glm::vec3(r.X1, -0.75f, 2.5f), whiteId, true);
    AddSolid(scene, glm::vec3(r.X0, 0.75f, 0.0f), glm::vec3(r.X1, 1.0f, 2.5f), whiteId, true);
  }
  return scene;
}

// The wall y = -1 within 0.3 of a rib (beside it, on the side toward the light or away) and
// elsewhere (between the ribs), the floor outside the ribs, the ribs' faces toward the light.
std::vector<Region> CorridorRegions(const std::vector<Footprint>& ribs)
{
  std::vector<Region> regions(5);
  regions[0] = { "wall beside the ribs, toward the light", { 0.0f, 1.0f, 0.0f }, {} };
  regions[4] = { "wall beside the ribs, away from the light", { 0.0f, 1.0f, 0.0f }, {} };
  regions[1] = { "wall between the ribs", { 0.0f, 1.0f, 0.0f }, {} };
  regions[2] = { "floor", { 0.0f, 0.0f, 1.0f }, {} };
  regions[3] = { "ribs toward the light", { 1.0f, 0.0f, 0.0f }, {} };
  for (int i = 0; i < 320; ++i)
  {
    const float x = -3.9875f + 0.025f * static_cast<float>(i);
    float nearest = 1e9f;
    bool behind = false, lightSide = false;
    for (const Footprint& r : ribs)
    {
      behind = behind || (x > r.X0 && x < r.X1);
      const float d = std::min(std::abs(x - r.X0), std::abs(x - r.X1));
      if (d < nearest)
      {
        nearest = d;
        lightSide = x > r.X1;
      }
    }
    if (behind || x < -3.5f || x > 3.5f)
    {
      continue;
    }
    for (int j = 0; j < 10; ++j)
    {
      const float z = 0.125f + 0.25f * static_cast<float>(j);
      (nearest < 0.3f ? regions[lightSide ? 0 : 4] : regions[1]).Points.push_back({ x, -1.0f, z });
      regions[2].Points.push_back({ x, -0.7f + 0.15f * static_cast<float>(j), 0.0f });
    }
  }
  for (const Footprint& r : ribs)
  {
    for (int j = 0; j < 10; ++j)
    {
      regions[3].Points.push_back({ r.X1, -0.9875f + 0.025f * static_cast<float>(j % 10),
        0.125f + 0.25f * static_cast<float>(j) });
    }
  }
  return regions;
}

TEST(VLFBlockedLines, RibsAgainstCorridorWallsMatchTheWallsCutBehindThem)
{
  std::vector<Footprint> ribs;
  const TriangleScene whole = MakeRibbedCorridor(false, ribs);
  const TriangleScene cut = MakeRibbedCorridor(true, ribs);
  std::unique_ptr<LightField> a = LightField::Build(whole, SmallSettings());
  std::unique_ptr<LightField> b = LightField::Build(cut, SmallSettings());
  Propagate(*a, 4);
  Propagate(*b, 4);
  const std::vector<Region> regions = CorridorRegions(ribs);
  const double worst = WorstRegionDifference("ribbed corridor", *a, *b, regions);
  // Measured: the wall beside the ribs -14% before, -0.35% with blocked lines left out; the other
  // regions -2% before, -0.1% after. The residual is not explained yet (the cut scene's frames
  // and texels are the same; its contact faces face the void).
  EXPECT_LT(worst, 0.01);
}

// Coincident faces that are not a contact: a zero-thickness two-sided panel (two coincident
// quads, fronts opposite) and a light on the ceiling's plane (no hole under it) shine about as
// when they stand 1 cm apart (the line order among equal depths is arbitrary; blocking every
// coincident crossing would leave the panel black). Measured: emitted flux -13%, panel -12%,
// floor -6%; before (lines into back sides counted) the panel was -22% / -13%. What remains is
// the tracing: of two coincident triangles Embree reports one per line (the next query starts
// past the hit), so the light or one panel face misses some of its lines. Not fixed yet.
TEST(VLFBlockedLines, CoincidentPanelAndLightShineLikeSeparatedOnes)
{
  auto makeScene = [](float gap)
  {
    TriangleScene scene;
    SceneMaterial white;
    white.Diffuse = glm::vec3(0.7f);
    SceneMaterial light;
    light.Diffuse = glm::vec3(0.0f);
    light.Emission = glm::vec3(10.0f);
    const std::uint32_t whiteId = scene.AddMaterial(white);
    const std::uint32_t lightId = scene.AddMaterial(light);
    vlftest::AddBox(
      scene, glm::vec3(-2.0f, -2.0f, 0.0f), glm::vec3(2.0f, 2.0f, 2.5f), whiteId, true);
    // The light, facing down, on the ceiling (gap 0) or just below it.
    scene.AddPolygon({ { -0.5f, -1.5f, 2.5f - gap }, { -0.5f, -0.5f, 2.5f - gap },
                       { 0.5f, -0.5f, 2.5f - gap }, { 0.5f, -1.5f, 2.5f - gap } },
      lightId);
    // The panel on x = 0 (and x = gap), y in [0, 1.5], z in [0.2, 2]: one face toward -x, one +x.
    scene.AddPolygon(
      { { 0.0f, 0.0f, 0.2f }, { 0.0f, 0.0f, 2.0f }, { 0.0f, 1.5f, 2.0f }, { 0.0f, 1.5f, 0.2f } },
      whiteId);
    scene.AddPolygon(
      { { gap, 0.0f, 0.2f }, { gap, 1.5f, 0.2f }, { gap, 1.5f, 2.0f }, { gap, 0.0f, 2.0f } },
      whiteId);
    return scene;
  };
  std::unique_ptr<LightField> touching = LightField::Build(makeScene(0.0f), SmallSettings());
  std::unique_ptr<LightField> apart = LightField::Build(makeScene(0.01f), SmallSettings());
  const double emittedTouching = UnshotFlux(*touching)[0], emittedApart = UnshotFlux(*apart)[0];
  std::printf("[ coincide ] emitted flux: light on the ceiling %.5g, 1 cm below %.5g\n",
    emittedTouching, emittedApart);
  EXPECT_NEAR(emittedTouching, emittedApart, 0.15 * emittedApart);
  Propagate(*touching, 3);
  Propagate(*apart, 3);
  std::vector<Region> regions(3);
  regions[0] = { "panel toward -x", { -1.0f, 0.0f, 0.0f }, {} };
  regions[1] = { "panel toward +x", { 1.0f, 0.0f, 0.0f }, {} };
  regions[2] = { "floor", { 0.0f, 0.0f, 1.0f }, {} };
  for (int a = 0; a < 20; ++a)
  {
    for (int b = 0; b < 20; ++b)
    {
      const float u = (static_cast<float>(a) + 0.5f) / 20.0f;
      const float v = (static_cast<float>(b) + 0.5f) / 20.0f;
      regions[0].Points.push_back({ 0.0f, 1.5f * u, 0.2f + 1.8f * v });
      regions[1].Points.push_back({ 0.0f, 1.5f * u, 0.2f + 1.8f * v });
      regions[2].Points.push_back({ -2.0f + 4.0f * u, -2.0f + 4.0f * v, 0.0f });
    }
  }
  // The +x face of the separated panel lies at x = 0.01: sample it there.
  std::vector<Region> apartRegions = regions;
  for (glm::vec3& p : apartRegions[1].Points)
  {
    p.x = 0.01f;
  }
  double worst = 0.0;
  for (std::size_t r = 0; r < regions.size(); ++r)
  {
    const double a = MeanRadiance(*touching, regions[r].Points, regions[r].Normal);
    const double b = MeanRadiance(*apart, apartRegions[r].Points, regions[r].Normal);
    std::printf("[ coincide ] %s: coincident %.5g, 1 cm apart %.5g (%+.2f%%)\n",
      regions[r].Name.c_str(), a, b, 100.0 * (a / b - 1.0));
    worst = std::max(worst, std::abs(a / b - 1.0));
  }
  EXPECT_LT(worst, 0.15);
}

TEST(VLFBlockedLines, EnergyBalancesWithoutABackFaceTerm)
{
  const struct
  {
    const char* Name;
    TriangleScene Scene;
  } scenes[] = { { "Cornell box", MakeCornellBox() },
    { "box room", MakeBoxRoom(false, true).Scene },
    { "box room, open boxes", MakeBoxRoom(false, false).Scene } };
  for (const auto& s : scenes)
  {
    std::unique_ptr<LightField> field = LightField::Build(s.Scene, SmallSettings());
    const std::array<double, 3> emitted = UnshotFlux(*field);
    Propagate(*field, 4);
    std::array<double, 3> gone{};
    for (const LightField::IterationEnergy& e : field->EnergyLog)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ(e.BackFaces[c], 0.0) << s.Name << ", iteration " << e.Iteration;
        EXPECT_NEAR(e.Shot[c], e.Escaped[c] + e.Absorbed[c] + e.SpecularLost[c] + e.Unshot[c],
          1e-5 * e.Shot[c])
          << s.Name << ", iteration " << e.Iteration;
        gone[c] += e.Escaped[c] + e.Absorbed[c] + e.SpecularLost[c];
      }
    }
    const LightField::IterationEnergy& last = field->EnergyLog.back();
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_NEAR(emitted[c], gone[c] + last.Unshot[c], 1e-5 * emitted[c]) << s.Name;
    }
    std::printf("[ balance  ] %s: emitted %.5g = absorbed + escaped %.5g + unshot %.5g "
                "(back faces %.3g)\n",
      s.Name, emitted[0], gone[0], last.Unshot[0], last.BackFaces[0]);
  }
}

TEST(VLFBlockedLines, ToleranceStopReachesTheToleranceAndStops)
{
  const double tolerance = 0.02;
  std::unique_ptr<LightField> field = LightField::Build(MakeCornellBox(), SmallSettings());
  std::vector<double> reported;
  PropagationOptions options;
  options.Progress = [&](double f)
  {
    reported.push_back(f);
    return true;
  };
  std::vector<double> fractions;
  EXPECT_TRUE(PropagateToTolerance(*field, tolerance, 100, options,
    [&](const LightField& f) { fractions.push_back(UnshotFraction(f)); }));
  ASSERT_FALSE(fractions.empty());
  std::printf("[ stop     ] tolerance %.3f reached after %d iterations: unshot %.4f (before the "
              "last %.4f)\n",
    tolerance, field->IterationsDone, fractions.back(),
    fractions.size() > 1 ? fractions[fractions.size() - 2] : 1.0);
  EXPECT_LE(UnshotFraction(*field), tolerance);
  // It stops at the first iteration below the tolerance.
  for (std::size_t i = 0; i + 1 < fractions.size(); ++i)
  {
    EXPECT_GT(fractions[i], tolerance) << "iteration " << i + 1;
  }
  EXPECT_EQ(static_cast<std::size_t>(field->IterationsDone), fractions.size());
  EXPECT_TRUE(std::is_sorted(reported.begin(), reported.end()));
  ASSERT_FALSE(reported.empty());
  EXPECT_DOUBLE_EQ(reported.back(), 1.0);

  // Negative: the old fixed count of 4 leaves more than the tolerance unshot.
  std::unique_ptr<LightField> fixed = LightField::Build(MakeCornellBox(), SmallSettings());
  Propagate(*fixed, 4);
  std::printf("[ stop     ] fixed 4 iterations: unshot %.4f\n", UnshotFraction(*fixed));
  EXPECT_GT(UnshotFraction(*fixed), tolerance);
  // The cap stops it short (and says so); a resumed field continues to the tolerance.
  EXPECT_FALSE(PropagateToTolerance(*fixed, 1e-6, 5));
  EXPECT_EQ(fixed->IterationsDone, 5);
  EXPECT_TRUE(PropagateToTolerance(*fixed, tolerance, 100));
  EXPECT_EQ(fixed->IterationsDone, field->IterationsDone > 5 ? field->IterationsDone : 5);
  EXPECT_THROW(PropagateToTolerance(*fixed, 0.0, 10), std::invalid_argument);
}

// Measurement (not run by ctest): the corridor with the walls cut behind the ribs, propagated to a
// 0.2% tolerance at 513 directions, per region against the path tracer (256 paths per point).
// Run: MesolightLightFieldCoreTests --gtest_also_run_disabled_tests --gtest_filter='*Disabled*'
TEST(VLFBlockedLines, DISABLED_CorridorAgainstThePathTracer)
{
  std::vector<Footprint> ribs;
  for (const int variant : { 0, 1, 2 })
  {
    // The whole corridor, the cut one, and the cut one with texels 4x finer than the line cells.
    const bool cut = variant > 0;
    const TriangleScene scene = MakeRibbedCorridor(cut, ribs);
    LightFieldSettings settings;
    settings.Directions = 513;
    settings.RaysPerSide = 32;
    settings.TilesPerSide = 4;
    settings.TexelSize = variant == 2 ? 0.25f * settings.CellSize() : 0.0f;
    std::unique_ptr<LightField> field = LightField::Build(scene, settings);
    PropagateToTolerance(*field, 0.002, 100);
    const EmbreeScene embree(scene);
    const PathTracer tracer(embree);
    for (const Region& r : CorridorRegions(ribs))
    {
      double traced = 0.0;
      std::vector<glm::vec3> used;
      for (std::size_t i = 0; i < r.Points.size(); i += 4)
      {
        const glm::vec3& p = r.Points[i];
        for (std::uint32_t t = 0; t < scene.TriangleCount(); ++t)
        {
          const glm::vec3 a = scene.Vertex(t, 0), b = scene.Vertex(t, 1), c = scene.Vertex(t, 2);
          const glm::vec3 n = glm::cross(b - a, c - a);
          if (glm::dot(glm::normalize(n), r.Normal) < 0.99f ||
            std::abs(glm::dot(glm::normalize(n), p - a)) > 1e-5f)
          {
            continue;
          }
          const float w0 = glm::dot(glm::cross(b - p, c - p), n);
          const float w1 = glm::dot(glm::cross(c - p, a - p), n);
          const float w2 = glm::dot(glm::cross(a - p, b - p), n);
          if (w0 >= 0.0f && w1 >= 0.0f && w2 >= 0.0f)
          {
            const glm::vec3 l = tracer.DiffuseRadianceLeaving(t, p, 256, 977 * i + 13);
            traced += static_cast<double>(l.x + l.y + l.z);
            used.push_back(p);
            break;
          }
        }
      }
      traced /= static_cast<double>(used.size());
      const double mine = MeanRadiance(*field, used, r.Normal);
      std::printf("[ traced   ] %s corridor (%d iterations), %s: field %.5g path tracer %.5g "
                  "(%+.2f%%)\n",
        variant == 0 ? "whole" : (variant == 1 ? "cut" : "cut, texels / 4"), field->IterationsDone,
        r.Name.c_str(), mine, traced, 100.0 * (mine / traced - 1.0));
    }
  }
}

} // namespace
