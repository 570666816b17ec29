// SPDX-License-Identifier: BSD-3-Clause
// Which way an image's rows run. VTK's images have the picture's bottom row first (row 0 at the
// smallest y): VTK's image readers and vtkOIIOImageReader turn a file's rows around. ParaView's
// GDAL Raster Reader (vtkGDALRasterReader) orders them by the raster's georeferenced y instead: a
// georeferenced raster (north up, by a GeoTIFF's tags or a world file) comes bottom row first as
// well, at its ground origin and pixel size, but an image without georeferencing comes in the
// file's order, the top row first (its y is the row number). That case is what the reader gives
// a plain image and nothing else: no map projection (MAP_PROJECTION empty), origin (0, 0) and
// pixels of 1 (a world file's raster has no projection either, but its ground origin and size).
#ifndef vtkRasterRowOrder_h
#define vtkRasterRowOrder_h

#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkStringArray.h"

#include <algorithm>
#include <cstddef>
#include <vector>

namespace mesolight
{
/** True when `image`'s rows run from the picture's top down (GDAL Raster Reader's plain images). */
inline bool RowsTopFirst(vtkImageData* image)
{
  vtkFieldData* fields = image ? image->GetFieldData() : nullptr;
  vtkStringArray* projection =
    fields ? vtkStringArray::SafeDownCast(fields->GetAbstractArray("MAP_PROJECTION")) : nullptr;
  if (!projection || projection->GetNumberOfValues() != 1 || !projection->GetValue(0).empty())
  {
    return false;
  }
  const double* origin = image->GetOrigin();
  const double* spacing = image->GetSpacing();
  return origin[0] == 0.0 && origin[1] == 0.0 && spacing[0] == 1.0 && spacing[1] == 1.0;
}

/** Reverses the order of the `rows` rows of `values` (rows of `rowLength` values each). */
template <class T>
void ReverseRows(std::vector<T>& values, std::size_t rows, std::size_t rowLength)
{
  for (std::size_t j = 0; j < rows / 2; ++j)
  {
    std::swap_ranges(values.begin() + static_cast<std::ptrdiff_t>(j * rowLength),
      values.begin() + static_cast<std::ptrdiff_t>((j + 1) * rowLength),
      values.begin() + static_cast<std::ptrdiff_t>((rows - 1 - j) * rowLength));
  }
}
} // namespace mesolight

#endif
