# SPDX-License-Identifier: BSD-3-Clause
# Running the tool from a test script, written once: every script of tests/cli includes this
# file. mesolight_cli_test(... SCRIPT <file>) gives the script CLI (the tool) and WORK (its own
# directory under the build's Testing/Temporary/cli).

# cli_fresh_work(): an empty ${WORK}.
function (cli_fresh_work)
  file(REMOVE_RECURSE "${WORK}")
  file(MAKE_DIRECTORY "${WORK}")
endfunction ()

# cli_execute(<argument>...): runs `mesolight <argument>...`, checks nothing; sets cli_rc (the
# exit code, or a signal's name after a crash), cli_stdout and cli_stderr.
function (cli_execute)
  execute_process(COMMAND "${CLI}" ${ARGN}
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  set(cli_rc "${rc}" PARENT_SCOPE)
  set(cli_stdout "${out}" PARENT_SCOPE)
  set(cli_stderr "${err}" PARENT_SCOPE)
endfunction ()

# cli_run(<expect success: TRUE|FALSE> <argument>...): runs the tool; fails the test if it
# succeeded when it should have failed, or failed when it should have succeeded. Sets last_output
# (stdout then stderr).
function (cli_run expect_success)
  cli_execute(${ARGN})
  if (expect_success AND NOT cli_rc EQUAL 0)
    message(FATAL_ERROR "'${ARGN}' failed (rc ${cli_rc}): ${cli_stdout} ${cli_stderr}")
  elseif (NOT expect_success AND cli_rc EQUAL 0)
    message(FATAL_ERROR "'${ARGN}' was accepted: ${cli_stdout} ${cli_stderr}")
  endif ()
  set(last_output "${cli_stdout}${cli_stderr}" PARENT_SCOPE)
endfunction ()

# cli_expect_failure(<what> <argument>...): runs the tool, which must fail; WHAT names the mistake
# in the message if it succeeds.
function (cli_expect_failure what)
  cli_execute(${ARGN})
  if (cli_rc EQUAL 0)
    message(FATAL_ERROR "${what}")
  endif ()
endfunction ()

# cli_expect(<code> <needle> <argument>...): the exit code must be exactly CODE (a crash is a
# signal's name, not a number) and stdout + stderr must contain NEEDLE.
# cli_expect_error(<code> <needle> <argument>...): the same, NEEDLE in stderr.
# Both set last_stdout and last_stderr.
function (_cli_expect stream code needle)
  cli_execute(${ARGN})
  if (NOT "${cli_rc}" STREQUAL "${code}")
    message(FATAL_ERROR
      "mesolight ${ARGN}: exit '${cli_rc}', expected ${code}\n${cli_stdout}\n${cli_stderr}")
  endif ()
  if (stream STREQUAL "stderr")
    string(FIND "${cli_stderr}" "${needle}" at)
    if (at EQUAL -1)
      message(FATAL_ERROR "mesolight ${ARGN}: stderr lacks '${needle}':\n${cli_stderr}")
    endif ()
  else ()
    string(FIND "${cli_stdout}${cli_stderr}" "${needle}" at)
    if (at EQUAL -1)
      message(FATAL_ERROR
        "mesolight ${ARGN}: output lacks '${needle}':\n${cli_stdout}\n${cli_stderr}")
    endif ()
  endif ()
  set(last_stdout "${cli_stdout}" PARENT_SCOPE)
  set(last_stderr "${cli_stderr}" PARENT_SCOPE)
endfunction ()
function (cli_expect code needle)
  _cli_expect(output "${code}" "${needle}" ${ARGN})
  set(last_stdout "${last_stdout}" PARENT_SCOPE)
  set(last_stderr "${last_stderr}" PARENT_SCOPE)
endfunction ()
function (cli_expect_error code needle)
  _cli_expect(stderr "${code}" "${needle}" ${ARGN})
  set(last_stdout "${last_stdout}" PARENT_SCOPE)
  set(last_stderr "${last_stderr}" PARENT_SCOPE)
endfunction ()

# cli_depth_image(<size>): an empty ${WORK} holding ${WORK}/depth.png, SIZE (WxH) pixels, rendered
# by `mesolight render` (the input of the commands that read a depth image: bake, cone).
function (cli_depth_image size)
  cli_fresh_work()
  cli_execute(render --offscreen --size ${size} --resolution 32 --out "${WORK}/depth.png")
  if (NOT cli_rc EQUAL 0)
    message(FATAL_ERROR "could not make an input image (rc ${cli_rc}): ${cli_stderr}")
  endif ()
endfunction ()

# An EXR's figure of `oiiotool --stats` (Avg or Max, first channel) in thousandths.
function (exr_stat_milli image what out)
  execute_process(COMMAND "${OIIOTOOL}" --stats "${image}"
    RESULT_VARIABLE rc OUTPUT_VARIABLE stats ERROR_VARIABLE err)
  if (NOT rc EQUAL 0 OR NOT stats MATCHES "Stats ${what}: +([0-9]+)\\.([0-9]+)")
    message(FATAL_ERROR "oiiotool cannot read ${image}: ${err}${stats}")
  endif ()
  string(SUBSTRING "${CMAKE_MATCH_2}000" 0 3 fraction)
  math(EXPR milli "${CMAKE_MATCH_1} * 1000 + 1${fraction} - 1000")
  set(${out} ${milli} PARENT_SCOPE)
endfunction ()
