# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench relief-aliasing` end to end on a tiny run: one distant and one near view of a
# fine procedural map; the table, the CSV and the chart appear, the distant view's far pixels are
# closer to the supersampled exact frame with the default (level of detail) than without, no
# near hit moves, and each row's frame time is printed; so too under an environment's light set.
# Bad arguments exit with 2, a missing environment file with its name.
cmake_minimum_required(VERSION 3.16) # quoted strings in if() are strings (CMP0054)
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
cli_execute(bench relief-aliasing --maps Stone --resolution 1024 --angles 45 --distances 0.05,2
            --size 80x60 --supersampling 4 --frames 2 --csv "${WORK}/aliasing.csv"
            --plot "${WORK}/aliasing.png")
message("${cli_stdout}")
if (NOT cli_rc EQUAL 0)
  message(FATAL_ERROR "bench relief-aliasing failed (rc ${cli_rc}): ${cli_stderr}")
endif ()
foreach (file aliasing.csv aliasing.png)
  if (NOT EXISTS "${WORK}/${file}")
    message(FATAL_ERROR "bench relief-aliasing wrote no ${file}")
  endif ()
endforeach ()
file(STRINGS "${WORK}/aliasing.csv" lines)
list(LENGTH lines count)
if (NOT count EQUAL 3)
  message(FATAL_ERROR "aliasing.csv has ${count} lines, not 3 (a header and two cases)")
endif ()
# A case's far error: the default's (CSV column 10) below level of detail off's (column 9).
function(check_far_error_below_before csv_line what)
  string(REPLACE "," ";" far "${csv_line}")
  list(GET far 8 before)
  list(GET far 9 default)
  if (NOT default LESS before)
    message(FATAL_ERROR "${what}: far error default ${default}, before ${before}")
  endif ()
endfunction()
list(GET lines 2 far) # the distant case
check_far_error_below_before("${far}" "distant view")
if (NOT cli_stdout MATCHES "ms per frame, summed over the cases: before [0-9.e+-]+, default [0-9.e+-]+ ")
  message(FATAL_ERROR "no frame times")
endif ()
if (NOT lines MATCHES "ms_before,ms_default,ms_third_row")
  message(FATAL_ERROR "aliasing.csv has no frame time columns")
endif ()
if (NOT cli_stdout MATCHES "largest move of a near hit: 0 texels")
  message(FATAL_ERROR "a near hit moved with level of detail")
endif ()
# Lit by an environment alone (every frame, the reference's too): the header says so, and the
# distant view's default is again closer to the reference than level of detail off.
cli_execute(bench relief-aliasing --maps Stone --resolution 1024 --angles 45 --distances 2
            --size 80x60 --supersampling 4 --frames 0 --environment procedural:sky --env-lights 8
            --lights 0 --csv "${WORK}/aliasing-sky.csv")
message("${cli_stdout}")
if (NOT cli_rc EQUAL 0)
  message(FATAL_ERROR "bench relief-aliasing --environment failed (rc ${cli_rc}): ${cli_stderr}")
endif ()
if (NOT cli_stdout MATCHES "lights: 0 VTK light.s.. environment procedural:sky, 8 median-cut")
  message(FATAL_ERROR "the header does not name the environment's light set")
endif ()
file(STRINGS "${WORK}/aliasing-sky.csv" lines)
list(GET lines 1 far)
check_far_error_below_before("${far}" "distant view under the sky")
cli_execute(bench relief-aliasing --maps Stone --environment "${WORK}/no-such-sky.exr" --frames 0)
if (cli_rc EQUAL 0 OR NOT cli_stderr MATCHES "no-such-sky")
  message(FATAL_ERROR "a missing environment file was not reported (rc ${cli_rc}): ${cli_stderr}")
endif ()
# Light options that would be ignored or leave nothing lit are refused, not run.
foreach (unlit "--lights;0" "--env-lights;8" "--exposure;2")
  cli_execute(bench relief-aliasing --maps Stone ${unlit})
  if (NOT cli_rc EQUAL 2 OR NOT cli_stderr MATCHES "environment")
    message(FATAL_ERROR "bench relief-aliasing ${unlit}: rc ${cli_rc}, not a usage error:\n${cli_stderr}")
  endif ()
endforeach ()
foreach (bad "--method;no-such-method" "--steps;x" "--supersampling;0" "--compare-filter;none"
             "--compare-far-view-rays;0" "--frames;-1" "--lights;3" "--env-lights;0"
             "--exposure;-1")
  cli_execute(bench relief-aliasing ${bad})
  if (NOT cli_rc EQUAL 2)
    message(FATAL_ERROR "bench relief-aliasing ${bad} exited with ${cli_rc}, not 2")
  endif ()
endforeach ()
