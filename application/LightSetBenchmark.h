// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench ibl`: a relief surface lit by median-cut light sets of an environment.
// Frame time against the number of lights (one run for all counts, like the relief thesis'
// table 1), the effect of each skip on time and error, the error of each light set against a
// Monte Carlo reference with exact height-field visibility, and relief vs relaxed cone stepping at
// equal error against the exact render of the same light set (references: LightSetReference.h).
#ifndef mesolight_LightSetBenchmark_h
#define mesolight_LightSetBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{
/** `mesolight bench ibl [--counts 32,...,1024] [--frames N] [--csv FILE] ...` */
int RunLightSetBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
