// ParallelTiles: runs a function over the square tiles of an image on a pool of std::threads
// (tiles handed out through an atomic counter), with progress reports and abort. Shared by the
// path tracer and the ray tracer.
#ifndef mesolight_ParallelTiles_h
#define mesolight_ParallelTiles_h

#include <functional>

namespace mesolight
{

// Called with the fraction done in [0, 1]; return false to abort. Called from one thread at a
// time (never concurrently), but not necessarily the caller's thread.
using ProgressCallback = std::function<bool(double fraction)>;

struct TileRange
{
  int X0, Y0, X1, Y1; // pixels [X0, X1) x [Y0, Y1)
};

// Runs work(tile) for every tile of a width x height image; threads <= 0 means all hardware
// threads. Returns false when progress asked to stop (tiles already started finish).
bool ForEachTile(int width, int height, int tileSize, int threads,
  const std::function<void(const TileRange&)>& work, const ProgressCallback& progress = {});

// Number of threads ForEachTile uses for a request (threads <= 0: hardware concurrency).
int ResolveThreadCount(int threads);

} // namespace mesolight

#endif
