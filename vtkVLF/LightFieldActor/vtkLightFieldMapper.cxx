// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldMapper.h"

#include "DisplayTransform.h"
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldShading.h"

#include "TextureAtlas.h"

#include "vtkDataObject.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <chrono>

// mlToneMap takes the actor's ToneMap, which the CPU paths read as mesolight::ToneMapOperator.
static_assert(vtkLightFieldActor::Clamp == static_cast<int>(mesolight::ToneMapOperator::Clamp) &&
    vtkLightFieldActor::Reinhard == static_cast<int>(mesolight::ToneMapOperator::Reinhard),
  "vtkLightFieldActor's tone maps and mesolight::ToneMapOperator share their values");

vtkStandardNewMacro(vtkLightFieldMapper);

//------------------------------------------------------------------------------
vtkLightFieldMapper::vtkLightFieldMapper()
{
  // Our own attribute: VTK uploads "tcoord" only when the actor has a texture.
  this->MapDataArrayToVertexAttribute(
    "mlAtlasTC", GetAtlasCoordinatesName(), vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  // Shadows of the movable object: each receiver's unit-sphere point, normal and Kd
  // (vtkLightFieldActor's scene; not VTK's vertexMC, which VTK may shift and scale).
  this->MapDataArrayToVertexAttribute(
    "mlShadowPoint", "mlShadowPoint", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute(
    "mlShadowNormal", "mlShadowNormal", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  this->MapDataArrayToVertexAttribute(
    "mlShadowKd", "mlShadowKd", vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

//------------------------------------------------------------------------------
vtkLightFieldMapper::~vtkLightFieldMapper() = default;

//------------------------------------------------------------------------------
bool vtkLightFieldMapper::UploadAtlas(vtkRenderer* ren, vtkActor* act)
{
  vtkLightFieldActor* actor = vtkLightFieldActor::SafeDownCast(act);
  const auto& impl = vtkLightFieldActorCore::GetInternals(actor);
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!impl.Scene.GetAtlas() || !window)
  {
    return false;
  }
  if (this->AtlasTexture && this->AtlasTexture->GetHandle() != 0 &&
    this->AtlasTexture->GetContext() == window &&
    this->AtlasVersion == impl.Scene.GetAtlasVersion() && this->AtlasFlipped == impl.FlipAtlas)
  {
    return true; // uploaded once per field
  }
  const mesolight::vlf::TextureAtlas& atlas = *impl.Scene.GetAtlas();
  std::vector<float> flipped;
  const float* data = atlas.Pixels().data();
  if (impl.FlipAtlas)
  {
    flipped = atlas.FlippedPixels();
    data = flipped.data();
  }
  if (!vtkLightFieldShading::UploadAtlasTexture(
        this->AtlasTexture, window, atlas.Width(), atlas.Height(), data))
  {
    vtkErrorMacro(<< "could not upload the light field's " << atlas.Width() << "x" << atlas.Height()
                  << " texture atlas");
    return false;
  }
  this->AtlasVersion = impl.Scene.GetAtlasVersion();
  this->AtlasFlipped = impl.FlipAtlas;
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldMapper::UploadScreen(vtkRenderer* ren, vtkActor* act)
{
  vtkLightFieldActor* actor = vtkLightFieldActor::SafeDownCast(act);
  auto& screen = vtkLightFieldActorCore::GetInternals(actor).Screen;
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!window)
  {
    return false;
  }
  if (!this->ScreenTexture)
  {
    this->ScreenTexture = vtkSmartPointer<vtkTextureObject>::New();
  }
  this->ScreenTexture->SetContext(window);
  this->ScreenTexture->SetMinificationFilter(vtkTextureObject::Nearest);
  this->ScreenTexture->SetMagnificationFilter(vtkTextureObject::Nearest);
  this->ScreenTexture->SetWrapS(vtkTextureObject::ClampToEdge);
  this->ScreenTexture->SetWrapT(vtkTextureObject::ClampToEdge);
  const mesolight::vlf::PixelRect& rect = screen.GetRect();
  const bool have =
    screen.IsValid() && !rect.Empty() && screen.GetPixels().size() == rect.Pixels() * 4;
  float none[4] = { 0.0f, 0.0f, 0.0f, 0.0f };
  const unsigned int w = have ? static_cast<unsigned int>(rect.Width()) : 1u;
  const unsigned int h = have ? static_cast<unsigned int>(rect.Height()) : 1u;
  float* data = have ? screen.GetPixels().data() : none;
  if (!this->ScreenTexture->Create2DFromRaw(w, h, 4, VTK_FLOAT, data))
  {
    vtkErrorMacro(<< "could not upload the " << w << "x" << h << " screen-space radiance texture");
    return false;
  }
  this->ScreenOrigin[0] = have ? screen.GetOrigin()[0] : 0;
  this->ScreenOrigin[1] = have ? screen.GetOrigin()[1] : 0;
  this->ScreenSize[0] = have ? static_cast<int>(w) : 0;
  this->ScreenSize[1] = have ? static_cast<int>(h) : 0;
  this->AllScreen = screen.IsAllScreen();
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* act)
{
  this->Radiance = false;
  vtkLightFieldActor* actor = vtkLightFieldActor::SafeDownCast(act);
  if (actor && vtkLightFieldActorCore::PrepareFrame(actor, ren) &&
    actor->GetRenderMode() != vtkLightFieldActor::Geometry)
  {
    const auto start = std::chrono::steady_clock::now();
    this->Radiance = this->UploadAtlas(ren, act) && this->UploadScreen(ren, act);
    vtkLightFieldActorCore::SetLastUploadSeconds(
      actor, std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count());
    this->Exposure = static_cast<float>(actor->GetExposure());
    this->ToneMap = actor->GetToneMap();
    this->Overwrite = vtkLightFieldActorCore::GetInternals(actor).OverwriteComposite;
  }
  // Geometry mode colours by Kd; the radiance modes by nothing VTK knows.
  if (this->ScalarVisibility == (this->Radiance ? 1 : 0))
  {
    this->SetScalarVisibility(!this->Radiance);
  }
  this->Shadowing = this->Radiance && this->UploadShadows(ren, act);
  this->ShadowCodeAlways = actor && vtkLightFieldActorCore::GetInternals(actor).ShadowCodeAlways;
  if (this->Radiance)
  {
    this->AtlasTexture->Activate();
    this->ScreenTexture->Activate();
  }
  if (this->Shadowing)
  {
    this->ShadowTexture->Activate();
  }
  this->Superclass::RenderPieceStart(ren, act);
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::RenderPieceFinish(ren, act);
  if (this->Shadowing)
  {
    this->ShadowTexture->Deactivate();
  }
  if (this->Radiance)
  {
    this->ScreenTexture->Deactivate();
    this->AtlasTexture->Deactivate();
  }
}

//------------------------------------------------------------------------------
bool vtkLightFieldMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  const auto built = this->BuiltRadiance.find(&cellBO);
  const bool changed = built == this->BuiltRadiance.end() || built->second != this->Variant();
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act) || changed;
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->BuiltRadiance[this->LastBoundBO] = this->Variant();
  if (!this->Radiance)
  {
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
    return;
  }
  vtkLightFieldShading::ReplaceRadianceShaderValues(
    shaders, [&]() { this->Superclass::ReplaceShaderValues(shaders, ren, act); }, false,
    this->Shadowing || this->ShadowCodeAlways);
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, act);
  if (!this->Radiance || !cellBO.Program)
  {
    return;
  }
  vtkLightFieldShading::RadianceUniforms uniforms;
  uniforms.AtlasUnit = this->AtlasTexture->GetTextureUnit();
  uniforms.ScreenUnit = this->ScreenTexture->GetTextureUnit();
  std::copy(this->ScreenOrigin, this->ScreenOrigin + 2, uniforms.ScreenOrigin);
  std::copy(this->ScreenSize, this->ScreenSize + 2, uniforms.ScreenSize);
  uniforms.Exposure = this->Exposure;
  uniforms.ToneMap = this->ToneMap;
  uniforms.AllScreen = this->AllScreen;
  uniforms.Overwrite = this->Overwrite;
  vtkLightFieldShading::SetRadianceUniforms(cellBO.Program, uniforms);
  this->SetShadowUniforms(cellBO.Program, act);
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::ReleaseGraphicsResources(vtkWindow* window)
{
  if (this->AtlasTexture)
  {
    this->AtlasTexture->ReleaseGraphicsResources(window);
  }
  if (this->ScreenTexture)
  {
    this->ScreenTexture->ReleaseGraphicsResources(window);
  }
  if (this->ShadowTexture)
  {
    this->ShadowTexture->ReleaseGraphicsResources(window);
  }
  this->ShadowVersion = 0;
  this->AtlasVersion = 0;
  this->BuiltRadiance.clear();
  this->Superclass::ReleaseGraphicsResources(window);
}

//------------------------------------------------------------------------------
bool vtkLightFieldMapper::UploadShadows(vtkRenderer* ren, vtkActor* act)
{
  vtkLightFieldActor* actor = vtkLightFieldActor::SafeDownCast(act);
  const vtkLightFieldObjectShadows* shadows =
    actor ? &vtkLightFieldActorCore::GetInternals(actor).Shadows : nullptr;
  vtkOpenGLRenderWindow* window = vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow());
  if (!shadows || !shadows->Active() || !window)
  {
    return false;
  }
  if (this->ShadowTexture && this->ShadowTexture->GetHandle() != 0 &&
    this->ShadowTexture->GetContext() == window && this->ShadowVersion == shadows->GetVersion())
  {
    return true; // uploaded once per rebuild of the maps
  }
  const mesolight::vlf::ShadowGpuData& gpu = shadows->GetGpu();
  if (!vtkLightFieldShading::UploadShadowTexture(this->ShadowTexture, window, gpu))
  {
    vtkErrorMacro(<< "could not upload the " << gpu.Width << "x" << gpu.Height
                  << " shadow map texture: the object casts no shadow");
    return false;
  }
  this->ShadowVersion = shadows->GetVersion();
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::SetShadowUniforms(vtkShaderProgram* program, vtkActor* act)
{
  vtkLightFieldActor* actor = vtkLightFieldActor::SafeDownCast(act);
  const vtkLightFieldObjectShadows* shadows =
    actor ? &vtkLightFieldActorCore::GetInternals(actor).Shadows : nullptr;
  vtkLightFieldShading::SetShadowUniforms(program,
    this->Shadowing && shadows ? &shadows->GetGpu() : nullptr,
    this->Shadowing ? this->ShadowTexture->GetTextureUnit() : this->AtlasTexture->GetTextureUnit());
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Radiance: " << this->Radiance << "\n";
  os << indent << "ScreenOrigin: " << this->ScreenOrigin[0] << ", " << this->ScreenOrigin[1]
     << "\n";
  os << indent << "ScreenSize: " << this->ScreenSize[0] << "x" << this->ScreenSize[1] << "\n";
}
