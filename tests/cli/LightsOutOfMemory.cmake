# SPDX-License-Identifier: BSD-3-Clause
# `mesolight lights` on a 8192 x 4096 procedural map under virtual-memory limits (ulimit -v). The
# memory estimate now sees the limit (AvailableMemory takes RLIMIT_AS into account), so the cut
# is refused before allocating, naming "the memory available" (it used to run into std::bad_alloc
# inside vtkMedianCutLights only for a machine-dependent window of limits, whose message said "set
# MemoryBudget", the VTK property, where the tool's option is --memory-budget). Whatever the limit:
# no crash (an unforeseen std::bad_alloc is one line and exit 1, not an abort), never the VTK
# property's name, and an explicit --memory-budget is named as the option.
# Even-energy cuts (--plain): the limits were chosen for their full-resolution table (the default
# variance cuts work on cells and need less).
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
set(refused FALSE)
foreach (limit IN ITEMS 700000 1100000 1500000 1700000 1900000 2100000)
  execute_process(COMMAND sh -c "ulimit -v ${limit} && exec \"$0\" lights procedural:sun --resolution 4096 --count 4 --plain --out \"$1\""
    "${CLI}" "${WORK}/lights-${limit}.csv"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc MATCHES "^[0-9]+$" OR err MATCHES "terminate called|Aborted")
    message(FATAL_ERROR "ulimit -v ${limit}: crashed (${rc}): ${err}")
  endif ()
  if (err MATCHES "set MemoryBudget")
    message(FATAL_ERROR "ulimit -v ${limit}: the message names the VTK property: ${err}")
  endif ()
  if (rc EQUAL 0)
    continue () # the machine maps little enough for the whole cut to fit
  endif ()
  if (NOT err MATCHES "memory available, [0-9]+ [MK]iB|out of memory|Out of memory")
    message(FATAL_ERROR "ulimit -v ${limit}: rc ${rc} without a memory message: ${err}")
  endif ()
  if (err MATCHES "Out of memory \\(std::bad_alloc\\)" AND NOT err MATCHES "set --memory-budget")
    message(FATAL_ERROR "ulimit -v ${limit}: the filter's advice names no option: ${err}")
  endif ()
  if (err MATCHES "needs about [0-9]+ MiB of memory, more than the memory available")
    set(refused TRUE)
    break () # larger limits only let more of the work run
  endif ()
endforeach ()
if (NOT refused)
  message(FATAL_ERROR "no virtual-memory limit was seen by the memory estimate")
endif ()
cli_expect_error(1 "more than the memory budget of 512 MiB; raise the budget"
  lights procedural:sun --resolution 4096 --count 4 --memory-budget 0.5 --out "${WORK}/budget.csv")
