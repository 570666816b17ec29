// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ParallelForThreads.h
 * @brief ParallelFor's own threads, for where vtkSMPTools has none: its Sequential backend, which
 *        ParaView's VTK selects by default (Debian's ParaView 5.11 builds STDThread but does not
 *        select it), and the VTK-free cores-only build. As VTK's imaging filters turn to
 *        vtkMultiThreader where vtkSMPTools is sequential. Plain C++17, no VTK.
 */
#ifndef mesolight_ParallelForThreads_h
#define mesolight_ParallelForThreads_h

#include "MesolightCommonModule.h" // for the export macro

#include <cstddef>
#include <functional>

namespace mesolight
{

/**
 * ParallelFor's contract (ParallelFor.h) on `workers` threads (the calling thread is one; the
 * others from a pool started once and kept): blocks of at least `grain` items, a few per worker,
 * taken in turn. workers <= 1, one item, a call from inside another call's body (nested) or one
 * made while another thread's call holds the pool runs body(begin, end) on the calling thread.
 */
MESOLIGHTCOMMON_EXPORT void ParallelForOnThreads(std::size_t begin, std::size_t end,
  std::size_t grain, const std::function<void(std::size_t, std::size_t)>& body, int workers);

/**
 * The ranks of an MPI job on this machine, as the launcher says (Open MPI's
 * OMPI_COMM_WORLD_LOCAL_SIZE, MPICH and Hydra's MPI_LOCALNRANKS), else `otherwise`.
 */
MESOLIGHTCOMMON_EXPORT int RanksOnThisMachine(int otherwise);

/**
 * The threads a parallel loop takes: VTK_SMP_MAX_THREADS when set (vtkSMPTools' own variable,
 * at most the hardware threads, as vtkSMPTools takes it), else the machine's hardware threads
 * split between the MPI ranks on it (RanksOnThisMachine(ranksOtherwise)), at least 1.
 * ParallelFor's own threads use it with one rank when the launcher does not say; `mesolight vlf
 * propagate` with its communicator's size.
 */
MESOLIGHTCOMMON_EXPORT int ParallelForThreadCount(int ranksOtherwise = 1);

} // namespace mesolight

#endif
