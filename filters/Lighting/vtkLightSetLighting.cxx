// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightSetLighting.h"

#include "LightSetSplit.h"
#include "MathConstants.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCameraPass.h"
#include "vtkDataArray.h"
#include "vtkLight.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderPass.h"
#include "vtkRenderPassCollection.h"
#include "vtkRenderer.h"
#include "vtkSequencePass.h"
#include "vtkShaderProperty.h"
#include "vtkShadowMapBakerPass.h"
#include "vtkShadowMapPass.h"
#include "vtkSmartPointer.h"
#include "vtkUniforms.h"
#include "vtkWeakPointer.h"

#include <algorithm>
#include <cmath>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkLightSetLighting);

namespace
{
constexpr const char* LightTag = "//VTK::Light::Impl";

// After VTK's lighting (the tag stays in front, so VTK and vtkShadowMapPass substitute it
// first): the remainder's irradiance at the world normal, as diffuse light. The coefficients
// already hold Exposure / pi.
constexpr const char* RemainderShader = R"(//VTK::Light::Impl
  {
    vec3 mlN = normalize(normalVCVSOutput.x * mesolightViewRows[0] +
      normalVCVSOutput.y * mesolightViewRows[1] + normalVCVSOutput.z * mesolightViewRows[2]);
    vec3 mlE = mesolightRemainder[0] + mesolightRemainder[1] * mlN.y +
      mesolightRemainder[2] * mlN.z + mesolightRemainder[3] * mlN.x +
      mesolightRemainder[4] * (mlN.x * mlN.y) + mesolightRemainder[5] * (mlN.y * mlN.z) +
      mesolightRemainder[6] * (3.0 * mlN.z * mlN.z - 1.0) + mesolightRemainder[7] * (mlN.x * mlN.z) +
      mesolightRemainder[8] * (mlN.x * mlN.x - mlN.y * mlN.y);
    gl_FragData[0].rgb += diffuseColor * max(mlE, vec3(0.0));
  }
)";
} // namespace

struct vtkLightSetLighting::Internals
{
  vtkSmartPointer<vtkPolyData> Lights;
  mesolight::LightSetSplit Split;
  vtkWeakPointer<vtkRenderer> Renderer;
  unsigned long ObserverTag = 0;
  std::vector<vtkSmartPointer<vtkLight>> AddedLights;
  std::vector<vtkWeakPointer<vtkActor>> Actors;
  vtkSmartPointer<vtkCallbackCommand> Callback;
  vtkWeakPointer<vtkRenderPass> Pass; // the shadow pass Apply set (cleared only if still set)
  float Coefficients[9][3] = {};

  void Detach()
  {
    if (this->Renderer && this->ObserverTag)
    {
      this->Renderer->RemoveObserver(this->ObserverTag);
    }
    this->ObserverTag = 0;
    this->Renderer = nullptr;
  }
};

//------------------------------------------------------------------------------
vtkLightSetLighting::vtkLightSetLighting()
  : Internal(new Internals)
{
  this->Internal->Callback = vtkSmartPointer<vtkCallbackCommand>::New();
  this->Internal->Callback->SetClientData(this);
  this->Internal->Callback->SetCallback([](vtkObject*, unsigned long, void* self, void*)
    { static_cast<vtkLightSetLighting*>(self)->UpdateViewUniforms(); });
}

//------------------------------------------------------------------------------
vtkLightSetLighting::~vtkLightSetLighting()
{
  this->Internal->Detach();
}

//------------------------------------------------------------------------------
void vtkLightSetLighting::SetLightSet(vtkPolyData* lights)
{
  if (this->Internal->Lights != lights)
  {
    this->Internal->Lights = lights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLightSetLighting::GetLightSet()
{
  return this->Internal->Lights;
}

//------------------------------------------------------------------------------
bool vtkLightSetLighting::Split()
{
  vtkPolyData* lights = this->Internal->Lights;
  if (!lights)
  {
    vtkErrorMacro("No light set: SetLightSet() with vtkMedianCutLights' or vtkLightSetReader's "
                  "output port 0.");
    return false;
  }
  const vtkIdType n = lights->GetNumberOfPoints();
  vtkDataArray* irradiance = lights->GetPointData()->GetArray("Irradiance");
  if (n < 1 || !irradiance || irradiance->GetNumberOfComponents() != 3 ||
    irradiance->GetNumberOfTuples() != n)
  {
    vtkErrorMacro("The light set needs points (the light directions) and a 3-component "
                  "\"Irradiance\" point array; it has "
      << n << " points" << (irradiance ? "" : " and no \"Irradiance\" array") << ".");
    return false;
  }
  std::vector<mesolight::SetLight> set(static_cast<size_t>(n));
  for (vtkIdType k = 0; k < n; ++k)
  {
    mesolight::SetLight& l = set[static_cast<size_t>(k)];
    lights->GetPoint(k, l.Direction);
    irradiance->GetTuple(k, l.Irradiance);
    const double length = std::sqrt(l.Direction[0] * l.Direction[0] +
      l.Direction[1] * l.Direction[1] + l.Direction[2] * l.Direction[2]);
    bool ok = std::isfinite(length) && length > 0.0;
    for (int c = 0; c < 3; ++c)
    {
      ok = ok && std::isfinite(l.Irradiance[c]) && l.Irradiance[c] >= 0.0;
      l.Direction[c] = ok ? l.Direction[c] / length : 0.0;
    }
    if (!ok)
    {
      vtkErrorMacro("Light " << k
                             << " of the light set has a zero or non-finite direction or a "
                                "negative or non-finite irradiance.");
      return false;
    }
  }
  const mesolight::RemainderModel model = this->Remainder == RemainderNone
    ? mesolight::RemainderModel::None
    : (this->Remainder == RemainderAmbient ? mesolight::RemainderModel::Ambient
                                           : mesolight::RemainderModel::SphericalHarmonics);
  this->Internal->Split = mesolight::SplitLightSet(set, this->NumberOfDirectionalLights, model);
  this->Internal->Split.PolynomialCoefficients(this->Internal->Coefficients);
  const float scale = static_cast<float>(this->Exposure / mesolight::Pi<double>);
  for (auto& c : this->Internal->Coefficients)
  {
    for (float& v : c)
    {
      v *= scale;
    }
  }
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightSetLighting::EvaluateIrradiance(const double n[3], double e[3])
{
  if (!this->Split())
  {
    return false;
  }
  this->Internal->Split.Evaluate(n, e);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightSetLighting::Apply(vtkRenderer* renderer)
{
  if (!renderer)
  {
    vtkErrorMacro("Apply() needs a renderer.");
    return false;
  }
  if (!this->Split())
  {
    return false;
  }
  Internals& in = *this->Internal;
  in.Detach();
  in.AddedLights.clear();
  in.Actors.clear();

  renderer->AutomaticLightCreationOff();
  renderer->RemoveAllLights();
  const double scale = this->Exposure / mesolight::Pi<double>;
  for (const mesolight::SetLight& l : in.Split.Directional)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->PositionalOff();
    light->SetFocalPoint(0.0, 0.0, 0.0);
    light->SetPosition(l.Direction);
    const double m = std::max({ l.Irradiance[0], l.Irradiance[1], l.Irradiance[2] });
    if (m > 0.0)
    {
      light->SetColor(l.Irradiance[0] / m, l.Irradiance[1] / m, l.Irradiance[2] / m);
    }
    light->SetIntensity(m * scale);
    renderer->AddLight(light);
    in.AddedLights.emplace_back(light);
  }
  if (in.AddedLights.empty())
  {
    // Without any light VTK draws unlit colours and computes no normal; a black light keeps
    // lighting (and the normal the remainder needs) on.
    vtkNew<vtkLight> black;
    black->SetLightTypeToSceneLight();
    black->PositionalOff();
    black->SetIntensity(0.0);
    renderer->AddLight(black);
    in.AddedLights.emplace_back(black);
  }

  if (this->Shadows)
  {
    vtkNew<vtkShadowMapPass> shadows;
    shadows->GetShadowMapBakerPass()->SetResolution(this->ShadowMapResolution);
    vtkNew<vtkRenderPassCollection> passes;
    passes->AddItem(shadows->GetShadowMapBakerPass());
    passes->AddItem(shadows);
    vtkNew<vtkSequencePass> sequence;
    sequence->SetPasses(passes);
    vtkNew<vtkCameraPass> camera;
    camera->SetDelegatePass(sequence);
    renderer->SetPass(camera);
    in.Pass = camera.Get();
  }
  else if (in.Pass && renderer->GetPass() == in.Pass)
  {
    renderer->SetPass(nullptr);
  }

  in.Renderer = renderer;
  in.ObserverTag = renderer->AddObserver(vtkCommand::StartEvent, in.Callback);
  vtkActorCollection* actors = renderer->GetActors();
  actors->InitTraversal();
  while (vtkActor* actor = actors->GetNextActor())
  {
    this->ApplyToActor(actor);
  }
  this->UpdateViewUniforms();
  return true;
}

//------------------------------------------------------------------------------
void vtkLightSetLighting::ApplyToActor(vtkActor* actor)
{
  if (!actor || !actor->GetMapper() || !actor->GetProperty()->GetLighting() ||
    !actor->GetMapper()->IsA("vtkOpenGLPolyDataMapper") ||
    actor->GetMapper()->IsA("vtkReliefMapper"))
  {
    return;
  }
  vtkShaderProperty* shader = actor->GetShaderProperty();
  shader->ClearFragmentShaderReplacement(LightTag, true);
  shader->AddFragmentShaderReplacement(LightTag, true, RemainderShader, false);
  vtkUniforms* uniforms = shader->GetFragmentCustomUniforms();
  uniforms->SetUniform3fv("mesolightRemainder", 9, this->Internal->Coefficients);
  this->Internal->Actors.emplace_back(actor);
  if (this->Internal->Renderer)
  {
    this->UpdateViewUniforms();
  }
}

//------------------------------------------------------------------------------
void vtkLightSetLighting::UpdateViewUniforms()
{
  Internals& in = *this->Internal;
  if (!in.Renderer)
  {
    return;
  }
  // World -> view rotation rows R: n_view = R n_world, so n_world = sum_i n_view[i] R[i].
  vtkMatrix4x4* view = in.Renderer->GetActiveCamera()->GetViewTransformMatrix();
  float rows[3][3];
  for (int i = 0; i < 3; ++i)
  {
    for (int j = 0; j < 3; ++j)
    {
      rows[i][j] = static_cast<float>(view->GetElement(i, j));
    }
  }
  for (const auto& actor : in.Actors)
  {
    if (actor)
    {
      vtkUniforms* uniforms = actor->GetShaderProperty()->GetFragmentCustomUniforms();
      uniforms->SetUniform3fv("mesolightViewRows", 3, rows);
      uniforms->SetUniform3fv("mesolightRemainder", 9, in.Coefficients);
    }
  }
}

//------------------------------------------------------------------------------
void vtkLightSetLighting::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightSet: " << this->Internal->Lights.Get() << "\n";
  os << indent << "NumberOfDirectionalLights: " << this->NumberOfDirectionalLights << "\n";
  os << indent << "Remainder: " << this->Remainder << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "Shadows: " << (this->Shadows ? "On" : "Off") << "\n";
  os << indent << "ShadowMapResolution: " << this->ShadowMapResolution << "\n";
}
