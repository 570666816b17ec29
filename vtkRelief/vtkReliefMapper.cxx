// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefMapper.h"

#include "vtkActor.h"
#include "vtkAlgorithmOutput.h"
#include "vtkAttachReliefTexture.h"
#include "vtkExecutive.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkLight.h"
#include "vtkMath.h"
#include "vtkMinDepthPyramidTexture.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLHelper.h"
#include "vtkOpenGLIndexBufferObject.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkProperty.h"
#include "vtkReliefGeometryCache.h"
#include "vtkReliefShading.h"
#include "vtkReliefTextureCache.h"
#include "vtkRenderer.h"
#include "vtkShader.h"
#include "vtkShaderProperty.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

#include <algorithm>

vtkStandardNewMacro(vtkReliefMapper);

//------------------------------------------------------------------------------
vtkReliefMapper::vtkReliefMapper()
{
  this->SetNumberOfInputPorts(4);
  this->Shading->SetMessageOwner(this);
  this->GetReliefProperty(); // the default settings, reporting to this mapper
  // Our own texture-coordinate attribute: VTK uploads "tcoord" only when the actor has a texture.
  this->MapDataArrayToVertexAttribute("mlTCoordMC", vtkReliefGeometryCache::GetReliefTCoordsName(),
    vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
  // The per-vertex quadrics of a curved mesh (absent on a flat one; the shader then reads none).
  this->MapDataArrayToVertexAttribute("mlQuadricMC",
    vtkReliefGeometryCache::GetReliefQuadricsName(), vtkDataObject::FIELD_ASSOCIATION_POINTS, -1);
}

//------------------------------------------------------------------------------
vtkReliefMapper::~vtkReliefMapper() = default;

//------------------------------------------------------------------------------
int vtkReliefMapper::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1 || port == 2 || port == 3)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkImageData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
vtkReliefProperty* vtkReliefMapper::GetReliefProperty()
{
  return this->Shading->GetReliefProperty();
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetReliefProperty(vtkReliefProperty* property)
{
  if (this->Shading->SetReliefProperty(property))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkReliefMapper::GetMTime()
{
  return std::max(this->Superclass::GetMTime(), this->Shading->GetReliefPropertyMTime());
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetReliefTextureData(vtkImageData* image)
{
  this->SetInputDataInternal(1, image);
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetReliefTextureConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
vtkIdType vtkReliefMapper::GetReliefTextureBytes()
{
  return this->Shading->GetReliefTextureCache()->GetUploadedBytes();
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetLightSetData(vtkImageData* lights)
{
  this->SetInputDataInternal(2, lights);
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetLightSetConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(2, output);
}

//------------------------------------------------------------------------------
vtkImageData* vtkReliefMapper::GetLightSet()
{
  if (this->GetNumberOfInputConnections(2) < 1)
  {
    return nullptr;
  }
  return vtkImageData::SafeDownCast(this->GetExecutive()->GetInputData(2, 0));
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetIrradianceProbesData(vtkImageData* probes)
{
  this->SetInputDataInternal(3, probes);
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetRadianceHook(vtkReliefRadianceHook* hook)
{
  if (this->Shading->SetRadianceHook(hook))
  {
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkReliefRadianceHook* vtkReliefMapper::GetRadianceHook()
{
  return this->Shading->GetRadianceHook();
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetIrradianceProbesConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(3, output);
}

//------------------------------------------------------------------------------
vtkImageData* vtkReliefMapper::GetIrradianceProbes()
{
  if (this->GetNumberOfInputConnections(3) < 1)
  {
    return nullptr;
  }
  return vtkImageData::SafeDownCast(this->GetExecutive()->GetInputData(3, 0));
}

//------------------------------------------------------------------------------
int vtkReliefMapper::GetMaximumNumberOfLights()
{
  return vtkReliefShading::MaximumNumberOfLights;
}

//------------------------------------------------------------------------------
void vtkReliefMapper::ConfigureEmitterLight(
  vtkLight* light, const double position[3], const double normal[3], const double intensityRGB[3])
{
  if (!light)
  {
    return;
  }
  double n[3] = { normal[0], normal[1], normal[2] };
  if (vtkMath::Normalize(n) <= 0.0)
  {
    n[2] = 1.0;
  }
  const double peak = std::max({ intensityRGB[0], intensityRGB[1], intensityRGB[2], 0.0 });
  light->SetLightTypeToSceneLight();
  light->PositionalOn();
  light->SetPosition(position[0], position[1], position[2]);
  light->SetFocalPoint(position[0] + n[0], position[1] + n[1], position[2] + n[2]);
  light->SetConeAngle(90.0); // a spot light of 90 degrees with exponent 1: the cosine lobe
  light->SetExponent(1.0);
  light->SetAttenuationValues(0.0, 0.0, 1.0); // 1 / d^2
  if (peak > 0.0)
  {
    light->SetColor(std::max(0.0, intensityRGB[0]) / peak, std::max(0.0, intensityRGB[1]) / peak,
      std::max(0.0, intensityRGB[2]) / peak);
  }
  else
  {
    light->SetColor(1.0, 1.0, 1.0);
  }
  // VTK lights shade albedo x colour x intensity x cosine; a Lambertian surface reflects albedo /
  // pi x irradiance.
  light->SetIntensity(peak / vtkMath::Pi());
  light->SwitchOn();
}

//------------------------------------------------------------------------------
vtkImageData* vtkReliefMapper::GetReliefTexture()
{
  if (this->GetNumberOfInputConnections(1) < 1)
  {
    return nullptr;
  }
  return vtkImageData::SafeDownCast(this->GetExecutive()->GetInputData(1, 0));
}

//------------------------------------------------------------------------------
void vtkReliefMapper::RenderPieceStart(vtkRenderer* ren, vtkActor* actor)
{
  // vtkOpenGLPolyDataMapper::RenderPiece has set CurrentInput to the input; draw a prepared copy
  // (normals and tangents added) instead, and bring the relief texture up to date.
  this->ReadyToDraw = false;
  if (!this->Static && this->GetNumberOfInputConnections(1) > 0)
  {
    vtkAlgorithmOutput* reliefPort = this->GetInputConnection(1, 0);
    reliefPort->GetProducer()->Update(reliefPort->GetIndex());
  }
  if (!this->Static && this->GetNumberOfInputConnections(2) > 0)
  {
    vtkAlgorithmOutput* lightPort = this->GetInputConnection(2, 0);
    lightPort->GetProducer()->Update(lightPort->GetIndex());
  }
  if (!this->Static && this->GetNumberOfInputConnections(3) > 0)
  {
    vtkAlgorithmOutput* probesPort = this->GetInputConnection(3, 0);
    probesPort->GetProducer()->Update(probesPort->GetIndex());
  }
  this->PreparedInput = nullptr;
  if (!this->CurrentInput)
  {
    return;
  }
  // Without connections, a relief texture and light set attached as field data are used.
  vtkSmartPointer<vtkImageData> relief = this->GetReliefTexture();
  if (!relief)
  {
    relief = vtkAttachReliefTexture::GetAttachedReliefTexture(this->CurrentInput);
  }
  vtkSmartPointer<vtkImageData> lights = this->GetLightSet();
  if (!lights)
  {
    lights = vtkAttachReliefTexture::GetAttachedLightSet(this->CurrentInput);
  }
  vtkImageData* probes = this->GetIrradianceProbes();
  vtkTexture* albedo = actor->GetTexture();
  const std::vector<vtkObject*> frameInputs{ this->GetReliefProperty(), this->CurrentInput, relief,
    lights, probes, albedo, albedo ? albedo->GetInput() : nullptr };
  if (!this->Shading->BeginFrame(this, relief, frameInputs))
  {
    return;
  }
  this->PreparedInput = this->Shading->GetGeometryCache()->Prepare(this->CurrentInput);
  if (!this->PreparedInput)
  {
    this->Shading->FrameFailed();
    return;
  }
  this->Shading->SetCurvedGeometry(vtkReliefGeometryCache::IsCurved(this->PreparedInput));
  if (!this->Shading->StartDraw(vtkOpenGLRenderWindow::SafeDownCast(ren->GetRenderWindow()),
        this->GetReliefProperty(), relief, lights, probes, actor))
  {
    this->Shading->FrameFailed();
    return;
  }
  this->CurrentInput = this->PreparedInput;
  this->Superclass::RenderPieceStart(ren, actor);
  this->ReadyToDraw = true;
}

//------------------------------------------------------------------------------
void vtkReliefMapper::RenderPieceDraw(vtkRenderer* ren, vtkActor* actor)
{
  // A shader that failed is not built again every frame (a compile per frame, and the compiler's
  // message repeated) until something it is built from changes; nothing is drawn meanwhile.
  if (this->ReadyToDraw && !this->ShaderStillFailing(actor))
  {
    this->Superclass::RenderPieceDraw(ren, actor);
  }
}

//------------------------------------------------------------------------------
void vtkReliefMapper::RenderPieceFinish(vtkRenderer* ren, vtkActor* actor)
{
  if (this->ReadyToDraw)
  {
    this->Superclass::RenderPieceFinish(ren, actor);
    this->Shading->FinishDraw();
  }
  this->ReadyToDraw = false;
}

//------------------------------------------------------------------------------
bool vtkReliefMapper::GetNeedToRebuildShaders(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  // (The superclass first: it records the light complexity the shader is built for. No
  // program: the last build failed; build again rather than draw with none.)
  const bool changed = this->Superclass::GetNeedToRebuildShaders(cellBO, ren, actor);
  return changed || this->Shading->ShaderKeyChanged(&cellBO) || !cellBO.Program ||
    cellBO.Program == this->NoProgram.Get();
}

//------------------------------------------------------------------------------
void vtkReliefMapper::UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  // VTK 9.1 reads the old program's time when the new program equals it, which dereferences a
  // null program when a build fails with none before (the first build, or after a failed one):
  // a placeholder stands in, and a failed build leaves no program (nothing is drawn).
  if (!cellBO.Program)
  {
    cellBO.Program = this->NoProgram;
  }
  this->Superclass::UpdateShaders(cellBO, ren, actor);
  if (cellBO.Program == this->NoProgram.Get())
  {
    cellBO.Program = nullptr;
  }
  const bool failed = !cellBO.Program;
  if (failed && !this->ShaderFailed)
  {
    vtkErrorMacro(<< "The relief shader (method "
                  << vtkReliefProperty::GetMethodName(this->GetReliefProperty()->GetMethod())
                  << ") did not compile; nothing is drawn.");
  }
  this->ShaderFailed = failed;
  if (failed)
  {
    this->FailedShaderInputsTime = this->ShaderInputsTime(actor);
  }
}

//------------------------------------------------------------------------------
vtkMTimeType vtkReliefMapper::ShaderInputsTime(vtkActor* actor)
{
  vtkMTimeType time = std::max(this->GetMTime(), actor->GetMTime());
  time = std::max(time, actor->GetProperty()->GetMTime());
  time = std::max(time, actor->GetShaderProperty()->GetMTime());
  if (this->CurrentInput)
  {
    time = std::max(time, this->CurrentInput->GetMTime());
  }
  return time;
}

//------------------------------------------------------------------------------
bool vtkReliefMapper::ShaderStillFailing(vtkActor* actor)
{
  if (!this->ShaderFailed || this->ShaderInputsTime(actor) > this->FailedShaderInputsTime)
  {
    return false;
  }
  for (int i = PrimitiveStart; i < PrimitiveEnd; ++i)
  {
    if (this->Primitives[i].IBO->IndexCount &&
      this->Shading->ShaderKeyChanged(&this->Primitives[i]))
    {
      return false;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkReliefMapper::ReplaceShaderValues(
  std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* actor)
{
  std::string vs = shaders[vtkShader::Vertex]->GetSource();
  std::string fs = shaders[vtkShader::Fragment]->GetSource();
  this->Shading->ReplaceShaderValuesBefore(
    vs, fs, this->PrimitiveInfo[this->LastBoundBO].LastLightComplexity == 0);
  shaders[vtkShader::Vertex]->SetSource(vs);
  shaders[vtkShader::Fragment]->SetSource(fs);
  this->Superclass::ReplaceShaderValues(shaders, ren, actor);
  fs = shaders[vtkShader::Fragment]->GetSource();
  this->Shading->ReplaceShaderValuesAfter(fs, this->LastBoundBO);
  shaders[vtkShader::Fragment]->SetSource(fs);
}

//------------------------------------------------------------------------------
void vtkReliefMapper::SetMapperShaderParameters(
  vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* actor)
{
  this->Superclass::SetMapperShaderParameters(cellBO, ren, actor);
  this->Shading->SetShaderParameters(cellBO.Program, ren, actor);
}

//------------------------------------------------------------------------------
void vtkReliefMapper::ReleaseGraphicsResources(vtkWindow* win)
{
  this->Shading->ReleaseGraphicsResources(win);
  this->Superclass::ReleaseGraphicsResources(win);
}

//------------------------------------------------------------------------------
void vtkReliefMapper::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  this->Shading->PrintForMapper(os, indent);
  os << indent << "LightSet: " << this->GetLightSet() << "\n";
  os << indent << "IrradianceProbes: " << this->GetIrradianceProbes() << "\n";
  os << indent << "ReliefTexture: " << this->GetReliefTexture() << "\n";
}
