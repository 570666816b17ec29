# SPDX-License-Identifier: BSD-3-Clause
# `vlf render FIELD --relief SURFACE=DEPTH_IMAGE`: named surfaces of the field's scene drawn as
# reliefs lit by the field (application/VlfRelief.h). A relief of depth 0 is the flat wall again:
# the image's mean is the plain render's within 10% (the relief's direct light is integrated from
# emitter samples, the field's from its lines); a relief with depth shows it (the mean moves, its
# valleys are shadowed); bad input gets clear errors. With --mode the walkthrough draws them
# (VlfReliefWalk.cmake).
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

cli_run(TRUE vlf propagate --directions 129 --rays 16 --iterations 3 --out "${WORK}/box.vlf")
# Depth images as ASCII PGM: all 0, and vertical grooves (every other 4 columns 255); the
# grooves' height map (white = high: 255 - depth).
set(_zero "P2\n8 8\n255\n")
set(_grooves "P2\n8 8\n255\n")
set(_grooves_height "P2\n8 8\n255\n")
foreach (_row RANGE 7)
  string(APPEND _zero "0 0 0 0 0 0 0 0\n")
  string(APPEND _grooves "0 0 0 0 255 255 255 255\n")
  string(APPEND _grooves_height "255 255 255 255 0 0 0 0\n")
endforeach ()
file(WRITE "${WORK}/zero.pgm" "${_zero}")
file(WRITE "${WORK}/grooves.pgm" "${_grooves}")
file(WRITE "${WORK}/grooves-height.pgm" "${_grooves_height}")

cli_run(TRUE vlf render "${WORK}/box.vlf" --size 48x48 --out "${WORK}/flat.png"
  --exr "${WORK}/flat.exr")
cli_run(TRUE vlf render "${WORK}/box.vlf" --size 48x48 --relief back=${WORK}/zero.pgm
  --relief floor=${WORK}/zero.pgm --out "${WORK}/zero.png" --exr "${WORK}/zero.exr")
cli_run(TRUE vlf render "${WORK}/box.vlf" --size 48x48
  --relief back=${WORK}/grooves.pgm --relief floor=${WORK}/grooves.pgm --relief-depth-scale 0.1
  --out "${WORK}/grooves.png" --exr "${WORK}/grooves.exr")
exr_stat_milli("${WORK}/flat.exr" Avg _flat)
exr_stat_milli("${WORK}/zero.exr" Avg _zero)
exr_stat_milli("${WORK}/grooves.exr" Avg _grooves)
message("mean red: flat ${_flat}/1000, relief of depth 0 ${_zero}/1000, grooves ${_grooves}/1000")
math(EXPR _off "100 * (${_zero} - ${_flat})")
math(EXPR _allowed "10 * ${_flat}")
if (_off GREATER _allowed OR _off LESS -${_allowed})
  message(FATAL_ERROR "a relief of depth 0 is not the flat wall within 10%")
endif ()
if (_grooves EQUAL _zero)
  message(FATAL_ERROR "a relief with depth looks like the flat wall")
endif ()

# A height map (white = high) with --relief-height is the same relief as its depth map, pixel for
# pixel; without the flag it is the inverted relief (the ridges where the grooves were).
foreach (_flag IN ITEMS height depth)
  set(_height_flag)
  if (_flag STREQUAL "height")
    set(_height_flag --relief-height)
  endif ()
  cli_run(TRUE vlf render "${WORK}/box.vlf" --size 48x48 --relief back=${WORK}/grooves-height.pgm
    --relief floor=${WORK}/grooves-height.pgm --relief-depth-scale 0.1 ${_height_flag}
    --out "${WORK}/ridges-as-${_flag}.png" --exr "${WORK}/ridges-as-${_flag}.exr")
  execute_process(COMMAND "${OIIOTOOL}" --fail 1e-6 --warn 1e-6 "${WORK}/grooves.exr"
    "${WORK}/ridges-as-${_flag}.exr" --diff RESULT_VARIABLE _differs OUTPUT_QUIET ERROR_QUIET)
  if (_flag STREQUAL "height" AND NOT _differs EQUAL 0)
    message(FATAL_ERROR "the height map with --relief-height is not the depth map's relief")
  elseif (_flag STREQUAL "depth" AND _differs EQUAL 0)
    message(FATAL_ERROR "the height map read as depth gives the depth map's relief")
  endif ()
endforeach ()
cli_expect_error(2 "--relief-height needs --relief" vlf render "${WORK}/box.vlf"
  --relief-height --out "${WORK}/never.png")

# Bad input.
cli_expect_error(2 "its surfaces are: floor, ceiling, back, left, right, light, short, tall"
  vlf render "${WORK}/box.vlf" --relief wall=${WORK}/zero.pgm --out "${WORK}/never.png")
cli_expect_error(2 "Cannot read image" vlf render "${WORK}/box.vlf"
  --relief back=${WORK}/missing.png --out "${WORK}/never.png")
cli_expect_error(2 "is not planar" vlf render "${WORK}/box.vlf" --relief tall=${WORK}/zero.pgm
  --out "${WORK}/never.png")
# Depths are read as the relief mapper and trace --relief read them (ReadDepthMapImage): an int16
# elevation map and a float map in metres are refused with the relief filter's reasons, where
# they were clamped to [0, 1] without a word.
foreach (_bad IN ITEMS "int16;signed integers" "float;must lie in [0,1]")
  list(GET _bad 0 _type)
  list(GET _bad 1 _reason)
  execute_process(COMMAND "${OIIOTOOL}" --pattern constant:color=2 8x8 1 -d ${_type}
    -o "${WORK}/metres-${_type}.tif" RESULT_VARIABLE _rc)
  if (NOT _rc EQUAL 0)
    message(FATAL_ERROR "oiiotool could not write metres-${_type}.tif")
  endif ()
  cli_expect_error(2 "${_reason}" vlf render "${WORK}/box.vlf"
    --relief back=${WORK}/metres-${_type}.tif --out "${WORK}/never.png")
endforeach ()
cli_expect_error(2 "give SURFACE=DEPTH_IMAGE" vlf render "${WORK}/box.vlf" --relief back
  --out "${WORK}/never.png")
cli_expect_error(2 "--out" vlf render "${WORK}/box.vlf" --relief back=${WORK}/zero.pgm
  --out "${WORK}/zero.pgm" --force)

# A scene of its own (OBJ with `g` names and texture coordinates): the back wall's `vt` give the
# relief's texture frame; texture coordinates that are not one affine map of the plane are refused.
function (write_room path back_vt)
  file(WRITE "${WORK}/room.mtl" "newmtl white\nKd 0.7 0.7 0.7\nnewmtl lamp\nKd 0.5 0.5 0.5\nKe 10 10 10\n")
  file(WRITE "${path}" "mtllib room.mtl\n"
    "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1\n"
    "v 0.4 0.99 0.4\nv 0.6 0.99 0.4\nv 0.6 0.99 0.6\nv 0.4 0.99 0.6\n"
    "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\n${back_vt}"
    "usemtl white\n"
    "g floor\nf 1/1 5/2 6/3 2/4\n"
    "g ceiling\nf 4/1 3/2 7/3 8/4\n"
    "g back\nf 5/5 8/6 7/7 6/8\n"
    "g front\nf 1/1 2/2 3/3 4/4\n"
    "g left\nf 1/1 4/2 8/3 5/4\n"
    "g right\nf 2/1 6/2 7/3 3/4\n"
    "usemtl lamp\ng lamp\nf 9/1 10/2 11/3 12/4\n")
endfunction ()
# Back wall vertices 5 (0,0,1), 8 (0,1,1), 7 (1,1,1), 6 (1,0,1): vt = (x, y) is affine.
write_room("${WORK}/room.obj" "vt 0 0\nvt 0 1\nvt 1 1\nvt 1 0\n")
write_room("${WORK}/bent.obj" "vt 0 0\nvt 0 1\nvt 1 1\nvt 1 0.5\n")
foreach (_room IN ITEMS room bent)
  cli_run(TRUE vlf propagate "${WORK}/${_room}.obj" --directions 33 --rays 16 --iterations 2
    --out "${WORK}/${_room}.vlf")
endforeach ()
cli_expect(0 "wrote ${WORK}/room.exr" vlf render "${WORK}/room.vlf" --size 32x32
  --camera 0.5,0.5,0.05,0.5,0.5,1 --relief back=${WORK}/grooves.pgm --out "${WORK}/room.png"
  --exr "${WORK}/room.exr")
cli_expect_error(2 "are not one affine map of its plane" vlf render "${WORK}/bent.vlf"
  --size 32x32 --camera 0.5,0.5,0.05,0.5,0.5,1 --relief back=${WORK}/grooves.pgm
  --out "${WORK}/never.png")

# An elevation map in metres (a DEM) is refused without --relief-normalize, the message naming
# it; with it (and --relief-height) it is the same relief as the same checker stored as depths in
# [0, 1] (64 m: depth 0, 16 m: depth 1).
cli_elevation_maps()
cli_oiiotool(--pattern checker:width=4:height=4:color1=0:color2=1 64x64 1 -d uint8
  -o "${WORK}/checker-depth.png")
cli_expect_error(2 "--relief-normalize" vlf render "${WORK}/box.vlf" --size 32x32
  --relief back=${WORK}/metres.tif --out "${WORK}/never.png")
cli_run(TRUE vlf render "${WORK}/box.vlf" --size 32x32 --relief back=${WORK}/metres.tif
  --relief-normalize --relief-height --out "${WORK}/dem.png" --exr "${WORK}/dem.exr")
cli_run(TRUE vlf render "${WORK}/box.vlf" --size 32x32 --relief back=${WORK}/checker-depth.png
  --out "${WORK}/checker.png" --exr "${WORK}/checker.exr")
execute_process(COMMAND "${OIIOTOOL}" --fail 1e-6 --warn 1e-6 "${WORK}/dem.exr"
  "${WORK}/checker.exr" --diff RESULT_VARIABLE _differs OUTPUT_VARIABLE _out ERROR_QUIET)
if (NOT _differs EQUAL 0)
  message(FATAL_ERROR "the normalized elevation map is not the depth checker's relief: ${_out}")
endif ()

# The committed mirror box names its surfaces too; its mirror wall is refused (reliefs are
# diffuse), its back wall is drawn.
cli_run(TRUE vlf propagate "${DATA}/cornell-box-mirror.obj" --directions 33 --rays 16
  --iterations 2 --out "${WORK}/mirror.vlf")
cli_expect_error(2 "is a mirror" vlf render "${WORK}/mirror.vlf" --size 16x16
  --relief left=${WORK}/zero.pgm --out "${WORK}/never.png")
cli_run(TRUE vlf render "${WORK}/mirror.vlf" --size 16x16 --relief back=${WORK}/grooves.pgm
  --out "${WORK}/mirror.png")
