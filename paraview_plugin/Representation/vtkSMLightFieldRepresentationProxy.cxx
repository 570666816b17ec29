// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMLightFieldRepresentationProxy.h"

#include "vtkObjectFactory.h"
#include "vtkSMPVRepresentationProxy.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMSessionProxyManager.h"

#include <cstring>

vtkStandardNewMacro(vtkSMLightFieldRepresentationProxy);

//------------------------------------------------------------------------------
vtkSMLightFieldRepresentationProxy::vtkSMLightFieldRepresentationProxy() = default;

//------------------------------------------------------------------------------
void vtkSMLightFieldRepresentationProxy::CreateVTKObjects()
{
  if (!this->ObjectsCreated)
  {
    vtkSMSessionProxyManager* pxm = this->GetSessionProxyManager();
    this->LoadedFromState = pxm && pxm->GetInLoadXMLState();
  }
  this->Superclass::CreateVTKObjects();
}

//------------------------------------------------------------------------------
void vtkSMLightFieldRepresentationProxy::ViewUpdated(vtkSMProxy* view)
{
  this->Superclass::ViewUpdated(view);
  vtkSMProxy* composite = this->GetParentProxy();
  if (this->ColoringChecked || !composite || !view || !composite->GetProperty("Representation") ||
    !composite->GetProperty("Visibility"))
  {
    return;
  }
  const char* type = vtkSMPropertyHelper(composite, "Representation").GetAsString();
  if (!type || std::strcmp(type, "Light Field") != 0 ||
    vtkSMPropertyHelper(composite, "Visibility").GetAsInt() != 1)
  {
    return;
  }
  this->ColoringChecked = true;
  if (this->LoadedFromState || !vtkSMPVRepresentationProxy::GetUsingScalarColoring(composite))
  {
    return;
  }
  vtkSMPVRepresentationProxy::SetScalarColoring(composite, nullptr, 0);
  vtkSMPVRepresentationProxy::HideScalarBarIfNotNeeded(composite, view);
}

//------------------------------------------------------------------------------
void vtkSMLightFieldRepresentationProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LoadedFromState: " << this->LoadedFromState << "\n";
  os << indent << "ColoringChecked: " << this->ColoringChecked << "\n";
}
