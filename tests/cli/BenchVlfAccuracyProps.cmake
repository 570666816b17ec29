# SPDX-License-Identifier: BSD-3-Clause
# The light field on models nobody built for it: `bench vlf-accuracy --scenes props`, an office of
# nine models made for a game (Debian's redeclipse-data; open meshes whose hidden faces were left
# out), at the default resolution (auto) with the final gather, against the path tracer. The
# gathered field must be within a mean relative error of 4% over at least 95% of the pixels; the
# propagated textures alone must not be (the check tells the field the tool draws from the
# unfinished one). Skipped where the package is absent, unless MESOLIGHT_REQUIRE_REAL_MAPS=1.
cmake_minimum_required(VERSION 3.16)
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
if (NOT EXISTS "/usr/share/games/redeclipse/data/nieb/desk/model.obj")
  if ("$ENV{MESOLIGHT_REQUIRE_REAL_MAPS}" STREQUAL "1")
    message(FATAL_ERROR "redeclipse-data is absent, and MESOLIGHT_REQUIRE_REAL_MAPS=1 requires it "
      "(MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh installs it)")
  endif ()
  message("redeclipse-data is absent: skipped")
  return()
endif ()

cli_run(TRUE bench vlf-accuracy --scenes props --settings auto --variants none,gather
  --size 32x32 --samples 2048 --cache "${WORK}/cache" --csv "${WORK}/props.csv")
if (NOT last_output MATCHES "the models have ([0-9]+) open edges" OR CMAKE_MATCH_1 LESS 100)
  message(FATAL_ERROR "the props are not the open meshes this test is about:\n${last_output}")
endif ()
file(STRINGS "${WORK}/props.csv" lines)
list(LENGTH lines count)
if (NOT count EQUAL 3)
  message(FATAL_ERROR "expected a propagated and a gathered row:\n${lines}")
endif ()
foreach (row 1 2)
  list(GET lines ${row} line)
  string(REPLACE "," ";" fields "${line}")
  list(GET fields 16 variant)
  list(GET fields 19 pixels)
  list(GET fields 20 mean)
  if (pixels LESS 973)
    message(FATAL_ERROR "${variant}: ${pixels} of 1024 pixels compared:\n${line}")
  endif ()
  set(mean_${variant} "${mean}")
endforeach ()
if (NOT mean_gather LESS 0.04)
  message(FATAL_ERROR "the gathered field is ${mean_gather} from the path tracer (limit 0.04)")
endif ()
if (mean_none LESS 0.04)
  message(FATAL_ERROR
    "the propagated textures pass (${mean_none}): the check cannot tell the fields apart")
endif ()
message("props: gathered ${mean_gather}, propagated ${mean_none} mean relative error")
