// SPDX-License-Identifier: BSD-3-Clause
// MessageCollector: how a program shows the vtkErrorMacro / vtkWarningMacro messages of the
// objects it drives as its own (the mesolight tool, the evaluation scenes). Tests use
// tests/support/MessageCapture.h, which keeps VTK's full text.
#ifndef mesolight_vtkMessageCollector_h
#define mesolight_vtkMessageCollector_h

#include "VTKMessage.h"

#include <vtkCommand.h>
#include <vtkObject.h>

#include <functional>
#include <string>
#include <vector>

namespace mesolight
{

/**
 * Observes ErrorEvent and WarningEvent of the objects it watches (VTK then prints nothing of
 * them) and keeps each message as CleanVTKMessage gives it: one line, without VTK's location
 * and object prefix. With OnMessage set, each is also handed on as it arrives.
 */
class MessageCollector : public vtkCommand
{
public:
  static MessageCollector* New() { return new MessageCollector; }

  /** Observes `object`'s ErrorEvent and WarningEvent. */
  void Watch(vtkObject* object)
  {
    object->AddObserver(vtkCommand::ErrorEvent, this);
    object->AddObserver(vtkCommand::WarningEvent, this);
  }

  void Execute(vtkObject*, unsigned long event, void* callData) override
  {
    if (!callData)
    {
      return;
    }
    const std::string text = CleanVTKMessage(static_cast<const char*>(callData));
    const bool error = event == vtkCommand::ErrorEvent;
    (error ? this->Errors : this->Warnings).push_back(text);
    if (this->OnMessage)
    {
      this->OnMessage(error, text);
    }
  }

  /** The errors so far, joined by "; " ("" when none). */
  std::string ErrorText() const
  {
    std::string all;
    for (const std::string& e : this->Errors)
    {
      all += (all.empty() ? "" : "; ") + e;
    }
    return all;
  }

  std::vector<std::string> Errors;
  std::vector<std::string> Warnings;
  /** Called with (is an error, cleaned text) for each message, after it is kept. */
  std::function<void(bool, const std::string&)> OnMessage;
};

} // namespace mesolight

#endif
