# SPDX-License-Identifier: BSD-3-Clause
# `render --lights-csv` with a light set the renderer cannot hold or a spreadsheet's CSV: an
# irradiance above single precision (which rendered the whole relief black with exit 0) is
# refused naming the line and field; a UTF-8 byte order mark is skipped; a binary file's bytes
# are never echoed raw to the terminal.
include("${CMAKE_CURRENT_LIST_DIR}/RunTool.cmake")
cli_fresh_work()
set(header "u,v,x,y,z,r,g,b\n")
set(row "0.25,0.5,0,1,0,1,2,3\n")
foreach (value IN ITEMS 1e39 3.5e38)
  file(WRITE "${WORK}/${value}.csv" "${header}${row}0.25,0.5,0,1,0,${value},2,3\n")
  cli_expect_error(1 "line 3: the r field \"${value}\" is outside single precision"
    render --offscreen --size 64x64 --resolution 32 --lights 0
    --lights-csv "${WORK}/${value}.csv" --out "${WORK}/${value}.png")
  if (EXISTS "${WORK}/${value}.png")
    message(FATAL_ERROR "an image was written from the ${value} light set")
  endif ()
endforeach ()
string(ASCII 239 187 191 bom)
file(WRITE "${WORK}/bom.csv" "${bom}${header}${row}")
cli_run(TRUE render --offscreen --size 64x64 --resolution 32 --lights 0
        --lights-csv "${WORK}/bom.csv" --out "${WORK}/bom.png")
string(ASCII 27 escape)
string(ASCII 7 bell)
file(WRITE "${WORK}/binary.csv" "${escape}[2J${bell}u,v\n")
cli_expect_error(1 "the header is \"\\x1B[2J\\x07u,v\""
  render --offscreen --size 64x64 --resolution 32 --lights 0
  --lights-csv "${WORK}/binary.csv" --out "${WORK}/binary.png")
if (last_stderr MATCHES "${escape}|${bell}")
  message(FATAL_ERROR "raw bytes of the binary CSV were echoed: ${last_stderr}")
endif ()
