# SPDX-License-Identifier: BSD-3-Clause
# What the MPI command-line tests share (included after RunTool.cmake): Open MPI allowed to run
# as root and to oversubscribe (CI containers, 2 cores), and
#   mpi_run(EXPECT_SUCCESS ARGS...)  runs "${MPIEXEC}" ARGS within MPI_RUN_TIMEOUT seconds (default
#                                   60): a run that hangs fails the test, last_output keeps what
#                                   it printed
#   same_field(A B EXPECT_SAME)      compares two fields with COMPARE (the distributed test
#                                   program: every texel within 1e-5)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT} 1)
set(ENV{OMPI_ALLOW_RUN_AS_ROOT_CONFIRM} 1)
set(ENV{OMPI_MCA_rmaps_base_oversubscribe} 1)
if (NOT DEFINED MPI_RUN_TIMEOUT)
  set(MPI_RUN_TIMEOUT 60)
endif ()

function (mpi_run expect_success)
  execute_process(COMMAND "${MPIEXEC}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
    ERROR_VARIABLE err TIMEOUT ${MPI_RUN_TIMEOUT})
  if (rc MATCHES "timeout")
    message(FATAL_ERROR "'${ARGN}' hung (${rc}): ${out} ${err}")
  elseif (expect_success AND NOT rc EQUAL 0)
    message(FATAL_ERROR "'${ARGN}' failed (rc ${rc}): ${out} ${err}")
  elseif (NOT expect_success AND rc EQUAL 0)
    message(FATAL_ERROR "'${ARGN}' was accepted: ${out} ${err}")
  endif ()
  set(last_output "${out}${err}" PARENT_SCOPE)
endfunction ()

function (same_field a b expect_same)
  execute_process(COMMAND "${COMPARE}" compare "${a}" "${b}" RESULT_VARIABLE rc
    OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (expect_same AND NOT rc EQUAL 0)
    message(FATAL_ERROR "${a} and ${b} differ: ${out} ${err}")
  elseif (NOT expect_same AND rc EQUAL 0)
    message(FATAL_ERROR "${a} and ${b} compare equal, which they are not: ${out}")
  endif ()
  message(STATUS "${a} against ${b}: ${out}")
endfunction ()
