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
# Components are the module names: known ones are found, an unknown REQUIRED one fails
# find_package naming it (it was accepted without a word).
foreach (_case IN ITEMS "Relief ReliefTextures;0" "Relief NoSuchModule;1")
  list(GET _case 0 _components)
  list(GET _case 1 _must_fail)
  set(_project "${WORK}/components-${_must_fail}")
  file(WRITE "${_project}/CMakeLists.txt" "cmake_minimum_required(VERSION 3.16)\n"
    "project(MesolightComponents LANGUAGES C CXX)\n"
    "find_package(Mesolight REQUIRED COMPONENTS ${_components})\n")
  execute_process(COMMAND "${CMAKE_COMMAND}" -S "${_project}" -B "${_project}/build"
                          "-DCMAKE_PREFIX_PATH=${WORK}/prefix"
                  RESULT_VARIABLE rc OUTPUT_VARIABLE out ERROR_VARIABLE err)
  if (_must_fail AND (rc EQUAL 0 OR NOT "${out}${err}" MATCHES "NoSuchModule"))
    message(FATAL_ERROR "find_package(Mesolight COMPONENTS ${_components}) did not fail naming "
      "the unknown component:\n${out}\n${err}")
  elseif (NOT _must_fail AND NOT rc EQUAL 0)
    message(FATAL_ERROR "find_package(Mesolight COMPONENTS ${_components}) failed:\n${out}\n${err}")
  endif ()
endforeach ()
