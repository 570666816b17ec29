# SPDX-License-Identifier: BSD-3-Clause
# A relief on a large ground lit by the field keeps the scene's shadows: examples/data/town.obj,
# 10 m buildings on a 200 m ground under a 40 m sky panel. The relief mapper's emitter lights carry the scene's
# shadow as one factor per SH9 probe; 8 probes a side (25 m apart) averaged the buildings'
# shadows away where the CPU reference (`vlf render --relief`, a shadow ray per emitter sample)
# draws them. The automatic probe count (two per field line cell across the surface, 44 here,
# vlf::ReliefProbesPerSide) brings the walkthrough's relief (depth 0) to the CPU reference's
# image: mean |GPU - CPU| over the image within LIMIT/1000 of the reference's mean; negative:
# --relief-probes 8 is not, nor 22 (one per field line cell, the rule before).
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

file(WRITE "${WORK}/zero.pgm" "P2\n2 2\n255\n0 0\n0 0\n")

cli_run(TRUE vlf propagate "${DATA}/town.obj" --directions 513 --rays 32 --iterations 2
  --out "${WORK}/town.vlf")
set(_view --size 96x96 --camera 70,-90,45,0,0,5,0,0,1 --relief ground=${WORK}/zero.pgm)
cli_run(TRUE vlf render "${WORK}/town.vlf" ${_view} --out "${WORK}/cpu.png"
  --exr "${WORK}/cpu.exr")
exr_stat_milli("${WORK}/cpu.exr" Avg _reference)
foreach (_probes IN ITEMS 0 8 22)
  cli_run(TRUE vlf render "${WORK}/town.vlf" --mode progressive ${_view} --relief-probes ${_probes}
    --out "${WORK}/gpu-${_probes}.png" --exr "${WORK}/gpu-${_probes}.exr")
  cli_oiiotool("${WORK}/gpu-${_probes}.exr" "${WORK}/cpu.exr" --absdiff -o "${WORK}/diff-${_probes}.exr")
  exr_stat_milli("${WORK}/diff-${_probes}.exr" Avg _diff_${_probes})
  math(EXPR _relative_${_probes} "1000 * ${_diff_${_probes}} / ${_reference}")
  message("--relief-probes ${_probes}: mean |GPU - CPU| ${_relative_${_probes}}/1000 of the "
    "reference's mean (${_reference}/1000)")
endforeach ()
if (_relative_0 GREATER ${LIMIT})
  message(FATAL_ERROR "the automatic probes miss the scene's shadows on the ground")
endif ()
if (NOT _relative_8 GREATER ${LIMIT})
  message(FATAL_ERROR "8 probes a side pass the check: it cannot see the shadows")
endif ()
if (NOT _relative_22 GREATER ${LIMIT})
  message(FATAL_ERROR "22 probes a side (one per field line cell) pass the check: it cannot "
    "tell the rule's two per cell from one")
endif ()

# Terrain in metres on the ground: the walkthrough takes --relief-normalize as the CPU reference
# does (refused without it, naming it).
cli_elevation_maps()
set(_dem --size 48x48 --camera 70,-90,45,0,0,5,0,0,1 --relief ground=${WORK}/metres.tif)
cli_expect_error(2 "--relief-normalize" vlf render "${WORK}/town.vlf" --mode progressive ${_dem}
  --out "${WORK}/never.png")
cli_run(TRUE vlf render "${WORK}/town.vlf" --mode progressive ${_dem} --relief-normalize
  --relief-height --out "${WORK}/dem.png")

# The default camera of a scene with z up: with --view-up 0,0,1 it looks along +y and sees the
# town (it was refused: the view up parallel to the view direction); without it the black image's
# warning names the option.
cli_expect(0 "wrote" vlf render "${WORK}/town.vlf" --size 32x32 --view-up 0,0,1
  --out "${WORK}/default-z-up.png")
if (last_stderr MATCHES "every pixel is black")
  message(FATAL_ERROR "the default camera with --view-up 0,0,1 sees nothing: ${last_stderr}")
endif ()
cli_expect_error(0 "give --view-up 0,0,1" vlf render "${WORK}/town.vlf" --size 32x32
  --out "${WORK}/default.png")
