// SPDX-License-Identifier: BSD-3-Clause
// Snapshot: a light field on disk after each propagation iteration (Wither 2005 §2.4.2.1: the
// propagator writes its state after every iteration and can continue from it).
//
// Format (little-endian, version 2): a 48-byte header -- magic "MLVLFSNP", version, byte-order
// mark, payload size, payload checksum, header checksum -- then the payload: settings,
// iterations done, the (unit-sphere) scene with its materials, the diffuse textures, the energy
// log, every subfield's tile lists and maps (below) and the scene's surface names
// (TriangleScene::SurfaceNames, SurfaceIds). Surfaces and directions are rebuilt from the
// scene and settings on reading. The checksum is a 64-bit multiply-xorshift hash of the payload
// words.
//
// Writing goes to "<path>.tmp-<pid>" in the same directory, is flushed to disk (fsync), then
// renamed over <path>: a kill at any moment leaves either the previous snapshot or the new one.
// Reading checks the header, the size (a truncated file is named as such), every count against
// what the scene and settings imply and against the bytes left, and the checksum; any problem
// throws SnapshotError with a message saying what is wrong, never a crash.
#ifndef mesolight_vlf_Snapshot_h
#define mesolight_vlf_Snapshot_h

#include "LightField.h"

#include <functional>
#include <memory>
#include <stdexcept>
#include <string>

namespace mesolight
{
namespace vlf
{

class SnapshotError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

// Version 2 stores the maps sparse (RadianceStorage.h): per subfield the cell mask words, per
// map whether its depths follow from its surface's plane, the other maps' crossings' depths, and
// the radiance and unshot specular radiance each as a form byte then either floats (0: a snapshot
// taken while propagating) or a power-of-two exponent and shared-exponent words (1: a propagated
// field); both empty in a scene without mirrors (LightField::SentRadiance). Version 1 (every map
// cell, float radiance, no surface names) is still read, into the compact form.
constexpr std::uint32_t SnapshotVersion = 2;
constexpr std::uint32_t DenseSnapshotVersion = 1;

// Writes atomically (see above). Throws SnapshotError when the file cannot be written (the
// previous file, if any, is left untouched).
void WriteSnapshot(const LightField& field, const std::string& path);
// The same with subfield k's maps taken from subfieldOf(k), asked for in ascending k, one at a
// time (a distributed field's rank 0 receives the others' maps this way: Distribution.h).
void WriteSnapshot(const LightField& field, const std::string& path,
  const std::function<const Subfield&(std::size_t k)>& subfieldOf);

// The same in an older layout: version DenseSnapshotVersion writes what builds before version 2
// wrote (for the tests of reading old files and `mesolight bench vlf-storage`).
void WriteSnapshotVersion(const LightField& field, const std::string& path, std::uint32_t version,
  const std::function<const Subfield&(std::size_t k)>& subfieldOf = {});

// Reads a snapshot. memoryBudget (bytes, 0 = the one stored) is checked before allocating.
// Throws SnapshotError for a missing, foreign, truncated, corrupt or incompatible file, and
// MemoryBudgetError when the field does not fit the budget.
std::unique_ptr<LightField> ReadSnapshot(const std::string& path, std::uint64_t memoryBudget = 0);
// The same keeping the maps of some subfields only: share(field), called once the field's
// structure is built and before any map is read, sets field.OwnedSubfields; the maps of the
// others are read, checked (checksum, finite, non-negative) and dropped one at a time, so that a
// rank resuming its share of a distributed field never holds the whole (Distribution.h). The
// memory budget is checked against the maps / shareRanks.
std::unique_ptr<LightField> ReadSnapshot(const std::string& path, std::uint64_t memoryBudget,
  std::size_t shareRanks, const std::function<void(LightField&)>& share);

// A snapshot file around any payload: the header with matching checksums, then `payload`. For
// tests and the fuzz target (fuzz/snapshot.cxx), which reach the payload's checks past the
// checksums.
std::string SnapshotFileWithPayload(const std::string& payload);

// True when the file exists and starts with the snapshot magic (cheap: reads 8 bytes).
bool IsSnapshotFile(const std::string& path);
bool FileExists(const std::string& path);

} // namespace vlf
} // namespace mesolight

#endif
