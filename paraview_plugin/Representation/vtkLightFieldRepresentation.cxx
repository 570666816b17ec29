// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldRepresentation.h"

#include "vtkCompositeLightFieldMapper.h"
#include "vtkObjectFactory.h"

vtkStandardNewMacro(vtkLightFieldRepresentation);

//------------------------------------------------------------------------------
vtkLightFieldRepresentation::vtkLightFieldRepresentation()
{
  // As vtkReliefSurfaceRepresentation: replace the superclass' composite mappers, then wire
  // them up again.
  this->Mapper->Delete();
  this->LODMapper->Delete();
  this->Mapper = vtkCompositeLightFieldMapper::New();
  this->LODMapper = vtkCompositeLightFieldMapper::New();
  this->SetupDefaults();
}

//------------------------------------------------------------------------------
void vtkLightFieldRepresentation::SetExposure(double exposure)
{
  static_cast<vtkCompositeLightFieldMapper*>(this->Mapper)->SetExposure(exposure);
  static_cast<vtkCompositeLightFieldMapper*>(this->LODMapper)->SetExposure(exposure);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRepresentation::SetAutoExposure(bool on)
{
  static_cast<vtkCompositeLightFieldMapper*>(this->Mapper)->SetAutoExposure(on);
  static_cast<vtkCompositeLightFieldMapper*>(this->LODMapper)->SetAutoExposure(on);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRepresentation::SetToneMapping(int mode)
{
  static_cast<vtkCompositeLightFieldMapper*>(this->Mapper)->SetToneMap(mode);
  static_cast<vtkCompositeLightFieldMapper*>(this->LODMapper)->SetToneMap(mode);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Mapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
