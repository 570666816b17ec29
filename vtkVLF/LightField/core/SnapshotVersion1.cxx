// SPDX-License-Identifier: BSD-3-Clause
// Snapshot version 1 (every map cell, float radiance, no surface names): written for tests of
// old files, read into the compact form (Snapshot.h).
#include "SnapshotStream.h"

#include <algorithm>
#include <cmath>
#include <utility>

namespace mesolight
{
namespace vlf
{
namespace snapshot_io
{
namespace
{
float DepthOf(const LightField& field, const Subfield& f, std::size_t k, std::size_t tile,
  std::size_t map, std::uint32_t surface, std::size_t local, std::size_t slot)
{
  if (!f.Depth.FollowsPlane(map))
  {
    return f.Depth.Stored(map, slot - f.Cells.MapFirstSlot(map));
  }
  const std::size_t m = static_cast<std::size_t>(field.Settings().TilesPerSide);
  const std::size_t ts = static_cast<std::size_t>(field.Settings().TileSide());
  return field.PlaneDepth(k, static_cast<int>((tile % m) * ts + local % ts),
    static_cast<int>((tile / m) * ts + local / ts), surface);
}

// Version 1's maps: every cell of every map, depth -1 where no line crosses, float radiance.
} // namespace

void WriteDenseMaps(Writer& w, const LightField& field, const Subfield& f, std::size_t k)
{
  const std::size_t ts = static_cast<std::size_t>(field.Settings().TileSide());
  const std::size_t cellsPerMap = ts * ts;
  const std::size_t cells = f.Entries.size() * cellsPerMap;
  std::vector<float> depth(cells, -1.0f);
  std::vector<glm::vec3> radiance(cells, glm::vec3(0.0f));
  std::vector<glm::vec3> unshot(field.HasSpecular() ? cells : 0, glm::vec3(0.0f));
  for (std::size_t t = 0; t + 1 < f.TileStart.size(); ++t)
  {
    for (std::size_t e = f.TileStart[t]; e < f.TileStart[t + 1]; ++e)
    {
      const std::size_t map = f.Entries[e].Map;
      for (std::size_t local = 0; local < cellsPerMap; ++local)
      {
        const std::int64_t found = f.Cells.Slot(map, local);
        if (found < 0)
        {
          continue;
        }
        const std::size_t slot = static_cast<std::size_t>(found);
        const std::size_t c = map * cellsPerMap + local;
        const std::uint32_t surface = f.Entries[e].Surface;
        depth[c] = DepthOf(field, f, k, t, map, surface, local, slot);
        const std::size_t m = static_cast<std::size_t>(field.Settings().TilesPerSide);
        radiance[c] = slot < f.Radiance.size()
          ? glm::vec3(f.Radiance[slot])
          : field.SentRadiance(k, static_cast<int>((t % m) * ts + local % ts),
              static_cast<int>((t / m) * ts + local / ts), surface, slot);
        if (!unshot.empty() && slot < f.UnshotSpecular.size())
        {
          unshot[c] = f.UnshotSpecular[slot];
        }
      }
    }
  }
  w.Array(depth);
  w.Array(radiance);
  w.Array(unshot);
}

// Version 1 stored every map cell (depth < 0: no crossing) and float radiance; read one
// subfield's maps and keep them the way this version does (sparse, mirrors' maps first and only
// their radiance, compact).
void ReadDenseMaps(Reader& r, const LightField& field, Subfield& f, std::size_t k,
  std::uint64_t entries, std::size_t cellsPerMap)
{
  const bool specular = field.HasSpecular();
  std::vector<float> depth;
  std::vector<glm::vec3> radiance, unshot;
  r.Array(depth, "depth cells", entries * cellsPerMap);
  r.Array(radiance, "radiance cells", entries * cellsPerMap);
  r.Array(unshot, "unshot specular cells", specular ? entries * cellsPerMap : 0);
  const auto usable = [](const glm::vec3& x)
  {
    return std::isfinite(x.x) && std::isfinite(x.y) && std::isfinite(x.z) && x.x >= 0.0f &&
      x.y >= 0.0f && x.z >= 0.0f;
  };
  // New map numbers: mirrors first (LightField::StoresRadiance), each group in entry order.
  std::vector<std::uint32_t> renumber(entries, 0);
  std::vector<std::uint8_t> seen(entries, 0);
  std::uint32_t next = 0;
  for (int pass = 0; pass < 2; ++pass)
  {
    for (TileEntry& e : f.Entries)
    {
      if (field.StoresRadiance(e.Surface) == (pass == 0))
      {
        if (seen[e.Map])
        {
          r.Fail("two tile entries of subfield " + std::to_string(k) + " share a map");
        }
        seen[e.Map] = 1;
        renumber[e.Map] = next;
        e.Map = next++;
      }
    }
  }
  std::vector<std::pair<std::size_t, std::size_t>> cells; // new cell, old cell
  for (std::size_t c = 0; c < depth.size(); ++c)
  {
    if (!std::isfinite(depth[c]))
    {
      r.Fail("a depth of subfield " + std::to_string(k) + " is not finite");
    }
    if (!usable(radiance[c]) || (!unshot.empty() && !usable(unshot[c])))
    {
      r.Fail("subfield " + std::to_string(k) + " holds negative, NaN or infinite radiance");
    }
    if (depth[c] >= 0.0f)
    {
      cells.emplace_back(renumber[c / cellsPerMap] * cellsPerMap + c % cellsPerMap, c);
    }
  }
  std::sort(cells.begin(), cells.end());
  std::vector<std::size_t> occupied(cells.size());
  for (std::size_t q = 0; q < cells.size(); ++q)
  {
    occupied[q] = cells[q].first;
  }
  f.Cells.Build(entries, cellsPerMap, occupied);
  // Every map's depths kept as stored (the plane test is the tracer's: TraceSubfield).
  f.Depth.Clear();
  f.Depth.Start.resize(entries);
  for (std::size_t e = 0; e < entries; ++e)
  {
    f.Depth.Start[e] = static_cast<std::uint32_t>(f.Cells.MapFirstSlot(e));
  }
  f.Depth.Values.resize(cells.size());
  const std::size_t stored = field.SpecularSlots(f);
  f.Radiance.assign(stored, glm::vec3(0.0f));
  f.UnshotSpecular.assign(stored, glm::vec3(0.0f));
  for (std::size_t q = 0; q < cells.size(); ++q)
  {
    f.Depth.Values[q] = depth[cells[q].second];
    if (q < stored)
    {
      f.Radiance[q] = radiance[cells[q].second];
      // (No unshot maps in a file whose materials say no mirror: a corrupt file can still
      // number mirror maps; found by fuzz/snapshot.cxx.)
      f.UnshotSpecular[q] = unshot.empty() ? glm::vec3(0.0f) : unshot[cells[q].second];
    }
  }
  f.Radiance.MakeCompact();
  f.UnshotSpecular.MakeCompact();
}
} // namespace snapshot_io
} // namespace vlf
} // namespace mesolight
