// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench relief-field-cost`: what it costs to light a GPU relief (vtkReliefMapper) by a
// light field instead of by one VTK light: SH9 irradiance probes plus the field's emitters as
// self-shadowing VTK lights (vtkReliefMapper::ConfigureEmitterLight), against one self-shadowing
// VTK light, per frame of the same relief filling the same window, in one run.
#ifndef mesolight_ReliefFieldCostBenchmark_h
#define mesolight_ReliefFieldCostBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{
/** `mesolight bench relief-field-cost [--map PATTERN] [--size WxH] [--frames N] [--csv FILE]` */
int RunReliefFieldCostBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
