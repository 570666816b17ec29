// SPDX-License-Identifier: BSD-3-Clause
// A raster given as cells (ParaView's GDAL Raster Reader) read at the points (core/RasterCells.h):
// each point the mean of the cells around it with data, worked out by hand.
#include "RasterCells.h"

#include <gtest/gtest.h>

#include <vector>

namespace
{
// 3 x 2 cells, row 0 first:   row 1:  40 50 60
//                             row 0:  10 20 30
const std::vector<double> Cells = { 10, 20, 30, 40, 50, 60 };
}

TEST(RasterCells, EveryPointIsTheMeanOfTheCellsAroundIt)
{
  std::vector<double> value;
  std::vector<char> noData;
  mesolight::CellsToCorners(Cells, {}, 3, 2, value, noData);
  // 4 x 3 points: corners take one cell, edges two, the inside four.
  const std::vector<double> expected = { 10, 15, 25, 30, 25, 30, 40, 45, 40, 45, 55, 60 };
  ASSERT_EQ(value.size(), expected.size());
  ASSERT_EQ(noData.size(), expected.size());
  for (size_t k = 0; k < expected.size(); ++k)
  {
    EXPECT_DOUBLE_EQ(value[k], expected[k]) << "point " << k;
    EXPECT_EQ(noData[k], 0) << "point " << k;
  }
}

TEST(RasterCells, CellsWithoutDataAreLeftOut)
{
  // The top right cell (60) has no data: the points around it average the others only, and the
  // top right point, which only that cell touches, has no data.
  std::vector<char> cellNoData(6, 0);
  cellNoData[5] = 1;
  std::vector<double> value;
  std::vector<char> noData;
  mesolight::CellsToCorners(Cells, cellNoData, 3, 2, value, noData);
  const std::vector<double> expected = { 10, 15, 25, 30, 25, 30, 100.0 / 3.0, 30, 40, 45, 50, 0 };
  for (size_t k = 0; k < expected.size(); ++k)
  {
    EXPECT_DOUBLE_EQ(value[k], expected[k]) << "point " << k;
    EXPECT_EQ(noData[k], k == 11 ? 1 : 0) << "point " << k;
  }
  // Every cell without data: every point without data.
  mesolight::CellsToCorners(Cells, std::vector<char>(6, 1), 3, 2, value, noData);
  for (size_t k = 0; k < noData.size(); ++k)
  {
    EXPECT_EQ(noData[k], 1) << "point " << k;
  }
}

TEST(RasterCells, OneCellGivesItsFourCorners)
{
  std::vector<double> value;
  std::vector<char> noData;
  mesolight::CellsToCorners({ 7.5 }, {}, 1, 1, value, noData);
  EXPECT_EQ(value, std::vector<double>(4, 7.5));
  EXPECT_EQ(noData, std::vector<char>(4, 0));
}
