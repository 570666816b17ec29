# SPDX-License-Identifier: BSD-3-Clause
# `mpiexec -n N mesolight vlf propagate`: the directions split over N ranks give the serial field
# (every texel of the total diffuse textures within 1e-5, compared by COMPARE, the distributed
# test program; the final gather split over the ranks too), a field resumes on another rank
# count to the same field, and a rank that fails (a scene it cannot read, a budget it refuses)
# stops every rank with that rank's message.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
set(MPI_RUN_TIMEOUT 30)
include("${CMAKE_CURRENT_LIST_DIR}/MpiRun.cmake")
set(small --directions 129 --rays 16)

cli_run(TRUE vlf propagate ${small} --iterations 3 --out "${WORK}/serial.vlf")
cli_run(TRUE vlf propagate ${small} --iterations 2 --out "${WORK}/two.vlf")
same_field("${WORK}/serial.vlf" "${WORK}/two.vlf" FALSE) # the comparison can fail
foreach (ranks IN ITEMS 2) # 3 ranks: the resume below
  mpi_run(TRUE -n ${ranks} "${CLI}" vlf propagate ${small} --iterations 3
    --out "${WORK}/ranks-${ranks}.vlf")
  if (NOT last_output MATCHES "split over ${ranks} MPI ranks")
    message(FATAL_ERROR "not distributed over ${ranks} ranks: ${last_output}")
  endif ()
  # Ranks on one machine split its cores (VTK_SMP_MAX_THREADS unset here).
  if (NOT DEFINED ENV{VTK_SMP_MAX_THREADS} AND NOT last_output MATCHES "[0-9]+ threads? per rank")
    message(FATAL_ERROR "no thread count per rank: ${last_output}")
  endif ()
  # The final gather (on by default) split over the ranks, the file the serial one's.
  if (NOT last_output MATCHES "final gather: [^\n]*split over ${ranks} ranks")
    message(FATAL_ERROR "the final gather was not split over ${ranks} ranks: ${last_output}")
  endif ()
  same_field("${WORK}/serial.vlf" "${WORK}/ranks-${ranks}.vlf" TRUE)
endforeach ()
# Written by 2 ranks, resumed by 3 (every rank reads it and keeps its share).
mpi_run(TRUE -n 2 "${CLI}" vlf propagate ${small} --iterations 2 --out "${WORK}/resumed.vlf")
mpi_run(TRUE -n 3 "${CLI}" vlf propagate --resume --iterations 3 --out "${WORK}/resumed.vlf")
if (NOT last_output MATCHES "final gather: [^\n]*split over 3 ranks")
  message(FATAL_ERROR "the resumed field's gather was not split over 3 ranks: ${last_output}")
endif ()
same_field("${WORK}/serial.vlf" "${WORK}/resumed.vlf" TRUE)
# One rank fails: every rank stops (no hang: the timeout), the message names the rank.
set(obj "${PROJECT_SOURCE_DIR}/examples/data/cornell-box.obj")
mpi_run(FALSE -n 1 "${CLI}" vlf propagate "${obj}" ${small} --out "${WORK}/bad.vlf"
  : -n 1 "${CLI}" vlf propagate "${WORK}/missing.obj" ${small} --out "${WORK}/bad.vlf")
if (NOT last_output MATCHES "rank 1 of 2: .*missing.obj")
  message(FATAL_ERROR "no message naming the failing rank and its scene: ${last_output}")
endif ()
# (128 x 128 rays: the small field is compact enough to fit the smallest budget, 1 MiB, and at
# 64 x 64 the half of the maps a rank holds nearly does.)
mpi_run(FALSE -n 1 "${CLI}" vlf propagate ${small} --out "${WORK}/budget.vlf"
  : -n 1 "${CLI}" vlf propagate --directions 129 --rays 128 --memory-budget 0.001
  --out "${WORK}/budget.vlf")
if (NOT last_output MATCHES "rank 1 of 2: .*memory budget")
  message(FATAL_ERROR "no memory budget message naming the rank: ${last_output}")
endif ()
# Mirrors: the mirrored radiance crosses to the owners of the mirrored directions; the field
# written by 2 ranks is the serial one.
set(mirror_obj "${PROJECT_SOURCE_DIR}/examples/data/cornell-box-mirror.obj")
cli_run(TRUE vlf propagate "${mirror_obj}" ${small} --iterations 3 --out "${WORK}/mirror-serial.vlf")
mpi_run(TRUE -n 2 "${CLI}" vlf propagate "${mirror_obj}" ${small} --iterations 3
  --out "${WORK}/mirror.vlf")
same_field("${WORK}/mirror-serial.vlf" "${WORK}/mirror.vlf" TRUE)
same_field("${WORK}/serial.vlf" "${WORK}/mirror.vlf" FALSE) # the mirror changes the field
# A usage error on one rank only (different options per rank) ends the job instead of leaving
# the others waiting.
mpi_run(FALSE -n 1 "${CLI}" vlf propagate ${small} --out "${WORK}/usage.vlf"
  : -n 1 "${CLI}" vlf propagate ${small} --memory-budget 0.00001 --out "${WORK}/usage.vlf")
