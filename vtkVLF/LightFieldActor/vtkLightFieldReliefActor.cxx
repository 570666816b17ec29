// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReliefActor.h"

#include "vtkImageData.h"
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldReliefMapper.h"
#include "vtkLightFieldReliefSurface.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkReliefProperty.h"

#include "LightField.h"
#include "TriangleScene.h"

vtkStandardNewMacro(vtkLightFieldReliefActor);

//------------------------------------------------------------------------------
vtkLightFieldReliefActor::vtkLightFieldReliefActor()
  : Surface(vtkSmartPointer<vtkLightFieldReliefSurface>::New())
  , ReliefMapper(vtkSmartPointer<vtkLightFieldReliefMapper>::New())
{
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
}

//------------------------------------------------------------------------------
vtkLightFieldReliefActor::~vtkLightFieldReliefActor() = default;

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::SetLightFieldActor(vtkLightFieldActor* actor)
{
  if (this->LightFieldActor != actor)
  {
    this->LightFieldActor = actor;
    this->Surface->SetLightFieldActor(actor);
    this->ReliefMapper->SetLightFieldActor(actor);
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
    this->SurfaceName = value;
    this->Surface->SetSurfaceName(value.c_str());
    this->HideSurface();
    this->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefActor::HideSurface()
{
  // Now, not at the first frame: the walkthrough may draw before this actor in that frame, and
  // its flat surface in front of the relief would hide it.
  if (!this->LightFieldActor || this->SurfaceName.empty())
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
  this->LightFieldActor->AddHiddenSurface(this->SurfaceName);
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
  if (this->DepthScale != relief->GetDepthScale())
  {
    this->DepthScale = relief->GetDepthScale();
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
bool vtkLightFieldReliefActor::Prepare()
{
  if (!this->LightFieldActor)
  {
    vtkErrorMacro("No light field actor: SetLightFieldActor(the walkthrough's actor).");
    return false;
  }
  vtkImageData* texture = this->ReliefTexture;
  if (!texture)
  {
    vtkErrorMacro("No relief texture: SetReliefTextureData(vtkReliefTextureFilter's output).");
    return false;
  }
  // The relief's occlusion of its indirect light and its inter-reflection (its visible-share
  // map), and the scene's shadows of the emitter lights, added to the probes; walled, as the
  // CPU reference's relief recessed into its wall.
  this->Surface->SetReliefTextureData(this->Occlusion ? texture : nullptr);
  this->Surface->SetReliefDepthScale(this->DepthScale);
  this->Surface->WalledReliefOn();
  this->Surface->SetSceneOcclusion(this->Occlusion);
  this->Surface->Update(); // nothing when nothing changed
  const vtkMTimeType updated = this->Surface->GetOutput()->GetMTime();
  if (updated != this->PreparedTime)
  {
    this->PreparedTime = updated;
    this->Drawable = this->Surface->GetOutput()->GetNumberOfPolys() > 0;
    vtkReliefProperty* relief = this->ReliefMapper->GetReliefProperty();
    // The surface's own emitter lights: the probes' scene visibility is per light of that list
    // (more lamps than the relief shades are merged, this surface's nearest kept apart).
    relief->SetLights(this->Drawable ? this->Surface->GetEmitterLights() : nullptr);
    // A relief on a lamp or a window still emits its light.
    relief->SetEmission(this->Surface->GetSurfaceEmission());
    if (this->Drawable)
    {
      this->GetProperty()->SetColor(this->Surface->GetSurfaceDiffuse());
      this->HideSurface(); // if the field was not there when the name was set
    }
  }
  if (this->Drawable)
  {
    vtkLightFieldReliefActor::CopyDisplay(this->LightFieldActor, this->GetReliefProperty());
  }
  return this->Drawable;
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
  os << indent << "ProbesPerSide: " << this->ProbesPerSide << "\n";
  os << indent << "Occlusion: " << this->Occlusion << "\n";
  os << indent << "Drawable: " << this->Drawable << "\n";
}
