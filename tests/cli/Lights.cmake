# SPDX-License-Identifier: BSD-3-Clause
# mesolight lights: the CSV has the documented header and one row per light; bad input fails.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
execute_process(COMMAND "${CLI}" lights procedural:sun --count 16 --out "${WORK}/lights.csv"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "lights failed (rc ${rc}): ${out} ${err}")
endif ()
file(STRINGS "${WORK}/lights.csv" lines)
list(LENGTH lines count)
list(GET lines 0 header)
if (NOT header STREQUAL "u,v,x,y,z,r,g,b" OR NOT count EQUAL 17)
  message(FATAL_ERROR "unexpected CSV: header '${header}', ${count} lines")
endif ()
execute_process(COMMAND "${CLI}" lights procedural:sun --count 0 --out "${WORK}/none.csv"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if (rc EQUAL 0)
  message(FATAL_ERROR "a count of 0 was accepted")
endif ()
execute_process(COMMAND "${CLI}" lights "${WORK}/missing.exr" --count 8 --out "${WORK}/x.csv"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if (rc EQUAL 0)
  message(FATAL_ERROR "a missing environment file was accepted")
endif ()
