// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldMovableObject.h"

#include "vtkLightFieldActor.h" // For GatherDirectionSets
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldObjectShadows.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkTriangleSceneConverter.h"

#include "IrradianceVolume.h"
#include "LightField.h"
#include "ObjectGatherer.h"
#include "WalkthroughTracer.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <exception>

namespace vlf = mesolight::vlf;

namespace
{
using Clock = std::chrono::steady_clock;

double SecondsSince(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

// The object's triangles in model coordinates, with its point normals when it has them (else
// area-weighted ones), and its reflectance from the property's diffuse colour.
vlf::ObjectMesh ReadObjectMesh(vtkPolyData* input, vtkActor* object)
{
  vlf::ObjectMesh mesh;
  vtkTriangleSceneConverter::ToTriangleMesh(input, mesh);
  mesh.TextureCoordinates.clear(); // the object is shaded per point, untextured
  bool useNormals = !mesh.Normals.empty();
  for (glm::vec3& normal : mesh.Normals)
  {
    const float length = glm::length(normal);
    useNormals = useNormals && std::isfinite(length) && length > 0.0f;
    normal = useNormals ? normal / length : normal;
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
    mesh.Diffuse[c] = static_cast<float>(std::min(1.0, std::max(0.0, kd[c] * k)));
  }
  return mesh;
}

} // namespace

//------------------------------------------------------------------------------
vtkLightFieldMovableObject::vtkLightFieldMovableObject(vtkObject* owner)
  : Owner(owner)
{
}

//------------------------------------------------------------------------------
vtkLightFieldMovableObject::~vtkLightFieldMovableObject() = default;

//------------------------------------------------------------------------------
void vtkLightFieldMovableObject::SetActor(vtkActor* object)
{
  this->Object = object;
  this->Forget();
  this->ProblemWarned.clear();
}

//------------------------------------------------------------------------------
void vtkLightFieldMovableObject::Forget()
{
  this->Data = nullptr;
  this->DataTime = 0;
  this->Usable = false;
  this->Placed = false;
  this->GatheredSubdivision = -1;
  this->GatheredDirections = -1;
  this->GatheredVolume = -1;
  this->TracedMesh = 0;
  this->TracedSubdivision = -1;
  this->Gatherer.reset();
  this->Gathered = false;
  ++this->Version;
}

//------------------------------------------------------------------------------
void vtkLightFieldMovableObject::ForgetField()
{
  this->Forget();
  this->Volume.reset();
  this->VolumeField = nullptr;
}

//------------------------------------------------------------------------------
const mesolight::vlf::ShadedObject* vtkLightFieldMovableObject::GetShaded() const
{
  return this->Usable && this->Gathered && this->Gatherer ? &this->Gatherer->Result() : nullptr;
}

//------------------------------------------------------------------------------
bool vtkLightFieldMovableObject::ChangedSinceLastFrame()
{
  const bool changed = this->Version != this->VersionAtLastFrame;
  this->VersionAtLastFrame = this->Version;
  return changed;
}

//------------------------------------------------------------------------------
void vtkLightFieldMovableObject::Drop(vlf::WalkthroughTracer& tracer,
  vtkLightFieldObjectShadows& shadows, const std::function<void()>& stopReaders)
{
  if (this->Placed || this->Gathered || tracer.HasObject())
  {
    stopReaders();
    tracer.ClearObject();
    this->Placed = false;
    this->Gathered = false;
    this->TracedMesh = 0;
    ++this->Version;
    shadows.ClearCaster();
  }
}

//------------------------------------------------------------------------------
bool vtkLightFieldMovableObject::Fail(const std::string& why, vlf::WalkthroughTracer& tracer,
  vtkLightFieldObjectShadows& shadows, const std::function<void()>& stopReaders)
{
  this->Drop(tracer, shadows, stopReaders);
  if (this->ProblemWarned != why)
  {
    vtkErrorWithObjectMacro(this->Owner, << why);
    this->ProblemWarned = why;
  }
  return false;
}

//------------------------------------------------------------------------------
bool vtkLightFieldMovableObject::Update(const vlf::LightField* field,
  vlf::WalkthroughTracer* tracer, const Settings& settings, vtkLightFieldObjectShadows& shadows,
  const std::function<void()>& stopReaders, Clock::time_point start)
{
  if (!field || !tracer)
  {
    return false;
  }
  auto fail = [&](const std::string& why)
  { return this->Fail(why, *tracer, shadows, stopReaders); };
  vtkActor* object = this->Object;
  if (!object)
  {
    // None set, or the actor was deleted (held weakly): nothing of it may stay in the tracer.
    this->Drop(*tracer, shadows, stopReaders);
    this->Usable = false;
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
  // 1. The mesh.
  std::string problem;
  if (!this->ReadMesh(data, problem))
  {
    return fail(problem);
  }
  if (!this->Usable)
  {
    return false;
  }
  // 2. The placement: the actor's matrix, then the field's normalisation.
  const glm::mat4 placement =
    vtkLightFieldActorCore::UnitSpherePlacement(*field, object->GetMatrix());
  const bool meshChanged = this->GatheredMesh != this->MeshVersion ||
    this->GatheredSubdivision != settings.Subdivision ||
    this->GatheredDirections != settings.Directions ||
    this->GatheredVolume != settings.IrradianceVolume;
  if (this->Placed && placement == this->Placement && !meshChanged &&
    settings.Ignore == this->Ignored)
  {
    return true; // the figures stay those of the last update that did work
  }
  const vlf::ObjectMesh unit = vlf::TransformMesh(this->Model, placement);
  const std::string unitProblem = unit.Validate();
  if (!unitProblem.empty())
  {
    return fail("the movable object's placement cannot be used (" + unitProblem +
      "): is its scale zero or its matrix not finite?");
  }
  // 3. Its shading: one gather per change, shared by the tracer and the object's mapper.
  stopReaders(); // the worker must not trace while the instance and radiance change
  try
  {
    this->Gather(*field, placement, settings);
  }
  catch (const std::exception& e)
  {
    this->Gathered = false;
    return fail(std::string("cannot gather the light field onto the movable object: ") + e.what());
  }
  // 4. The tracer's instance.
  try
  {
    this->Trace(*tracer, placement, settings);
  }
  catch (const std::exception& e)
  {
    return fail(std::string("cannot trace the movable object: ") + e.what());
  }
  this->Placement = placement;
  this->Placed = true;
  shadows.SetCaster(unit); // the maps follow at this frame's vtkLightFieldObjectShadows::Prepare
  this->GatheredMesh = this->MeshVersion;
  this->GatheredSubdivision = settings.Subdivision;
  this->GatheredDirections = settings.Directions;
  this->GatheredVolume = settings.IrradianceVolume;
  this->Ignored = settings.Ignore;
  ++this->Version;

  // 5. Checks a user wants to hear about (the object is still shown).
  const std::string warning = Check(unit, *tracer);
  if (!warning.empty() && this->ProblemWarned != warning)
  {
    vtkWarningWithObjectMacro(this->Owner, << warning);
  }
  this->ProblemWarned = warning;
  this->LastSeconds = SecondsSince(start);
  return true;
}

//------------------------------------------------------------------------------
bool vtkLightFieldMovableObject::ReadMesh(vtkPolyData* data, std::string& problem)
{
  vtkActor* object = this->Object;
  const vtkMTimeType dataTime = std::max(data->GetMTime(), object->GetProperty()->GetMTime());
  if (data == this->Data && dataTime == this->DataTime)
  {
    return true;
  }
  this->Data = data;
  this->DataTime = dataTime;
  this->Model = ReadObjectMesh(data, object);
  ++this->MeshVersion;
  this->Usable = false;
  this->ProblemWarned.clear();
  const std::string invalid = this->Model.Validate();
  if (!invalid.empty())
  {
    this->Model = vlf::ObjectMesh{};
    problem = "the movable object cannot be used: " + invalid;
    return false;
  }
  this->Usable = true;
  const std::size_t degenerate = this->Model.DegenerateTriangleCount();
  if (degenerate > 0)
  {
    vtkWarningWithObjectMacro(this->Owner,
      << "the movable object has " << degenerate << " triangles of zero area; they are skipped");
  }
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldMovableObject::Gather(
  const vlf::LightField& field, const glm::mat4& placement, const Settings& settings)
{
  if (!this->Gatherer)
  {
    this->Gatherer.reset(new vlf::ObjectGatherer(field));
  }
  const Clock::time_point start = Clock::now();
  vlf::GatherSettings gather;
  gather.Subdivision = settings.Subdivision;
  gather.Directions = settings.Directions == vtkLightFieldActor::HalfDirections
    ? vlf::DirectionSampling::Half
    : settings.Directions == vtkLightFieldActor::ImportanceDirections
    ? vlf::DirectionSampling::Importance
    : vlf::DirectionSampling::All;
  if (settings.IrradianceVolume > 0)
  {
    if (!this->Volume || this->VolumeField != &field ||
      this->VolumeResolution != settings.IrradianceVolume)
    {
      this->Volume.reset();
      vlf::IrradianceVolumeSettings volume;
      volume.Resolution = settings.IrradianceVolume;
      this->Volume.reset(new vlf::IrradianceVolume(field, volume));
      this->VolumeField = &field;
      this->VolumeResolution = settings.IrradianceVolume;
    }
    gather.Volume = this->Volume.get();
  }
  // The model-space overload: the subdivision is kept while the object only moves, and the
  // gatherer's cache re-gathers only the points that moved.
  this->Gatherer->Gather(this->Model, placement, gather);
  this->Gathered = true;
  this->LastGatherSeconds = SecondsSince(start);
}

//------------------------------------------------------------------------------
void vtkLightFieldMovableObject::Trace(
  vlf::WalkthroughTracer& tracer, const glm::mat4& placement, const Settings& settings)
{
  if (settings.Ignore)
  {
    tracer.ClearObject();
    this->TracedMesh = 0;
    return;
  }
  // Its mesh is the gathered one (subdivided) in model coordinates, rebuilt only when the mesh
  // or the subdivision changed; a move changes its transform only.
  const vlf::ShadedObject& shaded = this->Gatherer->Result();
  if (this->TracedMesh != this->MeshVersion || this->TracedSubdivision != settings.Subdivision ||
    tracer.Object().Positions.size() != shaded.Mesh.Positions.size())
  {
    vlf::ObjectMesh model =
      settings.Subdivision == 0 && shaded.Mesh.Positions.size() == this->Model.Positions.size()
      ? this->Model
      : vlf::TransformMesh(shaded.Mesh, glm::inverse(placement));
    tracer.SetObject(model);
    this->TracedMesh = this->MeshVersion;
    this->TracedSubdivision = settings.Subdivision;
  }
  tracer.SetObjectPlacement(placement);
  tracer.SetObjectRadiance(shaded.Radiance);
}

//------------------------------------------------------------------------------
std::string vtkLightFieldMovableObject::Check(
  const vlf::ObjectMesh& unit, const vlf::WalkthroughTracer& tracer)
{
  // Outside the field's unit sphere nothing gathered is meaningful.
  for (const glm::vec3& p : unit.Positions)
  {
    if (glm::length(p) > 1.0f)
    {
      return "the movable object reaches outside the light field's bounds: its shading there "
             "is not meaningful";
    }
  }
  // Through a wall: rays from its centre to its points cross a static surface.
  glm::vec3 lower, upper;
  unit.Bounds(lower, upper);
  const glm::vec3 centre = 0.5f * (lower + upper);
  const std::size_t step = std::max<std::size_t>(1, unit.Positions.size() / 256);
  for (std::size_t i = 0; i < unit.Positions.size(); i += step)
  {
    mesolight::SceneRay ray;
    ray.Origin = centre;
    ray.Direction = unit.Positions[i] - centre;
    ray.TFar = 0.999f;
    if (glm::length(ray.Direction) > 0.0f &&
      tracer.Embree().Intersect(ray).Triangle != mesolight::SceneHit::None)
    {
      return "the movable object intersects a surface of the light field (a wall?)";
    }
  }
  return std::string();
}
