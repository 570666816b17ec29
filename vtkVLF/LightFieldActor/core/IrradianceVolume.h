// SPDX-License-Identifier: BSD-3-Clause
// IrradianceVolume: the light field's irradiance, precomputed once on a regular grid of points
// over the scene for a fixed set of normals, so that shading a moving object costs a trilinear,
// three-normal interpolation per vertex instead of a gather over every direction (ObjectGatherer:
// about 100 us per vertex at 2049 directions). This is the irradiance volume of Greger, Shirley,
// Hubbard and Greenberg, "The Irradiance Volume" (IEEE CG&A 18(2), 1998), filled from the virtual
// light field: at each grid point the radiance arriving along every direction's lines
// (Lookup::IncidentRadiance, Wither 2005 §3.6) is read once and summed, with the gather's
// solid-angle weights and projected-area normalisation, for every normal of the table
// (+-DirectionSet(NormalSubdivisions): 2 x 129 normals by default, about 12 degrees apart).
//
// Why a table of normals and not spherical harmonics: second-order harmonics (Ramamoorthi and
// Hanrahan, "An Efficient Representation for Irradiance Environment Maps", SIGGRAPH 2001) were
// tried first and smooth the Cornell box's small, close light too much (28% mean error on a
// sphere below it against the path tracer, where the gather has 3%).
//
// What it gives up against the per-vertex gather, measured in the tests and `mesolight bench
// gather`: the irradiance is interpolated in space (shadow edges on the object are as soft as the
// grid is coarse) and between the normals of the table.
//
// Grid points inside solid geometry see the back of a surface along many lines (the field is
// one-sided: no light comes from there), and blending them in would darken every vertex near a
// block. A point whose lines end on back sides more often than MaximumBackSideFraction is
// invalid; lookups blend only the valid corners of their cell (weights renormalised) and fall
// back to the nearest valid point within two cells, else to the per-vertex gather
// (Lookup::Irradiance), counted in FallbackLookups.
//
// Plain C++ (GLM, no VTK types); the build is parallel over grid points, reports progress and
// can be aborted (AbortedError).
#ifndef mesolight_vlf_IrradianceVolume_h
#define mesolight_vlf_IrradianceVolume_h

#include "DirectionSet.h"
#include "Lookup.h"
#include "Progress.h"

#include <glm/vec3.hpp>

#include <array>
#include <atomic>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{

struct IrradianceVolumeSettings
{
  int Resolution = 16;        // grid points along the scene's longest side, [2, 128]
  int NormalSubdivisions = 8; // the normals: +-DirectionSet(n), 2 (2 n^2 + 1); [1, 32]
  GatherOptions Lookup;       // cell interpolation and occlusion of the incident radiance
  // A grid point whose lines end on a back side in more than this fraction of the directions
  // is inside geometry or outside the scene; 1 keeps every point (negative tests only).
  float MaximumBackSideFraction = 0.1f;
  int Threads = 0;           // 1: the calling thread only; else all of ParallelFor's threads
  ProgressCallback Progress; // false stops the build with AbortedError

  std::string Validate() const; // empty when usable
};

class IrradianceVolume
{
public:
  // Builds the volume over `field`'s scene (unit-sphere coordinates). Throws
  // std::invalid_argument for settings Validate rejects, AbortedError when Progress says stop.
  IrradianceVolume(const LightField& field, const IrradianceVolumeSettings& settings);

  // Irradiance at p (unit-sphere coordinates) for unit normal n; points outside the grid are
  // clamped onto it.
  glm::vec3 Irradiance(const glm::vec3& p, const glm::vec3& n) const;

  const std::array<int, 3>& Dimensions() const { return this->Size; }
  std::size_t PointCount() const { return this->Valid.size(); }
  std::size_t ValidPointCount() const;
  std::size_t FallbackLookups() const { return this->Fallbacks.load(); }
  double BuildSeconds() const { return this->Seconds; }

  std::size_t NormalCount() const { return 2 * this->Normals.Size(); }

private:
  std::size_t Index(int x, int y, int z) const;

  const LightField& Field;
  GatherOptions Options;
  glm::vec3 Origin{ 0.0f }; // the first grid point
  glm::vec3 Step{ 1.0f };   // between grid points, per axis
  std::array<int, 3> Size{ { 0, 0, 0 } };
  DirectionSet Normals;
  // Per grid point (x fastest) and normal: 2 i for +Direction(i), 2 i + 1 for -Direction(i).
  std::vector<glm::vec3> Table;
  std::vector<std::uint8_t> Valid;
  double Seconds = 0.0;
  mutable std::atomic<std::size_t> Fallbacks{ 0 };
};

} // namespace vlf
} // namespace mesolight

#endif
