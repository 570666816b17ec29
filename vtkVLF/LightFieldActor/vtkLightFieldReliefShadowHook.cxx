// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReliefShadowHook.h"

#include "ObjectMesh.h"    // WorldToUnitSphere
#include "ObjectShadows.h" // ShadowGpuData
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldCasterShadows.h"
#include "vtkLightFieldReliefShadowFS.h"
#include "vtkLightFieldShading.h"
#include "vtkLightFieldShadowFS.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <algorithm>

vtkStandardNewMacro(vtkLightFieldReliefShadowHook);

//------------------------------------------------------------------------------
vtkLightFieldReliefShadowHook::vtkLightFieldReliefShadowHook() = default;
vtkLightFieldReliefShadowHook::~vtkLightFieldReliefShadowHook() = default;

//------------------------------------------------------------------------------
void vtkLightFieldReliefShadowHook::SetLightFieldActor(vtkLightFieldActor* actor)
{
  if (this->LightFieldActor != actor)
  {
    this->LightFieldActor = actor;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLightFieldActor* vtkLightFieldReliefShadowHook::GetLightFieldActor()
{
  return this->LightFieldActor;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefShadowHook::SetCasterShadows(vtkLightFieldCasterShadows* shadows)
{
  if (this->CasterShadows != shadows)
  {
    this->CasterShadows = shadows;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLightFieldCasterShadows* vtkLightFieldReliefShadowHook::GetCasterShadows()
{
  return this->CasterShadows;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefShadowHook::StartDraw(vtkOpenGLRenderWindow* window)
{
  this->Shadowing = false;
  this->DrawnGpu = nullptr;
  const mesolight::vlf::ShadowGpuData* gpu = nullptr;
  const void* owner = nullptr;
  unsigned long version = 0;
  if (vtkLightFieldActor* actor = this->LightFieldActor)
  {
    // The walkthrough draws the shadow in its radiance modes only (the geometry mode is VTK's
    // shading by Kd): the relief follows.
    const mesolight::vlf::LightField* field = vtkLightFieldActorCore::GetLightField(actor);
    const vtkLightFieldObjectShadows& shadows = vtkLightFieldActorCore::GetInternals(actor).Shadows;
    if (!actor->GetVisibility() || actor->GetRenderMode() == vtkLightFieldActor::Geometry ||
      !field || !shadows.Active())
    {
      return false;
    }
    gpu = &shadows.GetGpu();
    owner = &shadows;
    version = shadows.GetVersion();
    const glm::mat4 toUnit = mesolight::vlf::WorldToUnitSphere(*field);
    std::copy(glm::value_ptr(toUnit), glm::value_ptr(toUnit) + 16, this->WorldToUnit);
  }
  else if (vtkLightFieldCasterShadows* caster = this->CasterShadows)
  {
    if (!caster->HasShadows())
    {
      return false;
    }
    gpu = &caster->GetGpu();
    owner = caster;
    version = caster->GetVersion();
    caster->GetWorldToUnitSphere(this->WorldToUnit);
  }
  if (!gpu || !window)
  {
    return false;
  }
  if (!this->ShadowTexture || this->ShadowTexture->GetHandle() == 0 ||
    this->ShadowTexture->GetContext() != window || this->UploadedFrom != owner ||
    this->UploadedVersion != version)
  {
    // Uploaded once per rebuild of the maps.
    this->UploadedFrom = nullptr;
    if (!vtkLightFieldShading::UploadShadowTexture(this->ShadowTexture, window, *gpu))
    {
      vtkErrorMacro(<< "could not upload the " << gpu->Width << "x" << gpu->Height
                    << " shadow map texture: the relief shows no shadow");
      return false;
    }
    this->UploadedFrom = owner;
    this->UploadedVersion = version;
  }
  this->ShadowTexture->Activate();
  this->DrawnGpu = gpu;
  this->Shadowing = true;
  return true;
}

//------------------------------------------------------------------------------
const std::string& vtkLightFieldReliefShadowHook::GetFragmentDeclarations()
{
  static const std::string declarations = std::string("#define ML_SHADOW_RECEIVER_GIVEN\n") +
    vtkLightFieldShadowFS + vtkLightFieldReliefShadowFS;
  return declarations;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefShadowHook::SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren)
{
  if (!program || !this->Shadowing || !program->IsUniformUsed("mlViewToUnitSphere"))
  {
    return;
  }
  vtkLightFieldShading::SetShadowUniforms(
    program, this->DrawnGpu, this->ShadowTexture->GetTextureUnit());
  // View coordinates (the relief's hit point) to the field's unit sphere, where the maps live.
  vtkMatrix4x4* view = ren->GetActiveCamera()->GetModelViewTransformMatrix();
  glm::mat4 worldToView(1.0f);
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      worldToView[c][r] = static_cast<float>(view->GetElement(r, c));
    }
  }
  glm::mat4 viewToUnit = glm::make_mat4(this->WorldToUnit) * glm::inverse(worldToView);
  program->SetUniformMatrix4x4("mlViewToUnitSphere", glm::value_ptr(viewToUnit));
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefShadowHook::FinishDraw()
{
  if (this->Shadowing)
  {
    this->ShadowTexture->Deactivate();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefShadowHook::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->ShadowTexture)
  {
    this->ShadowTexture->ReleaseGraphicsResources(window);
  }
  this->UploadedFrom = nullptr;
  this->UploadedVersion = 0;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefShadowHook::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightFieldActor: " << this->LightFieldActor.GetPointer() << "\n";
  os << indent << "CasterShadows: " << this->CasterShadows.Get() << "\n";
  os << indent << "Shadowing: " << this->Shadowing << "\n";
}
