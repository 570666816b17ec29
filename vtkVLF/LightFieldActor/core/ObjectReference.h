// SPDX-License-Identifier: BSD-3-Clause
// ObjectReference: the full solution the gathered shading of a movable object (ObjectGatherer)
// is measured against. The object's triangles are appended to the field's own (unit-sphere)
// scene and the path tracer (vtkRayTracing/core/PathTracer.h) estimates the radiance each chosen
// vertex leaves, Kd / pi x E with the vertex's smooth normal, with the object in place: it
// shadows the scene and the scene lights it, which the field (propagated without the object)
// cannot know. Shared by the tests and `mesolight bench gather`. Plain C++ (GLM, no VTK types).
#ifndef mesolight_vlf_ObjectReference_h
#define mesolight_vlf_ObjectReference_h

#include "ObjectGatherer.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mesolight
{
namespace vlf
{

struct ObjectReferenceSettings
{
  int Samples = 1024;          // paths per vertex (next-event estimation, MIS)
  std::size_t MaxPoints = 150; // at most this many vertices, evenly strided over the mesh
  std::uint64_t Seed = 1;
};

struct ObjectReference
{
  std::vector<std::uint32_t> Points; // indices into the mesh's points
  std::vector<glm::vec3> Radiance;   // outgoing radiance there, path-traced
};

// `unitMesh` in the field's unit sphere (ShadedObject::Mesh). Points of no non-degenerate
// triangle are left out. Parallel over the chosen points.
ObjectReference TraceObjectReference(
  const LightField& field, const ObjectMesh& unitMesh, const ObjectReferenceSettings& settings);

// Mean over the reference points of |L - L_ref| / L_ref (RGB summed); ignores points whose
// reference is black.
double MeanRelativeError(const std::vector<glm::vec3>& radiance, const ObjectReference& reference);

} // namespace vlf
} // namespace mesolight

#endif
