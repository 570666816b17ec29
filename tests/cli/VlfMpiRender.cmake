# SPDX-License-Identifier: BSD-3-Clause
# `mpiexec -n N mesolight vlf render` of a scene with a mirror (examples/data/cornell-box-mirror.obj):
# the ranks split the rows and the field's directions, a mirror pixel is answered by the owners
# of the directions around its view. The linear image at 1, 2 and 3 ranks equals the serial
# render within float reduction order (oiiotool --diff, largest difference 1e-5 of radiance
# about 0.1-17); the render of a field one iteration short must differ (the comparison can fail).
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
include("${CMAKE_CURRENT_LIST_DIR}/MpiRun.cmake")
set(obj "${PROJECT_SOURCE_DIR}/examples/data/cornell-box-mirror.obj")
set(small --directions 129 --rays 16)
set(view --size 96x96)

cli_run(TRUE vlf propagate "${obj}" ${small} --iterations 3 --out "${WORK}/mirror.vlf")
cli_run(TRUE vlf propagate "${obj}" ${small} --iterations 2 --out "${WORK}/short.vlf")
cli_run(TRUE vlf render "${WORK}/mirror.vlf" ${view} --out "${WORK}/serial.png"
  --exr "${WORK}/serial.exr")
cli_run(TRUE vlf render "${WORK}/short.vlf" ${view} --out "${WORK}/short.png"
  --exr "${WORK}/short.exr")

function (same_image a b expect_same)
  execute_process(COMMAND "${OIIOTOOL}" --fail 1e-5 --warn 1e-5 "${a}" "${b}" --diff
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (expect_same AND NOT rc EQUAL 0)
    message(FATAL_ERROR "${a} and ${b} differ: ${out} ${err}")
  elseif (NOT expect_same AND rc EQUAL 0)
    message(FATAL_ERROR "${a} and ${b} compare equal, which they are not: ${out}")
  endif ()
endfunction ()

same_image("${WORK}/serial.exr" "${WORK}/short.exr" FALSE)
foreach (ranks IN ITEMS 1 2 3)
  execute_process(COMMAND "${MPIEXEC}" -n ${ranks} "${CLI}" vlf render "${WORK}/mirror.vlf"
      ${view} --out "${WORK}/ranks-${ranks}.png" --exr "${WORK}/ranks-${ranks}.exr"
    RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err TIMEOUT 60)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "vlf render on ${ranks} rank(s) failed (${rc}): ${out} ${err}")
  endif ()
  if (NOT out MATCHES "MPI: ${ranks} ranks, .* [1-9][0-9]* mirror pixels")
    message(FATAL_ERROR "not rendered over ${ranks} rank(s), or no mirror seen: ${out}")
  endif ()
  same_image("${WORK}/serial.exr" "${WORK}/ranks-${ranks}.exr" TRUE)
endforeach ()
