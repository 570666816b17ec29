# SPDX-License-Identifier: BSD-3-Clause
# The lights CSV read back by the tool: `mesolight lights` writes it, `mesolight render
# --lights-csv` lights the relief with it; a malformed CSV or two light sets fail with one line.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
execute_process(COMMAND "${CLI}" lights procedural:sun --count 32 --out "${WORK}/lights.csv"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "lights failed (rc ${rc}): ${out} ${err}")
endif ()
execute_process(COMMAND "${CLI}" render --offscreen --size 96x96 --resolution 64 --lights 0
                        --lights-csv "${WORK}/lights.csv" --out "${WORK}/from-csv.png"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/from-csv.png")
  message(FATAL_ERROR "render --lights-csv failed (rc ${rc}): ${out} ${err}")
endif ()
file(WRITE "${WORK}/bad.csv" "x,y,z,r,g,b\n0,0,1,1,1,1\n")
execute_process(COMMAND "${CLI}" render --offscreen --size 96x96 --resolution 64 --lights 0
                        --lights-csv "${WORK}/bad.csv" --out "${WORK}/bad.png"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (rc EQUAL 0 OR NOT err MATCHES "line 1: the header" OR EXISTS "${WORK}/bad.png")
  message(FATAL_ERROR "a malformed CSV was not reported (rc ${rc}): ${err}")
endif ()
execute_process(COMMAND "${CLI}" render --offscreen --environment procedural:sun
                        --lights-csv "${WORK}/lights.csv" --out "${WORK}/both.png"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_VARIABLE err)
if (NOT rc EQUAL 2 OR NOT err MATCHES "give one light set")
  message(FATAL_ERROR "--environment with --lights-csv was accepted (rc ${rc}): ${err}")
endif ()
# The CSV is an input: render never writes over it.
execute_process(COMMAND "${CLI}" render --offscreen --lights-csv "${WORK}/lights.csv"
                        --out "${WORK}/lights.csv"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
file(STRINGS "${WORK}/lights.csv" lines LIMIT_COUNT 1)
if (rc EQUAL 0 OR NOT lines STREQUAL "u,v,x,y,z,r,g,b")
  message(FATAL_ERROR "render --out overwrote the light set (rc ${rc})")
endif ()
