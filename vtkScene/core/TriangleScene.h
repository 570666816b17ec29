// SPDX-License-Identifier: BSD-3-Clause
// TriangleScene: a static scene of triangles with per-triangle materials, in plain C++ (GLM, no
// VTK types): the one scene model of Mesolight (Mesolight::Scene). The Embree ray tracer (its
// references) and the virtual light field both read it, so both see the same geometry, materials
// and Cornell box.
#ifndef mesolight_TriangleScene_h
#define mesolight_TriangleScene_h

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{

// Wavefront MTL terms (Wither 2005 §2.1 uses Kd, Ks and emission): diffuse reflectance,
// perfect-specular reflectance, emitted radiance. Glossy terms are for the ray tracer
// (Ahern 1999 §1): Phong shininess and a roughness in [0,1] that spreads reflected rays.
struct SceneMaterial
{
  std::string Name;
  glm::vec3 Diffuse{ 0.8f };  // Kd, albedo in [0,1]
  glm::vec3 Specular{ 0.0f }; // Ks, perfect-mirror reflectance in [0,1]
  glm::vec3 Emission{ 0.0f }; // Ke, emitted radiance (W sr^-1 m^-2, arbitrary units)
  glm::vec3 Ambient{ 0.0f };  // Ka
  float Shininess = 0.0f;     // Ns, Phong exponent
  float Roughness = 0.0f;     // 0 mirror .. 1 very rough
};

// The geometry every Mesolight triangle mesh has, written once: points, triangles indexing them
// (counter-clockwise seen from the front) and optional per-point attributes. A scene adds
// per-triangle materials (TriangleScene); the light field's movable object one reflectance for
// the whole object (vlf::ObjectMesh).
struct TriangleMesh
{
  std::vector<glm::vec3> Positions;
  std::vector<glm::uvec3> Triangles; // indices into Positions
  // Optional per-vertex attributes (empty, or one per position).
  std::vector<glm::vec3> Normals;
  std::vector<glm::vec2> TextureCoordinates;

  std::size_t TriangleCount() const { return this->Triangles.size(); }
  glm::vec3 Vertex(std::size_t triangle, int corner) const
  {
    return this->Positions[this->Triangles[triangle][corner]];
  }
  // Unnormalised geometric normal (cross product of the edges, counter-clockwise front face);
  // its length is twice the triangle's area.
  glm::vec3 FaceNormal(std::size_t triangle) const;
  float Area(std::size_t triangle) const;
};

struct TriangleScene : TriangleMesh
{
  std::vector<std::uint32_t> MaterialIds; // one per triangle, index into Materials
  std::vector<SceneMaterial> Materials;
  // Named surfaces (OBJ `g`/`o` groups, the Cornell box's walls and blocks), so a tool or a test
  // can address one wall ("put a relief on `back`") independently of the triangle order. Empty
  // SurfaceIds: no triangle is named. Otherwise one per triangle, an index into SurfaceNames or
  // NoSurface for an unnamed triangle.
  std::vector<std::string> SurfaceNames;
  std::vector<std::uint32_t> SurfaceIds;
  static constexpr std::uint32_t NoSurface = 0xffffffffu;

  const SceneMaterial& MaterialOf(std::size_t triangle) const
  {
    return this->Materials[this->MaterialIds[triangle]];
  }

  // Appends a material and returns its id.
  std::uint32_t AddMaterial(const SceneMaterial& material);
  // The id of the surface called `name`, appended to SurfaceNames if new.
  std::uint32_t AddSurface(const std::string& name);
  // The surface name of a triangle; empty when it has none.
  const std::string& SurfaceOf(std::size_t triangle) const;
  // Names a triangle just appended (Triangles.back()): keeps SurfaceIds one per triangle once any
  // triangle is named. NoSurface leaves it unnamed.
  void NameLastTriangle(std::uint32_t surfaceId);
  // Appends a planar simple polygon (TriangulatePolygon), counter-clockwise seen from its front,
  // optionally part of a named surface (an id from AddSurface).
  void AddPolygon(const std::vector<glm::vec3>& corners, std::uint32_t materialId,
    std::uint32_t surfaceId = NoSurface);
  // Appends another scene (materials are appended too, ids remapped; surfaces of the same name
  // merge).
  void Append(const TriangleScene& other);
};

// A surface name the scene does not have; the message lists the names it has.
class SceneSurfaceError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// The triangles of the surface called `name`, in scene order. Throws SceneSurfaceError naming the
// surfaces the scene has when it has none of that name (or none at all).
std::vector<std::size_t> SurfaceTriangles(const TriangleScene& scene, const std::string& name);
// "back, ceiling, floor" (the named surfaces that have triangles, in SurfaceNames order), or
// "(none)".
std::string SurfaceNameList(const TriangleScene& scene);

// What is wrong with a scene, one problem per entry ("triangle 12 is degenerate (area 0)",
// "no emitter"): empty when the scene can be used. Degenerate means a triangle float arithmetic
// cannot tell from a segment: its height over its longest edge is at most two float roundings of
// its largest coordinate (each triangle on its own, whatever else the scene holds).
struct SceneCheck
{
  std::vector<std::string> Errors;   // the scene cannot be used
  std::vector<std::string> Warnings; // usable, but probably not what the user meant
  std::size_t DegenerateTriangles = 0;
  bool Ok() const { return this->Errors.empty(); }
};
SceneCheck CheckScene(const TriangleScene& scene, bool requireEmitter);

// How many times the scene's bounding-box diagonal exceeds that of the box holding 98% of its
// surface area (per axis, area-weighted 1st and 99th percentiles of the triangles' extents); 1 for
// an empty scene. The light field scales the whole box into the unit sphere, so a few far
// triangles leave the rest that many times fewer lines across (the Cornell box with a triangle
// 3000 mm beside it: 3.3). CheckScene warns above FarGeometryWarningRatio.
float FarGeometryRatio(const TriangleScene& scene);
constexpr float FarGeometryWarningRatio = 2.5f;

// Whether triangle `triangle` is degenerate (see CheckScene).
bool IsDegenerateTriangle(const TriangleScene& scene, std::size_t triangle);

// Drops degenerate triangles (see CheckScene); returns how many were dropped.
std::size_t RemoveDegenerateTriangles(TriangleScene& scene);

// Axis-aligned bounds; false for an empty scene.
bool SceneBounds(const TriangleScene& scene, glm::vec3& lower, glm::vec3& upper);

// Translates and scales uniformly so the bounding sphere of the bounding box is the unit sphere
// centred at the origin (Wither 2005 §2.4 assumes the scene inside the unit sphere). Returns the
// scale applied (1 for an empty scene). Emission is radiance, so it is not rescaled.
float NormalizeToUnitSphere(TriangleScene& scene);

// The Cornell box as published by the Cornell Program of Computer Graphics
// (https://www.graphics.cornell.edu/online/box/data.html): floor, ceiling, back, red left and
// green right walls, a short and a tall block, the ceiling light; surfaces named `floor`,
// `ceiling`, `back`, `left` (red), `right` (green), `short`, `tall` and `light`. Millimetres, y up,
// camera at (278, 273, -800) looking along +z with a 39.3 degree field of view (35 mm focal length
// on a 25 mm film). The published reflectance spectra are given as the RGB values commonly used by
// renderers (white 0.725/0.71/0.68, red 0.63/0.065/0.05, green 0.14/0.45/0.091; light radiance
// 17/12/4). The light quad sits 0.1 mm below the ceiling so the two never coincide. All faces
// point into the room (blocks: outward).
TriangleScene MakeCornellBox();
// The Cornell box with a mirror wall: the red (left, x = 550) wall perfect-specular (Ks 0.9,
// Kd 0), the walkthrough's mirror test scene (Wither 2005 §2.4.2.2: specular surfaces seen
// through the light field). Same geometry, triangle order and camera as MakeCornellBox.
TriangleScene MakeCornellBoxWithMirror();
struct CornellCamera
{
  glm::vec3 Position{ 278.0f, 273.0f, -800.0f };
  glm::vec3 FocalPoint{ 278.0f, 273.0f, 0.0f };
  glm::vec3 ViewUp{ 0.0f, 1.0f, 0.0f };
  float ViewAngleDegrees = 39.3077f; // 2 atan(12.5 / 35)
};

} // namespace mesolight

#endif
