// SPDX-License-Identifier: BSD-3-Clause
// Snapshots (Wither 2005 §2.4.2.1): exact round trip, resuming gives the same field as running
// straight through, atomic replacement, and clear errors (never a crash) for foreign, truncated
// and corrupt files.
#include "Propagation.h"
#include "Snapshot.h"
#include "TestDirectory.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <csignal>
#include <cstdio>
#include <cstring>
#include <fstream>
#include <iterator>
#include <limits>
#include <string>
#include <thread>
#include <vector>

#include <sys/stat.h>
#include <sys/wait.h>
#include <unistd.h>

namespace
{
using namespace mesolight;
using namespace mesolight::vlf;

std::string TempPath(const std::string& name)
{
  return mesolight_test::TestPath(name);
}

// mirror: the box with a mirror, whose maps store their radiance (LightField::SentRadiance).
std::unique_ptr<LightField> SmallCornell(int iterations, bool mirror = false)
{
  LightFieldSettings settings;
  settings.Directions = 33;
  settings.RaysPerSide = 16;
  settings.TilesPerSide = 4;
  std::unique_ptr<LightField> field =
    LightField::Build(mirror ? MakeCornellBoxWithMirror() : MakeCornellBox(), settings);
  Propagate(*field, iterations);
  return field;
}

// A subfield whose lines cross the mirror (its radiance is stored).
std::size_t MirrorSubfield(const LightField& field)
{
  for (std::size_t k = 0; k < field.SubfieldCount(); ++k)
  {
    if (!field.GetSubfield(k).Radiance.empty())
    {
      return k;
    }
  }
  return 0;
}

std::vector<char> ReadBytes(const std::string& path)
{
  std::ifstream in(path, std::ios::binary);
  return std::vector<char>(std::istreambuf_iterator<char>(in), std::istreambuf_iterator<char>());
}

void WriteBytes(const std::string& path, const std::vector<char>& bytes)
{
  std::ofstream out(path, std::ios::binary | std::ios::trunc);
  out.write(bytes.data(), static_cast<std::streamsize>(bytes.size()));
}

std::string ReadError(const std::string& path)
{
  try
  {
    ReadSnapshot(path);
  }
  catch (const SnapshotError& e)
  {
    return e.what();
  }
  return "";
}

void ExpectSameField(const LightField& a, const LightField& b)
{
  ASSERT_EQ(a.IterationsDone, b.IterationsDone);
  ASSERT_EQ(a.SubfieldCount(), b.SubfieldCount());
  EXPECT_EQ(a.TotalDiffuse, b.TotalDiffuse);
  EXPECT_EQ(a.UnshotDiffuse, b.UnshotDiffuse);
  EXPECT_EQ(a.Capacity, b.Capacity);
  EXPECT_EQ(a.NormalizationScale(), b.NormalizationScale());
  EXPECT_EQ(a.Scene().Positions, b.Scene().Positions);
  for (std::size_t k = 0; k < a.SubfieldCount(); ++k)
  {
    EXPECT_TRUE(a.GetSubfield(k).Depth == b.GetSubfield(k).Depth);
    EXPECT_EQ(a.GetSubfield(k).Radiance, b.GetSubfield(k).Radiance);
  }
}

TEST(VLFSnapshot, RoundTripsExactlyAndResumes)
{
  const std::string path = TempPath("roundtrip.vlf");
  std::remove(path.c_str());
  // A snapshot taken while propagating (the float radiance of iteration 2 of 3).
  std::unique_ptr<LightField> two = SmallCornell(0, true);
  PropagateIteration(*two);
  PropagateIteration(*two);
  ASSERT_FALSE(two->GetSubfield(MirrorSubfield(*two)).Radiance.IsCompact());
  WriteSnapshot(*two, path);
  EXPECT_TRUE(IsSnapshotFile(path));
  EXPECT_FALSE(FileExists(path + ".tmp-" + std::to_string(static_cast<long>(::getpid()))));
  std::unique_ptr<LightField> loaded = ReadSnapshot(path);
  ExpectSameField(*two, *loaded);
  ASSERT_EQ(loaded->EnergyLog.size(), 2u);
  EXPECT_EQ(loaded->EnergyLog[1].Shot, two->EnergyLog[1].Shot);

  // Resume: two iterations, a snapshot, one more == three straight through.
  Propagate(*loaded, 3);
  const std::unique_ptr<LightField> three = SmallCornell(3, true);
  ExpectSameField(*three, *loaded);

  // A propagated field is compact, and its snapshot reads back the same words.
  ASSERT_TRUE(three->GetSubfield(MirrorSubfield(*three)).Radiance.IsCompact());
  WriteSnapshot(*three, path);
  const std::unique_ptr<LightField> reread = ReadSnapshot(path);
  ASSERT_TRUE(reread->GetSubfield(MirrorSubfield(*reread)).Radiance.IsCompact());
  ExpectSameField(*three, *reread);
}

// Version 1 files (every map cell, float radiance) load into the sparse compact form; the
// radiance the lookups see is the float one within the shared exponent's rounding.
TEST(VLFSnapshot, VersionOneFilesStillLoad)
{
  const std::string path = TempPath("version1.vlf");
  std::unique_ptr<LightField> field = SmallCornell(0, true);
  PropagateIteration(*field);
  PropagateIteration(*field);
  WriteSnapshotVersion(*field, path, DenseSnapshotVersion);
  const std::vector<char> bytes = ReadBytes(path);
  std::uint32_t version = 0;
  std::memcpy(&version, bytes.data() + 8, sizeof(version));
  ASSERT_EQ(version, 1u);
  const std::unique_ptr<LightField> loaded = ReadSnapshot(path);
  ASSERT_EQ(loaded->SubfieldCount(), field->SubfieldCount());
  EXPECT_EQ(loaded->TotalDiffuse, field->TotalDiffuse);
  std::size_t crossings = 0;
  for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
  {
    const Subfield& a = field->GetSubfield(k);
    const Subfield& b = loaded->GetSubfield(k);
    ASSERT_TRUE(b.Radiance.IsCompact());
    EXPECT_TRUE(a.Cells == b.Cells);
    // Version 1 stored every depth; they are those the plane gives, or the stored ones.
    std::vector<Crossing> ca, cb;
    const int lines = a.TileStart.empty() ? 0 : 16;
    for (int j = 0; j < lines; ++j)
    {
      for (int i = 0; i < lines; ++i)
      {
        field->LineCrossings(k, i, j, ca);
        loaded->LineCrossings(k, i, j, cb);
        ASSERT_EQ(ca.size(), cb.size());
        for (std::size_t q = 0; q < ca.size(); ++q)
        {
          EXPECT_EQ(ca[q].Surface, cb[q].Surface);
          EXPECT_EQ(ca[q].Cell, cb[q].Cell);
          EXPECT_NEAR(ca[q].Depth, cb[q].Depth, 1e-6f);
        }
      }
    }
    ASSERT_EQ(a.Radiance.size(), b.Radiance.size());
    for (std::size_t q = 0; q < a.Radiance.size(); ++q)
    {
      const glm::vec3 x = a.Radiance[q], y = b.Radiance[q];
      const float bound = 1.002f * std::ldexp(std::max({ x.x, x.y, x.z }), -9) + 1e-9f;
      ASSERT_LE(glm::length(x - y), std::sqrt(3.0f) * bound) << k << " " << q;
    }
    crossings += a.Radiance.size();
  }
  EXPECT_GT(crossings, 1000u);
  std::remove(path.c_str());
}

TEST(VLFSnapshot, ForeignTruncatedAndCorruptFilesGiveClearErrors)
{
  const std::string path = TempPath("damaged.vlf");
  WriteSnapshot(*SmallCornell(1), path);
  const std::vector<char> good = ReadBytes(path);
  ASSERT_GT(good.size(), 1000u);

  EXPECT_NE(ReadError(TempPath("does-not-exist.vlf")).find("cannot open"), std::string::npos);

  WriteBytes(path, std::vector<char>{ 'h', 'e', 'l', 'l', 'o' });
  EXPECT_NE(ReadError(path).find("not a Mesolight light field snapshot"), std::string::npos);
  EXPECT_FALSE(IsSnapshotFile(path));

  // Cut at several places: the header, the settings, the middle, the last byte.
  for (const std::size_t length :
    { std::size_t(20), std::size_t(60), good.size() / 2, good.size() - 1 })
  {
    WriteBytes(
      path, std::vector<char>(good.begin(), good.begin() + static_cast<std::ptrdiff_t>(length)));
    EXPECT_NE(ReadError(path).find("truncated"), std::string::npos)
      << "cut at " << length << ": " << ReadError(path);
  }

  // Flip one byte at several places: header, counts, data.
  for (const std::size_t at : { std::size_t(10), std::size_t(30), std::size_t(60), std::size_t(100),
         good.size() / 3, good.size() - 5 })
  {
    std::vector<char> bad = good;
    bad[at] = static_cast<char>(bad[at] ^ 0x5a);
    WriteBytes(path, bad);
    const std::string message = ReadError(path);
    EXPECT_TRUE(message.find("corrupt") != std::string::npos ||
      message.find("version") != std::string::npos ||
      message.find("byte order") != std::string::npos ||
      message.find("truncated") != std::string::npos)
      << "flipped byte " << at << ": '" << message << "'";
  }

  // Extra bytes at the end.
  std::vector<char> longer = good;
  longer.push_back('x');
  WriteBytes(path, longer);
  EXPECT_NE(ReadError(path).find("corrupt"), std::string::npos);
}

TEST(VLFSnapshot, AFailedWriteLeavesThePreviousFile)
{
  const std::string path = TempPath("kept.vlf");
  WriteSnapshot(*SmallCornell(1), path);
  const std::vector<char> before = ReadBytes(path);
  // A directory cannot be renamed over by a file: the write fails, the old file stays intact.
  EXPECT_THROW(WriteSnapshot(*SmallCornell(1), TempPath("no-such-dir/field.vlf")), SnapshotError);
  EXPECT_EQ(ReadBytes(path), before);
}

} // namespace

// A write killed before its rename leaves FIELD.tmp-PID behind; the next write of FIELD removes
// such leftovers of processes that are gone, and nothing else.
TEST(VLFSnapshot, StaleTemporariesOfDeadWritersAreRemoved)
{
  const std::string path = TempPath("stale.vlf");
  WriteSnapshot(*SmallCornell(1), path);
  const std::vector<char> snapshot = ReadBytes(path);
  // PIDs above Linux's largest pid_max (2^22) name no process.
  const std::string stale = path + ".tmp-999999999";
  const std::string staleEmpty = path + ".tmp-999999998";
  const std::string foreign = path + ".tmp-999999997";           // not a snapshot: kept
  const std::string other = TempPath("other.vlf.tmp-999999996"); // another field's: kept
  const std::string alive = path + ".tmp-1";                     // init is running: kept
  WriteBytes(stale, std::vector<char>(snapshot.begin(), snapshot.begin() + snapshot.size() / 2));
  WriteBytes(staleEmpty, {});
  WriteBytes(foreign, { 'h', 'e', 'l', 'l', 'o', ' ', 'w', 'o', 'r', 'l', 'd' });
  WriteBytes(other, snapshot);
  WriteBytes(alive, snapshot);
  WriteSnapshot(*SmallCornell(1), path);
  auto exists = [](const std::string& file) { return std::ifstream(file).good(); };
  EXPECT_FALSE(exists(stale));
  EXPECT_FALSE(exists(staleEmpty));
  EXPECT_TRUE(exists(foreign));
  EXPECT_TRUE(exists(other));
  EXPECT_TRUE(exists(alive));
  for (const std::string& file : { foreign, other, alive })
  {
    std::remove(file.c_str());
  }
}

// A field of NaNs with a valid checksum is refused on reading, not rendered blank or resumed
// (float radiance: a snapshot taken while propagating).
TEST(VLFSnapshot, NonFiniteValuesAreRefused)
{
  const std::string path = TempPath("nan.vlf");
  std::unique_ptr<LightField> field = SmallCornell(0, true);
  PropagateIteration(*field);
  ASSERT_FALSE(field->GetSubfield(MirrorSubfield(*field)).Radiance.empty());
  field->GetSubfield(MirrorSubfield(*field)).Radiance.Floats()[0].y =
    std::numeric_limits<float>::quiet_NaN();
  WriteSnapshot(*field, path);
  EXPECT_NE(ReadError(path).find("NaN or infinite"), std::string::npos) << ReadError(path);
  field = SmallCornell(1);
  field->TotalDiffuse[0].x = std::numeric_limits<float>::infinity();
  WriteSnapshot(*field, path);
  EXPECT_NE(ReadError(path).find("NaN or infinite"), std::string::npos) << ReadError(path);
  // The same in a version 1 file.
  field = SmallCornell(1, true);
  field->GetSubfield(MirrorSubfield(*field)).Radiance[0] =
    glm::vec3(std::numeric_limits<float>::quiet_NaN());
  WriteSnapshotVersion(*field, path, DenseSnapshotVersion);
  EXPECT_NE(ReadError(path).find("NaN or infinite radiance"), std::string::npos) << ReadError(path);
  WriteSnapshot(*SmallCornell(1), path);
  EXPECT_EQ(ReadError(path), "");
  std::remove(path.c_str());
}

// Radiance is never negative: a field holding some (checksums valid) rendered black with exit 0.
TEST(VLFSnapshot, NegativeRadianceIsRefused)
{
  const std::string path = TempPath("negative.vlf");
  std::unique_ptr<LightField> field = SmallCornell(1);
  field->TotalDiffuse[0].y = -0.5f;
  WriteSnapshot(*field, path);
  EXPECT_NE(ReadError(path).find("holds negative radiance"), std::string::npos) << ReadError(path);
  field = SmallCornell(0, true);
  PropagateIteration(*field);
  ASSERT_FALSE(field->GetSubfield(MirrorSubfield(*field)).Radiance.empty());
  field->GetSubfield(MirrorSubfield(*field)).Radiance.Floats()[0].z = -1.0f;
  WriteSnapshot(*field, path);
  EXPECT_NE(ReadError(path).find("holds negative radiance"), std::string::npos) << ReadError(path);
  std::remove(path.c_str());
}

// kill -9 during a snapshot write (what a user's Ctrl-C or an OOM killer does to `mesolight vlf
// propagate`): the file on disk stays the previous complete snapshot, resuming from it gives the
// field of an uninterrupted run bit for bit, and the next write removes the dead writer's
// temporary file. The writer is a forked child running the propagation loop of the command
// (Propagate with a snapshot after every iteration); the parent kills it the moment its
// temporary file appears.
TEST(VLFSnapshot, KilledDuringAWriteResumesToTheSameField)
{
  const std::string path = TempPath("killed.vlf");
  std::remove(path.c_str());
  LightFieldSettings settings;
  settings.Directions = 513; // a snapshot of several MB: its write takes a while
  settings.RaysPerSide = 32;
  settings.TilesPerSide = 4;
  const int iterations = 40;
  const pid_t child = ::fork(); // before this process starts any thread pool
  ASSERT_GE(child, 0);
  if (child == 0)
  {
    try
    {
      std::unique_ptr<LightField> field = LightField::Build(MakeCornellBox(), settings);
      Propagate(*field, iterations, {}, [&](const LightField& f) { WriteSnapshot(f, path); });
    }
    catch (...)
    {
    }
    std::_Exit(0);
  }
  const std::string temporary = path + ".tmp-" + std::to_string(static_cast<long>(child));
  auto exists = [](const std::string& file)
  {
    struct stat info;
    return ::stat(file.c_str(), &info) == 0;
  };
  // Wait for a write after the first complete snapshot, then kill in the middle of it.
  bool killedWriting = false;
  const auto deadline = std::chrono::steady_clock::now() + std::chrono::minutes(5);
  while (std::chrono::steady_clock::now() < deadline)
  {
    if (exists(path) && exists(temporary))
    {
      ::kill(child, SIGKILL);
      killedWriting = exists(temporary);
      break;
    }
    int status = 0;
    if (::waitpid(child, &status, WNOHANG) == child)
    {
      break; // finished without being caught writing (should not happen: 40 writes)
    }
  }
  ::kill(child, SIGKILL);
  ::waitpid(child, nullptr, 0);
  ASSERT_TRUE(killedWriting) << "the writer was never caught during a snapshot write";
  EXPECT_TRUE(exists(temporary));

  // What is on disk is a complete snapshot of some iteration; resume it one iteration further.
  std::unique_ptr<LightField> resumed;
  ASSERT_NO_THROW(resumed = ReadSnapshot(path));
  const int done = resumed->IterationsDone;
  ASSERT_GE(done, 1);
  ASSERT_LT(done, iterations);
  std::printf("[ figures  ] killed during the write of iteration %d's snapshot (%d done on disk)\n",
    done + 1, done);
  Propagate(*resumed, done + 1);
  WriteSnapshot(*resumed, path);
  EXPECT_FALSE(exists(temporary)) << "the killed writer's temporary file was left behind";

  std::unique_ptr<LightField> straight = LightField::Build(MakeCornellBox(), settings);
  Propagate(*straight, done + 1);
  ExpectSameField(*straight, *ReadSnapshot(path));
}
