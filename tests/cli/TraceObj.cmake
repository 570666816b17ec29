# SPDX-License-Identifier: BSD-3-Clause
# `mesolight trace --scene FILE.obj`: the path tracer on an OBJ + MTL scene from a walkthrough
# camera, to linear EXR (read back with oiiotool --stats, OIIOTOOL).
# - The furnace: a closed box of albedo 0.5 whose every face emits 1 (Ke) reads Le / (1 - a) = 2
#   in every pixel; cutting the paths after one bounce (--bounces 1) reads 1 + a = 1.5 and must
#   fail the same check (the check can fail).
# - The camera convention of `vlf render`: an emitter above the view axis is in the image's top
#   half with view up +y and in its bottom half with the view up given as -y (the nine-value
#   --camera), so the up vector and the row order are both checked.
# - Bad input: a missing file, a malformed camera, a NaN or out-of-range field of view, a camera
#   without a frame, a scene without emitter, a view up given twice, the EXR over the scene file.
# - A relief (--relief SURFACE=DEPTH_IMAGE, the dense displaced mesh): the furnace with a deep
#   relief on its back face still reads 2 (the relief is closed: a gap along its border would let
#   paths out), its mask covers the view of that face, and bad relief input is refused.
# PART (furnace, camera, bad_input or relief) picks one, so that each is its own cli.trace.* test.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

file(WRITE "${WORK}/furnace.mtl" "newmtl glow\nKd 0.5 0.5 0.5\nKe 1 1 1\n")
# The unit cube, faces counter-clockwise seen from inside (their emitting front faces inward).
file(WRITE "${WORK}/furnace.obj" "mtllib furnace.mtl
v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1
usemtl glow
f 1 5 6 2\nf 4 3 7 8\nf 1 2 3 4\nf 5 8 7 6\nf 1 4 8 5\nf 2 6 7 3
")
set(_inside --camera 0.5,0.5,0.1,0.5,0.5,0.9 --fov 90 --width 24 --height 24 --samples 16)

# The mean of the first channel of an EXR in thousandths (CMake's arithmetic is integer); an
# optional third argument cuts a window first (oiiotool geometry WxH+X+Y, rows from the top).
function (exr_mean_milli image out)
  if (ARGC GREATER 2)
    execute_process(COMMAND "${OIIOTOOL}" "${image}" --cut "${ARGV2}" -o "${WORK}/cut.exr"
      RESULT_VARIABLE rc ERROR_VARIABLE err)
    if (NOT rc EQUAL 0)
      message(FATAL_ERROR "oiiotool cannot cut ${image}: ${err}")
    endif ()
    set(image "${WORK}/cut.exr")
  endif ()
  exr_stat_milli("${image}" Avg milli)
  set(${out} ${milli} PARENT_SCOPE)
endfunction ()

# |mean - 2| <= 2% of 2.
function (furnace_agrees image out)
  exr_mean_milli("${image}" milli)
  math(EXPR off "${milli} - 2000")
  if (off LESS 0)
    math(EXPR off "-${off}")
  endif ()
  message("${image}: mean radiance ${milli}/1000, the furnace's 2000/1000")
  if (off LESS_EQUAL 40)
    set(${out} TRUE PARENT_SCOPE)
  else ()
    set(${out} FALSE PARENT_SCOPE)
  endif ()
endfunction ()

if (PART STREQUAL "furnace")
  cli_expect(0 "wrote ${WORK}/furnace.exr (linear radiance)" trace --scene "${WORK}/furnace.obj"
    ${_inside} --offscreen --out "${WORK}/furnace.png" --exr "${WORK}/furnace.exr")
  furnace_agrees("${WORK}/furnace.exr" _ok)
  if (NOT _ok)
    message(FATAL_ERROR "the furnace does not read Le / (1 - a) = 2")
  endif ()
  cli_expect(0 "wrote" trace --scene "${WORK}/furnace.obj" ${_inside} --bounces 1 --offscreen
    --out "${WORK}/truncated.png" --exr "${WORK}/truncated.exr")
  furnace_agrees("${WORK}/truncated.exr" _ok)
  if (_ok)
    message(FATAL_ERROR "paths cut after one bounce pass the furnace check: it cannot fail")
  endif ()
endif ()

if (PART STREQUAL "camera")
  # An emitter facing the camera, above the view axis: the camera at z = 0 looks along +z.
  file(WRITE "${WORK}/above.mtl" "newmtl lamp\nKd 0 0 0\nKe 1 1 1\n")
  file(WRITE "${WORK}/above.obj" "mtllib above.mtl\nv -1 0.2 2\nv -1 1 2\nv 1 1 2\nv 1 0.2 2
usemtl lamp\nf 1 2 3 4\n")
  foreach (_up IN ITEMS 1 -1)
    cli_expect(0 "wrote" trace --scene "${WORK}/above.obj" --camera 0,0,0,0,0,1,0,${_up},0
      --fov 60 --width 16 --height 16 --samples 4 --offscreen --out "${WORK}/above${_up}.png"
      --exr "${WORK}/above${_up}.exr")
    # oiiotool's first rows are the image's top.
    exr_mean_milli("${WORK}/above${_up}.exr" _top 16x8+0+0)
    exr_mean_milli("${WORK}/above${_up}.exr" _bottom 16x8+0+8)
    message("view up ${_up}: top half ${_top}/1000, bottom half ${_bottom}/1000")
    if (_up EQUAL 1 AND NOT (_top GREATER 300 AND _bottom EQUAL 0))
      message(FATAL_ERROR "view up +y: the emitter above the axis is not in the top half")
    elseif (_up EQUAL -1 AND NOT (_bottom GREATER 300 AND _top EQUAL 0))
      message(FATAL_ERROR "view up -y: the emitter above the axis is not in the bottom half")
    endif ()
  endforeach ()
endif ()

if (PART STREQUAL "bad_input")
  # Bad input: exit code and a message naming the problem, nothing written.
  set(_never --offscreen --out "${WORK}/never.png" --exr "${WORK}/never.exr")
  cli_expect_error(1 "cannot open" trace --scene "${WORK}/missing.obj" ${_never})
  cli_expect_error(2 "--camera needs X,Y,Z,FX,FY,FZ" trace --scene "${WORK}/furnace.obj"
    --camera 1,2,3 ${_never})
  cli_expect_error(2 "--camera needs" trace --scene "${WORK}/furnace.obj"
    --camera 0,0,0,a,b,c ${_never})
  cli_expect_error(2 "--camera needs" trace --scene "${WORK}/furnace.obj"
    --camera 0,0,0,0,0,nan ${_never})
  cli_expect_error(2 "--fov: 'nan' is not a number" trace --scene "${WORK}/furnace.obj"
    --fov nan ${_never})
  cli_expect_error(2 "--fov: 180 is outside [1, 179]" trace --scene "${WORK}/furnace.obj"
    --fov 180 ${_never})
  cli_expect_error(2 "distinct position and focal point" trace --scene "${WORK}/furnace.obj"
    --camera 1,1,1,1,1,1 ${_never})
  cli_expect_error(2 "not parallel to the view direction" trace --scene "${WORK}/furnace.obj"
    --camera 0,0,0,0,1,0 ${_never})
  cli_expect_error(2 "give the view up once" trace --scene "${WORK}/furnace.obj"
    --camera 0,0,0,0,0,1,0,1,0 --view-up 0,1,0 ${_never})
  file(WRITE "${WORK}/dark.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
  cli_expect_error(1 "no emitter" trace --scene "${WORK}/dark.obj" ${_never})
  cli_expect_error(2 "would overwrite" trace --scene "${WORK}/furnace.obj" --offscreen
    --out "${WORK}/never.png" --exr "${WORK}/furnace.obj")
  cli_expect_error(2 "--scene cornell only" trace --scene "${WORK}/furnace.obj"
    --compare-exr "${WORK}/furnace.exr" ${_never})
  cli_expect_error(2 "--fov applies to --scene FILE.obj or cornell only" trace --scene spheres
    --fov 30 ${_never})
  foreach (_file IN ITEMS never.png never.exr)
    if (EXISTS "${WORK}/${_file}")
      message(FATAL_ERROR "bad input wrote ${_file}")
    endif ()
  endforeach ()
endif ()

if (PART STREQUAL "relief")
  # The furnace with its far face (z = 1, facing -z) named `far`, the others `box`.
  file(WRITE "${WORK}/relief.obj" "mtllib furnace.mtl
v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\nv 0 0 1\nv 1 0 1\nv 1 1 1\nv 0 1 1
usemtl glow
g box\nf 1 5 6 2\nf 4 3 7 8\nf 1 2 3 4\nf 1 4 8 5\nf 2 6 7 3
g far\nf 5 8 7 6
")
  # A rough depth map: blurred noise over [0, 1].
  execute_process(COMMAND "${OIIOTOOL}" --pattern noise:type=uniform:min=0:max=1:seed=3 24x24 1
    --blur 3x3 -d uint8 -o "${WORK}/depth.png" RESULT_VARIABLE rc ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "oiiotool cannot make the depth map: ${err}")
  endif ()
  set(_relief --relief "far=${WORK}/depth.png" --relief-depth-scale 0.4)
  cli_expect(0 "relief on 'far': 24x24 depth texels" trace --scene "${WORK}/relief.obj"
    ${_relief} ${_inside} --offscreen --out "${WORK}/relief.png" --exr "${WORK}/relief.exr")
  furnace_agrees("${WORK}/relief.exr" _ok)
  if (NOT _ok)
    message(FATAL_ERROR "the furnace with a relief does not read 2: the relief leaks")
  endif ()
  # Looking at the relief (a 40 degree view from inside sees only the far face): the mask is 1
  # everywhere; looking away from it, 0. The view is off the face's centre: from the centre, the
  # mask's symmetric rays run exactly along the face's diagonal edge, which Embree's (non-robust)
  # triangle test may let through between the two triangles sharing it.
  cli_expect(0 "relief coverage per pixel" trace --scene "${WORK}/relief.obj" ${_relief}
    --camera 0.47,0.52,0.1,0.47,0.52,0.9 --fov 40 --width 16 --height 16 --samples 1 --offscreen
    --out "${WORK}/mask-view.png" --relief-mask "${WORK}/mask.exr")
  exr_stat_milli("${WORK}/mask.exr" Avg _covered)
  cli_expect(0 "relief coverage per pixel" trace --scene "${WORK}/relief.obj" ${_relief}
    --camera 0.5,0.5,0.9,0.5,0.5,0.1 --fov 40 --width 16 --height 16 --samples 1 --offscreen
    --out "${WORK}/mask-away.png" --relief-mask "${WORK}/mask-away.exr")
  exr_stat_milli("${WORK}/mask-away.exr" Max _away)
  message("relief mask: mean ${_covered}/1000 facing it, max ${_away}/1000 facing away")
  if (NOT _covered EQUAL 1000 OR NOT _away EQUAL 0)
    message(FATAL_ERROR "the relief mask does not follow the relief")
  endif ()
  # The built-in box takes a relief on its named walls and a walkthrough camera.
  cli_expect(0 "relief on 'back'" trace --scene cornell --relief "back=${WORK}/depth.png"
    --camera 278,273,-800,278,273,0 --width 8 --height 8 --samples 1 --offscreen
    --out "${WORK}/cornell.png")
  # Bad relief input: exit code and a message naming the problem, nothing written.
  set(_never --offscreen --out "${WORK}/never.png" --exr "${WORK}/never.exr")
  cli_expect_error(1 "its surfaces are: box, far" trace --scene "${WORK}/relief.obj"
    --relief "window=${WORK}/depth.png" ${_never})
  cli_expect_error(1 "is not planar" trace --scene "${WORK}/relief.obj"
    --relief "box=${WORK}/depth.png" ${_never})
  cli_expect_error(1 "is not planar" trace --scene cornell --relief "tall=${WORK}/depth.png"
    ${_never})
  cli_expect_error(1 "takes SURFACE=DEPTH_IMAGE" trace --scene cornell --relief back ${_never})
  cli_expect_error(1 "missing.png" trace --scene cornell --relief "back=${WORK}/missing.png"
    ${_never})
  cli_expect_error(2 "--relief-mask needs --relief" trace --scene cornell --camera 0,0,0,0,0,1
    --relief-mask "${WORK}/never-mask.exr" ${_never})
  cli_expect_error(2 "--relief applies to --scene FILE.obj or cornell only" trace --scene spheres
    --relief "back=${WORK}/depth.png" ${_never})
  foreach (_file IN ITEMS never.png never.exr never-mask.exr)
    if (EXISTS "${WORK}/${_file}")
      message(FATAL_ERROR "bad relief input wrote ${_file}")
    endif ()
  endforeach ()
endif ()
