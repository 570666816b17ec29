// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the unit tests of the Mesolight modules (message capture, temporary files).
#ifndef MesolightTestUtilities_h
#define MesolightTestUtilities_h

#include "MessageCapture.h" // the one test observer of VTK errors and warnings

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace mesolight_test
{

/// A fresh, empty directory for the current test under the build tree.
inline std::filesystem::path TestDirectory()
{
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(MESOLIGHT_TEST_TEMP_DIR) /
    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

} // namespace mesolight_test

#endif
