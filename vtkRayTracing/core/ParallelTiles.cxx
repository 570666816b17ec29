// SPDX-License-Identifier: BSD-3-Clause
#include "ParallelTiles.h"

#include "ParallelFor.h"

#include <algorithm>
#include <atomic>
#include <cstddef>
#include <mutex>

namespace mesolight
{

bool ForEachTile(int width, int height, int tileSize, int threads,
  const std::function<void(const TileRange&)>& work, const ProgressCallback& progress)
{
  if (width <= 0 || height <= 0)
  {
    return true;
  }
  tileSize = std::max(1, tileSize);
  const int tilesX = (width + tileSize - 1) / tileSize;
  const int tilesY = (height + tileSize - 1) / tileSize;
  const int tileCount = tilesX * tilesY;
  std::atomic<int> done{ 0 };
  std::atomic<bool> aborted{ false };
  std::mutex progressMutex;
  // One tile per item: a tile's pixels do not depend on which thread traces them.
  ParallelFor(
    0, static_cast<std::size_t>(tileCount), 1,
    [&](std::size_t first, std::size_t last)
    {
      for (std::size_t index = first; index < last; ++index)
      {
        if (aborted.load())
        {
          return;
        }
        const int tile = static_cast<int>(index);
        const int tx = tile % tilesX;
        const int ty = tile / tilesX;
        const TileRange range{ tx * tileSize, ty * tileSize, std::min(width, (tx + 1) * tileSize),
          std::min(height, (ty + 1) * tileSize) };
        work(range);
        const int finished = done.fetch_add(1) + 1;
        if (progress)
        {
          std::lock_guard<std::mutex> lock(progressMutex);
          if (!aborted.load() && !progress(static_cast<double>(finished) / tileCount))
          {
            aborted.store(true);
          }
        }
      }
    },
    threads);
  return !aborted.load();
}

} // namespace mesolight
