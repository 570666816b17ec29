// SPDX-License-Identifier: BSD-3-Clause
// TexturedRayTracer: the ray tracer of Ahern 1999 (§1-4) on Embree. Phong shading
// of triangles and analytic spheres lit by directional and positional (spot) lights with hard
// shadows; every material channel may come from a texture map: diffuse colour, specular colour
// (which is also the mirror reflectivity, Ahern 1999 §1), ambient colour, shininess, bump (normal
// tilt) and roughness. Reflections recurse to a depth limit; rough surfaces reflect by
// distributed rays around the mirror direction with conical weights (Ahern 1999 §2). Adaptive
// supersampling (3 x 3 samples where a pixel differs from a neighbour, §3) and progressive
// refinement (1 ray, 2 x 2, 4 x 4, ... blocks, no pixel traced twice, §4) are options.
//
// Shading follows VTK's OpenGL lighting so images resemble what a vtkRenderer shows:
// colour = Ka + sum over lights of light colour x attenuation x
// (Kd max(0, N.L) + Ks max(0, R.V)^n), plus Ks x reflected colour; two-sided surfaces.
#ifndef mesolight_TexturedRayTracer_h
#define mesolight_TexturedRayTracer_h

#include "EmbreeScene.h"
#include "ParallelTiles.h"
#include "PinholeCamera.h"
#include "RandomSequence.h"
#include "RgbImage.h"
#include "TextureMaps.h"
#include "TriangleScene.h"

#include <glm/vec3.hpp>

#include <cstdint>
#include <functional>
#include <memory>
#include <string>
#include <vector>

namespace mesolight
{

// A Phong material whose channels may be texture mapped (a map multiplies the constant, so a
// white constant shows the map as it is). Scalar maps read the red channel.
struct TexturedMaterial
{
  std::string Name;
  glm::vec3 Ambient{ 0.0f };  // Ka x ambient colour, added unlit
  glm::vec3 Diffuse{ 0.8f };  // Kd x diffuse colour
  glm::vec3 Specular{ 0.0f }; // Ks x specular colour: highlight colour and mirror reflectivity
  float SpecularPower = 1.0f; // Phong exponent (times the shininess map's red)
  float Roughness = 0.0f;     // 0 = mirror .. 1 = widest spread (times the roughness map's red)
  float BumpScale = 1.0f;     // tilt per unit of (2 x bump map value - 1)
  std::shared_ptr<const RgbImage> DiffuseMap, SpecularMap, AmbientMap, ShininessMap, BumpMap,
    RoughnessMap;
};

// An analytic sphere with its texture orientation: t from the axis pole, s from the meridian.
struct TexturedSphere
{
  SceneSphere Geometry;
  glm::vec3 Axis{ 0.0f, 0.0f, 1.0f };
  glm::vec3 Meridian{ 1.0f, 0.0f, 0.0f };
  std::uint32_t Material = 0;
};

struct SceneLightSource
{
  bool Positional = false;
  glm::vec3 Position{ 0.0f };                // positional lights
  glm::vec3 Direction{ 0.0f, 0.0f, -1.0f };  // direction light travels (spot axis if positional)
  glm::vec3 Colour{ 1.0f };                  // colour x intensity
  float ConeAngleDegrees = 180.0f;           // positional: spot half angle; >= 90 means no cone
  float Exponent = 1.0f;                     // spot fall-off, cos^Exponent
  glm::vec3 Attenuation{ 1.0f, 0.0f, 0.0f }; // positional: 1 / (a0 + a1 d + a2 d^2)
  bool CastsShadows = true;
};

struct TexturedScene
{
  // Triangles (MaterialIds index Materials below; Mesh.Materials may stay empty), with optional
  // per-vertex normals (smooth shading) and texture coordinates.
  TriangleScene Mesh;
  std::vector<TexturedSphere> Spheres;
  std::vector<TexturedMaterial> Materials;
  std::vector<SceneLightSource> Lights;
  glm::vec3 Background{ 0.0f };
};

struct RayTracerSettings
{
  int MaxDepth = 5; // reflection recursion limit (0: no reflections), [0, 64]
  bool Shadows = true;
  bool Reflections = true;
  int GlossySamples = 16; // distributed rays per rough reflection at a primary hit (Ahern: 40)
  TextureFilter Filter = TextureFilter::Bilinear;
  bool AdaptiveSupersampling = false;
  float AdaptiveThreshold = 0.1f; // largest channel difference to a neighbour before 3 x 3 samples
  bool Progressive = false;
  int Threads = 0; // 1: the calling thread only; otherwise all of vtkSMPTools' threads
  int TileSize = 16;
  float RayEpsilon = 1e-5f; // ray offset, fraction of the scene's bounding-box diagonal
  std::uint64_t Seed = 0;   // of the distributed reflection rays
};

struct RayCounts
{
  std::uint64_t Primary = 0;
  std::uint64_t Shadow = 0;
  std::uint64_t Secondary = 0; // reflection rays
  std::uint64_t SupersampledPixels = 0;
  RayCounts& operator+=(const RayCounts& other);
};

// Called after each progressive level (block size 2^k .. 1) and after adaptive supersampling
// (block size 0) with the image so far; return false to stop.
using RefinementCallback = std::function<bool(const RgbImage& image, int blockSize)>;

class TexturedRayTracer
{
public:
  // Checks and prepares the scene (degenerate triangles are dropped with a warning). Throws
  // std::invalid_argument with a one-line reason for an empty scene, bad mesh indices,
  // non-finite or negative material values, or settings out of range.
  TexturedRayTracer(TexturedScene scene, const RayTracerSettings& settings = {});
  ~TexturedRayTracer();

  // Colour seen along a ray (depth = reflection depth of the ray).
  glm::vec3 Trace(const SceneRay& ray, int depth, RandomSequence& rng, RayCounts& counts) const;

  // Linear float RGB image (VTK row order). Empty when stopped or the arguments are bad.
  RgbImage Render(const PinholeCamera& camera, int width, int height,
    const RefinementCallback& refinement = {}, const ProgressCallback& progress = {}) const;

  // Pixels adaptive supersampling refines: colour differs from a 4-neighbour by more than the
  // threshold in some channel.
  static std::vector<std::uint8_t> EdgePixels(const RgbImage& image, float threshold);

  // Rays of the last Render.
  RayCounts LastCounts() const { return this->Counts; }
  const std::vector<std::string>& Warnings() const { return this->Messages; }
  const TexturedScene& Scene() const { return this->Data; }

private:
  struct Surface;
  Surface SurfaceAt(const SceneHit& hit, const SceneRay& ray) const;
  glm::vec3 ReflectedColour(const Surface& surface, float roughness, int depth, RandomSequence& rng,
    RayCounts& counts) const;

  TexturedScene Data;
  RayTracerSettings Parameters;
  std::unique_ptr<EmbreeScene> Embree;
  float Epsilon = 0.0f;
  std::vector<std::string> Messages;
  mutable RayCounts Counts;
};

} // namespace mesolight

#endif
