# SPDX-License-Identifier: BSD-3-Clause
# `render --normalize` and `--no-data`, for elevation maps (DEMs). A depth file in metres (a 0 /
# 64 checker) is refused without --normalize, with a message naming the option and no image;
# with it, the relief drawn is the one of the same map already in [0, 1] (a 0 / 1 checker) drawn
# without it, to the byte.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
foreach (top IN ITEMS 64 1)
  execute_process(COMMAND "${OIIOTOOL}" --pattern checker:width=8:height=8:color1=${top}:color2=0
    64x64 1 -d float -o "${WORK}/checker-${top}.tif" RESULT_VARIABLE rc ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "oiiotool could not write the checker: ${err}")
  endif ()
endforeach ()
set(scene render --offscreen --size 96x96 --height)
cli_expect_error(1 "mesolight: --normalize"
  ${scene} --depth-file "${WORK}/checker-64.tif" --out "${WORK}/never.png")
if (EXISTS "${WORK}/never.png")
  message(FATAL_ERROR "an image was written from a depth file outside [0, 1]")
endif ()
cli_run(TRUE ${scene} --depth-file "${WORK}/checker-64.tif" --normalize
  --out "${WORK}/metres.png")
cli_run(TRUE ${scene} --depth-file "${WORK}/checker-1.tif" --out "${WORK}/unit.png")
file(SHA256 "${WORK}/metres.png" metres)
file(SHA256 "${WORK}/unit.png" unit)
if (NOT metres STREQUAL unit)
  message(FATAL_ERROR "--normalize on the map in metres drew another relief than the unit map")
endif ()
# Not the flat map: the same unit map with --normalize off and --height off differs.
cli_run(TRUE render --offscreen --size 96x96 --depth-file "${WORK}/checker-1.tif"
  --out "${WORK}/depth.png")
file(SHA256 "${WORK}/depth.png" depth)
if (depth STREQUAL unit)
  message(FATAL_ERROR "--height changed nothing: the checker draws no relief")
endif ()

# `--no-data`: a map in metres (16 and 64 m) with holes at -9999 (the no-data value) is drawn,
# with it, as the same map with the holes at its lowest ground, 16 m; without it, otherwise.
cli_elevation_maps()
cli_run(TRUE ${scene} --normalize --depth-file "${WORK}/holes.tif" --no-data -9999
  --out "${WORK}/holes-no-data.png")
cli_run(TRUE ${scene} --normalize --depth-file "${WORK}/filled.tif" --out "${WORK}/filled.png")
cli_run(TRUE ${scene} --normalize --depth-file "${WORK}/holes.tif" --out "${WORK}/holes-data.png")
file(SHA256 "${WORK}/holes-no-data.png" holes_no_data)
file(SHA256 "${WORK}/filled.png" filled)
file(SHA256 "${WORK}/holes-data.png" holes_data)
if (NOT holes_no_data STREQUAL filled)
  message(FATAL_ERROR "--no-data -9999 did not draw the holes as the lowest ground")
endif ()
if (holes_data STREQUAL filled)
  message(FATAL_ERROR "without --no-data the holes drew as the lowest ground: the test shows nothing")
endif ()
cli_expect_error(2 "option --no-data: 'deep' is not a number"
  ${scene} --depth-file "${WORK}/holes.tif" --no-data deep --out "${WORK}/never.png")

# A GeoTIFF names its no-data value (GDAL_NODATA): the same holes drawn without --no-data are the
# lowest ground, as with `--no-data -9999`, and the tool says so; `--no-data none` draws them as
# elevations again.
cli_expect(0 "names the no-data value -9999 (GDAL_NODATA)"
  ${scene} --normalize --depth-file "${WORK}/holes-tagged.tif" --out "${WORK}/tagged.png")
file(SHA256 "${WORK}/tagged.png" tagged)
if (NOT tagged STREQUAL filled)
  message(FATAL_ERROR "the GeoTIFF's own no-data value did not draw the holes as the lowest ground")
endif ()
cli_run(TRUE ${scene} --normalize --depth-file "${WORK}/holes-tagged.tif" --no-data none
  --out "${WORK}/tagged-none.png")
file(SHA256 "${WORK}/tagged-none.png" tagged_none)
if (NOT tagged_none STREQUAL holes_data)
  message(FATAL_ERROR "--no-data none did not draw the file's no-data texels as elevations")
endif ()

# Signed 16-bit elevations (64 and 16 m) are measurements: refused without --normalize (as a
# fraction of 32767 they would draw a flat wall), drawn as the float map with it.
cli_expect_error(1 "signed integers"
  ${scene} --depth-file "${WORK}/metres-int16.tif" --out "${WORK}/never.png")
cli_run(TRUE ${scene} --normalize --depth-file "${WORK}/metres-int16.tif"
  --out "${WORK}/metres-int16.png")
cli_run(TRUE ${scene} --normalize --depth-file "${WORK}/metres.tif" --out "${WORK}/metres-float.png")
file(SHA256 "${WORK}/metres-int16.png" int16)
file(SHA256 "${WORK}/metres-float.png" float)
if (NOT int16 STREQUAL float)
  message(FATAL_ERROR "the int16 map in metres drew another relief than the float one")
endif ()

# SRTM height tiles (.hgt, big-endian int16 metres, voids at -32768), which OpenImageIO does not
# read: drawn with --normalize alone, the voids as the lowest ground (the same tile with those
# texels at its lowest height draws the same PNG), and the tool says which value it applied;
# refused without --normalize, as signed metres are.
find_program(PYTHON3 NAMES python3 REQUIRED)
foreach (mode IN ITEMS voids filled)
  execute_process(COMMAND "${PYTHON3}" "${CMAKE_CURRENT_LIST_DIR}/WriteSrtmTile.py"
    "${WORK}/N46E007-${mode}.hgt" 121 ${mode} RESULT_VARIABLE rc ERROR_VARIABLE err)
  if (NOT rc EQUAL 0)
    message(FATAL_ERROR "WriteSrtmTile.py: ${err}")
  endif ()
endforeach ()
cli_expect(0 "names the no-data value -32768 (SRTM voids)"
  ${scene} --normalize --depth-file "${WORK}/N46E007-voids.hgt" --out "${WORK}/srtm-voids.png")
cli_run(TRUE ${scene} --normalize --depth-file "${WORK}/N46E007-filled.hgt"
  --out "${WORK}/srtm-filled.png")
cli_run(TRUE ${scene} --normalize --depth-file "${WORK}/N46E007-voids.hgt" --no-data none
  --out "${WORK}/srtm-voids-as-data.png")
file(SHA256 "${WORK}/srtm-voids.png" srtm_voids)
file(SHA256 "${WORK}/srtm-filled.png" srtm_filled)
file(SHA256 "${WORK}/srtm-voids-as-data.png" srtm_voids_as_data)
if (NOT srtm_voids STREQUAL srtm_filled)
  message(FATAL_ERROR "an SRTM tile's voids were not drawn as its lowest ground")
endif ()
if (srtm_voids_as_data STREQUAL srtm_filled)
  message(FATAL_ERROR "--no-data none still drew the SRTM voids as the lowest ground")
endif ()
cli_expect_error(1 "signed integers"
  ${scene} --depth-file "${WORK}/N46E007-voids.hgt" --out "${WORK}/never.png")

# The tile is georeferenced (a degree from 46 N): the tool states its true vertical scale, and
# --vertical-exaggeration E draws E times it in place of --depth-scale; a map without a
# georeference is refused, as are the option without --normalize and beside --depth-scale.
cli_expect(0 "is georeferenced: its true vertical scale is depth scale"
  ${scene} --normalize --depth-file "${WORK}/N46E007-voids.hgt" --out "${WORK}/srtm-default.png")
cli_expect(0 "3 times exaggerated" ${scene} --normalize --depth-file "${WORK}/N46E007-voids.hgt"
  --vertical-exaggeration 3 --out "${WORK}/srtm-exaggerated.png")
file(SHA256 "${WORK}/srtm-exaggerated.png" srtm_exaggerated)
if (srtm_exaggerated STREQUAL srtm_voids)
  message(FATAL_ERROR "--vertical-exaggeration 3 drew the relief of the default depth scale")
endif ()
cli_expect_error(1 "carries its pixel size on the ground" ${scene} --normalize
  --depth-file "${WORK}/metres.tif" --vertical-exaggeration 3 --out "${WORK}/never.png")
cli_expect_error(2 "--vertical-exaggeration needs --normalize" ${scene}
  --depth-file "${WORK}/N46E007-voids.hgt" --vertical-exaggeration 3 --out "${WORK}/never.png")
cli_expect_error(2 "give one" ${scene} --normalize --depth-file "${WORK}/N46E007-voids.hgt"
  --vertical-exaggeration 3 --depth-scale 0.1 --out "${WORK}/never.png")
if (EXISTS "${WORK}/never.png")
  message(FATAL_ERROR "an image was written from a refused command")
endif ()
