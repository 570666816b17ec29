// SPDX-License-Identifier: BSD-3-Clause
// mesolight::ParallelFor for the cores-only build (MESOLIGHT_CORES_ONLY=ON, tests/cores), which
// has no VTK and so no vtkSMPTools: std::thread over fixed blocks, so that the sanitizers still
// see the cores run concurrently as they do in the tool. Same contract as common/ParallelFor.cxx:
// the first exception of a body is rethrown on the calling thread.
#include "ParallelFor.h"

#include <algorithm>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mesolight
{

void ParallelFor(std::size_t begin, std::size_t end, std::size_t grain,
  const std::function<void(std::size_t, std::size_t)>& body, int threads)
{
  if (end <= begin)
  {
    return;
  }
  const std::size_t count = end - begin;
  const std::size_t workers =
    std::min<std::size_t>(std::max(2u, std::thread::hardware_concurrency()), count);
  if (threads == 1 || workers < 2)
  {
    body(begin, end);
    return;
  }
  // Blocks of at least `grain` items, a few per worker.
  const std::size_t block = std::max<std::size_t>(
    std::max<std::size_t>(grain, 1), (count + 4 * workers - 1) / (4 * workers));
  std::exception_ptr failure;
  std::mutex mutex;
  std::size_t next = begin;
  auto work = [&]()
  {
    for (;;)
    {
      std::size_t b = 0;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next >= end)
        {
          return;
        }
        b = next;
        next = std::min(end, next + block);
      }
      try
      {
        body(b, std::min(end, b + block));
      }
      catch (...)
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (!failure)
        {
          failure = std::current_exception();
        }
      }
    }
  };
  std::vector<std::thread> pool;
  for (std::size_t w = 1; w < workers; ++w)
  {
    pool.emplace_back(work);
  }
  work();
  for (std::thread& t : pool)
  {
    t.join();
  }
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}

} // namespace mesolight
