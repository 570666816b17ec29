// SPDX-License-Identifier: BSD-3-Clause
// The commands of the `mesolight` tool that draw the standard relief scene (ReliefScene.h):
// `render` (a PNG, then an interactive window) and `bench` (relief vs the dense mesh).
#ifndef mesolight_RenderCommand_h
#define mesolight_RenderCommand_h

#include <string>
#include <vector>

namespace mesolight
{

/** mesolight render [options]; `args` excludes "render". */
int RunRenderCommand(const std::vector<std::string>& args);

/** mesolight bench [options] (no benchmark name); `args` excludes "bench". */
int RunReliefBenchmarkCommand(const std::vector<std::string>& args);

} // namespace mesolight

#endif
