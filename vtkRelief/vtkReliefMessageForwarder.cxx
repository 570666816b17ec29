// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefMessageForwarder.h"

#include "vtkObject.h"
#include "vtkOutputWindow.h"

#include <sstream>
#include <string>

namespace
{
// The message as the owner's: "vtkReliefGeometryCache (0x...): text" becomes
// "vtkReliefMapper (0x...): text", the object the user made and watches.
std::string AttributedToOwner(const char* message, vtkObject* caller, vtkObject* owner)
{
  std::string text = message ? message : "";
  const std::string from = std::string(caller->GetClassName()) + " (";
  const std::size_t start = text.find(from);
  const std::size_t end = start == std::string::npos ? start : text.find("): ", start);
  if (end == std::string::npos)
  {
    return text;
  }
  std::ostringstream to;
  to << owner->GetClassName() << " (" << static_cast<const void*>(owner) << ")";
  return text.replace(start, end + 1 - start, to.str());
}
}

//------------------------------------------------------------------------------
vtkReliefMessageForwarder* vtkReliefMessageForwarder::New()
{
  return new vtkReliefMessageForwarder;
}

//------------------------------------------------------------------------------
void vtkReliefMessageForwarder::Watch(vtkObject* source)
{
  source->AddObserver(vtkCommand::ErrorEvent, this);
  source->AddObserver(vtkCommand::WarningEvent, this);
}

//------------------------------------------------------------------------------
void vtkReliefMessageForwarder::Execute(vtkObject* caller, unsigned long event, void* callData)
{
  vtkObject* owner = this->Owner;
  const char* message = static_cast<const char*>(callData);
  std::string attributed;
  if (owner && caller && caller != owner)
  {
    attributed = AttributedToOwner(message, caller, owner);
    message = attributed.c_str();
  }
  if (owner && owner->HasObserver(event))
  {
    owner->InvokeEvent(event, const_cast<char*>(message));
  }
  else if (event == vtkCommand::ErrorEvent)
  {
    vtkOutputWindowDisplayErrorText(message);
  }
  else
  {
    vtkOutputWindowDisplayWarningText(message);
  }
}
