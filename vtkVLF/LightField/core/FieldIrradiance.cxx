// SPDX-License-Identifier: BSD-3-Clause
#include "FieldIrradiance.h"

#include "MathConstants.h"

#include <glm/geometric.hpp>

namespace mesolight
{
namespace vlf
{

double IncidentWeightScale(const LightField& field)
{
  double total = 0.0;
  for (std::size_t k = 0; k < field.SubfieldCount(); ++k)
  {
    total += 2.0 * field.GetSubfield(k).Weight;
  }
  return total > 0.0 ? 4.0 * Pi<double> / total : 0.0;
}

std::vector<IncidentSample> IncidentRadianceSamples(
  const LightField& field, const glm::vec3& p, const IncidentOptions& options)
{
  const Lookup lookup(field);
  const std::size_t count = field.SubfieldCount();
  const double scale = IncidentWeightScale(field);
  std::vector<IncidentSample> samples;
  samples.reserve(2 * count);
  for (std::size_t k = 0; k < count; ++k)
  {
    const Subfield& f = field.GetSubfield(k);
    for (const int sense : { 1, -1 })
    {
      IncidentSample s;
      s.Direction = static_cast<float>(sense) * f.Direction;
      s.SolidAngle = static_cast<float>(scale * f.Weight);
      s.Radiance = lookup.IncidentRadiance(
        k, sense, p, CellInterpolation::Bilinear, options.Ignore, true, options.Emission);
      samples.push_back(s);
    }
  }
  return samples;
}

SH9 ProjectIncidentSH9(const std::vector<IncidentSample>& samples)
{
  SH9 sh;
  for (const IncidentSample& s : samples)
  {
    const double d[3] = { s.Direction.x, s.Direction.y, s.Direction.z };
    double y[9];
    EvaluateSHBasis(d, y);
    for (int k = 0; k < 9; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        sh.L[k][c] += static_cast<double>(s.SolidAngle) * s.Radiance[c] * y[k];
      }
    }
  }
  return sh;
}

glm::vec3 IncidentIrradiance(const std::vector<IncidentSample>& samples, const glm::vec3& n)
{
  glm::dvec3 sum(0.0);
  for (const IncidentSample& s : samples)
  {
    const float c = glm::dot(n, s.Direction);
    if (c > 0.0f)
    {
      sum += glm::dvec3(s.Radiance) * static_cast<double>(s.SolidAngle * c);
    }
  }
  return glm::vec3(sum);
}

} // namespace vlf
} // namespace mesolight
