// SPDX-License-Identifier: BSD-3-Clause
// ObjectSelfOcclusion: the movable object against its own geometry, for ObjectGatherer. The
// field is propagated without the object, so a point gathering from it under an overhang of the
// object itself (below a lid, inside a concave part) would receive the light the object blocks.
// This class answers, for the gatherer's directions, whether a ray from a point of the object
// hits the object first, and where (triangle and barycentrics, so the gatherer can take the
// radiance leaving the object there: its inter-reflection).
//
// The object's (subdivided) mesh is one Embree scene in its own model coordinates, built once
// per mesh; a move only changes the inverse placement the rays are taken through (a rigid
// move and a uniform scale leave which directions are blocked unchanged).
//
// Convex objects cost nothing: a point whose tangent plane has none of the object's input points
// above it cannot see the object along any direction of its hemisphere (subdivision only adds
// convex combinations of the input points), so no ray is cast for it: on a convex object no
// point casts rays, on a concave one only the points that face part of it. Points above the
// plane by less than 5% of the object's bounding radius do not count: a subdivided point of a
// tessellated smooth surface lies that much below its neighbours' facets, which a smooth convex
// surface would not put in its way; dents shallower than that are treated as flat. Meshes of
// more than 4096 input points (large surfaces gathered in ParaView) are tested against 4096 of
// them, evenly strided: a dent that only unsampled points make is then not seen. A ray that meets
// the inside of the object (a back face: it entered the object, e.g. from a point on an inner edge
// of two faces, along the other face) is blocked and receives nothing, as the path tracer's
// one-sided surfaces do.
#ifndef mesolight_vlf_ObjectSelfOcclusion_h
#define mesolight_vlf_ObjectSelfOcclusion_h

#include "ObjectMesh.h"

#include <glm/mat3x3.hpp>
#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace mesolight
{
class EmbreeScene;
struct TriangleScene;

namespace vlf
{

struct ObjectSelfHit
{
  static constexpr std::uint32_t None = 0xffffffffu;
  std::uint32_t Triangle = None; // index into the mesh's triangles; None: the ray leaves it
  float U = 0.0f, V = 0.0f;      // barycentrics: (1-U-V) v0 + U v1 + V v2
  bool Front = true;             // false: the inside of the object (it sends no light)
};

class ObjectSelfOcclusion
{
public:
  ObjectSelfOcclusion();
  ~ObjectSelfOcclusion();
  ObjectSelfOcclusion(const ObjectSelfOcclusion&) = delete;
  ObjectSelfOcclusion& operator=(const ObjectSelfOcclusion&) = delete;

  // The mesh the rays test (model coordinates; the gatherer's subdivided mesh) and the points
  // it is made of before subdivision (the horizon test reads only those). Rebuilt only when
  // `key` differs from the last call's. Throws std::runtime_error when Embree fails.
  void Prepare(
    const ObjectMesh& model, const std::vector<glm::vec3>& inputPoints, std::uint64_t key);
  // Model -> unit sphere of the next queries (affine, not singular).
  void Place(const glm::mat4& modelToUnit);
  void Clear();
  bool Ready() const { return static_cast<bool>(this->Scene); }

  // True when part of the object lies above the tangent plane of p (normal n), both in unit
  // coordinates: only then can a direction of n's hemisphere meet the object.
  bool SeesItself(const glm::vec3& p, const glm::vec3& n) const;
  // The first hits on the object of up to 16 rays from points `origins` (their
  // normals `normals`; the rays start just off the surface) along `directions` (unit
  // coordinates). Thread-safe.
  void Trace16(const glm::vec3* origins, const glm::vec3* normals, const glm::vec3* directions,
    int count, ObjectSelfHit* hits) const;

private:
  std::unique_ptr<TriangleScene> Mesh;
  std::unique_ptr<EmbreeScene> Scene;
  std::vector<glm::vec3> InputPoints;  // model coordinates
  std::vector<glm::vec3> PlacedPoints; // unit coordinates
  std::uint64_t Key = 0;
  glm::mat4 UnitToModel{ 1.0f };
  glm::mat3 DirectionToModel{ 1.0f };
  glm::vec3 Centre{ 0.0f }; // bounding sphere of the placed input points
  float Radius = 0.0f;
  float PlaneTolerance = 0.0f, RayOffset = 0.0f;
};

} // namespace vlf
} // namespace mesolight

#endif
