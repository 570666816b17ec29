#include "ParallelTiles.h"

#include <algorithm>
#include <atomic>
#include <mutex>
#include <thread>
#include <vector>

namespace mesolight
{

int ResolveThreadCount(int threads)
{
  if (threads > 0)
  {
    return threads;
  }
  return std::max(1, static_cast<int>(std::thread::hardware_concurrency()));
}

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
  std::atomic<int> next{ 0 };
  std::atomic<int> done{ 0 };
  std::atomic<bool> aborted{ false };
  std::mutex progressMutex;
  auto worker = [&]() {
    for (;;)
    {
      if (aborted.load())
      {
        return;
      }
      const int tile = next.fetch_add(1);
      if (tile >= tileCount)
      {
        return;
      }
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
  };
  const int count = std::min(ResolveThreadCount(threads), tileCount);
  std::vector<std::thread> pool;
  for (int t = 1; t < count; ++t)
  {
    pool.emplace_back(worker);
  }
  worker();
  for (std::thread& thread : pool)
  {
    thread.join();
  }
  return !aborted.load();
}

} // namespace mesolight
