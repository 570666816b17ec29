// SPDX-License-Identifier: BSD-3-Clause
// Depth hallucination in the `mesolight` tool: `hallucinate` (a diffuse and a flash photograph ->
// albedo and depth, vtkDepthHallucinationFilter) and `bench hallucinate` (path-traced photographs
// of known height fields, the filter's depth and albedo against the truth; docs/hallucination.md).
#ifndef mesolight_HallucinateCommand_h
#define mesolight_HallucinateCommand_h

#include <string>
#include <vector>

namespace mesolight
{

/** mesolight hallucinate DIFFUSE FLASH [--calibration C] --albedo A --depth D; `args` excludes
 * "hallucinate". */
int RunHallucinateCommand(const std::vector<std::string>& args);

/** mesolight bench hallucinate [options]; `args` excludes "bench hallucinate". */
int RunHallucinationBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
