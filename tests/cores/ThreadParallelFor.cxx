// SPDX-License-Identifier: BSD-3-Clause
// mesolight::ParallelFor for the cores-only build (MESOLIGHT_CORES_ONLY=ON, tests/cores), which
// has no VTK and so no vtkSMPTools: ParallelFor's own threads (common/ParallelForThreads.h), at
// least two, so that the sanitizers still see the cores run concurrently as they do in the tool.
// Same contract as common/ParallelFor.cxx.
#include "ParallelFor.h"
#include "ParallelForThreads.h"

#include <algorithm>

namespace mesolight
{

void ParallelFor(std::size_t begin, std::size_t end, std::size_t grain,
  const std::function<void(std::size_t, std::size_t)>& body, int threads)
{
  ParallelForOnThreads(
    begin, end, grain, body, threads == 1 ? 1 : std::max(2, ParallelForThreadCount()));
}

} // namespace mesolight
