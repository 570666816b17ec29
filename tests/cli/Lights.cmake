# SPDX-License-Identifier: BSD-3-Clause
# mesolight lights: the CSV has the documented header and one row per light; bad input fails.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
cli_run(TRUE lights procedural:sun --count 16 --out "${WORK}/lights.csv")
file(STRINGS "${WORK}/lights.csv" lines)
list(LENGTH lines count)
list(GET lines 0 header)
if (NOT header STREQUAL "u,v,x,y,z,r,g,b" OR NOT count EQUAL 17)
  message(FATAL_ERROR "unexpected CSV: header '${header}', ${count} lines")
endif ()
cli_expect_failure("a count of 0 was accepted"
  lights procedural:sun --count 0 --out "${WORK}/none.csv")
cli_expect_failure("a missing environment file was accepted"
  lights "${WORK}/missing.exr" --count 8 --out "${WORK}/x.csv")
# Variance-minimizing cuts are the default; --plain asks for even-energy cuts, not with --variance.
cli_run(TRUE lights procedural:sun --count 16 --plain --out "${WORK}/plain.csv")
file(STRINGS "${WORK}/plain.csv" lines)
list(LENGTH lines count)
if (NOT count EQUAL 17)
  message(FATAL_ERROR "--plain wrote ${count} lines, expected 17")
endif ()
cli_expect_failure("--plain with --variance was accepted"
  lights procedural:sun --count 16 --plain --variance --out "${WORK}/both.csv")
