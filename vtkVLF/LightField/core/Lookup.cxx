// SPDX-License-Identifier: BSD-3-Clause
#include "Lookup.h"

#include "MathConstants.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <cmath>

namespace mesolight
{
namespace vlf
{

//------------------------------------------------------------------------------
int CellsAround(const glm::vec2& c, CellInterpolation mode, int (&i)[4], int (&j)[4], float (&w)[4])
{
  if (mode == CellInterpolation::Nearest)
  {
    i[0] = static_cast<int>(std::lround(c.x));
    j[0] = static_cast<int>(std::lround(c.y));
    w[0] = 1.0f;
    return 1;
  }
  const float fi = std::floor(c.x), fj = std::floor(c.y);
  const float ai = c.x - fi, aj = c.y - fj;
  for (int q = 0; q < 4; ++q)
  {
    const int di = q & 1, dj = q >> 1;
    i[q] = static_cast<int>(fi) + di;
    j[q] = static_cast<int>(fj) + dj;
    w[q] = (di ? ai : 1.0f - ai) * (dj ? aj : 1.0f - aj);
  }
  return 4;
}

glm::vec3 Lookup::CellRadiance(
  std::size_t k, int i, int j, std::uint32_t s, std::size_t cell, const glm::vec3& x) const
{
  const Subfield& f = this->Field.GetSubfield(k);
  glm::vec3 radiance = this->Field.SentRadiance(k, i, j, s, cell) +
    this->Field.SampleTexture(this->Field.UnshotDiffuse, s, x);
  if (cell < f.UnshotSpecular.size()) // a mirror's crossing
  {
    radiance += f.UnshotSpecular[cell];
  }
  return radiance;
}

bool Lookup::SubfieldRadiance(std::size_t k, std::uint32_t s, const glm::vec3& p,
  CellInterpolation cells, glm::vec3& radiance) const
{
  int is[4], js[4];
  float ws[4];
  const int count = CellsAround(this->Field.CellCoordinates(k, p), cells, is, js, ws);
  glm::vec3 sum(0.0f);
  float weight = 0.0f;
  for (int q = 0; q < count; ++q)
  {
    if (ws[q] <= 0.0f)
    {
      continue;
    }
    const std::int64_t cell = this->Field.FindCell(k, is[q], js[q], s);
    if (cell >= 0)
    {
      sum += ws[q] * this->CellRadiance(k, is[q], js[q], s, static_cast<std::size_t>(cell), p);
      weight += ws[q];
    }
  }
  if (!(weight > 0.0f))
  {
    return false;
  }
  radiance = sum / weight;
  return true;
}

glm::vec3 Lookup::DiffuseRadiance(std::uint32_t surface, const glm::vec3& p) const
{
  return this->Field.SampleTexture(this->Field.TotalDiffuse, surface, p);
}

glm::vec3 Lookup::RadianceLeaving(std::uint32_t surface, const glm::vec3& p, const glm::vec3& w,
  CellInterpolation cells, DirectionInterpolation directions) const
{
  const DirectionSet& set = this->Field.Directions();
  glm::vec3 sum(0.0f);
  float weight = 0.0f;
  if (directions == DirectionInterpolation::Nearest)
  {
    bool flipped = false;
    const std::size_t k = set.Nearest(w, &flipped);
    glm::vec3 value;
    if (this->Field.Orientation(k, surface) == (flipped ? -1 : 1) &&
      this->SubfieldRadiance(k, surface, p, cells, value))
    {
      return value;
    }
    return this->DiffuseRadiance(surface, p);
  }
  const DirectionSet::Interpolation blend = set.Interpolate(w);
  for (int v = 0; v < 3; ++v)
  {
    const std::size_t k = blend.Index[v];
    glm::vec3 value;
    if (blend.Weight[v] > 0.0f &&
      this->Field.Orientation(k, surface) == (blend.VertexFlipped[v] ? -1 : 1) &&
      this->SubfieldRadiance(k, surface, p, cells, value))
    {
      sum += blend.Weight[v] * value;
      weight += blend.Weight[v];
    }
  }
  return weight > 0.0f ? sum / weight : this->DiffuseRadiance(surface, p);
}

glm::vec4 Lookup::RadianceLeavingShare(std::uint32_t surface, const glm::vec3& p,
  const glm::vec3& w, CellInterpolation cells, DirectionInterpolation directions) const
{
  const DirectionSet& set = this->Field.Directions();
  glm::vec3 sum(0.0f);
  float weight = 0.0f;
  if (directions == DirectionInterpolation::Nearest)
  {
    bool flipped = false;
    const std::size_t k = set.Nearest(w, &flipped);
    glm::vec3 value;
    if (this->Field.OwnsSubfield(k) && this->Field.Orientation(k, surface) == (flipped ? -1 : 1) &&
      this->SubfieldRadiance(k, surface, p, cells, value))
    {
      return glm::vec4(value, 1.0f);
    }
    return glm::vec4(0.0f);
  }
  const DirectionSet::Interpolation blend = set.Interpolate(w);
  for (int v = 0; v < 3; ++v)
  {
    const std::size_t k = blend.Index[v];
    glm::vec3 value;
    if (blend.Weight[v] > 0.0f && this->Field.OwnsSubfield(k) &&
      this->Field.Orientation(k, surface) == (blend.VertexFlipped[v] ? -1 : 1) &&
      this->SubfieldRadiance(k, surface, p, cells, value))
    {
      sum += blend.Weight[v] * value;
      weight += blend.Weight[v];
    }
  }
  return glm::vec4(sum, weight);
}

glm::vec3 Lookup::IncidentRadiance(std::size_t k, int sense, const glm::vec3& p,
  CellInterpolation cells, std::uint32_t ignore, bool occlusion, bool emission) const
{
  int is[4], js[4];
  float ws[4];
  const int count = CellsAround(this->Field.CellCoordinates(k, p), cells, is, js, ws);
  const float depth = this->Field.DepthOf(k, p);
  thread_local std::vector<Crossing> crossings;
  auto orientationOf = [&](const Crossing& c) { return this->Field.Orientation(k, c.Surface); };
  auto ignored = [&](const Crossing& c) { return c.Surface == ignore; };
  IncidentBlend blend;
  for (int q = 0; q < count; ++q)
  {
    if (ws[q] <= 0.0f)
    {
      continue;
    }
    this->Field.LineCrossings(k, is[q], js[q], crossings);
    const Crossing* first = crossings.data();
    const SegmentAroundPoint<Crossing> segment =
      FindSegment(first, first + crossings.size(), depth, sense, orientationOf, ignored);
    glm::vec3 radiance(0.0f); // nothing (light leaves the scene) or a back side: no light
    if (!occlusion)
    {
      // Negative tests only: the brightest crossing on p's side that faces p, however far.
      float brightest = -1.0f;
      for (const Crossing& c : crossings)
      {
        const bool beyond = sense > 0 ? c.Depth > depth + SelfDepth : c.Depth < depth - SelfDepth;
        if (c.Surface == ignore || !beyond || orientationOf(c) != -sense)
        {
          continue;
        }
        const glm::vec3 x = this->Field.PointOnLine(k, is[q], js[q], c.Depth);
        const glm::vec3 value = this->CellRadiance(k, is[q], js[q], c.Surface, c.Cell, x);
        if (value.x + value.y + value.z > brightest)
        {
          brightest = value.x + value.y + value.z;
          radiance = value;
        }
      }
    }
    else if (segment.Sender)
    {
      const Crossing& sender = *segment.Sender;
      const glm::vec3 x = this->Field.PointOnLine(k, is[q], js[q], sender.Depth);
      radiance = this->CellRadiance(k, is[q], js[q], sender.Surface, sender.Cell, x);
      if (!emission)
      {
        radiance = glm::max(radiance - this->Field.MaterialOf(sender.Surface).Emission, 0.0f);
      }
    }
    blend.Add(ws[q], radiance, segment.Open);
  }
  return blend.Result();
}

glm::vec3 Lookup::Irradiance(
  const glm::vec3& p, const glm::vec3& n, const GatherOptions& options, std::uint32_t ignore) const
{
  const std::size_t count = this->Field.SubfieldCount();
  const float uniform = 2.0f * Pi<float> / static_cast<float>(count);
  glm::vec3 sum(0.0f);
  float total = 0.0f;
  for (std::size_t k = 0; k < count; ++k)
  {
    const float c = glm::dot(this->Field.GetSubfield(k).Direction, n);
    if (c == 0.0f)
    {
      continue;
    }
    const float weight =
      (options.SolidAngleWeights ? this->Field.Directions().SolidAngle(k) : uniform) * std::abs(c);
    total += weight;
    if (!this->Field.OwnsSubfield(k))
    {
      continue; // a distributed field: the owner adds it (the result is additive over the ranks)
    }
    sum += weight *
      this->IncidentRadiance(
        k, c > 0.0f ? 1 : -1, p, options.Cells, ignore, options.SceneOcclusion);
  }
  if (!options.ProjectedAreaNormalization)
  {
    return sum;
  }
  return total > 0.0f ? sum * (Pi<float> / total) : glm::vec3(0.0f);
}

} // namespace vlf
} // namespace mesolight
