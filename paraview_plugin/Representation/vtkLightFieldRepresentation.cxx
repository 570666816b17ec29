// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldRepresentation.h"

#include "vtkAlgorithm.h"
#include "vtkAppendPolyData.h"
#include "vtkCompositeLightFieldMapper.h"
#include "vtkFieldData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLightFieldGatherFilter.h"
#include "vtkMultiProcessController.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPolyData.h"

#include <vector>

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
  // A gathered surface moved after the gather is said here, once per new data (RequestData): the
  // level-of-detail copy's points are moved by its decimation, not by the user.
  static_cast<vtkCompositeLightFieldMapper*>(this->Mapper)->CheckGatheredPositionsOff();
  static_cast<vtkCompositeLightFieldMapper*>(this->LODMapper)->CheckGatheredPositionsOff();
  this->SetupDefaults();
  this->SetNumberOfInputPorts(2); // 1: the Shadow Caster
}

//------------------------------------------------------------------------------
vtkLightFieldRepresentation::~vtkLightFieldRepresentation() = default;

//------------------------------------------------------------------------------
int vtkLightFieldRepresentation::FillInputPortInformation(int port, vtkInformation* info)
{
  if (port == 1)
  {
    info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
    info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
    return 1;
  }
  return this->Superclass::FillInputPortInformation(port, info);
}

//------------------------------------------------------------------------------
int vtkLightFieldRepresentation::RequestData(
  vtkInformation* request, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  if (!this->Superclass::RequestData(request, inputVector, outputVector))
  {
    return 0;
  }
  vtkCompositeLightFieldMapper::WarnIfMovedSinceGathered(
    vtkDataObject::GetData(inputVector[0], 0), this);
  vtkPolyData* piece =
    this->GetNumberOfInputConnections(1) > 0 ? vtkPolyData::GetData(inputVector[1], 0) : nullptr;
  vtkSmartPointer<vtkPolyData> whole = GatherShadowCaster(piece);
  this->Caster = whole;
  static_cast<vtkCompositeLightFieldMapper*>(this->Mapper)->SetShadowCaster(whole);
  static_cast<vtkCompositeLightFieldMapper*>(this->LODMapper)->SetShadowCaster(whole);
  return 1;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkPolyData> vtkLightFieldRepresentation::GatherShadowCaster(vtkPolyData* piece)
{
  // This rank's piece, then every rank's (a shadow map needs the whole object).
  vtkSmartPointer<vtkPolyData> whole;
  vtkMultiProcessController* controller = vtkMultiProcessController::GetGlobalController();
  if (controller && controller->GetNumberOfProcesses() > 1)
  {
    int mine = piece ? 1 : 0, any = 0;
    controller->AllReduce(&mine, &any, 1, vtkCommunicator::MAX_OP);
    if (!any)
    {
      return whole;
    }
    vtkNew<vtkPolyData> local;
    if (piece)
    {
      local->ShallowCopy(piece);
    }
    std::vector<vtkSmartPointer<vtkDataObject>> pieces;
    controller->AllGather(local, pieces);
    vtkNew<vtkAppendPolyData> append;
    vtkFieldData* fields = nullptr;
    for (const auto& received : pieces)
    {
      auto* poly = vtkPolyData::SafeDownCast(received);
      if (poly && poly->GetNumberOfPoints() > 0)
      {
        append->AddInputData(poly);
      }
      if (poly && !fields && poly->GetFieldData() &&
        poly->GetFieldData()->GetAbstractArray(vtkLightFieldGatherFilter::GetEmittersName()))
      {
        fields = poly->GetFieldData();
      }
    }
    whole = vtkSmartPointer<vtkPolyData>::New();
    if (append->GetNumberOfInputConnections(0) > 0)
    {
      append->Update();
      whole->ShallowCopy(append->GetOutput());
    }
    if (fields)
    {
      whole->GetFieldData()->ShallowCopy(fields); // the emitters travel as field data
    }
  }
  else if (piece)
  {
    whole = vtkSmartPointer<vtkPolyData>::New();
    whole->ShallowCopy(piece);
  }
  return whole;
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLightFieldRepresentation::GetShadowCaster()
{
  return this->Caster;
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
void vtkLightFieldRepresentation::SetShadowMode(int mode)
{
  static_cast<vtkCompositeLightFieldMapper*>(this->Mapper)->SetShadowMode(mode);
  static_cast<vtkCompositeLightFieldMapper*>(this->LODMapper)->SetShadowMode(mode);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRepresentation::SetShadowMapResolution(int texels)
{
  static_cast<vtkCompositeLightFieldMapper*>(this->Mapper)->SetShadowMapResolution(texels);
  static_cast<vtkCompositeLightFieldMapper*>(this->LODMapper)->SetShadowMapResolution(texels);
  this->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldRepresentation::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "ShadowCaster: "
     << (this->Caster ? std::to_string(this->Caster->GetNumberOfPoints()) + " points" : "(none)")
     << "\n";
  os << indent << "Mapper:\n";
  this->Mapper->PrintSelf(os, indent.GetNextIndent());
}
