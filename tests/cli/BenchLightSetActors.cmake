# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench light-set-actors` on a tiny sweep: it runs, prints the table and writes one CSV
# row per configuration; the K = 2 + SH9 sphere beats VTK's headlight against the exact reference.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
cli_run(TRUE bench light-set-actors --counts 2 --lights 64 --size 48 --samples 4 --frames 1
        --frame-size 64 --shadow-map 256 --csv "${WORK}/bench.csv")
file(STRINGS "${WORK}/bench.csv" lines)
list(LENGTH lines count)
list(GET lines 0 header)
# sphere: K=2, ambient, none, headlight, y-up; plane: K=2 off/on, ambient, none, headlight, y-up.
if (NOT header MATCHES "^scene,variant,k,remainder,shadows,exact_mean" OR NOT count EQUAL 12)
  message(FATAL_ERROR "unexpected CSV: '${header}', ${count} lines")
endif ()
list(GET lines 1 good)
list(GET lines 4 headlight)
string(REPLACE "," ";" good "${good}")
string(REPLACE "," ";" headlight "${headlight}")
list(GET good 5 goodError)
list(GET headlight 5 headlightError)
if (NOT goodError LESS headlightError)
  message(FATAL_ERROR "the light set (${goodError}) is not better than the headlight (${headlightError})")
endif ()
