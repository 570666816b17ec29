// SPDX-License-Identifier: BSD-3-Clause
// ObjectGatherer: shading a movable object by gathering the light field's irradiance at its
// vertices (Wither 2005, "Interactive dynamic objects in a virtual light field", §3.6): the
// object is not part of the propagated field, so every vertex asks the field for the radiance
// arriving along each direction's lines through it (Lookup::Irradiance, solid-angle and
// projected-cell-area normalisations) and leaves Kd / pi x E toward every viewer (Gouraud
// shading between vertices). Plain C++ (GLM, no VTK types); parallel over vertices.
#ifndef mesolight_vlf_ObjectGatherer_h
#define mesolight_vlf_ObjectGatherer_h

#include "Lookup.h"
#include "ObjectMesh.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace mesolight
{
namespace vlf
{

struct GatherSettings
{
  // Midpoint subdivision levels (0-3) applied to the object before gathering (Wither 2005
  // §3.6.6): each level splits every triangle into four, so the Gouraud-shaded object shows
  // shadows and colour bleeding finer than its own triangles.
  int Subdivision = 0;
  GatherOptions Lookup; // cell interpolation and the normalisations (negative tests)
};

// The object as drawn: the (subdivided) mesh in unit-sphere coordinates and, per point, the
// irradiance gathered there and the radiance it leaves (Kd / pi x E).
struct ShadedObject
{
  ObjectMesh Mesh;
  std::vector<glm::vec3> Irradiance;
  std::vector<glm::vec3> Radiance;
  std::size_t GatheredPoints = 0; // points whose irradiance the last Gather computed
};

class ObjectGatherer
{
public:
  explicit ObjectGatherer(const LightField& field);

  // Shades `unitMesh` (already in the field's unit sphere: TransformMesh with
  // WorldToUnitSphere x placement). Throws std::invalid_argument for a mesh Validate rejects.
  const ShadedObject& Gather(const ObjectMesh& unitMesh, const GatherSettings& settings);
  const ShadedObject& Result() const { return this->Shaded; }

private:
  const LightField& Field;
  ShadedObject Shaded;
};

} // namespace vlf
} // namespace mesolight

#endif
