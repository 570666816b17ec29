// SPDX-License-Identifier: BSD-3-Clause
// ReliefOcclusion: what a relief surface lit by a light field needs beyond its probes to shade
// like the CPU reference (`mesolight vlf render --relief`) at near-zero cost per pixel in the
// relief mapper (vtkIrradianceProbesTexture): the field's emitters as small area samples (the CPU
// reference's direct light), the scene's visibility of each emitter light from each probe
// (Embree), and the relief's own visible-share map over its texture (ReliefVisibleShareMap on
// the exact height-field intersector, Mesolight::ReliefCore). One implementation, used by
// vtkLightFieldReliefSurface for the walkthrough's reliefs (`vlf view --relief`) and ParaView's
// Relief Surface alike, and by the CPU reference's emitter samples (application/VlfRelief.cxx).
// Plain C++ (GLM), unit-sphere coordinates.
#ifndef mesolight_vlf_ReliefOcclusion_h
#define mesolight_vlf_ReliefOcclusion_h

#include "HeightFieldTracer.h" // HeightField
#include "Progress.h"
#include "ReliefShading.h" // ReliefEmitterSample, ReliefFrame

#include <glm/vec3.hpp>

#include <vector>

namespace mesolight
{
class EmbreeScene;
class TriangleScene;
namespace vlf
{
class LightField;
struct EmitterLight;
class Reducer;
struct ReliefSurface;

// Texels per side of a relief's visible-share map at most: V varies at the scale of the
// relief's features, and the map costs OcclusionDirections exact marches per texel, once.
constexpr int MaxVisibleShareSide = 256;

// n x n stratified samples of every emitting triangle of the scene (Shirley's square-to-triangle
// map), the CPU reference's emitters.
std::vector<ReliefEmitterSample> EmitterSamples(const TriangleScene& scene, int n);

// The most EmitterLightFactors gives a light (vtkIrradianceProbesTexture::MaxLightFactor, what
// the relief mapper accepts): where a point light delivers next to nothing of what its samples
// do, a larger factor would only amplify the bilinear step between probes.
constexpr float MaxEmitterLightFactor = 8.0f;

// What makes the relief mapper's point lights deliver the emitters' light (for the relief mapper,
// vtkIrradianceProbesTexture's fourth component): per probe (i, j) of a probesU x probesV grid
// (ReliefProbePoint, j slowest) and light k, the flat wall's irradiance there from the CPU
// renderer's emitter samples (n x n per emitting triangle) nearest to light k that reach the
// probe past the scene, over light k's own as a point light (Le A cos_e cos / d^2 from its
// position, with its normal and intensity: vtkReliefMapper::ConfigureEmitterLight's light). One
// factor corrects the scene's shadow and the point light's error at once: a light standing for
// several merged lamps (EstimateEmitterLights' MaxLights) is no point, and the lights times their
// factors sum to the samples' irradiance at every probe, however the samples are grouped (unless
// a factor is clamped, or a light's samples reach a probe its point light does not). Luminance
// weights; clamped to [0, MaxEmitterLightFactor]; 1 where the point light does not light the
// probe (nothing to correct). Index ((j probesU + i) lights + k).
std::vector<float> EmitterLightFactors(const LightField& field, const EmbreeScene& scene,
  const ReliefSurface& surface, const std::vector<EmitterLight>& lights, int probesU, int probesV,
  int samplesPerSide = 4);

// The samples (EmitterSamples, n x n per emitting triangle) nearer to light `light` of `lights`
// (unit-sphere positions, e.g. EstimateEmitterLights') than to any other: the area that light
// stands for, as EmitterLightFactors groups them.
std::vector<ReliefEmitterSample> EmitterSamplesOfLight(
  const TriangleScene& scene, const std::vector<glm::vec3>& lights, std::size_t light, int n = 4);

// The relief frame of a surface's texture (unit sphere) with that depth scale.
ReliefFrame ReliefFrameOf(const ReliefSurface& surface, double depthScale);

// The relief's visible-share map (ReliefVisibleShareMap with ReliefLighting's directions, as the
// CPU reference shades) on the height field's texel grid, at most MaxVisibleShareSide cells a
// side; gridWidth and gridHeight are set to the grid used. The values of a cell follow one
// another (row-major, j slowest), as many per cell as vtkIrradianceProbesTexture's visible-share
// array has components (3: V, V over the share of directions above the macro plane, and the
// visible share of the relief the occluded directions meet, ReliefSeenShareMap; 4 with
// `lightSamples`: the share of that area light the relief lets through, ReliefEmitterShadowMap,
// for the renderer's light 0). A stop asked through progress throws AbortedError.
// With a reducer of several ranks (collective: every rank calls it with the same arguments) the
// rows are split as the final gather splits its texels (Distribution.h): each rank computes every
// ranks-th row (GridRows) into a map of zeros and one sum over the ranks per pass gives every
// rank the whole map, the one-rank map bit for bit (the seen shares read the whole visible-share
// map, so one sum per pass: 8, 4 and, with light samples, 4 bytes a cell; on a walled relief
// also the side walls' shares, read by the seen shares: ReliefWallVisibleShareMap). A failure or
// stop on one rank is agreed (Agree): every rank throws, AbortedError where it was a stop. With
// `walls` on a walled height field (HeightField::Edge::Walled) the side walls' map too
// (ReliefWallShareMap, WallShareLevels levels, split and summed as the rest; as many values per
// cell as the grid's), else `walls` is left empty: vtkIrradianceProbesTexture's wall array.
// With `probes` the walls' second value is weighted by the probes' radiance (ReliefWallShareMap).
std::vector<float> ReliefVisibleShareGrid(const HeightField& field, const ReliefFrame& frame,
  int& gridWidth, int& gridHeight, const ProgressCallback& progress = {},
  const std::vector<ReliefEmitterSample>& lightSamples = {}, Reducer* reducer = nullptr,
  std::vector<float>* walls = nullptr, const ReliefLighting* probes = nullptr);

// The depth levels per side wall of ReliefVisibleShareGrid's wall map: a wall runs from the
// room's share at its lip to a slot bottom's at its foot.
constexpr int WallShareLevels = 8;

} // namespace vlf
} // namespace mesolight

#endif
