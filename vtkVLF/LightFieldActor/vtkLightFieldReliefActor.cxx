// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReliefActor.h"

#include "vtkCallbackCommand.h"
#include "vtkDataArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldReliefShadowHook.h"
#include "vtkLightFieldReliefSurface.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkReliefMapper.h"
#include "vtkReliefMessageForwarder.h"
#include "vtkReliefProperty.h"

#include "LightField.h"
#include "TriangleScene.h"

#include <algorithm>

vtkStandardNewMacro(vtkLightFieldReliefActor);

//------------------------------------------------------------------------------
vtkLightFieldReliefActor::vtkLightFieldReliefActor()
  : Surface(vtkSmartPointer<vtkLightFieldReliefSurface>::New())
  , ReliefMapper(vtkSmartPointer<vtkReliefMapper>::New())
  , ObjectShadow(vtkSmartPointer<vtkLightFieldReliefShadowHook>::New())
{
  this->ReliefMapper->SetRadianceHook(this->ObjectShadow);
  this->ReliefMapper->SetInputConnection(this->Surface->GetOutputPort(0));
  this->ReliefMapper->SetIrradianceProbesConnection(this->Surface->GetOutputPort(1));
  vtkReliefProperty* relief = this->ReliefMapper->GetReliefProperty();
  relief->SetDepthScale(this->DepthScale);
  relief->SetSelfShadowing(true);
  // A wall of a closed room has no silhouette: a view ray leaving the texture at its edge would
  // show the background through the hidden wall (the CPU reference keeps the wall there).
  relief->SilhouettesOff();
  this->SetMapper(this->ReliefMapper);
  // Lambertian, as the field's surfaces: Kd x E / pi (vtkReliefMapper::ConfigureEmitterLight).
  this->GetProperty()->SetAmbient(0.0);
  this->GetProperty()->SetDiffuse(1.0);
  this->GetProperty()->SetSpecular(0.0);
  // Users watch this actor, not the filter inside it.
  auto forwarder = vtkSmartPointer<vtkReliefMessageForwarder>::New();
  forwarder->SetOwner(this);
  forwarder->Watch(this->Surface);
  this->Forwarder = forwarder;
  auto noise = vtkSmartPointer<vtkCallbackCommand>::New();
  this->Surface->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, noise);
  this->ExecutiveNoise = noise;
}

//------------------------------------------------------------------------------
vtkLightFieldReliefActor::~vtkLightFieldReliefActor()
{
  this->ShowSurface();
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetLightFieldActor(vtkLightFieldActor* actor)
{
  if (this->LightFieldActor != actor)
  {
    this->ShowSurface();
    this->LightFieldActor = actor;
    this->Surface->SetLightFieldActor(actor);
    this->ObjectShadow->SetLightFieldActor(actor);
    this->HideSurface();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLightFieldActor* vtkLightFieldReliefActor::GetLightFieldActor()
{
  return this->LightFieldActor;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetSurfaceName(const char* name)
{
  const std::string value = name ? name : "";
  if (this->SurfaceName != value)
  {
    this->ShowSurface();
    this->SurfaceName = value;
    this->Surface->SetSurfaceName(value.c_str());
    this->HideSurface();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetVisibility(vtkTypeBool visible)
{
  this->Superclass::SetVisibility(visible);
  if (visible)
  {
    this->HideSurface();
  }
  else
  {
    this->ShowSurface();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::HideSurface()
{
  // Now, not at the first frame: the walkthrough may draw before this actor in that frame, and
  // its flat surface in front of the relief would hide it.
  if (!this->LightFieldActor || this->SurfaceName.empty() || !this->GetVisibility() ||
    (this->HiddenIn == this->LightFieldActor && this->HiddenName == this->SurfaceName))
  {
    return;
  }
  if (const mesolight::vlf::LightField* field =
        vtkLightFieldActorCore::GetLightField(this->LightFieldActor))
  {
    try
    {
      mesolight::SurfaceTriangles(field->Scene(), this->SurfaceName);
    }
    catch (const mesolight::SceneSurfaceError&)
    {
      return; // the surface filter reports the name once, with the scene's names
    }
  }
  // (A field not loaded yet checks the name when it loads.)
  this->ShowSurface();
  this->LightFieldActor->AddHiddenSurface(this->SurfaceName);
  this->HiddenIn = this->LightFieldActor;
  this->HiddenName = this->SurfaceName;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::ShowSurface()
{
  if (this->HiddenIn)
  {
    this->HiddenIn->RemoveHiddenSurface(this->HiddenName);
  }
  this->HiddenIn = nullptr;
  this->HiddenName.clear();
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetReliefTextureData(vtkImageData* texture)
{
  if (this->ReliefTexture != texture)
  {
    this->ReliefTexture = texture;
    this->ReliefMapper->SetReliefTextureData(texture);
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightFieldReliefActor::GetReliefTextureData()
{
  return this->ReliefTexture;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetDepthScale(double scale)
{
  // vtkReliefProperty's range; a NaN keeps the value (it reports it).
  vtkReliefProperty* relief = this->ReliefMapper->GetReliefProperty();
  relief->SetDepthScale(scale);
  this->SetUseTextureDepthScale(false);
  if (this->DepthScale != relief->GetDepthScale())
  {
    this->DepthScale = relief->GetDepthScale();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetUseTextureDepthScale(bool on)
{
  if (this->UseTextureDepthScale != on)
  {
    this->UseTextureDepthScale = on;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetProbesPerSide(int count)
{
  this->Surface->SetProbesPerSide(count); // clamps and says so
  if (this->ProbesPerSide != this->Surface->GetProbesPerSide())
  {
    this->ProbesPerSide = this->Surface->GetProbesPerSide();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetOcclusion(bool on)
{
  if (this->Occlusion != on)
  {
    this->Occlusion = on;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkReliefProperty* vtkLightFieldReliefActor::GetReliefProperty()
{
  return this->ReliefMapper->GetReliefProperty();
}

//------------------------------------------------------------------------------
vtkLightFieldReliefSurface* vtkLightFieldReliefActor::GetReliefSurface()
{
  return this->Surface;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::CopyDisplay(vtkLightFieldActor* actor, vtkReliefProperty* property)
{
  property->SetExposure(actor->GetExposure());
  property->SetToneMapping(actor->GetToneMap() == vtkLightFieldActor::Reinhard);
  property->EncodeSRGBOn(); // the walkthrough's radiance is sRGB-encoded (vtkLightFieldActor)
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::Report(const std::string& problem)
{
  // GetBounds and Render ask several times a frame: one message per cause.
  if (problem != this->LastProblem)
  {
    this->LastProblem = problem;
    vtkErrorMacro(<< problem);
  }
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefActor::Prepare()
{
  if (!this->LightFieldActor)
  {
    this->Report("No light field actor: SetLightFieldActor(the walkthrough's actor).");
    return false;
  }
  vtkImageData* texture = this->ReliefTexture;
  if (!texture)
  {
    this->ShowSurface();
    this->Report("No relief texture: SetReliefTextureData(vtkReliefTextureFilter's output).");
    return false;
  }
  // The depth scale the relief is drawn with: the bake's unless overridden (vtkReliefShading's
  // rule), which the visible-share map must be computed for too.
  double depthScale = this->DepthScale;
  vtkDataArray* baked = texture->GetFieldData()->GetArray("MesolightDepthScale");
  if (this->UseTextureDepthScale && baked && baked->GetNumberOfTuples() > 0)
  {
    depthScale = std::clamp(baked->GetComponent(0, 0), 0.0, 10.0);
  }
  vtkReliefProperty* relief = this->ReliefMapper->GetReliefProperty();
  relief->SetUseTextureDepthScale(this->UseTextureDepthScale);
  // The relief's occlusion of its indirect light and its inter-reflection (its visible-share
  // map), and the scene's shadows of the emitter lights, added to the probes; walled, as the
  // CPU reference's relief recessed into its wall.
  this->Surface->SetReliefTextureData(this->Occlusion ? texture : nullptr);
  this->Surface->SetReliefDepthScale(depthScale);
  this->Surface->WalledReliefOn();
  this->Surface->SetSceneOcclusion(this->Occlusion);
  const vtkMTimeType settings = this->Surface->GetMTime();
  if (!this->Drawable && this->PreparedTime != 0 && settings == this->FailedTime)
  {
    return false; // failed with these settings: said once, not again per frame
  }
  this->Surface->Update(); // nothing when nothing changed
  const vtkMTimeType updated = this->Surface->GetOutput()->GetMTime();
  if (updated != this->PreparedTime)
  {
    this->PreparedTime = updated;
    vtkPolyData* surface = this->Surface->GetOutput();
    vtkDataArray* normals = surface->GetPointData()->GetNormals();
    this->Drawable = surface->GetNumberOfPolys() > 0 && normals;
    // The surface's own emitter lights: the probes' scene visibility is per light of that list
    // (more lamps than the relief shades are merged, this surface's nearest kept apart).
    relief->SetLights(this->Drawable ? this->Surface->GetEmitterLights() : nullptr);
    // A relief on a lamp or a window still emits its light.
    relief->SetEmission(this->Surface->GetSurfaceEmission());
    if (this->Drawable)
    {
      this->GetProperty()->SetColor(this->Surface->GetSurfaceDiffuse());
      // Recessed into its surface: no depth behind the surface's plane (its front normal).
      double origin[3], normal[3];
      surface->GetPoint(0, origin);
      normals->GetTuple(0, normal);
      relief->SetDepthLimitPlane(origin, normal);
    }
  }
  if (!this->Drawable)
  {
    this->FailedTime = settings;
    this->ShowSurface(); // a flat wall rather than a hole
    return false;
  }
  this->LastProblem.clear();
  this->HideSurface(); // if the field was not there when the name was set
  vtkLightFieldReliefActor::CopyDisplay(this->LightFieldActor, relief);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::Render(vtkRenderer* renderer, vtkMapper* mapper)
{
  if (this->Prepare())
  {
    this->Superclass::Render(renderer, mapper);
  }
}

//------------------------------------------------------------------------------
double* vtkLightFieldReliefActor::GetBounds()
{
  // Nothing to draw has no bounds (renderers leave such props out of the camera's reset).
  return this->Prepare() ? this->Superclass::GetBounds() : nullptr;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightFieldActor: " << this->LightFieldActor.GetPointer() << "\n";
  os << indent << "SurfaceName: " << this->SurfaceName << "\n";
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "UseTextureDepthScale: " << this->UseTextureDepthScale << "\n";
  os << indent << "ProbesPerSide: " << this->ProbesPerSide << "\n";
  os << indent << "Occlusion: " << this->Occlusion << "\n";
  os << indent << "Drawable: " << this->Drawable << "\n";
  os << indent << "HiddenName: " << this->HiddenName << "\n";
}
