// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ParallelFor.h
 * @brief The one parallel-for of Mesolight (plain C++17 interface; vtkSMPTools behind it).
 *
 * Every core and filter that works in parallel calls this; none starts its own threads or takes
 * a parallel-for callback. The split of [begin, end) into sub-ranges is up to vtkSMPTools (its
 * backend, TBB in Debian's VTK, and its thread count: vtkSMPTools::Initialize or
 * VTK_SMP_MAX_THREADS), or, where its backend is Sequential (ParaView's VTK by default), to
 * ParallelForOnThreads (ParallelForThreads.h), so a body must give the same result however the
 * range is split: write per-item results, or reduce over a fixed partition (blocks whose
 * contents do not depend on the split).
 */
#ifndef mesolight_ParallelFor_h
#define mesolight_ParallelFor_h

#include "MesolightCommonModule.h" // for the export macro

#include <cstddef>
#include <functional>

namespace mesolight
{

/**
 * Runs body(b, e) over disjoint sub-ranges [b, e) covering [begin, end), concurrently, and
 * returns when all are done. grain: the smallest sub-range worth a task (0: vtkSMPTools
 * chooses). threads == 1 runs body(begin, end) on the calling thread (single-thread timings,
 * tests); any other value uses all of vtkSMPTools' threads (ParallelForThreadCount() under
 * its Sequential backend). An exception thrown by the body
 * is rethrown here (the first one; the other sub-ranges still run).
 */
MESOLIGHTCOMMON_EXPORT void ParallelFor(std::size_t begin, std::size_t end, std::size_t grain,
  const std::function<void(std::size_t, std::size_t)>& body, int threads = 0);

} // namespace mesolight

#endif
