# SPDX-License-Identifier: BSD-3-Clause
# mesolight bake on a generated depth image: must write the relief texture, and must refuse to
# overwrite its own input.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_depth_image(64x64)
cli_run(TRUE bake "${WORK}/depth.png" --out "${WORK}/relief.exr")
if (NOT EXISTS "${WORK}/relief.exr")
  message(FATAL_ERROR "bake wrote no relief texture: ${last_output}")
endif ()
file(SIZE "${WORK}/depth.png" before)
cli_expect_failure("bake overwrote its own input"
  bake "${WORK}/depth.png" --out "${WORK}/depth.png")
file(SIZE "${WORK}/depth.png" after)
if (NOT before EQUAL after)
  message(FATAL_ERROR "bake overwrote its own input")
endif ()
cli_expect_failure("bake of a missing file succeeded" bake "${WORK}/garbage.png" --out "${WORK}/x.exr")
