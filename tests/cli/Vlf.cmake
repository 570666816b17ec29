# SPDX-License-Identifier: BSD-3-Clause
# mesolight vlf: propagate the built-in Cornell box (tiny settings), resume it, render it; bad input
# fails with nothing overwritten (a user's file next to the field is never replaced).
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

set(field "${WORK}/cornell.vlf")
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 1 --out "${field}")
cli_run(TRUE vlf propagate --iterations 2 --resume --out "${field}")
if (NOT last_output MATCHES "iteration 2:")
  message(FATAL_ERROR "resume did not run iteration 2: ${last_output}")
endif ()
# By default propagation runs until at most --tolerance of the emitted flux is left unshot, and
# says so per iteration; a fixed --iterations excludes it.
cli_run(TRUE vlf propagate --directions 33 --rays 16 --tolerance 0.05 --out "${WORK}/tolerance.vlf")
if (NOT last_output MATCHES "of the emitted \\(tolerance 5%\\)" OR NOT last_output MATCHES "iteration 2:")
  message(FATAL_ERROR "no progress toward the tolerance reported: ${last_output}")
endif ()
# Progress and results in one log (stdout and stderr captured together, as `> log 2>&1` does):
# progress lines end before each result line and use no carriage returns ("toward the tolerance
# 50%iteration 4: ..." ran together).
execute_process(COMMAND "${CLI}" vlf propagate --directions 33 --rays 16 --tolerance 0.05 --force
  --out "${WORK}/tolerance.vlf" OUTPUT_VARIABLE log ERROR_VARIABLE log)
string(ASCII 13 carriage_return)
if (log MATCHES "%[a-z]" OR log MATCHES "${carriage_return}" OR NOT log MATCHES "\n100%\n|% 100%\n")
  message(FATAL_ERROR "progress ran into the results of a captured run:\n${log}")
endif ()
cli_run(FALSE vlf propagate --directions 33 --rays 16 --iterations 2 --tolerance 0.05
  --out "${WORK}/both.vlf")
# --filter writes smoothed totals (a different field from the same propagation); it cannot resume.
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 2 --out "${WORK}/raw.vlf")
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 2 --filter --out "${WORK}/smooth.vlf")
execute_process(COMMAND "${CMAKE_COMMAND}" -E compare_files "${WORK}/raw.vlf" "${WORK}/smooth.vlf"
  RESULT_VARIABLE same)
if (same EQUAL 0)
  message(FATAL_ERROR "--filter changed nothing in the field")
endif ()
cli_run(FALSE vlf propagate --iterations 3 --resume --filter --out "${WORK}/smooth.vlf")
cli_run(TRUE vlf render "${field}" --size 64x64 --out "${WORK}/cornell.png")
if (NOT EXISTS "${WORK}/cornell.png")
  message(FATAL_ERROR "no image written")
endif ()
# An existing field is not replaced without --resume or --force; a foreign file never.
cli_run(FALSE vlf propagate --directions 33 --rays 16 --out "${field}")
file(WRITE "${WORK}/notes.txt" "precious")
cli_run(FALSE vlf propagate --directions 33 --rays 16 --force --out "${WORK}/notes.txt")
file(READ "${WORK}/notes.txt" notes)
if (NOT notes STREQUAL "precious")
  message(FATAL_ERROR "a user's file was overwritten")
endif ()
cli_run(FALSE vlf render "${field}" --size 64x64 --out "${WORK}/cornell.png")
# Bad input: absurd settings, over budget, truncated field, a scene without an emitter.
cli_run(FALSE vlf propagate --directions 500 --out "${WORK}/a.vlf")
cli_run(FALSE vlf propagate --rays 30 --tiles 4 --out "${WORK}/b.vlf")
# (The estimate is close to what is allocated: 8193 x 512 x 512 of the box fits the default
# 4 GiB, so the budget is the smallest, 1 MiB.)
cli_run(FALSE vlf propagate --directions 2049 --rays 128 --memory-budget 0.001 --out "${WORK}/c.vlf")
if (NOT last_output MATCHES "memory budget")
  message(FATAL_ERROR "no memory budget message: ${last_output}")
endif ()
execute_process(COMMAND head -c 4000 "${field}" OUTPUT_FILE "${WORK}/truncated.vlf")
cli_run(FALSE vlf render "${WORK}/truncated.vlf" --out "${WORK}/t.png")
if (NOT last_output MATCHES "truncated")
  message(FATAL_ERROR "no truncation message: ${last_output}")
endif ()
file(WRITE "${WORK}/dark.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
cli_run(FALSE vlf propagate "${WORK}/dark.obj" --out "${WORK}/d.vlf")
if (NOT last_output MATCHES "emitter")
  message(FATAL_ERROR "no emitter message: ${last_output}")
endif ()
# Refused when the scene is read: no 'the scene is dark' warning, no resolution chosen first.
if (last_output MATCHES "is dark|automatic resolution")
  message(FATAL_ERROR "the emitterless scene was set up before it was refused: ${last_output}")
endif ()
foreach (never a b c d)
  if (EXISTS "${WORK}/${never}.vlf")
    message(FATAL_ERROR "${never}.vlf was written for bad input")
  endif ()
endforeach ()
