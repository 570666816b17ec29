// SPDX-License-Identifier: BSD-3-Clause
// ObjectShadows: shadows a movable object casts onto the static scene of a light field
// (Wither 2005, "Interactive dynamic objects in a virtual light field", chapter 4: shadow maps
// from the scene's lights, blended instead of black, back projection removed). Plain C++ (GLM,
// no VTK types); every point is in the field's unit sphere.
//
// Emitters: the significant ones (EstimateEmitterLights, one per lamp, strongest first, by power
// Le x area; more lamps than MaximumEmitters merged down to it), each lamp of one sampled by
// g x g points (the stratified cell centres inside its triangles), which give its direct
// irradiance at a receiver and, in Soft mode (and in Field and PCF for an emitter of merged
// lamps, PerSampleMaps), one shadow map each (the area-light penumbra the thesis lists as future
// work).
//
// A shadow map is placed automatically: at the light point, looking at the centre of the
// object's bounding sphere with a square perspective frustum tangent to that sphere (near and
// far planes around it), so the whole object and nothing else fills it. It holds the eye depth
// (along the light's axis) of the nearest object point per texel, found by rasterising the
// object's triangles on the CPU: the object is small and changes every frame, rasterising costs
// only the texels it covers and needs no acceleration structure to rebuild per move (Embree
// would, or instance it and still cast a ray per texel), and it is exactly what a GPU depth pass
// computes (perspective-correct depth at texel centres), so the GLSL lookup reads the same map.
//
// Per receiver point p with unit normal n a map gives a blocked fraction (0 lit, 1 blocked):
// one texel (hard), the k x k texels around it (percentage-closer filtering, Reeves, Salesin,
// Cook 1987), and the modes use it as:
//   Black  L' = L (1 - b)                  hard b, the power-weighted mean over emitters
//   Blend  L' = L (1 - 0.5 b)              Wither's fixed alpha
//   Field  L' = L (A + (E - B) / pi) / (A + E / pi)   per channel, hard b_e per emitter
//   PCF    as Field with b_e filtered over k x k texels
//   Soft   as Field with one map per emitter sample: B = sum_e sum_i b_ei E_ei(p)
// where E_e(p) = sum_i Le A_i cos(theta_i') cos(theta_i) / d_i^2 over the emitter's samples
// (unoccluded direct irradiance), E = sum_e E_e, B = sum_e b_e E_e the part the object blocks,
// and A the field's mean radiance (EmitterLights' ambient term, so Kd A is the indirect light):
// the receiver keeps its indirect light and loses the share of its direct light the object
// blocks. The share, not the amount: subtracting Kd/pi B from the field's L (what these modes did
// before) takes an exact direct term from a field whose direct term carries the direction
// set's aliasing (at 513 directions a small light reaches a floor texel along a handful of
// directions, about 10% stripes on the lit floor); in the umbra only the indirect part is left,
// the same absolute error is several times larger relative to it, and where the field is darker
// than the exact term the per-channel clamp at 0 leaves only the red wall's bounce: red and
// black stripes. Scaling L by the ratio of the analytic shadowed to unshadowed lighting (the
// ratio estimator of Heitz, Hill, McGuire 2018, "Combining analytic direct illumination and
// stochastic shadows") keeps the field's relative error what it is on the lit floor. A is the
// indirect light where the shadow falls, gathered from the field's textures
// (EstimateShadowIndirect). Without it (SetAmbient never called) the modes subtract as before.
//
// Back projection: a receiver facing away from the light point (dot(n, light - p) <= 0) or lying
// behind the map's near plane (behind the light) is not shadowed. RemoveBackProjection = false
// (negative tests only) projects such receivers through the map like a plain depth comparison,
// which shadows points behind the light with the object's mirrored image.
//
// glsl/vtkLightFieldShadowFS.glsl is the same computation for the GPU; keep the two together.
#ifndef mesolight_vlf_ObjectShadows_h
#define mesolight_vlf_ObjectShadows_h

#include "EmitterLights.h"
#include "ObjectMesh.h"

#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{
class LightField;

enum class ShadowMode : int
{
  None = 0,
  Black = 1,
  Blend = 2,
  Field = 3,
  PCF = 4,
  Soft = 5
};
// "none", "black", "blend", "field", "pcf", "soft"; FromName returns false for others.
const char* ShadowModeName(ShadowMode mode);
bool ShadowModeFromName(const std::string& name, ShadowMode& mode);

struct ShadowSettings
{
  ShadowMode Mode = ShadowMode::Field;
  int Resolution = 256;               // texels per map side, [16, 4096]
  int MaximumEmitters = 4;            // the strongest emitters that cast shadows, [1, 8]
  float MinimumPowerFraction = 0.02f; // weaker emitters (of the strongest's power) cast none
  int AreaSamples = 3;                // g: g x g points per emitter, [1, 4]
  int PcfKernel = 3;                  // k: k x k texels, odd, [1, 9]
  float BlendAlpha = 0.5f;            // Blend's darkening (Wither 2005 §4: 0.5)
  float DepthBias = 1e-3f;            // unit-sphere units, plus 1e-4 of the depth
  bool RemoveBackProjection = true;   // false: negative tests only

  // Empty when usable, else what is wrong ("shadow map resolution 8 is not in [16, 4096]").
  std::string Validate() const;
};

// A significant emitter, its samples and its share of the shadowing emitters' power.
struct ShadowEmitter
{
  EmitterLight Light;
  std::vector<glm::vec4> Samples; // xyz: point on the emitter, w: the area it stands for
  float PowerWeight = 1.0f;       // Le x area (mean of RGB) / sum over shadowing emitters
  std::uint32_t Lamps = 1;        // the lamps it stands for (more than 1: merged)
};

struct ShadowMap
{
  std::uint32_t Emitter = 0; // index into ObjectShadows::Emitters()
  glm::vec3 Position{ 0.0f };
  glm::vec3 AxisX{ 1.0f, 0.0f, 0.0f }, AxisY{ 0.0f, 1.0f, 0.0f }; // image axes
  glm::vec3 AxisZ{ 0.0f, 0.0f, 1.0f };                            // toward the object
  float TanHalfAngle = 1.0f;                                      // frustum half width at depth 1
  float Near = 0.0f, Far = 1.0f;
  int Resolution = 0;
  // Eye depth of the nearest object point per texel, row y = 0 at -AxisY, EmptyDepth where the
  // object does not cover the texel.
  std::vector<float> Depth;
  static constexpr float EmptyDepth = 1e30f;
};

// The blocked fraction of one map seen from p (normal n): the k x k texels around p's texel
// (k = 1: one), with back projection removed or not. The GLSL mlShadowTap mirrors it.
float ShadowMapBlocked(const ShadowMap& map, const glm::vec3& p, const glm::vec3& n, int kernel,
  float bias, bool removeBackProjection);

// Unoccluded direct irradiance at p (normal n) from one emitter sample (point q, area a) of an
// emitter with normal ne and radiance le.
glm::vec3 SampleIrradiance(const glm::vec3& le, const glm::vec3& ne, const glm::vec4& sample,
  const glm::vec3& p, const glm::vec3& n);

// Whether an emitter gets a shadow map per sample point: in Soft mode, and in Field and PCF
// for an emitter of merged lamps (one hard map at their centroid, between the lamps, would cast
// a shadow none of them casts).
bool PerSampleMaps(ShadowMode mode, const ShadowEmitter& emitter);

// The field's significant emitters under the settings (its lamps merged to at most
// MaximumEmitters, power at least MinimumPowerFraction of the strongest), each lamp sampled by
// AreaSamples^2 points (a merged emitter's lamps by about that many in all).
std::vector<ShadowEmitter> SignificantEmitters(
  const LightField& field, const ShadowSettings& settings);

class ObjectShadows
{
public:
  // Places and fills the maps for the object (unit sphere). Returns "" or why there are no
  // shadows (bad settings or mesh, no emitter): the instance then shadows nothing.
  std::string Build(const LightField& field, const ObjectMesh& object,
    const ShadowSettings& settings, int threads = 0);
  // The field overload sets the ambient term (EstimateEmitterLights' Ambient); a caller of the
  // emitters overload sets it with SetAmbient (ParaView's gather output carries it), before or
  // after Build. Clear keeps it.
  std::string Build(const std::vector<ShadowEmitter>& emitters, const ObjectMesh& object,
    const ShadowSettings& settings, int threads = 0);
  void Clear();
  void SetAmbient(const glm::vec3& ambient)
  {
    this->AmbientRadiance = ambient;
    this->HaveAmbient = true;
  }
  void ClearAmbient() { this->HaveAmbient = false; }
  bool HasAmbient() const { return this->HaveAmbient; }
  const glm::vec3& Ambient() const { return this->AmbientRadiance; }

  const ShadowSettings& Settings() const { return this->Config; }
  const std::vector<ShadowEmitter>& Emitters() const { return this->EmitterList; }
  const std::vector<ShadowMap>& Maps() const { return this->MapList; }
  bool Empty() const { return this->MapList.empty(); }
  // Emitter e's maps: its centroid's first, then (Soft) one per sample, consecutive.
  const std::vector<std::uint32_t>& MapsOf(std::size_t e) const { return this->EmitterMaps[e]; }
  double FillSeconds() const { return this->Seconds; } // the last Build's placement and fill

  // Per emitter e: the fraction of its direct light the object blocks at p under the settings'
  // mode (hard, PCF or the irradiance-weighted mean over its samples' maps).
  float BlockedFraction(std::size_t e, const glm::vec3& p, const glm::vec3& n) const;
  // Unoccluded direct irradiance from emitter e at p.
  glm::vec3 DirectIrradiance(std::size_t e, const glm::vec3& p, const glm::vec3& n) const;
  // The multiplicative modes' visibility: 1 - power-weighted mean of the hard blocked
  // fractions.
  float Visibility(const glm::vec3& p, const glm::vec3& n) const;
  // The darkened radiance of a diffuse receiver (p, n, reflectance kd) whose unshadowed
  // radiance is `total` (the field's), per the settings' mode; None returns `total`.
  glm::vec3 Shade(
    const glm::vec3& total, const glm::vec3& p, const glm::vec3& n, const glm::vec3& kd) const;

private:
  ShadowSettings Config;
  std::vector<ShadowEmitter> EmitterList;
  std::vector<ShadowMap> MapList;
  std::vector<std::vector<std::uint32_t>> EmitterMaps; // per emitter: its maps
  double Seconds = 0.0;
  glm::vec3 AmbientRadiance{ 0.0f };
  bool HaveAmbient = false;
};

// What glsl/vtkLightFieldShadowFS.glsl reads: every map as a tile of one float image
// (Columns tiles a row), and its uniform arrays. Emitters whose maps or samples would not fit
// the shader's arrays (the weakest) are left out.
struct ShadowGpuData
{
  int Mode = 0; // ShadowMode as int
  int Resolution = 0, Columns = 1, Width = 0, Height = 0;
  std::vector<float> Depth; // Width x Height, row 0 first
  int EmitterCount = 0;
  glm::vec4 Params{ 0.0f };  // bias, alpha, kernel, removal
  glm::vec4 Ambient{ 0.0f }; // rgb the ambient radiance A, w 1 when known (ratio), else 0
  std::vector<glm::vec4> MapPosition, MapAxisX, MapAxisY, MapAxisZ; // see the shader
  std::vector<glm::vec4> EmitterRadiance, EmitterNormal, EmitterIndex, Samples;
};
constexpr int GpuShadowMaps = 40, GpuShadowEmitters = 8, GpuShadowSamples = 128;
ShadowGpuData PackShadowsForGpu(const ObjectShadows& shadows);

// The emitters flattened to floats and back, so they can travel with a dataset (ParaView's Light
// Field Gather puts them in its output's field data for the Light Field representation's
// shadows): per emitter Surface, Position, Normal, Radiance, Area, PowerWeight, the sample count,
// then its samples (4 floats each). Unpack returns false (and leaves `emitters` empty) for a
// malformed list.
std::vector<float> PackEmitters(const std::vector<ShadowEmitter>& emitters);
bool UnpackEmitters(const float* values, std::size_t count, std::vector<ShadowEmitter>& emitters);

// The indirect light (radiance per unit reflectance, RGB) where the object's shadow falls: per
// emitter, the point where the ray from the emitter's centre through the object's centre meets
// the scene behind the object, and there the field's radiance of every texel of the other
// non-emitting surfaces weighted by its point-to-texel form factor (visibility ignored; scaled
// down if they add up to more than the hemisphere), averaged over the emitters. Not the field's
// own value there less the exact direct light: a few percent of error in the field's direct
// light is most of the indirect. The field's mean radiance (EstimateEmitterLights' Ambient) when
// no such point is found. Everything in the unit sphere.
glm::vec3 EstimateShadowIndirect(
  const LightField& field, const std::vector<ShadowEmitter>& emitters, const ObjectMesh& object);

// Places a map at `light` for the object (its bounding sphere) and rasterises it. False when
// the object has no triangles. A light inside the bounding sphere gets a wide (80 degree half
// angle) frustum and triangles crossing its near plane are skipped.
bool FillShadowMap(ShadowMap& map, const glm::vec3& light, const ObjectMesh& object,
  const glm::vec3& centre, float radius, int resolution);

} // namespace vlf
} // namespace mesolight

#endif
