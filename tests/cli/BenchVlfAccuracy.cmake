# SPDX-License-Identifier: BSD-3-Clause
# `mesolight bench vlf-accuracy` on tiny sizes: the CSV's header and rows (2 scenes x 2 settings x
# propagated / gathered / filtered), the finer field closer to the path tracer than the coarse one on
# each scene (the error can tell them apart), the cached reference reused by a second run, and
# bad --settings / --scenes refused; a scene file (--scenes FILE.obj, seen from --camera) gives the
# built-in box's figures from its OBJ, and bad files and cameras are refused.
cmake_minimum_required(VERSION 3.16)
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

set(args bench vlf-accuracy --scenes cornell,thin --settings 33x16,129x32 --size 24x24
  --samples 64 --cache "${WORK}/cache")
cli_run(TRUE ${args} --csv "${WORK}/accuracy.csv")
if (NOT last_output MATCHES "path-traced reference")
  message(FATAL_ERROR "no reference was traced: ${last_output}")
endif ()
file(STRINGS "${WORK}/accuracy.csv" lines)
list(GET lines 0 header)
set(expected "scene,settings,directions,rays,tiles,texel_m,lines,surfaces,texels,map_cells,iterations,build_s,propagate_s,total_s,allocated_bytes,estimate_bytes,filter,gather_s,gather_rays,pixels,mean_rel_error,p95_rel_error,black_where_lit,reference_noise,peak_bytes")
if (NOT header STREQUAL expected)
  message(FATAL_ERROR "header\n  ${header}\nnot\n  ${expected}")
endif ()
list(LENGTH lines count)
if (NOT count EQUAL 13)
  message(FATAL_ERROR "expected 12 rows, got ${count} lines:\n${lines}")
endif ()
# The gathered row after each propagated one, with its rays.
list(GET lines 2 gathered_line)
string(REPLACE "," ";" g "${gathered_line}")
list(GET g 16 variant)
list(GET g 18 gather_rays)
if (NOT variant STREQUAL "gather" OR NOT gather_rays GREATER 0)
  message(FATAL_ERROR "row 2 is not a final gather: ${gathered_line}")
endif ()
# Unfiltered rows: lines 1 (cornell 33x16), 4 (cornell 129x32), 7 (thin 33x16), 10 (thin 129x32).
foreach (pair "1;4" "7;10")
  list(GET pair 0 coarse)
  list(GET pair 1 fine)
  list(GET lines ${coarse} coarse_line)
  list(GET lines ${fine} fine_line)
  string(REPLACE "," ";" c "${coarse_line}")
  string(REPLACE "," ";" f "${fine_line}")
  list(GET c 20 coarse_error)
  list(GET f 20 fine_error)
  list(GET f 16 filter)
  if (NOT filter STREQUAL "none")
    message(FATAL_ERROR "row ${fine} is not unfiltered: ${fine_line}")
  endif ()
  if (NOT fine_error LESS coarse_error)
    message(FATAL_ERROR "129x32 (${fine_error}) not closer than 33x16 (${coarse_error}):\n${lines}")
  endif ()
endforeach ()
cli_run(TRUE ${args})
if (last_output MATCHES "path-traced reference")
  message(FATAL_ERROR "the cached reference was traced again: ${last_output}")
endif ()
cli_expect_error(2 "is not auto, KxN or KxNtF" bench vlf-accuracy --scenes cornell --settings 33
  --cache "${WORK}/cache" --size 24x24 --samples 64)
cli_expect_error(2 "is not none, single, gather, bilateral or gather-bilateral" bench vlf-accuracy --scenes cornell
  --variants none,final --cache "${WORK}/cache" --size 24x24 --samples 64)
cli_expect_error(2 "unknown scene 'attic'" bench vlf-accuracy --scenes attic --cache "${WORK}/cache")

# A scene file: the Cornell box written as OBJ + MTL and measured from the published camera gives
# the built-in box's figures (same geometry, camera and rays); a missing file, a scene without an
# emitter and a bad camera are refused.
cli_run(TRUE bench vlf-accuracy --scenes cornell --write-obj "${WORK}/obj")
set(file_args --settings 33x16 --variants none --size 24x24 --samples 64 --cache "${WORK}/cache")
cli_run(TRUE bench vlf-accuracy --scenes cornell ${file_args} --csv "${WORK}/builtin.csv")
cli_run(TRUE bench vlf-accuracy --scenes "${WORK}/obj/cornell.obj"
  --camera 278,273,-800,278,273,0 --fov 39.3077 ${file_args} --csv "${WORK}/file.csv")
foreach (which builtin file)
  file(STRINGS "${WORK}/${which}.csv" rows)
  list(GET rows 1 row)
  string(REPLACE "," ";" fields "${row}")
  list(GET fields 0 scene_${which})
  list(GET fields 20 mean_${which})
  list(GET fields 19 pixels_${which})
endforeach ()
if (NOT scene_file STREQUAL "cornell" OR NOT mean_file STREQUAL mean_builtin OR
    NOT pixels_file STREQUAL pixels_builtin)
  message(FATAL_ERROR "the box from its OBJ file (${scene_file}: ${mean_file}, ${pixels_file} "
    "pixels) is not the built-in box (${mean_builtin}, ${pixels_builtin} pixels)")
endif ()
cli_expect_error(1 "does-not-exist.obj" bench vlf-accuracy --scenes "${WORK}/does-not-exist.obj"
  ${file_args})
file(WRITE "${WORK}/dark.obj" "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 3\n")
cli_expect_error(1 "emitter" bench vlf-accuracy --scenes "${WORK}/dark.obj" ${file_args})
cli_expect_error(2 "--camera" bench vlf-accuracy --scenes "${WORK}/obj/cornell.obj"
  --camera 1,2,3 ${file_args})
