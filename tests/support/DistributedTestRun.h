// SPDX-License-Identifier: BSD-3-Clause
// The set-up every test run under `mpiexec -n N` shares: the MPI controller made global, this
// rank's checks counted and printed with its rank, an unexpected error failing the rank rather
// than leaving the others waiting, and the exit code (0 when every check held on this rank).
// VTK only, no test framework.
#ifndef MesolightDistributedTestRun_h
#define MesolightDistributedTestRun_h

#include "vtkMPIController.h"
#include "vtkNew.h"

#include <exception>
#include <functional>
#include <iostream>
#include <string>

namespace mesolight_test
{

/** This rank's failed checks, and its rank (for the messages). */
inline int Failures = 0;
inline int Rank = 0;

/** Counts a failed check on this rank and prints it with the rank. */
inline void Check(bool ok, const std::string& what)
{
  if (!ok)
  {
    ++Failures;
    std::cerr << "rank " << Rank << ": FAILED: " << what << "\n";
  }
}

/**
 * Runs body(controller, argc, argv) with the MPI controller initialized and global (argc and
 * argv as MPI leaves them), and returns the exit code: 0 when body returns no failures and
 * throws nothing.
 */
inline int RunDistributedTest(
  int argc, char* argv[], const std::function<int(vtkMultiProcessController*, int, char**)>& body)
{
  vtkNew<vtkMPIController> controller;
  controller->Initialize(&argc, &argv);
  vtkMultiProcessController::SetGlobalController(controller);
  Rank = controller->GetLocalProcessId();
  int failures = 0;
  try
  {
    failures = body(controller, argc, argv);
  }
  catch (const std::exception& e)
  {
    std::cerr << "rank " << Rank << ": unexpected error: " << e.what() << "\n";
    failures = 1;
  }
  vtkMultiProcessController::SetGlobalController(nullptr);
  controller->Finalize();
  return failures == 0 ? 0 : 1;
}

} // namespace mesolight_test

#endif
