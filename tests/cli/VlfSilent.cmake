# SPDX-License-Identifier: BSD-3-Clause
# mesolight vlf: options that used to be silently ignored or blamed on the wrong cause (exit 0 or
# a misleading message) are clear errors naming the option: --resume with other settings than
# the stored ones, object options without --object, a directory as --object, an object transform
# beyond single precision; and `vlf render --help` lists the walkthrough's options.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
set(field "${WORK}/cornell.vlf")
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 1 --out "${field}")

# --resume keeps the stored settings: other values are refused, naming both.
cli_expect_error(2 "--resume: --directions 129 differs from the 33 stored in"
  vlf propagate --resume --iterations 2 --directions 129 --out "${field}")
cli_expect_error(2 "--resume: --rays 32 differs from the 16 stored in"
  vlf propagate --resume --iterations 2 --rays 32 --out "${field}")
cli_expect_error(2 "--resume: --tiles 1 differs from the 2 stored in"
  vlf propagate --resume --iterations 2 --tiles 1 --out "${field}")
cli_expect_error(2 "--resume: --contact-texels 1 differs from the 0 stored in"
  vlf propagate --resume --iterations 2 --contact-texels 1 --out "${field}")
cli_expect_error(2 "--contact-texels"
  vlf propagate --directions 33 --rays 16 --iterations 1 --contact-texels 4 --force
  --out "${field}")
# Texels from the light: a first pass chooses each surface's texels, the field file keeps them
# (a render reads it); on top of given contact texels; the options it cannot keep are refused,
# naming it.
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 1 --adaptive-texels
  --out "${WORK}/adaptive.vlf")
if (NOT last_output MATCHES "adaptive texels: texels finer on [0-9]+, coarser on 0 of 17 surfaces")
  message(FATAL_ERROR "no adaptive texel report: ${last_output}")
endif ()
cli_run(TRUE vlf render "${WORK}/adaptive.vlf" --size 32x32 --out "${WORK}/adaptive.png")
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 1 --adaptive-texels
  --contact-texels 1 --out "${WORK}/adaptive-contact.vlf")
if (NOT last_output MATCHES "texels; [1-9][0-9]* contact surfaces")
  message(FATAL_ERROR "the adaptive texels left out the contact texels: ${last_output}")
endif ()
# The gather budget: 0 leaves no refinement beyond the contact texels (the report says so);
# unbounded it refines (the negative); a budget that is not a number is refused, naming it.
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 1 --adaptive-texels
  --contact-texels 1 --adaptive-budget 0 --out "${WORK}/adaptive-budget.vlf")
if (NOT last_output MATCHES " 0 finer than the contact texels alone")
  message(FATAL_ERROR "--adaptive-budget 0 refined beyond the contact texels: ${last_output}")
endif ()
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 1 --adaptive-texels
  --contact-texels 1 --adaptive-budget -1 --out "${WORK}/adaptive-unbounded.vlf")
if (last_output MATCHES " 0 finer than the contact texels alone")
  message(FATAL_ERROR "unbounded, nothing refined beyond the contact texels: ${last_output}")
endif ()
cli_expect_error(2 "--adaptive-budget"
  vlf propagate --directions 33 --rays 16 --iterations 1 --adaptive-texels --adaptive-budget x
  --out "${WORK}/adaptive-refused.vlf")
# Given rays: no first pass unless asked for.
cli_run(TRUE vlf propagate --directions 33 --rays 16 --iterations 1 --out "${WORK}/given.vlf")
if (last_output MATCHES "adaptive texels:")
  message(FATAL_ERROR "a first pass with given rays: ${last_output}")
endif ()
cli_expect_error(2 "--adaptive-texels excludes"
  vlf propagate --directions 33 --rays 16 --iterations 1 --adaptive-texels --no-gather
  --out "${WORK}/adaptive-refused.vlf")
cli_expect_error(2 "--adaptive-texels and --no-adaptive-texels exclude each other"
  vlf propagate --directions 33 --rays 16 --iterations 1 --adaptive-texels --no-adaptive-texels
  --out "${WORK}/adaptive-refused.vlf")
cli_expect_error(2 "--adaptive-texels excludes"
  vlf propagate --iterations 2 --adaptive-texels --resume --out "${WORK}/adaptive.vlf")
# The same values (or none) resume.
cli_run(TRUE vlf propagate --resume --iterations 2 --directions 33 --rays 16 --tiles 2
        --out "${field}")

# Object options without --object would be ignored.
foreach (option IN ITEMS "--shading;flat" "--shadows;none" "--shadow-emitters;2" "--subdivision;2"
                         "--object-colour;1,0,0" "--gather-directions;half" "--gather-volume;4")
  list(GET option 0 name)
  cli_expect_error(2 "${name} needs --object"
    vlf render "${field}" --mode coherent --size 32x32 ${option} --out "${WORK}/never.png")
endforeach ()
if (EXISTS "${WORK}/never.png")
  message(FATAL_ERROR "an image was written with an object option but no object")
endif ()

# A directory is not "an object with no faces".
cli_expect_error(2 "--object '${WORK}' is a directory"
  vlf render "${field}" --mode coherent --size 32x32 --object "${WORK}" --out "${WORK}/never.png")
# A transform beyond single precision is out of range, not "zero area".
cli_expect_error(2 "--object-transform is out of range"
  vlf render "${field}" --mode coherent --size 32x32 --object sphere
  --object-transform 300,300,300,0,0,0,1e30 --out "${WORK}/never.png")
cli_expect_error(2 "--object-transform is out of range"
  vlf render "${field}" --mode coherent --size 32x32 --object sphere
  --object-transform 1e30,0,0 --out "${WORK}/never.png")

# The help without --mode shows the walkthrough's options too.
cli_run(TRUE vlf render --help)
foreach (option IN ITEMS --mode --object --shading --shadows --subdivision --exposure --compare-exr)
  string(FIND "${last_output}" "${option}" at)
  if (at EQUAL -1)
    message(FATAL_ERROR "vlf render --help does not list ${option}:\n${last_output}")
  endif ()
endforeach ()

# An --exr that would overwrite the field is labelled --exr, not --out.
cli_expect_error(2 "--exr: '${field}' would overwrite"
  vlf render "${field}" --size 32x32 --out "${WORK}/never.png" --exr "${field}")

# An object a million units beside the field rendered all black with no message (the clipping
# range, holding both, clipped the field away): refused naming the option.
cli_expect_error(2 "--object-transform puts the object"
  vlf render "${field}" --mode coherent --size 32x32 --object sphere
  --object-transform 1e6,1e6,1e6 --out "${WORK}/never.png")

set(data "${CMAKE_CURRENT_LIST_DIR}/../../examples/data")
# Triangles 3000 mm beside the Cornell box: the field, scaled to the whole bounding box, had 730
# texels fall to 19 and the image darken by half, with exit 0 and no word. Now a warning.
configure_file("${data}/cornell-box.mtl" "${WORK}/cornell-box.mtl" COPYONLY)
file(READ "${data}/cornell-box.obj" obj)
file(WRITE "${WORK}/far.obj" "${obj}\nv 3000 0 0\nv 3050 0 0\nv 3000 50 0\nf -3 -2 -1\n")
cli_expect_error(0 "times the size of the box holding 98% of its surface area"
  vlf propagate "${WORK}/far.obj" --directions 33 --rays 16 --iterations 1 --out "${WORK}/far.vlf")
cli_execute(vlf propagate "${data}/cornell-box.obj" --directions 33 --rays 16
  --iterations 1 --out "${WORK}/near.vlf")
if (cli_stderr MATCHES "bounding box is")
  message(FATAL_ERROR "the plain Cornell box was warned about: ${cli_stderr}")
endif ()
