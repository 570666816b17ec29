// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench relief-aliasing`: the relief's default against a supersampled exact reference
// where texels are smaller than pixels, with level of detail off (the default before) and as an
// untouched vtkReliefProperty draws it.
#ifndef mesolight_ReliefAliasingBenchmark_h
#define mesolight_ReliefAliasingBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{

int RunReliefAliasingBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
