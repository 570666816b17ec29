# SPDX-License-Identifier: BSD-3-Clause
# The lights CSV read back by the tool: `mesolight lights` writes it, `mesolight render
# --lights-csv` lights the relief with it; a malformed CSV or two light sets fail with one line.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
cli_run(TRUE lights procedural:sun --count 32 --out "${WORK}/lights.csv")
cli_run(TRUE render --offscreen --size 96x96 --resolution 64 --lights 0
        --lights-csv "${WORK}/lights.csv" --out "${WORK}/from-csv.png")
if (NOT EXISTS "${WORK}/from-csv.png")
  message(FATAL_ERROR "render --lights-csv wrote no image: ${last_output}")
endif ()
file(WRITE "${WORK}/bad.csv" "x,y,z,r,g,b\n0,0,1,1,1,1\n")
cli_execute(render --offscreen --size 96x96 --resolution 64 --lights 0
            --lights-csv "${WORK}/bad.csv" --out "${WORK}/bad.png")
if (cli_rc EQUAL 0 OR NOT cli_stderr MATCHES "line 1: the header" OR EXISTS "${WORK}/bad.png")
  message(FATAL_ERROR "a malformed CSV was not reported (rc ${cli_rc}): ${cli_stderr}")
endif ()
cli_execute(render --offscreen --environment procedural:sun --lights-csv "${WORK}/lights.csv"
            --out "${WORK}/both.png")
if (NOT cli_rc EQUAL 2 OR NOT cli_stderr MATCHES "give one light set")
  message(FATAL_ERROR "--environment with --lights-csv was accepted (rc ${cli_rc}): ${cli_stderr}")
endif ()
# The CSV is an input: render never writes over it.
cli_execute(render --offscreen --lights-csv "${WORK}/lights.csv" --out "${WORK}/lights.csv")
file(STRINGS "${WORK}/lights.csv" lines LIMIT_COUNT 1)
if (cli_rc EQUAL 0 OR NOT lines STREQUAL "u,v,x,y,z,r,g,b")
  message(FATAL_ERROR "render --out overwrote the light set (rc ${cli_rc})")
endif ()
