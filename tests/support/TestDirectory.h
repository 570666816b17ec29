// SPDX-License-Identifier: BSD-3-Clause
// A fresh directory per test, written once for the modules' unit tests and the algorithm cores'
// (which build without VTK, so this header includes none of it).
#ifndef mesolight_TestDirectory_h
#define mesolight_TestDirectory_h

#include <gtest/gtest.h>

#include <filesystem>
#include <string>

namespace mesolight_test
{

/// A fresh, empty directory for the current test under the build tree (MESOLIGHT_TEST_TEMP_DIR,
/// set by the test target), named after the test.
inline std::filesystem::path TestDirectory()
{
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(MESOLIGHT_TEST_TEMP_DIR) /
    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  return dir;
}

/// A file of the current test: `name` in the test's own directory under MESOLIGHT_TEST_TEMP_DIR
/// (created if missing, not emptied). ctest runs each test in its own process, in parallel: a
/// name shared by two tests of one executable was a race between them.
inline std::string TestPath(const std::string& name)
{
  const ::testing::TestInfo* info = ::testing::UnitTest::GetInstance()->current_test_info();
  std::filesystem::path dir = std::filesystem::path(MESOLIGHT_TEST_TEMP_DIR) /
    (std::string(info->test_suite_name()) + "." + info->name());
  std::filesystem::create_directories(dir);
  return (dir / name).string();
}

} // namespace mesolight_test

#endif
