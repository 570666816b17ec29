// SPDX-License-Identifier: BSD-3-Clause
// Snapshots whose checksums match but whose contents lie (fuzz/snapshot.cxx builds such files
// with SnapshotFileWithPayload; docs/fuzzing.md): a scene far outside the unit sphere, a direction
// count the file cannot hold, a stored memory budget larger than the machine. Each must be a clear
// error (or a capped budget), never a crash or an allocation the file does not justify.
#include "MemoryBudget.h"
#include "Snapshot.h"
#include "TestDirectory.h"

#include <gtest/gtest.h>

#include <cstdint>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>

namespace
{
using namespace mesolight;
using namespace mesolight::vlf;

// Offsets in the payload (Snapshot.cxx, WritePayload): directions (u64), rays per side (i32),
// tiles per side (i32), texel size (f32), memory budget (u64), solid-angle flag (u8), iterations
// (i32), scale (f32), centre (3 x f32), then the position count (u64) and the positions.
constexpr std::size_t DirectionsAt = 0;
constexpr std::size_t BudgetAt = 20;
constexpr std::size_t ScaleAt = 33;
constexpr std::size_t CentreAt = 37;
constexpr std::size_t FirstPositionAt = 57;

std::string TempPath(const std::string& name)
{
  return mesolight_test::TestPath(name);
}

// The payload of a small valid field (its 48-byte header stripped).
std::string SmallPayload()
{
  LightFieldSettings settings;
  settings.Directions = 19;
  settings.RaysPerSide = 4;
  settings.TilesPerSide = 2;
  settings.TexelSize = 0.5f;
  const std::string path = TempPath("corrupt-counts-source.vlf");
  WriteSnapshot(*LightField::Build(MakeCornellBox(), settings), path);
  std::ifstream in(path, std::ios::binary);
  const std::string file((std::istreambuf_iterator<char>(in)), std::istreambuf_iterator<char>());
  std::remove(path.c_str());
  return file.substr(48);
}

template <typename T>
void Put(std::string& payload, std::size_t at, T value)
{
  std::memcpy(&payload[at], &value, sizeof(T));
}

// Reads `payload` as a snapshot (matching checksums); "" when it reads, else the error.
std::string ReadError(const std::string& payload, std::uint64_t budget = 0,
  std::unique_ptr<LightField>* field = nullptr)
{
  const std::string path = TempPath("corrupt-counts.vlf");
  {
    std::ofstream out(path, std::ios::binary | std::ios::trunc);
    out << SnapshotFileWithPayload(payload);
  }
  std::string error;
  try
  {
    std::unique_ptr<LightField> read = ReadSnapshot(path, budget);
    if (field)
    {
      *field = std::move(read);
    }
  }
  catch (const std::exception& e)
  {
    error = e.what();
  }
  std::remove(path.c_str());
  return error;
}

TEST(VLFSnapshotCorrupt, TheUnalteredPayloadReads)
{
  // What the other tests alter reads back: the wrapping helper itself is right.
  EXPECT_EQ(ReadError(SmallPayload()), "");
}

// Found by fuzz/snapshot.cxx (corpus crash-texture-size-overflow): a vertex far outside the unit
// sphere made a surface's texture side overflow int (undefined behaviour) in GroupSurfaces.
TEST(VLFSnapshotCorrupt, ASceneOutsideTheUnitSphereIsRefused)
{
  std::string payload = SmallPayload();
  Put(payload, FirstPositionAt, 1.0e6f);
  const std::string error = ReadError(payload);
  EXPECT_NE(error.find("not normalized to the unit sphere"), std::string::npos) << error;
}

// A NaN normalisation scale or centre (checksums valid) put the scene nowhere: every command then
// benchmarked empty frames or blamed the object, the placement or the camera.
TEST(VLFSnapshotCorrupt, ANonFiniteNormalisationIsRefused)
{
  const float nan = std::numeric_limits<float>::quiet_NaN();
  std::string payload = SmallPayload();
  Put(payload, ScaleAt, nan);
  std::string error = ReadError(payload);
  EXPECT_NE(error.find("normalisation scale nan is not a positive number"), std::string::npos)
    << error;
  payload = SmallPayload();
  Put(payload, ScaleAt, 0.0f);
  error = ReadError(payload);
  EXPECT_NE(error.find("normalisation scale 0.000000 is not a positive"), std::string::npos)
    << error;
  for (int axis = 0; axis < 3; ++axis)
  {
    payload = SmallPayload();
    Put(payload, CentreAt + 4 * axis, axis == 1 ? std::numeric_limits<float>::infinity() : nan);
    error = ReadError(payload);
    EXPECT_NE(error.find("normalisation centre"), std::string::npos) << axis << ": " << error;
    EXPECT_NE(error.find("is not finite"), std::string::npos) << axis << ": " << error;
  }
}

// A valid-looking 2n^2+1 direction count (n = 4096, 33554433 directions, a 1.3 GB direction
// lattice) in a file of a few KB: refused before the directions are set up.
TEST(VLFSnapshotCorrupt, ADirectionCountTheFileCannotHoldIsRefused)
{
  std::string payload = SmallPayload();
  Put<std::uint64_t>(payload, DirectionsAt, 2ull * 4096 * 4096 + 1);
  const std::string error = ReadError(payload, std::uint64_t(256) << 20);
  EXPECT_NE(error.find("direction count 33554433 does not fit"), std::string::npos) << error;
}

// The same count in memory: LightField::Setup refuses it against the budget before building the
// direction set, not after (the full estimate would refuse it too, but only after allocating).
TEST(VLFSnapshotCorrupt, DirectionsBeyondTheBudgetAreRefusedFirst)
{
  LightFieldSettings settings;
  settings.Directions = 2ull * 4096 * 4096 + 1;
  settings.RaysPerSide = 4;
  settings.TilesPerSide = 2;
  settings.MemoryBudget = std::uint64_t(256) << 20;
  try
  {
    LightField::CreateEmpty(MakeCornellBox(), settings);
    FAIL() << "33554433 directions fit a 256 MiB budget";
  }
  catch (const MemoryBudgetError& e)
  {
    EXPECT_NE(std::string(e.what()).find("directions alone"), std::string::npos) << e.what();
  }
}

// A stored budget of 2^64 - 1 bytes is not believed: the field read back carries at most the
// memory this machine has.
TEST(VLFSnapshotCorrupt, TheStoredBudgetIsCappedByTheMachine)
{
  std::string payload = SmallPayload();
  Put(payload, BudgetAt, std::numeric_limits<std::uint64_t>::max());
  std::unique_ptr<LightField> field;
  ASSERT_EQ(ReadError(payload, 0, &field), "");
  EXPECT_LE(field->Settings().MemoryBudget, AvailableMemory());
  // An explicit budget still wins.
  ASSERT_EQ(ReadError(payload, std::uint64_t(1) << 30, &field), "");
  EXPECT_EQ(field->Settings().MemoryBudget, std::uint64_t(1) << 30);
}

} // namespace
