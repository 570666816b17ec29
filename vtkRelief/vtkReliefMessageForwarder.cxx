// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefMessageForwarder.h"

#include "vtkObject.h"
#include "vtkOutputWindow.h"

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
void vtkReliefMessageForwarder::Execute(vtkObject*, unsigned long event, void* callData)
{
  vtkObject* owner = this->Owner;
  if (owner && owner->HasObserver(event))
  {
    owner->InvokeEvent(event, callData);
  }
  else if (event == vtkCommand::ErrorEvent)
  {
    vtkOutputWindowDisplayErrorText(static_cast<const char*>(callData));
  }
  else
  {
    vtkOutputWindowDisplayWarningText(static_cast<const char*>(callData));
  }
}
