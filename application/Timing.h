// SPDX-License-Identifier: BSD-3-Clause
// Wall-clock timing shared by the commands and benchmarks: seconds since a start on the steady
// clock, and the fastest of repeated runs.
#ifndef mesolight_Timing_h
#define mesolight_Timing_h

#include <algorithm>
#include <chrono>
#include <functional>

namespace mesolight
{

/** Seconds from start to now on the steady clock. */
inline double SecondsSince(std::chrono::steady_clock::time_point start)
{
  return std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
}

/** Seconds of the fastest of `repeats` runs of run (1e30 when repeats < 1). */
inline double FastestSeconds(int repeats, const std::function<void()>& run)
{
  double fastest = 1e30;
  for (int r = 0; r < repeats; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    fastest = std::min(fastest, SecondsSince(start));
  }
  return fastest;
}

} // namespace mesolight

#endif
