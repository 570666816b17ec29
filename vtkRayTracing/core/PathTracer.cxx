// SPDX-License-Identifier: BSD-3-Clause
#include "PathTracer.h"

#include "EnvironmentMaps.h" // the lat-long lookup (MapUVFromDirection)
#include "Luminance.h"
#include "MathConstants.h"
#include "OrthonormalBasis.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

namespace mesolight
{

namespace
{

float MaxComponent(const glm::vec3& c)
{
  return std::max(c.x, std::max(c.y, c.z));
}

// Cosine-weighted direction around n (pdf cos / pi).
glm::vec3 SampleCosine(const glm::vec3& n, float u1, float u2)
{
  const float r = std::sqrt(u1);
  const float phi = 2.0f * Pi<float> * u2;
  glm::vec3 b1, b2;
  OrthonormalBasis(n, b1, b2);
  const float z = std::sqrt(std::max(0.0f, 1.0f - u1));
  return glm::normalize(r * std::cos(phi) * b1 + r * std::sin(phi) * b2 + z * n);
}

float PowerHeuristic(float chosen, float other)
{
  const float a = chosen * chosen;
  const float b = other * other;
  return a + b > 0.0f ? a / (a + b) : 0.0f;
}

bool Positive(const glm::vec3& c)
{
  return c.x > 0.0f || c.y > 0.0f || c.z > 0.0f;
}
} // namespace

glm::vec3 EnvironmentLight::Radiance(const glm::vec3& d) const
{
  if (this->Map.Width <= 0 || this->Map.Height <= 0)
  {
    return glm::vec3(0.0f);
  }
  // The lat-long lookup of filters/Lighting/core/EnvironmentMaps (as its ResampleLatLong does it).
  const glm::vec3 m = this->WorldToMap * d;
  const double direction[3] = { m.x, m.y, m.z };
  double u = 0.0, v = 0.0;
  MapUVFromDirection(direction, u, v);
  float rgb[3];
  SampleBilinear(this->Map, u * this->Map.Width, (1.0 - v) * this->Map.Height, true, rgb);
  return this->Scale * glm::vec3(rgb[0], rgb[1], rgb[2]);
}

EnvironmentLight EnvironmentLight::Uniform(const glm::vec3& radiance)
{
  EnvironmentLight light;
  light.Map = RgbImage(2, 1);
  for (int i = 0; i < 2; ++i)
  {
    float* p = light.Map.Pixel(i, 0);
    p[0] = radiance.x;
    p[1] = radiance.y;
    p[2] = radiance.z;
  }
  return light;
}

struct PathTracer::PathState
{
  SceneRay Ray;
  glm::vec3 Throughput{ 1.0f };
  glm::vec3 Radiance{ 0.0f };
  bool LastSpecular = true; // camera rays and mirror bounces: emitters seen in full
  float LastPdf = 0.0f;     // solid-angle pdf of the BSDF sample that made Ray
  int Depth = 0;
};

struct PathTracer::SurfacePoint
{
  glm::vec3 Position;
  glm::vec3 Normal;   // unit geometric normal on the side the light path arrives from
  glm::vec3 Incoming; // unit direction of travel of the arriving ray
  std::uint32_t Triangle;
};

PathTracer::PathTracer(const EmbreeScene& scene, const PathTracerSettings& settings)
  : Embree(scene)
  , Scene(scene.Scene())
  , Parameters(settings)
{
  const SceneCheck check = CheckScene(this->Scene, false);
  if (!check.Ok())
  {
    throw std::invalid_argument("PathTracer: " + check.Errors.front());
  }
  if (settings.RouletteDepth < 0 || settings.MaxDepth < 1 || settings.MaxDepth > 100000 ||
    !(settings.RayEpsilon >= 0.0f && settings.RayEpsilon < 0.1f) || settings.TileSize < 1)
  {
    throw std::invalid_argument(
      "PathTracer: settings out of range (RouletteDepth >= 0, MaxDepth in "
      "[1, 100000], RayEpsilon in [0, 0.1), TileSize >= 1)");
  }
  glm::vec3 lower, upper;
  SceneBounds(this->Scene, lower, upper);
  this->Epsilon = settings.RayEpsilon * glm::length(upper - lower);

  const std::size_t count = this->Scene.TriangleCount();
  this->UnitNormals.resize(count, glm::vec3(0.0f));
  this->EmitterProbability.assign(count, 0.0f);
  std::vector<float> power;
  for (std::size_t t = 0; t < count; ++t)
  {
    const glm::vec3 n = this->Scene.FaceNormal(t);
    const float length = glm::length(n);
    if (!(length > 0.0f))
    {
      continue; // degenerate: Embree never hits it, and it emits nothing
    }
    this->UnitNormals[t] = n / length;
    const glm::vec3& emission = this->Scene.MaterialOf(t).Emission;
    if (Positive(emission))
    {
      this->Emitters.push_back(static_cast<std::uint32_t>(t));
      power.push_back(
        0.5f * length * std::max(Luminance(emission.x, emission.y, emission.z), 1e-6f));
    }
  }
  // Emitters are chosen in proportion to their power; EmitterProbability holds the area pdf
  // (selection probability / area) of each emitter triangle.
  double total = 0.0;
  for (float p : power)
  {
    total += p;
  }
  double running = 0.0;
  for (std::size_t k = 0; k < this->Emitters.size(); ++k)
  {
    running += power[k];
    this->EmitterCdf.push_back(static_cast<float>(running / total));
    const std::uint32_t t = this->Emitters[k];
    this->EmitterProbability[t] = static_cast<float>(power[k] / total) / this->Scene.Area(t);
  }
  if (!this->EmitterCdf.empty())
  {
    this->EmitterCdf.back() = 1.0f;
  }
}

PathTracer::~PathTracer() = default;

void PathTracer::SetEnvironment(const EnvironmentLight& environment)
{
  this->Environment.reset(new EnvironmentLight(environment));
}

void PathTracer::ClearEnvironment()
{
  this->Environment.reset();
}

float PathTracer::LightPdf(std::uint32_t triangle, const glm::vec3& from, const glm::vec3& to) const
{
  const glm::vec3 offset = to - from;
  const float distance2 = glm::dot(offset, offset);
  const float cosLight = -glm::dot(this->UnitNormals[triangle], offset) / std::sqrt(distance2);
  if (!(cosLight > 0.0f))
  {
    return 0.0f;
  }
  return this->EmitterProbability[triangle] * distance2 / cosLight;
}

glm::vec3 PathTracer::SampleDirectLight(
  const SurfacePoint& point, const glm::vec3& kd, float diffuseChoice, RandomSequence& rng) const
{
  // diffuseChoice is the probability that Scatter continues diffusely: the BSDF-sampling pdf
  // of a direction is diffuseChoice * cos / pi, which the MIS weight needs.
  const float choose = rng.NextFloat();
  const auto found = std::upper_bound(this->EmitterCdf.begin(), this->EmitterCdf.end(), choose);
  const std::size_t k = std::min<std::size_t>(
    static_cast<std::size_t>(found - this->EmitterCdf.begin()), this->Emitters.size() - 1);
  const std::uint32_t triangle = this->Emitters[k];
  // Uniform point on the triangle.
  const float r1 = std::sqrt(rng.NextFloat());
  const float r2 = rng.NextFloat();
  const glm::vec3 y = (1.0f - r1) * this->Scene.Vertex(triangle, 0) +
    r1 * (1.0f - r2) * this->Scene.Vertex(triangle, 1) + r1 * r2 * this->Scene.Vertex(triangle, 2);
  const glm::vec3 origin = point.Position + this->Epsilon * point.Normal;
  const glm::vec3 offset = y - origin;
  const float distance = glm::length(offset);
  if (!(distance > 2.0f * this->Epsilon))
  {
    return glm::vec3(0.0f);
  }
  const glm::vec3 wi = offset / distance;
  const float cosSurface = glm::dot(point.Normal, wi);
  const float cosLight = -glm::dot(this->UnitNormals[triangle], wi);
  if (cosSurface <= 0.0f || cosLight <= 0.0f)
  {
    return glm::vec3(0.0f); // behind the surface, or the emitter's back (one-sided)
  }
  SceneRay shadow;
  shadow.Origin = origin;
  shadow.Direction = wi;
  shadow.TFar = distance - 2.0f * this->Epsilon;
  if (this->Embree.Occluded(shadow))
  {
    return glm::vec3(0.0f);
  }
  const float lightPdf = this->EmitterProbability[triangle] * distance * distance / cosLight;
  float weight = 1.0f;
  if (this->Parameters.Sampling == LightSampling::MultipleImportance)
  {
    weight = PowerHeuristic(lightPdf, diffuseChoice * cosSurface / Pi<float>);
  }
  return kd / Pi<float> * this->Scene.MaterialOf(triangle).Emission *
    (cosSurface * weight / lightPdf);
}

bool PathTracer::Scatter(
  const SurfacePoint& point, bool diffuseOnly, PathState& state, RandomSequence& rng) const
{
  const SceneMaterial& material = this->Scene.MaterialOf(point.Triangle);
  const glm::vec3 kd = material.Diffuse;
  const glm::vec3 ks = diffuseOnly ? glm::vec3(0.0f) : material.Specular;
  const float diffuseWeight = std::max(0.0f, Luminance(kd.x, kd.y, kd.z));
  const float specularWeight = std::max(0.0f, Luminance(ks.x, ks.y, ks.z));
  if (!(diffuseWeight + specularWeight > 0.0f) || state.Depth >= this->Parameters.MaxDepth)
  {
    return false;
  }
  const float diffuseChoice = diffuseWeight / (diffuseWeight + specularWeight);
  // Next-event estimation for the diffuse lobe, whichever lobe continues the path.
  if (diffuseWeight > 0.0f && this->Parameters.Sampling != LightSampling::BsdfOnly &&
    !this->Emitters.empty())
  {
    state.Radiance += state.Throughput * this->SampleDirectLight(point, kd, diffuseChoice, rng);
  }
  glm::vec3 direction;
  if (rng.NextFloat() < diffuseChoice)
  {
    const float u1 = rng.NextFloat();
    const float u2 = rng.NextFloat();
    direction = SampleCosine(point.Normal, u1, u2);
    // f cos / pdf = (Kd / pi) cos / (choice cos / pi).
    state.Throughput *= kd / diffuseChoice;
    state.LastPdf = diffuseChoice * std::max(0.0f, glm::dot(direction, point.Normal)) / Pi<float>;
    state.LastSpecular = false;
  }
  else
  {
    direction = point.Incoming - 2.0f * glm::dot(point.Incoming, point.Normal) * point.Normal;
    state.Throughput *= ks / (1.0f - diffuseChoice);
    state.LastPdf = 0.0f;
    state.LastSpecular = true;
  }
  ++state.Depth;
  if (state.Depth >= this->Parameters.RouletteDepth)
  {
    const float survive = std::min(0.95f, MaxComponent(state.Throughput));
    if (!(rng.NextFloat() < survive))
    {
      return false;
    }
    state.Throughput /= survive;
  }
  state.Ray.Origin = point.Position + this->Epsilon * point.Normal;
  state.Ray.Direction = direction;
  state.Ray.TNear = 0.0f;
  state.Ray.TFar = std::numeric_limits<float>::infinity();
  return true;
}

glm::vec3 PathTracer::Trace(PathState& state, RandomSequence& rng) const
{
  for (;;)
  {
    const SceneHit hit = this->Embree.Intersect(state.Ray);
    const glm::vec3 direction = glm::normalize(state.Ray.Direction);
    if (!hit.Hit())
    {
      if (this->Environment)
      {
        // The environment is found only by BSDF sampling: full weight.
        state.Radiance += state.Throughput * this->Environment->Radiance(direction);
      }
      break;
    }
    const std::uint32_t triangle = hit.Triangle;
    const glm::vec3& normal = this->UnitNormals[triangle];
    const bool front = glm::dot(normal, direction) < 0.0f;
    const glm::vec3 position = (1.0f - hit.U - hit.V) * this->Scene.Vertex(triangle, 0) +
      hit.U * this->Scene.Vertex(triangle, 1) + hit.V * this->Scene.Vertex(triangle, 2);
    const glm::vec3& emission = this->Scene.MaterialOf(triangle).Emission;
    if (front && Positive(emission))
    {
      float weight = 1.0f;
      if (!state.LastSpecular && this->Parameters.Sampling == LightSampling::MultipleImportance)
      {
        weight =
          PowerHeuristic(state.LastPdf, this->LightPdf(triangle, state.Ray.Origin, position));
      }
      state.Radiance += state.Throughput * emission * weight;
    }
    const SurfacePoint point{ position, front ? normal : -normal, direction, triangle };
    if (!this->Scatter(point, false, state, rng))
    {
      break;
    }
  }
  return state.Radiance;
}

glm::vec3 PathTracer::Radiance(const SceneRay& ray, RandomSequence& rng) const
{
  PathState state;
  state.Ray = ray;
  return this->Trace(state, rng);
}

glm::vec3 PathTracer::DiffuseRadianceLeaving(
  std::uint32_t triangle, glm::vec3 point, int samples, std::uint64_t seed) const
{
  if (triangle >= this->Scene.TriangleCount() || samples < 1)
  {
    throw std::invalid_argument("DiffuseRadianceLeaving: triangle " + std::to_string(triangle) +
      " of " + std::to_string(this->Scene.TriangleCount()) + ", " + std::to_string(samples) +
      " samples (need a valid triangle and samples >= 1)");
  }
  const glm::vec3& normal = this->UnitNormals[triangle];
  if (normal == glm::vec3(0.0f))
  {
    throw std::invalid_argument(
      "DiffuseRadianceLeaving: triangle " + std::to_string(triangle) + " is degenerate");
  }
  return this->DiffuseRadianceLeaving(triangle, point, normal, samples, seed);
}

glm::vec3 PathTracer::DiffuseRadianceLeaving(
  std::uint32_t triangle, glm::vec3 point, glm::vec3 normal, int samples, std::uint64_t seed) const
{
  const float length = glm::length(normal);
  if (triangle >= this->Scene.TriangleCount() || samples < 1 || !(length > 0.0f) ||
    !std::isfinite(length))
  {
    throw std::invalid_argument("DiffuseRadianceLeaving: triangle " + std::to_string(triangle) +
      " of " + std::to_string(this->Scene.TriangleCount()) + ", " + std::to_string(samples) +
      " samples, a normal of length " + std::to_string(length) +
      " (need a valid triangle, samples >= 1 and a nonzero normal)");
  }
  normal /= length;
  glm::vec3 sum(0.0f);
  for (int s = 0; s < samples; ++s)
  {
    RandomSequence rng(SampleSeed(seed, triangle, static_cast<std::uint64_t>(s)));
    PathState state;
    const SurfacePoint surface{ point, normal, -normal, triangle };
    if (this->Scatter(surface, true, state, rng))
    {
      this->Trace(state, rng);
    }
    sum += state.Radiance;
  }
  return this->Scene.MaterialOf(triangle).Emission + sum / static_cast<float>(samples);
}

RgbImage PathTracer::RenderImage(const PinholeCamera& camera, int width, int height,
  int samplesPerPixel, std::uint64_t seed, const ProgressCallback& progress) const
{
  if (width < 1 || height < 1 || width > 16384 || height > 16384 || samplesPerPixel < 1 ||
    samplesPerPixel > (1 << 20) || !camera.Valid())
  {
    return RgbImage();
  }
  RgbImage image(width, height);
  const bool finished = ForEachTile(
    width, height, this->Parameters.TileSize, this->Parameters.Threads,
    [&](const TileRange& tile)
    {
      for (int j = tile.Y0; j < tile.Y1; ++j)
      {
        for (int i = tile.X0; i < tile.X1; ++i)
        {
          glm::vec3 sum(0.0f);
          const auto pixel = static_cast<std::uint64_t>(j) * static_cast<std::uint64_t>(width) +
            static_cast<std::uint64_t>(i);
          for (int s = 0; s < samplesPerPixel; ++s)
          {
            RandomSequence rng(SampleSeed(seed, pixel, static_cast<std::uint64_t>(s)));
            const float x = static_cast<float>(i) + rng.NextFloat();
            const float y = static_cast<float>(j) + rng.NextFloat();
            sum += this->Radiance(camera.Ray(x, y, width, height), rng);
          }
          sum /= static_cast<float>(samplesPerPixel);
          float* out = image.Pixel(i, j);
          out[0] = sum.x;
          out[1] = sum.y;
          out[2] = sum.z;
        }
      }
    },
    progress);
  return finished ? image : RgbImage();
}

} // namespace mesolight
