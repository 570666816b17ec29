// SPDX-License-Identifier: BSD-3-Clause
// PathTracer: the reference renderer of Mesolight (the others are measured against it). Path
// tracing of a TriangleScene on Embree: diffuse (Kd) and perfect-specular (Ks) surfaces,
// one-sided area emitters (Ke, front = counter-clockwise face), an optional lat-long
// environment, next-event estimation on emitter triangles combined with cosine-weighted BSDF
// sampling by multiple importance sampling (power heuristic), Russian roulette after a minimum
// depth. Estimates are deterministic: every pixel sample has its own counter-based seed.
//
// Reflection is two-sided (a surface reflects on whichever side the ray arrives); emission is
// one-sided. Units: radiance in the scene's emission units; images are linear float RGB.
#ifndef mesolight_PathTracer_h
#define mesolight_PathTracer_h

#include "EmbreeScene.h"
#include "ParallelTiles.h"
#include "PinholeCamera.h"
#include "RandomSequence.h"
#include "RgbImage.h"
#include "TriangleScene.h"

#include <glm/mat3x3.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <memory>
#include <vector>

namespace mesolight
{

// How direct light from emitter triangles is found.
enum class LightSampling
{
  // Emitters are found only by BSDF-sampled rays (unbiased, noisy with small lights).
  BsdfOnly,
  // Next-event estimation on emitter triangles plus BSDF sampling, weighted by the power
  // heuristic (Veach 1997): the default.
  MultipleImportance,
  // WRONG ON PURPOSE, for negative tests: next-event estimation and BSDF hits both counted in
  // full, so direct light is counted twice.
  DoubleCounted
};

struct PathTracerSettings
{
  LightSampling Sampling = LightSampling::MultipleImportance;
  // Bounces always taken before Russian roulette may end a path (roulette is unbiased; it
  // only adds variance).
  int RouletteDepth = 3;
  // Hard limit on bounces. Truncation biases by about albedo^MaxDepth, so keep it large.
  int MaxDepth = 1000;
  // Ray offset from surfaces as a fraction of the scene's bounding-box diagonal.
  float RayEpsilon = 1e-5f;
  int Threads = 0;   // 1: the calling thread only; otherwise all of vtkSMPTools' threads
  int TileSize = 16; // pixels per tile side
};

// A lat-long environment (filters/Lighting/core/EnvironmentMaps.h conventions, +Z up in map space),
// radiance arriving from infinitely far away in direction -d for the map direction d.
struct EnvironmentLight
{
  RgbImage Map;
  glm::mat3 WorldToMap{ 1.0f }; // rotates world directions into map space (e.g. y-up scenes)
  float Scale = 1.0f;
  // Radiance arriving from direction d (world, need not be unit): bilinear lookup.
  glm::vec3 Radiance(const glm::vec3& d) const;
  // A constant environment (2 x 1 map) of radiance L.
  static EnvironmentLight Uniform(const glm::vec3& radiance);
};

class PathTracer
{
public:
  // Traces the given Embree scene (which must outlive the tracer). Throws std::invalid_argument
  // when the scene cannot be used (CheckScene errors) or the settings are out of range.
  PathTracer(const EmbreeScene& scene, const PathTracerSettings& settings = {});
  ~PathTracer();

  void SetEnvironment(const EnvironmentLight& environment);
  void ClearEnvironment();
  const PathTracerSettings& Settings() const { return this->Parameters; }

  // Radiance arriving at ray.Origin from direction ray.Direction (i.e. travelling along
  // -Direction), one path sample.
  glm::vec3 Radiance(const SceneRay& ray, RandomSequence& rng) const;

  // Radiance leaving the front side of a diffuse triangle at a point on it: Le + Kd/pi * E,
  // E the irradiance on the front side estimated from `samples` paths (next-event estimation
  // and cosine-weighted sampling as set). Ks of the triangle is ignored here. Deterministic in
  // `seed`. This is what the light field's per-patch radiance is compared with.
  glm::vec3 DiffuseRadianceLeaving(
    std::uint32_t triangle, glm::vec3 point, int samples, std::uint64_t seed) const;
  // The same with a given unit shading normal instead of the triangle's own (the smooth normal
  // at a vertex of a tessellated object); the triangle gives Kd and Le. Throws
  // std::invalid_argument for a normal that is not finite and nonzero.
  glm::vec3 DiffuseRadianceLeaving(std::uint32_t triangle, glm::vec3 point, glm::vec3 normal,
    int samples, std::uint64_t seed) const;

  // Linear float RGB image, VTK row order (row 0 bottom), samplesPerPixel jittered samples per
  // pixel averaged. Returns an empty image (Width 0) when progress aborts or the arguments are
  // out of range (width/height in [1, 16384], samples in [1, 1<<20], a valid camera).
  RgbImage RenderImage(const PinholeCamera& camera, int width, int height, int samplesPerPixel,
    std::uint64_t seed = 0, const ProgressCallback& progress = {}) const;

  // Emitter triangles the tracer samples (non-degenerate, Ke > 0).
  std::size_t EmitterCount() const { return this->Emitters.size(); }

private:
  struct PathState;
  struct SurfacePoint;
  glm::vec3 Trace(PathState& state, RandomSequence& rng) const;
  // Next-event estimation and the choice of the next direction at a surface point. Returns false
  // when the path ends.
  bool Scatter(
    const SurfacePoint& point, bool diffuseOnly, PathState& state, RandomSequence& rng) const;
  glm::vec3 SampleDirectLight(
    const SurfacePoint& point, const glm::vec3& kd, float diffuseChoice, RandomSequence& rng) const;
  float LightPdf(std::uint32_t triangle, const glm::vec3& from, const glm::vec3& to) const;

  const EmbreeScene& Embree;
  const TriangleScene& Scene;
  PathTracerSettings Parameters;
  float Epsilon = 0.0f;
  std::vector<glm::vec3> UnitNormals;    // per triangle (zero for degenerate ones)
  std::vector<std::uint32_t> Emitters;   // emitter triangles
  std::vector<float> EmitterCdf;         // cumulative selection probability, by power
  std::vector<float> EmitterProbability; // per triangle: selection probability (0: not an emitter)
  std::unique_ptr<EnvironmentLight> Environment;
};

} // namespace mesolight

#endif
