// SPDX-License-Identifier: BSD-3-Clause
#include "PatchComparison.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <cstdio>
#include <sstream>
#include <stdexcept>

namespace mesolight
{
namespace vlf
{

namespace
{
double Sum(const glm::vec3& v)
{
  return static_cast<double>(v.x) + static_cast<double>(v.y) + static_cast<double>(v.z);
}

std::string AxisName(const glm::vec3& n)
{
  int axis = 0;
  for (int a = 1; a < 3; ++a)
  {
    if (std::abs(n[a]) > std::abs(n[axis]))
    {
      axis = a;
    }
  }
  const char* names[] = { "x", "y", "z" };
  return std::string(n[axis] >= 0.0f ? "+" : "-") + names[axis];
}
} // namespace

glm::vec3 ToWorld(const LightField& field, const glm::vec3& unit)
{
  return field.NormalizationCentre() + unit / field.NormalizationScale();
}

glm::vec3 ToUnit(const LightField& field, const glm::vec3& world)
{
  return (world - field.NormalizationCentre()) * field.NormalizationScale();
}

PatchComparisonResult ComparePatches(
  const LightField& field, const ReferenceRadiance& reference, int samples)
{
  if (samples < 1)
  {
    throw std::invalid_argument("samples per patch must be at least 1");
  }
  if (!reference)
  {
    throw std::invalid_argument("no reference radiance given");
  }
  const TriangleScene& scene = field.Scene();
  const double worldArea =
    1.0 / (static_cast<double>(field.NormalizationScale()) * field.NormalizationScale());
  PatchComparisonResult result;
  double weightedError = 0.0, weightedArea = 0.0;
  for (std::uint32_t s = 0; s < field.Surfaces().size(); ++s)
  {
    const Surface& surface = field.Surfaces()[s];
    const SceneMaterial& material = field.MaterialOf(s);
    PatchError patch;
    patch.Surface = s;
    patch.Name =
      (material.Name.empty() ? "material " + std::to_string(surface.Material) : material.Name) +
      ", normal " + AxisName(surface.Normal);
    patch.Area = surface.Area * worldArea;
    double squaredError = 0.0;
    // R2 sequence (Roberts 2018): the plastic number's powers give well spread 2D points.
    const double g = 1.32471795724474602596;
    const double a1 = 1.0 / g, a2 = 1.0 / (g * g);
    for (int q = 0; q < samples; ++q)
    {
      // The triangle: by area, from the first coordinate.
      const double u = std::fmod(0.5 + a1 * (q + 1), 1.0);
      double v = std::fmod(0.5 + a2 * (q + 1), 1.0);
      double target = u * surface.Area, acc = 0.0;
      std::uint32_t triangle = surface.Triangles.back();
      double within = 0.5;
      for (std::uint32_t t : surface.Triangles)
      {
        const double area = scene.Area(t);
        if (acc + area >= target)
        {
          triangle = t;
          within = area > 0.0 ? (target - acc) / area : 0.5;
          break;
        }
        acc += area;
      }
      // Uniform point in the triangle from (within, v).
      double r1 = std::sqrt(std::min(std::max(within, 0.0), 1.0));
      v = std::min(std::max(v, 0.0), 1.0);
      const glm::vec3 p = static_cast<float>(1.0 - r1) * scene.Vertex(triangle, 0) +
        static_cast<float>(r1 * (1.0 - v)) * scene.Vertex(triangle, 1) +
        static_cast<float>(r1 * v) * scene.Vertex(triangle, 2);
      const glm::vec3 mine = field.SampleTexture(field.TotalDiffuse, s, p);
      const glm::vec3 theirs = reference(triangle, ToWorld(field, p));
      patch.Field += mine;
      patch.Reference += theirs;
      const double denominator = Sum(theirs);
      if (denominator > 0.0)
      {
        const double e = (Sum(mine) - denominator) / denominator;
        squaredError += e * e;
      }
    }
    patch.Samples = static_cast<std::size_t>(samples);
    patch.Field /= static_cast<float>(samples);
    patch.Reference /= static_cast<float>(samples);
    const double ref = Sum(patch.Reference);
    patch.MeanError =
      ref > 0.0 ? std::abs(Sum(patch.Field) - ref) / ref : (Sum(patch.Field) > 0.0 ? 1.0 : 0.0);
    patch.PointError = std::sqrt(squaredError / samples);
    const bool emitter = Sum(material.Emission) > 0.0;
    if (!emitter)
    {
      weightedError += patch.MeanError * patch.Area;
      weightedArea += patch.Area;
      result.WorstMeanError = std::max(result.WorstMeanError, patch.MeanError);
    }
    result.Patches.push_back(patch);
  }
  result.AreaWeightedMeanError = weightedArea > 0.0 ? weightedError / weightedArea : 0.0;
  return result;
}

std::string PatchComparisonResult::Table() const
{
  std::ostringstream out;
  char line[320];
  std::snprintf(line, sizeof(line), "%-28s %10s %7s  %-26s %-26s %8s %8s\n", "patch", "area",
    "samples", "field RGB", "reference RGB", "mean err", "rms err");
  out << line;
  for (const PatchError& p : this->Patches)
  {
    std::snprintf(line, sizeof(line),
      "%-28s %10.4g %7zu  %8.4f %8.4f %8.4f %8.4f %8.4f %8.4f %7.2f%% %7.2f%%\n", p.Name.c_str(),
      p.Area, p.Samples, p.Field.x, p.Field.y, p.Field.z, p.Reference.x, p.Reference.y,
      p.Reference.z, 100.0 * p.MeanError, 100.0 * p.PointError);
    out << line;
  }
  std::snprintf(line, sizeof(line),
    "non-emitting patches: area-weighted mean error %.2f%%, worst patch %.2f%%\n",
    100.0 * this->AreaWeightedMeanError, 100.0 * this->WorstMeanError);
  out << line;
  return out.str();
}

std::string PatchComparisonResult::Csv() const
{
  std::ostringstream out;
  out << "patch,area,samples,field_r,field_g,field_b,reference_r,reference_g,reference_b,mean_"
         "error,rms_error\n";
  for (const PatchError& p : this->Patches)
  {
    out << '"' << p.Name << "\"," << p.Area << ',' << p.Samples << ',' << p.Field.x << ','
        << p.Field.y << ',' << p.Field.z << ',' << p.Reference.x << ',' << p.Reference.y << ','
        << p.Reference.z << ',' << p.MeanError << ',' << p.PointError << '\n';
  }
  return out.str();
}

} // namespace vlf
} // namespace mesolight
