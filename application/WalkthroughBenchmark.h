// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench walkthrough`: the frame time of every walkthrough mode (vtkLightFieldActor)
// split into stages, with CSV and a chart (docs/walkthrough.md).
#ifndef mesolight_WalkthroughBenchmark_h
#define mesolight_WalkthroughBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{
/** mesolight bench walkthrough [FIELD] [--size 800x800] [--frames N] [--csv F] [--plot F.png] */
int RunWalkthroughBenchmark(const std::vector<std::string>& args);
} // namespace mesolight

#endif
