# SPDX-License-Identifier: BSD-3-Clause
# `mesolight hallucinate` inputs that gave a wrong depth or albedo with exit 0: a negative diffuse
# photograph and 1x1 photographs (flat depth), both weights 0 (flat depth), a calibration card
# black in half the view (albedo up to 4444). Each is now one clear line, exit 1 or 2, and no
# file. Absurd --layers for the photograph's size are refused naming the option; the progress is
# printed; a flat depth (a uniform photograph) is written with a warning.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
if (NOT OIIOTOOL)
  message(STATUS "oiiotool not found: nothing to replay")
  return ()
endif ()
cli_fresh_work()
function (make name)
  execute_process(COMMAND "${OIIOTOOL}" ${ARGN} -d float -o "${WORK}/${name}.exr" RESULT_VARIABLE rc)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "oiiotool could not write ${name}.exr")
  endif ()
endfunction ()
make(diffuse --pattern noise:min=0.1:max=0.6 32x32 3)
make(flash "${WORK}/diffuse.exr" --addc 0.5)
make(negative "${WORK}/diffuse.exr" --mulc -1)
# A white card whose top half is black (oiiotool pastes the first image onto the second).
make(halfblack --pattern constant:color=0,0,0 32x16 3 --pattern constant:color=1,1,1 32x32 3 --paste +0+0)
make(dot --pattern constant:color=0.2,0.2,0.2 1x1 3)
make(dotflash --pattern constant:color=0.7,0.7,0.7 1x1 3)

set(d "${WORK}/diffuse.exr")
set(f "${WORK}/flash.exr")
# The photographs themselves are fine: a depth, with progress and no warning.
cli_expect(0 "% 100%" hallucinate "${d}" "${f}" --depth "${WORK}/good.exr")
if (NOT EXISTS "${WORK}/good.exr" OR last_stderr MATCHES "warning")
  message(FATAL_ERROR "good photographs: ${last_stdout} ${last_stderr}")
endif ()
# A depth written as PNG keeps 16 bits (it was 8: 256 levels, without a word).
cli_expect(0 "wrote" hallucinate "${d}" "${f}" --depth "${WORK}/depth.png")
execute_process(COMMAND "${OIIOTOOL}" --info "${WORK}/depth.png" OUTPUT_VARIABLE _info)
if (NOT _info MATCHES "uint16")
  message(FATAL_ERROR "the PNG depth is not 16-bit: ${_info}")
endif ()
cli_expect_error(1 "diffuse photograph is negative in 100% of the pixels"
  hallucinate "${WORK}/negative.exr" "${f}" --depth "${WORK}/negative-depth.exr")
cli_expect_error(1 "at least 4x4 pixels"
  hallucinate "${WORK}/dot.exr" "${WORK}/dotflash.exr" --depth "${WORK}/dot-depth.exr")
cli_expect_error(2 "--hill-weight and --valley-weight are both 0"
  hallucinate "${d}" "${f}" --hill-weight 0 --valley-weight 0 --depth "${WORK}/flat.exr")
cli_expect_error(1 "calibration card is darker than 2% of its bright level in 50% of the pixels"
  hallucinate "${d}" "${f}" --calibration "${WORK}/halfblack.exr" --albedo "${WORK}/albedo.exr")
# --layers 7 on 32x32: sigma 64 texels, beyond the photograph.
cli_expect_error(2 "--layers 7 on a 32x32 photograph"
  hallucinate "${d}" "${f}" --layers 7 --depth "${WORK}/layers.exr")
string(FIND "${last_stderr}" "use --layers 6 or fewer" at)
if (at EQUAL -1)
  message(FATAL_ERROR "the layers refusal names no limit: ${last_stderr}")
endif ()
# A grey photograph beside a colour one (one channel, or R = G = B): the albedo's colours would be
# wrong (blue 0.14 instead of 0.22), or the refusal blamed swapped photographs. Refused, naming it.
make(luminance "${d}" --chsum:weight=0.2126,0.7152,0.0722)
make(greyrgb "${WORK}/luminance.exr" --ch 0,0,0)
foreach (_grey IN ITEMS luminance greyrgb)
  cli_expect_error(1 "diffuse photograph is grey and the flash one is in colour"
    hallucinate "${WORK}/${_grey}.exr" "${f}" --albedo "${WORK}/${_grey}-albedo.exr")
endforeach ()
cli_expect_error(1 "flash photograph is grey and the diffuse one is in colour"
  hallucinate "${d}" "${WORK}/greyrgb.exr" --albedo "${WORK}/greyflash-albedo.exr")
# A uniformly lit, uniform surface has no depth to find: written, but said so.
make(grey --pattern constant:color=0.3,0.3,0.3 16x16 3)
make(greyflash --pattern constant:color=0.8,0.8,0.8 16x16 3)
cli_expect_error(0 "warning: the depth is flat"
  hallucinate "${WORK}/grey.exr" "${WORK}/greyflash.exr" --depth "${WORK}/grey-depth.exr")
foreach (file IN ITEMS negative-depth dot-depth flat albedo layers luminance-albedo greyrgb-albedo
    greyflash-albedo)
  if (EXISTS "${WORK}/${file}.exr")
    message(FATAL_ERROR "a refused run wrote ${file}.exr")
  endif ()
endforeach ()
