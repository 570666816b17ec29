# SPDX-License-Identifier: BSD-3-Clause
# mesolight cone on a generated depth image writes a cone map and refuses to overwrite its input.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_depth_image(48x48)
foreach (type relaxed conservative)
  execute_process(COMMAND "${CLI}" cone "${WORK}/depth.png" --type ${type}
                          --out "${WORK}/cone-${type}.exr"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/cone-${type}.exr")
    message(FATAL_ERROR "cone ${type} failed (rc ${rc}): ${out} ${err}")
  endif ()
endforeach ()
cli_expect_failure("cone overwrote its own input" cone "${WORK}/depth.png" --out "${WORK}/depth.png")
