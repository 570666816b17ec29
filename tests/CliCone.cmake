# SPDX-License-Identifier: BSD-3-Clause
# mesolight cone on a generated depth image writes a cone map and refuses to overwrite its input.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${CLI}" render --offscreen --size 48x48 --resolution 32
                        --out "${WORK}/depth.png" RESULT_VARIABLE rc OUTPUT_QUIET)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "could not make an input image")
endif ()
foreach (type relaxed conservative)
  execute_process(COMMAND "${CLI}" cone "${WORK}/depth.png" --type ${type}
                          --out "${WORK}/cone-${type}.exr"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/cone-${type}.exr")
    message(FATAL_ERROR "cone ${type} failed (rc ${rc}): ${out} ${err}")
  endif ()
endforeach ()
execute_process(COMMAND "${CLI}" cone "${WORK}/depth.png" --out "${WORK}/depth.png"
                RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
if (rc EQUAL 0)
  message(FATAL_ERROR "cone overwrote its own input")
endif ()
