# SPDX-License-Identifier: BSD-3-Clause
# `mesolight render --geometry-image` as a user runs it: a float EXR geometry image (a plane,
# RGB = XYZ) with a NaN hole made by oiiotool, regular and adaptive sampling, a colour image, the
# procedural surfaces, and bad input with clear messages.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
set(common --offscreen --size 96x96 --resolution 64)

# The procedural surfaces need no data.
cli_expect(0 "procedural:cylinder: 128 triangles (stride 8)" render ${common}
  --geometry-image procedural:cylinder --stride 8 --out "${WORK}/cylinder.png")
cli_expect(0 "triangles (tolerance 0.002)" render ${common}
  --geometry-image procedural:bump --tolerance 0.002 --out "${WORK}/bump.png")
foreach (png cylinder bump)
  if (NOT EXISTS "${WORK}/${png}.png")
    message(FATAL_ERROR "${png}.png was not written")
  endif ()
endforeach ()

if (OIIOTOOL)
  # A 64 x 64 plane with an 11 x 11 NaN hole: stride 8 gives 8 x 8 quads, the 2 x 2 around the
  # hole dropped: 120 triangles.
  execute_process(COMMAND "${OIIOTOOL}"
    --pattern fill:topleft=0,0,0:topright=1,0,0:bottomleft=0,1,0:bottomright=1,1,0 64x64 3
    -d float --box:color=nan,nan,nan:fill=1 20,20,30,30 -o "${WORK}/plane.exr"
    RESULT_VARIABLE rc)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "oiiotool could not write the geometry image")
  endif ()
  cli_expect(0 "120 triangles (stride 8)" render ${common} --geometry-image "${WORK}/plane.exr"
    --stride 8 --color "${WORK}/cylinder.png" --out "${WORK}/plane.png")
  cli_expect(0 "triangles (tolerance 0.001)" render ${common}
    --geometry-image "${WORK}/plane.exr" --tolerance 0.001 --out "${WORK}/plane-adaptive.png")
  cli_expect(1 "stride 64 is outside 1..63" render ${common}
    --geometry-image "${WORK}/plane.exr" --stride 64 --out "${WORK}/never.png")
  execute_process(COMMAND "${OIIOTOOL}" --pattern constant:color=nan,nan,nan 16x16 3 -d float
    -o "${WORK}/holes.exr")
  cli_expect(1 "every pixel of the geometry image is empty" render ${common}
    --geometry-image "${WORK}/holes.exr" --out "${WORK}/never.png")
  execute_process(COMMAND "${OIIOTOOL}" --pattern constant:color=0.5 16x16 1 -d float
    -o "${WORK}/grey.exr")
  cli_expect(1 "needs 3 components per pixel" render ${common}
    --geometry-image "${WORK}/grey.exr" --out "${WORK}/never.png")
  # A colour image with one NaN texel rendered that texel black, silently: refused by position.
  execute_process(COMMAND "${OIIOTOOL}" --pattern constant:color=0.8,0.6,0.4 16x16 3 -d float
    --box:color=nan,nan,nan:fill=1 5,7,5,7 -o "${WORK}/nan-colour.exr")
  cli_expect(1 "has a NaN or infinite value at texel (5, 7) (column, row from the top), channel 0" render ${common}
    --geometry-image "${WORK}/plane.exr" --stride 8 --color "${WORK}/nan-colour.exr"
    --out "${WORK}/never.png")
endif ()

cli_expect(2 "exclude each other" render ${common} --geometry-image procedural:plane --stride 4
  --tolerance 0.01 --out "${WORK}/never.png")
cli_expect(2 "--stride needs --geometry-image" render ${common} --stride 4
  --out "${WORK}/never.png")
cli_expect(1 "unknown procedural geometry image" render ${common}
  --geometry-image procedural:torus --out "${WORK}/never.png")
cli_expect(1 "cannot read the geometry image" render ${common}
  --geometry-image "${WORK}/missing.exr" --out "${WORK}/never.png")
if (EXISTS "${WORK}/never.png")
  message(FATAL_ERROR "a failed render wrote its output")
endif ()
