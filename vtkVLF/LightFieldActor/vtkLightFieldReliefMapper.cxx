// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReliefMapper.h"

#include "ObjectMesh.h"    // WorldToUnitSphere
#include "ObjectShadows.h" // ShadowGpuData
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldReliefShadowFS.h"
#include "vtkLightFieldShading.h"
#include "vtkLightFieldShadowFS.h"

#include "vtkCamera.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <glm/gtc/type_ptr.hpp>
#include <glm/mat4x4.hpp>

#include <string>

vtkStandardNewMacro(vtkLightFieldReliefMapper);

//------------------------------------------------------------------------------
vtkLightFieldReliefMapper::vtkLightFieldReliefMapper() = default;
vtkLightFieldReliefMapper::~vtkLightFieldReliefMapper() = default;

//------------------------------------------------------------------------------
void vtkLightFieldReliefMapper::SetLightFieldActor(vtkLightFieldActor* actor)
{
  if (this->LightFieldActor != actor)
  {
    this->LightFieldActor = actor;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLightFieldActor* vtkLightFieldReliefMapper::GetLightFieldActor()
{
  return this->LightFieldActor;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefMapper::UploadShadows(vtkRenderer* ren)
{
  vtkLightFieldActor* actor = this->LightFieldActor;
  // The walkthrough draws the shadow in its radiance modes only (the geometry mode is VTK's
  // shading by Kd): the relief follows.
  if (!actor || !actor->GetVisibility() || actor->GetRenderMode() == vtkLightFieldActor::Geometry ||
    !vtkLightFieldActorCore::GetLightField(actor))
  {
    return false;
  }
  const vtkLightFieldObjectShadows& shadows = vtkLightFieldActorCore::GetInternals(actor).Shadows;
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!shadows.Active() || !window)
  {
    return false;
  }
  if (this->ShadowTexture && this->ShadowTexture->GetHandle() != 0 &&
    this->ShadowTexture->GetContext() == window && this->ShadowVersion == shadows.GetVersion())
  {
    return true; // uploaded once per rebuild of the maps
  }
  const mesolight::vlf::ShadowGpuData& gpu = shadows.GetGpu();
  if (!vtkLightFieldShading::UploadShadowTexture(this->ShadowTexture, window, gpu))
  {
    vtkErrorMacro(<< "could not upload the " << gpu.Width << "x" << gpu.Height
                  << " shadow map texture: the relief shows no shadow");
    return false;
  }
  this->ShadowVersion = shadows.GetVersion();
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* actor)
{
  this->Shadowing = this->UploadShadows(ren);
  this->Superclass::RenderPieceStart(ren, actor);
  this->ShadowActive = this->Shadowing && this->ReadyToDraw;
  if (this->ShadowActive)
  {
    this->ShadowTexture->Activate();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::RenderPieceFinish(ren, actor);
  if (this->ShadowActive)
  {
    this->ShadowTexture->Deactivate();
  }
  this->ShadowActive = false;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const bool changed = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act);
  auto built = this->BuiltWithShadows.find(&cellBO);
  return changed || built == this->BuiltWithShadows.end() || built->second != this->Shadowing;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  if (this->Shadowing)
  {
    // Declared after the relief's own declarations (vtkReliefShaderSource puts them right
    // after this tag too), before main, which calls the hook.
    std::string fs = shaders[vtkShader::Fragment]->GetSource();
    vtkShaderProgram::Substitute(fs, "//VTK::CustomUniforms::Dec",
      std::string("//VTK::CustomUniforms::Dec\n#define ML_SHADOW_RECEIVER_GIVEN\n") +
        vtkLightFieldShadowFS + vtkLightFieldReliefShadowFS);
    shaders[vtkShader::Fragment]->SetSource(fs);
  }
  this->BuiltWithShadows[this->LastBoundBO] = this->Shadowing;
  this->Superclass::ReplaceShaderValues(shaders, ren, act);
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  vtkShaderProgram* program = cellBO.Program;
  vtkLightFieldActor* actor = this->LightFieldActor;
  if (!program || !this->ShadowActive || !actor || !program->IsUniformUsed("mlViewToUnitSphere"))
  {
    return;
  }
  const mesolight::vlf::LightField* field = vtkLightFieldActorCore::GetLightField(actor);
  if (!field)
  {
    return;
  }
  vtkLightFieldShading::SetShadowUniforms(program,
    &vtkLightFieldActorCore::GetInternals(actor).Shadows.GetGpu(),
    this->ShadowTexture->GetTextureUnit());
  // View coordinates (the relief's hit point; the relief's actor is placed at the identity, as
  // the field's walls are) to the field's unit sphere, where the maps live.
  vtkMatrix4x4* view = ren->GetActiveCamera()->GetModelViewTransformMatrix();
  glm::mat4 worldToView(1.0f);
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      worldToView[c][r] = static_cast<float>(view->GetElement(r, c));
    }
  }
  glm::mat4 viewToUnit = mesolight::vlf::WorldToUnitSphere(*field) * glm::inverse(worldToView);
  program->SetUniformMatrix4x4("mlViewToUnitSphere", glm::value_ptr(viewToUnit));
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->ShadowTexture)
  {
    this->ShadowTexture->ReleaseGraphicsResources(window);
  }
  this->ShadowVersion = 0;
  this->BuiltWithShadows.clear();
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightFieldActor: " << this->LightFieldActor.GetPointer() << "\n";
  os << indent << "Shadowing: " << this->Shadowing << "\n";
}
