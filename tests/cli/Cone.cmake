# SPDX-License-Identifier: BSD-3-Clause
# mesolight cone on a generated depth image writes a cone map and refuses to overwrite its input.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_depth_image(48x48)
foreach (type relaxed conservative)
  cli_run(TRUE cone "${WORK}/depth.png" --type ${type} --out "${WORK}/cone-${type}.exr")
  if (NOT EXISTS "${WORK}/cone-${type}.exr")
    message(FATAL_ERROR "cone ${type} wrote no cone map: ${last_output}")
  endif ()
endforeach ()
cli_expect_failure("cone overwrote its own input" cone "${WORK}/depth.png" --out "${WORK}/depth.png")
