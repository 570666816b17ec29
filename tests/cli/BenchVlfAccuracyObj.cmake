# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench vlf-accuracy --write-obj DIR`: the boxes scene written as OBJ + MTL reads back
# as the scene the benchmark measures. Read by the tool's reader (vtkOBJSceneReader, through
# ObjSceneFigures.py), its triangles, emitting triangles, area and emitted power are the ones the
# command printed for the scene it generated; `vlf propagate` on the file builds a field of as
# many surfaces and texels as the benchmark's own field of the same settings (its CSV).
# Negative: the file with its lamp's material swapped for the white boxes' (the power), or one
# face fewer (the count and area), fails the same check. Existing files are kept; bad --scenes.
cmake_minimum_required(VERSION 3.16)
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
set(ENV{MESOLIGHT_BUILD_DIR} "${BUILD}")

cli_run(TRUE bench vlf-accuracy --scenes boxes --write-obj "${WORK}/scenes")
set(_number "[0-9.e+-]+")
if (NOT last_output MATCHES
    "wrote [^\n]*boxes.obj and boxes.mtl: ([0-9]+) triangles \\(([0-9]+) emitting\\), area (${_number}), emitted power (${_number},${_number},${_number})")
  message(FATAL_ERROR "no figures of the written scene: ${last_output}")
endif ()
set(_figures ${CMAKE_MATCH_1} ${CMAKE_MATCH_2} ${CMAKE_MATCH_3} ${CMAKE_MATCH_4})
message("generated: ${_figures}")
if (NOT CMAKE_MATCH_1 EQUAL 9004)
  message(FATAL_ERROR "the boxes scene has 9004 triangles, not ${CMAKE_MATCH_1}")
endif ()

# ObjSceneFigures.py FILE: 0 when FILE's figures are the generated scene's.
function (figures_of file result)
  execute_process(COMMAND bash "${PYTHON_SH}" "${CMAKE_CURRENT_LIST_DIR}/ObjSceneFigures.py"
    "${file}" ${_figures} RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  message("${out}")
  if (NOT out MATCHES "SAME|DIFFERENT")
    message(FATAL_ERROR "ObjSceneFigures.py did not compare ${file}: ${out}${err}")
  endif ()
  set(${result} ${rc} PARENT_SCOPE)
endfunction ()
figures_of("${WORK}/scenes/boxes.obj" _rc)
if (NOT _rc EQUAL 0)
  message(FATAL_ERROR "the written boxes scene does not read back as the generated one")
endif ()

# Negative cases.
file(READ "${WORK}/scenes/boxes.obj" _obj)
string(REPLACE "usemtl lamp" "usemtl white" _unlit "${_obj}")
file(WRITE "${WORK}/scenes/unlit.obj" "${_unlit}")
string(REGEX REPLACE "\nf [^\n]*\n$" "\n" _short "${_obj}")
file(WRITE "${WORK}/scenes/short.obj" "${_short}")
foreach (_wrong IN ITEMS unlit short)
  figures_of("${WORK}/scenes/${_wrong}.obj" _rc)
  if (_rc EQUAL 0)
    message(FATAL_ERROR "the check passes ${_wrong}.obj: it cannot fail")
  endif ()
endforeach ()

# The light field's surfaces: the benchmark's own field of the scene against vlf propagate's of
# the file, same settings.
cli_run(TRUE bench vlf-accuracy --scenes boxes --settings 33x8 --variants none --size 8x8
  --samples 2 --cache "${WORK}/cache" --csv "${WORK}/boxes.csv")
file(STRINGS "${WORK}/boxes.csv" _lines)
list(GET _lines 1 _row)
string(REPLACE "," ";" _row "${_row}")
list(GET _row 7 _surfaces)
list(GET _row 8 _texels)
cli_run(TRUE vlf propagate "${WORK}/scenes/boxes.obj" --directions 33 --rays 8 --iterations 1
  --no-gather --out "${WORK}/boxes.vlf")
if (NOT last_output MATCHES "([0-9]+) surfaces with ([0-9]+) texels")
  message(FATAL_ERROR "vlf propagate printed no surfaces: ${last_output}")
endif ()
message("light field surfaces / texels: benchmark ${_surfaces} / ${_texels}, "
  "from the OBJ ${CMAKE_MATCH_1} / ${CMAKE_MATCH_2}")
if (NOT CMAKE_MATCH_1 EQUAL _surfaces OR NOT CMAKE_MATCH_2 EQUAL _texels)
  message(FATAL_ERROR "vlf propagate sees another scene in the written OBJ")
endif ()

# Existing files are kept; an unknown scene is refused before anything is written.
cli_expect_error(1 "exists; not overwritten" bench vlf-accuracy --scenes boxes
  --write-obj "${WORK}/scenes")
cli_expect_error(2 "unknown scene 'attic'" bench vlf-accuracy --scenes thin,attic
  --write-obj "${WORK}/more")
if (EXISTS "${WORK}/more/thin.obj")
  message(FATAL_ERROR "a scene was written before the unknown one was refused")
endif ()
