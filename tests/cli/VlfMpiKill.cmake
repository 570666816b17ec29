# SPDX-License-Identifier: BSD-3-Clause
# A distributed `mesolight vlf propagate` killed with SIGKILL -- one rank, or every rank -- right
# after the snapshot of iteration 2 is on disk (MESOLIGHT_TEST_KILL_AFTER, VlfPropagateCommand.cxx:
# a known point, so the test is deterministic): mpiexec ends the job (no hang: every run has a
# timeout), the file holds the complete iteration 2, and resuming it on the same or another rank
# count gives the field of an uninterrupted run (every texel within 1e-5, compared by COMPARE).
# A writer killed in the middle of a write leaves FIELD.tmp-PID behind and FIELD whole: a
# truncated temporary is never read, and a truncated FIELD is refused by every rank. With
# --snapshot-every 2 a run killed after iteration 3 resumes from iteration 2.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
include("${CMAKE_CURRENT_LIST_DIR}/MpiRun.cmake")
set(ENV{VTK_SMP_MAX_THREADS} 1) # up to 3 ranks on 2 cores: one thread each
set(small --directions 129 --rays 16)

# Killed after iteration 2: the job fails, mpiexec names the killed process, FIELD holds
# iteration 2 (the last line printed is iteration 2's, nothing of iteration 3 reached the file).
function (killed_run ranks who field)
  set(ENV{MESOLIGHT_TEST_KILL_AFTER} "2:${who}")
  mpi_run(FALSE -n ${ranks} "${CLI}" vlf propagate ${small} --iterations 4 --out "${field}")
  unset(ENV{MESOLIGHT_TEST_KILL_AFTER})
  if (NOT last_output MATCHES "iteration 2: ")
    message(FATAL_ERROR "iteration 2 was not written before the kill: ${last_output}")
  endif ()
  if (last_output MATCHES "iteration 3: ")
    message(FATAL_ERROR "iteration 3 completed although a rank was killed: ${last_output}")
  endif ()
  if (NOT last_output MATCHES "signal 9|Killed|killed")
    message(FATAL_ERROR "mpiexec did not report the killed rank: ${last_output}")
  endif ()
  message(STATUS "${ranks} ranks, killed ${who}: ${last_output}")
endfunction ()

# Resumes a copy of FIELD on RANKS ranks to 4 iterations; it must equal the uninterrupted run.
function (resume_equals field ranks name)
  file(COPY_FILE "${field}" "${WORK}/${name}")
  mpi_run(TRUE -n ${ranks} "${CLI}" vlf propagate --resume --iterations 4 --out "${WORK}/${name}")
  if (NOT last_output MATCHES "after 2 iterations")
    message(FATAL_ERROR "the killed run's file did not hold iteration 2: ${last_output}")
  endif ()
  same_field("${WORK}/straight.vlf" "${WORK}/${name}" TRUE)
endfunction ()

# The uninterrupted reference (one process), and a field one iteration short, which must differ.
cli_run(TRUE vlf propagate ${small} --iterations 4 --out "${WORK}/straight.vlf")
cli_run(TRUE vlf propagate ${small} --iterations 3 --out "${WORK}/short.vlf")
same_field("${WORK}/straight.vlf" "${WORK}/short.vlf" FALSE)

# One rank of two killed (the other is inside iteration 3, waiting in its sum): resumed on 2 and 3.
killed_run(2 1 "${WORK}/one.vlf")
resume_equals("${WORK}/one.vlf" 2 one-on-2.vlf)
resume_equals("${WORK}/one.vlf" 3 one-on-3.vlf)
# Rank 0, the writer, killed: the same.
killed_run(3 0 "${WORK}/writer.vlf")
resume_equals("${WORK}/writer.vlf" 3 writer-on-3.vlf)
# Every rank of three killed: resumed on 3, on 2 and on one process.
killed_run(3 all "${WORK}/all.vlf")
resume_equals("${WORK}/all.vlf" 3 all-on-3.vlf)
resume_equals("${WORK}/all.vlf" 2 all-on-2.vlf)
file(COPY_FILE "${WORK}/all.vlf" "${WORK}/all-on-1.vlf")
cli_run(TRUE vlf propagate --resume --iterations 4 --out "${WORK}/all-on-1.vlf")
same_field("${WORK}/straight.vlf" "${WORK}/all-on-1.vlf" TRUE)

# With --snapshot-every 2, every rank killed after iteration 3 (not written): FIELD holds
# iteration 2, and resumes from it to the same field.
set(ENV{MESOLIGHT_TEST_KILL_AFTER} "3:all")
mpi_run(FALSE -n 2 "${CLI}" vlf propagate ${small} --iterations 4 --snapshot-every 2
  --out "${WORK}/every.vlf")
unset(ENV{MESOLIGHT_TEST_KILL_AFTER})
if (NOT last_output MATCHES "iteration 3: [^\n]*not written")
  message(FATAL_ERROR "iteration 3 was written although --snapshot-every 2: ${last_output}")
endif ()
resume_equals("${WORK}/every.vlf" 3 every-on-3.vlf)

# A writer killed during its write: FIELD.tmp-PID is a truncated snapshot (of iteration 3 here),
# FIELD the complete previous one. Resuming reads FIELD (iteration 2) and removes the dead
# writer's temporary.
file(SIZE "${WORK}/short.vlf" size)
math(EXPR half "${size} / 2")
file(COPY_FILE "${WORK}/all.vlf" "${WORK}/partial.vlf")
set(temporary "${WORK}/partial.vlf.tmp-999999999")
execute_process(COMMAND head -c ${half} "${WORK}/short.vlf" OUTPUT_FILE "${temporary}")
resume_equals("${WORK}/partial.vlf" 2 partial-on-2.vlf)
file(COPY_FILE "${temporary}" "${WORK}/partial-on-2.vlf.tmp-999999999")
mpi_run(TRUE -n 2 "${CLI}" vlf propagate --resume --iterations 5 --out "${WORK}/partial-on-2.vlf")
if (EXISTS "${WORK}/partial-on-2.vlf.tmp-999999999")
  message(FATAL_ERROR "the dead writer's temporary file was left behind")
endif ()
# A truncated FIELD itself (copied by hand, say) is refused on every rank, clearly, no hang.
execute_process(COMMAND head -c ${half} "${WORK}/short.vlf" OUTPUT_FILE "${WORK}/truncated.vlf")
mpi_run(FALSE -n 2 "${CLI}" vlf propagate --resume --iterations 4 --out "${WORK}/truncated.vlf")
if (NOT last_output MATCHES "truncated")
  message(FATAL_ERROR "a truncated snapshot was not named as such: ${last_output}")
endif ()
