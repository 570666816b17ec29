// SPDX-License-Identifier: BSD-3-Clause
// The light field's memory estimate: the maps' crossings and (tile, surface) pairs counted from
// the projected triangles without tracing, and the bytes a LightField allocates for them. Split
// from LightField.cxx, which builds and traces the field.
#include "LightFieldMemory.h"

#include "ParallelFor.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <sstream>

namespace mesolight
{
namespace vlf
{

namespace
{
// What the maps of every subfield hold, counted from the projected triangles without tracing:
// the (tile, surface) pairs (maps), the crossings, and the crossings of mirrors (whose radiance
// is stored) and of surfaces whose triangles lie off their plane (whose depths are stored).
struct MapCounts
{
  std::uint64_t Pairs = 0;
  std::uint64_t Crossings = 0;
  std::uint64_t SpecularCrossings = 0;
  std::uint64_t DepthCrossings = 0;
};

// Line (i, j) of a subfield crosses a surface where the projection of one of its triangles
// holds the lattice point (i, j) (cell centres at integers): per triangle and lattice row, the
// span of the row inside it gives its crossings and the tiles they fall in. (An earlier bound --
// the tiles of each projected triangle's bounding box and A + P + 1 crossings per triangle of
// projected area A and perimeter P, 4 bytes each -- counted 10 times what the boxes of
// `bench vlf-accuracy` allocate: their small faces are mostly perimeter.) Lines that only graze
// an edge may be counted where Embree finds no hit, or the reverse; both are rare.
MapCounts CountMapContents(const TriangleScene& scene, const std::vector<Surface>& surfaces,
  const DirectionSet& directions, const LightFieldSettings& settings, std::size_t stride)
{
  MapCounts counts;
  const int n = settings.RaysPerSide;
  const int m = settings.TilesPerSide;
  const int ts = settings.TileSide();
  const float h = settings.CellSize();
  // Depths are stored for maps whose crossings lie off the plane by more than the tolerance
  // (CrossingDepths); a surface with a vertex that far off its plane is counted as storing all.
  std::vector<std::uint8_t> offPlane(surfaces.size(), 0), mirror(surfaces.size(), 0);
  for (std::size_t s = 0; s < surfaces.size(); ++s)
  {
    const glm::vec3& ks = scene.Materials[surfaces[s].Material].Specular;
    mirror[s] = ks.x > 0.0f || ks.y > 0.0f || ks.z > 0.0f;
    for (std::uint32_t t : surfaces[s].Triangles)
    {
      for (int c = 0; c < 3; ++c)
      {
        const float off =
          std::abs(glm::dot(surfaces[s].Normal, scene.Vertex(t, c)) - surfaces[s].Offset);
        offPlane[s] = offPlane[s] || off > 0.25f * PlaneDepthTolerance;
      }
    }
  }
  // The directions are counted in parallel, each into its own counts (summed in order below,
  // so the sum does not depend on the split): 8193 directions of 1024 x 1024 lines took 106 s
  // on one thread before a refusal. With stride > 1, only every stride-th direction.
  const std::size_t sampled = (directions.Size() + stride - 1) / stride;
  std::vector<MapCounts> perDirection(sampled);
  ParallelFor(0, sampled, 1,
    [&](std::size_t first, std::size_t last)
    {
      std::vector<std::uint8_t> marked(static_cast<std::size_t>(m) * m);
      for (std::size_t sample = first; sample < last; ++sample)
      {
        MapCounts& own = perDirection[sample];
        const std::size_t k = sample * stride;
        glm::vec3 u, v;
        const glm::vec3 d = directions.Direction(k);
        SubfieldFrame(k, d, u, v);
        for (std::size_t s = 0; s < surfaces.size(); ++s)
        {
          const Surface& surface = surfaces[s];
          if (glm::dot(surface.Normal, d) == 0.0f)
          {
            continue; // parallel to the lines: never crossed (LightField::Orientation)
          }
          std::fill(marked.begin(), marked.end(), 0);
          std::uint64_t crossings = 0;
          for (std::uint32_t t : surface.Triangles)
          {
            double x[3], y[3];
            for (int c = 0; c < 3; ++c)
            {
              const glm::vec3 p = scene.Vertex(t, c);
              x[c] = (static_cast<double>(glm::dot(p, u)) + 1.0) / h - 0.5;
              y[c] = (static_cast<double>(glm::dot(p, v)) + 1.0) / h - 0.5;
            }
            const int j0 = std::max(0, static_cast<int>(std::ceil(std::min({ y[0], y[1], y[2] }))));
            const int j1 =
              std::min(n - 1, static_cast<int>(std::floor(std::max({ y[0], y[1], y[2] }))));
            for (int j = j0; j <= j1; ++j)
            {
              const double row = static_cast<double>(j);
              double lo = 1e30, hi = -1e30;
              for (int c = 0; c < 3; ++c)
              {
                const int e = (c + 1) % 3;
                const double ya = y[c], yb = y[e];
                if ((ya <= row && row <= yb) || (yb <= row && row <= ya))
                {
                  const double xs =
                    ya == yb ? std::min(x[c], x[e]) : x[c] + (row - ya) / (yb - ya) * (x[e] - x[c]);
                  const double xe = ya == yb ? std::max(x[c], x[e]) : xs;
                  lo = std::min(lo, xs);
                  hi = std::max(hi, xe);
                }
              }
              const int i0 = std::max(0, static_cast<int>(std::ceil(lo)));
              const int i1 = std::min(n - 1, static_cast<int>(std::floor(hi)));
              if (i0 > i1)
              {
                continue;
              }
              crossings += static_cast<std::uint64_t>(i1 - i0 + 1);
              for (int ti = i0 / ts; ti <= i1 / ts; ++ti)
              {
                marked[static_cast<std::size_t>(j / ts) * m + ti] = 1;
              }
            }
          }
          own.Pairs += static_cast<std::uint64_t>(std::count(marked.begin(), marked.end(), 1));
          own.Crossings += crossings;
          own.SpecularCrossings += mirror[s] ? crossings : 0;
          own.DepthCrossings += offPlane[s] ? crossings : 0;
        }
      }
    });
  for (const MapCounts& c : perDirection)
  {
    counts.Pairs += c.Pairs;
    counts.Crossings += c.Crossings;
    counts.SpecularCrossings += c.SpecularCrossings;
    counts.DepthCrossings += c.DepthCrossings;
  }
  if (sampled < directions.Size())
  {
    const double scale = static_cast<double>(directions.Size()) / static_cast<double>(sampled);
    for (std::uint64_t* count :
      { &counts.Pairs, &counts.Crossings, &counts.SpecularCrossings, &counts.DepthCrossings })
    {
      *count = static_cast<std::uint64_t>(static_cast<double>(*count) * scale);
    }
  }
  return counts;
}
} // namespace

// What a LightField allocates for the counts (AllocatedBytes), plus the propagation's receive
// buffers (one texture's worth of flux per worker block): the peak while propagating.
MemoryEstimate EstimateFor(const TriangleScene& scene, const std::vector<Surface>& surfaces,
  const DirectionSet& directions, const LightFieldSettings& settings, bool specular,
  std::size_t sampleStride)
{
  MemoryEstimate e;
  e.Surfaces = surfaces.size();
  for (const Surface& s : surfaces)
  {
    e.Texels += s.TexelCount();
  }
  const MapCounts c =
    CountMapContents(scene, surfaces, directions, settings, std::max<std::size_t>(sampleStride, 1));
  const std::uint64_t ts = static_cast<std::uint64_t>(settings.TileSide());
  const std::uint64_t tiles =
    static_cast<std::uint64_t>(settings.TilesPerSide) * settings.TilesPerSide;
  e.MapCells = c.Crossings;
  const std::uint64_t words = CellIndex::WordsPerMap(ts * ts);
  // Per map: its tile entry, its depth start, its cell index's mask and rank words. Per
  // crossing: a blocked bit, a float depth off the plane, float radiance and unshot specular
  // radiance on mirrors (while propagating). Per subfield: its tile starts.
  e.MapBytes = c.Pairs *
      (sizeof(TileEntry) + sizeof(std::uint32_t) +
        words * (sizeof(std::uint64_t) + sizeof(std::uint32_t))) +
    (c.Crossings + 63 * directions.Size()) / 64 * sizeof(std::uint64_t) +
    c.DepthCrossings * sizeof(float) +
    (specular ? c.SpecularCrossings * 2 * sizeof(glm::vec3) : 0) +
    directions.Size() * ((tiles + 1) * sizeof(std::uint32_t) + sizeof(Subfield));
  const std::uint64_t blocks = DefaultBlockCount(directions.Size());
  // The final gather's working memory (FinalGather.cxx), counted as if every texel had
  // triangles: the shares summed over the ranks (value and flag, 4 floats), the working copy of
  // the totals (which then stays as the gathered totals, the propagated ones kept beside them:
  // AllocatedBytes counts both), the first pass's totals the second pass reads
  // (FinalGatherOptions::Prepass), the per-texel triangle lists' starts and about one entry, and
  // two flag bytes.
  e.GatherBytes = e.Texels *
    (4 * sizeof(float) + 2 * sizeof(glm::vec3) + 2 * sizeof(std::uint32_t) +
      2 * sizeof(std::uint8_t));
  // total + unshot + capacity (+ the propagated totals a gathered field keeps), and the larger
  // of one receive buffer per worker block during propagation and the final gather's working
  // memory (the two never overlap).
  e.TextureBytes = e.Texels * (2 * sizeof(glm::vec3) + sizeof(float)) +
    std::max<std::uint64_t>(blocks * e.Texels * sizeof(glm::vec3), e.GatherBytes);
  e.TotalBytes = e.MapBytes + e.TextureBytes;
  return e;
}

MemoryEstimate EstimateWithinBudget(const TriangleScene& scene,
  const std::vector<Surface>& surfaces, const DirectionSet& directions,
  const LightFieldSettings& settings, bool specular, std::size_t ranks)
{
  const std::size_t stride = 64;
  if (directions.Size() >= 8 * stride)
  {
    MemoryEstimate sampled = EstimateFor(scene, surfaces, directions, settings, specular, stride);
    const std::uint64_t share =
      sampled.TotalBytes - sampled.MapBytes + sampled.MapBytes / std::max<std::size_t>(ranks, 1);
    if (static_cast<double>(share) > 1.5 * static_cast<double>(settings.MemoryBudget))
    {
      sampled.SampleStride = stride;
      return sampled;
    }
  }
  return EstimateFor(scene, surfaces, directions, settings, specular);
}

std::string MemoryEstimate::Describe() const
{
  std::ostringstream out;
  out << (this->SampleStride > 1 ? "about " : "") << FormatBytes(this->TotalBytes)
      << " (radiance maps " << FormatBytes(this->MapBytes) << " for " << this->MapCells
      << " crossings, " << this->Surfaces << " surfaces with " << this->Texels
      << " texels: " << FormatBytes(this->TextureBytes);
  if (this->SampleStride > 1)
  {
    out << "; counted on 1 in " << this->SampleStride << " directions";
  }
  out << ")";
  return out.str();
}

MemoryEstimate EstimateMemory(const TriangleScene& scene, const LightFieldSettings& settings)
{
  const std::string problem = settings.Validate();
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  if (scene.TriangleCount() == 0)
  {
    throw std::invalid_argument("the scene has no triangles");
  }
  TriangleScene unit = scene;
  NormalizeToUnitSphere(unit);
  const DirectionSet directions = DirectionSet::WithCount(settings.Directions);
  std::vector<std::uint32_t> triangleSurface;
  const float texel = settings.TexelSize > 0.0f ? settings.TexelSize : settings.CellSize();
  const std::vector<Surface> surfaces = GroupSurfaces(
    unit, texel, triangleSurface, settings.ContactTexelHalvings, settings.SurfaceTexelLevels);
  bool specular = false;
  for (const SceneMaterial& m : unit.Materials)
  {
    specular = specular || glm::length(m.Specular) > 0.0f;
  }
  return EstimateWithinBudget(unit, surfaces, directions, settings, specular, 1);
}

} // namespace vlf
} // namespace mesolight
