// SPDX-License-Identifier: BSD-3-Clause
// LightField: the virtual light field's data structure (Wither 2005 §2.4.1), in plain C++ (GLM, no
// VTK types).
//
// For each direction d_k of a DirectionSet a parallel subfield (PSF) of N x N lines parallel to
// d_k covers the unit sphere's projection: line (i, j) passes through the centre of cell (i, j)
// of a square [-1, 1]^2 in the plane perpendicular to d_k (cell side h = 2/N). The cells are
// split into m x m tiles. A line carries light both ways, so the upper-hemisphere directions
// d_k stand for the whole sphere {+d_k, -d_k}.
//
// Surfaces. The scene's triangles are grouped into planar surfaces: triangles of one material on
// one plane (within 1e-4 of the unit sphere) form one surface. A line crosses a plane at most
// once, so (subfield, cell, surface) names at most one crossing. Surfaces are one-sided: the front
// (counter-clockwise) side emits and reflects; light reaching a back side is absorbed (closed
// scenes never show back sides to light).
//
// Per tile the list of surfaces its lines cross, sorted by surface id (lookups binary-search it,
// Wither 2005 §2.4.2.2.2). Per surface per tile a radiance map of tileSide x tileSide cells: the
// crossing's depth along the line (negative when the cell's line misses the surface: Wither's
// visibility map), the radiance the surface has sent along the line so far (RGB), and, when the
// scene has mirror surfaces, the perfect-specular radiance received but not yet sent. Only the
// cells whose line crosses the surface are stored, the radiance in a shared exponent once
// propagated (RadianceStorage.h).
//
// Per surface a total diffuse radiance texture for walkthrough (Wither 2005 §2.4.2.2.3, progressive
// mode): texels on the surface's plane in its own frame x = Origin + s AxisU + t AxisV, spanning
// the bounding rectangle of its triangles; texel centres at ((a + 1/2) TexelU, (b + 1/2) TexelV).
// Values are read and written with clamped bilinear weights. Beside the total, each texel keeps
// the diffuse radiance received but not yet shot (progressive radiosity) and its shooting
// capacity (Propagation.h).
#ifndef mesolight_vlf_LightField_h
#define mesolight_vlf_LightField_h

#include "DirectionSet.h"
#include "MemoryBudget.h" // FormatBytes
#include "Progress.h"
#include "RadianceStorage.h"
#include "TriangleScene.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstdint>
#include <functional>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{
class EmbreeScene;

namespace vlf
{

/** Lines start this far behind the centre: the scene lies within the unit sphere. */
constexpr float LineStart = 1.01f;

// Thrown when the progress callback (Progress.h) returned false; the light field is then
// unusable (its last snapshot is not).
class AbortedError : public std::runtime_error
{
public:
  AbortedError()
    : std::runtime_error("light field computation aborted")
  {
  }
};

// Runs work(block, item) for every item in [0, count) on mesolight::ParallelFor. Items are
// dealt out in rounds of `blocks` concurrent workers, item start + b * 4 + q to block b whatever
// the thread, so a block's private buffer (no other concurrent worker touches it) gets the same
// items in the same order on any machine split. Before every round and at the end (on the
// calling thread) progress gets a fraction from begin to end; false throws AbortedError.
void RunInBlocks(std::size_t count, std::size_t blocks, const ProgressCallback& progress,
  double begin, double end, const std::function<void(std::size_t block, std::size_t item)>& work);
// Worker blocks used for `count` items: twice the hardware threads, at most count.
std::size_t DefaultBlockCount(std::size_t count);

// Thrown when the structure would need more memory than the budget allows (nothing allocated).
class MemoryBudgetError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// The most LightFieldSettings::ContactTexelHalvings: texels an eighth of the scene's.
constexpr int MaxContactTexelHalvings = 3;
// The range of LightFieldSettings::SurfaceTexelLevels: texels from an eighth to four times the
// scene's.
constexpr int MinSurfaceTexelLevel = -3;
constexpr int MaxSurfaceTexelLevel = 2;

struct LightFieldSettings
{
  std::size_t Directions = 513; // 2 n^2 + 1: 513, 2049, 8193 (DirectionSet::WithCount)
  int RaysPerSide = 32;         // N: lines per subfield side
  int TilesPerSide = 4;         // m: tiles per subfield side, N a multiple of m
  // Texel side of the total diffuse textures in unit-sphere units; 0 = the cell side 2/N.
  float TexelSize = 0.0f;
  // Surfaces on which other surfaces stand (a box on a floor, a rib against a wall:
  // ContactSurfaces) get texels 2^-ContactTexelHalvings of TexelSize (0-3). A contact shadow is a
  // strip about as wide as the feature is high, narrower than the texels chosen for the whole
  // scene, and bilinear reads between texel centres smear it into the light beside it. (A
  // contact edge is a discontinuity of the radiance itself, the D0 discontinuity of Heckbert,
  // "Discontinuity Meshing for Radiosity", 1992: radiosity meshes are refined there for the same
  // reason.)
  int ContactTexelHalvings = 0;
  // Per surface (in GroupSurfaces' order) a texel level: texels TexelSize * 2^level, level in
  // [MinSurfaceTexelLevel, MaxSurfaceTexelLevel]. Empty: every surface at TexelSize (contact
  // surfaces finer by ContactTexelHalvings); set, it replaces ContactTexelHalvings. Chosen from a
  // first pass's light (AdaptiveTexels.h, by default with automatic lines: finer where the light
  // varies, the contact surfaces at least at their halvings) and kept in the field file.
  std::vector<std::int8_t> SurfaceTexelLevels;
  std::uint64_t MemoryBudget = std::uint64_t(4) << 30; // bytes
  // §3.6.2: weight each direction by its solid angle. False gives every direction 2 pi / K
  // (only for the negative tests: the field is then biased toward densely sampled directions).
  bool UseSolidAngleWeights = true;

  // Empty when usable, else what is wrong ("--rays 30 is not a multiple of --tiles 4").
  std::string Validate() const;
  int TileSide() const { return this->RaysPerSide / this->TilesPerSide; }
  float CellSize() const { return 2.0f / static_cast<float>(this->RaysPerSide); }
};

struct Surface
{
  std::uint32_t Material = 0;
  glm::vec3 Normal{ 0.0f, 0.0f, 1.0f }; // unit, front side
  float Offset = 0.0f;                  // plane: dot(Normal, x) == Offset
  glm::vec3 Origin{ 0.0f };             // texture frame
  glm::vec3 AxisU{ 1.0f, 0.0f, 0.0f };
  glm::vec3 AxisV{ 0.0f, 1.0f, 0.0f };
  int TextureWidth = 1;
  int TextureHeight = 1;
  float TexelU = 1.0f; // texel size along AxisU / AxisV
  float TexelV = 1.0f;
  std::size_t TexelOffset = 0; // first texel in LightField::Textures
  double Area = 0.0;
  std::vector<std::uint32_t> Triangles;

  std::size_t TexelCount() const
  {
    return static_cast<std::size_t>(this->TextureWidth) *
      static_cast<std::size_t>(this->TextureHeight);
  }
  // Continuous texel coordinates of a point (texel centres at integers).
  glm::vec2 TexelCoordinates(const glm::vec3& x) const;
  glm::vec3 TexelCentre(int a, int b) const;
};

// Up to four texels and clamped bilinear weights (sum 1) of a point on a surface.
struct TexelWeights
{
  std::array<std::size_t, 4> Texel{}; // global texel index (Surface::TexelOffset included)
  std::array<float, 4> Weight{};
};

struct TileEntry
{
  std::uint32_t Surface = 0;
  std::uint32_t Map = 0; // index of the map: its cells start at Map * tileSide^2
};

struct Subfield
{
  glm::vec3 Direction{ 0.0f, 0.0f, 1.0f };
  glm::vec3 AxisU{ 1.0f, 0.0f, 0.0f }; // cell i grows along AxisU, j along AxisV
  glm::vec3 AxisV{ 0.0f, 1.0f, 0.0f };
  float Weight = 0.0f;                  // solid angle used in propagation and gathering (sr)
  std::vector<std::uint32_t> TileStart; // m*m + 1 offsets into Entries
  std::vector<TileEntry> Entries;       // per tile, sorted by surface
  // The maps' cells are sparse (RadianceStorage.h): Cells says which hold a crossing and gives
  // each its slot, the index into the per-crossing arrays below.
  CellIndex Cells;
  CrossingDepths Depth;         // per crossing: distance along the line (LightField::CrossingDepth)
  RadianceArray Radiance;       // per mirror crossing (the first slots): radiance sent along
                                // the line so far (LightField::SentRadiance)
  RadianceArray UnshotSpecular; // per mirror crossing (empty without mirror surfaces)
};

// One surface crossing of a line.
struct Crossing
{
  std::uint32_t Surface = 0;
  float Depth = 0.0f;
  std::size_t Cell = 0; // slot: index into the subfield's per-crossing arrays
};

struct MemoryEstimate
{
  std::size_t Surfaces = 0;
  std::size_t Texels = 0;
  std::uint64_t MapCells = 0; // crossings: lattice points in the projected triangles
  std::uint64_t MapBytes = 0; // cell indices, tile lists, stored depths and mirror radiance
  // total, unshot, capacity, + the larger of the per-block receive buffers and GatherBytes
  std::uint64_t TextureBytes = 0;
  // The final gather's working memory (FinalGather.h): its shares, its copy of the totals (kept
  // afterwards beside the propagated ones), triangle lists
  std::uint64_t GatherBytes = 0;
  std::uint64_t TotalBytes = 0;
  // 1: counted on every direction. n > 1: on 1 in n, scaled (a field far over its budget:
  // EstimateWithinBudget); Describe() then says "about".
  std::size_t SampleStride = 1;
  std::string Describe() const; // "1.23 GiB (maps 1.2 GiB for 2.1e7 cells, textures 3 MiB)"
};

// Bytes needed by a LightField for the scene (normalised to the unit sphere first, as Build
// does) and settings while it propagates, computed without allocating the structure: the maps'
// crossings and (tile, surface) pairs counted from the projected triangles, so within a few
// percent of what Build allocates (AllocatedBytes) plus propagation's receive buffers. A field
// of many directions far over settings.MemoryBudget is counted on a sample of its directions
// only (SampleStride): enough to refuse it, as Build does, without the exact count's minute.
// Throws std::invalid_argument for unusable settings or an empty scene.
MemoryEstimate EstimateMemory(const TriangleScene& scene, const LightFieldSettings& settings);

class Reducer; // Distribution.h

class LightField
{
public:
  // Normalises a copy of the scene into the unit sphere, groups surfaces, checks the memory
  // estimate against the budget (MemoryBudgetError, nothing allocated), then traces every
  // subfield's lines with Embree (repeated nearest hits, 16-ray packets) to fill the tile
  // lists, depths and texture capacities. Throws std::invalid_argument for bad settings or a
  // scene CheckScene rejects (no emitter, degenerate triangles) or with Kd + Ks > 1.
  static std::unique_ptr<LightField> Build(const TriangleScene& scene,
    const LightFieldSettings& settings, const ProgressCallback& progress = {});
  // Distributed (Distribution.h): with a reducer of several ranks, traces only this rank's share
  // of the directions (BalanceDirections), sums the texel capacities over the ranks, and checks
  // the budget against this rank's share of the maps; failures are agreed between the ranks.
  static std::unique_ptr<LightField> Build(const TriangleScene& scene,
    const LightFieldSettings& settings, const ProgressCallback& progress, Reducer* reducer);

  // The structure without subfield contents (for Snapshot): scene normalised, surfaces grouped,
  // directions and frames set, memory checked; maps, tile lists and textures left empty.
  static std::unique_ptr<LightField> CreateEmpty(
    const TriangleScene& scene, const LightFieldSettings& settings);

  const LightFieldSettings& Settings() const { return this->Config; }
  const DirectionSet& Directions() const { return *this->DirectionsPtr; }
  const TriangleScene& Scene() const { return this->NormalizedScene; } // in the unit sphere
  // world = Centre + unit / Scale
  float NormalizationScale() const { return this->Scale; }
  glm::vec3 NormalizationCentre() const { return this->Centre; }
  const std::vector<Surface>& Surfaces() const { return this->SurfaceList; }
  std::uint32_t SurfaceOfTriangle(std::size_t triangle) const
  {
    return this->TriangleSurface[triangle];
  }
  const SceneMaterial& MaterialOf(std::uint32_t surface) const
  {
    return this->NormalizedScene.Materials[this->SurfaceList[surface].Material];
  }
  bool HasSpecular() const { return this->AnySpecular; }
  const MemoryEstimate& Estimate() const { return this->EstimateUsed; }
  // What the maps and textures hold now (with the propagated totals a gathered field keeps).
  std::uint64_t AllocatedBytes() const;
  // The radiance maps to their compact form (RadianceStorage.h): propagation's float
  // accumulators become shared-exponent words. The next propagation turns them back.
  void CompactRadiance();

  std::size_t SubfieldCount() const { return this->Subfields.size(); }
  // Whether this process holds subfield k's maps (all when OwnedSubfields is empty: serial).
  bool OwnsSubfield(std::size_t k) const
  {
    return this->OwnedSubfields.empty() || this->OwnedSubfields[k] != 0;
  }
  std::vector<std::uint8_t> OwnedSubfields; // per direction, 1 = held here (Distribution.h)
  const Subfield& GetSubfield(std::size_t k) const { return this->Subfields[k]; }
  Subfield& GetSubfield(std::size_t k) { return this->Subfields[k]; }

  // Continuous cell coordinates of a point in subfield k (cell centres at integers).
  glm::vec2 CellCoordinates(std::size_t k, const glm::vec3& p) const;
  // Distance along subfield k's lines from their origin plane to p.
  float DepthOf(std::size_t k, const glm::vec3& p) const;
  // Point where line (i, j) of subfield k is at the given depth.
  glm::vec3 PointOnLine(std::size_t k, int i, int j, float depth) const;
  // Depth of the crossing in slot `slot` of map `map` (surface s, line (i, j)) of subfield k:
  // stored, or where the line meets the surface's plane (CrossingDepths).
  float CrossingDepth(
    std::size_t k, int i, int j, std::size_t map, std::uint32_t surface, std::size_t slot) const;
  float PlaneDepth(std::size_t k, int i, int j, std::uint32_t surface) const;
  // Radiance the crossing in slot `slot` (surface s, line (i, j)) of subfield k has sent along
  // its line so far. Stored (Subfield::Radiance) in a scene with mirrors; without, every surface
  // sends the same radiance along every line, its diffuse texture at the crossing, so what it
  // has sent is the total diffuse texture less its unshot part there (exactly the sum the
  // propagation shot; 0 for crossings whose line runs into a solid, which shoot nothing).
  // Nothing is stored then: the maps hold visibility only.
  glm::vec3 SentRadiance(
    std::size_t k, int i, int j, std::uint32_t surface, std::size_t slot) const;
  // Whether crossings of the surface store their radiance: those of mirrors (Ks > 0), whose
  // radiance depends on the direction. Their maps are numbered first (TileEntry::Map), so their
  // crossings hold the first slots: SpecularSlots of them, the length of Subfield::Radiance and
  // UnshotSpecular.
  bool StoresRadiance(std::uint32_t surface) const;
  // Marks subfield k's crossings whose line runs into a solid (Receiver: LineBlocked) in its
  // cell index: they send nothing (SentRadiance 0). Build and ReadSnapshot call it.
  void MarkBlocked(std::size_t k);
  std::size_t SpecularSlots(const Subfield& f) const;
  // Slot (Crossing::Cell) of surface s on line (i, j) of subfield k, or -1 when the line misses it.
  std::int64_t FindCell(std::size_t k, int i, int j, std::uint32_t surface) const;
  // The crossings of line (i, j) of subfield k ordered by depth (out is cleared first).
  void LineCrossings(std::size_t k, int i, int j, std::vector<Crossing>& out) const;
  // Which way surface s sends light along subfield k's lines: +1 toward greater depth
  // (its front faces +d_k), -1 toward smaller depth, 0 when it lies along the lines.
  int Orientation(std::size_t k, std::uint32_t surface) const;
  // Where crossing q of a line (LineCrossings of subfield k) sends its light along the line: the
  // index of the receiving crossing, LineEscapes when the line leaves the scene, or LineBlocked
  // when the segment it would light lies inside a solid: the next crossing is a back side (the
  // floor under a box sees the inside of its top). Coincident faces (a closed box's bottom on the
  // floor, a two-sided panel, a light on a ceiling) are stepped over, and of a coincident group
  // the face turned toward the sender receives. A blocked crossing is not part of what the
  // surface shows: it neither shoots nor counts in the texel's capacity (Propagation.h).
  static constexpr std::ptrdiff_t LineEscapes = -1;
  static constexpr std::ptrdiff_t LineBlocked = -2;
  std::ptrdiff_t Receiver(std::size_t k, const std::vector<Crossing>& line, std::size_t q) const;

  // Total diffuse textures (radiance leaving diffusely), unshot diffuse radiance and the
  // shooting capacity (Propagation.h), all indexed by Surface::TexelOffset + b * width + a.
  std::vector<glm::vec3> TotalDiffuse;
  std::vector<glm::vec3> UnshotDiffuse;
  std::vector<float> Capacity;
  // The propagated totals while TotalDiffuse holds the final gather's (FinalGather.h); empty
  // otherwise. Propagating again restores them first.
  std::vector<glm::vec3> PropagatedDiffuse;
  TexelWeights WeightsAt(std::uint32_t surface, const glm::vec3& x) const;
  glm::vec3 SampleTexture(
    const std::vector<glm::vec3>& texture, std::uint32_t surface, const glm::vec3& x) const;

  // Propagation state (Propagation.h).
  int IterationsDone = 0;
  struct IterationEnergy
  {
    int Iteration = 0;
    std::array<double, 3> Shot{};     // flux sent along lines this iteration
    std::array<double, 3> Escaped{};  // left the scene
    std::array<double, 3> Absorbed{}; // (1 - Kd - Ks) of what surfaces received
    // Always zero since blocked crossings (Receiver) shoot nothing; kept for the snapshot format.
    std::array<double, 3> BackFaces{};
    std::array<double, 3> SpecularLost{}; // mirrored into a direction no line can carry
    std::array<double, 3> Unshot{};       // reflected, to be sent next iteration
    double Seconds = 0.0;
    // |Shot - (Escaped + Absorbed + BackFaces + SpecularLost + Unshot)| / Shot, worst channel.
    double ConservationError() const;
  };
  std::vector<IterationEnergy> EnergyLog;

  std::size_t TexelCount() const { return this->TexelTotal; }

private:
  LightField() = default;
  // normalize false: the scene already lies in the unit sphere (a snapshot's).
  void Setup(const TriangleScene& scene, const LightFieldSettings& settings, bool normalize);
  std::size_t BudgetShareRanks = 1; // Setup checks the budget against maps / this (Distribution.h)
  friend std::unique_ptr<LightField> ReadSnapshot(
    const std::string& path, std::uint64_t memoryBudget);
  friend std::unique_ptr<LightField> ReadSnapshot(const std::string& path,
    std::uint64_t memoryBudget, std::size_t shareRanks,
    const std::function<void(LightField&)>& share);
  void TraceSubfield(std::size_t k, const EmbreeScene& embree);

  LightFieldSettings Config;
  std::unique_ptr<DirectionSet> DirectionsPtr;
  TriangleScene NormalizedScene;
  float Scale = 1.0f;
  glm::vec3 Centre{ 0.0f };
  std::vector<Surface> SurfaceList;
  std::vector<std::uint32_t> TriangleSurface;
  std::vector<Subfield> Subfields;
  std::size_t TexelTotal = 0;
  bool AnySpecular = false;
  MemoryEstimate EstimateUsed;
};

// Surface index of degenerate triangles (they belong to no surface).
constexpr std::uint32_t NoSurface = 0xffffffffu;

// The largest texture side of a surface: a unit-sphere scene at the smallest texel size (1e-4)
// needs at most 20000.
constexpr int MaxTextureSide = 1 << 16;

// Groups a (unit-sphere) scene's triangles into planar one-material surfaces with texture
// frames; triangleSurface gets each triangle's surface. Texels are texelSize, on contact surfaces
// (ContactSurfaces) texelSize / 2^contactHalvings; with levels (one per surface,
// LightFieldSettings::SurfaceTexelLevels) texelSize * 2^levels[s] instead. Exposed for tests and
// the estimate. Throws std::invalid_argument when a surface would need more than MaxTextureSide
// texels per side (a scene not normalized to the unit sphere) or when levels has not one entry
// per surface.
std::vector<Surface> GroupSurfaces(const TriangleScene& scene, float texelSize,
  std::vector<std::uint32_t>& triangleSurface, int contactHalvings = 0,
  const std::vector<std::int8_t>& levels = {});

// Per surface of GroupSurfaces, 1 where another surface stands on it: an edge of a triangle of
// another plane lies in its plane (within 1e-4), the surface continues on both sides of that
// edge (probed `probe` away from its midpoint, so an edge along the surface's border -- a wall
// meeting a floor at the room's edge -- is not one) and the triangle rises in front of it. A
// box on a floor, a rib against a wall, a shelf on a wall, a table leg on a floor.
std::vector<std::uint8_t> ContactSurfaces(const TriangleScene& scene,
  const std::vector<Surface>& surfaces, const std::vector<std::uint32_t>& triangleSurface,
  float probe);

} // namespace vlf
} // namespace mesolight

#endif
