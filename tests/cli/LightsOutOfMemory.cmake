# SPDX-License-Identifier: BSD-3-Clause
# A filter's out-of-memory advice names the tool's option: under a virtual-memory limit
# (ulimit -v, which the memory estimate does not see) `mesolight lights` on a 8192 x 4096
# procedural map runs out of memory inside vtkMedianCutLights, whose message said "set
# MemoryBudget" (its VTK property) where the tool's option is --memory-budget. The limit that
# lets the map be made but not cut depends on the machine: several are tried, and at least one
# must reach the filter's message. Even-energy cuts (--plain): their full-resolution table is
# what the limits were chosen for (the default variance cuts' tables are over cells, smaller).
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
set(reached FALSE)
foreach (limit IN ITEMS 1100000 1200000 1300000 1400000 1500000 1600000 1700000 1800000 1900000)
  execute_process(COMMAND sh -c "ulimit -v ${limit} && exec \"$0\" lights procedural:sun --resolution 4096 --count 4 --plain --out \"$1\""
    "${CLI}" "${WORK}/lights-${limit}.csv"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (err MATCHES "set MemoryBudget")
    message(FATAL_ERROR "ulimit -v ${limit}: the message names the VTK property: ${err}")
  endif ()
  if (err MATCHES "Out of memory \\(std::bad_alloc\\)")
    if (NOT err MATCHES "set --memory-budget to be told" OR rc EQUAL 0)
      message(FATAL_ERROR "ulimit -v ${limit}: rc ${rc}: ${err}")
    endif ()
    set(reached TRUE)
  endif ()
endforeach ()
if (NOT reached)
  message(FATAL_ERROR "no memory limit reached vtkMedianCutLights' out-of-memory message")
endif ()
