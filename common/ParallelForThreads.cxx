// SPDX-License-Identifier: BSD-3-Clause
#include "ParallelForThreads.h"

#include <algorithm>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <thread>
#include <vector>

namespace mesolight
{
namespace
{
// Set on the threads running a body, so that a parallel-for inside it runs inline instead of
// starting workers² threads.
thread_local bool InsideBody = false;

int PositiveEnvironment(const char* name)
{
  const char* value = std::getenv(name);
  const int n = value ? std::atoi(value) : 0;
  return n > 0 ? n : 0;
}
} // namespace

void ParallelForOnThreads(std::size_t begin, std::size_t end, std::size_t grain,
  const std::function<void(std::size_t, std::size_t)>& body, int workers)
{
  if (end <= begin)
  {
    return;
  }
  const std::size_t count = end - begin;
  const std::size_t threads = std::min<std::size_t>(static_cast<std::size_t>(std::max(workers, 1)),
    (count + std::max<std::size_t>(grain, 1) - 1) / std::max<std::size_t>(grain, 1));
  if (threads < 2 || InsideBody)
  {
    body(begin, end);
    return;
  }
  // Blocks of at least `grain` items, a few per thread, so that uneven items even out.
  const std::size_t block = std::max<std::size_t>(
    std::max<std::size_t>(grain, 1), (count + 4 * threads - 1) / (4 * threads));
  std::exception_ptr failure;
  std::mutex mutex;
  std::size_t next = begin;
  auto work = [&]()
  {
    InsideBody = true;
    for (;;)
    {
      std::size_t b = 0;
      {
        std::lock_guard<std::mutex> lock(mutex);
        if (next >= end)
        {
          break;
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
    InsideBody = false;
  };
  std::vector<std::thread> pool;
  for (std::size_t t = 1; t < threads; ++t)
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

int RanksOnThisMachine(int otherwise)
{
  for (const char* name : { "OMPI_COMM_WORLD_LOCAL_SIZE", "MPI_LOCALNRANKS" })
  {
    if (const int n = PositiveEnvironment(name))
    {
      return n;
    }
  }
  return otherwise;
}

int ParallelForThreadCount()
{
  if (const int n = PositiveEnvironment("VTK_SMP_MAX_THREADS"))
  {
    return n;
  }
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  return std::max(1, hardware / std::max(1, RanksOnThisMachine(1)));
}

} // namespace mesolight
