// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldActorCore.h"

#include "vtkLightFieldActorInternals.h"

#include "ObjectMesh.h"
#include "WalkthroughTracer.h"

#include <utility>

#include "vtkMatrix4x4.h"

//------------------------------------------------------------------------------
void vtkLightFieldActorCore::SetLightField(
  vtkLightFieldActor* actor, const mesolight::vlf::LightField* field)
{
  vtkLightFieldActor::Internals& impl = *actor->Impl;
  impl.Worker.Stop();
  impl.Input.Borrow();
  impl.UseField(*actor, field);
}

//------------------------------------------------------------------------------
const mesolight::vlf::LightField* vtkLightFieldActorCore::GetLightField(
  const vtkLightFieldActor* actor)
{
  return actor->Impl->Scene.GetField();
}

//------------------------------------------------------------------------------
const mesolight::vlf::ShadedObject* vtkLightFieldActorCore::GetShadedObject(
  const vtkLightFieldActor* actor)
{
  return actor->Impl->Object.GetShaded();
}

//------------------------------------------------------------------------------
const mesolight::vlf::LightApproximation* vtkLightFieldActorCore::GetEmitterLights(
  vtkLightFieldActor* actor)
{
  actor->RefreshField();
  return actor->Impl->Scene.GetEmitterLights();
}

//------------------------------------------------------------------------------
const mesolight::vlf::ObjectShadows* vtkLightFieldActorCore::GetObjectShadows(
  const vtkLightFieldActor* actor)
{
  return actor->Impl->Shadows.GetMaps();
}

//------------------------------------------------------------------------------
void vtkLightFieldActorCore::SetTracedReliefs(
  vtkLightFieldActor* actor, std::shared_ptr<const mesolight::vlf::TracedReliefs> reliefs)
{
  vtkLightFieldActor::Internals& impl = *actor->Impl;
  impl.Worker.Stop(); // it reads the tracer
  impl.Worker.Forget();
  if (mesolight::vlf::WalkthroughTracer* tracer = impl.Scene.GetTracer())
  {
    tracer->SetReliefs(std::move(reliefs));
  }
  actor->Modified();
}

//------------------------------------------------------------------------------
bool vtkLightFieldActorCore::PrepareFrame(vtkLightFieldActor* actor, vtkRenderer* renderer)
{
  return actor->PrepareFrame(renderer);
}

//------------------------------------------------------------------------------
vtkLightFieldActor::Internals& vtkLightFieldActorCore::GetInternals(vtkLightFieldActor* actor)
{
  return *actor->Impl;
}

//------------------------------------------------------------------------------
void vtkLightFieldActorCore::SetLastUploadSeconds(vtkLightFieldActor* actor, double seconds)
{
  actor->LastUploadSeconds = seconds;
}

//------------------------------------------------------------------------------
glm::mat4 vtkLightFieldActorCore::UnitSpherePlacement(
  const mesolight::vlf::LightField& field, vtkMatrix4x4* objectMatrix)
{
  glm::mat4 world(1.0f);
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      world[column][row] = static_cast<float>(objectMatrix->GetElement(row, column));
    }
  }
  return mesolight::vlf::WorldToUnitSphere(field) * world;
}
