// SPDX-License-Identifier: BSD-3-Clause
// Wall-clock timing shared by the commands and benchmarks: seconds since a start on the steady
// clock, the fastest of repeated runs, and the median of repeated runs.
#ifndef mesolight_Timing_h
#define mesolight_Timing_h

#include <algorithm>
#include <chrono>
#include <functional>
#include <vector>

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

/** Milliseconds of the median of `repeats` runs of run (0 when repeats < 1). */
inline double MedianMilliseconds(int repeats, const std::function<void()>& run)
{
  std::vector<double> times;
  for (int r = 0; r < repeats; ++r)
  {
    const auto start = std::chrono::steady_clock::now();
    run();
    times.push_back(1000.0 * SecondsSince(start));
  }
  if (times.empty())
  {
    return 0.0;
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

} // namespace mesolight

#endif
