// SPDX-License-Identifier: BSD-3-Clause
#include "vtkSMReliefSurfaceRepresentationProxy.h"

#include "vtkDataObject.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPVDataInformation.h"
#include "vtkPVRenderView.h"
#include "vtkPVRenderViewSettings.h"
#include "vtkSMInputProperty.h"
#include "vtkSMParaViewPipelineControllerWithRendering.h"
#include "vtkSMPropertyHelper.h"
#include "vtkSMPropertyIterator.h"
#include "vtkSMProxyManager.h"
#include "vtkSMRenderViewProxy.h"
#include "vtkSMSessionProxyManager.h"
#include "vtkSMSourceProxy.h"
#include "vtkSMViewProxy.h"
#include "vtkSmartPointer.h"

#include <cstring>
#include <utility>
#include <vector>

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

// Every source upstream of `start` (through all its input properties, recursively).
std::vector<vtkSMSourceProxy*> UpstreamSources(vtkSMSourceProxy* start)
{
  std::vector<vtkSMSourceProxy*> found;
  std::vector<vtkSMProxy*> pending{ start };
  std::set<vtkSMProxy*> visited{ start };
  while (!pending.empty())
  {
    vtkSMProxy* proxy = pending.back();
    pending.pop_back();
    vtkSmartPointer<vtkSMPropertyIterator> it;
    it.TakeReference(proxy->NewPropertyIterator());
    for (it->Begin(); !it->IsAtEnd(); it->Next())
    {
      auto* input = vtkSMInputProperty::SafeDownCast(it->GetProperty());
      if (!input)
      {
        continue;
      }
      for (unsigned int i = 0; i < input->GetNumberOfProxies(); ++i)
      {
        auto* producer = vtkSMSourceProxy::SafeDownCast(input->GetProxy(i));
        if (producer && visited.insert(producer).second)
        {
          found.push_back(producer);
          pending.push_back(producer);
        }
      }
    }
  }
  return found;
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
  this->FollowSceneDisplay(view);
  const bool hidden = this->HideUpstreamImages(composite, view);
  this->UpdateInteractionMode(composite, view, hidden);
}

//------------------------------------------------------------------------------
bool vtkSMReliefSurfaceRepresentationProxy::HideUpstreamImages(
  vtkSMProxy* composite, vtkSMProxy* view)
{
  auto* viewProxy = vtkSMViewProxy::SafeDownCast(view);
  if (!viewProxy || !ShownAsRelief(composite) || !composite->GetProperty("Input"))
  {
    return false;
  }
  auto* relief =
    vtkSMSourceProxy::SafeDownCast(vtkSMPropertyHelper(composite, "Input").GetAsProxy(0));
  if (!relief)
  {
    return false;
  }
  // Only the GUI's Apply hides inputs (see the class comment); a state file's visibility stands
  // for what is upstream when it is loaded.
  vtkSMProxyManager* manager = vtkSMProxyManager::GetProxyManager();
  const bool act = manager && manager->GetUndoStackBuilder() &&
    !(this->LoadedFromState && !this->InteractionModeChecked);
  bool hidden = false;
  vtkNew<vtkSMParaViewPipelineControllerWithRendering> controller;
  for (vtkSMSourceProxy* source : UpstreamSources(relief))
  {
    for (unsigned int port = 0; port < source->GetNumberOfOutputPorts(); ++port)
    {
      const auto key = std::make_pair(source->GetGlobalID(), static_cast<int>(port));
      if (!this->UpstreamPortsSeen.insert(key).second || !act)
      {
        continue;
      }
      vtkSMProxy* shown = viewProxy->FindRepresentation(source, static_cast<int>(port));
      if (!shown || !shown->GetProperty("Visibility") ||
        vtkSMPropertyHelper(shown, "Visibility").GetAsInt() != 1)
      {
        continue;
      }
      vtkPVDataInformation* info = source->GetDataInformation(port);
      if (info && info->DataSetTypeIsA("vtkImageData"))
      {
        controller->Hide(source, static_cast<int>(port), viewProxy);
        hidden = true;
      }
    }
  }
  return hidden;
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
  const bool fieldSet = this->GetProperty("LightField") &&
    vtkSMPropertyHelper(this, "LightField").GetNumberOfElements() > 0 &&
    vtkSMPropertyHelper(this, "LightField").GetAsProxy(0);
  const bool lightSet =
    info && info->GetArrayInformation(LightSetArrayName(), vtkDataObject::FIELD);
  // Properties of the proxy, so the panel's decorators hear of a change at once: Exposure and
  // Tone Mapping shade either, the light set's and the field's own settings only theirs.
  for (const auto& [name, value] : { std::pair<const char*, bool>{ "LightSetAttached", lightSet },
         std::pair<const char*, bool>{ "LightFieldAttached", fieldSet } })
  {
    if (this->GetProperty(name) && vtkSMPropertyHelper(this, name).GetAsInt() != (value ? 1 : 0))
    {
      vtkSMPropertyHelper(this, name).Set(value ? 1 : 0);
    }
  }
}

//------------------------------------------------------------------------------
void vtkSMReliefSurfaceRepresentationProxy::FollowSceneDisplay(vtkSMProxy* view)
{
  auto* viewProxy = vtkSMViewProxy::SafeDownCast(view);
  if (!viewProxy || !this->GetProperty("ReliefLightFieldSceneDisplay") ||
    vtkSMPropertyHelper(this, "ReliefLightFieldSceneDisplay").GetAsInt() == 0 ||
    !this->GetProperty("LightField") ||
    vtkSMPropertyHelper(this, "LightField").GetNumberOfElements() == 0)
  {
    return;
  }
  vtkSMPropertyHelper field(this, "LightField");
  auto* source = vtkSMSourceProxy::SafeDownCast(field.GetAsProxy(0));
  vtkSMProxy* scene =
    source ? viewProxy->FindRepresentation(source, field.GetOutputPort(0)) : nullptr;
  if (!scene || !scene->GetProperty("LightFieldExposure"))
  {
    return; // the field is not shown in this view: the relief's own settings
  }
  bool changed = false;
  bool inputChanged = false;
  const auto copy = [&](const char* from, const char* to)
  {
    const double value = vtkSMPropertyHelper(scene, from).GetAsDouble();
    if (this->GetProperty(to) && vtkSMPropertyHelper(this, to).GetAsDouble() != value)
    {
      vtkSMPropertyHelper(this, to).Set(value);
      changed = true;
    }
  };
  copy("LightFieldExposure", "Exposure");
  copy("LightFieldToneMapping", "ToneMapping"); // 0 clamp, 1 Reinhard: the relief's on/off
  copy("LightFieldAutoExposure", "ReliefLightFieldAutoExposure");
  // The movable object shadows the relief as it shadows the scene.
  copy("LightFieldShadowMode", "ReliefShadowMode");
  copy("LightFieldShadowMapResolution", "ReliefShadowMapResolution");
  if (scene->GetProperty("ShadowCaster") && this->GetProperty("ReliefShadowCaster"))
  {
    vtkSMPropertyHelper from(scene, "ShadowCaster");
    vtkSMPropertyHelper to(this, "ReliefShadowCaster");
    vtkSMProxy* caster = from.GetNumberOfElements() > 0 ? from.GetAsProxy(0) : nullptr;
    const unsigned int port = caster ? from.GetOutputPort(0) : 0;
    vtkSMProxy* current = to.GetNumberOfElements() > 0 ? to.GetAsProxy(0) : nullptr;
    if (caster != current || (caster && to.GetOutputPort(0) != port))
    {
      if (caster)
      {
        to.Set(caster, port);
      }
      else
      {
        to.RemoveAllValues();
      }
      changed = inputChanged = true;
    }
  }
  if (changed)
  {
    this->UpdateVTKObjects(); // before the render this update precedes
  }
  if (inputChanged && !this->UpdatingForCaster)
  {
    // A new input leaves the representation without delivered data until it updates: update
    // the view again now, so the render this update precedes shows the relief (with its
    // shadow), not nothing. The nested update finds nothing more to follow.
    this->UpdatingForCaster = true;
    viewProxy->Update();
    this->UpdatingForCaster = false;
  }
}

//------------------------------------------------------------------------------
void vtkSMReliefSurfaceRepresentationProxy::UpdateInteractionMode(
  vtkSMProxy* composite, vtkSMProxy* view, bool imagesHidden)
{
  auto* renderView = vtkSMRenderViewProxy::SafeDownCast(view);
  if (!renderView || !ShownAsRelief(composite))
  {
    return;
  }
  // Decided at the first update that shows the relief (a mode the user picks later stays), and
  // again only when images were hidden for it (the view framed them, not the relief).
  const bool first = !this->InteractionModeChecked;
  this->InteractionModeChecked = true;
  if ((!first && !imagesHidden) || (first && this->LoadedFromState) ||
    VisibleDataRepresentations(view) != 1)
  {
    return;
  }
  bool reset = imagesHidden;
  if (view->GetProperty("InteractionMode") &&
    vtkPVRenderViewSettings::GetInstance()->GetDefaultInteractionMode() ==
      vtkPVRenderViewSettings::AUTOMATIC &&
    vtkSMPropertyHelper(view, "InteractionMode").GetAsInt() == vtkPVRenderView::INTERACTION_MODE_2D)
  {
    vtkSMPropertyHelper(view, "InteractionMode").Set(vtkPVRenderView::INTERACTION_MODE_3D);
    view->UpdateProperty("InteractionMode", 1);
    reset = true;
  }
  if (reset)
  {
    // The 2D rule put the camera far along the flat axis for a parallel projection, or the camera
    // framed the images: frame the relief, as ParaView resets the camera for the only visible data.
    renderView->ResetCamera();
  }
}

//------------------------------------------------------------------------------
void vtkSMReliefSurfaceRepresentationProxy::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LoadedFromState: " << this->LoadedFromState << "\n";
  os << indent << "InteractionModeChecked: " << this->InteractionModeChecked << "\n";
}
