# SPDX-License-Identifier: BSD-3-Clause
# `mesolight render --geometry-image` of images with no usable triangle in single precision (a
# constant image, collinear positions, a plane scaled by 1e-30 or 1e30) printed "N triangles" and
# rendered background only with exit 0: now a clear error naming the cause, and no image.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
if (NOT OIIOTOOL)
  message(STATUS "oiiotool not found: nothing to replay")
  return ()
endif ()
cli_fresh_work()
set(common --offscreen --size 64x64 --resolution 32 --stride 4)
set(images
  "constant|constant:color=0.5,0.5,0.5|all its positions are the same point"
  "line|fill:left=0,0,0:right=1,1,1|its positions are collinear"
  "tiny|fill:topleft=0,0,0:topright=1e-30,0,0:bottomleft=0,1e-30,0:bottomright=1e-30,1e-30,0|too small"
  "huge|fill:topleft=0,0,0:topright=1e30,0,0:bottomleft=0,1e30,0:bottomright=1e30,1e30,0|too large")
foreach (entry IN LISTS images)
  string(REPLACE "|" ";" entry "${entry}")
  list(GET entry 0 name)
  list(GET entry 1 pattern)
  list(GET entry 2 needle)
  execute_process(COMMAND "${OIIOTOOL}" --pattern ${pattern} 16x16 3 -d float -o "${WORK}/${name}.exr"
    RESULT_VARIABLE rc)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "oiiotool could not write ${name}.exr")
  endif ()
  cli_expect_error(1 "Cannot mesh the geometry image: every triangle has zero or non-finite area"
    render ${common} --geometry-image "${WORK}/${name}.exr" --out "${WORK}/${name}.png")
  string(FIND "${last_stderr}" "${needle}" at)
  if (at EQUAL -1 OR EXISTS "${WORK}/${name}.png")
    message(FATAL_ERROR "${name}.exr: expected '${needle}' and no image: ${last_stderr}")
  endif ()
endforeach ()
