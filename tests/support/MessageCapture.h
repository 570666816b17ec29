// SPDX-License-Identifier: BSD-3-Clause
// MessageCapture: the one test observer of VTK errors and warnings, for every test that expects
// (or forbids) a message. VTK only, no test framework, so any test target can include it.
#ifndef MesolightMessageCapture_h
#define MesolightMessageCapture_h

#include "vtkAlgorithm.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkSmartPointer.h"

#include <string>
#include <vector>

namespace mesolight_test
{

/**
 * Records the ErrorEvent / WarningEvent messages of the objects it watches (the full VTK text,
 * location line included), so tests can assert on them and the console stays quiet. For an
 * algorithm it also silences its executive, whose "returned failure" follow-up is expected noise.
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

  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
    if (auto* algorithm = vtkAlgorithm::SafeDownCast(object))
    {
      if (!this->ExecutiveErrors)
      {
        this->ExecutiveErrors = vtkSmartPointer<Silencer>::New();
      }
      algorithm->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, this->ExecutiveErrors);
    }
  }

  bool HasError(const std::string& needle) const { return Contains(this->Errors, needle); }
  bool HasWarning(const std::string& needle) const { return Contains(this->Warnings, needle); }
  std::string AllErrors() const { return Join(this->Errors); }
  std::string AllWarnings() const { return Join(this->Warnings); }
  void Clear()
  {
    this->Errors.clear();
    this->Warnings.clear();
  }

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

} // namespace mesolight_test

#endif
