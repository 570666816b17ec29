// SPDX-License-Identifier: BSD-3-Clause
// ParallelTiles: runs a function over the square tiles of an image on mesolight::ParallelFor,
// with progress reports and abort. Shared by the path tracer and the ray tracer.
#ifndef mesolight_ParallelTiles_h
#define mesolight_ParallelTiles_h

#include "Progress.h" // ProgressCallback

#include <functional>

namespace mesolight
{

struct TileRange
{
  int X0, Y0, X1, Y1; // pixels [X0, X1) x [Y0, Y1)
};

// Runs work(tile) for every tile of a width x height image. threads == 1 works on the calling
// thread only; any other value uses all of vtkSMPTools' threads (ParallelFor.h). progress is
// called with the fraction of tiles done, from one thread at a time (never concurrently) but
// not necessarily the caller's. Returns false when progress asked to stop (tiles already
// started finish, later ones are skipped).
bool ForEachTile(int width, int height, int tileSize, int threads,
  const std::function<void(const TileRange&)>& work, const ProgressCallback& progress = {});

} // namespace mesolight

#endif
