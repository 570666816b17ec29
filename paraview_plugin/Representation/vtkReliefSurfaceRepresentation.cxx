// SPDX-License-Identifier: BSD-3-Clause
#include "vtkReliefSurfaceRepresentation.h"

#include "vtkAttachReliefTexture.h"
#include "vtkCompositeReliefMapper.h"
#include "vtkDataObjectLeaves.h"
#include "vtkImageData.h"
#include "vtkObjectFactory.h"
#include "vtkPVLODActor.h"
#include "vtkPVView.h"
#include "vtkPointData.h"
#include "vtkReliefProperty.h"

vtkStandardNewMacro(vtkReliefSurfaceRepresentation);

//------------------------------------------------------------------------------
vtkReliefSurfaceRepresentation::vtkReliefSurfaceRepresentation()
{
  // ParaView's geometry representations draw through a composite mapper: replace the
  // superclass' mappers by relief ones, then wire them up again.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  auto* mapper = vtkCompositeReliefMapper::New();
  auto* lodMapper = vtkCompositeReliefMapper::New();
  mapper->SetReliefProperty(this->ReliefProperty);
  lodMapper->SetReliefProperty(this->ReliefProperty);
  // Errors of the shared settings reach whoever watches the (full-resolution) mapper.
  this->ReliefProperty->SetMessageOwner(mapper);
  this->Mapper = mapper;
  this->LODMapper = lodMapper;
  // The relief texture's bake is the one source of truth unless the user overrides it.
  this->ReliefProperty->SetUseTextureDepthScale(true);
  // Float albedos (EXR) are colours, not scalars to map through a lookup table.
  this->AttachedColorTexture->SetColorModeToDirectScalars();
  this->AttachedColorTexture->InterpolateOn();
  this->AttachedColorTexture->MipmapOn();
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetTexture(vtkTexture* texture)
{
  this->UserTexture = texture;
  this->Superclass::SetTexture(texture);
}

//------------------------------------------------------------------------------
int vtkReliefSurfaceRepresentation::ProcessViewRequest(
  vtkInformationRequestKey* requestType, vtkInformation* inInfo, vtkInformation* outInfo)
{
  if (!this->Superclass::ProcessViewRequest(requestType, inInfo, outInfo))
  {
    return 0;
  }
  if (requestType == vtkPVView::REQUEST_RENDER())
  {
    this->UpdateAttachedColorTexture();
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::UpdateAttachedColorTexture()
{
  if (this->UserTexture)
  {
    return;
  }
  vtkSmartPointer<vtkImageData> color;
  for (vtkDataObject* leaf : mesolight::DataObjectLeaves(this->Mapper->GetInputDataObject(0, 0)))
  {
    if ((color = vtkAttachReliefTexture::GetAttachedColorTexture(leaf)))
    {
      break;
    }
  }
  if (!color)
  {
    if (this->Actor->GetTexture() == this->AttachedColorTexture)
    {
      this->Actor->SetTexture(nullptr);
    }
    return;
  }
  // Re-upload only when the texels changed: the detached image shares the field array.
  auto* shown = vtkImageData::SafeDownCast(this->AttachedColorTexture->GetInput());
  if (!shown || shown->GetPointData()->GetScalars() != color->GetPointData()->GetScalars())
  {
    this->AttachedColorTexture->SetInputData(color);
  }
  if (this->Actor->GetTexture() != this->AttachedColorTexture)
  {
    this->Actor->SetTexture(this->AttachedColorTexture);
  }
}

//------------------------------------------------------------------------------
vtkReliefProperty* vtkReliefSurfaceRepresentation::GetReliefProperty()
{
  return this->ReliefProperty;
}

// Each proxy command sets the shared property and marks the representation modified.
#define MESOLIGHT_FORWARD(Name, Type, PropertySetter)                                              \
  void vtkReliefSurfaceRepresentation::Set##Name(Type value)                                       \
  {                                                                                                \
    this->ReliefProperty->PropertySetter(value);                                                   \
    this->Modified();                                                                              \
  }

MESOLIGHT_FORWARD(ReliefMethod, int, SetMethod)
MESOLIGHT_FORWARD(LinearSteps, int, SetLinearSteps)
MESOLIGHT_FORWARD(RefinementSteps, int, SetRefinementSteps)
MESOLIGHT_FORWARD(AdaptiveSteps, bool, SetAdaptiveSteps)
MESOLIGHT_FORWARD(MinimumSteps, int, SetMinimumSteps)
MESOLIGHT_FORWARD(ReliefDepthScale, double, SetDepthScale)
MESOLIGHT_FORWARD(SelfShadowing, bool, SetSelfShadowing)
MESOLIGHT_FORWARD(Silhouettes, bool, SetSilhouettes)
MESOLIGHT_FORWARD(WriteDepth, bool, SetWriteDepth)
MESOLIGHT_FORWARD(RepeatTexture, bool, SetRepeatTexture)
MESOLIGHT_FORWARD(LevelOfDetail, bool, SetLevelOfDetail)
MESOLIGHT_FORWARD(Exposure, double, SetExposure)
MESOLIGHT_FORWARD(ToneMapping, bool, SetToneMapping)
MESOLIGHT_FORWARD(LightSetThreshold, double, SetLightSetThreshold)
MESOLIGHT_FORWARD(ShadowedLights, int, SetShadowedLights)
#undef MESOLIGHT_FORWARD

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::SetOverrideDepthScale(bool on)
{
  this->ReliefProperty->SetUseTextureDepthScale(!on);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkReliefSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ReliefProperty:\n";
  this->ReliefProperty->PrintSelf(os, indent.GetNextIndent());
}
