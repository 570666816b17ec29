# SPDX-License-Identifier: BSD-3-Clause
# Shared by the CLI tests of the commands that read a depth image (bake, cone), included by them.

# An empty ${WORK} holding ${WORK}/depth.png, SIZE (WxH) pixels, rendered by `mesolight render`.
function (cli_depth_image size)
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")
  execute_process(COMMAND "${CLI}" render --offscreen --size ${size} --resolution 32
                          --out "${WORK}/depth.png" RESULT_VARIABLE rc OUTPUT_QUIET)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "could not make an input image (rc ${rc})")
  endif ()
endfunction ()

# Runs `mesolight ARGN`, which must fail; WHAT names the mistake in the message if it succeeds.
function (cli_expect_failure what)
  execute_process(COMMAND "${CLI}" ${ARGN} RESULT_VARIABLE rc OUTPUT_QUIET ERROR_QUIET)
  if (rc EQUAL 0)
    message(FATAL_ERROR "${what}")
  endif ()
endfunction ()
