#include "vtkReliefSurfaceRepresentation.h"

#include "vtkCompositeReliefMapper.h"
#include "vtkObjectFactory.h"
#include "vtkReliefShading.h"

vtkStandardNewMacro(vtkReliefSurfaceRepresentation);

//------------------------------------------------------------------------------
vtkReliefSurfaceRepresentation::vtkReliefSurfaceRepresentation()
{
  // ParaView's geometry representations draw through a composite mapper: replace the
  // superclass' mappers by relief ones, then wire them up again.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkCompositeReliefMapper::New();
  this->LODMapper = vtkCompositeReliefMapper::New();
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
vtkReliefShading* vtkReliefSurfaceRepresentation::Shading(int which)
{
  return static_cast<vtkCompositeReliefMapper*>(which == 0 ? this->Mapper : this->LODMapper)
    ->GetShading();
}

// Each setter sets both mappers' shadings and marks the representation modified.
#define MESOLIGHT_FORWARD(Name, Type, ShadingSetter)                                              \
  void vtkReliefSurfaceRepresentation::Set##Name(Type value)                                       \
  {                                                                                                \
    this->Shading(0)->ShadingSetter(value);                                                        \
    this->Shading(1)->ShadingSetter(value);                                                        \
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
void vtkReliefSurfaceRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Shading:\n";
  this->Shading(0)->PrintSelf(os, indent.GetNextIndent());
}
