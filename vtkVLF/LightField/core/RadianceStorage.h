// SPDX-License-Identifier: BSD-3-Clause
// RadianceStorage: how a LightField keeps its radiance maps in memory, in plain C++ (GLM, no VTK).
// Measured with `mesolight bench vlf-storage` (docs/vlf.md, "Storage"): a few percent of the
// dense float maps of Wither 2005 §2.4.1, the same lookups.
//
// Sparse cells. Most cells of most radiance maps hold no crossing: a tile's map of a surface
// covers the tile's whole square but the surface's projection only a part of it (a quarter to a
// half of the cells on the Cornell box). CellIndex keeps one bit per map cell (crossing or not)
// and, per 64-bit word, how many crossings come before it; a crossing's slot -- its index into
// the per-crossing arrays -- is that count plus the set bits below it in its word (a popcount).
//
// Depths from the planes. Surfaces are planar: where a line crosses one follows from its plane.
// Only maps whose traced crossings lie off it (CrossingDepths) store their depths.
//
// Radiance from the textures. Without mirrors, a surface sends the same radiance along every
// line, its diffuse texture at the crossing: what a crossing has sent is its surface's total
// diffuse texture less the unshot part there (LightField::SentRadiance), nothing to store. A
// mirror's radiance depends on the direction: the mirrors' maps are numbered first, so their
// crossings hold the first slots, and only they store radiance (and unshot specular radiance).
//
// Shared-exponent radiance. That stored radiance is RGB9E5 (Ward, "Real Pixels", Graphics Gems
// II 1991, in the layout of EXT_texture_shared_exponent) once propagated: three 9-bit mantissas
// and one 5-bit exponent in 32 bits instead of 96. Every channel is within 2^-9 max(r, g, b) of
// its value (round to nearest). A RadianceArray scales its values by a power of two (Exponent)
// so that its largest value sits at the top of the format's range: any emission is
// representable, and values more than 2^29 below the largest become zero.
//
// Propagation adds to the radiance of every mirror crossing once per iteration; shared-exponent
// rounding at every step would lose each addition smaller than half a step of the 9-bit
// mantissa (late bounces onto bright cells) and bias the field dark. So a RadianceArray is
// either full float (while propagating) or compact, and turns itself back to float at the first
// write. Propagate and PropagateToTolerance compact the field after their last iteration (before
// its snapshot). A snapshot stores each array as it is held: the last one compact, and loaded
// compact; those of earlier iterations float, so that resuming from them gives the field of an
// uninterrupted run bit for bit.
#ifndef mesolight_vlf_RadianceStorage_h
#define mesolight_vlf_RadianceStorage_h

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{

// RGB9E5 (see above). Negative, NaN and zero channels encode as 0; values above MaxRgb9e5 clamp.
constexpr float MaxRgb9e5 = 65408.0f; // (2^9 - 1) / 2^9 * 2^16
std::uint32_t EncodeRgb9e5(const glm::vec3& rgb);
inline glm::vec3 DecodeRgb9e5(std::uint32_t packed)
{
  // 2^(e - 15 - 9) as a float built from its bits: e - 24 is within [-24, 7], always normal.
  const std::uint32_t bits = ((packed >> 27) + 103u) << 23;
  float scale;
  std::memcpy(&scale, &bits, sizeof(scale));
  return glm::vec3(static_cast<float>(packed & 0x1ffu), static_cast<float>((packed >> 9) & 0x1ffu),
           static_cast<float>((packed >> 18) & 0x1ffu)) *
    scale;
}

// Which cells of a subfield's maps (maps x cellsPerMap, map m's cells at m * cellsPerMap) hold a
// crossing, and each such cell's slot (see above).
class CellIndex
{
public:
  // Occupied cells given as ascending global cell indices (map * cellsPerMap + local).
  void Build(std::size_t maps, std::size_t cellsPerMap, const std::vector<std::size_t>& occupied);
  // From stored mask words (maps * WordsPerMap(cellsPerMap) of them). Returns false, leaving the
  // index empty, when the count is wrong or a bit lies beyond a map's last cell.
  bool Assign(std::size_t maps, std::size_t cellsPerMap, std::vector<std::uint64_t> words);
  void Clear();

  // Slot of the cell (map, local), or -1 when it holds no crossing.
  std::int64_t Slot(std::size_t map, std::size_t local) const
  {
    const std::size_t w = map * this->PerMap + (local >> 6);
    const std::uint64_t word = this->Mask[w];
    const std::uint64_t bit = std::uint64_t(1) << (local & 63);
    if (!(word & bit))
    {
      return -1;
    }
    return static_cast<std::int64_t>(this->Rank[w]) + __builtin_popcountll(word & (bit - 1));
  }
  std::size_t Slots() const { return this->Occupied; }
  // Slot of the map's first crossing (its crossings are the next consecutive slots).
  std::size_t MapFirstSlot(std::size_t map) const { return this->Rank[map * this->PerMap]; }
  std::size_t MapSlots(std::size_t map) const
  {
    return (map + 1 < this->MapCount ? this->Rank[(map + 1) * this->PerMap] : this->Occupied) -
      this->Rank[map * this->PerMap];
  }
  std::size_t Maps() const { return this->MapCount; }
  std::size_t CellsPerMap() const { return this->Cells; }
  const std::vector<std::uint64_t>& Words() const { return this->Mask; }
  std::uint64_t Bytes() const;
  static std::size_t WordsPerMap(std::size_t cellsPerMap) { return (cellsPerMap + 63) / 64; }

  void Pack(std::string& out) const;
  // Throws std::runtime_error for a truncated or inconsistent message.
  void Unpack(const std::string& in, std::size_t& at);

  // Crossings whose line runs into a solid (LightField::Receiver): they send nothing. Found from
  // the geometry (LightField::MarkBlocked), neither packed nor stored.
  void SetBlocked(std::size_t slot)
  {
    if (this->BlockedBits.size() * 64 < this->Occupied)
    {
      this->BlockedBits.assign((this->Occupied + 63) / 64, 0);
    }
    this->BlockedBits[slot >> 6] |= std::uint64_t(1) << (slot & 63);
  }
  bool Blocked(std::size_t slot) const
  {
    return (slot >> 6) < this->BlockedBits.size() &&
      (this->BlockedBits[slot >> 6] >> (slot & 63) & 1) != 0;
  }

  bool operator==(const CellIndex& other) const
  {
    return this->Cells == other.Cells && this->Mask == other.Mask;
  }

private:
  void Count();
  std::size_t MapCount = 0;
  std::size_t Cells = 0;
  std::size_t PerMap = 0;
  std::size_t Occupied = 0;
  std::vector<std::uint64_t> Mask;
  std::vector<std::uint32_t> Rank; // crossings before each word
  std::vector<std::uint64_t> BlockedBits;
};

// Depth of each crossing along its line. Surfaces are planar, so where a line crosses one follows
// from the plane (LightField::PlaneDepth): a map whose traced crossings all lie within
// PlaneDepthTolerance of it stores no depth; the others (triangles a little off their surface's
// plane) store a float per crossing.
constexpr float PlaneDepthTolerance = 1e-6f; // a tenth of the coincident-face distance
class CrossingDepths
{
public:
  static constexpr std::uint32_t FromPlane = 0xffffffffu;
  bool FollowsPlane(std::size_t map) const { return this->Start[map] == FromPlane; }
  // Stored depth of the crossing `index` of the map (its slot minus the map's first).
  float Stored(std::size_t map, std::size_t index) const
  {
    return this->Values[this->Start[map] + index];
  }
  std::vector<std::uint32_t> Start; // per map: its first stored depth, or FromPlane
  std::vector<float> Values;

  void Clear();
  std::uint64_t Bytes() const;
  void Pack(std::string& out) const;
  void Unpack(const std::string& in, std::size_t& at); // throws std::runtime_error
  bool operator==(const CrossingDepths& other) const
  {
    return this->Start == other.Start && this->Values == other.Values;
  }
};

// Radiance per crossing (slot), full float or compact (see above).
class RadianceArray
{
public:
  // A writable element: it is its value (a glm::vec3, so glm's operators take it); writing it
  // turns the array to float first.
  class Reference : public glm::vec3
  {
  public:
    Reference& operator=(const glm::vec3& v)
    {
      this->Array->Floats()[this->I] = v;
      static_cast<glm::vec3&>(*this) = v;
      return *this;
    }
    Reference& operator+=(const glm::vec3& v)
    {
      glm::vec3& stored = this->Array->Floats()[this->I];
      stored += v;
      static_cast<glm::vec3&>(*this) = stored;
      return *this;
    }

  private:
    friend class RadianceArray;
    Reference(RadianceArray* array, std::size_t i)
      : glm::vec3(static_cast<const RadianceArray&>(*array)[i])
      , Array(array)
      , I(i)
    {
    }
    RadianceArray* Array;
    std::size_t I;
  };
  class ConstIterator
  {
  public:
    glm::vec3 operator*() const { return (*this->Array)[this->I]; }
    ConstIterator& operator++()
    {
      ++this->I;
      return *this;
    }
    bool operator!=(const ConstIterator& o) const { return this->I != o.I; }

  private:
    friend class RadianceArray;
    ConstIterator(const RadianceArray* array, std::size_t i)
      : Array(array)
      , I(i)
    {
    }
    const RadianceArray* Array;
    std::size_t I;
  };

  glm::vec3 operator[](std::size_t i) const
  {
    return this->IsCompact() ? DecodeRgb9e5(this->Packed[i]) * this->Scale : this->Values[i];
  }
  Reference operator[](std::size_t i) { return Reference(this, i); }
  std::size_t size() const { return this->IsCompact() ? this->Packed.size() : this->Values.size(); }
  bool empty() const { return this->size() == 0; }
  ConstIterator begin() const { return ConstIterator(this, 0); }
  ConstIterator end() const { return ConstIterator(this, this->size()); }

  // n float values (the array is float after it).
  void assign(std::size_t n, const glm::vec3& value);
  void clear(); // and frees the memory
  bool IsCompact() const { return this->Compact; }
  // To RGB9E5 (nothing when already compact), freeing the float values.
  void MakeCompact();
  // The float values, converted from the compact form first when needed.
  std::vector<glm::vec3>& Floats();

  // The compact form: the words and the power of two they are scaled by (for the snapshot).
  // Compact() makes it when the array is float, without changing the array.
  struct CompactForm
  {
    std::int32_t Exponent = 0;
    std::vector<std::uint32_t> Words;
  };
  CompactForm Compacted() const;
  // The array from a compact form (the snapshot's); exponents outside [-100, 100] are refused
  // (false, array unchanged): no radiance needs them.
  bool AssignCompact(std::int32_t exponent, std::vector<std::uint32_t> words);

  std::uint64_t Bytes() const; // held now (capacity)
  // The same values (as read, whatever the form).
  bool operator==(const RadianceArray& other) const;
  // The values as floats, without changing the array.
  std::vector<glm::vec3> ToVector() const;
  void Pack(std::string& out) const;
  void Unpack(const std::string& in, std::size_t& at); // throws std::runtime_error

private:
  std::vector<glm::vec3> Values;
  std::vector<std::uint32_t> Packed;
  float Scale = 1.0f;
  std::int32_t Exponent = 0;
  bool Compact = false;
};

} // namespace vlf
} // namespace mesolight

#endif
