# SPDX-License-Identifier: BSD-3-Clause
# `cmake --install` must give a VTK C++ user modules to find_package and link: install this
# build into a scratch prefix, then configure and build examples/cxx on its own against it, and
# the README's C++ snippets as written (tests/readme-snippets).
file(REMOVE_RECURSE "${WORK}")
execute_process(COMMAND "${CMAKE_COMMAND}" --install "${BUILD}" --prefix "${WORK}/prefix"
                RESULT_VARIABLE rc OUTPUT_QUIET)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "cmake --install failed (${rc})")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE}/examples/cxx" -B "${WORK}/consumer"
                        "-DCMAKE_PREFIX_PATH=${WORK}/prefix" -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring a consumer of the installed Mesolight failed:\n${out}\n${err}")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK}/consumer"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "building a consumer of the installed Mesolight failed:\n${out}\n${err}")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" -S "${SOURCE}/tests/readme-snippets"
                        -B "${WORK}/readme-snippets" "-DCMAKE_PREFIX_PATH=${WORK}/prefix"
                        "-DMESOLIGHT_README=${SOURCE}/README.md" -DCMAKE_BUILD_TYPE=Release
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "configuring the README's C++ snippets failed:\n${out}\n${err}")
endif ()
execute_process(COMMAND "${CMAKE_COMMAND}" --build "${WORK}/readme-snippets"
                RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
if (NOT rc EQUAL 0)
  message(FATAL_ERROR "building the README's C++ snippets as written failed:\n${out}\n${err}")
endif ()
