// SPDX-License-Identifier: BSD-3-Clause
// ObjectMesh: the movable object of Wither 2005 ("Interactive dynamic objects in a virtual light
// field", chapter 3): a triangle mesh that is not part of the propagated field and moves through
// it. Plain C++ (GLM, no VTK types); the VTK side converts a vtkPolyData and a vtkProp3D matrix.
//
// The mesh is kept in its own model coordinates; a placement (model -> world, the actor's
// matrix) and the field's normalisation (world -> unit sphere, LightField::NormalizationScale /
// NormalizationCentre) give the points every light field query needs. Normals transform by the
// inverse transpose, so a rotation turns them and a scale does not stretch them.
#ifndef mesolight_vlf_ObjectMesh_h
#define mesolight_vlf_ObjectMesh_h

#include "TriangleScene.h" // TriangleMesh

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{
class LightField;

// The object's geometry is the scene model's TriangleMesh (Normals: unit, one per point;
// ComputeNormals fills them; texture coordinates only lay out a relief's probes,
// ObjectReliefProbes.h); its material is one diffuse reflectance for the whole object.
struct ObjectMesh : TriangleMesh
{
  glm::vec3 Diffuse{ 0.7f }; // Kd, diffuse reflectance of the whole object in [0, 1]

  // Empty when usable, else what is wrong (no triangles, an index out of range, a non-finite
  // point, Diffuse outside [0, 1], a normal count that does not match the points).
  std::string Validate() const;
  // Area-weighted vertex normals from the triangles (counter-clockwise = outside); degenerate
  // triangles add nothing; a point no triangle gives a direction gets +Z.
  void ComputeNormals();
  // Triangles with (nearly) zero area, which are skipped by every query.
  std::size_t DegenerateTriangleCount() const;
  // Axis-aligned bounds of the points (min, max); both 0 for an empty mesh.
  void Bounds(glm::vec3& lower, glm::vec3& upper) const;
};

// world -> the field's unit sphere: unit = (world - Centre) * Scale.
glm::mat4 WorldToUnitSphere(const LightField& field);

// The mesh with its points moved by `transform` and its normals by the inverse transpose of
// its upper 3 x 3 (renormalised). Triangles and Diffuse are copied.
ObjectMesh TransformMesh(const ObjectMesh& mesh, const glm::mat4& transform);

// A UV sphere (rings x segments quads split into triangles, poles as fans) and an axis-aligned
// cube (24 points, flat normals per face, each face mapping the texture square [0,1]^2), both
// centred on the origin: the objects of tests, benchmarks and `mesolight vlf render --object
// sphere|cube`.
ObjectMesh MakeSphere(float radius, int rings, int segments);
ObjectMesh MakeCube(float side);
// A concave object: a C-shaped bracket (a profile of width x height, bars `thickness` thick, open
// toward +x) extruded `depth` along z, centred on the origin, flat normals per face: its bottom
// bar's upper face lies under the top bar (the object's own overhang).
ObjectMesh MakeBracket(float width, float height, float thickness, float depth);

} // namespace vlf
} // namespace mesolight

#endif
