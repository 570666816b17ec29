// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldMapper.h"

#include "DisplayTransform.h"
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldFS.h"
#include "vtkLightFieldShadowFS.h"

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
  if (!UploadAtlasTexture(this->AtlasTexture, window, atlas.Width(), atlas.Height(), data))
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
  const bool changed = built == this->BuiltRadiance.end() || built->second != this->Radiance;
  return this->Superclass::GetNeedToRebuildShaders(cellBO, ren, act) || changed;
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act)
{
  this->BuiltRadiance[this->LastBoundBO] = this->Radiance;
  if (!this->Radiance)
  {
    this->Superclass::ReplaceShaderValues(shaders, ren, act);
    return;
  }
  ReplaceRadianceShaderValues(
    shaders, [&]() { this->Superclass::ReplaceShaderValues(shaders, ren, act); });
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
  RadianceUniforms uniforms;
  uniforms.AtlasUnit = this->AtlasTexture->GetTextureUnit();
  uniforms.ScreenUnit = this->ScreenTexture->GetTextureUnit();
  std::copy(this->ScreenOrigin, this->ScreenOrigin + 2, uniforms.ScreenOrigin);
  std::copy(this->ScreenSize, this->ScreenSize + 2, uniforms.ScreenSize);
  uniforms.Exposure = this->Exposure;
  uniforms.ToneMap = this->ToneMap;
  uniforms.AllScreen = this->AllScreen;
  uniforms.Overwrite = this->Overwrite;
  SetRadianceUniforms(cellBO.Program, uniforms);
  this->SetShadowUniforms(cellBO.Program, act);
}

//------------------------------------------------------------------------------
bool vtkLightFieldMapper::UploadAtlasTexture(vtkSmartPointer<vtkTextureObject>& texture,
  vtkOpenGLRenderWindow* window, int width, int height, const float* rgba)
{
  if (!texture)
  {
    texture = vtkSmartPointer<vtkTextureObject>::New();
  }
  texture->SetContext(window);
  // Bilinear and clamped: with each surface's 1-texel gutter this equals the field's own lookup.
  texture->SetMinificationFilter(vtkTextureObject::Linear);
  texture->SetMagnificationFilter(vtkTextureObject::Linear);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture->Create2DFromRaw(static_cast<unsigned int>(width),
    static_cast<unsigned int>(height), 4, VTK_FLOAT, const_cast<float*>(rgba));
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::ReplaceRadianceShaderValues(
  std::map<vtkShader::Type, vtkShader*>& shaders, const std::function<void()>& superclass,
  bool vertexRadiance)
{
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(
    vs, "//VTK::Normal::Dec", "in vec2 mlAtlasTC;\nout vec2 mlAtlasTCVC;\n//VTK::Normal::Dec");
  vtkShaderProgram::Substitute(
    vs, "//VTK::Normal::Impl", "mlAtlasTCVC = mlAtlasTC;\n  //VTK::Normal::Impl");
  // Shadows of the movable object: the receiver's unit-sphere point, normal and Kd for
  // vtkLightFieldShadowFS.glsl.
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec",
    "in vec3 mlShadowPoint;\nin vec3 mlShadowNormal;\nin vec3 mlShadowKd;\n"
    "out vec3 mlShadowPointVC;\n"
    "out vec3 mlShadowNormalVC;\nout vec3 mlShadowKdVC;\n//VTK::Normal::Dec");
  vtkShaderProgram::Substitute(vs, "//VTK::Normal::Impl",
    "mlShadowPointVC = mlShadowPoint;\n  mlShadowNormalVC = mlShadowNormal;\n"
    "  mlShadowKdVC = mlShadowKd;\n  //VTK::Normal::Impl");
  if (vertexRadiance)
  {
    vtkShaderProgram::Substitute(vs, "//VTK::Normal::Dec",
      "in vec3 mlVertexRadiance;\nout vec3 mlVertexRadianceVC;\n//VTK::Normal::Dec");
    vtkShaderProgram::Substitute(
      vs, "//VTK::Normal::Impl", "mlVertexRadianceVC = mlVertexRadiance;\n  //VTK::Normal::Impl");
  }
  vtkShaderProgram::Substitute(fs, "//VTK::CustomUniforms::Dec",
    std::string("//VTK::CustomUniforms::Dec\n") + vtkLightFieldShadowFS + vtkLightFieldFS +
      (vertexRadiance ? "in vec3 mlVertexRadianceVC;\n" : ""));
  // VTK's lighting gives way to the field's radiance.
  vtkShaderProgram::Substitute(fs, "//VTK::Light::Impl", "//MESOLIGHT::LightField::Impl");
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Fragment]->SetSource(fs);
  superclass();
  fs = shaders[vtkShader::Fragment]->GetSource();
  vtkShaderProgram::Substitute(fs, "//MESOLIGHT::LightField::Impl",
    vertexRadiance ? "gl_FragData[0] = vec4(mlDisplay(mlVertexRadianceVC), opacity);"
                   : "gl_FragData[0] = vec4(mlDisplay(mlRadiance()), opacity);");
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::SetRadianceUniforms(
  vtkShaderProgram* program, const RadianceUniforms& uniforms)
{
  program->SetUniformi("mlAtlas", uniforms.AtlasUnit);
  program->SetUniformi("mlScreen", uniforms.ScreenUnit);
  program->SetUniform2i("mlScreenOrigin", uniforms.ScreenOrigin);
  program->SetUniform2i("mlScreenSize", uniforms.ScreenSize);
  program->SetUniformf("mlExposure", uniforms.Exposure);
  program->SetUniformi("mlToneMap", uniforms.ToneMap);
  program->SetUniformi("mlAllScreen", uniforms.AllScreen ? 1 : 0);
  program->SetUniformi("mlOverwrite", uniforms.Overwrite ? 1 : 0);
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
  if (!UploadShadowTexture(this->ShadowTexture, window, gpu))
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
  SetShadowUniforms(program, this->Shadowing && shadows ? &shadows->GetGpu() : nullptr,
    this->Shadowing ? this->ShadowTexture->GetTextureUnit() : this->AtlasTexture->GetTextureUnit());
}

//------------------------------------------------------------------------------
bool vtkLightFieldMapper::UploadShadowTexture(vtkSmartPointer<vtkTextureObject>& texture,
  vtkOpenGLRenderWindow* window, const mesolight::vlf::ShadowGpuData& gpu)
{
  if (!texture)
  {
    texture = vtkSmartPointer<vtkTextureObject>::New();
  }
  texture->SetContext(window);
  // Read with texelFetch: no filtering, the shader compares depths per texel.
  texture->SetMinificationFilter(vtkTextureObject::Nearest);
  texture->SetMagnificationFilter(vtkTextureObject::Nearest);
  texture->SetWrapS(vtkTextureObject::ClampToEdge);
  texture->SetWrapT(vtkTextureObject::ClampToEdge);
  return texture->Create2DFromRaw(static_cast<unsigned int>(gpu.Width),
    static_cast<unsigned int>(gpu.Height), 1, VTK_FLOAT, const_cast<float*>(gpu.Depth.data()));
}

//------------------------------------------------------------------------------
void vtkLightFieldMapper::SetShadowUniforms(
  vtkShaderProgram* program, const mesolight::vlf::ShadowGpuData* gpu, int textureUnit)
{
  // Always a unit holding a 2D texture: a sampler left on a unit another draw has since given a
  // buffer texture makes the draw an invalid operation, even unread.
  program->SetUniformi("mlShadowDepth", textureUnit);
  if (!gpu)
  {
    program->SetUniformi("mlShadowMode", 0);
    program->SetUniformi("mlShadowEmitterCount", 0);
    return;
  }
  program->SetUniformi("mlShadowMode", gpu->Mode);
  program->SetUniformi("mlShadowColumns", gpu->Columns);
  program->SetUniformi("mlShadowResolution", gpu->Resolution);
  program->SetUniformi("mlShadowEmitterCount", gpu->EmitterCount);
  program->SetUniform4f("mlShadowParams", &gpu->Params.x);
  auto arrays = [&](const char* name, const std::vector<glm::vec4>& values)
  {
    if (!values.empty())
    {
      program->SetUniform4fv(name, static_cast<int>(values.size()), &values[0].x);
    }
  };
  arrays("mlShadowMapPosition", gpu->MapPosition);
  arrays("mlShadowMapAxisX", gpu->MapAxisX);
  arrays("mlShadowMapAxisY", gpu->MapAxisY);
  arrays("mlShadowMapAxisZ", gpu->MapAxisZ);
  arrays("mlShadowEmitterRadiance", gpu->EmitterRadiance);
  arrays("mlShadowEmitterNormal", gpu->EmitterNormal);
  arrays("mlShadowEmitterIndex", gpu->EmitterIndex);
  arrays("mlShadowSample", gpu->Samples);
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
