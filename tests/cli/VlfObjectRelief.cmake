# SPDX-License-Identifier: BSD-3-Clause
# `vlf render --mode progressive --object cube|FILE.obj --object-relief DEPTH_IMAGE`: the movable
# object drawn as relief charts lit by the field (application/LightFieldObjectRelief.h). Against
# the same run without the relief: the object's pixels differ, and its shadow on the floor is
# unchanged (the shadow is the object's macro geometry): at every pixel the shadow darkens (the
# run with --shadows field against --shadows none), the relief run equals the flat one. The
# negative case, the run without shadows, fails that check. An OBJ box whose faces each map the
# texture square gives six charts; the viewer's frames regather the probes when the object moves;
# bad input (no texture coordinates, an unreadable depth image, options without their object)
# exits 2 with a message.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

cli_run(TRUE vlf propagate --directions 129 --rays 16 --iterations 3 --out "${WORK}/box.vlf")
# Horizontal grooves, 4 rows deep and 4 rows flat, 32 x 32 (ASCII PGM).
set(_grooves "P2\n32 32\n255\n")
foreach (_row RANGE 31)
  math(EXPR _band "(${_row} / 4) % 2")
  if (_band)
    string(REPEAT "255 " 32 _line)
  else ()
    string(REPEAT "0 " 32 _line)
  endif ()
  string(APPEND _grooves "${_line}\n")
endforeach ()
file(WRITE "${WORK}/grooves.pgm" "${_grooves}")

# A 80 mm cube above the floor, clear of the blocks, below and in front of the light.
set(_object --object cube --object-transform 400,120,120,0,30,0,80 --size 160x160 --mode progressive)
cli_run(TRUE vlf render "${WORK}/box.vlf" ${_object} --out "${WORK}/flat.png")
cli_run(TRUE vlf render "${WORK}/box.vlf" ${_object} --object-relief "${WORK}/grooves.pgm"
  --object-relief-depth-scale 0.1 --out "${WORK}/relief.png")
if (NOT last_output MATCHES "object relief: .*grooves.pgm, 6 charts, 384 probes \\(8 a side\\)")
  message(FATAL_ERROR "the relief run does not report the cube's six charts: ${last_output}")
endif ()
cli_run(TRUE vlf render "${WORK}/box.vlf" ${_object} --shadows none --out "${WORK}/unshadowed.png")

# oiiotool's largest and mean value of the first channel (of 255) of A op B.
function (image_op a b op out_max out_avg)
  execute_process(COMMAND "${OIIOTOOL}" "${a}" "${b}" ${op} -o "${WORK}/op.png"
    RESULT_VARIABLE rc ERROR_VARIABLE err)
  execute_process(COMMAND "${OIIOTOOL}" --stats "${WORK}/op.png"
    RESULT_VARIABLE rc2 OUTPUT_VARIABLE stats ERROR_VARIABLE err2)
  if (NOT rc EQUAL 0 OR NOT rc2 EQUAL 0 OR NOT stats MATCHES "Stats Max: +([0-9]+)")
    message(FATAL_ERROR "oiiotool cannot compare ${a} and ${b}: ${err}${err2}${stats}")
  endif ()
  set(${out_max} ${CMAKE_MATCH_1} PARENT_SCOPE)
  if (NOT stats MATCHES "Stats Avg: +([0-9]+)\\.([0-9]+)")
    message(FATAL_ERROR "no mean in ${stats}")
  endif ()
  set(${out_avg} "${CMAKE_MATCH_1}.${CMAKE_MATCH_2}" PARENT_SCOPE)
endfunction ()

image_op("${WORK}/flat.png" "${WORK}/unshadowed.png" --absdiff _shadow_max _shadow_avg)
file(COPY_FILE "${WORK}/op.png" "${WORK}/shadow.png")
image_op("${WORK}/flat.png" "${WORK}/relief.png" --absdiff _object_max _object_avg)
file(COPY_FILE "${WORK}/op.png" "${WORK}/object.png")
message("shadow: largest ${_shadow_max}, mean ${_shadow_avg}; relief against flat: largest "
  "${_object_max}, mean ${_object_avg} (of 255)")
if (_shadow_max LESS 10)
  message(FATAL_ERROR "the object casts no visible shadow here: the check below would be empty")
endif ()
if (_object_max LESS 20)
  message(FATAL_ERROR "the relief object looks like the flat one (largest difference ${_object_max})")
endif ()
# Where the shadow darkens the scene, the relief run is the flat run: shadow x difference is 0.
image_op("${WORK}/shadow.png" "${WORK}/object.png" --mul _masked_max _masked_avg)
if (NOT _masked_max EQUAL 0)
  message(FATAL_ERROR "the relief changed the object's shadow (largest masked difference "
    "${_masked_max})")
endif ()
# Negative: an image without the shadow fails the same check.
image_op("${WORK}/relief.png" "${WORK}/unshadowed.png" --absdiff _unused_max _unused_avg)
image_op("${WORK}/shadow.png" "${WORK}/op.png" --mul _negative_max _negative_avg)
if (_negative_max EQUAL 0)
  message(FATAL_ERROR "the shadow check does not see a missing shadow")
endif ()

# An OBJ box whose six faces each map the texture square ("a brick-textured box"): six charts.
file(WRITE "${WORK}/box.obj" "v -0.5 -0.5 -0.5\nv 0.5 -0.5 -0.5\nv 0.5 0.5 -0.5\nv -0.5 0.5 -0.5\n"
  "v -0.5 -0.5 0.5\nv 0.5 -0.5 0.5\nv 0.5 0.5 0.5\nv -0.5 0.5 0.5\n"
  "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n"
  "f 1/1 4/2 3/3\nf 1/1 3/3 2/4\nf 5/1 6/2 7/3\nf 5/1 7/3 8/4\n"
  "f 1/1 2/2 6/3\nf 1/1 6/3 5/4\nf 4/1 8/2 7/3\nf 4/1 7/3 3/4\n"
  "f 1/1 5/2 8/3\nf 1/1 8/3 4/4\nf 2/1 3/2 7/3\nf 2/1 7/3 6/4\n")
cli_run(TRUE vlf render "${WORK}/box.vlf" --object "${WORK}/box.obj"
  --object-transform 400,120,120,0,30,0,80 --size 96x96 --mode coherent
  --object-relief "${WORK}/grooves.pgm" --out "${WORK}/obj.png")
if (NOT last_output MATCHES "6 charts, 384 probes")
  message(FATAL_ERROR "the OBJ box is not six charts: ${last_output}")
endif ()

# The viewer's frames along a path: the probes are regathered when the object moves (the first
# placement is the one set up, gathered before the first frame).
file(WRITE "${WORK}/path.csv" "400,120,120,0,30,0,80\n380,120,140,0,40,0,80\n360,130,160,0,50,0,80\n")
cli_run(TRUE vlf view "${WORK}/box.vlf" --frames 3 --offscreen ${_object}
  --object-relief "${WORK}/grooves.pgm" --path "${WORK}/path.csv")
if (NOT last_output MATCHES "relief probes: 384 in 6 charts, regathered in 2 frames")
  message(FATAL_ERROR "the viewer does not regather the probes per move: ${last_output}")
endif ()

# A drag that starts on the relief (its charts stand in for the hidden object) moves the object.
cli_run(TRUE vlf view "${WORK}/box.vlf" --frames 3 --offscreen ${_object}
  --object-relief "${WORK}/grooves.pgm" --drag 20,0)
if (NOT last_output MATCHES "moved in 1 of 3 frames" OR NOT last_output MATCHES "regathered in 1 frames")
  message(FATAL_ERROR "a drag on the relief did not move the object: ${last_output}")
endif ()

# Bad input.
set(_bad --mode progressive --size 32x32)
cli_expect_error(2 "has no texture coordinates" vlf render "${WORK}/box.vlf" ${_bad} --object sphere
  --object-relief "${WORK}/grooves.pgm" --out "${WORK}/never.png")
file(WRITE "${WORK}/tetra.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\nf 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n")
cli_expect_error(2 "'vt' coordinate on every face corner" vlf render "${WORK}/box.vlf" ${_bad}
  --object "${WORK}/tetra.obj" --object-relief "${WORK}/grooves.pgm" --out "${WORK}/never.png")
cli_expect_error(2 "cannot read the depth image" vlf render "${WORK}/box.vlf" ${_bad} --object cube
  --object-relief "${WORK}/missing.png" --out "${WORK}/never.png")
file(WRITE "${WORK}/notanimage.png" "this is not an image\n")
cli_expect_error(2 "cannot read the depth image" vlf render "${WORK}/box.vlf" ${_bad} --object cube
  --object-relief "${WORK}/notanimage.png" --out "${WORK}/never.png")
cli_expect_error(2 "--object-relief needs --object" vlf render "${WORK}/box.vlf" ${_bad}
  --object-relief "${WORK}/grooves.pgm" --out "${WORK}/never.png")
cli_expect_error(2 "--object-relief-depth-scale needs --object-relief" vlf render
  "${WORK}/box.vlf" ${_bad} --object cube --object-relief-depth-scale 0.1 --out "${WORK}/never.png")
cli_expect_error(2 "--object-relief-depth-scale" vlf render "${WORK}/box.vlf" ${_bad} --object cube
  --object-relief "${WORK}/grooves.pgm" --object-relief-depth-scale -1 --out "${WORK}/never.png")
cli_expect_error(2 "--out" vlf render "${WORK}/box.vlf" ${_bad} --object cube
  --object-relief "${WORK}/grooves.pgm" --out "${WORK}/grooves.pgm" --force)
if (EXISTS "${WORK}/never.png")
  message(FATAL_ERROR "a refused command wrote its image")
endif ()
