// SPDX-License-Identifier: BSD-3-Clause
// EmitterLights: ordinary point lights that approximate a light field's emitters, so a movable
// object can be shaded by plain (VTK/OpenGL) lighting. Wither 2005 ("Interactive dynamic objects
// in a virtual light field", §3.5) placed such lights by hand and lists estimating them from the
// field as future work; here each lamp (a connected piece of an emitting surface: separate lamps
// of one material on one plane are one field surface) becomes one light at its centroid, facing
// along its normal, with the radiant intensity Le x area (cosine lobe), and the field's mean
// radiance gives an ambient term for the indirect light. Plain C++ (GLM, no VTK types);
// positions are in the field's unit sphere.
#ifndef mesolight_vlf_EmitterLights_h
#define mesolight_vlf_EmitterLights_h

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mesolight
{
struct TriangleScene;
namespace vlf
{
class LightField;

struct EmitterLight
{
  std::uint32_t Surface = 0;            // the field surface it stands for (a part of)
  glm::vec3 Position{ 0.0f };           // area-weighted centroid of its lamp
  glm::vec3 Normal{ 0.0f, 0.0f, 1.0f }; // emitting (front) side
  glm::vec3 Radiance{ 0.0f };           // Le
  double Area = 0.0;                    // unit-sphere units
  // The scene triangles of the lamp (or merged lamps) it stands for; empty for a cell of a cut
  // lamp or surface (its part of them).
  std::vector<std::uint32_t> Triangles;
  // Radiant intensity along the normal, Le x Area; at angle theta it is that times cos theta.
  glm::vec3 Intensity() const { return this->Radiance * static_cast<float>(this->Area); }
};

struct LightApproximation
{
  std::vector<EmitterLight> Lights; // brightest first
  glm::vec3 Ambient{ 0.0f };        // mean radiance of the non-emitting surfaces' textures
};

LightApproximation EstimateEmitterLights(const LightField& field);

// The lamps among `triangles`: the pieces that touch (share a corner; corners welded by
// position). A field surface is every triangle of one material on one plane, so a row of ceiling
// lamps is one surface.
std::vector<std::vector<std::uint32_t>> LampsOf(
  const TriangleScene& scene, const std::vector<std::uint32_t>& triangles);

// Splitting large emitters: a point light is a good stand-in for an area emitter only far from
// it (the inverse-square law holds beyond a few emitter sizes). With Split, a lamp whose side
// exceeds SplitRatio x its distance to ReferencePoint (the object's centre, unit sphere) is cut
// into a grid of up to MaxSplit x MaxSplit rectangles of its plane, each a light at the centroid
// of the lamp's part inside it (triangles clipped exactly), with that part's area. A surface of
// more than MaxSplit^2 lamps is cut into that grid whatever Split says, so the lights of one
// surface never outnumber its cells.
//
// MaxLights (0: no limit) caps the count for a consumer that shades only so many lights (the
// relief shader shades 8): the lights are merged in pairs, cheapest first, by the cluster metric
// of Walter et al.'s "Lightcuts" (SIGGRAPH 2005) for oriented lights, intensity x (the extent of
// the merged lights' positions^2 + (field diameter x (1 - cos of their normals' cone))^2): near
// lamps facing the same way merge before far ones or ones that face apart. A merged light stands
// at the intensity-weighted centroid, faces along the intensity-weighted mean normal and keeps
// the lights' summed intensity (so their power; for lamps of one plane, exactly their light), so
// no lamp's light is dropped. Past 256 lights (a curved lamp's pieces) they are first gathered by
// position and normal direction, as the pairing costs n^2. When the receivers are known (a relief
// surface: the parallelogram ReceiverCorner + s ReceiverEdgeU + t ReceiverEdgeV, s and t in
// [0, 1], facing ReceiverNormal; zero edges: anywhere), a merge's cost is instead the error it
// adds there: the merged light's unshadowed irradiance against its lights' own at 8 x 8 points
// of the parallelogram, relative to all the lights' irradiance at each point, summed. So the
// lamps nearest the receivers stay separate and lamps facing apart merge only where that costs
// the receivers least (Lightcuts bounds a cluster's error at each receiver; here it is evaluated).
struct EmitterLightOptions
{
  bool Split = false;
  glm::vec3 ReferencePoint{ 0.0f };
  float SplitRatio = 0.5f;
  int MaxSplit = 4;
  std::size_t MaxLights = 0;
  glm::vec3 ReceiverCorner{ 0.0f };
  glm::vec3 ReceiverEdgeU{ 0.0f };
  glm::vec3 ReceiverEdgeV{ 0.0f };
  glm::vec3 ReceiverNormal{ 0.0f, 0.0f, 1.0f };
};

// The lights' positions (unit sphere), in their order: what groups emitter samples by the nearest
// light (EmitterSamplesOfLight, EmitterLightFactors).
std::vector<glm::vec3> LightPositions(const std::vector<EmitterLight>& lights);

// The merging above, on its own: `lights` merged until at most options.MaxLights remain
// (brightest first). MaxLights 0 leaves them as they are.
std::vector<EmitterLight> MergeEmitterLights(
  std::vector<EmitterLight> lights, const EmitterLightOptions& options);

LightApproximation EstimateEmitterLights(
  const LightField& field, const EmitterLightOptions& options);

// Radiance a diffuse point (position p, unit normal n, reflectance kd) leaves under the
// approximation: sum over lights of kd/pi x I cos(theta_light) cos(theta_p) / d^2, plus kd x
// Ambient (the ambient term is a radiance, so kd/pi x pi L). No shadows.
glm::vec3 ShadeWithLights(
  const LightApproximation& lights, const glm::vec3& p, const glm::vec3& n, const glm::vec3& kd);

} // namespace vlf
} // namespace mesolight

#endif
