// SPDX-License-Identifier: BSD-3-Clause
// Relief surfaces in a light field, for `mesolight vlf render --relief SURFACE=DEPTH_IMAGE`: where
// the relief side (ReliefShading, light-field agnostic) and the light-field side (FieldIrradiance,
// relief agnostic) meet (docs/dev/architecture.md). A named planar surface of the field's scene
// carries a depth image; the field, propagated with the wall's macro geometry, lights it per
// pixel: indirect light as SH9 probes over the surface's texture (the field's incident radiance
// without the emitters' own, evaluated at the relief's perturbed normal), direct light from
// samples of the field's emitters with the relief's self-shadowing and the scene's occlusion.
#ifndef mesolight_VlfRelief_h
#define mesolight_VlfRelief_h

#include "ReliefShading.h"
#include "ReliefSurface.h" // AutomaticReliefProbes, ReliefSurfaceError

#include <glm/vec3.hpp>

#include <cstdint>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{
class EmbreeScene;
namespace vlf
{
class LightField;
}

// Bad --relief input (unknown surface, unreadable image, a surface that is not planar): what()
// says what is wrong and how to fix it.
class ReliefSetupError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

struct FieldRelief
{
  std::string Name;
  std::string DepthImage;
  ReliefFrame Frame; // in the field's unit-sphere coordinates
  HeightField Height{ 1, 1, { 0.0f } };
  ReliefLighting Lighting;
  glm::vec3 Albedo{ 0.0f };
  glm::vec3 Emission{ 0.0f };
};

struct FieldReliefOptions
{
  double DepthScale = 0.05;   // vtkReliefProperty's default
  bool DepthIsHeight = false; // the images store height (white = high), not depth (--relief-height)
  bool NormalizeDepth = false; // their value range stretched to [0, 1] (--relief-normalize)
  // SH9 probes per side of the texture; AutomaticReliefProbes: vlf::ReliefProbesPerSide's choice.
  int Probes = vlf::AutomaticReliefProbes;
  int EmitterSamplesPerSide = 4; // per emitter triangle: n x n stratified samples
  // Per item, its SH9 probes (n x n, n = vlf::ReliefProbesPerSide(Probes),
  // vlf::ReliefSurfaceProbes) when they are already computed (the walkthrough's
  // vtkLightFieldReliefSurface did); empty: computed here.
  std::vector<std::vector<SH9>> KnownProbes;
};

// The help of --relief-probes, written once for the CPU reference and the relief mapper.
std::string ReliefProbesHelp();

// The --relief items ("SURFACE=DEPTH_IMAGE") set up against the field. Throws ReliefSetupError,
// and std::invalid_argument when KnownProbes is neither empty nor the probes of every item.
std::vector<FieldRelief> SetUpFieldReliefs(const vlf::LightField& field, const EmbreeScene& scene,
  const std::vector<std::string>& items, const FieldReliefOptions& options);

// Per triangle of the field's scene, the index of its relief in `reliefs`, or -1.
std::vector<int> ReliefOfTriangle(
  const vlf::LightField& field, const std::vector<FieldRelief>& reliefs);

// The radiance a relief shows along a world ray (unit-sphere coordinates) that hit its macro
// surface; false when the ray misses the relief (the caller keeps the flat value).
bool ReliefRadiance(
  const FieldRelief& relief, const glm::vec3& origin, const glm::vec3& dir, glm::vec3& radiance);

// The depths of an image file as the relief mapper reads them (ReadDepthMapImage: luminance,
// 0..1 or the range stretched to it with `normalize`, inverted when `isHeight`; row 0 at the
// bottom, v ~ 0). Throws ReliefSetupError naming the file and the reason.
HeightField ReadDepthImage(const std::string& path, bool isHeight, bool normalize);

} // namespace mesolight

#endif
