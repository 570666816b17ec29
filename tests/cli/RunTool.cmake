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

# cli_elevation_maps(): elevation maps (DEMs) in ${WORK}, 64 x 64, written with OIIOTOOL:
#   metres.tif        a 16 / 64 m checker (float);
#   holes.tif         the same with holes at -9999 (the no-data value) in a coarser checker;
#   filled.tif        the same with the holes at the lowest ground, 16 m;
#   holes-tagged.tif  holes.tif naming -9999 as its no-data value (GDAL_NODATA), as GDAL writes;
#   metres-int16.tif  metres.tif as signed 16-bit metres.
# cli_oiiotool(<argument>...): runs OIIOTOOL; a failure fails the test with oiiotool's output.
function (cli_oiiotool)
  execute_process(COMMAND "${OIIOTOOL}" ${ARGN} RESULT_VARIABLE rc OUTPUT_VARIABLE out
    ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "oiiotool ${ARGN}: ${out}${err}")
  endif ()
endfunction ()
function (cli_elevation_maps)
  cli_oiiotool(--pattern checker:width=4:height=4:color1=64:color2=16 64x64 1 -d float
    -o "${WORK}/metres.tif")
  cli_oiiotool(--pattern checker:width=16:height=16:color1=1:color2=0 64x64 1 -d float
    -o "${WORK}/has.tif")
  cli_oiiotool("${WORK}/metres.tif" "${WORK}/has.tif" --mul -d float -o "${WORK}/kept.tif")
  cli_oiiotool("${WORK}/has.tif" --subc 1 --mulc 9999 "${WORK}/kept.tif" --add -d float
    -o "${WORK}/holes.tif")
  cli_oiiotool("${WORK}/has.tif" --subc 1 --mulc -16 "${WORK}/kept.tif" --add -d float
    -o "${WORK}/filled.tif")
  find_program(PYTHON3 NAMES python3 REQUIRED)
  execute_process(COMMAND "${PYTHON3}" "${CMAKE_CURRENT_FUNCTION_LIST_DIR}/AddGdalNoData.py"
    "${WORK}/holes.tif" "${WORK}/holes-tagged.tif" -9999 RESULT_VARIABLE rc ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "AddGdalNoData.py: ${err}")
  endif ()
  # OpenImageIO writes floats to int16 as fractions of 32767: 1 / 32767 keeps the metres.
  cli_oiiotool("${WORK}/metres.tif" --mulc 3.0518509475997192e-05 -d int16
    -o "${WORK}/metres-int16.tif")
endfunction ()
