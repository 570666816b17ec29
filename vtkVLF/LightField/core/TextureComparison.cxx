// SPDX-License-Identifier: BSD-3-Clause
#include "TextureComparison.h"

#include "ParallelFor.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
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

bool Inside(const TriangleScene& scene, std::uint32_t t, const glm::vec3& p, const glm::vec3& n)
{
  const glm::vec3 a = scene.Vertex(t, 0), b = scene.Vertex(t, 1), c = scene.Vertex(t, 2);
  // Same side of all three edges (with a little slack so centres on a shared edge count).
  const float slack = -1e-6f;
  return glm::dot(glm::cross(b - a, p - a), n) >= slack &&
    glm::dot(glm::cross(c - b, p - b), n) >= slack &&
    glm::dot(glm::cross(a - c, p - c), n) >= slack;
}

double Percentile95(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  const std::size_t k = std::min(v.size() - 1, static_cast<std::size_t>(0.95 * v.size()));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// Below this fraction of its surface's mean reference a texel counts as hidden.
constexpr double HiddenFraction = 0.05;

double Mean(const std::vector<double>& v)
{
  double s = 0.0;
  for (double x : v)
  {
    s += x;
  }
  return v.empty() ? 0.0 : s / static_cast<double>(v.size());
}
} // namespace

std::vector<TexelPoint> SurfaceTexels(const LightField& field)
{
  const TriangleScene& scene = field.Scene();
  std::vector<TexelPoint> texels;
  for (std::uint32_t s = 0; s < field.Surfaces().size(); ++s)
  {
    const Surface& surface = field.Surfaces()[s];
    if (Sum(field.MaterialOf(s).Emission) > 0.0)
    {
      continue;
    }
    for (int b = 0; b < surface.TextureHeight; ++b)
    {
      for (int a = 0; a < surface.TextureWidth; ++a)
      {
        const glm::vec3 p = surface.TexelCentre(a, b);
        for (std::uint32_t t : surface.Triangles)
        {
          if (Inside(scene, t, p, surface.Normal))
          {
            TexelPoint q;
            q.Surface = s;
            q.A = a;
            q.B = b;
            q.Texel = surface.TexelOffset + static_cast<std::size_t>(b) * surface.TextureWidth + a;
            q.Triangle = t;
            q.Unit = p;
            texels.push_back(q);
            break;
          }
        }
      }
    }
  }
  return texels;
}

std::vector<glm::vec3> ReferenceAtTexels(const LightField& field,
  const std::vector<TexelPoint>& texels, const ReferenceRadiance& reference)
{
  if (!reference)
  {
    throw std::invalid_argument("no reference radiance given");
  }
  std::vector<glm::vec3> out(texels.size());
  ParallelFor(0, texels.size(), 16,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        out[i] = reference(texels[i].Triangle, ToWorld(field, texels[i].Unit));
      }
    });
  return out;
}

std::vector<glm::vec3> FieldAtTexels(const LightField& field, const std::vector<TexelPoint>& texels)
{
  std::vector<glm::vec3> out(texels.size());
  for (std::size_t i = 0; i < texels.size(); ++i)
  {
    out[i] = field.TotalDiffuse[texels[i].Texel];
  }
  return out;
}

TexelError CompareTexels(const LightField& field, const std::vector<TexelPoint>& texels,
  const std::vector<glm::vec3>& values, const std::vector<glm::vec3>& reference)
{
  if (values.size() != texels.size() || reference.size() != texels.size())
  {
    throw std::invalid_argument("one value and one reference per texel are needed");
  }
  // Where each global texel sits in `texels` (neighbours must be compared texels too).
  std::vector<std::int64_t> slot(field.TexelCount(), -1);
  for (std::size_t i = 0; i < texels.size(); ++i)
  {
    slot[texels[i].Texel] = static_cast<std::int64_t>(i);
  }
  // Texels the reference sees (almost) no light at -- floor under a block -- are not compared:
  // a relative error there is meaningless (and a path tracer leaks a little light into them).
  std::vector<double> surfaceMean(field.Surfaces().size(), 0.0);
  std::vector<std::size_t> surfaceCount(field.Surfaces().size(), 0);
  for (std::size_t i = 0; i < texels.size(); ++i)
  {
    surfaceMean[texels[i].Surface] += Sum(reference[i]);
    ++surfaceCount[texels[i].Surface];
  }
  for (std::size_t s = 0; s < surfaceMean.size(); ++s)
  {
    surfaceMean[s] /= static_cast<double>(std::max<std::size_t>(surfaceCount[s], 1));
  }
  auto lit = [&](std::size_t i)
  { return Sum(reference[i]) > HiddenFraction * surfaceMean[texels[i].Surface]; };
  std::vector<double> errors, contrast;
  errors.reserve(texels.size());
  for (std::size_t i = 0; i < texels.size(); ++i)
  {
    const double r = Sum(reference[i]);
    if (!(r > 0.0) || !lit(i))
    {
      continue;
    }
    errors.push_back(std::abs(Sum(values[i]) - r) / r);
    const Surface& s = field.Surfaces()[texels[i].Surface];
    double vn = 0.0, rn = 0.0;
    int count = 0;
    const int da[] = { 1, -1, 0, 0 }, db[] = { 0, 0, 1, -1 };
    for (int q = 0; q < 4; ++q)
    {
      const int a = texels[i].A + da[q], b = texels[i].B + db[q];
      if (a < 0 || b < 0 || a >= s.TextureWidth || b >= s.TextureHeight)
      {
        continue;
      }
      const std::int64_t j = slot[s.TexelOffset + static_cast<std::size_t>(b) * s.TextureWidth + a];
      if (j < 0 || !lit(static_cast<std::size_t>(j)))
      {
        continue;
      }
      vn += Sum(values[static_cast<std::size_t>(j)]);
      rn += Sum(reference[static_cast<std::size_t>(j)]);
      ++count;
    }
    if (count > 0 && rn > 0.0)
    {
      vn /= count;
      rn /= count;
      contrast.push_back(std::abs((Sum(values[i]) - vn) - (r - rn)) / rn);
    }
  }
  TexelError e;
  e.Texels = errors.size();
  e.Mean = Mean(errors);
  e.P95 = Percentile95(errors);
  e.ContrastMean = Mean(contrast);
  e.ContrastP95 = Percentile95(contrast);
  return e;
}

std::string TexelError::Describe() const
{
  char line[200];
  std::snprintf(line, sizeof(line),
    "%zu texels: error mean %.2f%%, p95 %.2f%%; local contrast error mean %.2f%%, p95 %.2f%%",
    this->Texels, 100.0 * this->Mean, 100.0 * this->P95, 100.0 * this->ContrastMean,
    100.0 * this->ContrastP95);
  return line;
}

void FilterTotalDiffuse(LightField& field, const TextureFilterSettings& settings)
{
  if (settings.Radius <= 0 || field.TotalDiffuse.empty())
  {
    return;
  }
  const std::vector<glm::vec3> source = field.TotalDiffuse;
  const int r = settings.Radius;
  const double inverseVariance = settings.RangeSigma > 0.0f
    ? 1.0 / (static_cast<double>(settings.RangeSigma) * settings.RangeSigma)
    : 0.0;
  for (std::uint32_t si = 0; si < field.Surfaces().size(); ++si)
  {
    const Surface& s = field.Surfaces()[si];
    const int w = s.TextureWidth, h = s.TextureHeight;
    ParallelFor(0, static_cast<std::size_t>(h), 1,
      [&](std::size_t begin, std::size_t end)
      {
        for (int b = static_cast<int>(begin); b < static_cast<int>(end); ++b)
        {
          for (int a = 0; a < w; ++a)
          {
            const std::size_t centre = s.TexelOffset + static_cast<std::size_t>(b) * w + a;
            const double c = Sum(source[centre]);
            glm::dvec3 sum(0.0);
            double weights = 0.0;
            for (int y = std::max(0, b - r); y <= std::min(h - 1, b + r); ++y)
            {
              for (int x = std::max(0, a - r); x <= std::min(w - 1, a + r); ++x)
              {
                const glm::vec3& v = source[s.TexelOffset + static_cast<std::size_t>(y) * w + x];
                double weight = 1.0;
                if (inverseVariance > 0.0)
                {
                  // Relative to the larger of the two, so dark and bright sides are symmetric.
                  const double n = Sum(v), m = std::max(std::max(c, n), 1e-12);
                  const double d = (n - c) / m;
                  weight = std::exp(-0.5 * d * d * inverseVariance);
                }
                sum += weight * glm::dvec3(v);
                weights += weight;
              }
            }
            field.TotalDiffuse[centre] = glm::vec3(sum / weights);
          }
        }
      });
  }
}

} // namespace vlf
} // namespace mesolight
