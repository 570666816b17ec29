// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench`: frame time and error of each way to draw a height field, in one run.
#ifndef mesolight_ReliefBenchmark_h
#define mesolight_ReliefBenchmark_h

#include "ReliefScene.h"

#include <ostream>
#include <string>
#include <vector>

namespace mesolight
{

struct BenchmarkSettings
{
  ReliefSceneOptions Scene;
  std::vector<int> Resolutions{ 512, 1024 };
  int Frames = 20;
  std::string CsvFile;
};

/** Prints the table (and writes CSV when asked); false if a scene could not be built. */
bool RunReliefBenchmark(const BenchmarkSettings& settings, std::ostream& out);

} // namespace mesolight

#endif
