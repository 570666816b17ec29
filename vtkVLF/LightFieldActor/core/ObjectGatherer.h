// SPDX-License-Identifier: BSD-3-Clause
// ObjectGatherer: shading a movable object by gathering the light field's irradiance at its
// vertices (Wither 2005, "Interactive dynamic objects in a virtual light field", §3.6): the
// object is not part of the propagated field, so every vertex asks the field for the radiance
// arriving along each direction's lines through it (Lookup::IncidentRadiance, solid-angle and
// projected-cell-area normalisations) and leaves Kd / pi x E toward every viewer (Gouraud
// shading between vertices). Plain C++ (GLM, no VTK types); parallel over vertices.
//
// Beyond the thesis' gather:
// - midpoint subdivision (§3.6.6), computed once per model mesh in its own coordinates and
//   reused while only the placement changes;
// - a per-vertex cache: after a move, a vertex whose unit-sphere position and normal moved less
//   than the tolerances keeps its irradiance (a rotation about the object's axis or a small
//   step re-gathers only the points that moved far enough to see different cells);
// - back-facing vertices skipped when an eye is given (unless reflections need them);
// - cheaper direction sets: every other direction, or a subset drawn in proportion to the
//   radiance the field carries along each direction (the thesis' future work); both keep the
//   projected-area normalisation, so the weights of the directions used renormalise;
// - the object's own occlusion (ObjectSelfOcclusion.h): a direction in which the object itself
//   lies in front of a point is not looked up in the field (which does not know the object) but
//   takes the radiance leaving the object where the ray meets it (its inter-reflection, by
//   fixed-point iterations of the gather); convex objects are detected per point and cast no ray.
//
// Points outside the field's unit sphere (an object partly outside the scene's bounds) are
// gathered at their radial projection onto the sphere and counted in OutsidePoints: the lines
// there still carry the light leaving the scene, and far points would otherwise project outside
// every subfield's grid (zero light). Degenerate triangles add nothing to normals or
// subdivision's normals; missing or unusable normals are computed from the triangles.
#ifndef mesolight_vlf_ObjectGatherer_h
#define mesolight_vlf_ObjectGatherer_h

#include "Distribution.h"
#include "Lookup.h"
#include "ObjectMesh.h"
#include "Progress.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{
class ObjectSelfOcclusion;

class IrradianceVolume;

// Which of the field's directions a vertex gathers along.
enum class DirectionSampling
{
  All,       // every direction (Wither 2005 §3.6)
  Half,      // every other direction (indices 0, 2, 4, ...): half the cost
  Importance // ImportanceFraction of the directions, drawn by the field's radiance per direction
};

struct GatherSettings
{
  // Midpoint subdivision levels (0-3) applied to the object before gathering (Wither 2005
  // §3.6.6): each level splits every triangle into four, so the Gouraud-shaded object shows
  // shadows and colour bleeding finer than its own triangles.
  int Subdivision = 0;
  GatherOptions Lookup; // cell interpolation, the normalisations, occlusion (negative tests)
  DirectionSampling Directions = DirectionSampling::All;
  // Importance: the fraction of the field's directions drawn (0, 1]. Half the draws follow the
  // radiance the field carries along each direction, half the solid angles (so no direction
  // with light is impossible); a direction drawn m times counts m / p times.
  float ImportanceFraction = 0.5f;

  // The per-vertex cache: a vertex keeps its irradiance when its unit-sphere position moved
  // less than CachePositionTolerance field cells (cell side 2 / RaysPerSide) and its normal
  // turned less than CacheNormalTolerance radians since it was gathered. Any other change of
  // the settings (but the eye) or of the mesh re-gathers everything.
  bool UseCache = true;
  float CachePositionTolerance = 0.25f;
  float CacheNormalTolerance = 0.02f;

  // Back faces: with SkipBackFacing, points of no triangle that faces Eye (unit-sphere
  // coordinates) are not gathered; they keep their last value (0 before any) and are counted
  // in SkippedPoints. ReflectionsNeedBackFaces gathers them anyway (a mirror shows the back).
  // The object's own occlusion (ObjectSelfOcclusion.h). ObjectOcclusion false: every direction
  // reads the field (the object then lights itself through its own overhangs; for objects known
  // to be convex, which cost nothing either way, and for negative tests).
  bool ObjectOcclusion = true;
  // Blocked directions send the radiance leaving the object where they meet it, from this many
  // fixed-point iterations: 0 sends nothing (the object's shadow only), 1 the radiance the
  // object leaves from the field's light (one bounce on itself), 2 one more bounce (the
  // default: against the path tracer a concave bracket's slot is 40%, 18%, 14% off after 0, 1, 2).
  int ObjectInterreflections = 2;

  bool SkipBackFacing = false;
  glm::vec3 Eye{ 0.0f };
  bool ReflectionsNeedBackFaces = false;

  // Optional: irradiance read from a precomputed IrradianceVolume of the same field (a
  // trilinear spherical-harmonic lookup per point) instead of gathered along the directions;
  // Directions and the Lookup options then play no part. Not owned.
  const IrradianceVolume* Volume = nullptr;

  int Threads = 0; // 1: the calling thread only (timings); else all of ParallelFor's threads
  ProgressCallback Progress; // between batches of points; false stops with AbortedError

  // Empty when usable, else what is wrong ("subdivision 5 is outside 0-3").
  std::string Validate() const;
};

// The object as drawn: the (subdivided) mesh in unit-sphere coordinates and, per point, the
// irradiance gathered there and the radiance it leaves (Kd / pi x E).
struct ShadedObject
{
  ObjectMesh Mesh;
  std::vector<glm::vec3> Irradiance;
  std::vector<glm::vec3> Radiance;
  std::size_t GatheredPoints = 0; // points whose irradiance the last Gather computed
  std::size_t CachedPoints = 0;   // points that kept the cached value (moved too little)
  std::size_t SkippedPoints = 0;  // back-facing points not gathered
  std::size_t OutsidePoints = 0;  // points outside the field's unit sphere (gathered on it)
  std::size_t DegenerateTriangles = 0;
  std::size_t DirectionsUsed = 0;   // distinct directions each gathered point asked
  std::size_t SelfFacingPoints = 0; // gathered points that face part of the object (cast rays)
  std::size_t SelfBlockedRays = 0;  // of their rays, those the object itself blocks
};

class ObjectGatherer
{
public:
  explicit ObjectGatherer(const LightField& field);
  // A distributed field (Distribution.h): each rank reads its own directions and one sum over
  // the ranks (12 bytes a gathered point, and the importance per direction once) completes the
  // irradiance, equal to a whole field's. Every rank must then gather the same mesh with the
  // same settings together (collective). reducer: not owned, nullptr = one process.
  ObjectGatherer(const LightField& field, Reducer* reducer);
  ~ObjectGatherer();

  // Shades `unitMesh` (already in the field's unit sphere: TransformMesh with
  // WorldToUnitSphere x placement). Throws std::invalid_argument for a mesh Validate rejects
  // or settings GatherSettings::Validate rejects, AbortedError when Progress says stop.
  const ShadedObject& Gather(const ObjectMesh& unitMesh, const GatherSettings& settings);
  // Shades `modelMesh` placed by `modelToUnit` (WorldToUnitSphere(field) x the actor's
  // matrix). The subdivision is computed in model coordinates once and reused while the same
  // mesh only moves; the cache then re-gathers only the points that moved.
  const ShadedObject& Gather(
    const ObjectMesh& modelMesh, const glm::mat4& modelToUnit, const GatherSettings& settings);
  const ShadedObject& Result() const { return this->Shaded; }
  // Forgets the cache and the subdivision (the next Gather computes everything).
  void Invalidate();

  // Midpoint subdivision: each level splits every triangle into four; an edge shared by two
  // triangles is split once; a new point's normal is the renormalised mean of its edge's
  // normals (a face normal when they cancel). Normals are computed first when missing.
  static ObjectMesh Subdivide(const ObjectMesh& mesh, int levels);
  // The directions (subfield indices) and their multipliers a setting gathers along: all with
  // 1, every other with 1, or the importance draw with m / p (normalisation makes the scale
  // irrelevant).
  void DirectionsFor(const GatherSettings& settings, std::vector<std::uint32_t>& directions,
    std::vector<float>& multipliers) const;
  // Radiance the field carries along each direction (luminance summed over its lines' cells):
  // the importance of DirectionSampling::Importance, computed once.
  const std::vector<double>& DirectionImportance() const;

private:
  const LightField& Field;
  Reducer* Reduce = nullptr;
  ShadedObject Shaded;

  // The subdivided model mesh and what it was made from.
  ObjectMesh Model;
  std::uint64_t ModelHash = 0;
  int ModelLevels = -1;
  // What the cached values were gathered with.
  std::vector<glm::vec3> CachedPositions;
  std::vector<glm::vec3> CachedNormals;
  std::vector<std::uint8_t> CachedValid;
  std::uint64_t CacheKey = 0;
  mutable std::vector<double> Importance;
  // The object's own mesh as an Embree scene (model coordinates), built once per model mesh.
  std::unique_ptr<ObjectSelfOcclusion> Self;
  std::vector<glm::vec3> InputPoints; // the model mesh's points before subdivision
};

} // namespace vlf
} // namespace mesolight

#endif
