// SPDX-License-Identifier: BSD-3-Clause
// ReliefSurface: a named planar surface of a light field's scene made ready to carry a relief
// lit by the field (docs/vlf.md, "Relief surfaces in a light field"), for both renderers of
// such surfaces: the CPU reference (`mesolight vlf render --relief`, application/VlfRelief.cxx)
// and the walkthrough's relief mapper (vtkLightFieldReliefSurface). What they share is here,
// once: which triangles the name means, the surface's texture frame (from its texture
// coordinates when the scene has them, else the plane rule of SurfacePlaneOf in
// vtkScene/core/SurfaceRelief.h, which also says how planar a surface must be), and its indirect
// light as SH9 radiance probes over that texture (FieldIrradiance, the emitters' own radiance
// left out: both renderers add the emitters as lights of their own). Plain C++ (GLM),
// unit-sphere coordinates.
#ifndef mesolight_vlf_ReliefSurface_h
#define mesolight_vlf_ReliefSurface_h

#include "EnvironmentMaps.h" // SH9
#include "Progress.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{
class LightField;

// A surface that cannot carry a relief (unknown name: the message lists the scene's names; not
// planar; a mirror; degenerate texture coordinates). what() says how to fix it.
class ReliefSurfaceError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// SH9 probes per side of the texture: the fewest (and the count a wall of the Cornell box gets)
// and the most the automatic choice (ReliefProbesPerSide) gives; 0 asks for that choice.
constexpr int DefaultReliefProbesPerSide = 8;
constexpr int MaximumAutomaticReliefProbesPerSide = 64;
constexpr int AutomaticReliefProbes = 0;

struct ReliefSurface
{
  std::string Name;
  std::vector<std::size_t> Triangles; // the scene's, in scene order
  std::uint32_t FieldSurface = 0;     // the field surface of its first triangle
  // The affine texture map of its plane: texture (u, v) is Origin + u AxisU + v AxisV; Normal is
  // the unit front side (the field surface's).
  glm::dvec3 Origin{ 0.0 };
  glm::dvec3 AxisU{ 1.0, 0.0, 0.0 };
  glm::dvec3 AxisV{ 0.0, 1.0, 0.0 };
  glm::dvec3 Normal{ 0.0, 0.0, 1.0 };
  glm::vec3 Diffuse{ 0.0f };
  glm::vec3 Emission{ 0.0f };
  bool SceneTextureCoordinates = false; // the frame came from the scene's vt, not the plane
  // ReliefSurfaceFromTriangles: the scene surfaces of other materials the patch also covers, by
  // material name (its Diffuse is the one under its centre), empty when it covers one material.
  std::vector<std::string> OtherMaterials;

  glm::dvec3 Point(double u, double v) const
  {
    return this->Origin + u * this->AxisU + v * this->AxisV;
  }
  // The texture coordinates of a point of its plane.
  glm::dvec3 TextureOf(const glm::dvec3& point) const;
};

// The surface of that name (OBJ g/o name, or a Cornell box name). Throws ReliefSurfaceError.
ReliefSurface FindReliefSurface(const LightField& field, const std::string& name);

// A relief surface made of any planar triangles (unit-sphere positions; texture coordinates one
// per position, or empty: then from its plane, as for a named surface), e.g. a patch a user
// places on a wall. FieldSurface is the scene surface whose plane it lies on facing the same way,
// or stands in front of by up to 5% of the scene radius (a relief's depth lies behind its plane,
// so a relief mounted on a wall stands that far in front of it) (NoSurface if none), Diffuse and
// Emission that surface's material's (zero if none); OtherMaterials names the materials of the
// other such surfaces it overlaps (a patch across a two-tone wall); `name` is how messages call
// it. Throws
// ReliefSurfaceError (no triangles, no area, not planar, degenerate or non-affine texture
// coordinates).
ReliefSurface ReliefSurfaceFromTriangles(const LightField& field,
  const std::vector<glm::vec3>& positions, const std::vector<glm::vec2>& textureCoordinates,
  const std::vector<glm::uvec3>& triangles, const std::string& name);

// The field's indirect light over the surface: probesU x probesV SH9 radiance projections
// (ProjectIncidentSH9 of IncidentRadianceSamples, emitters left out, the surface's own crossing
// ignored), probe (i, j) at texture ((i + 1/2) / probesU, (j + 1/2) / probesV) just in front of
// the plane; row-major, j slowest. Reports progress per row; a stop throws AbortedError.
std::vector<SH9> ReliefSurfaceProbes(const LightField& field, const ReliefSurface& surface,
  int probesU, int probesV, const ProgressCallback& progress = {});

// Probes per side for a relief on `surface`: `requested` when positive, else two probes per
// field line cell across the surface's longer texture side (LightFieldSettings::CellSize: the
// field resolves light about a cell wide, and bilinear probes need two samples per cell to hold
// it), within [DefaultReliefProbesPerSide, MaximumAutomaticReliefProbesPerSide]. The probes
// carry the scene's shadows on the relief (the emitter lights' factors) and its indirect light:
// on a 200 m ground under 10 m buildings, 8 probes a side (25 m apart) averaged the buildings'
// shadows away where the field itself, and the CPU reference, drew them; one per cell (22) erred
// by 14.2/1000 of the reference's mean, two (44) by 9.3 (docs/vlf.md).
int ReliefProbesPerSide(const LightField& field, const ReliefSurface& surface, int requested);

// Where probe (i, j) stands (unit sphere): its texture point lifted off the plane by 1e-3.
glm::vec3 ReliefProbePoint(const ReliefSurface& surface, int i, int j, int probesU, int probesV);

} // namespace vlf
} // namespace mesolight

#endif
