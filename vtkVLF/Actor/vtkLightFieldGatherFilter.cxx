// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldGatherFilter.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkNew.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataNormals.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkVirtualLightField.h"

#include "LightField.h"
#include "ObjectGatherer.h"
#include "Progress.h"

#include <algorithm>
#include <cmath>
#include <stdexcept>

vtkStandardNewMacro(vtkLightFieldGatherFilter);

namespace
{
// The vtkVirtualLightField whose output reaches `algorithm`: itself, or the first one found
// walking up through the first input of pass-through filters (ParaView's post filter).
vtkVirtualLightField* FindLightField(vtkAlgorithm* algorithm)
{
  for (int depth = 0; algorithm && depth < 16; ++depth)
  {
    if (auto* field = vtkVirtualLightField::SafeDownCast(algorithm))
    {
      return field;
    }
    if (algorithm->GetNumberOfInputPorts() < 1 || algorithm->GetNumberOfInputConnections(0) < 1)
    {
      return nullptr;
    }
    algorithm = algorithm->GetInputAlgorithm(0, 0);
  }
  return nullptr;
}
} // namespace

//------------------------------------------------------------------------------
vtkLightFieldGatherFilter::vtkLightFieldGatherFilter()
{
  this->SetNumberOfInputPorts(2);
}

//------------------------------------------------------------------------------
vtkLightFieldGatherFilter::~vtkLightFieldGatherFilter() = default;

//------------------------------------------------------------------------------
void vtkLightFieldGatherFilter::SetLightFieldConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(1, output);
}

//------------------------------------------------------------------------------
int vtkLightFieldGatherFilter::FillInputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  (void)port;
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldGatherFilter::RequestUpdateExtent(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  vtkInformation* out = outputVector->GetInformationObject(0);
  vtkInformation* surface = inputVector[0]->GetInformationObject(0);
  if (surface)
  {
    // The surface: the piece asked of this filter.
    surface->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(),
      out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER()));
    surface->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(),
      out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES()));
    surface->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(),
      out->Get(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS()));
  }
  if (vtkInformation* field = inputVector[1]->GetInformationObject(0))
  {
    field->Set(vtkStreamingDemandDrivenPipeline::UPDATE_PIECE_NUMBER(), 0);
    field->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_PIECES(), 1);
    field->Set(vtkStreamingDemandDrivenPipeline::UPDATE_NUMBER_OF_GHOST_LEVELS(), 0);
  }
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldGatherFilter::RequestData(
  vtkInformation*, vtkInformationVector** inputVector, vtkInformationVector* outputVector)
{
  using namespace mesolight;
  vtkPolyData* input = vtkPolyData::GetData(inputVector[0], 0);
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  this->OutsidePoints = 0;
  if (!input || !output)
  {
    vtkErrorMacro("Light Field Gather needs a surface (polygonal data) as its Input.");
    return 0;
  }
  output->ShallowCopy(input);
  if (input->GetNumberOfPoints() == 0)
  {
    return 1; // an empty piece (e.g. another rank's): nothing to gather
  }
  vtkVirtualLightField* producer = FindLightField(this->GetInputAlgorithm(1, 0));
  const vlf::LightField* field = producer ? producer->GetLightField() : nullptr;
  if (!field)
  {
    vtkErrorMacro("Light Field Gather needs the output of a Virtual Light Field filter that has "
                  "propagated successfully as its Light Field input.");
    return 0;
  }
  if (input->GetNumberOfPolys() == 0)
  {
    vtkErrorMacro("Light Field Gather needs a surface with polygons (the input has none): apply "
                  "Extract Surface or Triangulate first.");
    return 0;
  }

  // Normals: the input's, else computed without splitting (the points stay the input's).
  vtkDataArray* normals = input->GetPointData()->GetNormals();
  vtkNew<vtkPolyDataNormals> normalFilter;
  if (!normals || normals->GetNumberOfComponents() != 3 ||
    normals->GetNumberOfTuples() != input->GetNumberOfPoints())
  {
    vtkNew<vtkPolyData> copy;
    copy->CopyStructure(input);
    normalFilter->SetInputData(copy);
    normalFilter->SplittingOff();
    normalFilter->ConsistencyOff();
    normalFilter->ComputePointNormalsOn();
    normalFilter->ComputeCellNormalsOff();
    normalFilter->Update();
    normals = normalFilter->GetOutput()->GetPointData()->GetNormals();
    if (!normals || normals->GetNumberOfTuples() != input->GetNumberOfPoints())
    {
      vtkErrorMacro("Light Field Gather could not compute normals for the surface.");
      return 0;
    }
    output->GetPointData()->SetNormals(normals); // what the irradiance was gathered with
  }

  vlf::ObjectMesh mesh;
  const vtkIdType n = input->GetNumberOfPoints();
  mesh.Points.resize(static_cast<std::size_t>(n));
  mesh.Normals.resize(static_cast<std::size_t>(n));
  for (vtkIdType i = 0; i < n; ++i)
  {
    double p[3], m[3];
    input->GetPoint(i, p);
    normals->GetTuple(i, m);
    mesh.Points[i] = glm::vec3(p[0], p[1], p[2]);
    mesh.Normals[i] = glm::vec3(m[0], m[1], m[2]);
  }
  // Polygons as fans (only the normals repair and the placement checks use the triangles).
  vtkCellArray* polys = input->GetPolys();
  vtkNew<vtkIdList> ids;
  for (polys->InitTraversal(); polys->GetNextCell(ids);)
  {
    for (vtkIdType k = 1; k + 1 < ids->GetNumberOfIds(); ++k)
    {
      mesh.Triangles.emplace_back(static_cast<unsigned>(ids->GetId(0)),
        static_cast<unsigned>(ids->GetId(k)), static_cast<unsigned>(ids->GetId(k + 1)));
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    mesh.Kd[c] = static_cast<float>(std::min(1.0, std::max(0.0, this->Reflectance[c])));
  }

  vlf::GatherSettings settings;
  settings.UseCache = false;
  settings.Directions = this->DirectionSet == HALF_DIRECTIONS ? vlf::DirectionSampling::Half
    : this->DirectionSet == IMPORTANCE_DIRECTIONS             ? vlf::DirectionSampling::Importance
                                                              : vlf::DirectionSampling::All;
  settings.Progress = AlgorithmProgress(this);
  try
  {
    vlf::ObjectGatherer gatherer(*field);
    const vlf::ShadedObject& shaded =
      gatherer.Gather(mesh, vlf::WorldToUnitSphere(*field), settings);
    vtkNew<vtkFloatArray> irradiance, radiance;
    irradiance->SetName("Irradiance");
    radiance->SetName("Radiance");
    irradiance->SetNumberOfComponents(3);
    radiance->SetNumberOfComponents(3);
    irradiance->SetNumberOfTuples(n);
    radiance->SetNumberOfTuples(n);
    for (vtkIdType i = 0; i < n; ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        irradiance->SetTypedComponent(i, c, shaded.Irradiance[i][c]);
        radiance->SetTypedComponent(i, c, shaded.Radiance[i][c]);
      }
    }
    output->GetPointData()->AddArray(irradiance);
    output->GetPointData()->AddArray(radiance);
    output->GetPointData()->SetActiveScalars("Radiance");
    this->OutsidePoints = static_cast<vtkIdType>(shaded.OutsidePoints);
    if (shaded.OutsidePoints > 0)
    {
      vtkWarningMacro(<< shaded.OutsidePoints << " of " << n
                      << " points lie outside the light field's bounding sphere; they were "
                         "gathered on its boundary.");
    }
  }
  catch (const vlf::AbortedError&)
  {
    output->Initialize();
    vtkWarningMacro("Light Field Gather aborted.");
    return 1;
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Light Field Gather cannot shade this surface: " << e.what() << ".");
    return 0;
  }
  return 1;
}

//------------------------------------------------------------------------------
void vtkLightFieldGatherFilter::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Reflectance: " << this->Reflectance[0] << " " << this->Reflectance[1] << " "
     << this->Reflectance[2] << "\n";
  os << indent << "DirectionSet: " << this->DirectionSet << "\n";
  os << indent << "OutsidePoints: " << this->OutsidePoints << "\n";
}
