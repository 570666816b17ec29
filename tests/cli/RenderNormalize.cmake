# SPDX-License-Identifier: BSD-3-Clause
# `render --normalize`: a depth file in metres (a 0 / 64 checker, as a DEM's elevations) is
# refused without it, with a message naming the option and no image; with it, the relief drawn
# is the one of the same map already in [0, 1] (a 0 / 1 checker) drawn without it, to the byte.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
foreach (top IN ITEMS 64 1)
  execute_process(COMMAND "${OIIOTOOL}" --pattern checker:width=8:height=8:color1=${top}:color2=0
    64x64 1 -d float -o "${WORK}/checker-${top}.tif" RESULT_VARIABLE rc ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "oiiotool could not write the checker: ${err}")
  endif ()
endforeach ()
set(scene render --offscreen --size 96x96 --height)
cli_expect_error(1 "mesolight: --normalize"
  ${scene} --depth-file "${WORK}/checker-64.tif" --out "${WORK}/never.png")
if (EXISTS "${WORK}/never.png")
  message(FATAL_ERROR "an image was written from a depth file outside [0, 1]")
endif ()
cli_run(TRUE ${scene} --depth-file "${WORK}/checker-64.tif" --normalize
  --out "${WORK}/metres.png")
cli_run(TRUE ${scene} --depth-file "${WORK}/checker-1.tif" --out "${WORK}/unit.png")
file(SHA256 "${WORK}/metres.png" metres)
file(SHA256 "${WORK}/unit.png" unit)
if (NOT metres STREQUAL unit)
  message(FATAL_ERROR "--normalize on the map in metres drew another relief than the unit map")
endif ()
# Not the flat map: the same unit map with --normalize off and --height off differs.
cli_run(TRUE render --offscreen --size 96x96 --depth-file "${WORK}/checker-1.tif"
  --out "${WORK}/depth.png")
file(SHA256 "${WORK}/depth.png" depth)
if (depth STREQUAL unit)
  message(FATAL_ERROR "--height changed nothing: the checker draws no relief")
endif ()
