// SPDX-License-Identifier: BSD-3-Clause
// mesolight::ParallelFor under vtkSMPTools' Sequential backend, ParaView's VTK's default: its own
// threads (ParallelForThreads.h) must run every item once, on several threads, honour
// VTK_SMP_MAX_THREADS and the MPI ranks sharing the machine, run nested loops inline and hand an
// exception back to the caller. Each test runs in its own process (ctest), so the environment
// variables it sets do not reach the others.
#include "ParallelFor.h"
#include "ParallelForThreads.h"

#include <vtkSMPTools.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cstdlib>
#include <mutex>
#include <set>
#include <stdexcept>
#include <string>
#include <thread>
#include <vector>

namespace
{
using mesolight::ParallelFor;

// Selects vtkSMPTools' Sequential backend for the test's lifetime (ParaView's default).
struct SequentialBackend
{
  SequentialBackend()
    : Previous(vtkSMPTools::GetBackend())
  {
    vtkSMPTools::SetBackend("Sequential");
  }
  ~SequentialBackend() { vtkSMPTools::SetBackend(this->Previous.c_str()); }
  std::string Previous;
};

// Runs ParallelFor over `items` items, each taking a little time so that every thread gets some;
// returns the threads that ran them and checks every item ran exactly once.
std::set<std::thread::id> ThreadsThatRan(std::size_t items)
{
  std::vector<std::atomic<int>> runs(items);
  std::set<std::thread::id> threads;
  std::mutex mutex;
  ParallelFor(0, items, 1,
    [&](std::size_t begin, std::size_t end)
    {
      {
        std::lock_guard<std::mutex> lock(mutex);
        threads.insert(std::this_thread::get_id());
      }
      for (std::size_t k = begin; k < end; ++k)
      {
        ++runs[k];
        std::this_thread::sleep_for(std::chrono::microseconds(200));
      }
    });
  for (std::size_t k = 0; k < items; ++k)
  {
    EXPECT_EQ(runs[k].load(), 1) << "item " << k;
  }
  return threads;
}

TEST(ParallelFor, UnderTheSequentialBackendItStartsThreadsOfItsOwn)
{
  if (std::thread::hardware_concurrency() < 2)
  {
    GTEST_SKIP() << "one hardware thread";
  }
  unsetenv("VTK_SMP_MAX_THREADS");
  unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  unsetenv("MPI_LOCALNRANKS");
  SequentialBackend sequential;
  ASSERT_STREQ(vtkSMPTools::GetBackend(), "Sequential");
  EXPECT_EQ(vtkSMPTools::GetEstimatedNumberOfThreads(), 1); // what ran every core on one thread
  const std::set<std::thread::id> threads = ThreadsThatRan(400);
  std::printf("[          ] Sequential backend: %zu threads ran 400 items (%u hardware threads)\n",
    threads.size(), std::thread::hardware_concurrency());
  EXPECT_GE(threads.size(), 2u);
  EXPECT_LE(threads.size(), std::thread::hardware_concurrency());
}

// The threads are kept between loops (a light field runs thousands of short ones): thousands of
// loops of a few items, and loops asked for from two threads at once (the second runs on its
// caller while the first holds the threads), each run every item exactly once.
TEST(ParallelFor, ManyShortLoopsAndLoopsFromTwoThreadsRunEveryItemOnce)
{
  unsetenv("VTK_SMP_MAX_THREADS");
  SequentialBackend sequential;
  const auto loops = [](int count, std::size_t items)
  {
    long wrong = 0;
    for (int n = 0; n < count; ++n)
    {
      std::vector<std::atomic<int>> runs(items);
      ParallelFor(0, items, 1,
        [&](std::size_t begin, std::size_t end)
        {
          for (std::size_t k = begin; k < end; ++k)
          {
            ++runs[k];
          }
        });
      for (const std::atomic<int>& r : runs)
      {
        wrong += r.load() != 1 ? 1 : 0;
      }
    }
    return wrong;
  };
  EXPECT_EQ(loops(5000, 4), 0);
  long wrongElsewhere = -1;
  std::thread other([&]() { wrongElsewhere = loops(2000, 37); });
  EXPECT_EQ(loops(2000, 53), 0);
  other.join();
  EXPECT_EQ(wrongElsewhere, 0);
}

TEST(ParallelFor, OneThreadWhenVtkSmpMaxThreadsSaysOne)
{
  setenv("VTK_SMP_MAX_THREADS", "1", 1);
  SequentialBackend sequential;
  EXPECT_EQ(mesolight::ParallelForThreadCount(), 1);
  const std::set<std::thread::id> threads = ThreadsThatRan(100);
  ASSERT_EQ(threads.size(), 1u);
  EXPECT_EQ(*threads.begin(), std::this_thread::get_id());
}

TEST(ParallelFor, ThreadsOnlyOneThreadAskedForRunOnTheCaller)
{
  SequentialBackend sequential;
  std::set<std::thread::id> threads;
  ParallelFor(
    0, 100, 1, [&](std::size_t, std::size_t) { threads.insert(std::this_thread::get_id()); }, 1);
  ASSERT_EQ(threads.size(), 1u);
  EXPECT_EQ(*threads.begin(), std::this_thread::get_id());
}

TEST(ParallelFor, RanksOnOneMachineSplitItsThreads)
{
  unsetenv("VTK_SMP_MAX_THREADS");
  unsetenv("MPI_LOCALNRANKS");
  const int hardware = static_cast<int>(std::max(1u, std::thread::hardware_concurrency()));
  unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  EXPECT_EQ(mesolight::RanksOnThisMachine(5), 5); // the launcher says nothing
  EXPECT_EQ(mesolight::ParallelForThreadCount(), hardware);
  setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "2", 1); // Open MPI: two ranks here
  EXPECT_EQ(mesolight::RanksOnThisMachine(5), 2);
  EXPECT_EQ(mesolight::ParallelForThreadCount(), std::max(1, hardware / 2));
  setenv("OMPI_COMM_WORLD_LOCAL_SIZE", "not a number", 1);
  setenv("MPI_LOCALNRANKS", "3", 1); // MPICH / Hydra
  EXPECT_EQ(mesolight::RanksOnThisMachine(5), 3);
  EXPECT_EQ(mesolight::ParallelForThreadCount(7), std::max(1, hardware / 3)); // said: not 7
  unsetenv("MPI_LOCALNRANKS");
  unsetenv("OMPI_COMM_WORLD_LOCAL_SIZE");
  EXPECT_EQ(mesolight::ParallelForThreadCount(2), std::max(1, hardware / 2)); // not said: 2
  setenv("VTK_SMP_MAX_THREADS", "3", 1); // VTK's own variable wins, up to the hardware threads
  EXPECT_EQ(mesolight::ParallelForThreadCount(), std::min(3, hardware));
  EXPECT_EQ(mesolight::ParallelForThreadCount(2), std::min(3, hardware));
  // An absurd count (a typo, an exponent) is held to the hardware threads, as vtkSMPTools holds
  // it, instead of asking the system for a hundred thousand threads; garbage is not a count.
  setenv("VTK_SMP_MAX_THREADS", "100000", 1);
  EXPECT_EQ(mesolight::ParallelForThreadCount(), hardware);
  setenv("VTK_SMP_MAX_THREADS", "many", 1);
  EXPECT_EQ(mesolight::ParallelForThreadCount(), hardware);
  {
    SequentialBackend sequential;
    EXPECT_LE(ThreadsThatRan(200).size(), static_cast<std::size_t>(hardware));
    // Unset before the TBB backend comes back: VTK 9.1's TBB backend takes the variable as it is
    // (TBB then asks for 99999 workers and crashes at exit), which is VTK's, not this code's.
    unsetenv("VTK_SMP_MAX_THREADS");
  }
}

TEST(ParallelFor, ANestedLoopRunsOnItsCallersThread)
{
  SequentialBackend sequential;
  std::atomic<int> nestedOnOtherThreads{ 0 }, inner{ 0 };
  ParallelFor(0, 8, 1,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t k = begin; k < end; ++k)
      {
        const std::thread::id outer = std::this_thread::get_id();
        ParallelFor(0, 50, 1,
          [&](std::size_t b, std::size_t e)
          {
            inner += static_cast<int>(e - b);
            nestedOnOtherThreads += std::this_thread::get_id() == outer ? 0 : 1;
          });
      }
    });
  EXPECT_EQ(inner.load(), 8 * 50);
  EXPECT_EQ(nestedOnOtherThreads.load(), 0);
}

TEST(ParallelFor, TheFirstExceptionReachesTheCallerAndTheOtherItemsStillRun)
{
  SequentialBackend sequential;
  std::atomic<int> ran{ 0 };
  EXPECT_THROW(ParallelFor(0, 1000, 1,
                 [&](std::size_t begin, std::size_t end)
                 {
                   for (std::size_t k = begin; k < end; ++k)
                   {
                     if (k == 500)
                     {
                       throw std::runtime_error("item 500");
                     }
                     ++ran;
                   }
                 }),
    std::runtime_error);
  // Only the items after 500 in its block are lost: every other block ran.
  EXPECT_GE(ran.load(), 1000 - 1 - 250);
  EXPECT_LT(ran.load(), 1000);
}
} // namespace
