// SPDX-License-Identifier: BSD-3-Clause
// Helpers shared by the unit tests of the Mesolight modules (message capture, temporary files).
#ifndef MesolightTestUtilities_h
#define MesolightTestUtilities_h

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkSmartPointer.h"

#include <gtest/gtest.h>

#include <filesystem>
#include <string>
#include <vector>

namespace mesolight_test
{

/**
 * Records ErrorEvent / WarningEvent messages of an algorithm (and of its executive, whose
 * "returned failure" follow-up is expected noise), so tests can assert on them and the
 * console stays quiet.
 */
class MessageCapture : public vtkCommand
{
public:
  static MessageCapture* New() { return new MessageCapture; }

  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    const std::string text = callData ? static_cast<const char*>(callData) : "";
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings).push_back(text);
  }

  void Watch(vtkAlgorithm* algorithm)
  {
    algorithm->AddObserver(vtkCommand::ErrorEvent, this);
    algorithm->AddObserver(vtkCommand::WarningEvent, this);
    this->ExecutiveErrors = vtkSmartPointer<Silencer>::New();
    algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->ExecutiveErrors);
  }

  bool HasError(const std::string& needle) const { return Contains(this->Errors, needle); }
  bool HasWarning(const std::string& needle) const { return Contains(this->Warnings, needle); }
  std::string AllErrors() const { return Join(this->Errors); }

  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;

private:
  class Silencer : public vtkCommand
  {
  public:
    static Silencer* New() { return new Silencer; }
    void Execute(vtkObject*, unsigned long, void*) override {}
  };
  vtkSmartPointer<Silencer> ExecutiveErrors;

  static bool Contains(const std::vector<std::string>& messages, const std::string& needle)
  {
    for (const auto& m : messages)
    {
      if (m.find(needle) != std::string::npos)
      {
        return true;
      }
    }
    return false;
  }
  static std::string Join(const std::vector<std::string>& messages)
  {
    std::string all;
    for (const auto& m : messages)
    {
      all += m + "\n";
    }
    return all;
  }
};

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
