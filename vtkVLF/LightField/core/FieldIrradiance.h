// SPDX-License-Identifier: BSD-3-Clause
// The field's incident light at a point as a lighting input other code can take without knowing
// the field: the radiance arriving along every line through p (both ways along each of the
// field's directions: the same sum the movable object's gather makes, Lookup::Irradiance), and
// its projection on the nine real spherical harmonics (Ramamoorthi and Hanrahan, "An efficient
// representation for irradiance environment maps"), whose irradiance for any normal is
// Lighting's IrradianceSH9. A relief surface lit by the field (docs/vlf.md, "Relief surfaces
// in a light field") shades its perturbed normals with it.
//
// Weights: direction k stands for +d_k and -d_k, each with the field's solid angle w_k, scaled
// so that the 2K weights sum to exactly 4 pi (a uniform radiance L then gives L00 = 2 sqrt(pi) L
// and irradiance pi L for every normal). All points are in the field's unit-sphere coordinates.
#ifndef mesolight_vlf_FieldIrradiance_h
#define mesolight_vlf_FieldIrradiance_h

#include "EnvironmentMaps.h" // SH9
#include "Lookup.h"

#include <vector>

namespace mesolight
{
namespace vlf
{

struct IncidentSample
{
  glm::vec3 Direction{ 0.0f, 0.0f, 1.0f }; // unit, from p toward where the light comes from
  float SolidAngle = 0.0f;                 // sr
  glm::vec3 Radiance{ 0.0f };
};

struct IncidentOptions
{
  // The surface p lies on: its own crossing is not a sender (Lookup::IncidentRadiance).
  std::uint32_t Ignore = NoSurface;
  // False: the emitters' own radiance is left out (the indirect part; the caller integrates the
  // emitters with its own visibility).
  bool Emission = true;
};

// The factor that makes the 2K weights (each direction's solid angle, both senses) sum to exactly
// 4 pi (see above).
double IncidentWeightScale(const LightField& field);

// The 2K samples of the radiance arriving at p (see above).
std::vector<IncidentSample> IncidentRadianceSamples(
  const LightField& field, const glm::vec3& p, const IncidentOptions& options = {});

// Their projection: L_lm = sum_i w_i L_i Y_lm(direction_i).
SH9 ProjectIncidentSH9(const std::vector<IncidentSample>& samples);

// The exact irradiance of the samples at unit normal n: sum_i w_i L_i max(0, n . direction_i).
glm::vec3 IncidentIrradiance(const std::vector<IncidentSample>& samples, const glm::vec3& n);

} // namespace vlf
} // namespace mesolight

#endif
