# SPDX-License-Identifier: BSD-3-Clause
# `vlf render FIELD --mode M --exr F.exr` writes linear radiance in every walkthrough mode
# (exposure bracketing of the actor's 8-bit frame, application/WalkthroughExr.h): in the raytrace,
# progressive and coherent modes the EXR's mean is the CPU reference's (`vlf render` without
# --mode, which writes the field's radiance directly) within 3%, and its maximum is the light's
# radiance (17), far above what one 8-bit frame holds (1: a frame merely decoded would fail).
# The geometry mode draws no radiance: its EXR is the frame's linear colour, within [0, 1].
# --supersampling 2 writes the box filter of the image drawn at twice the size (the EXR equal to
# oiiotool's box filter of the 48 x 48 frame to 1e-6; the negative: one ray per pixel differs from
# it by over 1e-3 on average), PNG and EXR at --size; a factor outside [1, 8] is refused.
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

# --supersampling: the mean of S x S drawn pixels per pixel.
cli_expect(0 "the mean of 2x2 drawn pixels each" vlf render "${FIELD}" --mode coherent
  --size 24x24 --supersampling 2 --out "${WORK}/ss.png" --exr "${WORK}/ss.exr")
cli_expect(0 "wrote ${WORK}/big.exr" vlf render "${FIELD}" --mode coherent --size 48x48
  --out "${WORK}/big.png" --exr "${WORK}/big.exr")
cli_expect(0 "wrote ${WORK}/one.exr" vlf render "${FIELD}" --mode coherent --size 24x24
  --out "${WORK}/one.png" --exr "${WORK}/one.exr")
foreach (_image IN ITEMS ss.exr ss.png)
  execute_process(COMMAND "${OIIOTOOL}" --info "${WORK}/${_image}" OUTPUT_VARIABLE _info)
  if (NOT _info MATCHES "24 x +24")
    message(FATAL_ERROR "--supersampling 2: ${_image} is not 24 x 24: ${_info}")
  endif ()
endforeach ()
execute_process(COMMAND "${OIIOTOOL}" "${WORK}/big.exr" --resize:filter=box 24x24
  -o "${WORK}/boxed.exr" RESULT_VARIABLE _rc)
foreach (_image IN ITEMS ss one)
  # Radiance x 1e6, so that thousandths of it are nanounits.
  execute_process(COMMAND "${OIIOTOOL}" "${WORK}/boxed.exr" "${WORK}/${_image}.exr" --absdiff
    --mulc 1000000 -o "${WORK}/diff-${_image}.exr" RESULT_VARIABLE _rc)
  exr_stat_milli("${WORK}/diff-${_image}.exr" Avg _diff_${_image})
endforeach ()
message("mean |image - box filter of the 48 x 48 frame| x 1e9: supersampled ${_diff_ss}, "
  "one ray per pixel ${_diff_one}")
if (_diff_ss GREATER 1000 OR _diff_one LESS 1000000)
  message(FATAL_ERROR "--supersampling 2 is not the box filter of the frame drawn at twice the "
    "size (or one ray per pixel is: the check cannot fail)")
endif ()
cli_expect_error(2 "--supersampling: 9 is outside [1, 8]" vlf render "${FIELD}" --mode coherent
  --size 24x24 --supersampling 9 --out "${WORK}/never.png")
cli_expect_error(2 "--supersampling: 0 is outside [1, 8]" vlf render "${FIELD}" --mode coherent
  --size 24x24 --supersampling 0 --out "${WORK}/never.png")
