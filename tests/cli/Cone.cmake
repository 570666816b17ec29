# SPDX-License-Identifier: BSD-3-Clause
# mesolight cone on a generated depth image writes a cone map and refuses to overwrite its input;
# elevation maps (below).
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_depth_image(48x48)
foreach (type relaxed conservative)
  cli_run(TRUE cone "${WORK}/depth.png" --type ${type} --out "${WORK}/cone-${type}.exr")
  if (NOT EXISTS "${WORK}/cone-${type}.exr")
    message(FATAL_ERROR "cone ${type} wrote no cone map: ${last_output}")
  endif ()
endforeach ()
cli_expect_failure("cone overwrote its own input" cone "${WORK}/depth.png" --out "${WORK}/depth.png")

# Elevation maps (DEMs) are read as `bake` and `render` read them: a map in metres with holes at
# the no-data value gives, with `--no-data -9999` or the value its file names, the cone map of the
# same map with the holes at its lowest ground, and the tool says which value it applied;
# `--no-data none` takes them as elevations; signed metres are refused without --normalize.
cli_elevation_maps()
set(dem --height --normalize --type relaxed)
cli_run(TRUE cone "${WORK}/filled.tif" ${dem} --out "${WORK}/filled.exr")
cli_run(TRUE cone "${WORK}/holes.tif" ${dem} --no-data -9999 --out "${WORK}/holes-no-data.exr")
cli_expect(0 "names the no-data value -9999 (GDAL_NODATA)"
  cone "${WORK}/holes-tagged.tif" ${dem} --out "${WORK}/tagged.exr")
cli_run(TRUE cone "${WORK}/holes-tagged.tif" ${dem} --no-data none --out "${WORK}/tagged-none.exr")
# Pixel values compared (an EXR's header holds the time it was written).
function (same_exr a b out)
  execute_process(COMMAND "${OIIOTOOL}" --fail 0 --diff "${WORK}/${a}.exr" "${WORK}/${b}.exr"
    OUTPUT_VARIABLE diff ERROR_VARIABLE err)
  if (NOT diff MATCHES "PASS|FAILURE")
    message(FATAL_ERROR "oiiotool could not compare ${a}.exr and ${b}.exr: ${diff}${err}")
  endif ()
  string(FIND "${diff}" "PASS" at)
  if (at EQUAL -1)
    set(${out} FALSE PARENT_SCOPE)
  else ()
    set(${out} TRUE PARENT_SCOPE)
  endif ()
endfunction ()
same_exr(holes-no-data filled same)
if (NOT same)
  message(FATAL_ERROR "cone --no-data -9999 did not make the holes the lowest ground")
endif ()
same_exr(tagged filled same)
if (NOT same)
  message(FATAL_ERROR "cone did not apply the no-data value the GeoTIFF names")
endif ()
same_exr(tagged-none filled same)
if (same)
  message(FATAL_ERROR "cone --no-data none still made the holes the lowest ground")
endif ()
cli_expect_error(1 "--normalize" cone "${WORK}/metres-int16.tif" --height --out "${WORK}/never.exr")
if (EXISTS "${WORK}/never.exr")
  message(FATAL_ERROR "a cone map was written from signed metres without --normalize")
endif ()
