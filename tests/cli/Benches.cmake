# SPDX-License-Identifier: BSD-3-Clause
# Every `mesolight bench` command and `mesolight probe` on tiny sizes (running is not enough: the
# outputs are asserted): each exits 0 and writes its CSV with the documented header
# and the expected rows, the charts where asked, and one sanity relation per command.
cmake_minimum_required(VERSION 3.16) # quoted strings in if() are strings (CMP0054)
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()

# run(<name> <args>...): runs the tool, fails the test on a non-zero exit.
function (run name)
  cli_execute(${ARGN})
  file(WRITE "${WORK}/${name}.log" "${cli_stdout}\n${cli_stderr}")
  if (NOT cli_rc EQUAL 0)
    message(FATAL_ERROR "mesolight ${ARGN} failed (rc ${cli_rc}):\n${cli_stdout}\n${cli_stderr}")
  endif ()
  set(output "${cli_stdout}" PARENT_SCOPE)
endfunction ()

# check_csv(<file> <header> <minimum data rows>): the header line and the row count.
function (check_csv file header rows)
  if (NOT EXISTS "${file}")
    message(FATAL_ERROR "no ${file}")
  endif ()
  file(STRINGS "${file}" lines)
  list(GET lines 0 first)
  if (NOT first STREQUAL "${header}")
    message(FATAL_ERROR "${file}: header\n  ${first}\nnot\n  ${header}")
  endif ()
  list(LENGTH lines count)
  math(EXPR count "${count} - 1")
  if (count LESS rows)
    message(FATAL_ERROR "${file}: ${count} rows, fewer than ${rows}")
  endif ()
  set(csv_lines "${lines}" PARENT_SCOPE)
endfunction ()

# column(<line> <index> <out>): one comma-separated field of a CSV line (no quoted commas).
function (column line index out)
  string(REPLACE "," ";" fields "${line}")
  list(GET fields ${index} value)
  set(${out} "${value}" PARENT_SCOPE)
endfunction ()

# `bench`: the stock plane, relief and the dense mesh; relief is closer to the mesh.
run(bench bench --sizes 64 --frames 1 --size 64x64 --csv "${WORK}/bench.csv")
check_csv("${WORK}/bench.csv"
  "configuration,map,ms_per_frame,first_frame_ms,mean_color_error,rms_color_error,psnr_db,silhouette_mismatch_pct,depth_mismatch_pct,gpu_megabytes"
  4)
set(plane "")
set(relief "")
foreach (line IN LISTS csv_lines)
  if (line MATCHES "^\"textured plane")
    column("${line}" 4 plane)
  elseif (line MATCHES "^\"relief 10\\+8\",")
    column("${line}" 4 relief)
  endif ()
endforeach ()
if (plane STREQUAL "" OR relief STREQUAL "")
  message(FATAL_ERROR "bench.csv lacks the textured plane or relief rows")
endif ()
if (NOT relief LESS plane) # both are decimals; LESS compares them as numbers
  message(FATAL_ERROR "relief (${relief}) is not closer to the dense mesh than the plane (${plane})")
endif ()
# Its rows fix their methods and steps: asking for one is refused, not silently ignored.
foreach (fixed "--method;max-mipmap" "--linear-steps;64" "--refinement-steps;4")
  cli_execute(bench --sizes 64 --frames 1 --size 64x64 ${fixed})
  if (NOT cli_rc EQUAL 2 OR NOT cli_stderr MATCHES "does not apply")
    message(FATAL_ERROR "bench ${fixed}: rc ${cli_rc}, not a usage error:\n${cli_stderr}")
  endif ()
endforeach ()

# `bench cones`: one row per map, size and cone type.
run(cones bench cones --maps Bricks --sizes 64 --oracle-size 16 --compare-size 32
    --stepping-size 32 --stepping-rays 200 --csv "${WORK}/cones.csv")
check_csv("${WORK}/cones.csv"
  "map,size,type,threads,seconds,cpu_seconds,oracle_seconds_extrapolated,speedup,median_ratio,clamped_fraction"
  2)

# `bench lights`: every map and method at each count, SH9 too, and the timing rows.
run(lights bench lights --counts 4,8 --normals 50 --resolution 32 --timing-repeats 1
    --csv "${WORK}/lights.csv")
check_csv("${WORK}/lights.csv" "map,width,height,method,lights,mean_rel_error,max_rel_error" 10)
string(FIND "${csv_lines}" "SmoothSky,64,32,SH9,9," sh9)
if (sh9 EQUAL -1)
  message(FATAL_ERROR "lights.csv has no SH9 row for SmoothSky")
endif ()

# `bench ibl`: the light-count sweep and the skips, each with its error against Monte Carlo.
run(ibl bench ibl --counts 8,16 --skip-count 8 --frames 1 --size 64x64 --samples 16
    --compare-count 0 --csv "${WORK}/ibl.csv")
check_csv("${WORK}/ibl.csv"
  "configuration,lights,ms_per_frame,error_pct_vs_monte_carlo,mean_diff_vs_full" 9)

# `bench vlf`: a row per iteration, energy conserved, and both charts.
run(vlf bench vlf --directions 33 --rays 8 --iterations 2 --csv "${WORK}/vlf.csv"
    --plot "${WORK}/vlf.png")
check_csv("${WORK}/vlf.csv"
  "directions,rays,tiles,iteration,build_s,propagate_s,total_s,estimate_bytes,allocated_bytes,peak_rss_bytes,energy_error,floor_mean_error,floor_rms_error,furnace_error,cornell_error"
  2)
foreach (chart vlf.png vlf-error.png)
  if (NOT EXISTS "${WORK}/${chart}")
    message(FATAL_ERROR "bench vlf wrote no ${chart}")
  endif ()
endforeach ()

# `probe`: an angular probe (any picture) to a lat-long EXR of the asked width.
run(render render --offscreen --size 64x64 --resolution 64 --out "${WORK}/probe.png")
run(probe probe "${WORK}/probe.png" --out "${WORK}/environment.exr" --width 64)
if (NOT output MATCHES "64x32 lat-long" OR NOT EXISTS "${WORK}/environment.exr")
  message(FATAL_ERROR "probe did not write a 64x32 lat-long map: ${output}")
endif ()
