# SPDX-License-Identifier: BSD-3-Clause
# mesolight bake on a generated depth image: must write the relief texture, and must refuse to
# overwrite its own input.
file(REMOVE_RECURSE "${WORK}")
file(MAKE_DIRECTORY "${WORK}")
execute_process(COMMAND "${CLI}" render --offscreen --size 64x64 --resolution 32
                        --out "${WORK}/depth.png"
                RESULT_VARIABLE rc)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "could not make an input image (rc ${rc})")
endif ()
execute_process(COMMAND "${CLI}" bake "${WORK}/depth.png" --out "${WORK}/relief.exr"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0 OR NOT EXISTS "${WORK}/relief.exr")
  message(FATAL_ERROR "bake failed (rc ${rc}): ${out} ${err}")
endif ()
file(SIZE "${WORK}/depth.png" before)
execute_process(COMMAND "${CLI}" bake "${WORK}/depth.png" --out "${WORK}/depth.png"
                RESULT_VARIABLE rc)
file(SIZE "${WORK}/depth.png" after)
if (rc EQUAL 0 OR NOT before EQUAL after)
  message(FATAL_ERROR "bake overwrote its own input")
endif ()
execute_process(COMMAND "${CLI}" bake "${WORK}/garbage.png" --out "${WORK}/x.exr"
                RESULT_VARIABLE rc ERROR_VARIABLE err)
if (rc EQUAL 0)
  message(FATAL_ERROR "bake of a missing file succeeded")
endif ()
