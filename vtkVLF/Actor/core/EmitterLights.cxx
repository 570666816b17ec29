// SPDX-License-Identifier: BSD-3-Clause
#include "EmitterLights.h"

#include "LightField.h"
#include "MathConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>

namespace mesolight
{
namespace vlf
{

//------------------------------------------------------------------------------
LightApproximation EstimateEmitterLights(const LightField& field)
{
  LightApproximation out;
  const TriangleScene& scene = field.Scene();
  glm::dvec3 radianceArea(0.0);
  double area = 0.0;
  for (std::uint32_t s = 0; s < field.Surfaces().size(); ++s)
  {
    const Surface& surface = field.Surfaces()[s];
    const glm::vec3 le = field.MaterialOf(s).Emission;
    if (std::max({ le.x, le.y, le.z }) <= 0.0f)
    {
      // The ambient term: the mean radiance the non-emitting surfaces leave (their texels
      // weighted by the surface's area per texel).
      if (surface.TexelCount() > 0 && surface.Area > 0.0 && !field.TotalDiffuse.empty())
      {
        glm::dvec3 sum(0.0);
        for (std::size_t t = 0; t < surface.TexelCount(); ++t)
        {
          sum += glm::dvec3(field.TotalDiffuse[surface.TexelOffset + t]);
        }
        radianceArea += sum / static_cast<double>(surface.TexelCount()) * surface.Area;
        area += surface.Area;
      }
      continue;
    }
    EmitterLight light;
    light.Surface = s;
    light.Normal = surface.Normal;
    light.Radiance = le;
    glm::dvec3 centroid(0.0);
    for (const std::uint32_t t : surface.Triangles)
    {
      const double a = scene.Area(t);
      centroid +=
        a * glm::dvec3(scene.Vertex(t, 0) + scene.Vertex(t, 1) + scene.Vertex(t, 2)) / 3.0;
      light.Area += a;
    }
    if (light.Area <= 0.0)
    {
      continue;
    }
    light.Position = glm::vec3(centroid / light.Area);
    out.Lights.push_back(light);
  }
  std::sort(out.Lights.begin(), out.Lights.end(),
    [](const EmitterLight& a, const EmitterLight& b)
    {
      const glm::vec3 ia = a.Intensity(), ib = b.Intensity();
      return ia.x + ia.y + ia.z > ib.x + ib.y + ib.z;
    });
  if (area > 0.0)
  {
    out.Ambient = glm::vec3(radianceArea / area);
  }
  return out;
}

//------------------------------------------------------------------------------
glm::vec3 ShadeWithLights(
  const LightApproximation& lights, const glm::vec3& p, const glm::vec3& n, const glm::vec3& kd)
{
  glm::vec3 radiance = kd * lights.Ambient;
  for (const EmitterLight& light : lights.Lights)
  {
    const glm::vec3 toLight = light.Position - p;
    const float d2 = glm::dot(toLight, toLight);
    if (!(d2 > 0.0f))
    {
      continue;
    }
    const glm::vec3 w = toLight / std::sqrt(d2);
    const float cosLight = std::max(0.0f, -glm::dot(light.Normal, w));
    const float cosPoint = std::max(0.0f, glm::dot(n, w));
    radiance += kd / Pi<float> * light.Intensity() * (cosLight * cosPoint / d2);
  }
  return radiance;
}

} // namespace vlf
} // namespace mesolight
