// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldActorCore.h"

#include "vtkLightFieldActorInternals.h"

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
