// SPDX-License-Identifier: BSD-3-Clause
#include "RasterCells.h"

#include <algorithm>
#include <cstddef>

namespace mesolight
{

void CellsToCorners(const std::vector<double>& cellValue, const std::vector<char>& cellNoData,
  int cw, int ch, std::vector<double>& value, std::vector<char>& noData)
{
  const int w = cw + 1;
  const int h = ch + 1;
  value.assign(static_cast<size_t>(w) * h, 0.0);
  noData.assign(static_cast<size_t>(w) * h, 0);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      double sum = 0.0;
      int count = 0;
      for (int cj = std::max(0, j - 1); cj <= std::min(ch - 1, j); ++cj)
      {
        for (int ci = std::max(0, i - 1); ci <= std::min(cw - 1, i); ++ci)
        {
          const size_t c = static_cast<size_t>(cj) * cw + ci;
          if (cellNoData.empty() || !cellNoData[c])
          {
            sum += cellValue[c];
            ++count;
          }
        }
      }
      const size_t k = static_cast<size_t>(j) * w + i;
      value[k] = count > 0 ? sum / count : 0.0;
      noData[k] = count == 0;
    }
  }
}

} // namespace mesolight
