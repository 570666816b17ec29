// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMReliefSurfaceRepresentationProxy.h"

#include "vtkDataObject.h"
#include "vtkObjectFactory.h"
#include "vtkPVDataInformation.h"
#include "vtkPVRenderView.h"
#include "vtkPVRenderViewSettings.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMRenderViewProxy.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"

#include <cstring>

vtkStandardNewMacro(vtkSMReliefSurfaceRepresentationProxy);

namespace
{
// The composite (Geometry / UnstructuredGrid representation) shows this sub-representation.
bool ShownAsRelief(vtkSMProxy* composite)
{
  if (!composite->GetProperty("Visibility") || !composite->GetProperty("Representation"))
  {
    return false;
  }
  const char* type = vtkSMPropertyHelper(composite, "Representation").GetAsString();
  return vtkSMPropertyHelper(composite, "Visibility").GetAsInt() == 1 && type &&
    std::strcmp(type, "Relief Surface") == 0;
}

// Visible representations of data in the view (pqView::getNumberOfVisibleDataRepresentations).
int VisibleDataRepresentations(vtkSMProxy* view)
{
  int count = 0;
  vtkSMPropertyHelper representations(view, "Representations");
  for (unsigned int i = 0; i < representations.GetNumberOfElements(); ++i)
  {
    vtkSMProxy* repr = representations.GetAsProxy(i);
    if (repr && repr->GetProperty("Input") && repr->GetProperty("Visibility") &&
      vtkSMPropertyHelper(repr, "Visibility").GetAsInt() == 1)
    {
      ++count;
    }
  }
  return count;
}
} // namespace

//------------------------------------------------------------------------------
vtkSMReliefSurfaceRepresentationProxy::vtkSMReliefSurfaceRepresentationProxy() = default;

//------------------------------------------------------------------------------
void vtkSMReliefSurfaceRepresentationProxy::CreateVTKObjects()
{
  if (!this->ObjectsCreated)
  {
    vtkSMSessionProxyManager* pxm = this->GetSessionProxyManager();
    this->LoadedFromState = pxm && pxm->GetInLoadXMLState();
  }
  this->Superclass::CreateVTKObjects();
}

//------------------------------------------------------------------------------
void vtkSMReliefSurfaceRepresentationProxy::ViewUpdated(vtkSMProxy* view)
{
  this->Superclass::ViewUpdated(view);
  vtkSMProxy* composite = this->GetParentProxy();
  if (!composite || !view)
  {
    return;
  }
  this->UpdateLightSetAttached(composite);
  this->UpdateInteractionMode(composite, view);
}

//------------------------------------------------------------------------------
void vtkSMReliefSurfaceRepresentationProxy::UpdateLightSetAttached(vtkSMProxy* composite)
{
  if (!this->GetProperty("LightSetAttached") || !composite->GetProperty("Input"))
  {
    return;
  }
  vtkSMPropertyHelper input(composite, "Input");
  auto* source = vtkSMSourceProxy::SafeDownCast(input.GetAsProxy(0));
  if (!source)
  {
    return;
  }
  vtkPVDataInformation* info = source->GetDataInformation(input.GetOutputPort(0));
  const int attached =
    info && info->GetArrayInformation(LightSetArrayName(), vtkDataObject::FIELD) ? 1 : 0;
  vtkSMPropertyHelper flag(this, "LightSetAttached");
  if (flag.GetAsInt() != attached)
  {
    // A property of the proxy, so the panel's decorators hear of the change at once.
    flag.Set(attached);
  }
}

//------------------------------------------------------------------------------
void vtkSMReliefSurfaceRepresentationProxy::UpdateInteractionMode(
  vtkSMProxy* composite, vtkSMProxy* view)
{
  auto* renderView = vtkSMRenderViewProxy::SafeDownCast(view);
  if (this->InteractionModeChecked || !renderView || !ShownAsRelief(composite))
  {
    return;
  }
  // Decided once, at the first update that shows the relief: a mode the user picks later stays.
  this->InteractionModeChecked = true;
  if (this->LoadedFromState || !view->GetProperty("InteractionMode") ||
    vtkPVRenderViewSettings::GetInstance()->GetDefaultInteractionMode() !=
      vtkPVRenderViewSettings::AUTOMATIC ||
    vtkSMPropertyHelper(view, "InteractionMode").GetAsInt() !=
      vtkPVRenderView::INTERACTION_MODE_2D ||
    VisibleDataRepresentations(view) != 1)
  {
    return;
  }
  vtkSMPropertyHelper(view, "InteractionMode").Set(vtkPVRenderView::INTERACTION_MODE_3D);
  view->UpdateProperty("InteractionMode", 1);
  // The 2D rule put the camera far along the flat axis for a parallel projection; frame the
  // relief for the perspective one, as ParaView resets the camera for the only visible data.
  renderView->ResetCamera();
}

//------------------------------------------------------------------------------
void vtkSMReliefSurfaceRepresentationProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LoadedFromState: " << this->LoadedFromState << "\n";
  os << indent << "InteractionModeChecked: " << this->InteractionModeChecked << "\n";
}
