// SPDX-License-Identifier: BSD-3-Clause
// mesolight::ParallelFor for the fuzz build (MESOLIGHT_FUZZ=ON), which has no VTK and so no
// vtkSMPTools: the whole range on the calling thread. One input at a time is what libFuzzer runs,
// and -jobs gives it parallelism across processes.
#include "ParallelFor.h"

namespace mesolight
{

void ParallelFor(std::size_t begin, std::size_t end, std::size_t /*grain*/,
  const std::function<void(std::size_t, std::size_t)>& body, int /*threads*/)
{
  if (end > begin)
  {
    body(begin, end);
  }
}

} // namespace mesolight
