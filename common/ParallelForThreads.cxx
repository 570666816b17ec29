// SPDX-License-Identifier: BSD-3-Clause
#include "ParallelForThreads.h"

#include <algorithm>
#include <condition_variable>
#include <cstdlib>
#include <exception>
#include <mutex>
#include <system_error>
#include <thread>
#include <vector>

namespace mesolight
{
namespace
{
// Set on the threads running a body, so that a parallel-for inside it runs inline instead of
// asking the busy pool for more threads.
thread_local bool InsideBody = false;

int PositiveEnvironment(const char* name)
{
  const char* value = std::getenv(name);
  const int n = value ? std::atoi(value) : 0;
  return n > 0 ? n : 0;
}

// Threads started once and kept, so that a loop costs a wake-up, not a thread start (a light
// field's propagation runs a few thousand short loops). One loop at a time: a loop asked for
// while another runs (from another thread) runs on its caller alone. Never destroyed: its threads
// wait on it until the process ends (a plugin's library stays loaded as long).
class WorkerPool
{
public:
  static WorkerPool& Instance()
  {
    static WorkerPool* pool = new WorkerPool;
    return *pool;
  }

  // Runs work() on the calling thread and on `helpers` pool threads, returning when every call
  // has; false, running nothing, when the pool is busy with another caller's loop.
  bool Run(int helpers, const std::function<void()>& work)
  {
    std::unique_lock<std::mutex> busy(this->Busy, std::try_to_lock);
    if (!busy.owns_lock())
    {
      return false;
    }
    {
      std::lock_guard<std::mutex> lock(this->Mutex);
      while (static_cast<int>(this->Threads.size()) < helpers)
      {
        try
        {
          this->Threads.emplace_back([this]() { this->Serve(); });
        }
        catch (const std::system_error&)
        {
          break; // the system gives no more threads: the loop runs on those there are
        }
      }
      this->Job = &work;
      this->Waiting = std::min(helpers, static_cast<int>(this->Threads.size()));
    }
    this->Wake.notify_all();
    work();
    // work() returns when nothing is left to take: the helpers not started yet need not start.
    std::unique_lock<std::mutex> lock(this->Mutex);
    this->Waiting = 0;
    this->Done.wait(lock, [this]() { return this->Running == 0; });
    this->Job = nullptr;
    return true;
  }

private:
  void Serve()
  {
    std::unique_lock<std::mutex> lock(this->Mutex);
    for (;;)
    {
      this->Wake.wait(lock, [this]() { return this->Waiting > 0; });
      --this->Waiting;
      ++this->Running;
      const std::function<void()>* job = this->Job;
      lock.unlock();
      (*job)();
      lock.lock();
      if (--this->Running == 0)
      {
        this->Done.notify_all();
      }
    }
  }

  std::mutex Busy; // held for a whole loop
  std::mutex Mutex;
  std::condition_variable Wake;
  std::condition_variable Done;
  std::vector<std::thread> Threads;
  const std::function<void()>* Job = nullptr;
  int Waiting = 0; // helpers asked for and not started
  int Running = 0; // helpers inside the job
};
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
  const std::function<void()> work = [&]()
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
  if (!WorkerPool::Instance().Run(static_cast<int>(threads) - 1, work))
  {
    work(); // the pool runs another thread's loop: this one on its caller
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

int ParallelForThreadCount(int ranksOtherwise)
{
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  if (const int n = PositiveEnvironment("VTK_SMP_MAX_THREADS"))
  {
    return std::min(n, hardware); // as vtkSMPTools takes it: more threads than cores buy nothing
  }
  return std::max(1, hardware / std::max(1, RanksOnThisMachine(ranksOtherwise)));
}

} // namespace mesolight
