// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefShading.h"

#include "DepthScaleSetting.h" // MaximumDepthScale

#include "vtkActor.h"
#include "vtkCamera.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkIrradianceProbesTexture.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkLightSetTexture.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkMinDepthPyramidTexture.h"
#include "vtkObjectFactory.h"
#include "vtkOpenGLRenderWindow.h"
#include "vtkPointData.h"
#include "vtkProperty.h"
#include "vtkReliefGeometryCache.h"
#include "vtkReliefMessageForwarder.h"
#include "vtkReliefProperty.h"
#include "vtkReliefRadianceHook.h"
#include "vtkReliefShaderSource.h"
#include "vtkReliefTextureCache.h"
#include "vtkRenderer.h"
#include "vtkShaderProgram.h"
#include "vtkTexture.h"
#include "vtkTextureObject.h"

#include <algorithm>
#include <cmath>
#include <vector>

vtkStandardNewMacro(vtkReliefShading);

//------------------------------------------------------------------------------
vtkReliefShading::vtkReliefShading()
{
  // Every piece reports through one forwarder, to the mapper's observers.
  this->Messages->Watch(this);
  this->Messages->Watch(this->GeometryCache);
  this->Messages->Watch(this->ReliefTexture);
  this->Messages->Watch(this->ReliefTexture->GetPyramid());
  this->Messages->Watch(this->LightSet);
  this->Messages->Watch(this->Probes);
  this->Messages->Watch(this->ShaderSource);
}

//------------------------------------------------------------------------------
vtkReliefShading::~vtkReliefShading() = default;

//------------------------------------------------------------------------------
void vtkReliefShading::SetMessageOwner(vtkObject* owner)
{
  this->Messages->SetOwner(owner);
}

//------------------------------------------------------------------------------
vtkReliefProperty* vtkReliefShading::GetReliefProperty()
{
  if (!this->ReliefProperty)
  {
    this->ReliefProperty = vtkSmartPointer<vtkReliefProperty>::New();
    this->ReliefProperty->SetMessageOwner(this->Messages->GetOwner());
  }
  return this->ReliefProperty;
}

//------------------------------------------------------------------------------
bool vtkReliefShading::SetReliefProperty(vtkReliefProperty* property)
{
  if (this->ReliefProperty == property)
  {
    return false;
  }
  this->ReliefProperty = property;
  return true;
}

//------------------------------------------------------------------------------
void vtkReliefShading::PrintForMapper(ostream& os, vtkIndent indent)
{
  os << indent << "ReliefProperty: " << this->ReliefProperty.Get() << "\n";
  if (this->ReliefProperty)
  {
    this->ReliefProperty->PrintSelf(os, indent.GetNextIndent());
  }
  os << indent << "Shading:\n";
  this->PrintSelf(os, indent.GetNextIndent());
}

//------------------------------------------------------------------------------
vtkMTimeType vtkReliefShading::GetReliefPropertyMTime()
{
  return this->ReliefProperty ? this->ReliefProperty->GetMTime() : 0;
}

//------------------------------------------------------------------------------
vtkReliefGeometryCache* vtkReliefShading::GetGeometryCache()
{
  return this->GeometryCache;
}

//------------------------------------------------------------------------------
bool vtkReliefShading::BeginFrame(
  const void* drawer, vtkImageData* relief, const std::vector<vtkObject*>& inputs)
{
  this->FrameDrawer = drawer;
  this->FrameInputs.clear();
  for (vtkObject* input : inputs)
  {
    this->FrameInputs.emplace_back(input, input ? input->GetMTime() : 0);
  }
  const auto failed = this->FailedFrames.find(drawer);
  if (failed != this->FailedFrames.end())
  {
    if (failed->second == this->FrameInputs)
    {
      return false;
    }
    this->FailedFrames.erase(failed);
  }
  if (!relief)
  {
    vtkErrorMacro(<< "No relief texture. In ParaView: apply Mesolight Attach Relief Texture to "
                     "this surface, with Mesolight Relief Texture's output as its Relief "
                     "Texture input. In VTK: give the mapper vtkReliefTextureFilter's output.");
    this->FrameFailed();
    return false;
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkReliefShading::FrameFailed()
{
  this->FailedFrames[this->FrameDrawer] = this->FrameInputs;
}

//------------------------------------------------------------------------------
bool vtkReliefShading::StartDraw(vtkOpenGLRenderWindow* renWin, vtkReliefProperty* property,
  vtkImageData* relief, vtkImageData* lights, vtkImageData* probes, vtkActor* actor)
{
  this->Drawing = false;
  this->Property = property;
  if (!relief) // (reported by BeginFrame)
  {
    return false;
  }
  const int method = property->GetMethod();
  const bool maximumMipmap =
    vtkReliefShaderSource::GetMarchMethod(property, this->ShaderSource->GetCurvedGeometry()) ==
    vtkReliefProperty::MaximumMipmap;
  const int requiredCones = vtkReliefProperty::GetRequiredConeMap(method);
  // Only what the method reads is uploaded: the pyramid for MaximumMipmap, cones for cone methods.
  if (!this->ReliefTexture->Update(renWin, relief, property->GetLevelOfDetail(), maximumMipmap,
        requiredCones != vtkReliefProperty::NoConeMap, property->GetFloatTextures(),
        property->GetLevelOfDetail()))
  {
    return false;
  }
  // A malformed light set or probes: reported, the relief drawn without them (lit as the
  // renderer's lights light it), not hidden.
  this->LightSet->Update(renWin, lights);
  this->Probes->Update(renWin, probes);
  if (requiredCones != vtkReliefProperty::NoConeMap &&
    this->ReliefTexture->GetConeMap() == vtkReliefProperty::NoConeMap)
  {
    vtkErrorMacro(<< "Method '" << vtkReliefProperty::GetMethodName(method)
                  << "' needs a relief texture with cone ratios. In ParaView: apply Mesolight "
                     "Cone Map to the depth image and connect its output as Attach Relief "
                     "Texture's Relief Texture (or pick a method without cones). In VTK: use "
                     "vtkConeMapFilter's output.");
    return false;
  }
  if (requiredCones == vtkReliefProperty::ConservativeConeMap &&
    this->ReliefTexture->GetConeMap() == vtkReliefProperty::RelaxedConeMap)
  {
    vtkWarningMacro(<< "Conservative cone stepping with relaxed cones may step through the "
                       "surface; bake conservative cones for method 'cone'.");
  }
  // A NaN or Inf texel of the albedo texture is turned into a number (often 0, black) when VTK
  // uploads it, where no check in the shader can see it: refused before drawing, like the relief
  // texels. Checked once per image and modification.
  vtkImageData* albedo = actor->GetTexture() ? actor->GetTexture()->GetInput() : nullptr;
  vtkDataArray* albedoTexels = albedo ? albedo->GetPointData()->GetScalars() : nullptr;
  if (albedoTexels && albedoTexels->GetDataType() != VTK_UNSIGNED_CHAR &&
    (albedo != this->CheckedAlbedo || albedo->GetMTime() != this->CheckedAlbedoTime))
  {
    const vtkIdType count = albedoTexels->GetNumberOfTuples();
    const int components = albedoTexels->GetNumberOfComponents();
    for (vtkIdType t = 0; t < count; ++t)
    {
      for (int c = 0; c < components; ++c)
      {
        if (!std::isfinite(albedoTexels->GetComponent(t, c)))
        {
          vtkErrorMacro(<< "The albedo texture has a non-finite value at texel " << t
                        << " (component " << c << "); NaN or Inf cannot be rendered.");
          return false;
        }
      }
    }
    this->CheckedAlbedo = albedo;
    this->CheckedAlbedoTime = albedo->GetMTime();
  }
  this->ShaderSource->Configure(property, actor->GetTexture() != nullptr,
    this->ReliefTexture->GetConePacked(), this->LightSet->GetHasLightSet(),
    this->Probes->GetHasProbes());
  this->ShaderSource->SetTextureLayout(this->ReliefTexture->GetFloatTextures(),
    this->ReliefTexture->GetNormalsStored(), this->ReliefTexture->GetMomentsUploaded(),
    this->ReliefTexture->GetNormalsFromDepth());
  const int wrap =
    property->GetRepeatTexture() ? vtkTextureObject::Repeat : vtkTextureObject::ClampToEdge;
  this->ReliefTexture->ActivateTextures(wrap);
  this->PyramidActive = maximumMipmap;
  if (this->PyramidActive)
  {
    this->ReliefTexture->GetPyramid()->GetTextureObject()->Activate();
  }
  this->LightSetActive = this->LightSet->GetHasLightSet();
  if (this->LightSetActive)
  {
    this->LightSet->GetTextureObject()->Activate();
  }
  this->ProbesActive = this->Probes->GetHasProbes();
  if (this->ProbesActive)
  {
    this->Probes->Activate();
  }
  this->RadianceHookActive = this->RadianceHook && this->RadianceHook->StartDraw(renWin);
  static const std::string none;
  this->ShaderSource->SetRadianceHookSource(
    this->RadianceHookActive ? this->RadianceHook->GetFragmentDeclarations() : none);
  this->Drawing = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkReliefShading::FinishDraw()
{
  if (!this->Drawing)
  {
    return;
  }
  this->ReliefTexture->DeactivateTextures();
  if (this->PyramidActive)
  {
    this->ReliefTexture->GetPyramid()->GetTextureObject()->Deactivate();
  }
  if (this->LightSetActive)
  {
    this->LightSet->GetTextureObject()->Deactivate();
  }
  if (this->ProbesActive)
  {
    this->Probes->Deactivate();
  }
  if (this->RadianceHookActive)
  {
    this->RadianceHook->FinishDraw();
  }
  this->RadianceHookActive = false;
  this->Drawing = false;
}

//------------------------------------------------------------------------------
void vtkReliefShading::SetCurvedGeometry(bool curved)
{
  this->ShaderSource->SetCurvedGeometry(curved);
}

//------------------------------------------------------------------------------
bool vtkReliefShading::ShaderKeyChanged(const void* cellBO) const
{
  return this->ShaderSource->KeyChanged(cellBO);
}

//------------------------------------------------------------------------------
void vtkReliefShading::ReplaceShaderValuesBefore(std::string& vs, std::string& fs, bool noVTKLights)
{
  this->ShaderSource->ReplaceValuesBefore(vs, fs, noVTKLights);
}

//------------------------------------------------------------------------------
void vtkReliefShading::ReplaceShaderValuesAfter(std::string& fs, const void* cellBO)
{
  this->ShaderSource->ReplaceValuesAfter(fs, cellBO);
}

//------------------------------------------------------------------------------
void vtkReliefShading::SetShaderParameters(
  vtkShaderProgram* program, vtkRenderer* ren, vtkActor* actor)
{
  if (!program || !this->Property)
  {
    return;
  }
  vtkReliefProperty* p = this->Property;
  vtkReliefTextureCache* relief = this->ReliefTexture;
  relief->SetShaderParameters(program);
  const bool hasBaked = relief->GetBakedDepthScale() >= 0.0;
  const double depthScale = hasBaked && p->GetUseTextureDepthScale()
    ? std::min(relief->GetBakedDepthScale(), mesolight::MaximumDepthScale)
    : p->GetDepthScale();
  program->SetUniformf("mlDepthScale", static_cast<float>(depthScale));
  // Normals baked with another depth scale are rescaled through the depth gradient.
  const double baked = hasBaked ? relief->GetBakedDepthScale() : depthScale;
  program->SetUniformf("mlGradientScale", baked > 0.0 ? static_cast<float>(1.0 / baked) : 0.0f);
  const int* size = relief->GetSize();
  program->SetUniformf("mlTexelAspect", size[0] > 0 ? static_cast<float>(size[1]) / size[0] : 1.0f);
  program->SetUniformi("mlLinearSteps", p->GetLinearSteps());
  program->SetUniformi("mlRefinementSteps", p->GetRefinementSteps());
  program->SetUniformi("mlMinimumSteps", std::min(p->GetMinimumSteps(), p->GetLinearSteps()));
  const float textureSize[2] = { static_cast<float>(size[0]), static_cast<float>(size[1]) };
  program->SetUniform2f("mlTextureSize", textureSize);
  vtkMinDepthPyramidTexture* pyramid = relief->GetPyramid();
  if (this->PyramidActive && pyramid->GetTextureObject())
  {
    program->SetUniformi("mlMinDepthPyramid", pyramid->GetTextureObject()->GetTextureUnit());
    program->SetUniformi("mlPyramidLevels", pyramid->GetNumberOfLevels());
    program->SetUniformf("mlPyramidTop", static_cast<float>(pyramid->GetMinimumDepth()));
  }

  vtkCamera* camera = ren->GetActiveCamera();
  program->SetUniformi("mlCameraParallel", camera->GetParallelProjection());
  vtkMatrix4x4* projection =
    camera->GetProjectionTransformMatrix(ren->GetTiledAspectRatio(), -1, 1);
  float columnMajor[16];
  for (int r = 0; r < 4; ++r)
  {
    for (int c = 0; c < 4; ++c)
    {
      columnMajor[c * 4 + r] = static_cast<float>(projection->GetElement(r, c));
    }
  }
  program->SetUniformMatrix4x4("mlViewToClip", columnMajor);
  if (p->GetWriteDepth() && p->GetHasDepthLimitPlane())
  {
    // The plane in view coordinates (the camera's view transform is rigid: the normal turns as
    // a direction).
    vtkMatrix4x4* view = camera->GetViewTransformMatrix();
    const double* o = p->GetDepthLimitOrigin();
    const double* n = p->GetDepthLimitNormal();
    double originVC[4] = { o[0], o[1], o[2], 1.0 };
    view->MultiplyPoint(originVC, originVC);
    double normalVC[3];
    for (int r = 0; r < 3; ++r)
    {
      normalVC[r] = view->GetElement(r, 0) * n[0] + view->GetElement(r, 1) * n[1] +
        view->GetElement(r, 2) * n[2];
    }
    vtkMath::Normalize(normalVC);
    const float plane[4] = { static_cast<float>(normalVC[0]), static_cast<float>(normalVC[1]),
      static_cast<float>(normalVC[2]), static_cast<float>(-vtkMath::Dot(normalVC, originVC)) };
    program->SetUniform4f("mlDepthLimitVC", plane);
  }

  // Tangents are surface directions: transform them with the linear part of model-view.
  vtkNew<vtkMatrix4x4> modelView;
  vtkMatrix4x4::Multiply4x4(camera->GetViewTransformMatrix(), actor->GetMatrix(), modelView);
  float tangentMatrix[9];
  for (int r = 0; r < 3; ++r)
  {
    for (int c = 0; c < 3; ++c)
    {
      tangentMatrix[c * 3 + r] = static_cast<float>(modelView->GetElement(r, c));
    }
  }
  program->SetUniformMatrix3x3("mlTangentMatrix", tangentMatrix);

  vtkProperty* property = actor->GetProperty();
  const double* sc = property->GetSpecularColor();
  const float specular[3] = { static_cast<float>(property->GetSpecular() * sc[0]),
    static_cast<float>(property->GetSpecular() * sc[1]),
    static_cast<float>(property->GetSpecular() * sc[2]) };
  program->SetUniform3f("mlSpecularColor", specular);
  program->SetUniformf("mlSpecularPower", static_cast<float>(property->GetSpecularPower()));
  program->SetUniformf("mlExposure", static_cast<float>(p->GetExposure()));
  const double* emission = p->GetEmission();
  const float emitted[3] = { static_cast<float>(emission[0]), static_cast<float>(emission[1]),
    static_cast<float>(emission[2]) };
  program->SetUniform3f("mlEmission", emitted);
  if (this->LightSet->GetHasLightSet())
  {
    program->SetUniformi("mlLightSet", this->LightSet->GetTextureObject()->GetTextureUnit());
    program->SetUniformi("mlLightSetCount", this->LightSet->GetNumberOfLights());
    program->SetUniformf("mlLightSetCutoff",
      static_cast<float>(p->GetLightSetThreshold() * this->LightSet->GetMaximumLuminance()));
    program->SetUniformi("mlShadowedLights", p->GetShadowedLights());
  }
  if (this->ProbesActive)
  {
    this->Probes->SetUniforms(program);
  }
  if (this->LightSet->GetHasLightSet() || this->ProbesActive)
  {
    float worldToView[9];
    vtkMatrix4x4* view = camera->GetViewTransformMatrix();
    for (int r = 0; r < 3; ++r)
    {
      for (int c = 0; c < 3; ++c)
      {
        worldToView[c * 3 + r] = static_cast<float>(view->GetElement(r, c));
      }
    }
    program->SetUniformMatrix3x3("mlWorldToView", worldToView);
  }
  if (this->RadianceHookActive)
  {
    this->RadianceHook->SetShaderParameters(program, ren);
  }

  this->SetLightUniforms(program, ren);
}

//------------------------------------------------------------------------------
bool vtkReliefShading::SetRadianceHook(vtkReliefRadianceHook* hook)
{
  if (this->RadianceHook == hook)
  {
    return false;
  }
  this->RadianceHook = hook;
  return true;
}

//------------------------------------------------------------------------------
vtkReliefRadianceHook* vtkReliefShading::GetRadianceHook()
{
  return this->RadianceHook;
}

//------------------------------------------------------------------------------
void vtkReliefShading::SetLightUniforms(vtkShaderProgram* program, vtkRenderer* ren)
{
  float color[MaximumNumberOfLights][3] = {};
  float direction[MaximumNumberOfLights][3] = {};
  float position[MaximumNumberOfLights][3] = {};
  float attenuation[MaximumNumberOfLights][3] = {};
  float coneAngle[MaximumNumberOfLights] = {};
  float exponent[MaximumNumberOfLights] = {};
  int positional[MaximumNumberOfLights] = {};

  vtkMatrix4x4* view = ren->GetActiveCamera()->GetViewTransformMatrix();
  int count = 0;
  vtkCollectionSimpleIterator it;
  // The property's own lights when it has them (a relief lit by a light field's emitters).
  vtkLightCollection* lights =
    this->Property && this->Property->GetLights() ? this->Property->GetLights() : ren->GetLights();
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    if (!light->GetSwitch())
    {
      continue;
    }
    if (count == MaximumNumberOfLights)
    {
      if (!this->WarnedTooManyLights)
      {
        vtkWarningMacro(<< "More than " << MaximumNumberOfLights
                        << " lights are switched on; the relief surface shades the first "
                        << MaximumNumberOfLights << ".");
        this->WarnedTooManyLights = true;
      }
      break;
    }
    const double intensity = light->GetIntensity();
    const double* diffuse = light->GetDiffuseColor();
    double lp[4] = { 0, 0, 0, 1 };
    double lfp[3];
    light->GetTransformedPosition(lp);
    light->GetTransformedFocalPoint(lfp);
    double dirWC[3] = { lfp[0] - lp[0], lfp[1] - lp[1], lfp[2] - lp[2] };
    vtkMath::Normalize(dirWC);
    double posVC[4];
    view->MultiplyPoint(lp, posVC);
    for (int k = 0; k < 3; ++k)
    {
      color[count][k] = static_cast<float>(diffuse[k] * intensity);
      direction[count][k] = static_cast<float>(view->GetElement(k, 0) * dirWC[0] +
        view->GetElement(k, 1) * dirWC[1] + view->GetElement(k, 2) * dirWC[2]);
      position[count][k] = static_cast<float>(posVC[k]);
      attenuation[count][k] = static_cast<float>(light->GetAttenuationValues()[k]);
    }
    coneAngle[count] = static_cast<float>(light->GetConeAngle());
    exponent[count] = static_cast<float>(light->GetExponent());
    positional[count] = light->GetPositional();
    ++count;
  }
  program->SetUniformi("mlNumberOfLights", count);
  program->SetUniform3fv("mlLightColor", MaximumNumberOfLights, color);
  program->SetUniform3fv("mlLightDirectionVC", MaximumNumberOfLights, direction);
  program->SetUniform3fv("mlLightPositionVC", MaximumNumberOfLights, position);
  program->SetUniform3fv("mlLightAttenuation", MaximumNumberOfLights, attenuation);
  program->SetUniform1fv("mlLightConeAngle", MaximumNumberOfLights, coneAngle);
  program->SetUniform1fv("mlLightExponent", MaximumNumberOfLights, exponent);
  program->SetUniform1iv("mlLightPositional", MaximumNumberOfLights, positional);
}

//------------------------------------------------------------------------------
vtkReliefTextureCache* vtkReliefShading::GetReliefTextureCache()
{
  return this->ReliefTexture;
}

//------------------------------------------------------------------------------
void vtkReliefShading::ReleaseGraphicsResources(vtkWindow* win)
{
  this->ReliefTexture->ReleaseGraphicsResources(win);
  this->LightSet->ReleaseGraphicsResources(win);
  this->Probes->ReleaseGraphicsResources(win);
  if (this->RadianceHook)
  {
    this->RadianceHook->ReleaseGraphicsResources(win);
  }
  this->ShaderSource->ForgetShaders();
}

//------------------------------------------------------------------------------
void vtkReliefShading::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReliefTexture:\n";
  this->ReliefTexture->PrintSelf(os, indent.GetNextIndent());
  os << indent << "LightSet:\n";
  this->LightSet->PrintSelf(os, indent.GetNextIndent());
  os << indent << "IrradianceProbes:\n";
  this->Probes->PrintSelf(os, indent.GetNextIndent());
  os << indent << "RadianceHook: " << this->RadianceHook.Get() << "\n";
  os << indent << "ShaderSource:\n";
  this->ShaderSource->PrintSelf(os, indent.GetNextIndent());
}
