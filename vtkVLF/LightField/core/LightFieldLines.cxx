// SPDX-License-Identifier: BSD-3-Clause
// The light field's lines: where a point lies in a subfield, the crossings of one line, where a
// crossing's light goes (Receiver), and the bilinear texel weights of a surface point (Wither
// 2005 §3.4-3.6). Split from LightField.cxx, which builds and traces the field.
#include "LightField.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace mesolight
{
namespace vlf
{

glm::vec2 LightField::CellCoordinates(std::size_t k, const glm::vec3& p) const
{
  const Subfield& f = this->Subfields[k];
  const float h = this->Config.CellSize();
  return glm::vec2(
    (glm::dot(p, f.AxisU) + 1.0f) / h - 0.5f, (glm::dot(p, f.AxisV) + 1.0f) / h - 0.5f);
}

float LightField::DepthOf(std::size_t k, const glm::vec3& p) const
{
  return glm::dot(p, this->Subfields[k].Direction) + LineStart;
}

glm::vec3 LightField::PointOnLine(std::size_t k, int i, int j, float depth) const
{
  const Subfield& f = this->Subfields[k];
  const float h = this->Config.CellSize();
  const float a = -1.0f + (static_cast<float>(i) + 0.5f) * h;
  const float b = -1.0f + (static_cast<float>(j) + 0.5f) * h;
  return a * f.AxisU + b * f.AxisV + (depth - LineStart) * f.Direction;
}

float LightField::PlaneDepth(std::size_t k, int i, int j, std::uint32_t surface) const
{
  // The line o + t d, o = a u + b v - LineStart d, meets dot(n, x) = offset at t.
  const Subfield& f = this->Subfields[k];
  const Surface& s = this->SurfaceList[surface];
  const float h = this->Config.CellSize();
  const float a = -1.0f + (static_cast<float>(i) + 0.5f) * h;
  const float b = -1.0f + (static_cast<float>(j) + 0.5f) * h;
  const float nd = glm::dot(s.Normal, f.Direction);
  return (s.Offset - a * glm::dot(s.Normal, f.AxisU) - b * glm::dot(s.Normal, f.AxisV)) / nd +
    LineStart;
}

float LightField::CrossingDepth(
  std::size_t k, int i, int j, std::size_t map, std::uint32_t surface, std::size_t slot) const
{
  const Subfield& f = this->Subfields[k];
  return f.Depth.FollowsPlane(map) ? this->PlaneDepth(k, i, j, surface)
                                   : f.Depth.Stored(map, slot - f.Cells.MapFirstSlot(map));
}

glm::vec3 LightField::SentRadiance(
  std::size_t k, int i, int j, std::uint32_t surface, std::size_t slot) const
{
  const Subfield& f = this->Subfields[k];
  if (slot < f.Radiance.size())
  {
    return f.Radiance[slot];
  }
  if (f.Cells.Blocked(slot))
  {
    return glm::vec3(0.0f);
  }
  const glm::vec3 x = this->PointOnLine(k, i, j, this->PlaneDepth(k, i, j, surface));
  const TexelWeights w = this->WeightsAt(surface, x);
  glm::vec3 sent(0.0f);
  for (int t = 0; t < 4; ++t)
  {
    sent += w.Weight[t] * (this->TotalDiffuse[w.Texel[t]] - this->UnshotDiffuse[w.Texel[t]]);
  }
  return glm::max(sent, glm::vec3(0.0f));
}

void LightField::MarkBlocked(std::size_t k)
{
  const int n = this->Config.RaysPerSide;
  std::vector<Crossing> line;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      this->LineCrossings(k, i, j, line);
      for (std::size_t q = 0; q < line.size(); ++q)
      {
        if (this->Receiver(k, line, q) == LineBlocked)
        {
          this->Subfields[k].Cells.SetBlocked(line[q].Cell);
        }
      }
    }
  }
}

std::int64_t LightField::FindCell(std::size_t k, int i, int j, std::uint32_t surface) const
{
  const int n = this->Config.RaysPerSide;
  if (i < 0 || j < 0 || i >= n || j >= n)
  {
    return -1;
  }
  const Subfield& f = this->Subfields[k];
  if (f.TileStart.empty())
  {
    return -1;
  }
  const int ts = this->Config.TileSide();
  const std::size_t tile = static_cast<std::size_t>((j / ts) * this->Config.TilesPerSide + i / ts);
  const auto begin = f.Entries.begin() + f.TileStart[tile];
  const auto end = f.Entries.begin() + f.TileStart[tile + 1];
  const auto found = std::lower_bound(
    begin, end, surface, [](const TileEntry& e, std::uint32_t s) { return e.Surface < s; });
  if (found == end || found->Surface != surface)
  {
    return -1;
  }
  return f.Cells.Slot(found->Map, static_cast<std::size_t>((j % ts) * ts + i % ts));
}

void LightField::LineCrossings(std::size_t k, int i, int j, std::vector<Crossing>& out) const
{
  out.clear();
  const int n = this->Config.RaysPerSide;
  const Subfield& f = this->Subfields[k];
  if (i < 0 || j < 0 || i >= n || j >= n || f.TileStart.empty())
  {
    return;
  }
  const int ts = this->Config.TileSide();
  const std::size_t tile = static_cast<std::size_t>((j / ts) * this->Config.TilesPerSide + i / ts);
  const std::size_t local = static_cast<std::size_t>((j % ts) * ts + i % ts);
  for (std::uint32_t e = f.TileStart[tile]; e < f.TileStart[tile + 1]; ++e)
  {
    const std::int64_t slot = f.Cells.Slot(f.Entries[e].Map, local);
    if (slot >= 0)
    {
      const std::size_t cell = static_cast<std::size_t>(slot);
      Crossing c{ f.Entries[e].Surface,
        this->CrossingDepth(k, i, j, f.Entries[e].Map, f.Entries[e].Surface, cell), cell };
      // Insertion sort: a line crosses few surfaces.
      out.push_back(c);
      for (std::size_t q = out.size() - 1; q > 0 && out[q - 1].Depth > out[q].Depth; --q)
      {
        std::swap(out[q - 1], out[q]);
      }
    }
  }
}

int LightField::Orientation(std::size_t k, std::uint32_t surface) const
{
  const float c = glm::dot(this->SurfaceList[surface].Normal, this->Subfields[k].Direction);
  return c > 0.0f ? 1 : (c < 0.0f ? -1 : 0);
}

std::ptrdiff_t LightField::Receiver(
  std::size_t k, const std::vector<Crossing>& line, std::size_t q) const
{
  // Crossings at the same depth (to float precision of the repeated Embree queries) are
  // coincident faces: a box's bottom on a floor, a zero-thickness two-sided panel, a light on a
  // ceiling. Light passes them by: the sender steps over its own coincident faces, and of the
  // receiving group the face turned toward the sender receives. The solid behind a contact then
  // shows as a back side (a floor under a box sees the box top's inside).
  constexpr float Coincident = 1e-5f;
  const int sense = this->Orientation(k, line[q].Surface);
  const std::ptrdiff_t n = static_cast<std::ptrdiff_t>(line.size());
  auto at = [&](std::ptrdiff_t r) { return line[static_cast<std::size_t>(r)]; };
  std::ptrdiff_t r = static_cast<std::ptrdiff_t>(q) + sense;
  while (r >= 0 && r < n && std::abs(at(r).Depth - line[q].Depth) < Coincident)
  {
    r += sense;
  }
  if (r < 0 || r >= n)
  {
    return LineEscapes;
  }
  const float depth = at(r).Depth;
  for (std::ptrdiff_t g = r; g >= 0 && g < n && std::abs(at(g).Depth - depth) < Coincident;
       g += sense)
  {
    if (this->Orientation(k, at(g).Surface) == -sense)
    {
      return g;
    }
  }
  return LineBlocked;
}

TexelWeights LightField::WeightsAt(std::uint32_t surface, const glm::vec3& x) const
{
  const Surface& s = this->SurfaceList[surface];
  const glm::vec2 c = s.TexelCoordinates(x);
  const float fa = std::floor(c.x), fb = std::floor(c.y);
  const float wa = c.x - fa, wb = c.y - fb;
  const int a0 = static_cast<int>(fa), b0 = static_cast<int>(fb);
  auto clampA = [&](int a) { return std::min(std::max(a, 0), s.TextureWidth - 1); };
  auto clampB = [&](int b) { return std::min(std::max(b, 0), s.TextureHeight - 1); };
  TexelWeights w;
  const int as[2] = { clampA(a0), clampA(a0 + 1) };
  const int bs[2] = { clampB(b0), clampB(b0 + 1) };
  for (int q = 0; q < 4; ++q)
  {
    const int da = q & 1, db = q >> 1;
    w.Texel[q] = s.TexelOffset + static_cast<std::size_t>(bs[db]) * s.TextureWidth + as[da];
    w.Weight[q] = (da ? wa : 1.0f - wa) * (db ? wb : 1.0f - wb);
  }
  return w;
}

glm::vec3 LightField::SampleTexture(
  const std::vector<glm::vec3>& texture, std::uint32_t surface, const glm::vec3& x) const
{
  const TexelWeights w = this->WeightsAt(surface, x);
  glm::vec3 sum(0.0f);
  for (int q = 0; q < 4; ++q)
  {
    sum += w.Weight[q] * texture[w.Texel[q]];
  }
  return sum;
}

} // namespace vlf
} // namespace mesolight
