// SPDX-License-Identifier: BSD-3-Clause
// Real height maps for the tests: game textures' height channels from Debian's
// redeclipse-data (512^2, white = high), rougher and noisier than the procedural patterns, which
// no figure was tuned on. scripts/test.sh (the README's test command, and so CI) installs the
// package and sets MESOLIGHT_REQUIRE_REAL_MAPS=1: there a missing map fails the test instead of
// skipping it, so the real-data checks cannot silently stop running. Elsewhere
// (MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh installs the package, about 860 MB) a test
// without its maps is skipped.
#ifndef mesolight_RealHeightMaps_h
#define mesolight_RealHeightMaps_h

#include <gtest/gtest.h>

#include <cstdlib>
#include <fstream>
#include <string>

namespace mesolight_test
{

/**
 * The path of redeclipse-data's map `name` (e.g. "dziq/dq_stones01_b.jpg"), or "" when it is
 * absent, which is a test failure where MESOLIGHT_REQUIRE_REAL_MAPS=1.
 */
inline std::string FindRealHeightMap(const std::string& name)
{
  const std::string path = "/usr/share/games/redeclipse/data/" + name;
  if (std::ifstream(path).good())
  {
    return path;
  }
  const char* required = std::getenv("MESOLIGHT_REQUIRE_REAL_MAPS");
  if (required && std::string(required) == "1")
  {
    ADD_FAILURE() << path << " is absent, and MESOLIGHT_REQUIRE_REAL_MAPS=1 requires it "
                  << "(MESOLIGHT_REAL_MAPS=1 scripts/install-deps.sh installs redeclipse-data)";
  }
  return "";
}

} // namespace mesolight_test

#endif
