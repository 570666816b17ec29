// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldObjectReliefProbes.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkTriangleSceneConverter.h"

#include "LightField.h"
#include "ObjectMesh.h"
#include "ObjectReliefProbes.h"

#include <chrono>
#include <exception>

namespace vlf = mesolight::vlf;

vtkStandardNewMacro(vtkLightFieldObjectReliefProbes);

namespace
{
// Chart `chart` of `mesh` as polydata: its own points (renumbered), normals, texture coordinates.
vtkSmartPointer<vtkPolyData> ChartPolyData(
  const vlf::ObjectMesh& mesh, const vlf::ObjectChart& chart)
{
  mesolight::TriangleMesh part;
  std::vector<std::uint32_t> renumbered(mesh.Positions.size(), ~0u);
  for (const std::uint32_t t : chart.Triangles)
  {
    glm::uvec3 tri = mesh.Triangles[t];
    for (int k = 0; k < 3; ++k)
    {
      std::uint32_t& id = renumbered[tri[k]];
      if (id == ~0u)
      {
        id = static_cast<std::uint32_t>(part.Positions.size());
        part.Positions.push_back(mesh.Positions[tri[k]]);
        part.Normals.push_back(mesh.Normals[tri[k]]);
        part.TextureCoordinates.push_back(mesh.TextureCoordinates[tri[k]]);
      }
      tri[k] = id;
    }
    part.Triangles.push_back(tri);
  }
  return vtkTriangleSceneConverter::MeshToPolyData(part);
}
} // namespace

//------------------------------------------------------------------------------
vtkLightFieldObjectReliefProbes::vtkLightFieldObjectReliefProbes() = default;

//------------------------------------------------------------------------------
vtkLightFieldObjectReliefProbes::~vtkLightFieldObjectReliefProbes() = default;

//------------------------------------------------------------------------------
void vtkLightFieldObjectReliefProbes::SetLightFieldActor(vtkLightFieldActor* scene)
{
  if (this->Scene != scene)
  {
    this->Scene = scene;
    this->Probes.reset();
    this->Field = nullptr;
    this->Modified();
  }
}

//------------------------------------------------------------------------------
vtkLightFieldActor* vtkLightFieldObjectReliefProbes::GetLightFieldActor()
{
  return this->Scene;
}

//------------------------------------------------------------------------------
bool vtkLightFieldObjectReliefProbes::Fail(const char* why)
{
  vtkErrorMacro(<< why);
  return false;
}

//------------------------------------------------------------------------------
bool vtkLightFieldObjectReliefProbes::Update()
{
  vtkLightFieldActor* scene = this->Scene;
  if (!scene)
  {
    return this->Fail("no light field actor: set one with SetLightFieldActor");
  }
  scene->UpdateMovableObject(); // the placement the tracer and the shadows use this frame
  const vlf::LightField* field = vtkLightFieldActorCore::GetLightField(scene);
  if (!field)
  {
    return this->Fail("the light field actor has no field to light the object's relief with");
  }
  vtkActor* object = scene->GetMovableObject();
  vtkMapper* mapper = object ? object->GetMapper() : nullptr;
  if (!mapper)
  {
    return this->Fail(
      "the light field actor has no movable object (with a mapper) to carry a relief");
  }
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    mapper->GetInputAlgorithm()->Update();
  }
  vtkPolyData* data = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (!data)
  {
    return this->Fail("the movable object's mapper has no vtkPolyData input");
  }
  const auto start = std::chrono::steady_clock::now();
  try
  {
    if (field != this->Field || !this->Probes)
    {
      this->Probes.reset(new vlf::ObjectReliefProbes(*field));
      this->Field = field;
      this->Data = nullptr;
      this->ObjectVersion = 0;
    }
    if (data != this->Data || data->GetMTime() != this->DataTime ||
      this->ProbesPerSide != this->ChartsPerSide)
    {
      vlf::ObjectMesh mesh;
      vtkTriangleSceneConverter::ToTriangleMesh(data, mesh);
      const std::string problem = mesh.Validate();
      if (!problem.empty())
      {
        return this->Fail(("the movable object cannot carry a relief: " + problem).c_str());
      }
      if (mesh.Normals.size() != mesh.Positions.size())
      {
        mesh.ComputeNormals();
      }
      this->Probes->SetMesh(mesh, this->ProbesPerSide);
      this->Data = data;
      this->DataTime = data->GetMTime();
      this->ChartsPerSide = this->ProbesPerSide;
      this->Charts.clear();
      this->Images.clear();
      for (const vlf::ObjectChart& chart : this->Probes->Charts())
      {
        this->Charts.push_back(ChartPolyData(mesh, chart));
        vtkNew<vtkImageData> image;
        image->SetDimensions(9 * chart.ProbesU, chart.ProbesV, 1);
        image->AllocateScalars(VTK_FLOAT, 3);
        image->GetPointData()->GetScalars()->SetName("IrradianceProbes");
        this->Images.emplace_back(image);
      }
      ++this->ChartsVersion;
      this->ObjectVersion = 0;
    }
    if (this->ObjectVersion == scene->GetObjectVersion())
    {
      return true; // nothing moved
    }
    const glm::mat4 placement =
      vtkLightFieldActorCore::UnitSpherePlacement(*field, object->GetMatrix());
    vlf::ReliefProbeSettings settings;
    this->LastGatheredProbes = static_cast<vtkIdType>(this->Probes->Gather(placement, settings));
  }
  catch (const std::exception& e)
  {
    this->Charts.clear();
    this->Images.clear();
    this->Data = nullptr;
    return this->Fail(e.what());
  }
  const auto& charts = this->Probes->Charts();
  for (std::size_t c = 0; c < charts.size(); ++c)
  {
    const std::vector<mesolight::SH9>& values = this->Probes->Probes()[c];
    auto* out = static_cast<float*>(this->Images[c]->GetScalarPointer());
    const int nu = charts[c].ProbesU;
    for (std::size_t q = 0; q < values.size(); ++q)
    {
      const std::size_t i = q % static_cast<std::size_t>(nu), j = q / static_cast<std::size_t>(nu);
      for (int k = 0; k < 9; ++k)
      {
        float* pixel = out + 3 * (j * 9 * static_cast<std::size_t>(nu) + 9 * i + k);
        for (int channel = 0; channel < 3; ++channel)
        {
          pixel[channel] = static_cast<float>(values[q].L[k][channel]);
        }
      }
    }
    this->Images[c]->Modified();
  }
  this->ObjectVersion = scene->GetObjectVersion();
  this->LastSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  this->Modified();
  return true;
}

//------------------------------------------------------------------------------
int vtkLightFieldObjectReliefProbes::GetNumberOfCharts() const
{
  return static_cast<int>(this->Charts.size());
}

//------------------------------------------------------------------------------
vtkPolyData* vtkLightFieldObjectReliefProbes::GetChart(int i)
{
  return i >= 0 && i < this->GetNumberOfCharts() ? this->Charts[static_cast<std::size_t>(i)].Get()
                                                 : nullptr;
}

//------------------------------------------------------------------------------
vtkImageData* vtkLightFieldObjectReliefProbes::GetProbes(int i)
{
  return i >= 0 && i < this->GetNumberOfCharts() ? this->Images[static_cast<std::size_t>(i)].Get()
                                                 : nullptr;
}

//------------------------------------------------------------------------------
vtkIdType vtkLightFieldObjectReliefProbes::GetOverlappingProbes() const
{
  vtkIdType n = 0;
  if (this->Probes)
  {
    for (const vlf::ObjectChart& chart : this->Probes->Charts())
    {
      n += static_cast<vtkIdType>(chart.OverlappingProbes);
    }
  }
  return n;
}

//------------------------------------------------------------------------------
vtkIdType vtkLightFieldObjectReliefProbes::GetNumberOfProbes() const
{
  return this->Probes ? static_cast<vtkIdType>(this->Probes->ProbeCount()) : 0;
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectReliefProbes::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "LightFieldActor: " << static_cast<void*>(this->Scene.GetPointer()) << "\n";
  os << indent << "ProbesPerSide: " << this->ProbesPerSide << "\n";
  os << indent << "NumberOfCharts: " << this->GetNumberOfCharts() << "\n";
  os << indent << "LastSeconds: " << this->LastSeconds << "\n";
  os << indent << "LastGatheredProbes: " << this->LastGatheredProbes << "\n";
}
