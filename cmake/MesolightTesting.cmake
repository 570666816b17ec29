# SPDX-License-Identifier: BSD-3-Clause
# How every GoogleTest executable registers its tests with CTest: one place, one policy.
include(GoogleTest)

# mesolight_discover_tests(<target> [<test property> <value>]...)
#
# The test list is read when ctest starts (PRE_TEST), so building needs no display and no run of
# the test programs. Listing loads every library a program links (VTK, Embree, OpenImageIO, TBB);
# on a machine whose disk cache is cold that took 21 s here for one program, far past CMake's 5 s
# default, and a listing that times out stops ctest before it runs any test (exit code 8, with
# no test named as failed). Hence the long discovery timeout.
function(mesolight_discover_tests target)
  gtest_discover_tests(${target}
    DISCOVERY_MODE PRE_TEST
    DISCOVERY_TIMEOUT 300
    PROPERTIES ${ARGN})
endfunction()
