// SPDX-License-Identifier: BSD-3-Clause
// The sample counts the relief benchmarks read from vtkReliefMapper's SampleCountOutput: the
// mean a texture unit fetches and the lock-step count a SIMD group's loop runs for.
#include "ImageCompare.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{
// A frame whose pixel (x, y) holds counts[y][x] samples (16 bits in R, G); -1 is background.
mesolight::Frame CountFrame(const std::vector<std::vector<int>>& counts)
{
  mesolight::Frame frame;
  frame.Height = static_cast<int>(counts.size());
  frame.Width = static_cast<int>(counts[0].size());
  frame.Rgb.assign(3 * frame.Width * frame.Height, 0);
  frame.Depth.assign(frame.Width * frame.Height, 1.0f);
  for (int y = 0; y < frame.Height; ++y)
  {
    for (int x = 0; x < frame.Width; ++x)
    {
      const size_t p = static_cast<size_t>(y) * frame.Width + x;
      const int c = counts[y][x];
      if (c >= 0)
      {
        frame.Depth[p] = 0.5f;
        frame.Rgb[3 * p] = static_cast<unsigned char>(c / 256);
        frame.Rgb[3 * p + 1] = static_cast<unsigned char>(c % 256);
      }
    }
  }
  return frame;
}
}

TEST(SampleCounts, LockStepChargesEveryCoveredPixelItsGroupsLargestCount)
{
  // Two 2 x 2 groups side by side, and a partial third (the frame is 5 wide); background pixels
  // (-1) are neither charged nor counted.
  const mesolight::Frame frame = CountFrame({
    { 1, 1, 4, 4, 7 },
    { 1, 300, 4, -1, -1 },
  });
  EXPECT_DOUBLE_EQ(mesolight::MeanSampleCount(frame), (1 + 1 + 1 + 300 + 4 + 4 + 4 + 7) / 8.0);
  EXPECT_DOUBLE_EQ(
    mesolight::MeanLockStepSampleCount(frame, 2, 2), (4 * 300 + 3 * 4 + 1 * 7) / 8.0);
  // One-pixel groups are the mean: nothing runs in lock step.
  EXPECT_DOUBLE_EQ(
    mesolight::MeanLockStepSampleCount(frame, 1, 1), mesolight::MeanSampleCount(frame));
  // A group covering the frame charges every pixel the largest count.
  EXPECT_DOUBLE_EQ(mesolight::MeanLockStepSampleCount(frame, 8, 4), 300.0);
}

TEST(SampleCounts, LockStepOfNothingIsZero)
{
  EXPECT_EQ(mesolight::MeanLockStepSampleCount(CountFrame({ { -1, -1 } }), 8, 4), 0.0);
  EXPECT_EQ(mesolight::MeanLockStepSampleCount(CountFrame({ { 3, 3 } }), 0, 4), 0.0);
  EXPECT_EQ(mesolight::MeanLockStepSampleCount(mesolight::Frame(), 8, 4), 0.0);
}

TEST(SampleCounts, LockStepOfCountsGivenDirectlyMatchesTheFrames)
{
  // The same two rows as above (row 0 first), as plain counts.
  const std::vector<int> counts{ 1, 1, 4, 4, 7, 1, 300, 4, -1, -1 };
  const mesolight::Frame frame = CountFrame({
    { 1, 1, 4, 4, 7 },
    { 1, 300, 4, -1, -1 },
  });
  EXPECT_DOUBLE_EQ(mesolight::MeanLockStepCount(counts, 5, 2, 2, 2),
    mesolight::MeanLockStepSampleCount(frame, 2, 2));
  // Hand-computed, independently of either: groups of 2 x 2 charge 300, 4 and 7.
  EXPECT_DOUBLE_EQ(mesolight::MeanLockStepCount(counts, 5, 2, 2, 2), (4 * 300 + 3 * 4 + 7) / 8.0);
  EXPECT_DOUBLE_EQ(mesolight::MeanCount(counts), (1 + 1 + 4 + 4 + 7 + 1 + 300 + 4) / 8.0);
  EXPECT_EQ(mesolight::MeanCount({ -1, -3 }), 0.0);
  EXPECT_EQ(mesolight::MeanLockStepCount(counts, 4, 2, 2, 2), 0.0); // size mismatch
}
