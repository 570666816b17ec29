# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench vlf-relief`: a relief lit by a small light field against the path-traced dense
# mesh of the same relief (`trace --relief ... --relief-mask`), end to end at small sizes. The
# run prints the relief's pixel count, the five renderings' errors and the cost ratio, and
# writes one CSV row per rendering; the negative case without indirect light (one-light) must
# be worse than the field even at these settings (the comparison can fail); bad input is refused.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

cli_run(TRUE vlf propagate --directions 129 --rays 16 --iterations 3 --out "${WORK}/box.vlf")
# Vertical grooves: every other 4 columns at depth 1.
set(_grooves "P2\n8 8\n255\n")
foreach (_row RANGE 7)
  string(APPEND _grooves "0 0 0 0 255 255 255 255\n")
endforeach ()
file(WRITE "${WORK}/grooves.pgm" "${_grooves}")
set(_relief --relief "back=${WORK}/grooves.pgm" --relief-depth-scale 0.1)
set(_view --camera 278,273,-800,278,273,0 --fov 39.3077)
cli_expect(0 "relief coverage per pixel" trace --scene cornell ${_relief} ${_view} --width 32
  --height 32 --samples 16 --offscreen --out "${WORK}/ref.png" --exr "${WORK}/ref.exr"
  --relief-mask "${WORK}/mask.exr")

# Coarse settings may miss the goal (exit 1); the figures must be there either way.
cli_execute(bench vlf-relief "${WORK}/box.vlf" ${_relief} ${_view} --reference "${WORK}/ref.exr"
  --mask "${WORK}/mask.exr" --csv "${WORK}/rows.csv")
if (NOT (cli_rc EQUAL 0 OR cli_rc EQUAL 1))
  message(FATAL_ERROR "bench vlf-relief failed (rc ${cli_rc}): ${cli_stdout}${cli_stderr}")
endif ()
message("${cli_stdout}")
if (NOT cli_stdout MATCHES "relief pixels: ([0-9]+)" OR CMAKE_MATCH_1 LESS 20)
  message(FATAL_ERROR "too few relief pixels measured: ${cli_stdout}")
endif ()
if (NOT cli_stdout MATCHES "cost: a relief pixel lit by the field / by one light")
  message(FATAL_ERROR "no cost ratio: ${cli_stdout}")
endif ()
file(STRINGS "${WORK}/rows.csv" _rows)
list(LENGTH _rows _count)
if (NOT _count EQUAL 9)
  message(FATAL_ERROR "expected a header and 8 rows in rows.csv (field, flat-wall, one-light, "
    "field-unoccluded, three inter-reflection models, flat-normal), got ${_count}: ${_rows}")
endif ()
# mean_relative_error (4th column) of field and one-light, in thousandths.
foreach (_row IN LISTS _rows)
  string(REPLACE "," ";" _cells "${_row}")
  list(GET _cells 1 _name)
  list(GET _cells 3 _error)
  if (_name STREQUAL "field" OR _name STREQUAL "one-light")
    math(EXPR _milli "0")
    if (_error MATCHES "^([0-9]+)\\.?([0-9]*)")
      string(SUBSTRING "${CMAKE_MATCH_2}000" 0 3 _fraction)
      math(EXPR _milli "${CMAKE_MATCH_1} * 1000 + 1${_fraction} - 1000")
    endif ()
    set(_error_${_name} ${_milli})
  endif ()
endforeach ()
if (NOT _error_field LESS _error_one-light)
  message(FATAL_ERROR "one light without indirect light (${_error_one-light}/1000) is not worse "
    "than the field (${_error_field}/1000)")
endif ()

# Bad input: a FIELD without --relief, a mask of another size.
cli_expect_error(2 "FIELD and --relief" bench vlf-relief "${WORK}/box.vlf"
  --reference "${WORK}/ref.exr" --mask "${WORK}/mask.exr")
cli_run(TRUE trace --scene cornell ${_relief} ${_view} --width 16 --height 16 --samples 1
  --offscreen --out "${WORK}/small.png" --relief-mask "${WORK}/small-mask.exr")
cli_expect_error(1 "differ in size" bench vlf-relief "${WORK}/box.vlf" ${_relief} ${_view}
  --reference "${WORK}/ref.exr" --mask "${WORK}/small-mask.exr")
