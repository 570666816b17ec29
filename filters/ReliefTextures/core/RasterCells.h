// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file RasterCells.h
 * @brief A raster given as the cells of a grid one point larger, read at the points (plain C++17,
 * no VTK types).
 *
 * ParaView's GDAL Raster Reader gives a raster's pixels as cells and hides the cells without data.
 * A relief texture's texels are points, so each point takes the mean of the cells around it that
 * have data: what VTK's Cell Data to Point Data computes, without the cells that have none.
 */
#ifndef mesolight_RasterCells_h
#define mesolight_RasterCells_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

#include <vector>

namespace mesolight
{

/**
 * Cell values (cw x ch, row-major, row 0 first) to the (cw + 1) x (ch + 1) points at their corners:
 * each point the mean of the cells around it (up to four) with data; a point with no such cell has
 * no data (its value 0).
 *
 * @param cellValue  cw * ch values.
 * @param cellNoData cw * ch flags (non-zero: no data), or empty: every cell has data.
 * @param value      out: (cw + 1) * (ch + 1) point values.
 * @param noData     out: (cw + 1) * (ch + 1) flags, 1 where no cell around the point has data.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT void CellsToCorners(const std::vector<double>& cellValue,
  const std::vector<char>& cellNoData, int cw, int ch, std::vector<double>& value,
  std::vector<char>& noData);

} // namespace mesolight

#endif
