// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefProperty.h"

#include "DepthScaleSetting.h"
#include "DisplayTransform.h"
#include "vtkLightCollection.h"
#include "vtkMath.h"
#include "vtkObjectFactory.h"
#include "vtkReliefMessageForwarder.h"

#include <algorithm>
#include <cmath>
#include <cstring>
#include <string>

vtkStandardNewMacro(vtkReliefProperty);

namespace
{
const char* const MethodNames[] = { "texture", "bump", "parallax", "parallax-limit",
  "parallax-slope", "iterative-parallax", "binary", "secant", "linear", "pom", "relief", "interval",
  "relaxed-cone", "relaxed-cone-interval", "cone", "max-mipmap" };
static_assert(sizeof(MethodNames) / sizeof(MethodNames[0]) == vtkReliefProperty::NumberOfMethods,
  "one name per method");
const char* const NormalFilterNames[] = { "mean", "visible", "masked" };
static_assert(sizeof(NormalFilterNames) / sizeof(NormalFilterNames[0]) ==
    vtkReliefProperty::MaskedNormalFilter + 1,
  "one name per normal filter");
} // namespace

//------------------------------------------------------------------------------
vtkReliefProperty::vtkReliefProperty()
  : Exposure(mesolight::ReliefLightSetDisplay.Exposure)
  , ToneMapping(mesolight::ReliefLightSetDisplay.ToneMap == mesolight::ToneMapOperator::Reinhard)
{
}

//------------------------------------------------------------------------------
vtkReliefProperty::~vtkReliefProperty() = default;

//------------------------------------------------------------------------------
void vtkReliefProperty::SetLights(vtkLightCollection* lights)
{
  if (this->Lights != lights)
  {
    this->Lights = lights;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLightCollection* vtkReliefProperty::GetLights()
{
  return this->Lights;
}

//------------------------------------------------------------------------------
void vtkReliefProperty::SetDepthLimitPlane(const double origin[3], const double normal[3])
{
  const bool finite = std::all_of(origin, origin + 3, [](double x) { return std::isfinite(x); }) &&
    std::all_of(normal, normal + 3, [](double x) { return std::isfinite(x); });
  if (!finite || vtkMath::Norm(normal) <= 0.0)
  {
    vtkErrorMacro(<< "SetDepthLimitPlane needs a finite point and a non-zero finite normal; the "
                     "depth limit is left as it was.");
    return;
  }
  if (this->HasDepthLimitPlane && std::equal(origin, origin + 3, this->DepthLimitOrigin) &&
    std::equal(normal, normal + 3, this->DepthLimitNormal))
  {
    return;
  }
  std::copy(origin, origin + 3, this->DepthLimitOrigin);
  std::copy(normal, normal + 3, this->DepthLimitNormal);
  this->HasDepthLimitPlane = true;
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkReliefProperty::RemoveDepthLimitPlane()
{
  if (this->HasDepthLimitPlane)
  {
    this->HasDepthLimitPlane = false;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
const char* vtkReliefProperty::GetMethodName(int method)
{
  if (method < 0 || method >= NumberOfMethods)
  {
    return "unknown";
  }
  return MethodNames[method];
}

//------------------------------------------------------------------------------
const char* vtkReliefProperty::GetNormalFilterName(int filter)
{
  if (filter < MeanNormalFilter || filter > MaskedNormalFilter)
  {
    return "unknown";
  }
  return NormalFilterNames[filter];
}

//------------------------------------------------------------------------------
int vtkReliefProperty::GetNormalFilterFromName(const char* name)
{
  for (int f = MeanNormalFilter; name && f <= MaskedNormalFilter; ++f)
  {
    if (std::strcmp(name, NormalFilterNames[f]) == 0)
    {
      return f;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
int vtkReliefProperty::GetMethodFromName(const char* name)
{
  if (!name)
  {
    return -1;
  }
  if (std::strcmp(name, "steep") == 0)
  {
    return LinearSearch;
  }
  for (int m = 0; m < NumberOfMethods; ++m)
  {
    if (std::strcmp(name, MethodNames[m]) == 0)
    {
      return m;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
std::string vtkReliefProperty::GetMethodNameList()
{
  std::string names;
  for (int m = 0; m < NumberOfMethods; ++m)
  {
    names += std::string(m > 0 ? ", " : "") + MethodNames[m];
  }
  return names;
}

//------------------------------------------------------------------------------
bool vtkReliefProperty::SetMethodByName(const char* name)
{
  const int method = GetMethodFromName(name);
  if (method < 0)
  {
    vtkErrorMacro(<< "Unknown relief method '" << (name ? name : "(null)")
                  << "'; the method is kept. The names are " << GetMethodNameList() << ".");
    return false;
  }
  this->SetMethod(method);
  return true;
}

//------------------------------------------------------------------------------
int vtkReliefProperty::GetRequiredConeMap(int method)
{
  switch (method)
  {
    case RelaxedConeBinary:
    case RelaxedConeInterval:
      return RelaxedConeMap;
    case ConservativeCone:
      return ConservativeConeMap;
    default:
      return NoConeMap;
  }
}

//------------------------------------------------------------------------------
void vtkReliefProperty::SetDepthScale(double requested)
{
  mesolight::SetDepthScaleOf(this, this->DepthScale, requested, mesolight::MaximumDepthScale);
}

//------------------------------------------------------------------------------
void vtkReliefProperty::SetMessageOwner(vtkObject* owner)
{
  if (!this->Messages)
  {
    this->Messages = vtkSmartPointer<vtkReliefMessageForwarder>::New();
    this->Messages->Watch(this);
  }
  this->Messages->SetOwner(owner);
}

//------------------------------------------------------------------------------
vtkObject* vtkReliefProperty::GetMessageOwner()
{
  return this->Messages ? this->Messages->GetOwner() : nullptr;
}

//------------------------------------------------------------------------------
void vtkReliefProperty::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Method: " << GetMethodName(this->Method) << "\n";
  os << indent << "LinearSteps: " << this->LinearSteps << "\n";
  os << indent << "RefinementSteps: " << this->RefinementSteps << "\n";
  os << indent << "DepthScale: " << this->DepthScale << "\n";
  os << indent << "UseTextureDepthScale: " << (this->UseTextureDepthScale ? "On" : "Off") << "\n";
  os << indent << "SelfShadowing: " << (this->SelfShadowing ? "On" : "Off") << "\n";
  os << indent << "Silhouettes: " << (this->Silhouettes ? "On" : "Off") << "\n";
  os << indent << "SurfaceCurvature: " << (this->SurfaceCurvature ? "On" : "Off") << "\n";
  os << indent << "WriteDepth: " << (this->WriteDepth ? "On" : "Off") << "\n";
  os << indent << "DepthLimitPlane: ";
  if (this->HasDepthLimitPlane)
  {
    os << "(" << this->DepthLimitOrigin[0] << ", " << this->DepthLimitOrigin[1] << ", "
       << this->DepthLimitOrigin[2] << "), normal (" << this->DepthLimitNormal[0] << ", "
       << this->DepthLimitNormal[1] << ", " << this->DepthLimitNormal[2] << ")\n";
  }
  else
  {
    os << "(none)\n";
  }
  os << indent << "RepeatTexture: " << (this->RepeatTexture ? "On" : "Off") << "\n";
  os << indent << "FloatTextures: " << (this->FloatTextures ? "On" : "Off") << "\n";
  static const char* const outputNames[NumberOfOutputs] = { "shaded", "hit u", "hit v",
    "light visibility", "non-finite check", "sample count" };
  os << indent << "Output: "
     << (this->Output >= 0 && this->Output < NumberOfOutputs ? outputNames[this->Output]
                                                             : "unknown")
     << "\n";
  os << indent << "AdaptiveSteps: " << (this->AdaptiveSteps ? "On" : "Off") << "\n";
  os << indent << "MinimumSteps: " << this->MinimumSteps << "\n";
  os << indent << "LevelOfDetail: " << (this->LevelOfDetail ? "On" : "Off") << "\n";
  os << indent << "NormalFilter: " << GetNormalFilterName(this->NormalFilter) << "\n";
  os << indent << "FarViewRays: " << this->FarViewRays << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "Emission: " << this->Emission[0] << " " << this->Emission[1] << " "
     << this->Emission[2] << "\n";
  os << indent << "ToneMapping: " << (this->ToneMapping ? "On" : "Off") << "\n";
  os << indent << "EncodeSRGB: " << (this->EncodeSRGB ? "On" : "Off") << "\n";
  os << indent << "Lights: "
     << (this->Lights ? std::to_string(this->Lights->GetNumberOfItems())
                      : std::string("(the renderer's)"))
     << "\n";
  os << indent << "LightSetThreshold: " << this->LightSetThreshold << "\n";
  os << indent << "ShadowedLights: " << this->ShadowedLights << "\n";
  os << indent << "ShadowCulling: " << (this->ShadowCulling ? "On" : "Off") << "\n";
  os << indent << "MessageOwner: " << this->GetMessageOwner() << "\n";
}
