// SPDX-License-Identifier: BSD-3-Clause
#include "TriangleScene.h"

#include "PolygonTriangulation.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <utility>

namespace mesolight
{

glm::vec3 TriangleMesh::FaceNormal(std::size_t triangle) const
{
  const glm::vec3 a = this->Vertex(triangle, 0);
  return glm::cross(this->Vertex(triangle, 1) - a, this->Vertex(triangle, 2) - a);
}

float TriangleMesh::Area(std::size_t triangle) const
{
  return 0.5f * glm::length(this->FaceNormal(triangle));
}

std::uint32_t TriangleScene::AddMaterial(const SceneMaterial& material)
{
  this->Materials.push_back(material);
  return static_cast<std::uint32_t>(this->Materials.size() - 1);
}

std::uint32_t TriangleScene::AddSurface(const std::string& name)
{
  const auto found = std::find(this->SurfaceNames.begin(), this->SurfaceNames.end(), name);
  if (found != this->SurfaceNames.end())
  {
    return static_cast<std::uint32_t>(found - this->SurfaceNames.begin());
  }
  this->SurfaceNames.push_back(name);
  return static_cast<std::uint32_t>(this->SurfaceNames.size() - 1);
}

const std::string& TriangleScene::SurfaceOf(std::size_t triangle) const
{
  static const std::string unnamed;
  if (triangle >= this->SurfaceIds.size() || this->SurfaceIds[triangle] == NoSurface ||
    this->SurfaceIds[triangle] >= this->SurfaceNames.size())
  {
    return unnamed;
  }
  return this->SurfaceNames[this->SurfaceIds[triangle]];
}

void TriangleScene::NameLastTriangle(std::uint32_t surfaceId)
{
  if (this->Triangles.empty() || (surfaceId == NoSurface && this->SurfaceIds.empty()))
  {
    return;
  }
  this->SurfaceIds.resize(this->Triangles.size() - 1, NoSurface);
  this->SurfaceIds.push_back(surfaceId);
}

void TriangleScene::AddPolygon(
  const std::vector<glm::vec3>& corners, std::uint32_t materialId, std::uint32_t surfaceId)
{
  if (corners.size() < 3)
  {
    return;
  }
  const auto first = static_cast<std::uint32_t>(this->Positions.size());
  this->Positions.insert(this->Positions.end(), corners.begin(), corners.end());
  for (const glm::uvec3& t : TriangulatePolygon(corners))
  {
    this->Triangles.emplace_back(first + t);
    this->MaterialIds.push_back(materialId);
    this->NameLastTriangle(surfaceId);
  }
}

void TriangleScene::Append(const TriangleScene& other)
{
  const auto vertexOffset = static_cast<std::uint32_t>(this->Positions.size());
  const auto materialOffset = static_cast<std::uint32_t>(this->Materials.size());
  const bool hadNormals = !this->Normals.empty() || this->Positions.empty();
  const bool hadTCoords = !this->TextureCoordinates.empty() || this->Positions.empty();
  // Per-vertex attributes stay consistent: kept only when both scenes have them.
  if (!(hadNormals && other.Normals.size() == other.Positions.size()))
  {
    this->Normals.clear();
  }
  else
  {
    this->Normals.insert(this->Normals.end(), other.Normals.begin(), other.Normals.end());
  }
  if (!(hadTCoords && other.TextureCoordinates.size() == other.Positions.size()))
  {
    this->TextureCoordinates.clear();
  }
  else
  {
    this->TextureCoordinates.insert(this->TextureCoordinates.end(),
      other.TextureCoordinates.begin(), other.TextureCoordinates.end());
  }
  this->Positions.insert(this->Positions.end(), other.Positions.begin(), other.Positions.end());
  this->Materials.insert(this->Materials.end(), other.Materials.begin(), other.Materials.end());
  std::vector<std::uint32_t> surfaceOf; // other's surface id -> ours
  for (const std::string& name : other.SurfaceNames)
  {
    surfaceOf.push_back(this->AddSurface(name));
  }
  for (std::size_t t = 0; t < other.Triangles.size(); ++t)
  {
    this->Triangles.push_back(other.Triangles[t] + glm::uvec3(vertexOffset));
    this->MaterialIds.push_back(other.MaterialIds[t] + materialOffset);
    const std::uint32_t surface = t < other.SurfaceIds.size() ? other.SurfaceIds[t] : NoSurface;
    this->NameLastTriangle(surface < surfaceOf.size() ? surfaceOf[surface] : NoSurface);
  }
}

std::string SurfaceNameList(const TriangleScene& scene)
{
  std::vector<bool> used(scene.SurfaceNames.size(), false);
  for (const std::uint32_t id : scene.SurfaceIds)
  {
    if (id < used.size())
    {
      used[id] = true;
    }
  }
  std::string list;
  for (std::size_t s = 0; s < used.size(); ++s)
  {
    if (used[s])
    {
      list += (list.empty() ? "" : ", ") + scene.SurfaceNames[s];
    }
  }
  return list.empty() ? std::string("(none)") : list;
}

std::vector<std::size_t> SurfaceTriangles(const TriangleScene& scene, const std::string& name)
{
  std::vector<std::size_t> triangles;
  const auto found = std::find(scene.SurfaceNames.begin(), scene.SurfaceNames.end(), name);
  if (found != scene.SurfaceNames.end())
  {
    const auto id = static_cast<std::uint32_t>(found - scene.SurfaceNames.begin());
    for (std::size_t t = 0; t < scene.SurfaceIds.size() && t < scene.Triangles.size(); ++t)
    {
      if (scene.SurfaceIds[t] == id)
      {
        triangles.push_back(t);
      }
    }
  }
  if (triangles.empty())
  {
    throw SceneSurfaceError("the scene has no surface named '" + name + "'; its surfaces are: " +
      SurfaceNameList(scene) + " (OBJ files name surfaces with `g` or `o` statements)");
  }
  return triangles;
}

bool SceneBounds(const TriangleScene& scene, glm::vec3& lower, glm::vec3& upper)
{
  if (scene.Triangles.empty())
  {
    return false;
  }
  lower = glm::vec3(std::numeric_limits<float>::max());
  upper = glm::vec3(std::numeric_limits<float>::lowest());
  for (const glm::uvec3& triangle : scene.Triangles)
  {
    for (int corner = 0; corner < 3; ++corner)
    {
      lower = glm::min(lower, scene.Positions[triangle[corner]]);
      upper = glm::max(upper, scene.Positions[triangle[corner]]);
    }
  }
  return true;
}

namespace
{
bool IsFinite(const glm::vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

} // namespace

// Whether float coordinates cannot tell the triangle from a segment or a point: its height over
// its longest edge is within two roundings of its largest coordinate. The test is per triangle (in
// double, so huge coordinates do not overflow), not relative to the scene's size: a ground plane a
// thousand kilometres wide must not erase the room standing on it.
bool IsDegenerateTriangle(const TriangleScene& scene, std::size_t triangle)
{
  const glm::dvec3 a(scene.Vertex(triangle, 0)), b(scene.Vertex(triangle, 1)),
    c(scene.Vertex(triangle, 2));
  const double twiceArea = glm::length(glm::cross(b - a, c - a));
  const double longest =
    std::sqrt(std::max({ glm::dot(b - a, b - a), glm::dot(c - a, c - a), glm::dot(c - b, c - b) }));
  const glm::dvec3 magnitude = glm::max(glm::abs(a), glm::max(glm::abs(b), glm::abs(c)));
  const double resolution = 2.0 * std::numeric_limits<float>::epsilon() *
    std::max({ magnitude.x, magnitude.y, magnitude.z, longest });
  return !(twiceArea > longest * resolution); // height <= resolution; also catches NaN
}

SceneCheck CheckScene(const TriangleScene& scene, bool requireEmitter)
{
  SceneCheck check;
  if (scene.Triangles.empty())
  {
    check.Errors.emplace_back("the scene has no triangles");
    return check;
  }
  if (scene.MaterialIds.size() != scene.Triangles.size())
  {
    check.Errors.emplace_back("the scene has " + std::to_string(scene.MaterialIds.size()) +
      " material ids for " + std::to_string(scene.Triangles.size()) + " triangles");
    return check;
  }
  for (std::size_t v = 0; v < scene.Positions.size(); ++v)
  {
    if (!IsFinite(scene.Positions[v]))
    {
      check.Errors.emplace_back("vertex " + std::to_string(v) + " is not finite (NaN or Inf)");
      return check;
    }
  }
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    const glm::uvec3& triangle = scene.Triangles[t];
    for (int corner = 0; corner < 3; ++corner)
    {
      if (triangle[corner] >= scene.Positions.size())
      {
        check.Errors.emplace_back("triangle " + std::to_string(t) + " refers to vertex " +
          std::to_string(triangle[corner]) + " of " + std::to_string(scene.Positions.size()));
        return check;
      }
    }
    if (scene.MaterialIds[t] >= scene.Materials.size())
    {
      check.Errors.emplace_back("triangle " + std::to_string(t) + " refers to material " +
        std::to_string(scene.MaterialIds[t]) + " of " + std::to_string(scene.Materials.size()));
      return check;
    }
  }
  bool emitter = false;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (IsDegenerateTriangle(scene, t))
    {
      ++check.DegenerateTriangles;
      continue;
    }
    const glm::vec3& e = scene.MaterialOf(t).Emission;
    emitter = emitter || (e.x > 0.0f || e.y > 0.0f || e.z > 0.0f);
  }
  if (check.DegenerateTriangles == scene.Triangles.size())
  {
    check.Errors.emplace_back("every triangle of the scene is degenerate (zero area)");
  }
  else if (check.DegenerateTriangles > 0)
  {
    check.Warnings.emplace_back(
      std::to_string(check.DegenerateTriangles) + " degenerate (zero-area) triangles are ignored");
  }
  for (const SceneMaterial& material : scene.Materials)
  {
    const glm::vec3 reflectance = material.Diffuse + material.Specular;
    if (!IsFinite(material.Diffuse) || !IsFinite(material.Specular) || !IsFinite(material.Emission))
    {
      check.Errors.emplace_back("material '" + material.Name + "' has a non-finite value");
    }
    else if (glm::any(glm::lessThan(material.Diffuse, glm::vec3(0.0f))) ||
      glm::any(glm::lessThan(material.Specular, glm::vec3(0.0f))) ||
      glm::any(glm::lessThan(material.Emission, glm::vec3(0.0f))))
    {
      check.Errors.emplace_back("material '" + material.Name + "' has a negative value");
    }
    else if (glm::any(glm::greaterThan(reflectance, glm::vec3(1.0f))))
    {
      check.Warnings.emplace_back("material '" + material.Name +
        "' reflects more than it receives (Kd + Ks > 1): energy is not conserved");
    }
  }
  if (requireEmitter && !emitter)
  {
    check.Errors.emplace_back("the scene has no emitter (no material with emission Ke > 0)");
  }
  const float spread = FarGeometryRatio(scene);
  if (spread > FarGeometryWarningRatio)
  {
    char text[64];
    std::snprintf(text, sizeof(text), "%.1f", static_cast<double>(spread));
    check.Warnings.emplace_back(std::string("the scene's bounding box is ") + text +
      " times the size of the box holding 98% of its surface area: a few far triangles make a "
      "light field (scaled to the whole box) coarser and darker for the rest; remove them if "
      "they are not meant to be there");
  }
  return check;
}

float FarGeometryRatio(const TriangleScene& scene)
{
  // Per axis, the area-weighted 1st percentile of the triangles' lowest coordinates and the 99th
  // of their highest: the box most of the surface lies in (a single large quad spans all of it),
  // which a few small stray triangles do not move.
  glm::vec3 lower, upper;
  if (!SceneBounds(scene, lower, upper))
  {
    return 1.0f;
  }
  std::vector<std::pair<float, float>> lows, highs; // (coordinate, area)
  glm::vec3 low(0.0f), high(0.0f);
  for (int a = 0; a < 3; ++a)
  {
    lows.clear();
    highs.clear();
    double total = 0.0;
    for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
    {
      const float area = scene.Area(t);
      if (std::isfinite(area) && area > 0.0f)
      {
        const float c0 = scene.Vertex(t, 0)[a], c1 = scene.Vertex(t, 1)[a],
                    c2 = scene.Vertex(t, 2)[a];
        lows.emplace_back(std::min({ c0, c1, c2 }), area);
        highs.emplace_back(-std::max({ c0, c1, c2 }), area);
        total += area;
      }
    }
    if (!(total > 0.0))
    {
      return 1.0f;
    }
    const auto percentile = [total](std::vector<std::pair<float, float>>& values)
    {
      std::sort(values.begin(), values.end());
      double sum = 0.0;
      for (const auto& entry : values)
      {
        sum += entry.second;
        if (sum >= 0.01 * total)
        {
          return entry.first;
        }
      }
      return values.back().first;
    };
    low[a] = percentile(lows);
    high[a] = -percentile(highs);
  }
  const float bulk = glm::length(high - low);
  const float whole = glm::length(upper - lower);
  return bulk > 0.0f ? whole / bulk : 1.0f;
}

std::size_t RemoveDegenerateTriangles(TriangleScene& scene)
{
  std::size_t kept = 0;
  for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
  {
    if (!IsDegenerateTriangle(scene, t))
    {
      scene.Triangles[kept] = scene.Triangles[t];
      scene.MaterialIds[kept] = scene.MaterialIds[t];
      if (t < scene.SurfaceIds.size())
      {
        scene.SurfaceIds[kept] = scene.SurfaceIds[t];
      }
      ++kept;
    }
  }
  const std::size_t dropped = scene.Triangles.size() - kept;
  scene.Triangles.resize(kept);
  scene.MaterialIds.resize(kept);
  if (!scene.SurfaceIds.empty())
  {
    scene.SurfaceIds.resize(kept, TriangleScene::NoSurface);
  }
  return dropped;
}

float NormalizeToUnitSphere(TriangleScene& scene)
{
  glm::vec3 lower, upper;
  if (!SceneBounds(scene, lower, upper))
  {
    return 1.0f;
  }
  const glm::vec3 centre = 0.5f * (lower + upper);
  const float radius = 0.5f * glm::length(upper - lower);
  const float scale = radius > 0.0f ? 1.0f / radius : 1.0f;
  for (glm::vec3& p : scene.Positions)
  {
    p = (p - centre) * scale;
  }
  return scale;
}

namespace
{
// Orients a quad so its normal points toward (into == true) or away from a reference point.
std::vector<glm::vec3> Facing(std::vector<glm::vec3> quad, const glm::vec3& reference, bool toward)
{
  const glm::vec3 normal = glm::cross(quad[1] - quad[0], quad[2] - quad[0]);
  const glm::vec3 centre = 0.25f * (quad[0] + quad[1] + quad[2] + quad[3]);
  const bool pointsToward = glm::dot(normal, reference - centre) > 0.0f;
  if (pointsToward != toward)
  {
    std::reverse(quad.begin(), quad.end());
  }
  return quad;
}

void AddBlock(TriangleScene& scene, const std::vector<std::vector<glm::vec3>>& faces,
  std::uint32_t material, std::uint32_t surface)
{
  glm::vec3 centre(0.0f);
  for (const auto& face : faces)
  {
    for (const glm::vec3& p : face)
    {
      centre += p;
    }
  }
  centre /= static_cast<float>(4 * faces.size());
  for (const auto& face : faces)
  {
    scene.AddPolygon(Facing(face, centre, false), material, surface);
  }
}
} // namespace

TriangleScene MakeCornellBox()
{
  TriangleScene scene;
  SceneMaterial white;
  white.Name = "white";
  white.Diffuse = glm::vec3(0.725f, 0.71f, 0.68f);
  SceneMaterial red = white;
  red.Name = "red";
  red.Diffuse = glm::vec3(0.63f, 0.065f, 0.05f);
  SceneMaterial green = white;
  green.Name = "green";
  green.Diffuse = glm::vec3(0.14f, 0.45f, 0.091f);
  SceneMaterial light = white;
  light.Name = "light";
  light.Diffuse = glm::vec3(0.78f);
  light.Emission = glm::vec3(17.0f, 12.0f, 4.0f);
  const std::uint32_t whiteId = scene.AddMaterial(white);
  const std::uint32_t redId = scene.AddMaterial(red);
  const std::uint32_t greenId = scene.AddMaterial(green);
  const std::uint32_t lightId = scene.AddMaterial(light);

  const glm::vec3 room(278.0f, 274.4f, 279.6f);
  using Quad = std::vector<glm::vec3>;
  // Floor, ceiling, back wall, left (red, x = 550) and right (green, x = 0) walls.
  scene.AddPolygon(Facing(Quad{ { 552.8f, 0.0f, 0.0f }, { 0.0f, 0.0f, 0.0f },
                            { 0.0f, 0.0f, 559.2f }, { 549.6f, 0.0f, 559.2f } },
                     room, true),
    whiteId, scene.AddSurface("floor"));
  scene.AddPolygon(Facing(Quad{ { 556.0f, 548.8f, 0.0f }, { 556.0f, 548.8f, 559.2f },
                            { 0.0f, 548.8f, 559.2f }, { 0.0f, 548.8f, 0.0f } },
                     room, true),
    whiteId, scene.AddSurface("ceiling"));
  scene.AddPolygon(Facing(Quad{ { 549.6f, 0.0f, 559.2f }, { 0.0f, 0.0f, 559.2f },
                            { 0.0f, 548.8f, 559.2f }, { 556.0f, 548.8f, 559.2f } },
                     room, true),
    whiteId, scene.AddSurface("back"));
  scene.AddPolygon(Facing(Quad{ { 552.8f, 0.0f, 0.0f }, { 549.6f, 0.0f, 559.2f },
                            { 556.0f, 548.8f, 559.2f }, { 556.0f, 548.8f, 0.0f } },
                     room, true),
    redId, scene.AddSurface("left"));
  scene.AddPolygon(Facing(Quad{ { 0.0f, 0.0f, 559.2f }, { 0.0f, 0.0f, 0.0f },
                            { 0.0f, 548.8f, 0.0f }, { 0.0f, 548.8f, 559.2f } },
                     room, true),
    greenId, scene.AddSurface("right"));
  // The light, facing down.
  scene.AddPolygon(Facing(Quad{ { 343.0f, 548.7f, 227.0f }, { 343.0f, 548.7f, 332.0f },
                            { 213.0f, 548.7f, 332.0f }, { 213.0f, 548.7f, 227.0f } },
                     glm::vec3(278.0f, 0.0f, 279.5f), true),
    lightId, scene.AddSurface("light"));
  // Short block.
  AddBlock(scene,
    { { { 130.0f, 165.0f, 65.0f }, { 82.0f, 165.0f, 225.0f }, { 240.0f, 165.0f, 272.0f },
        { 290.0f, 165.0f, 114.0f } },
      { { 290.0f, 0.0f, 114.0f }, { 290.0f, 165.0f, 114.0f }, { 240.0f, 165.0f, 272.0f },
        { 240.0f, 0.0f, 272.0f } },
      { { 130.0f, 0.0f, 65.0f }, { 130.0f, 165.0f, 65.0f }, { 290.0f, 165.0f, 114.0f },
        { 290.0f, 0.0f, 114.0f } },
      { { 82.0f, 0.0f, 225.0f }, { 82.0f, 165.0f, 225.0f }, { 130.0f, 165.0f, 65.0f },
        { 130.0f, 0.0f, 65.0f } },
      { { 240.0f, 0.0f, 272.0f }, { 240.0f, 165.0f, 272.0f }, { 82.0f, 165.0f, 225.0f },
        { 82.0f, 0.0f, 225.0f } } },
    whiteId, scene.AddSurface("short"));
  // Tall block.
  AddBlock(scene,
    { { { 423.0f, 330.0f, 247.0f }, { 265.0f, 330.0f, 296.0f }, { 314.0f, 330.0f, 456.0f },
        { 472.0f, 330.0f, 406.0f } },
      { { 423.0f, 0.0f, 247.0f }, { 423.0f, 330.0f, 247.0f }, { 472.0f, 330.0f, 406.0f },
        { 472.0f, 0.0f, 406.0f } },
      { { 472.0f, 0.0f, 406.0f }, { 472.0f, 330.0f, 406.0f }, { 314.0f, 330.0f, 456.0f },
        { 314.0f, 0.0f, 456.0f } },
      { { 314.0f, 0.0f, 456.0f }, { 314.0f, 330.0f, 456.0f }, { 265.0f, 330.0f, 296.0f },
        { 265.0f, 0.0f, 296.0f } },
      { { 265.0f, 0.0f, 296.0f }, { 265.0f, 330.0f, 296.0f }, { 423.0f, 330.0f, 247.0f },
        { 423.0f, 0.0f, 247.0f } } },
    whiteId, scene.AddSurface("tall"));
  return scene;
}

TriangleScene MakeCornellBoxWithMirror()
{
  TriangleScene scene = MakeCornellBox();
  SceneMaterial mirror;
  mirror.Name = "mirror";
  mirror.Diffuse = glm::vec3(0.0f);
  mirror.Specular = glm::vec3(0.9f);
  const std::uint32_t mirrorId = scene.AddMaterial(mirror);
  // The red wall becomes the mirror: seen from the camera it reflects the room (a mirror
  // facing the camera would mostly show the box's open front, i.e. nothing).
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    if (scene.Materials[scene.MaterialIds[t]].Name == "red")
    {
      scene.MaterialIds[t] = mirrorId;
    }
  }
  return scene;
}

} // namespace mesolight
