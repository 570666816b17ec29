// SPDX-License-Identifier: BSD-3-Clause
// The light field's map storage (RadianceStorage.h): shared-exponent radiance within its
// analytic bound (every channel within 2^-9 of the largest, round to nearest), the cell index's
// slots against a brute-force count, the float/compact array's behaviour, and the identity
// LightField::SentRadiance relies on without mirrors (what a diffuse crossing has sent is its
// total diffuse texture less the unshot part).
#include "Propagation.h"
#include "RadianceStorage.h"

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <random>

namespace
{
using namespace mesolight::vlf;

// |decoded - value| per channel over the largest channel (the format's error measure).
double WorstError(const glm::vec3& value, const glm::vec3& decoded)
{
  const float largest = std::max({ value.x, value.y, value.z });
  double worst = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    worst = std::max(worst, std::abs(static_cast<double>(decoded[c]) - value[c]) / largest);
  }
  return worst;
}

TEST(VLFRadianceStorage, Rgb9e5IsWithinItsBound)
{
  std::mt19937 rng(7);
  std::uniform_real_distribution<float> unit(0.0f, 1.0f);
  std::uniform_real_distribution<float> exponent(-14.0f, 15.0f);
  double worst = 0.0;
  for (int i = 0; i < 200000; ++i)
  {
    const float scale = std::exp2(exponent(rng));
    const glm::vec3 v(unit(rng) * scale, unit(rng) * scale, unit(rng) * scale);
    if (std::max({ v.x, v.y, v.z }) < std::ldexp(1.0f, -14))
    {
      continue;
    }
    worst = std::max(worst, WorstError(v, DecodeRgb9e5(EncodeRgb9e5(v))));
  }
  // 2^-9 (half a step of a 9-bit mantissa in [256, 512), times 512 / 511.5 when rounding
  // carries into the exponent).
  EXPECT_LE(worst, std::ldexp(1.0, -9) * 512.0 / 511.5);
  // The bound is tight: half of it fails (a test that can fail), and a 8-bit mantissa's would.
  EXPECT_GT(worst, std::ldexp(1.0, -10));
  // Exact values: small integers, powers of two, zero; negatives, NaN clamp to 0, huge to max.
  EXPECT_EQ(DecodeRgb9e5(EncodeRgb9e5(glm::vec3(1.0f, 0.5f, 0.25f))), glm::vec3(1.0f, 0.5f, 0.25f));
  EXPECT_EQ(
    DecodeRgb9e5(EncodeRgb9e5(glm::vec3(17.0f, 12.0f, 4.0f))), glm::vec3(17.0f, 12.0f, 4.0f));
  EXPECT_EQ(EncodeRgb9e5(glm::vec3(0.0f)), 0u);
  EXPECT_EQ(DecodeRgb9e5(EncodeRgb9e5(glm::vec3(-1.0f, NAN, 2.0f))), glm::vec3(0.0f, 0.0f, 2.0f));
  EXPECT_EQ(DecodeRgb9e5(EncodeRgb9e5(glm::vec3(1e9f))), glm::vec3(MaxRgb9e5));
}

TEST(VLFRadianceStorage, ArraysScaleToAnyRangeAndTurnFloatOnWrite)
{
  for (const float scale : { 1e-25f, 1e-6f, 1.0f, 3e4f, 1e6f, 1e20f })
  {
    RadianceArray a;
    a.assign(4, glm::vec3(0.0f));
    a[0] = glm::vec3(1.0f, 0.3f, 0.02f) * scale;
    a[1] = glm::vec3(0.5f) * scale;
    a[3] = glm::vec3(1e-6f, 2e-6f, 0.0f) * scale; // far below the largest: may become 0
    const std::vector<glm::vec3> before = a.ToVector();
    a.MakeCompact();
    ASSERT_TRUE(a.IsCompact());
    EXPECT_EQ(a.Bytes(), 4 * sizeof(std::uint32_t));
    for (std::size_t i = 0; i < 3; ++i)
    {
      const float largest = std::max({ before[i].x, before[i].y, before[i].z });
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_LE(std::abs(a[i][c] - before[i][c]), std::ldexp(largest, -9) * 1.001f)
          << scale << " " << i;
      }
    }
    EXPECT_EQ(static_cast<const RadianceArray&>(a)[2], glm::vec3(0.0f));
    // Writing turns it to float, from the compact values.
    const glm::vec3 kept = static_cast<const RadianceArray&>(a)[1];
    a[0] += glm::vec3(scale);
    EXPECT_FALSE(a.IsCompact());
    EXPECT_EQ(static_cast<const RadianceArray&>(a)[1], kept);
    // Pack / unpack keeps the form and the values.
    std::string message;
    a.MakeCompact();
    a.Pack(message);
    RadianceArray b;
    std::size_t at = 0;
    b.Unpack(message, at);
    EXPECT_EQ(at, message.size());
    EXPECT_TRUE(b.IsCompact());
    EXPECT_TRUE(a == b);
  }
}

TEST(VLFRadianceStorage, CellIndexSlotsMatchABruteForceCount)
{
  std::mt19937 rng(3);
  for (const std::size_t cellsPerMap :
    { std::size_t(16), std::size_t(64), std::size_t(100), std::size_t(256) })
  {
    const std::size_t maps = 37;
    std::vector<std::size_t> occupied;
    std::vector<std::int64_t> expected(maps * cellsPerMap, -1);
    for (std::size_t c = 0; c < maps * cellsPerMap; ++c)
    {
      if (rng() % 5 == 0)
      {
        expected[c] = static_cast<std::int64_t>(occupied.size());
        occupied.push_back(c);
      }
    }
    CellIndex index;
    index.Build(maps, cellsPerMap, occupied);
    EXPECT_EQ(index.Slots(), occupied.size());
    for (std::size_t c = 0; c < maps * cellsPerMap; ++c)
    {
      ASSERT_EQ(index.Slot(c / cellsPerMap, c % cellsPerMap), expected[c])
        << cellsPerMap << " " << c;
    }
    CellIndex copy;
    EXPECT_TRUE(copy.Assign(maps, cellsPerMap, index.Words()));
    EXPECT_TRUE(copy == index);
    EXPECT_FALSE(copy.Assign(maps + 1, cellsPerMap, index.Words())); // wrong count
    if (cellsPerMap % 64 != 0)
    {
      std::vector<std::uint64_t> words = index.Words();
      words.back() |= std::uint64_t(1) << 63; // a bit beyond the map's last cell
      EXPECT_FALSE(copy.Assign(maps, cellsPerMap, words));
    }
  }
}

// What a diffuse crossing has sent along its line is the sum over the iterations of its
// unshot diffuse texture there (Propagation.h), summed here independently, iteration by
// iteration; SentRadiance, which stores nothing, gives it from the textures' total less unshot.
// The total alone (negative case) is not it.
TEST(VLFRadianceStorage, DiffuseSentRadianceIsWhatTheIterationsShot)
{
  LightFieldSettings settings;
  settings.Directions = 33;
  settings.RaysPerSide = 16;
  settings.TilesPerSide = 4;
  std::unique_ptr<LightField> field = LightField::Build(mesolight::MakeCornellBox(), settings);
  struct Line
  {
    std::size_t K;
    int I, J;
    Crossing C;
    glm::vec3 Point;
    bool Blocked;
    glm::vec3 Shot{ 0.0f };
  };
  std::vector<Line> lines;
  std::vector<Crossing> line;
  for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
  {
    for (int j = 0; j < settings.RaysPerSide; ++j)
    {
      for (int i = 0; i < settings.RaysPerSide; ++i)
      {
        field->LineCrossings(k, i, j, line);
        for (std::size_t q = 0; q < line.size(); ++q)
        {
          lines.push_back({ k, i, j, line[q], field->PointOnLine(k, i, j, line[q].Depth),
            field->Receiver(k, line, q) == LightField::LineBlocked });
        }
      }
    }
  }
  for (int it = 0; it < 3; ++it)
  {
    for (Line& l : lines)
    {
      if (!l.Blocked) // runs into a solid: shoots nothing (Propagation.h)
      {
        l.Shot += field->SampleTexture(field->UnshotDiffuse, l.C.Surface, l.Point);
      }
    }
    PropagateIteration(*field);
  }
  double worst = 0.0, worstTotal = 0.0;
  std::size_t compared = 0, blocked = 0;
  for (const Line& l : lines)
  {
    if (l.Blocked)
    {
      EXPECT_EQ(field->SentRadiance(l.K, l.I, l.J, l.C.Surface, l.C.Cell), glm::vec3(0.0f));
      ++blocked;
      continue;
    }
    const double size = static_cast<double>(l.Shot.x) + l.Shot.y + l.Shot.z;
    if (!(size > 1e-3))
    {
      continue;
    }
    const glm::vec3 sent = field->SentRadiance(l.K, l.I, l.J, l.C.Surface, l.C.Cell);
    const glm::vec3 total = field->SampleTexture(field->TotalDiffuse, l.C.Surface, l.Point);
    const glm::vec3 d = glm::abs(sent - l.Shot), dt = glm::abs(total - l.Shot);
    worst = std::max(worst, (static_cast<double>(d.x) + d.y + d.z) / size);
    worstTotal = std::max(worstTotal, (static_cast<double>(dt.x) + dt.y + dt.z) / size);
    ++compared;
  }
  std::printf(
    "[ sent     ] %zu diffuse crossings: worst %.2e (the total alone %.2e); %zu blocked\n",
    compared, worst, worstTotal, blocked);
  EXPECT_GT(blocked, 10u);                              // the floor under the blocks
  EXPECT_EQ(field->GetSubfield(0).Radiance.size(), 0u); // nothing stored without mirrors
  EXPECT_GT(compared, 1000u);
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(worstTotal, 1e-2);
}

} // namespace
