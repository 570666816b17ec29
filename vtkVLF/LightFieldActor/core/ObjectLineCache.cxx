// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectLineCache.h"

#include "LightField.h"
#include "ParallelFor.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace mesolight
{
namespace vlf
{

void ObjectLineCache::Build(const LightField& field, const std::vector<std::uint32_t>& directions,
  const glm::vec3& lower, const glm::vec3& upper, int threads, bool emission)
{
  this->Windows.assign(field.SubfieldCount(), Window());
  ParallelFor(
    0, directions.size(), 4,
    [&](std::size_t begin, std::size_t end)
    {
      std::vector<Crossing> crossings;
      for (std::size_t q = begin; q < end; ++q)
      {
        const std::uint32_t k = directions[q];
        glm::vec2 cmin(std::numeric_limits<float>::max()), cmax(-cmin);
        for (int corner = 0; corner < 8; ++corner)
        {
          const glm::vec3 x((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
            (corner & 4) ? upper.z : lower.z);
          const glm::vec2 c = field.CellCoordinates(k, x);
          cmin = glm::min(cmin, c);
          cmax = glm::max(cmax, c);
        }
        Window& w = this->Windows[k];
        w.I0 = static_cast<int>(std::floor(cmin.x)) - 1;
        w.J0 = static_cast<int>(std::floor(cmin.y)) - 1;
        const int width = static_cast<int>(std::floor(cmax.x)) + 2 - w.I0 + 1;
        const int height = static_cast<int>(std::floor(cmax.y)) + 2 - w.J0 + 1;
        if (width * height > MaxLines)
        {
          continue;
        }
        const Subfield& f = field.GetSubfield(k);
        w.Start.reserve(static_cast<std::size_t>(width * height) + 1);
        for (int b = 0; b < height; ++b)
        {
          for (int a = 0; a < width; ++a)
          {
            w.Start.push_back(static_cast<std::uint32_t>(w.Entries.size()));
            field.LineCrossings(k, w.I0 + a, w.J0 + b, crossings);
            for (const Crossing& c : crossings)
            {
              const glm::vec3 x = field.PointOnLine(k, w.I0 + a, w.J0 + b, c.Depth);
              glm::vec3 radiance = field.SentRadiance(k, w.I0 + a, w.J0 + b, c.Surface, c.Cell) +
                field.SampleTexture(field.UnshotDiffuse, c.Surface, x);
              if (c.Cell < f.UnshotSpecular.size()) // a mirror's crossing
              {
                radiance += f.UnshotSpecular[c.Cell];
              }
              if (!emission) // as Lookup::IncidentRadiance leaves it out
              {
                radiance = glm::max(radiance - field.MaterialOf(c.Surface).Emission, 0.0f);
              }
              w.Entries.push_back({ c.Depth, field.Orientation(k, c.Surface), radiance });
            }
          }
        }
        w.Start.push_back(static_cast<std::uint32_t>(w.Entries.size()));
        w.Width = width;
        w.Height = height;
        w.U = f.AxisU;
        w.V = f.AxisV;
        w.D = f.Direction;
        w.InverseCell = 1.0f / field.Settings().CellSize();
        w.DepthStart = field.DepthOf(k, glm::vec3(0.0f));
      }
    },
    threads);
}

bool ObjectLineCache::Incident(
  std::size_t k, int sense, const glm::vec3& p, CellInterpolation cells, glm::vec3& out) const
{
  const Window& w = this->Windows[k];
  if (w.Width == 0)
  {
    return false;
  }
  int is[4], js[4];
  float ws[4];
  const glm::vec2 coordinates((glm::dot(p, w.U) + 1.0f) * w.InverseCell - 0.5f,
    (glm::dot(p, w.V) + 1.0f) * w.InverseCell - 0.5f);
  const int count = CellsAround(coordinates, cells, is, js, ws);
  const float depth = glm::dot(p, w.D) + w.DepthStart;
  // Lookup's open-segment rule (FindSegment, IncidentBlend) on the cached crossings.
  auto orientationOf = [](const Entry& e) { return e.Orientation; };
  auto ignored = [](const Entry&) { return false; };
  IncidentBlend blend;
  for (int q = 0; q < count; ++q)
  {
    if (ws[q] <= 0.0f)
    {
      continue;
    }
    const int a = is[q] - w.I0, b = js[q] - w.J0;
    if (a < 0 || b < 0 || a >= w.Width || b >= w.Height)
    {
      return false;
    }
    const std::size_t line = static_cast<std::size_t>(b) * w.Width + a;
    const SegmentAroundPoint<Entry> segment = FindSegment(w.Entries.data() + w.Start[line],
      w.Entries.data() + w.Start[line + 1], depth, sense, orientationOf, ignored);
    blend.Add(ws[q], segment.Sender ? segment.Sender->Radiance : glm::vec3(0.0f), segment.Open);
  }
  out = blend.Result();
  return true;
}

} // namespace vlf
} // namespace mesolight
