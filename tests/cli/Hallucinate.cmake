# SPDX-License-Identifier: BSD-3-Clause
# mesolight hallucinate end to end: `bench hallucinate --photos` path-traces the photographs of a
# known height field, `hallucinate` turns them into albedo and depth; bad input (swapped
# photographs, different sizes, an output over an input, a missing file) fails with one clear
# line and writes nothing.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

cli_run(TRUE bench hallucinate --maps HemisphereTorus --size 48 --samples 8 --photos "${WORK}"
    --csv "${WORK}/bench.csv")
if (NOT last_output MATCHES "HemisphereTorus +model")
  message(FATAL_ERROR "bench hallucinate printed no figures: ${last_output}")
endif ()
cli_run(TRUE bench hallucinate --maps Stone --size 32 --samples 4 --photos "${WORK}")
set(d "${WORK}/HemisphereTorus-diffuse.exr")
set(f "${WORK}/HemisphereTorus-flash.exr")
set(c "${WORK}/HemisphereTorus-calibration.exr")
foreach (file IN ITEMS "${d}" "${f}" "${c}" "${WORK}/HemisphereTorus-true-depth.exr" "${WORK}/bench.csv")
  if (NOT EXISTS "${file}")
    message(FATAL_ERROR "bench hallucinate --photos did not write ${file}")
  endif ()
endforeach ()

cli_run(TRUE hallucinate "${d}" "${f}" --calibration "${c}" --albedo "${WORK}/albedo.exr"
    --depth "${WORK}/depth.exr")
if (NOT EXISTS "${WORK}/albedo.exr" OR NOT EXISTS "${WORK}/depth.exr"
    OR NOT last_output MATCHES "depth-scale")
  message(FATAL_ERROR "hallucinate wrote no albedo or depth: ${last_output}")
endif ()
# By default the layers follow the ratio image's feature size (the scale average on fine
# features, one wide count on broad ones), and the choice is said; --layers average averages
# every count the photograph holds; a given count is kept.
if (NOT last_output MATCHES "layers: (the average of 1 to )?[0-9]+ \\(widest sigma [0-9]+ texels\\),? (fine|broad) features \\(autocorrelation length")
  message(FATAL_ERROR "hallucinate did not print the layers of the feature size: ${last_output}")
endif ()
cli_run(TRUE hallucinate "${d}" "${f}" --layers average --depth "${WORK}/depth-average.exr")
if (NOT last_output MATCHES "layers: the average of 1 to [0-9]+ \\(widest sigma [0-9]+ texels\\)\n")
  message(FATAL_ERROR "hallucinate --layers average did not print the scale average: ${last_output}")
endif ()
cli_run(TRUE hallucinate "${d}" "${f}" --layers 2 --residual-weight 0 --depth "${WORK}/depth-2.exr")
if (NOT last_output MATCHES "layers: 2 \\(widest sigma 2 texels\\)")
  message(FATAL_ERROR "hallucinate --layers 2: ${last_output}")
endif ()
cli_run(FALSE hallucinate "${d}" "${f}" --residual-weight -1 --depth "${WORK}/residual.exr")
if (NOT last_output MATCHES "--residual-weight" OR EXISTS "${WORK}/residual.exr")
  message(FATAL_ERROR "a negative --residual-weight was not refused: ${last_output}")
endif ()
# Without the card: a uniform flash, said so.
cli_run(TRUE hallucinate "${d}" "${f}" --depth "${WORK}/depth-uniform.exr")
if (NOT last_output MATCHES "uniform flash")
  message(FATAL_ERROR "no note of the uniform flash: ${last_output}")
endif ()

cli_run(FALSE hallucinate "${f}" "${d}" --depth "${WORK}/swapped.exr")
if (NOT last_output MATCHES "darker" OR EXISTS "${WORK}/swapped.exr")
  message(FATAL_ERROR "swapped photographs: ${last_output}")
endif ()
cli_run(FALSE hallucinate "${d}" "${WORK}/Stone-flash.exr" --depth "${WORK}/sizes.exr")
if (NOT last_output MATCHES "differ in size" OR EXISTS "${WORK}/sizes.exr")
  message(FATAL_ERROR "photographs of different sizes: ${last_output}")
endif ()
file(SIZE "${f}" before)
cli_run(FALSE hallucinate "${d}" "${f}" --depth "${f}")
file(SIZE "${f}" after)
if (NOT before EQUAL after OR NOT last_output MATCHES "would overwrite")
  message(FATAL_ERROR "the depth went over the flash photograph: ${last_output}")
endif ()
cli_run(FALSE hallucinate "${WORK}/missing.exr" "${f}" --depth "${WORK}/missing-depth.exr")
if (NOT last_output MATCHES "cannot read the diffuse photograph")
  message(FATAL_ERROR "missing file: ${last_output}")
endif ()
cli_run(FALSE hallucinate "${d}" "${f}")
