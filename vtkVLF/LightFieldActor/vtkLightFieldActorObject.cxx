// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor, the movable object (Wither 2005, "Interactive dynamic objects in a virtual
// light field", chapter 3): reading the object actor's polydata, placing it in the field, its
// instance in the tracer's Embree scene, its gathered shading, and the caster of its shadows.
#include "vtkLightFieldActor.h"

#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldActorShadows.h"

#include "vtkActor.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkTriangleFilter.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace vlf = mesolight::vlf;

//------------------------------------------------------------------------------
// The movable object (Wither 2005, "Interactive dynamic objects in a virtual light field").
//------------------------------------------------------------------------------
namespace
{
// The object's triangles in model coordinates, with its point normals when it has them (else
// area-weighted ones), and its reflectance from the property's diffuse colour.
vlf::ObjectMesh ReadObjectMesh(vtkPolyData* input, vtkActor* object)
{
  vtkNew<vtkPolyData> shallow;
  shallow->ShallowCopy(input); // the filter below never touches the user's polydata
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(shallow);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkPolyData* output = triangles->GetOutput();
  vlf::ObjectMesh mesh;
  if (!output->GetPoints())
  {
    return mesh;
  }
  mesh.Points.resize(static_cast<std::size_t>(output->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    mesh.Points[static_cast<std::size_t>(i)] = glm::vec3(p[0], p[1], p[2]);
  }
  vtkCellArray* polys = output->GetPolys();
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n == 3)
    {
      mesh.Triangles.emplace_back(static_cast<unsigned>(ids[0]), static_cast<unsigned>(ids[1]),
        static_cast<unsigned>(ids[2]));
    }
  }
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  bool useNormals = normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == output->GetNumberOfPoints();
  if (useNormals)
  {
    mesh.Normals.resize(mesh.Points.size());
    for (vtkIdType i = 0; i < output->GetNumberOfPoints() && useNormals; ++i)
    {
      double v[3];
      normals->GetTuple(i, v);
      const glm::vec3 nv(v[0], v[1], v[2]);
      const float length = glm::length(nv);
      useNormals = std::isfinite(length) && length > 0.0f;
      mesh.Normals[static_cast<std::size_t>(i)] = useNormals ? nv / length : nv;
    }
  }
  if (!useNormals)
  {
    mesh.ComputeNormals(); // a defined fallback for meshes without (usable) normals
  }
  double kd[3];
  object->GetProperty()->GetDiffuseColor(kd);
  const double k = object->GetProperty()->GetDiffuse();
  for (int c = 0; c < 3; ++c)
  {
    mesh.Kd[c] = static_cast<float>(std::min(1.0, std::max(0.0, kd[c] * k)));
  }
  return mesh;
}

glm::mat4 ToGlm(vtkMatrix4x4* m)
{
  glm::mat4 out(1.0f);
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      out[column][row] = static_cast<float>(m->GetElement(row, column));
    }
  }
  return out;
}
} // namespace

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetGatherDirectionsFromString(const std::string& name)
{
  return name == "all"     ? AllDirections
    : name == "half"       ? HalfDirections
    : name == "importance" ? ImportanceDirections
                           : -1;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::SetMovableObject(vtkActor* object)
{
  Internals& impl = *this->Impl;
  if (impl.Object == object)
  {
    return;
  }
  if (object == this)
  {
    vtkErrorMacro(<< "the light field actor cannot be its own movable object");
    return;
  }
  impl.StopWorker(); // the worker may be tracing the old object
  if (impl.Tracer)
  {
    impl.Tracer->ClearObject();
  }
  impl.Object = object;
  impl.ForgetObjectState();
  this->LastObjectProblem.clear();
  impl.ObjectProblemWarned.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
vtkActor* vtkLightFieldActor::GetMovableObject()
{
  return this->Impl->Object;
}

//------------------------------------------------------------------------------
const mesolight::vlf::ShadedObject* vtkLightFieldActor::GetShadedObject() const
{
  const Internals& impl = *this->Impl;
  return impl.ObjectUsable && impl.Gathered && impl.Gatherer ? &impl.Gatherer->Result() : nullptr;
}

//------------------------------------------------------------------------------
const mesolight::vlf::LightApproximation* vtkLightFieldActor::GetEmitterLights()
{
  Internals& impl = *this->Impl;
  this->RefreshField();
  if (!impl.Field)
  {
    return nullptr;
  }
  if (!impl.Lights)
  {
    impl.Lights.reset(new vlf::LightApproximation(vlf::EstimateEmitterLights(*impl.Field)));
  }
  return impl.Lights.get();
}

//------------------------------------------------------------------------------
unsigned long vtkLightFieldActor::GetObjectVersion() const
{
  return this->Impl->ObjectVersion;
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::UpdateMovableObject()
{
  Internals& impl = *this->Impl;
  const std::chrono::steady_clock::time_point start = std::chrono::steady_clock::now();
  this->RefreshField();
  vtkActor* object = impl.Object;
  // Takes the object out of the tracer (the mesh stays read: a later placement may work).
  auto drop = [&]()
  {
    if (impl.ObjectPlaced || impl.Gathered || impl.Tracer->HasObject())
    {
      impl.StopWorker();
      impl.Tracer->ClearObject();
      impl.ObjectPlaced = false;
      impl.Gathered = false;
      impl.TracedMesh = 0;
      ++impl.ObjectVersion;
      this->ClearObjectShadows();
    }
  };
  auto fail = [&](const std::string& why)
  {
    drop();
    this->LastObjectProblem = why;
    if (impl.ObjectProblemWarned != why)
    {
      vtkErrorMacro(<< why);
      impl.ObjectProblemWarned = why;
    }
    return false;
  };
  if (!impl.Field || !impl.Tracer)
  {
    return false;
  }
  if (!object)
  {
    // None set, or the actor was deleted (held weakly): nothing of it may stay in the tracer.
    drop();
    impl.ObjectUsable = false;
    this->LastObjectProblem.clear();
    return false;
  }
  vtkMapper* mapper = object->GetMapper();
  if (!mapper)
  {
    return fail("the movable object has no mapper: nothing to place in the light field");
  }
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    mapper->GetInputAlgorithm()->Update();
  }
  vtkPolyData* data = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (!data)
  {
    return fail("the movable object's mapper has no vtkPolyData input");
  }
  // 1. The mesh, reread only when the data (or the reflectance) changed.
  const vtkMTimeType dataTime = std::max(data->GetMTime(), object->GetProperty()->GetMTime());
  if (data != impl.ObjectData || dataTime != impl.ObjectDataTime)
  {
    impl.ObjectData = data;
    impl.ObjectDataTime = dataTime;
    impl.ObjectModel = ReadObjectMesh(data, object);
    ++impl.ObjectMeshVersion;
    impl.ObjectUsable = false;
    impl.ObjectProblemWarned.clear();
    const std::string problem = impl.ObjectModel.Validate();
    if (!problem.empty())
    {
      impl.ObjectModel = vlf::ObjectMesh{};
      return fail("the movable object cannot be used: " + problem);
    }
    impl.ObjectUsable = true;
    const std::size_t degenerate = impl.ObjectModel.DegenerateTriangleCount();
    if (degenerate > 0)
    {
      vtkWarningMacro(<< "the movable object has " << degenerate
                      << " triangles of zero area; they are skipped");
    }
  }
  if (!impl.ObjectUsable)
  {
    return false;
  }
  // 2. The placement: the actor's matrix, then the field's normalisation.
  const glm::mat4 placement = vlf::WorldToUnitSphere(*impl.Field) * ToGlm(object->GetMatrix());
  const bool ignore = this->IgnoreObjectForTesting;
  const bool meshChanged = impl.ObjectGatherMesh != impl.ObjectMeshVersion ||
    impl.ObjectGatherSubdivision != this->ObjectSubdivision ||
    impl.ObjectGatherDirections != this->ObjectGatherDirections ||
    impl.ObjectGatherVolume != this->ObjectIrradianceVolume;
  if (impl.ObjectPlaced && placement == impl.ObjectPlacement && !meshChanged &&
    ignore == impl.ObjectIgnored)
  {
    return true; // the figures stay those of the last update that did work
  }
  const vlf::ObjectMesh unit = vlf::TransformMesh(impl.ObjectModel, placement);
  const std::string unitProblem = unit.Validate();
  if (!unitProblem.empty())
  {
    return fail("the movable object's placement cannot be used (" + unitProblem +
      "): is its scale zero or its matrix not finite?");
  }
  // 3. Its shading: one gather per change, shared by the tracer and the object's mapper.
  impl.StopWorker(); // the worker must not trace while the instance and radiance change
  if (!impl.Gatherer)
  {
    impl.Gatherer.reset(new vlf::ObjectGatherer(*impl.Field));
  }
  const std::chrono::steady_clock::time_point gatherStart = std::chrono::steady_clock::now();
  vlf::GatherSettings settings;
  settings.Subdivision = this->ObjectSubdivision;
  settings.Directions = this->ObjectGatherDirections == HalfDirections
    ? vlf::DirectionSampling::Half
    : this->ObjectGatherDirections == ImportanceDirections ? vlf::DirectionSampling::Importance
                                                           : vlf::DirectionSampling::All;
  try
  {
    if (this->ObjectIrradianceVolume > 0)
    {
      if (!impl.Volume || impl.VolumeField != impl.Field ||
        impl.VolumeResolution != this->ObjectIrradianceVolume)
      {
        impl.Volume.reset();
        vlf::IrradianceVolumeSettings volume;
        volume.Resolution = this->ObjectIrradianceVolume;
        impl.Volume.reset(new vlf::IrradianceVolume(*impl.Field, volume));
        impl.VolumeField = impl.Field;
        impl.VolumeResolution = this->ObjectIrradianceVolume;
      }
      settings.Volume = impl.Volume.get();
    }
    // The model-space overload: the subdivision is kept while the object only moves, and the
    // gatherer's cache re-gathers only the points that moved.
    impl.Gatherer->Gather(impl.ObjectModel, placement, settings);
  }
  catch (const std::exception& e)
  {
    impl.Gathered = false;
    return fail(std::string("cannot gather the light field onto the movable object: ") + e.what());
  }
  impl.Gathered = true;
  this->LastGatherSeconds = SecondsSince(gatherStart);
  const vlf::ShadedObject& shaded = impl.Gatherer->Result();
  // 4. The tracer's instance: its mesh is the gathered one (subdivided) in model coordinates,
  // rebuilt only when the mesh or the subdivision changed; a move changes its transform only.
  try
  {
    if (ignore)
    {
      impl.Tracer->ClearObject();
      impl.TracedMesh = 0;
    }
    else
    {
      if (impl.TracedMesh != impl.ObjectMeshVersion ||
        impl.TracedSubdivision != this->ObjectSubdivision ||
        impl.Tracer->Object().Points.size() != shaded.Mesh.Points.size())
      {
        vlf::ObjectMesh model = this->ObjectSubdivision == 0 &&
            shaded.Mesh.Points.size() == impl.ObjectModel.Points.size()
          ? impl.ObjectModel
          : vlf::TransformMesh(shaded.Mesh, glm::inverse(placement));
        impl.Tracer->SetObject(model);
        impl.TracedMesh = impl.ObjectMeshVersion;
        impl.TracedSubdivision = this->ObjectSubdivision;
      }
      impl.Tracer->SetObjectPlacement(placement);
      impl.Tracer->SetObjectRadiance(shaded.Radiance);
    }
  }
  catch (const std::exception& e)
  {
    return fail(std::string("cannot trace the movable object: ") + e.what());
  }
  impl.ObjectPlacement = placement;
  impl.ObjectPlaced = true;
  this->UpdateObjectShadows(unit); // the maps follow at this frame's PrepareShadows
  impl.ObjectGatherMesh = impl.ObjectMeshVersion;
  impl.ObjectGatherSubdivision = this->ObjectSubdivision;
  impl.ObjectGatherDirections = this->ObjectGatherDirections;
  impl.ObjectGatherVolume = this->ObjectIrradianceVolume;
  impl.ObjectIgnored = ignore;
  ++impl.ObjectVersion;

  // 5. Checks a user wants to hear about (the object is still shown): outside the field's unit
  // sphere (nothing gathered there is meaningful), or through a wall (rays from its centre to
  // its points cross a static surface).
  std::string problem;
  glm::vec3 lower, upper;
  unit.Bounds(lower, upper);
  const glm::vec3 centre = 0.5f * (lower + upper);
  for (const glm::vec3& p : unit.Points)
  {
    if (glm::length(p) > 1.0f)
    {
      problem = "the movable object reaches outside the light field's bounds: its shading there "
                "is not meaningful";
      break;
    }
  }
  if (problem.empty())
  {
    const std::size_t step = std::max<std::size_t>(1, unit.Points.size() / 256);
    for (std::size_t i = 0; i < unit.Points.size() && problem.empty(); i += step)
    {
      mesolight::SceneRay ray;
      ray.Origin = centre;
      ray.Direction = unit.Points[i] - centre;
      ray.TFar = 0.999f;
      if (glm::length(ray.Direction) > 0.0f &&
        impl.Tracer->Embree().Intersect(ray).Triangle != mesolight::SceneHit::None)
      {
        problem = "the movable object intersects a surface of the light field (a wall?)";
      }
    }
  }
  this->LastObjectProblem = problem;
  if (!problem.empty() && impl.ObjectProblemWarned != problem)
  {
    vtkWarningMacro(<< problem);
  }
  impl.ObjectProblemWarned = problem;
  this->LastObjectSeconds = SecondsSince(start);
  return true;
}
