// SPDX-License-Identifier: BSD-3-Clause
// Filters that allocate in proportion to their input run their RequestData body through this, so
// a std::bad_alloc that their memory estimate did not foresee becomes the filter's error (what
// ParaView shows in Output Messages) instead of aborting the process.
#ifndef vtkOutOfMemory_h
#define vtkOutOfMemory_h

#include "vtkAlgorithm.h"
#include "vtkSetGet.h"

#include <new>

// Not for the wrappers (a function template of C++ code only).
#ifndef __VTK_WRAP__
namespace mesolight
{
/** body() is the filter's RequestData work; its result, or 0 with an error on std::bad_alloc. */
template <class Body>
int ExecuteReportingOutOfMemory(vtkAlgorithm* filter, Body&& body)
{
  try
  {
    return body();
  }
  catch (const std::bad_alloc&)
  {
    vtkErrorWithObjectMacro(filter,
      "Out of memory (std::bad_alloc) for this input; set MemoryBudget to be told before "
      "allocating how much it needs, or use a smaller input.");
    return 0;
  }
}
} // namespace mesolight
#endif

#endif
