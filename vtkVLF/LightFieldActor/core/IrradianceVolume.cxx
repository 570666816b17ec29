// SPDX-License-Identifier: BSD-3-Clause
#include "IrradianceVolume.h"

#include "MathConstants.h"
#include "ParallelFor.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <limits>
#include <stdexcept>

namespace mesolight
{
namespace vlf
{

namespace
{
constexpr std::size_t BackSideStride = 4; // every 4th direction classifies a grid point

// True when the line of subfield k through p, followed from p toward sense x d_k, first meets
// the back of a surface (p is inside geometry or outside the scene on that side). The nearest
// line only: a classification, not a radiance.
bool SeesBackSide(const LightField& field, std::size_t k, int sense, const glm::vec3& p,
  std::vector<Crossing>& crossings)
{
  int is[4], js[4];
  float ws[4];
  CellsAround(field.CellCoordinates(k, p), CellInterpolation::Nearest, is, js, ws);
  field.LineCrossings(k, is[0], js[0], crossings);
  const float depth = field.DepthOf(k, p);
  const Crossing* sender = nullptr;
  if (sense > 0)
  {
    for (const Crossing& c : crossings)
    {
      if (c.Depth > depth + SelfDepth)
      {
        sender = &c;
        break;
      }
    }
  }
  else
  {
    for (const Crossing& c : crossings)
    {
      if (c.Depth < depth - SelfDepth)
      {
        sender = &c;
      }
    }
  }
  return sender && field.Orientation(k, sender->Surface) != -sense;
}
} // namespace

//------------------------------------------------------------------------------
std::string IrradianceVolumeSettings::Validate() const
{
  if (this->Resolution < 2 || this->Resolution > 128)
  {
    return "irradiance volume resolution " + std::to_string(this->Resolution) +
      " is outside 2-128 grid points";
  }
  if (!(this->MaximumBackSideFraction >= 0.0f && this->MaximumBackSideFraction <= 1.0f))
  {
    return "the back-side fraction of an irradiance volume must be within [0, 1]";
  }
  if (this->NormalSubdivisions < 1 || this->NormalSubdivisions > 32)
  {
    return "the normal subdivisions of an irradiance volume must be within 1-32";
  }
  return {};
}

//------------------------------------------------------------------------------
IrradianceVolume::IrradianceVolume(
  const LightField& field, const IrradianceVolumeSettings& settings)
  : Field(field)
  , Options(settings.Lookup)
  , Normals(std::max(1, std::min(32, settings.NormalSubdivisions)))
{
  const std::string problem = settings.Validate();
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  const auto start = std::chrono::steady_clock::now();
  glm::vec3 lower(std::numeric_limits<float>::max()), upper(-lower);
  for (const glm::vec3& p : field.Scene().Positions)
  {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
  if (!(lower.x <= upper.x))
  {
    throw std::invalid_argument("the light field's scene has no points");
  }
  // Grid points at the centres of Size cells per axis, so that none lies on a bounding wall.
  const glm::vec3 extent = glm::max(upper - lower, glm::vec3(1e-6f));
  const float longest = std::max({ extent.x, extent.y, extent.z });
  for (int a = 0; a < 3; ++a)
  {
    this->Size[a] =
      std::max(2, static_cast<int>(std::lround(settings.Resolution * extent[a] / longest)));
    this->Step[a] = extent[a] / static_cast<float>(this->Size[a]);
  }
  this->Origin = lower + 0.5f * this->Step;
  const std::size_t count = static_cast<std::size_t>(this->Size[0]) * this->Size[1] * this->Size[2];
  const std::size_t normals = this->NormalCount();
  this->Table.assign(count * normals, glm::vec3(0.0f));
  this->Valid.assign(count, 0);

  const Lookup lookup(field);
  const DirectionSet& set = field.Directions();
  const std::size_t directions = field.SubfieldCount();
  const float uniform = 2.0f * Pi<float> / static_cast<float>(directions);
  auto build = [&](std::size_t index)
  {
    const int x = static_cast<int>(index % this->Size[0]);
    const int y = static_cast<int>((index / this->Size[0]) % this->Size[1]);
    const int z =
      static_cast<int>(index / (static_cast<std::size_t>(this->Size[0]) * this->Size[1]));
    const glm::vec3 p = this->Origin + glm::vec3(x, y, z) * this->Step;
    thread_local std::vector<Crossing> crossings;
    thread_local std::vector<glm::vec3> incident; // 2 k: from +d_k's side, 2 k + 1: from -d_k's
    incident.assign(2 * directions, glm::vec3(0.0f));
    std::size_t backSides = 0, tested = 0;
    for (std::size_t k = 0; k < directions; ++k)
    {
      for (const int sense : { 1, -1 })
      {
        if (k % BackSideStride == 0) // a classification: a subset of the directions will do
        {
          backSides += SeesBackSide(field, k, sense, p, crossings) ? 1 : 0;
          ++tested;
        }
        incident[2 * k + (sense > 0 ? 0 : 1)] = lookup.IncidentRadiance(
          k, sense, p, settings.Lookup.Cells, NoSurface, settings.Lookup.SceneOcclusion);
      }
    }
    // Lookup::Irradiance for every normal of the table, from the radiance read once.
    glm::vec3* row = this->Table.data() + index * normals;
    for (std::size_t j = 0; j < normals; ++j)
    {
      const glm::vec3 n = (j % 2 ? -1.0f : 1.0f) * this->Normals.Direction(j / 2);
      glm::vec3 sum(0.0f);
      float total = 0.0f;
      for (std::size_t k = 0; k < directions; ++k)
      {
        const float c = glm::dot(field.GetSubfield(k).Direction, n);
        if (c == 0.0f)
        {
          continue;
        }
        const float weight =
          (settings.Lookup.SolidAngleWeights ? set.SolidAngle(k) : uniform) * std::abs(c);
        total += weight;
        sum += weight * incident[2 * k + (c > 0.0f ? 0 : 1)];
      }
      row[j] = !settings.Lookup.ProjectedAreaNormalization
        ? sum
        : (total > 0.0f ? sum * (Pi<float> / total) : glm::vec3(0.0f));
    }
    this->Valid[index] =
      static_cast<float>(backSides) <= settings.MaximumBackSideFraction * static_cast<float>(tested)
      ? 1
      : 0;
  };
  // Batches of rows between progress reports.
  const std::size_t batch = std::max<std::size_t>(1, count / 32);
  for (std::size_t first = 0; first < count; first += batch)
  {
    if (!ReportProgress(settings.Progress, static_cast<double>(first) / static_cast<double>(count)))
    {
      throw AbortedError();
    }
    const std::size_t last = std::min(count, first + batch);
    ParallelFor(
      first, last, 1,
      [&](std::size_t b, std::size_t e)
      {
        for (std::size_t i = b; i < e; ++i)
        {
          build(i);
        }
      },
      settings.Threads);
  }
  ReportProgress(settings.Progress, 1.0);
  this->Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

//------------------------------------------------------------------------------
std::size_t IrradianceVolume::ValidPointCount() const
{
  return static_cast<std::size_t>(std::count(this->Valid.begin(), this->Valid.end(), 1));
}

//------------------------------------------------------------------------------
std::size_t IrradianceVolume::Index(int x, int y, int z) const
{
  return (static_cast<std::size_t>(z) * this->Size[1] + y) * this->Size[0] + x;
}

//------------------------------------------------------------------------------
glm::vec3 IrradianceVolume::Irradiance(const glm::vec3& p, const glm::vec3& n) const
{
  if (!(glm::dot(n, n) > 0.0f) || !std::isfinite(n.x + n.y + n.z) ||
    !std::isfinite(p.x + p.y + p.z))
  {
    return glm::vec3(0.0f); // no normal, no irradiance (the gatherer computes missing normals)
  }
  glm::vec3 g = (p - this->Origin) / this->Step;
  int i0[3];
  float f[3];
  for (int a = 0; a < 3; ++a)
  {
    g[a] = std::min(std::max(g[a], 0.0f), static_cast<float>(this->Size[a] - 1));
    i0[a] = std::min(static_cast<int>(g[a]), this->Size[a] - 2);
    f[a] = g[a] - static_cast<float>(i0[a]);
  }
  // The normal's three neighbours in the table and their spherical weights.
  const DirectionSet::Interpolation around = this->Normals.Interpolate(n);
  std::size_t columns[3];
  for (int v = 0; v < 3; ++v)
  {
    columns[v] = 2 * around.Index[v] + (around.VertexFlipped[v] ? 1 : 0);
  }
  const std::size_t normals = this->NormalCount();
  auto atPoint = [&](std::size_t index)
  {
    const glm::vec3* row = this->Table.data() + index * normals;
    return around.Weight[0] * row[columns[0]] + around.Weight[1] * row[columns[1]] +
      around.Weight[2] * row[columns[2]];
  };
  glm::vec3 blend(0.0f);
  float total = 0.0f;
  for (int corner = 0; corner < 8; ++corner)
  {
    const int dx = corner & 1, dy = (corner >> 1) & 1, dz = (corner >> 2) & 1;
    const std::size_t index = this->Index(i0[0] + dx, i0[1] + dy, i0[2] + dz);
    const float w =
      (dx ? f[0] : 1.0f - f[0]) * (dy ? f[1] : 1.0f - f[1]) * (dz ? f[2] : 1.0f - f[2]);
    if (!this->Valid[index] || w <= 0.0f)
    {
      continue;
    }
    total += w;
    blend += w * atPoint(index);
  }
  if (total > 1e-3f)
  {
    return blend / total;
  }
  // No valid corner with weight: the nearest valid point within two cells, else the gather.
  const int r[3] = { static_cast<int>(std::lround(g[0])), static_cast<int>(std::lround(g[1])),
    static_cast<int>(std::lround(g[2])) };
  float best = std::numeric_limits<float>::max();
  std::size_t found = this->Valid.size();
  for (int z = std::max(0, r[2] - 2); z <= std::min(this->Size[2] - 1, r[2] + 2); ++z)
  {
    for (int y = std::max(0, r[1] - 2); y <= std::min(this->Size[1] - 1, r[1] + 2); ++y)
    {
      for (int x = std::max(0, r[0] - 2); x <= std::min(this->Size[0] - 1, r[0] + 2); ++x)
      {
        const std::size_t index = this->Index(x, y, z);
        const float distance = glm::length(glm::vec3(x, y, z) - g);
        if (this->Valid[index] && distance < best)
        {
          best = distance;
          found = index;
        }
      }
    }
  }
  if (found < this->Valid.size())
  {
    return atPoint(found);
  }
  ++this->Fallbacks;
  return Lookup(this->Field).Irradiance(p, n, this->Options);
}

} // namespace vlf
} // namespace mesolight
