# SPDX-License-Identifier: BSD-3-Clause
# `vlf render FIELD --mode M --exr F.exr` writes linear radiance in every walkthrough mode
# (exposure bracketing of the actor's 8-bit frame, application/WalkthroughExr.h): in the raytrace,
# progressive and coherent modes the EXR's mean is the CPU reference's (`vlf render` without
# --mode, which writes the field's radiance directly) within 3%, and its maximum is the light's
# radiance (17), far above what one 8-bit frame holds (1: a frame merely decoded would fail).
# The geometry mode draws no radiance: its EXR is the frame's linear colour, within [0, 1].
# FIELD is the walkthrough fixture's field (tests/cli/CMakeLists.txt).
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

cli_expect(0 "wrote ${WORK}/cpu.exr (linear radiance)" vlf render "${FIELD}" --size 48x48
  --out "${WORK}/cpu.png" --exr "${WORK}/cpu.exr")
exr_stat_milli("${WORK}/cpu.exr" Avg _reference)
foreach (_mode IN ITEMS raytrace progressive coherent)
  cli_expect(0 "wrote ${WORK}/${_mode}.exr (linear radiance)" vlf render "${FIELD}"
    --mode ${_mode} --size 48x48 --exposure 3 --tone-map reinhard --out "${WORK}/${_mode}.png"
    --exr "${WORK}/${_mode}.exr")
  exr_stat_milli("${WORK}/${_mode}.exr" Avg _mean)
  exr_stat_milli("${WORK}/${_mode}.exr" Max _max)
  message("${_mode}: mean ${_mean}/1000 (CPU reference ${_reference}/1000), max ${_max}/1000")
  math(EXPR _off "100 * (${_mean} - ${_reference})")
  math(EXPR _allowed "3 * ${_reference}")
  if (_off GREATER _allowed OR _off LESS -${_allowed})
    message(FATAL_ERROR "${_mode}: the EXR's mean is not the CPU reference's within 3%")
  endif ()
  if (_max LESS 10000)
    message(FATAL_ERROR "${_mode}: the EXR holds no radiance above the display range")
  endif ()
endforeach ()
cli_expect(0 "linear colour" vlf render "${FIELD}" --mode geometry --size 48x48
  --out "${WORK}/geometry.png" --exr "${WORK}/geometry.exr")
exr_stat_milli("${WORK}/geometry.exr" Max _max)
exr_stat_milli("${WORK}/geometry.exr" Avg _mean)
if (_max GREATER 1000 OR _mean EQUAL 0)
  message(FATAL_ERROR "geometry: the EXR is not the frame's colour in [0, 1]")
endif ()
# The EXR is an output like the PNG: never the field itself.
cli_expect_error(2 "--exr" vlf render "${FIELD}" --mode coherent --size 16x16
  --out "${WORK}/never.png" --exr "${FIELD}")
