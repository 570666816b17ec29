# SPDX-License-Identifier: BSD-3-Clause
# What an adversarial user tried: degenerate inputs end with an error, never a crash; no
# command overwrites its input (by name or through a symbolic or hard link) or writes anything
# before every option is checked; writers' failures are reported; memory budgets refuse early.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_depth_image(48x48) # ${WORK}/depth.png, also used as an "environment" and as a user's file

# FILE must still have the content it had when cli_remember(FILE) was called.
function (cli_remember file)
  file(SHA256 "${file}" hash)
  set(hash_${file} "${hash}" PARENT_SCOPE)
endfunction ()
function (cli_expect_unchanged file)
  file(SHA256 "${file}" hash)
  if (NOT hash STREQUAL "${hash_${file}}")
    message(FATAL_ERROR "${file} was overwritten")
  endif ()
endfunction ()

# 1. Degenerate relief walls: a clear error (exit 1), no SIGSEGV.
cli_expect_error(1 "at least 2x2" render --offscreen --size 32x32 --resolution 1 --out "${WORK}/r1.png")

# 2. Inputs are never outputs, through links too; checked before any work.
set(user "${WORK}/depth.png")
cli_remember("${user}")
cli_expect_error(2 "would overwrite" lights "${user}" --count 4 --out "${user}")
file(CREATE_LINK "${user}" "${WORK}/symbolic.csv" SYMBOLIC)
cli_expect_error(2 "would overwrite" lights "${user}" --count 4 --out "${WORK}/symbolic.csv")
file(CREATE_LINK "${user}" "${WORK}/hard.csv")
cli_expect_error(2 "would overwrite" lights "${user}" --count 4 --out "${WORK}/hard.csv")
cli_expect_error(2 "would overwrite"
  render --offscreen --size 32x32 --resolution 16 --environment "${user}" --out "${user}")
cli_expect_error(2 "would overwrite" bake "${user}" --out "${WORK}/hard.csv")
cli_expect_unchanged("${user}")

cli_run(TRUE vlf propagate --out "${WORK}/field.vlf" --directions 33 --rays 8 --iterations 1)
cli_remember("${WORK}/field.vlf")
cli_expect_error(2 "would overwrite"
  vlf render "${WORK}/field.vlf" --out "${WORK}/field.vlf" --force --size 16x16)
cli_expect_error(2 "would overwrite"
  vlf render "${WORK}/field.vlf" --mode geometry --out "${WORK}/field.vlf" --force --size 16x16)
cli_expect_unchanged("${WORK}/field.vlf")

# 3. Every option is checked before anything is written.
file(WRITE "${WORK}/t.png" "a user's file")
cli_remember("${WORK}/t.png")
cli_expect_error(2 "--tolerance"
  trace --offscreen --scene cornell --width 8 --height 8 --samples 1 --tolerance nan
  --out "${WORK}/t.png")
cli_expect_unchanged("${WORK}/t.png")
cli_expect_error(2 "needs a value" lights procedural:sky --count= --out "${WORK}/l.csv")
cli_expect_error(2 "needs a value" render --offscreen --depth-scale= --out "${WORK}/d.png")
if (EXISTS "${WORK}/l.csv" OR EXISTS "${WORK}/d.png")
  message(FATAL_ERROR "an empty option value was taken as the default")
endif ()

# 4. Missing directories are reported up front, and a writer's failure is never "wrote".
cli_expect_error(2 "does not exist" bake "${user}" --out "${WORK}/no-such-dir/relief.png")
cli_expect_error(2 "does not exist" vlf propagate --out "${WORK}/no-such-dir/f.vlf" --directions 33
  --rays 8 --iterations 1)
cli_expect_error(2 "does not exist" trace --offscreen --scene cornell --width 8 --height 8 --samples 1
  --out "${WORK}/c.png" --exr "${WORK}/no-such-dir/c.exr")
if (EXISTS "${WORK}/c.png")
  message(FATAL_ERROR "trace wrote its PNG before finding --exr unwritable")
endif ()

# 5. Memory budgets refuse before allocating, with the size needed (exit 1, no abort).
cli_expect_error(1 "needs about" bake "${user}" --out "${WORK}/relief.exr" --memory-budget 0.00001)
cli_expect_error(1 "needs about" cone "${user}" --out "${WORK}/cone.exr" --memory-budget 0.00001)
cli_expect_error(1 "needs about"
  lights procedural:sky --resolution 64 --count 4 --out "${WORK}/l.csv" --memory-budget 0.00001)

# 6. A cone map in an integer format says how many ratios it clamps.
cli_expect_error(0 "clamped to 1" cone "${user}" --out "${WORK}/cone.png")

# 7. probe --merge: a 16-bit mask of 0.5 blends the two views (it was read as 32768, not 0.5).
# The total irradiance (one median-cut light) is linear in the map, so a blend's lies strictly
# between the two views' (the mask was clamped to 1: the first view only).
cli_execute(render --offscreen --size 48x48 --resolution 32 --lights 0 --out "${WORK}/second.png")
string(REPEAT "32768 " 64 row)
string(REPEAT "${row}\n" 32 rows)
file(WRITE "${WORK}/mask16.pgm" "P2\n64 32\n65535\n${rows}")
function (cli_total_red name)
  cli_expect_error(0 "" lights "${WORK}/${name}.exr" --count 1 --out "${WORK}/${name}.csv")
  file(STRINGS "${WORK}/${name}.csv" rows)
  list(GET rows 1 row)
  string(REPLACE "," ";" row "${row}")
  list(GET row 5 red)
  set(red_${name} "${red}" PARENT_SCOPE)
endfunction ()
cli_expect_error(0 "" probe "${user}" --width 64 --out "${WORK}/first.exr")
cli_expect_error(0 "" probe "${WORK}/second.png" --width 64 --out "${WORK}/second.exr")
cli_expect_error(0 "" probe "${user}" --merge "${WORK}/second.png" --mask "${WORK}/mask16.pgm"
  --width 64 --out "${WORK}/merged.exr")
cli_total_red(first)
cli_total_red(second)
cli_total_red(merged)
if (red_first LESS red_second)
  set(low ${red_first})
  set(high ${red_second})
else ()
  set(low ${red_second})
  set(high ${red_first})
endif ()
if (NOT (red_merged GREATER low AND red_merged LESS high)) # strictly: not one view only
  message(FATAL_ERROR "a 16-bit mask of 0.5 gave ${red_merged}, not between ${low} and ${high}")
endif ()

# 8. probe estimates its memory before converting (--width 32768 needed 12.8 GB unannounced).
cli_expect_error(1 "needs about" probe "${user}" --width 32768 --out "${WORK}/huge.exr"
  --memory-budget 1)

# 9. A light field that could never shoot (every direction along the emitter, or the room shrunk
# below a line cell by one far triangle) is refused before propagating, not saved dark.
cli_expect_error(1 "so few directions" vlf propagate --out "${WORK}/three.vlf" --directions 3 --rays 8)
file(READ "${CMAKE_CURRENT_LIST_DIR}/../../examples/data/cornell-box.obj" room)
string(REPLACE "mtllib cornell-box.mtl" "mtllib ${CMAKE_CURRENT_LIST_DIR}/../../examples/data/cornell-box.mtl" room "${room}")
string(REGEX MATCHALL "\nv " vertices "${room}")
list(LENGTH vertices count)
math(EXPR a "${count} + 1")
math(EXPR b "${count} + 2")
math(EXPR c "${count} + 3")
file(WRITE "${WORK}/far.obj"
  "${room}\nv 1000000 0 0\nv 1001000 0 0\nv 1000000 1000 0\nf ${a} ${b} ${c}\n")
cli_expect_error(1 "smaller than a line cell" vlf propagate "${WORK}/far.obj" --out "${WORK}/far.vlf")
if (EXISTS "${WORK}/three.vlf" OR EXISTS "${WORK}/far.vlf")
  message(FATAL_ERROR "a field that shoots nothing was written")
endif ()

# 10. trace --export-obj writes the .mtl beside the .obj through the one OBJ writer: a user's
# .mtl of that name is never replaced.
file(WRITE "${WORK}/users.mtl" "newmtl mine\n")
cli_remember("${WORK}/users.mtl")
cli_expect_error(1 "users.mtl: exists" trace --scene cornell --export-obj "${WORK}/users.obj")
cli_expect_unchanged("${WORK}/users.mtl")
cli_expect_error(0 "" trace --scene cornell --export-obj "${WORK}/box.obj")
file(STRINGS "${WORK}/box.mtl" emitters REGEX "^Ke [1-9]")
if (NOT emitters)
  message(FATAL_ERROR "box.mtl has no emitter")
endif ()

# 11. A writer's format is the command's, not the file name's: a PNG named r.exr, or a relief
# texture as a JPEG (its depth, in alpha, lost), is refused before any work, and nothing is
# written. A mistyped benchmark name is an unknown subcommand, not the default benchmark; a
# window that would wait for ever for a user (vlf view with no window, no frames) is refused.
cli_expect_error(2 "does not end in .png" render --offscreen --size 32x32 --out "${WORK}/r.exr")
cli_expect_error(2 "depth in alpha" bake "${user}" --out "${WORK}/relief.jpg")
cli_expect_error(2 "does not end in .png"
  trace --offscreen --scene cornell --width 8 --height 8 --samples 1 --out "${WORK}/t.exr")
cli_expect_error(2 "does not end in .exr"
  trace --offscreen --scene cornell --width 8 --height 8 --samples 1 --exr "${WORK}/t2.png")
cli_expect_error(2 "does not end in .png" vlf render "${WORK}/field.vlf" --out "${WORK}/v.exr")
cli_expect_error(2 "does not end in .png"
  vlf render "${WORK}/field.vlf" --mode geometry --out "${WORK}/v.jpg")
foreach (file r.exr relief.jpg t.exr t2.png v.exr v.jpg)
  if (EXISTS "${WORK}/${file}")
    message(FATAL_ERROR "${file} was written")
  endif ()
endforeach ()
cli_expect_error(2 "unknown subcommand 'foo'" bench foo --csv "${WORK}/bench.csv")
cli_expect_error(2 "--offscreen needs --frames" vlf view "${WORK}/field.vlf" --offscreen)
cli_expect_error(2 "--keys needs --frames" vlf view "${WORK}/field.vlf" --keys abc)
# Without an X server VTK's window aborts (SIGABRT): an ordinary error naming the way out.
set(display "$ENV{DISPLAY}")
unset(ENV{DISPLAY})
cli_expect_error(1 "run the command under scripts/xvfb.sh"
  render --offscreen --size 32x32 --out "${WORK}/no-display.png")
set(ENV{DISPLAY} "${display}")
# An unknown procedural environment is not a missing file; a --mode option without --mode says so.
cli_expect_error(1 "expected procedural:sky or procedural:sun"
  render --offscreen --size 32x32 --environment procedural:foo --out "${WORK}/sky.png")
cli_expect_error(2 "need --mode MODE"
  vlf render "${WORK}/field.vlf" --out "${WORK}/tone.png" --tone-map reinhard)
# 12. The default camera outside a closed room sees the walls' backs: an all-black image is
# written with a warning that says how to place the camera (the open box: no warning).
math(EXPR d "${count} + 4")
file(WRITE "${WORK}/closed.obj" "${room}\nv 0 0 0\nv 0 548.8 0\nv 556 548.8 0\nv 549.6 0 0\n"
  "usemtl white\nf ${a} ${b} ${c} ${d}\n")
cli_expect_error(0 "every pixel is black" trace --scene "${WORK}/closed.obj" --width 16 --height 16
  --samples 1 --out "${WORK}/closed.png")
cli_execute(trace --scene "${CMAKE_CURRENT_LIST_DIR}/../../examples/data/cornell-box.obj" --width 16
  --height 16 --samples 1 --out "${WORK}/open.png")
if (cli_stderr MATCHES "every pixel is black")
  message(FATAL_ERROR "the open box's image was called black:\n${cli_stderr}")
endif ()
# 13. A misspelt method or pattern is a usage error listing the names.
cli_expect_error(2 "the methods are texture, bump"
  render --offscreen --size 32x32 --method relief-mapping --out "${WORK}/method.png")
cli_expect_error(2 "the patterns are Bricks, Stone"
  render --offscreen --size 32x32 --pattern Brick --out "${WORK}/pattern.png")
