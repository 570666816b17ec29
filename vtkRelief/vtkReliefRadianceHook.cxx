// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefRadianceHook.h"

//------------------------------------------------------------------------------
vtkReliefRadianceHook::vtkReliefRadianceHook() = default;
vtkReliefRadianceHook::~vtkReliefRadianceHook() = default;

//------------------------------------------------------------------------------
void vtkReliefRadianceHook::ReleaseGraphicsResources(vtkWindow*) {}

//------------------------------------------------------------------------------
void vtkReliefRadianceHook::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
}
