# SPDX-License-Identifier: BSD-3-Clause
# How every GoogleTest executable registers its tests with CTest: one place, one policy.
include(GoogleTest)

# mesolight_discover_tests(<target> <area> [<test property> <value>]...)
#
# Each test is named <area>.<suite>.<case>: <area> is the module the program tests (Relief,
# LightField, LightFieldActor, Scene, RayTracing, Lighting, ...), so `ctest -R '^LightField\.'` runs
# one module's tests; the GoogleTest suite and case names are the program's own (what
# --gtest_filter selects). The tool's tests are cli.* (tests/cli), the fuzz corpus replays fuzz.*,
# the installed package's install.*, the cores-only build's cores.*.
#
# The test list is read when ctest starts (PRE_TEST), so building needs no display and no run of
# the test programs. Listing loads every library a program links (VTK, Embree, OpenImageIO, TBB);
# on a machine whose disk cache is cold that took 21 s here for one program, far past CMake's 5 s
# default, and a listing that times out stops ctest before it runs any test (exit code 8, with
# no test named as failed). Hence the long discovery timeout.
function(mesolight_discover_tests target area)
  if (NOT area MATCHES "^[A-Z][A-Za-z]+$")
    message(FATAL_ERROR "mesolight_discover_tests(${target}): '${area}' is not a module's name")
  endif ()
  gtest_discover_tests(${target}
    TEST_PREFIX "${area}."
    DISCOVERY_MODE PRE_TEST
    DISCOVERY_TIMEOUT 300
    PROPERTIES ${ARGN})
endfunction()

# mesolight_cli_test(NAME <command>.<case>
#                    ARGS <argument>... | SCRIPT <file.cmake> [DEFINES <var>=<value>...] |
#                    COMMAND <command>...
#                    [PASS_REGEX <regex>] [WILL_FAIL] [LABELS <label>...] [TIMEOUT <seconds>]
#                    [SKIP_RETURN_CODE <code>] [FIXTURES_SETUP <name>...]
#                    [FIXTURES_REQUIRED <name>...])
#
# The one way a test of the `mesolight` tool is registered (tests/cli/): the test is named
# cli.<command>.<case>, <command> the tool's command it runs (render, bake, vlf, bench, ...; `tool`
# for the tool as a whole), <case> lower case with underscores, so `ctest -R '^cli\.'` runs them
# all and `ctest -R '^cli\.vlf\.'` one command's.
#   ARGS     runs `mesolight <argument>...`.
#   SCRIPT   runs `cmake -DCLI=<the tool> -DWORK=<work> -D<define>... -P <file.cmake>` (the file
#            relative to the calling directory; it includes RunTool.cmake); <work> is
#            ${MESOLIGHT_CLI_WORK}/<command>.<case>, which the script empties.
#   COMMAND  runs a command of its own (a shell line that runs the tool several times, a comparison
#            script); $<TARGET_FILE:mesolight> in it is the tool.
# PASS_REGEX, WILL_FAIL, LABELS, TIMEOUT, SKIP_RETURN_CODE and the fixtures are the CTest test
# properties of those names (PASS_REGULAR_EXPRESSION for PASS_REGEX).
function(mesolight_cli_test)
  cmake_parse_arguments(PARSE_ARGV 0 _cli "WILL_FAIL"
    "NAME;SCRIPT;PASS_REGEX;TIMEOUT;SKIP_RETURN_CODE"
    "ARGS;COMMAND;DEFINES;LABELS;FIXTURES_SETUP;FIXTURES_REQUIRED")
  if (_cli_UNPARSED_ARGUMENTS)
    message(FATAL_ERROR "mesolight_cli_test(${_cli_NAME}): unknown arguments ${_cli_UNPARSED_ARGUMENTS}")
  endif ()
  if (NOT _cli_NAME MATCHES "^[a-z]+\\.[a-z0-9_]+$")
    message(FATAL_ERROR "mesolight_cli_test: '${_cli_NAME}' is not <command>.<case> "
      "(lower case, the case's words joined by '_')")
  endif ()
  set(_name "cli.${_cli_NAME}")
  if (_cli_SCRIPT)
    if (NOT IS_ABSOLUTE "${_cli_SCRIPT}")
      set(_cli_SCRIPT "${CMAKE_CURRENT_SOURCE_DIR}/${_cli_SCRIPT}")
    endif ()
    set(_defines)
    foreach (_define IN LISTS _cli_DEFINES)
      list(APPEND _defines "-D${_define}")
    endforeach ()
    add_test(NAME ${_name}
      COMMAND ${CMAKE_COMMAND} "-DCLI=$<TARGET_FILE:mesolight>"
        "-DWORK=${MESOLIGHT_CLI_WORK}/${_cli_NAME}" ${_defines} -P "${_cli_SCRIPT}")
  elseif (_cli_COMMAND)
    add_test(NAME ${_name} COMMAND ${_cli_COMMAND})
  else ()
    add_test(NAME ${_name} COMMAND $<TARGET_FILE:mesolight> ${_cli_ARGS})
  endif ()
  # One property at a time: a list value (two labels) stays one value.
  if (DEFINED _cli_PASS_REGEX)
    set_property(TEST ${_name} PROPERTY PASS_REGULAR_EXPRESSION "${_cli_PASS_REGEX}")
  endif ()
  if (_cli_WILL_FAIL)
    set_property(TEST ${_name} PROPERTY WILL_FAIL TRUE)
  endif ()
  foreach (_property IN ITEMS LABELS TIMEOUT SKIP_RETURN_CODE FIXTURES_SETUP FIXTURES_REQUIRED)
    if (DEFINED _cli_${_property})
      set_property(TEST ${_name} PROPERTY ${_property} ${_cli_${_property}})
    endif ()
  endforeach ()
endfunction()
