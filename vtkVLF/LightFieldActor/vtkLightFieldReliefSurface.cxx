// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReliefSurface.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkVirtualLightField.h"
#include "vtkVirtualLightFieldCore.h"

#include "vtkAlgorithmOutput.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkReliefMapper.h"
#include "vtkStreamingDemandDrivenPipeline.h"

#include "EmitterLights.h"
#include "LightField.h"
#include "PatchComparison.h" // ToWorld
#include "Progress.h"
#include "ReliefSurface.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <exception>

namespace vlf = mesolight::vlf;

namespace
{
// The field's emitters as VTK lights: radiant intensity Le x Area, the area in world units
// (world = centre + unit / scale).
void AddEmitterLights(const vlf::LightField& field, vtkLightCollection* lights)
{
  const double scale = field.NormalizationScale();
  for (const vlf::EmitterLight& emitter : vlf::EstimateEmitterLights(field).Lights)
  {
    const glm::vec3 world = vlf::ToWorld(field, emitter.Position);
    const glm::vec3 unitIntensity = emitter.Intensity();
    const double position[3] = { world.x, world.y, world.z };
    const double normal[3] = { emitter.Normal.x, emitter.Normal.y, emitter.Normal.z };
    const double intensity[3] = { unitIntensity.x / (scale * scale),
      unitIntensity.y / (scale * scale), unitIntensity.z / (scale * scale) };
    vtkNew<vtkLight> light;
    vtkReliefMapper::ConfigureEmitterLight(light, position, normal, intensity);
    lights->AddItem(light);
  }
}
} // namespace

vtkStandardNewMacro(vtkLightFieldReliefSurface);
vtkCxxSetObjectMacro(vtkLightFieldReliefSurface, LightFieldActor, vtkLightFieldActor);

//------------------------------------------------------------------------------
vtkLightFieldReliefSurface::vtkLightFieldReliefSurface()
  : ProbesPerSide(vlf::DefaultReliefProbesPerSide)
{
  this->SetNumberOfInputPorts(1);
  this->SetNumberOfOutputPorts(2);
}

//------------------------------------------------------------------------------
vtkLightFieldReliefSurface::~vtkLightFieldReliefSurface()
{
  this->SetLightFieldActor(nullptr);
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefSurface::SetLightFieldConnection(vtkAlgorithmOutput* output)
{
  this->SetInputConnection(0, output);
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightFieldReliefSurface::GetProbesOutput()
{
  return vtkImageData::SafeDownCast(this->GetOutputDataObject(1));
}

//------------------------------------------------------------------------------
vtkMTimeType vtkLightFieldReliefSurface::GetMTime()
{
  // The actor changes with every setting and camera-driven update; only a new field (loaded or
  // lent) makes the outputs stale, and the probes are too costly to recompute for less.
  if (this->LightFieldActor &&
    vtkLightFieldActorCore::GetLightField(this->LightFieldActor) != this->ExecutedField)
  {
    this->Modified();
  }
  return this->Superclass::GetMTime();
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::FillInputPortInformation(int, vtkInformation* info)
{
  info->Set(vtkAlgorithm::INPUT_REQUIRED_DATA_TYPE(), "vtkPolyData");
  info->Set(vtkAlgorithm::INPUT_IS_OPTIONAL(), 1);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::FillOutputPortInformation(int port, vtkInformation* info)
{
  info->Set(vtkDataObject::DATA_TYPE_NAME(), port == 1 ? "vtkImageData" : "vtkPolyData");
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  const int n = this->ProbesPerSide;
  const int extent[6] = { 0, 9 * n - 1, 0, n - 1, 0, 0 };
  vtkInformation* info = outputVector->GetInformationObject(1);
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_FLOAT, 3);
  return 1;
}

//------------------------------------------------------------------------------
int vtkLightFieldReliefSurface::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkPolyData* output = vtkPolyData::GetData(outputVector, 0);
  vtkImageData* probesOutput = vtkImageData::GetData(outputVector, 1);
  this->EmitterLights->RemoveAllItems();
  const vlf::LightField* field = nullptr;
  if (this->LightFieldActor)
  {
    field = vtkLightFieldActorCore::GetLightField(this->LightFieldActor);
    this->ExecutedField = field;
  }
  else if (auto* producer = vtkVirtualLightField::SafeDownCast(this->GetInputAlgorithm(0, 0)))
  {
    field = vtkVirtualLightFieldCore::GetLightField(producer);
  }
  if (!field)
  {
    vtkErrorMacro("a relief surface needs a light field: a vtkLightFieldActor showing one, or a "
                  "vtkVirtualLightField that has propagated connected to input port 0");
    return 0;
  }
  vlf::ReliefSurface surface;
  std::vector<mesolight::SH9> probes;
  const int n = this->ProbesPerSide;
  try
  {
    surface = vlf::FindReliefSurface(*field, this->SurfaceName);
    probes = vlf::ReliefSurfaceProbes(*field, surface, n, n, mesolight::AlgorithmProgress(this));
  }
  catch (const vlf::AbortedError&)
  {
    return 1; // stopped: empty outputs
  }
  catch (const std::exception& e)
  {
    if (!this->LightFieldActor && mesolight::SurfaceNameList(field->Scene()) == "(none)")
    {
      // vtkTriangleSceneConverter's polydata carries materials, not surface names.
      vtkErrorMacro(<< e.what()
                    << "; a field propagated from polydata has no surface names: load it from a "
                       "snapshot of a named scene into a vtkLightFieldActor and give that actor");
      return 0;
    }
    vtkErrorMacro(<< e.what());
    return 0;
  }
  for (int c = 0; c < 3; ++c)
  {
    this->SurfaceDiffuse[c] = surface.Diffuse[c];
  }

  // Port 0: the triangles, three points each (the surface's own normal and texture map).
  const mesolight::TriangleScene& scene = field->Scene();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName("TextureCoordinates");
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkCellArray> polys;
  for (const std::size_t t : surface.Triangles)
  {
    vtkIdType ids[3];
    for (int corner = 0; corner < 3; ++corner)
    {
      const glm::vec3 unit = scene.Vertex(t, corner);
      const glm::vec3 world = vlf::ToWorld(*field, unit);
      ids[corner] = points->InsertNextPoint(world.x, world.y, world.z);
      const glm::dvec3 uvw = surface.TextureOf(glm::dvec3(unit));
      tcoords->InsertNextTuple2(uvw.x, uvw.y);
      normals->InsertNextTuple3(surface.Normal.x, surface.Normal.y, surface.Normal.z);
    }
    // Counter-clockwise about the front normal (the relief lies behind the front side).
    const glm::dvec3 a(scene.Vertex(t, 0)), b(scene.Vertex(t, 1)), c(scene.Vertex(t, 2));
    if (glm::dot(glm::cross(b - a, c - a), surface.Normal) < 0.0)
    {
      std::swap(ids[1], ids[2]);
    }
    polys->InsertNextCell(3, ids);
  }
  output->SetPoints(points);
  output->SetPolys(polys);
  output->GetPointData()->SetNormals(normals);
  output->GetPointData()->SetTCoords(tcoords);

  // Port 1: the probes, pixel (9 i + k, j).
  probesOutput->SetExtent(0, 9 * n - 1, 0, n - 1, 0, 0);
  probesOutput->AllocateScalars(VTK_FLOAT, 3);
  auto* values = static_cast<float*>(probesOutput->GetScalarPointer());
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const mesolight::SH9& sh = probes[static_cast<std::size_t>(j) * n + i];
      for (int k = 0; k < 9; ++k)
      {
        float* pixel = values + 3 * (static_cast<std::size_t>(j) * 9 * n + 9 * i + k);
        for (int c = 0; c < 3; ++c)
        {
          pixel[c] = static_cast<float>(sh.L[k][c]);
        }
      }
    }
  }
  probesOutput->GetPointData()->GetScalars()->SetName("IrradianceProbes");

  AddEmitterLights(*field, this->EmitterLights);
  return 1;
}

//------------------------------------------------------------------------------
bool vtkLightFieldReliefSurface::GetEmitterLights(
  vtkLightFieldActor* actor, vtkLightCollection* lights)
{
  const vlf::LightField* field = actor ? vtkLightFieldActorCore::GetLightField(actor) : nullptr;
  if (!field || !lights)
  {
    return false;
  }
  AddEmitterLights(*field, lights);
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldReliefSurface::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightFieldActor: " << this->LightFieldActor << "\n";
  os << indent << "SurfaceName: " << this->SurfaceName << "\n";
  os << indent << "ProbesPerSide: " << this->ProbesPerSide << "\n";
  os << indent << "EmitterLights: " << this->EmitterLights->GetNumberOfItems() << "\n";
}
