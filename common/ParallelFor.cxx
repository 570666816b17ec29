// SPDX-License-Identifier: BSD-3-Clause
#include "ParallelFor.h"

#include "ParallelForThreads.h"

#include "vtkSMPTools.h"
#include "vtkType.h"

#include <cstring>
#include <exception>
#include <mutex>

namespace mesolight
{

void ParallelFor(std::size_t begin, std::size_t end, std::size_t grain,
  const std::function<void(std::size_t, std::size_t)>& body, int threads)
{
  if (end <= begin)
  {
    return;
  }
  if (threads == 1 || end - begin == 1)
  {
    body(begin, end);
    return;
  }
  // vtkSMPTools' Sequential backend (ParaView's VTK selects it by default) would run every core
  // on one thread: the cores' work (light-field propagation, cone maps, the relief's maps) takes
  // the machine's threads on its own instead, as VTK's imaging filters do.
  if (std::strcmp(vtkSMPTools::GetBackend(), "Sequential") == 0)
  {
    ParallelForOnThreads(begin, end, grain, body, ParallelForThreadCount());
    return;
  }
  // Exceptions must not leave a vtkSMPTools task (the STDThread backend would terminate):
  // keep the first, rethrow it on the calling thread.
  std::exception_ptr failure;
  std::mutex failureMutex;
  auto run = [&](vtkIdType b, vtkIdType e)
  {
    try
    {
      body(static_cast<std::size_t>(b), static_cast<std::size_t>(e));
    }
    catch (...)
    {
      std::lock_guard<std::mutex> lock(failureMutex);
      if (!failure)
      {
        failure = std::current_exception();
      }
    }
  };
  vtkSMPTools::For(
    static_cast<vtkIdType>(begin), static_cast<vtkIdType>(end), static_cast<vtkIdType>(grain), run);
  if (failure)
  {
    std::rethrow_exception(failure);
  }
}

} // namespace mesolight
