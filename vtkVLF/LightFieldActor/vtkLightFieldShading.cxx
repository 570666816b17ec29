// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldShading.h"

#include "mlEncodeSrgbFS.h"
#include "vtkLightFieldFS.h"
#include "vtkLightFieldShadowFS.h"

#include "ObjectShadows.h" // ShadowGpuData

#include "vtkOpenGLRenderWindow.h"
#include "vtkShaderProgram.h"
#include "vtkTextureObject.h"

#include <string>
#include <vector>

//------------------------------------------------------------------------------
bool vtkLightFieldShading::UploadAtlasTexture(vtkSmartPointer<vtkTextureObject>& texture,
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
void vtkLightFieldShading::ReplaceRadianceShaderValues(
  std::map<vtkShader::Type, vtkShader*>& shaders, const std::function<void()>& superclass,
  bool vertexRadiance, bool shadowCode)
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
    std::string("//VTK::CustomUniforms::Dec\n") +
      (shadowCode ? vtkLightFieldShadowFS : "vec3 mlShadowed(vec3 total) { return total; }\n") +
      mlEncodeSrgbFS + vtkLightFieldFS + (vertexRadiance ? "in vec3 mlVertexRadianceVC;\n" : ""));
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
void vtkLightFieldShading::SetRadianceUniforms(
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
bool vtkLightFieldShading::UploadShadowTexture(vtkSmartPointer<vtkTextureObject>& texture,
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
void vtkLightFieldShading::SetShadowUniforms(
  vtkShaderProgram* program, const mesolight::vlf::ShadowGpuData* gpu, int textureUnit)
{
  if (!program->IsUniformUsed("mlShadowMode"))
  {
    return; // built without the shadow code
  }
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
  program->SetUniform4f("mlShadowAmbient", &gpu->Ambient.x);
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
