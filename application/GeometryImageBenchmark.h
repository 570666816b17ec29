// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench geometry-image`: triangles against geometric error (Hausdorff distance to the
// full-resolution geometry image) and image error (relief on the coarse mesh against the dense
// displaced mesh), regular stride and adaptive sampling side by side at about equal triangle
// counts.
#ifndef mesolight_GeometryImageBenchmark_h
#define mesolight_GeometryImageBenchmark_h

#include <string>
#include <vector>

namespace mesolight
{

/** args: the options after "geometry-image". Returns the process exit code. */
int RunGeometryImageBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
