// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectShadows.h"

#include "LightField.h"
#include "MathConstants.h"
#include "OrthonormalBasis.h"
#include "ParallelFor.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <limits>

namespace mesolight
{
namespace vlf
{

namespace
{
constexpr const char* ModeNames[] = { "none", "black", "blend", "field", "pcf", "soft" };

float Mean(const glm::vec3& v)
{
  return (v.x + v.y + v.z) / 3.0f;
}

// Twice the signed area of (a, b, c) in the map's pixel plane.
float Edge(const glm::vec2& a, const glm::vec2& b, const glm::vec2& c)
{
  return (b.x - a.x) * (c.y - a.y) - (b.y - a.y) * (c.x - a.x);
}

// The sphere about the object's bounding-box centre holding all its points: its radius.
float BoundingRadius(const ObjectMesh& object, glm::vec3& centre)
{
  glm::vec3 lower, upper;
  object.Bounds(lower, upper);
  centre = 0.5f * (lower + upper);
  float radius = 0.0f;
  for (const glm::vec3& p : object.Positions)
  {
    radius = std::max(radius, glm::length(p - centre));
  }
  return radius;
}
} // namespace

//------------------------------------------------------------------------------
const char* ShadowModeName(ShadowMode mode)
{
  const int m = static_cast<int>(mode);
  return m >= 0 && m <= 5 ? ModeNames[m] : "unknown";
}

//------------------------------------------------------------------------------
bool ShadowModeFromName(const std::string& name, ShadowMode& mode)
{
  for (int m = 0; m <= 5; ++m)
  {
    if (name == ModeNames[m])
    {
      mode = static_cast<ShadowMode>(m);
      return true;
    }
  }
  return false;
}

//------------------------------------------------------------------------------
std::string ShadowSettings::Validate() const
{
  if (this->Resolution < 16 || this->Resolution > 4096)
  {
    return "shadow map resolution " + std::to_string(this->Resolution) + " is not in [16, 4096]";
  }
  if (this->MaximumEmitters < 1 || this->MaximumEmitters > 8)
  {
    return "shadow emitter count " + std::to_string(this->MaximumEmitters) + " is not in [1, 8]";
  }
  if (this->AreaSamples < 1 || this->AreaSamples > 4)
  {
    return "shadow area samples " + std::to_string(this->AreaSamples) + " is not in [1, 4]";
  }
  if (this->PcfKernel < 1 || this->PcfKernel > 9 || this->PcfKernel % 2 == 0)
  {
    return "PCF kernel " + std::to_string(this->PcfKernel) + " is not an odd number in [1, 9]";
  }
  if (!(this->BlendAlpha >= 0.0f && this->BlendAlpha <= 1.0f))
  {
    return "shadow blend alpha is not in [0, 1]";
  }
  if (!(this->DepthBias >= 0.0f) || !(this->MinimumPowerFraction >= 0.0f))
  {
    return "shadow depth bias and minimum power fraction must not be negative";
  }
  return std::string();
}

//------------------------------------------------------------------------------
float ShadowMapBlocked(const ShadowMap& map, const glm::vec3& p, const glm::vec3& n, int kernel,
  float bias, bool removeBackProjection)
{
  if (map.Resolution < 1)
  {
    return 0.0f;
  }
  const glm::vec3 d = p - map.Position;
  const float ez = glm::dot(d, map.AxisZ);
  // Back projection (Wither 2005 ch. 4): a receiver facing away from the light gets none of its
  // direct light to lose, and one behind the near plane (behind the light) would see the
  // object's image mirrored through the centre of projection.
  if (removeBackProjection && (glm::dot(n, -d) <= 0.0f || ez < map.Near))
  {
    return 0.0f;
  }
  if (ez == 0.0f)
  {
    return 0.0f; // on the light's plane: projects to infinity
  }
  const float scale = 1.0f / (ez * map.TanHalfAngle);
  const float fx = (glm::dot(d, map.AxisX) * scale * 0.5f + 0.5f) * map.Resolution;
  const float fy = (glm::dot(d, map.AxisY) * scale * 0.5f + 0.5f) * map.Resolution;
  const float limit = 2.0f * map.Resolution;
  if (!(std::abs(fx) < limit && std::abs(fy) < limit))
  {
    return 0.0f; // far outside (or not finite)
  }
  const int ix = static_cast<int>(std::floor(fx)), iy = static_cast<int>(std::floor(fy));
  const int half = kernel / 2;
  const float inverse = 1.0f / ez; // a plain depth test: negative (behind) is "farther"
  int blocked = 0;
  for (int y = iy - half; y <= iy + half; ++y)
  {
    for (int x = ix - half; x <= ix + half; ++x)
    {
      if (x < 0 || y < 0 || x >= map.Resolution || y >= map.Resolution)
      {
        continue; // outside the frustum the object covers nothing
      }
      const float depth = map.Depth[static_cast<std::size_t>(y) * map.Resolution + x];
      if (depth < ShadowMap::EmptyDepth && inverse < 1.0f / (depth * (1.0f + 1e-4f) + bias))
      {
        ++blocked;
      }
    }
  }
  return static_cast<float>(blocked) / static_cast<float>(kernel * kernel);
}

//------------------------------------------------------------------------------
glm::vec3 SampleIrradiance(const glm::vec3& le, const glm::vec3& ne, const glm::vec4& sample,
  const glm::vec3& p, const glm::vec3& n)
{
  const glm::vec3 toLight = glm::vec3(sample) - p;
  const float d2 = glm::dot(toLight, toLight);
  if (!(d2 > 0.0f))
  {
    return glm::vec3(0.0f);
  }
  const glm::vec3 w = toLight / std::sqrt(d2);
  const float cosLight = std::max(0.0f, -glm::dot(ne, w));
  const float cosReceiver = std::max(0.0f, glm::dot(n, w));
  return le * (sample.w * cosLight * cosReceiver / d2);
}

//------------------------------------------------------------------------------
std::vector<ShadowEmitter> SignificantEmitters(
  const LightField& field, const ShadowSettings& settings)
{
  std::vector<ShadowEmitter> out;
  // One light per lamp, merged down to the emitters that may cast shadows, so a room of more
  // lamps keeps all their light in the shadows' share (the first few alone would leave the rest
  // of the direct light unshadowed).
  EmitterLightOptions options;
  options.MaxLights = static_cast<std::size_t>(std::max(1, settings.MaximumEmitters));
  const LightApproximation lights = EstimateEmitterLights(field, options); // brightest first
  const TriangleScene& scene = field.Scene();
  const float strongest = lights.Lights.empty() ? 0.0f : Mean(lights.Lights[0].Intensity());
  float total = 0.0f;
  for (const EmitterLight& light : lights.Lights)
  {
    const float power = Mean(light.Intensity());
    if (static_cast<int>(out.size()) >= settings.MaximumEmitters ||
      !(power > 0.0f && power >= settings.MinimumPowerFraction * strongest))
    {
      break;
    }
    ShadowEmitter emitter;
    emitter.Light = light;
    emitter.PowerWeight = power;
    total += power;
    // Its lamps (a cell of a cut surface: the surface), each sampled by the g x g stratified
    // cell centres of its bounding rectangle in its plane that lie on one of its triangles, each
    // standing for an equal share of the area. A merged emitter's m lamps take g / sqrt(m) per
    // side each (at least 1; more lamps than g^2: g^2 of them, spread over the list), so that an
    // emitter never has more than g^2 samples (the GPU's budget of maps and samples is counted
    // in them).
    const Surface& surface = field.Surfaces()[light.Surface];
    std::vector<std::vector<std::uint32_t>> lamps = light.Triangles.empty()
      ? std::vector<std::vector<std::uint32_t>>{ surface.Triangles }
      : LampsOf(scene, light.Triangles);
    const std::size_t budget = static_cast<std::size_t>(settings.AreaSamples) *
      static_cast<std::size_t>(settings.AreaSamples);
    if (lamps.size() > budget)
    {
      std::vector<std::vector<std::uint32_t>> spread;
      for (std::size_t k = 0; k < budget; ++k)
      {
        spread.push_back(std::move(lamps[k * lamps.size() / budget]));
      }
      lamps = std::move(spread);
    }
    emitter.Lamps = static_cast<std::uint32_t>(lamps.size());
    const int g = std::max(1,
      static_cast<int>(
        std::floor(settings.AreaSamples / std::sqrt(static_cast<double>(lamps.size())))));
    std::vector<glm::vec3> points;
    for (const std::vector<std::uint32_t>& lamp : lamps)
    {
      if (lamp.empty())
      {
        continue;
      }
      // The lamp's plane: the surface's frame, or (a lamp merged from another surface) one of
      // its own normal.
      glm::vec3 origin = surface.Origin, axisU = surface.AxisU, axisV = surface.AxisV;
      glm::vec3 normal = surface.Normal;
      const glm::vec3 face = scene.FaceNormal(lamp.front());
      const float faceLength = glm::length(face);
      if (faceLength > 0.0f && glm::dot(face / faceLength, normal) < 0.9999f)
      {
        normal = face / faceLength;
        origin = scene.Vertex(lamp.front(), 0);
        OrthonormalBasis(normal, axisU, axisV);
      }
      auto uv = [&](const glm::vec3& x)
      { return glm::vec2(glm::dot(x - origin, axisU), glm::dot(x - origin, axisV)); };
      const float offset = glm::dot(scene.Vertex(lamp.front(), 0) - origin, normal);
      glm::vec2 lower(1e30f), upper(-1e30f);
      for (const std::uint32_t t : lamp)
      {
        for (int c = 0; c < 3; ++c)
        {
          lower = glm::min(lower, uv(scene.Vertex(t, c)));
          upper = glm::max(upper, uv(scene.Vertex(t, c)));
        }
      }
      for (int b = 0; b < g; ++b)
      {
        for (int a = 0; a < g; ++a)
        {
          const glm::vec2 q = lower + (upper - lower) * glm::vec2((a + 0.5f) / g, (b + 0.5f) / g);
          for (const std::uint32_t t : lamp)
          {
            const glm::vec2 p0 = uv(scene.Vertex(t, 0)), p1 = uv(scene.Vertex(t, 1)),
                            p2 = uv(scene.Vertex(t, 2));
            const float area = Edge(p0, p1, p2);
            if (area == 0.0f)
            {
              continue;
            }
            const float w0 = Edge(p1, p2, q) / area, w1 = Edge(p2, p0, q) / area,
                        w2 = Edge(p0, p1, q) / area;
            if (w0 >= 0.0f && w1 >= 0.0f && w2 >= 0.0f)
            {
              points.push_back(origin + q.x * axisU + q.y * axisV + offset * normal);
              break;
            }
          }
        }
      }
    }
    if (points.empty())
    {
      points.push_back(light.Position);
    }
    const float share = static_cast<float>(light.Area / static_cast<double>(points.size()));
    for (const glm::vec3& q : points)
    {
      emitter.Samples.emplace_back(q, share);
    }
    out.push_back(std::move(emitter));
  }
  for (ShadowEmitter& emitter : out)
  {
    emitter.PowerWeight /= total;
  }
  return out;
}

//------------------------------------------------------------------------------
bool PerSampleMaps(ShadowMode mode, const ShadowEmitter& emitter)
{
  return mode == ShadowMode::Soft ||
    ((mode == ShadowMode::Field || mode == ShadowMode::PCF) && emitter.Lamps > 1);
}

//------------------------------------------------------------------------------
std::vector<float> PackEmitters(const std::vector<ShadowEmitter>& emitters)
{
  std::vector<float> out;
  for (const ShadowEmitter& e : emitters)
  {
    const EmitterLight& l = e.Light;
    const float head[] = { static_cast<float>(l.Surface), l.Position.x, l.Position.y, l.Position.z,
      l.Normal.x, l.Normal.y, l.Normal.z, l.Radiance.x, l.Radiance.y, l.Radiance.z,
      static_cast<float>(l.Area), e.PowerWeight, static_cast<float>(e.Lamps),
      static_cast<float>(e.Samples.size()) };
    out.insert(out.end(), std::begin(head), std::end(head));
    for (const glm::vec4& s : e.Samples)
    {
      out.insert(out.end(), { s.x, s.y, s.z, s.w });
    }
  }
  return out;
}

//------------------------------------------------------------------------------
bool UnpackEmitters(const float* values, std::size_t count, std::vector<ShadowEmitter>& emitters)
{
  constexpr std::size_t head = 14;
  emitters.clear();
  std::size_t i = 0;
  while (i < count)
  {
    if (count - i < head)
    {
      emitters.clear();
      return false;
    }
    const float* v = values + i;
    const float samples = v[13];
    if (!(samples >= 0.0f && samples <= 4096.0f) || v[0] < 0.0f || !(v[12] >= 1.0f) ||
      (count - i - head) / 4 < static_cast<std::size_t>(samples))
    {
      emitters.clear();
      return false;
    }
    ShadowEmitter e;
    e.Light.Surface = static_cast<std::uint32_t>(v[0]);
    e.Light.Position = glm::vec3(v[1], v[2], v[3]);
    e.Light.Normal = glm::vec3(v[4], v[5], v[6]);
    e.Light.Radiance = glm::vec3(v[7], v[8], v[9]);
    e.Light.Area = v[10];
    e.PowerWeight = v[11];
    e.Lamps = static_cast<std::uint32_t>(std::min(v[12], 1e6f));
    const std::size_t n = static_cast<std::size_t>(samples);
    for (std::size_t k = 0; k < n; ++k)
    {
      const float* s = v + head + 4 * k;
      e.Samples.emplace_back(s[0], s[1], s[2], s[3]);
    }
    emitters.push_back(std::move(e));
    i += head + 4 * n;
  }
  return true;
}

//------------------------------------------------------------------------------
bool FillShadowMap(ShadowMap& map, const glm::vec3& light, const ObjectMesh& object,
  const glm::vec3& centre, float radius, int resolution)
{
  map.Position = light;
  map.Resolution = resolution;
  map.Depth.assign(static_cast<std::size_t>(resolution) * resolution, ShadowMap::EmptyDepth);
  if (object.Triangles.empty())
  {
    return false;
  }
  glm::vec3 axis = centre - light;
  const float distance = glm::length(axis);
  axis = distance > 0.0f ? axis / distance : glm::vec3(0.0f, 0.0f, 1.0f);
  map.AxisZ = axis;
  OrthonormalBasis(axis, map.AxisX, map.AxisY);
  if (distance > radius * 1.001f)
  {
    // The frustum tangent to the bounding sphere (a little wider, so its silhouette triangles
    // stay inside); every sphere point has an eye depth in [d - r, d + r].
    const float s = radius / distance;
    map.TanHalfAngle = 1.01f * s / std::sqrt(1.0f - s * s);
    map.Near = 0.999f * (distance - radius);
  }
  else
  {
    map.TanHalfAngle = std::tan(80.0f * Pi<float> / 180.0f);
    map.Near = 1e-4f * std::max(radius, 1e-3f);
  }
  map.Far = distance + radius;

  const float res = static_cast<float>(resolution);
  for (const glm::uvec3& t : object.Triangles)
  {
    glm::vec2 s[3];
    float inverseDepth[3];
    bool usable = true;
    for (int c = 0; c < 3; ++c)
    {
      const glm::vec3 d = object.Positions[t[c]] - light;
      const float z = glm::dot(d, map.AxisZ);
      if (!(z >= map.Near))
      {
        usable = false; // crosses the near plane (a light inside the object's bounds)
        break;
      }
      const float scale = 1.0f / (z * map.TanHalfAngle);
      s[c] = glm::vec2((glm::dot(d, map.AxisX) * scale * 0.5f + 0.5f) * res,
        (glm::dot(d, map.AxisY) * scale * 0.5f + 0.5f) * res);
      inverseDepth[c] = 1.0f / z;
    }
    if (!usable)
    {
      continue;
    }
    const float area = Edge(s[0], s[1], s[2]);
    if (!(std::abs(area) > 1e-12f))
    {
      continue;
    }
    const glm::vec2 lower = glm::min(s[0], glm::min(s[1], s[2]));
    const glm::vec2 upper = glm::max(s[0], glm::max(s[1], s[2]));
    const int x0 = std::max(0, static_cast<int>(std::ceil(lower.x - 0.5f)));
    const int y0 = std::max(0, static_cast<int>(std::ceil(lower.y - 0.5f)));
    const int x1 = std::min(resolution - 1, static_cast<int>(std::floor(upper.x - 0.5f)));
    const int y1 = std::min(resolution - 1, static_cast<int>(std::floor(upper.y - 0.5f)));
    for (int y = y0; y <= y1; ++y)
    {
      for (int x = x0; x <= x1; ++x)
      {
        // Texel centres inside either winding (both faces cast shadows); 1/z is linear in the
        // image plane, so its barycentric blend is the perspective-correct depth.
        const glm::vec2 q(x + 0.5f, y + 0.5f);
        const float w0 = Edge(s[1], s[2], q) / area, w1 = Edge(s[2], s[0], q) / area,
                    w2 = Edge(s[0], s[1], q) / area;
        if (w0 < 0.0f || w1 < 0.0f || w2 < 0.0f)
        {
          continue;
        }
        const float z = 1.0f / (w0 * inverseDepth[0] + w1 * inverseDepth[1] + w2 * inverseDepth[2]);
        float& texel = map.Depth[static_cast<std::size_t>(y) * resolution + x];
        texel = std::min(texel, z);
      }
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void ObjectShadows::Clear()
{
  this->EmitterList.clear();
  this->MapList.clear();
  this->EmitterMaps.clear();
  this->Seconds = 0.0;
}

//------------------------------------------------------------------------------
std::string ObjectShadows::Build(
  const LightField& field, const ObjectMesh& object, const ShadowSettings& settings, int threads)
{
  this->Clear();
  const std::string problem = settings.Validate();
  if (!problem.empty())
  {
    return problem;
  }
  const std::vector<ShadowEmitter> emitters = SignificantEmitters(field, settings);
  this->SetAmbient(EstimateShadowIndirect(field, emitters, object));
  return this->Build(emitters, object, settings, threads);
}

//------------------------------------------------------------------------------
std::string ObjectShadows::Build(const std::vector<ShadowEmitter>& emitters,
  const ObjectMesh& object, const ShadowSettings& settings, int threads)
{
  const auto start = std::chrono::steady_clock::now();
  this->Clear();
  std::string problem = settings.Validate();
  if (problem.empty())
  {
    problem = object.Validate(); // degenerate triangles among others: the rasteriser skips them
  }
  if (problem.empty() && emitters.empty())
  {
    problem = "the light field has no emitter to cast shadows from";
  }
  if (!problem.empty())
  {
    return problem;
  }
  this->Config = settings;
  this->EmitterList = emitters;
  glm::vec3 centre;
  const float radius = std::max(BoundingRadius(object, centre), 1e-6f);
  // Per emitter its centroid's map first (Black, Blend, Field, PCF), then one map per sample
  // point: in Soft mode, and in Field and PCF for an emitter of merged lamps (PerSampleMaps).
  std::vector<glm::vec3> lights;
  this->EmitterMaps.resize(emitters.size());
  for (std::size_t e = 0; e < emitters.size(); ++e)
  {
    this->EmitterMaps[e].push_back(static_cast<std::uint32_t>(lights.size()));
    lights.push_back(emitters[e].Light.Position);
    if (PerSampleMaps(settings.Mode, emitters[e]))
    {
      for (const glm::vec4& s : emitters[e].Samples)
      {
        this->EmitterMaps[e].push_back(static_cast<std::uint32_t>(lights.size()));
        lights.push_back(glm::vec3(s));
      }
    }
  }
  this->MapList.resize(lights.size());
  for (std::size_t e = 0; e < emitters.size(); ++e)
  {
    for (const std::uint32_t m : this->EmitterMaps[e])
    {
      this->MapList[m].Emitter = static_cast<std::uint32_t>(e);
    }
  }
  ParallelFor(
    0, lights.size(), 1,
    [&](std::size_t m0, std::size_t m1)
    {
      for (std::size_t m = m0; m < m1; ++m)
      {
        FillShadowMap(this->MapList[m], lights[m], object, centre, radius, settings.Resolution);
      }
    },
    threads);
  this->Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return std::string();
}

//------------------------------------------------------------------------------
glm::vec3 ObjectShadows::DirectIrradiance(
  std::size_t e, const glm::vec3& p, const glm::vec3& n) const
{
  const ShadowEmitter& emitter = this->EmitterList[e];
  glm::vec3 sum(0.0f);
  for (const glm::vec4& s : emitter.Samples)
  {
    sum += SampleIrradiance(emitter.Light.Radiance, emitter.Light.Normal, s, p, n);
  }
  return sum;
}

//------------------------------------------------------------------------------
float ObjectShadows::BlockedFraction(std::size_t e, const glm::vec3& p, const glm::vec3& n) const
{
  const ShadowSettings& c = this->Config;
  const std::vector<std::uint32_t>& maps = this->EmitterMaps[e];
  if (PerSampleMaps(c.Mode, this->EmitterList[e]) && maps.size() > 1)
  {
    const ShadowEmitter& emitter = this->EmitterList[e];
    float blocked = 0.0f, weight = 0.0f;
    for (std::size_t i = 0; i < emitter.Samples.size(); ++i)
    {
      const float w = Mean(
        SampleIrradiance(emitter.Light.Radiance, emitter.Light.Normal, emitter.Samples[i], p, n));
      blocked += w *
        ShadowMapBlocked(this->MapList[maps[i + 1]], p, n, 1, c.DepthBias, c.RemoveBackProjection);
      weight += w;
    }
    return weight > 0.0f ? blocked / weight : 0.0f;
  }
  const int kernel = c.Mode == ShadowMode::PCF ? c.PcfKernel : 1;
  return ShadowMapBlocked(
    this->MapList[maps[0]], p, n, kernel, c.DepthBias, c.RemoveBackProjection);
}

//------------------------------------------------------------------------------
float ObjectShadows::Visibility(const glm::vec3& p, const glm::vec3& n) const
{
  float blocked = 0.0f;
  for (std::size_t e = 0; e < this->EmitterList.size(); ++e)
  {
    blocked += this->EmitterList[e].PowerWeight *
      ShadowMapBlocked(this->MapList[this->EmitterMaps[e][0]], p, n, 1, this->Config.DepthBias,
        this->Config.RemoveBackProjection);
  }
  return std::max(0.0f, 1.0f - blocked);
}

//------------------------------------------------------------------------------
glm::vec3 ObjectShadows::Shade(
  const glm::vec3& total, const glm::vec3& p, const glm::vec3& n, const glm::vec3& kd) const
{
  const ShadowSettings& c = this->Config;
  if (this->EmitterList.empty() || c.Mode == ShadowMode::None)
  {
    return total;
  }
  if (c.Mode == ShadowMode::Black || c.Mode == ShadowMode::Blend)
  {
    const float alpha = c.Mode == ShadowMode::Black ? 1.0f : c.BlendAlpha;
    return total * (1.0f - alpha * (1.0f - this->Visibility(p, n)));
  }
  // Field, PCF, Soft: the direct light the object blocks, from the emitters' samples.
  glm::vec3 lost(0.0f);
  bool blocked = false;
  for (std::size_t e = 0; e < this->EmitterList.size(); ++e)
  {
    const ShadowEmitter& emitter = this->EmitterList[e];
    const std::vector<std::uint32_t>& maps = this->EmitterMaps[e];
    if (PerSampleMaps(c.Mode, emitter) && maps.size() > 1)
    {
      for (std::size_t i = 0; i < emitter.Samples.size(); ++i)
      {
        const float b = ShadowMapBlocked(
          this->MapList[maps[i + 1]], p, n, 1, c.DepthBias, c.RemoveBackProjection);
        if (b > 0.0f) // lit receivers (most) skip the irradiance
        {
          blocked = true;
          lost += b *
            SampleIrradiance(
              emitter.Light.Radiance, emitter.Light.Normal, emitter.Samples[i], p, n);
        }
      }
    }
    else
    {
      const float b = this->BlockedFraction(e, p, n);
      if (b > 0.0f)
      {
        blocked = true;
        lost += b * this->DirectIrradiance(e, p, n);
      }
    }
  }
  if (!blocked)
  {
    return total;
  }
  if (!this->HaveAmbient)
  {
    return glm::max(glm::vec3(0.0f), total - kd / Pi<float> * lost);
  }
  // The ratio (see the header); Kd cancels per channel.
  glm::vec3 direct(0.0f);
  for (std::size_t e = 0; e < this->EmitterList.size(); ++e)
  {
    direct += this->DirectIrradiance(e, p, n);
  }
  const glm::vec3 lit = this->AmbientRadiance + direct / Pi<float>;
  const glm::vec3 shadowed =
    this->AmbientRadiance + glm::max(glm::vec3(0.0f), direct - lost) / Pi<float>;
  glm::vec3 ratio(1.0f);
  for (int k = 0; k < 3; ++k)
  {
    if (lit[k] > 0.0f)
    {
      ratio[k] = std::min(1.0f, std::max(0.0f, shadowed[k] / lit[k]));
    }
  }
  return total * ratio;
}

//------------------------------------------------------------------------------
ShadowGpuData PackShadowsForGpu(const ObjectShadows& shadows)
{
  ShadowGpuData out;
  const ShadowSettings& c = shadows.Settings();
  out.Mode = static_cast<int>(c.Mode);
  out.Params = glm::vec4(c.DepthBias, c.BlendAlpha, static_cast<float>(c.PcfKernel),
    c.RemoveBackProjection ? 1.0f : 0.0f);
  out.Ambient = glm::vec4(shadows.Ambient(), shadows.HasAmbient() ? 1.0f : 0.0f);
  if (shadows.Empty())
  {
    out.Mode = 0;
    return out;
  }
  // The emitters (strongest first) whose maps and samples fit.
  std::vector<std::uint32_t> maps;
  for (std::size_t e = 0; e < shadows.Emitters().size(); ++e)
  {
    const ShadowEmitter& emitter = shadows.Emitters()[e];
    const std::vector<std::uint32_t>& own = shadows.MapsOf(e);
    if (out.EmitterCount >= GpuShadowEmitters ||
      maps.size() + own.size() > static_cast<std::size_t>(GpuShadowMaps) ||
      out.Samples.size() + emitter.Samples.size() > static_cast<std::size_t>(GpuShadowSamples))
    {
      break;
    }
    const float firstMap = own.size() > 1 ? static_cast<float>(maps.size() + 1) : -1.0f;
    out.EmitterIndex.emplace_back(static_cast<float>(out.Samples.size()),
      static_cast<float>(emitter.Samples.size()), static_cast<float>(maps.size()), firstMap);
    out.EmitterRadiance.emplace_back(emitter.Light.Radiance, emitter.PowerWeight);
    out.EmitterNormal.emplace_back(emitter.Light.Normal, 0.0f);
    out.Samples.insert(out.Samples.end(), emitter.Samples.begin(), emitter.Samples.end());
    maps.insert(maps.end(), own.begin(), own.end());
    ++out.EmitterCount;
  }
  const int res = c.Resolution;
  const int count = static_cast<int>(maps.size());
  out.Resolution = res;
  out.Columns = std::max(1, static_cast<int>(std::ceil(std::sqrt(static_cast<double>(count)))));
  const int rows = (count + out.Columns - 1) / out.Columns;
  out.Width = out.Columns * res;
  out.Height = rows * res;
  out.Depth.assign(static_cast<std::size_t>(out.Width) * out.Height, ShadowMap::EmptyDepth);
  for (int m = 0; m < count; ++m)
  {
    const ShadowMap& map = shadows.Maps()[maps[m]];
    const int x0 = (m % out.Columns) * res, y0 = (m / out.Columns) * res;
    for (int y = 0; y < res; ++y)
    {
      std::copy(map.Depth.begin() + static_cast<std::ptrdiff_t>(y) * res,
        map.Depth.begin() + static_cast<std::ptrdiff_t>(y + 1) * res,
        out.Depth.begin() + static_cast<std::ptrdiff_t>(y0 + y) * out.Width + x0);
    }
    out.MapPosition.emplace_back(map.Position, map.TanHalfAngle);
    out.MapAxisX.emplace_back(map.AxisX, map.Near);
    out.MapAxisY.emplace_back(map.AxisY, 0.0f);
    out.MapAxisZ.emplace_back(map.AxisZ, map.Far);
  }
  return out;
}

//------------------------------------------------------------------------------
namespace
{
// Nearest triangle of the field's scene along a ray beyond tMin (Moller, Trumbore 1997): the
// triangle index or SIZE_MAX. A scan over every triangle, once per emitter and placement.
std::size_t FirstHit(const TriangleScene& scene, const glm::vec3& origin,
  const glm::vec3& direction, float tMin, float& tHit)
{
  std::size_t best = SIZE_MAX;
  tHit = std::numeric_limits<float>::max();
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const glm::vec3 v0 = scene.Vertex(t, 0);
    const glm::vec3 e1 = scene.Vertex(t, 1) - v0, e2 = scene.Vertex(t, 2) - v0;
    const glm::vec3 pv = glm::cross(direction, e2);
    const float det = glm::dot(e1, pv);
    if (std::abs(det) < 1e-12f)
    {
      continue;
    }
    const float inverse = 1.0f / det;
    const glm::vec3 tv = origin - v0;
    const float u = glm::dot(tv, pv) * inverse;
    if (u < 0.0f || u > 1.0f)
    {
      continue;
    }
    const glm::vec3 qv = glm::cross(tv, e1);
    const float v = glm::dot(direction, qv) * inverse;
    if (v < 0.0f || u + v > 1.0f)
    {
      continue;
    }
    const float d = glm::dot(e2, qv) * inverse;
    if (d > tMin && d < tHit)
    {
      tHit = d;
      best = t;
    }
  }
  return best;
}
} // namespace

//------------------------------------------------------------------------------
glm::vec3 EstimateShadowIndirect(
  const LightField& field, const std::vector<ShadowEmitter>& emitters, const ObjectMesh& object)
{
  const glm::vec3 ambient = EstimateEmitterLights(field).Ambient;
  if (emitters.empty() || object.Positions.empty() || field.TotalDiffuse.empty())
  {
    return ambient;
  }
  glm::vec3 centre;
  const float radius = BoundingRadius(object, centre);
  const TriangleScene& scene = field.Scene();
  glm::dvec3 sum(0.0);
  std::size_t count = 0;
  for (const ShadowEmitter& emitter : emitters)
  {
    const glm::vec3 toObject = centre - emitter.Light.Position;
    const float distance = glm::length(toObject);
    if (!(distance > radius))
    {
      continue; // the light inside the object's sphere: no shadow centre to speak of
    }
    const glm::vec3 direction = toObject / distance;
    float t = 0.0f;
    const std::size_t triangle = FirstHit(scene, emitter.Light.Position, direction, distance, t);
    if (triangle == SIZE_MAX)
    {
      continue;
    }
    const std::uint32_t s = field.SurfaceOfTriangle(triangle);
    if (s == NoSurface)
    {
      continue;
    }
    const glm::vec3 n = field.Surfaces()[s].Normal;
    const glm::vec3 hit = emitter.Light.Position + t * direction;
    // Visibility by a scan of the scene's triangles per texel, when that stays small (a few
    // tens of millions of ray-triangle tests); beyond, visibility is ignored.
    std::size_t texels = 0;
    for (const Surface& other : field.Surfaces())
    {
      texels += other.TexelCount();
    }
    const bool occlusion =
      static_cast<double>(texels) * static_cast<double>(scene.TriangleCount()) <= 4e7;
    const glm::vec3 origin = hit + 1e-4f * n;
    // Sum over every texel of the other non-emitting surfaces, visibility ignored: the
    // point-to-texel form factor cos cos' A / (pi d^2) times the texel's radiance.
    glm::dvec3 gathered(0.0);
    double factors = 0.0;
    for (std::uint32_t r = 0; r < field.Surfaces().size(); ++r)
    {
      const Surface& other = field.Surfaces()[r];
      const glm::vec3 le = field.MaterialOf(r).Emission;
      if (r == s || std::max({ le.x, le.y, le.z }) > 0.0f)
      {
        continue;
      }
      const double area = static_cast<double>(other.TexelU) * other.TexelV;
      for (int b = 0; b < other.TextureHeight; ++b)
      {
        for (int a = 0; a < other.TextureWidth; ++a)
        {
          const glm::vec3 x = other.TexelCentre(a, b);
          const glm::vec3 d = x - hit;
          const float d2 = glm::dot(d, d);
          const float cosP = glm::dot(n, d), cosX = -glm::dot(other.Normal, d);
          if (!(cosP > 0.0f && cosX > 0.0f && d2 > 0.0f))
          {
            continue;
          }
          const glm::vec3 l = field.TotalDiffuse[other.TexelOffset +
            static_cast<std::size_t>(b) * static_cast<std::size_t>(other.TextureWidth) +
            static_cast<std::size_t>(a)];
          if (!(l.x + l.y + l.z > 0.0f))
          {
            continue; // off the surface's triangles
          }
          if (occlusion)
          {
            const float length = std::sqrt(d2);
            float tBlock = 0.0f;
            if (FirstHit(scene, origin, (x - origin) / length, 0.0f, tBlock) != SIZE_MAX &&
              tBlock < length * (1.0f - 1e-3f) - 1e-4f)
            {
              continue; // another surface in between
            }
          }
          // cos = dot / d for both angles; a texel no farther than its own size counts as there.
          const double f = static_cast<double>(cosP) * cosX /
            (Pi<double> * std::pow(std::max(static_cast<double>(d2), area), 2.0)) * area;
          gathered += f * glm::dvec3(l);
          factors += f;
        }
      }
    }
    if (factors > 0.0)
    {
      // More than the whole hemisphere (surfaces behind each other, no visibility): scale down.
      sum += gathered / std::max(1.0, factors);
      ++count;
    }
  }
  if (count == 0)
  {
    return ambient;
  }
  // A mean below 0 (the field darker than the exact direct light everywhere there) is no light.
  return glm::max(glm::vec3(0.0f), glm::vec3(sum / static_cast<double>(count)));
}

} // namespace vlf
} // namespace mesolight
