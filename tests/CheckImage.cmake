# SPDX-License-Identifier: BSD-3-Clause
# Runs a command that writes an image and checks the image, so that a blank, black or wrong
# picture fails where an exit code or "wrote" would pass: its size, its mean level per channel
# within TOLERANCE levels (of 255) of the reference's, and its spread (standard deviation, the
# mean of the channels') of at least MIN_STDDEV levels, read back with oiiotool --stats.
#
#   cmake -DCOMMAND_LINE="prog|arg|..." -DIMAGE=out.png -DSIZE=WxH -DMEAN="r g b"
#         -DTOLERANCE=levels -DMIN_STDDEV=levels [-DEXPECT_OUTPUT=regex] -DOIIOTOOL=path
#         -P CheckImage.cmake
#
# The reference means are the figures of a correct render (printed here on every run); the
# tolerance covers the renderers' noise and the drivers' rounding, far less than a blank or
# unlit image moves them.
foreach (_required IN ITEMS COMMAND_LINE IMAGE SIZE MEAN TOLERANCE MIN_STDDEV)
  if (NOT DEFINED ${_required})
    message(FATAL_ERROR "CheckImage.cmake: ${_required} is not set")
  endif ()
endforeach ()
if (NOT OIIOTOOL)
  message(FATAL_ERROR "oiiotool (openimageio-tools, scripts/install-deps.sh) is needed to check "
    "${IMAGE}")
endif ()

# An image left by an earlier run must not pass for this one's.
file(REMOVE "${IMAGE}")
string(REPLACE "|" ";" _command "${COMMAND_LINE}")
execute_process(COMMAND ${_command} RESULT_VARIABLE _rc OUTPUT_VARIABLE _out ERROR_VARIABLE _err)
message("${_out}${_err}")
if (NOT _rc EQUAL 0)
  message(FATAL_ERROR "'${_command}' failed (rc ${_rc})")
endif ()
if (DEFINED EXPECT_OUTPUT AND NOT "${_out}${_err}" MATCHES "${EXPECT_OUTPUT}")
  message(FATAL_ERROR "the output lacks '${EXPECT_OUTPUT}'")
endif ()
if (NOT EXISTS "${IMAGE}")
  message(FATAL_ERROR "no image ${IMAGE}")
endif ()

execute_process(COMMAND "${OIIOTOOL}" --stats "${IMAGE}"
  RESULT_VARIABLE _rc OUTPUT_VARIABLE _stats ERROR_VARIABLE _stats_err)
if (NOT _rc EQUAL 0)
  message(FATAL_ERROR "oiiotool cannot read ${IMAGE}: ${_stats_err}")
endif ()
if (NOT _stats MATCHES ": +([0-9]+) x +([0-9]+), ([0-9]+) channel")
  message(FATAL_ERROR "no size in oiiotool's stats of ${IMAGE}:\n${_stats}")
endif ()
set(_size "${CMAKE_MATCH_1}x${CMAKE_MATCH_2}")
if (NOT _size STREQUAL SIZE)
  message(FATAL_ERROR "${IMAGE} is ${_size}, expected ${SIZE}")
endif ()

# The first three channels' figures, truncated to whole levels (CMake's arithmetic is integer).
function (_check_image_levels what out)
  if (NOT _stats MATCHES "Stats ${what}: ([^\n(]*)")
    message(FATAL_ERROR "no '${what}' in oiiotool's stats of ${IMAGE}:\n${_stats}")
  endif ()
  string(STRIP "${CMAKE_MATCH_1}" _values)
  string(REGEX REPLACE " +" ";" _values "${_values}")
  list(SUBLIST _values 0 3 _values)
  set(_levels)
  foreach (_value IN LISTS _values)
    string(REGEX REPLACE "\\..*$" "" _value "${_value}")
    list(APPEND _levels "${_value}")
  endforeach ()
  set(${out} "${_levels}" PARENT_SCOPE)
endfunction ()
_check_image_levels(Avg _means)
_check_image_levels(StdDev _spreads)
message("${IMAGE}: ${_size}, mean levels ${_means} (reference ${MEAN} +- ${TOLERANCE}), "
  "standard deviations ${_spreads} (at least ${MIN_STDDEV} on average)")

string(REGEX REPLACE " +" ";" _reference "${MEAN}")
list(LENGTH _means _channels)
math(EXPR _last "${_channels} - 1")
set(_spread_sum 0)
foreach (_c RANGE ${_last})
  list(GET _means ${_c} _mean)
  list(GET _reference ${_c} _expected)
  list(GET _spreads ${_c} _spread)
  math(EXPR _difference "${_mean} - ${_expected}")
  if (_difference LESS 0)
    math(EXPR _difference "-${_difference}")
  endif ()
  if (_difference GREATER TOLERANCE)
    message(FATAL_ERROR "${IMAGE}: channel ${_c} mean level ${_mean}, expected ${_expected} "
      "+- ${TOLERANCE}")
  endif ()
  math(EXPR _spread_sum "${_spread_sum} + ${_spread}")
endforeach ()
math(EXPR _spread_mean "${_spread_sum} / ${_channels}")
if (_spread_mean LESS MIN_STDDEV)
  message(FATAL_ERROR "${IMAGE}: standard deviation ${_spread_mean} levels, at least "
    "${MIN_STDDEV} expected (a flat image)")
endif ()
