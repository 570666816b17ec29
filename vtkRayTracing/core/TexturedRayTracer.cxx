// SPDX-License-Identifier: BSD-3-Clause
#include "TexturedRayTracer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <mutex>
#include <stdexcept>

namespace mesolight
{

RayCounts& RayCounts::operator+=(const RayCounts& other)
{
  this->Primary += other.Primary;
  this->Shadow += other.Shadow;
  this->Secondary += other.Secondary;
  this->SupersampledPixels += other.SupersampledPixels;
  return *this;
}

namespace
{
bool Finite(const glm::vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}

bool NonNegative(const glm::vec3& v)
{
  return Finite(v) && v.x >= 0.0f && v.y >= 0.0f && v.z >= 0.0f;
}

float MaxComponent(const glm::vec3& v)
{
  return std::max(v.x, std::max(v.y, v.z));
}

bool UsableMap(const std::shared_ptr<const RgbImage>& map)
{
  return map && map->Width > 0 && map->Height > 0 &&
    map->Rgb.size() >=
    3u * static_cast<std::size_t>(map->Width) * static_cast<std::size_t>(map->Height);
}

std::string MaterialLabel(const TexturedMaterial& material, std::size_t index)
{
  return "material " + std::to_string(index) +
    (material.Name.empty() ? "" : " '" + material.Name + "'");
}

// Drops unusable maps with a warning; throws for values no shading can use.
void CheckMaterial(
  TexturedMaterial& material, std::size_t index, std::vector<std::string>& warnings)
{
  const std::string label = MaterialLabel(material, index);
  if (!NonNegative(material.Ambient) || !NonNegative(material.Diffuse) ||
    !NonNegative(material.Specular))
  {
    throw std::invalid_argument(label + " has a negative or non-finite colour");
  }
  if (!std::isfinite(material.SpecularPower) || material.SpecularPower < 0.0f ||
    !std::isfinite(material.Roughness) || material.Roughness < 0.0f ||
    !std::isfinite(material.BumpScale))
  {
    throw std::invalid_argument(
      label + " has a negative or non-finite specular power, roughness or bump scale");
  }
  if (material.Roughness > 1.0f)
  {
    warnings.push_back(
      label + ": roughness " + std::to_string(material.Roughness) + " clamped to 1");
    material.Roughness = 1.0f;
  }
  struct Channel
  {
    std::shared_ptr<const RgbImage>* Map;
    const char* Name;
  };
  for (const Channel& channel :
    { Channel{ &material.DiffuseMap, "diffuse" }, Channel{ &material.SpecularMap, "specular" },
      Channel{ &material.AmbientMap, "ambient" }, Channel{ &material.ShininessMap, "shininess" },
      Channel{ &material.BumpMap, "bump" }, Channel{ &material.RoughnessMap, "roughness" } })
  {
    if (*channel.Map && !UsableMap(*channel.Map))
    {
      warnings.push_back(
        label + ": the " + std::string(channel.Name) + " map is empty and is ignored");
      channel.Map->reset();
    }
  }
}
} // namespace

struct TexturedRayTracer::Surface
{
  glm::vec3 Position;
  glm::vec3 GeometricNormal; // unit, facing the arriving ray
  glm::vec3 Normal;          // unit shading normal (interpolated, bumped), same side
  glm::vec3 Incoming;        // unit direction of the arriving ray
  glm::vec2 TextureCoordinates{ 0.0f };
  TangentFrame Frame;
  const TexturedMaterial* Material;
};

TexturedRayTracer::TexturedRayTracer(TexturedScene scene, const RayTracerSettings& settings)
  : Data(std::move(scene))
  , Parameters(settings)
{
  if (settings.MaxDepth < 0 || settings.MaxDepth > 64 || settings.GlossySamples < 1 ||
    settings.GlossySamples > 1024 || !(settings.AdaptiveThreshold >= 0.0f) ||
    settings.TileSize < 1 || !(settings.RayEpsilon >= 0.0f && settings.RayEpsilon < 0.1f))
  {
    throw std::invalid_argument(
      "ray tracer settings out of range (MaxDepth in [0, 64], GlossySamples in "
      "[1, 1024], AdaptiveThreshold >= 0, TileSize >= 1, RayEpsilon in [0, 0.1))");
  }
  TriangleScene& mesh = this->Data.Mesh;
  if (mesh.Triangles.empty() && this->Data.Spheres.empty())
  {
    throw std::invalid_argument("the scene is empty (no triangles and no spheres)");
  }
  if (this->Data.Materials.empty())
  {
    throw std::invalid_argument("the scene has no materials");
  }
  for (std::size_t m = 0; m < this->Data.Materials.size(); ++m)
  {
    CheckMaterial(this->Data.Materials[m], m, this->Messages);
  }
  if (!mesh.Triangles.empty())
  {
    // CheckScene wants one SceneMaterial per id: mirror the textured materials' constants.
    mesh.Materials.clear();
    for (const TexturedMaterial& material : this->Data.Materials)
    {
      SceneMaterial plain;
      plain.Name = material.Name;
      plain.Diffuse = material.Diffuse;
      plain.Specular = material.Specular;
      plain.Ambient = material.Ambient;
      plain.Shininess = material.SpecularPower;
      plain.Roughness = material.Roughness;
      mesh.Materials.push_back(plain);
    }
    if (!mesh.Normals.empty() && mesh.Normals.size() != mesh.Positions.size())
    {
      throw std::invalid_argument("the mesh has " + std::to_string(mesh.Normals.size()) +
        " normals for " + std::to_string(mesh.Positions.size()) + " points");
    }
    if (!mesh.TextureCoordinates.empty() && mesh.TextureCoordinates.size() != mesh.Positions.size())
    {
      throw std::invalid_argument("the mesh has " + std::to_string(mesh.TextureCoordinates.size()) +
        " texture coordinates for " + std::to_string(mesh.Positions.size()) + " points");
    }
    const SceneCheck check = CheckScene(mesh, false);
    if (!check.Ok() &&
      !(check.DegenerateTriangles == mesh.Triangles.size() && !this->Data.Spheres.empty()))
    {
      throw std::invalid_argument(check.Errors.front());
    }
    const std::size_t dropped = RemoveDegenerateTriangles(mesh);
    if (dropped > 0)
    {
      this->Messages.push_back(
        std::to_string(dropped) + " degenerate (zero-area) triangles were dropped");
    }
  }
  std::vector<SceneSphere> spheres;
  glm::vec3 lower(std::numeric_limits<float>::max()), upper(std::numeric_limits<float>::lowest());
  SceneBounds(mesh, lower, upper);
  for (std::size_t s = 0; s < this->Data.Spheres.size(); ++s)
  {
    const TexturedSphere& sphere = this->Data.Spheres[s];
    if (!Finite(sphere.Geometry.Center) || !std::isfinite(sphere.Geometry.Radius) ||
      !(sphere.Geometry.Radius > 0.0f))
    {
      throw std::invalid_argument(
        "sphere " + std::to_string(s) + " has a non-finite centre or a radius <= 0");
    }
    if (sphere.Material >= this->Data.Materials.size())
    {
      throw std::invalid_argument("sphere " + std::to_string(s) + " refers to material " +
        std::to_string(sphere.Material) + " of " + std::to_string(this->Data.Materials.size()));
    }
    spheres.push_back(sphere.Geometry);
    lower = glm::min(lower, sphere.Geometry.Center - glm::vec3(sphere.Geometry.Radius));
    upper = glm::max(upper, sphere.Geometry.Center + glm::vec3(sphere.Geometry.Radius));
  }
  for (std::size_t l = 0; l < this->Data.Lights.size(); ++l)
  {
    const SceneLightSource& light = this->Data.Lights[l];
    if (!Finite(light.Position) || !Finite(light.Direction) || !NonNegative(light.Colour) ||
      !NonNegative(light.Attenuation) || !(glm::length(light.Direction) > 0.0f || light.Positional))
    {
      throw std::invalid_argument("light " + std::to_string(l) +
        " has a non-finite position, a zero direction, or a negative colour or attenuation");
    }
  }
  if (this->Data.Lights.empty())
  {
    this->Messages.emplace_back(
      "the scene has no lights: only ambient colours and reflections show");
  }
  this->Epsilon = settings.RayEpsilon * glm::length(upper - lower);
  this->Embree.reset(new EmbreeScene(this->Data.Mesh, std::move(spheres)));
}

TexturedRayTracer::~TexturedRayTracer() = default;

TexturedRayTracer::Surface TexturedRayTracer::SurfaceAt(
  const SceneHit& hit, const SceneRay& ray) const
{
  Surface surface;
  surface.Incoming = glm::normalize(ray.Direction);
  if (hit.Sphere != SceneHit::None)
  {
    const TexturedSphere& sphere = this->Data.Spheres[hit.Sphere];
    const glm::vec3 n = glm::normalize(ray.Origin + hit.T * ray.Direction - sphere.Geometry.Center);
    // Project onto the sphere so secondary rays start on it, whatever the float error of t.
    surface.Position = sphere.Geometry.Center + sphere.Geometry.Radius * n;
    surface.GeometricNormal = surface.Normal = n;
    surface.TextureCoordinates = SphereTextureCoordinates(n, sphere.Axis, sphere.Meridian);
    surface.Frame = SphereTangentFrame(n, sphere.Axis, sphere.Meridian);
    surface.Material = &this->Data.Materials[sphere.Material];
  }
  else
  {
    const TriangleScene& mesh = this->Data.Mesh;
    const std::uint32_t t = hit.Triangle;
    const glm::uvec3& corners = mesh.Triangles[t];
    const float w0 = 1.0f - hit.U - hit.V;
    const glm::vec3 p[3] = { mesh.Positions[corners.x], mesh.Positions[corners.y],
      mesh.Positions[corners.z] };
    surface.Position = w0 * p[0] + hit.U * p[1] + hit.V * p[2];
    surface.GeometricNormal = glm::normalize(glm::cross(p[1] - p[0], p[2] - p[0]));
    surface.Normal = surface.GeometricNormal;
    if (!mesh.Normals.empty())
    {
      const glm::vec3 n = w0 * mesh.Normals[corners.x] + hit.U * mesh.Normals[corners.y] +
        hit.V * mesh.Normals[corners.z];
      const float length = glm::length(n);
      if (length > 0.0f && std::isfinite(length))
      {
        surface.Normal = n / length;
        if (glm::dot(surface.Normal, surface.GeometricNormal) < 0.0f)
        {
          surface.GeometricNormal = -surface.GeometricNormal; // winding disagrees with the normals
        }
      }
    }
    if (!mesh.TextureCoordinates.empty())
    {
      const glm::vec2 st[3] = { mesh.TextureCoordinates[corners.x],
        mesh.TextureCoordinates[corners.y], mesh.TextureCoordinates[corners.z] };
      surface.TextureCoordinates = w0 * st[0] + hit.U * st[1] + hit.V * st[2];
      surface.Frame = TriangleTangentFrame(surface.Normal, p, st);
    }
    else
    {
      surface.Frame = FrameAroundNormal(surface.Normal);
    }
    surface.Material = &this->Data.Materials[mesh.MaterialIds[t]];
  }
  // Two-sided: shade the side the ray arrives on.
  if (glm::dot(surface.GeometricNormal, surface.Incoming) > 0.0f)
  {
    surface.GeometricNormal = -surface.GeometricNormal;
    surface.Normal = -surface.Normal;
  }
  if (glm::dot(surface.Normal, surface.Incoming) > 0.0f)
  {
    // An interpolated normal facing away from the viewer: use the geometric one.
    surface.Normal = surface.GeometricNormal;
  }
  return surface;
}

glm::vec3 TexturedRayTracer::ReflectedColour(
  const Surface& surface, float roughness, int depth, RandomSequence& rng, RayCounts& counts) const
{
  const glm::vec3 incoming = surface.Incoming;
  glm::vec3 mirror = incoming - 2.0f * glm::dot(incoming, surface.Normal) * surface.Normal;
  if (glm::dot(mirror, surface.GeometricNormal) <= 0.0f)
  {
    // A bumped normal can send the mirror ray into the surface: reflect about the true one.
    mirror =
      incoming - 2.0f * glm::dot(incoming, surface.GeometricNormal) * surface.GeometricNormal;
  }
  SceneRay ray;
  ray.Origin = surface.Position + this->Epsilon * surface.GeometricNormal;
  if (!(roughness > 0.0f))
  {
    ray.Direction = mirror;
    ++counts.Secondary;
    return this->Trace(ray, depth + 1, rng, counts);
  }
  // Ahern 1999 §2: rays D = R + s1 S + s2 T with s1, s2 uniform in [-roughness, roughness],
  // weighted linearly by their angle to R (a cone), averaged. The frame around R has no fixed
  // reference axis. Deeper reflections take one such ray.
  const TangentFrame frame = FrameAroundNormal(mirror);
  const float widest = std::atan(roughness * std::sqrt(2.0f));
  const int samples = depth == 0 ? this->Parameters.GlossySamples : 1;
  glm::vec3 sum(0.0f);
  float weights = 0.0f;
  for (int k = 0; k < samples; ++k)
  {
    const float s1 = (2.0f * rng.NextFloat() - 1.0f) * roughness;
    const float s2 = (2.0f * rng.NextFloat() - 1.0f) * roughness;
    const glm::vec3 direction = glm::normalize(mirror + s1 * frame.Tangent + s2 * frame.Bitangent);
    if (glm::dot(direction, surface.GeometricNormal) <= 0.0f)
    {
      continue; // below the surface
    }
    const float angle = std::acos(glm::clamp(glm::dot(direction, mirror), -1.0f, 1.0f));
    const float weight = samples == 1 ? 1.0f : std::max(1e-3f, 1.0f - angle / widest);
    ray.Direction = direction;
    ++counts.Secondary;
    sum += weight * this->Trace(ray, depth + 1, rng, counts);
    weights += weight;
  }
  return weights > 0.0f ? sum / weights : this->Data.Background;
}

glm::vec3 TexturedRayTracer::Trace(
  const SceneRay& ray, int depth, RandomSequence& rng, RayCounts& counts) const
{
  const SceneHit hit = this->Embree->Intersect(ray);
  if (!hit.Hit())
  {
    return this->Data.Background;
  }
  Surface surface = this->SurfaceAt(hit, ray);
  const TexturedMaterial& material = *surface.Material;
  const TextureFilter filter = this->Parameters.Filter;
  const glm::vec2 st = surface.TextureCoordinates;
  glm::vec3 kd = material.Diffuse;
  glm::vec3 ks = material.Specular;
  glm::vec3 ka = material.Ambient;
  float power = material.SpecularPower;
  float roughness = material.Roughness;
  if (material.DiffuseMap)
  {
    kd *= SampleTexture(*material.DiffuseMap, st, filter);
  }
  if (material.SpecularMap)
  {
    ks *= SampleTexture(*material.SpecularMap, st, filter);
  }
  if (material.AmbientMap)
  {
    ka *= SampleTexture(*material.AmbientMap, st, filter);
  }
  if (material.ShininessMap)
  {
    power *= SampleTexture(*material.ShininessMap, st, filter).x;
  }
  if (material.RoughnessMap)
  {
    roughness =
      glm::clamp(roughness * SampleTexture(*material.RoughnessMap, st, filter).x, 0.0f, 1.0f);
  }
  if (material.BumpMap)
  {
    surface.Normal = BumpedNormal(surface.Normal, surface.Frame,
      SampleTexture(*material.BumpMap, st, filter), material.BumpScale);
  }
  const glm::vec3 n = surface.Normal;
  const glm::vec3 toViewer = -surface.Incoming;
  const glm::vec3 origin = surface.Position + this->Epsilon * surface.GeometricNormal;
  glm::vec3 colour = ka;
  for (const SceneLightSource& light : this->Data.Lights)
  {
    glm::vec3 toLight;
    float distance = std::numeric_limits<float>::infinity();
    glm::vec3 intensity = light.Colour;
    if (light.Positional)
    {
      const glm::vec3 offset = light.Position - surface.Position;
      distance = glm::length(offset);
      if (!(distance > 0.0f))
      {
        continue;
      }
      toLight = offset / distance;
      const float attenuation = light.Attenuation.x + light.Attenuation.y * distance +
        light.Attenuation.z * distance * distance;
      intensity /= std::max(attenuation, 1e-12f);
      if (light.ConeAngleDegrees < 90.0f)
      {
        const float axisLength = glm::length(light.Direction);
        const float cosine =
          axisLength > 0.0f ? glm::dot(-toLight, light.Direction / axisLength) : 1.0f;
        if (cosine < std::cos(glm::radians(light.ConeAngleDegrees)))
        {
          continue;
        }
        intensity *= std::pow(std::max(cosine, 0.0f), light.Exponent);
      }
    }
    else
    {
      toLight = -glm::normalize(light.Direction);
    }
    const float nDotL = glm::dot(n, toLight);
    if (nDotL <= 0.0f || glm::dot(surface.GeometricNormal, toLight) <= 0.0f)
    {
      continue;
    }
    if (this->Parameters.Shadows && light.CastsShadows)
    {
      SceneRay shadow;
      shadow.Origin = origin;
      shadow.Direction = toLight;
      shadow.TFar = std::isfinite(distance) ? distance - 2.0f * this->Epsilon
                                            : std::numeric_limits<float>::infinity();
      ++counts.Shadow;
      if (this->Embree->Occluded(shadow))
      {
        continue;
      }
    }
    glm::vec3 lit = kd * nDotL;
    if (MaxComponent(ks) > 0.0f)
    {
      const glm::vec3 reflected = 2.0f * nDotL * n - toLight;
      lit += ks * std::pow(std::max(0.0f, glm::dot(reflected, toViewer)), power);
    }
    colour += intensity * lit;
  }
  if (this->Parameters.Reflections && depth < this->Parameters.MaxDepth && MaxComponent(ks) > 1e-3f)
  {
    colour += ks * this->ReflectedColour(surface, roughness, depth, rng, counts);
  }
  return colour;
}

std::vector<std::uint8_t> TexturedRayTracer::EdgePixels(const RgbImage& image, float threshold)
{
  const int w = image.Width;
  const int h = image.Height;
  std::vector<std::uint8_t> edges(static_cast<std::size_t>(w) * static_cast<std::size_t>(h), 0);
  auto differs = [&](int i, int j, int k, int l)
  {
    const float* a = image.Pixel(i, j);
    const float* b = image.Pixel(k, l);
    return std::abs(a[0] - b[0]) > threshold || std::abs(a[1] - b[1]) > threshold ||
      std::abs(a[2] - b[2]) > threshold;
  };
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      edges[static_cast<std::size_t>(j) * w + i] = static_cast<std::uint8_t>(
        (i > 0 && differs(i, j, i - 1, j)) || (i + 1 < w && differs(i, j, i + 1, j)) ||
        (j > 0 && differs(i, j, i, j - 1)) || (j + 1 < h && differs(i, j, i, j + 1)));
    }
  }
  return edges;
}

RgbImage TexturedRayTracer::Render(const PinholeCamera& camera, int width, int height,
  const RefinementCallback& refinement, const ProgressCallback& progress) const
{
  this->Counts = RayCounts{};
  if (width < 1 || height < 1 || width > 16384 || height > 16384 || !camera.Valid())
  {
    return RgbImage();
  }
  RgbImage image(width, height);
  std::mutex countsMutex;
  RayCounts total;
  auto pixelIndex = [width](int i, int j)
  {
    return static_cast<std::uint64_t>(j) * static_cast<std::uint64_t>(width) +
      static_cast<std::uint64_t>(i);
  };
  auto traceSample = [&](int i, int j, float x, float y, std::uint64_t sample, RayCounts& counts)
  {
    RandomSequence rng(SampleSeed(this->Parameters.Seed, pixelIndex(i, j), sample));
    ++counts.Primary;
    return this->Trace(camera.Ray(x, y, width, height), 0, rng, counts);
  };
  auto store = [](float* out, const glm::vec3& c)
  {
    out[0] = c.x;
    out[1] = c.y;
    out[2] = c.z;
  };
  // Progressive refinement (Ahern 1999 §4): the pixel at the corner of each block of the current
  // level is traced and fills its block; a pixel traced at a coarser level is never traced
  // again. Without it, one level of block size 1.
  int block = 1;
  if (this->Parameters.Progressive)
  {
    while (block < std::max(width, height))
    {
      block *= 2;
    }
  }
  for (int size = block; size >= 1; size /= 2)
  {
    const int columns = (width + size - 1) / size;
    const int rows = (height + size - 1) / size;
    const bool coarsest = size == block;
    const bool finished = ForEachTile(
      columns, rows, this->Parameters.TileSize, this->Parameters.Threads,
      [&](const TileRange& tile)
      {
        RayCounts counts;
        for (int gj = tile.Y0; gj < tile.Y1; ++gj)
        {
          for (int gi = tile.X0; gi < tile.X1; ++gi)
          {
            const int i = gi * size;
            const int j = gj * size;
            if (!coarsest && i % (2 * size) == 0 && j % (2 * size) == 0)
            {
              continue; // traced at a coarser level; its block already holds its colour
            }
            const glm::vec3 c = traceSample(i, j, i + 0.5f, j + 0.5f, 0, counts);
            for (int y = j; y < std::min(height, j + size); ++y)
            {
              for (int x = i; x < std::min(width, i + size); ++x)
              {
                store(image.Pixel(x, y), c);
              }
            }
          }
        }
        std::lock_guard<std::mutex> lock(countsMutex);
        total += counts;
      },
      progress);
    if (!finished || (this->Parameters.Progressive && refinement && !refinement(image, size)))
    {
      this->Counts = total;
      return RgbImage();
    }
  }
  if (this->Parameters.AdaptiveSupersampling)
  {
    // Ahern 1999 §3: pixels differing from a neighbour get a regular 3 x 3 grid of rays; the
    // centre ray is the pixel's first sample, reused.
    const std::vector<std::uint8_t> edges = EdgePixels(image, this->Parameters.AdaptiveThreshold);
    const bool finished = ForEachTile(
      width, height, this->Parameters.TileSize, this->Parameters.Threads,
      [&](const TileRange& tile)
      {
        RayCounts counts;
        for (int j = tile.Y0; j < tile.Y1; ++j)
        {
          for (int i = tile.X0; i < tile.X1; ++i)
          {
            if (!edges[pixelIndex(i, j)])
            {
              continue;
            }
            float* out = image.Pixel(i, j);
            glm::vec3 sum(out[0], out[1], out[2]);
            std::uint64_t sample = 1;
            for (int b = 0; b < 3; ++b)
            {
              for (int a = 0; a < 3; ++a)
              {
                if (a == 1 && b == 1)
                {
                  continue;
                }
                sum +=
                  traceSample(i, j, i + (a + 0.5f) / 3.0f, j + (b + 0.5f) / 3.0f, sample++, counts);
              }
            }
            store(out, sum / 9.0f);
            ++counts.SupersampledPixels;
          }
        }
        std::lock_guard<std::mutex> lock(countsMutex);
        total += counts;
      },
      progress);
    if (!finished || (refinement && !refinement(image, 0)))
    {
      this->Counts = total;
      return RgbImage();
    }
  }
  this->Counts = total;
  return image;
}

} // namespace mesolight
