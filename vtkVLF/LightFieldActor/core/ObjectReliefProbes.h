// SPDX-License-Identifier: BSD-3-Clause
// ObjectReliefProbes: the light field's incident light over a textured movable object, as the
// irradiance probes a relief mapped on it is shaded with (the same lighting input as a relief on a
// static surface: nine-coefficient spherical-harmonic radiance projections over the texture,
// Ramamoorthi and Hanrahan, "An efficient representation for irradiance environment maps"; the
// emitters are lit separately, as lights the relief self-shadows toward).
//
// Charts: one probe grid covers the texture's [0,1]^2, so the object is split into charts whose
// texture coordinates do not overlap (a box whose six faces each map [0,1]^2 gives six). A chart
// is a set of triangles connected through shared points (a textured mesh splits its points at
// texture seams); a connected set whose texture overlaps itself is split further into planar
// groups (triangles of one face normal, connected through shared positions).
//
// Per chart, each probe stands at the surface point under its texture coordinates ((i + 0.5) /
// Nu, (j + 0.5) / Nv), found by rasterizing the chart's triangles in texture space once per mesh
// (model coordinates: moving the object changes nothing of it); a probe under no triangle takes
// the nearest probe that is under one. Each gather then places the points (model -> the field's
// unit sphere), and projects the field's incident radiance there (FieldIrradiance: both ways
// along every direction, the emitters' own radiance left out) on SH9. Directions behind the
// surface (n . d < 0) bring nothing: the object's own body blocks them (the field, propagated
// without the object, would send light through it). A probe keeps its last value when it moved
// less than a quarter of a field cell and turned less than 0.02 rad, as the object gather's
// per-vertex cache does. Where the object faces itself (a concave object), the directions it
// blocks are found by rays against it (ObjectSelfOcclusion) and bring nothing. Plain C++ (GLM, no
// VTK types); parallel over probes.
#ifndef mesolight_vlf_ObjectReliefProbes_h
#define mesolight_vlf_ObjectReliefProbes_h

#include "EnvironmentMaps.h" // SH9
#include "ObjectMesh.h"
#include "Progress.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

namespace mesolight
{
namespace vlf
{
class LightField;
class ObjectSelfOcclusion;

// A mesh that cannot carry a relief (no texture coordinates, not finite ones): what() says so.
class ObjectChartError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct ObjectChart
{
  std::vector<std::uint32_t> Triangles; // indices into the mesh's triangles
  // The probes, row-major (probe (i, j) is j * ProbesU + i), in model coordinates.
  int ProbesU = 0, ProbesV = 0;
  std::vector<glm::vec3> Positions;
  std::vector<glm::vec3> Normals;    // unit (the mesh's point normals, interpolated)
  std::vector<std::uint8_t> Inside;  // 1: under a triangle of the chart; 0: a nearest one's copy
  std::size_t OverlappingProbes = 0; // probes under two triangles of the chart (the first kept)
};

// The charts of `mesh` (model coordinates, TextureCoordinates one per point; normals computed
// when missing) with probesU x probesV probes each. Throws ObjectChartError for a mesh without
// usable texture coordinates, std::invalid_argument for fewer than one probe a side.
std::vector<ObjectChart> SplitIntoCharts(const ObjectMesh& mesh, int probesU, int probesV);

struct ReliefProbeSettings
{
  // The probes stand this far in front of the surface (unit-sphere units), as a static relief's.
  float Offset = 1e-3f;
  // The probes' cache (see above); false: every probe every gather.
  bool UseCache = true;
  float CachePositionTolerance = 0.25f; // field cells
  float CacheNormalTolerance = 0.02f;   // radians
  // The object's own concavities: a probe that faces part of the object casts rays against it
  // (ObjectSelfOcclusion, the object gather's) and the directions it blocks bring nothing (its
  // shadow; the light the object reflects onto itself is not added). Convex objects cast none.
  bool ObjectOcclusion = true;
  // Read the probes' lines once per gather (ObjectLineCache, the object gather's) when there are
  // enough probes; false: every probe through the lookup (the same values, for tests).
  bool UseLineCache = true;
  int Threads = 0;           // 1: the calling thread only
  ProgressCallback Progress; // false stops with AbortedError
};

class ObjectReliefProbes
{
public:
  explicit ObjectReliefProbes(const LightField& field);
  ~ObjectReliefProbes();

  // The object's mesh (model coordinates, with texture coordinates) and probes per side; the
  // charts are rebuilt only when the mesh or the count changed. Throws as SplitIntoCharts.
  void SetMesh(const ObjectMesh& model, int probesPerSide);
  const std::vector<ObjectChart>& Charts() const { return this->ChartList; }

  // The probes of every chart at `modelToUnit` (WorldToUnitSphere(field) x the actor's matrix);
  // returns how many were gathered (the others kept their cached values).
  std::size_t Gather(const glm::mat4& modelToUnit, const ReliefProbeSettings& settings = {});
  // Per chart, per probe (row-major), the last gather's projections.
  const std::vector<std::vector<SH9>>& Probes() const { return this->Values; }
  // Where probe `probe` of chart `chart` was gathered (unit sphere, before the offset) and its
  // unit normal there.
  glm::vec3 PointOf(std::size_t chart, std::size_t probe) const;
  glm::vec3 NormalOf(std::size_t chart, std::size_t probe) const;
  std::size_t ProbeCount() const;

private:
  const LightField& Field;
  std::uint64_t MeshHash = 0;
  int PerSide = 0;
  std::vector<ObjectChart> ChartList;
  std::vector<std::vector<SH9>> Values;
  std::vector<std::vector<glm::vec3>> Points, PointNormals; // unit sphere, last gather
  std::vector<std::vector<std::uint8_t>> Valid;
  ObjectMesh Model; // as set, normals completed (the self-occlusion's scene refers to it)
  std::unique_ptr<ObjectSelfOcclusion> Self;
  bool GatheredWithOcclusion = true;
};

// The SH9 projection of the field's incident radiance at p (unit sphere) over the directions in
// front of the unit normal n (the others blocked by the surface), emitters' own radiance left
// out: one probe's value.
SH9 ProbeRadianceSH9(const LightField& field, const glm::vec3& p, const glm::vec3& n);

} // namespace vlf
} // namespace mesolight

#endif
