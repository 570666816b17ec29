// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldActorTesting.h"

#include "vtkLightFieldActorInternals.h"

#include <algorithm>

namespace
{
template <typename T>
void Change(vtkLightFieldActor* actor, T& hook, T value)
{
  if (hook != value)
  {
    hook = value;
    actor->Modified();
  }
}
} // namespace

//------------------------------------------------------------------------------
void vtkLightFieldActorTesting::SetFlipAtlas(vtkLightFieldActor* actor, bool flip)
{
  Change(actor, actor->Impl->FlipAtlas, flip);
}

//------------------------------------------------------------------------------
bool vtkLightFieldActorTesting::GetFlipAtlas(const vtkLightFieldActor* actor)
{
  return actor->Impl->FlipAtlas;
}

//------------------------------------------------------------------------------
void vtkLightFieldActorTesting::SetOverwriteComposite(vtkLightFieldActor* actor, bool overwrite)
{
  Change(actor, actor->Impl->OverwriteComposite, overwrite);
}

//------------------------------------------------------------------------------
bool vtkLightFieldActorTesting::GetOverwriteComposite(const vtkLightFieldActor* actor)
{
  return actor->Impl->OverwriteComposite;
}

//------------------------------------------------------------------------------
void vtkLightFieldActorTesting::SetReflectionBouncesShort(vtkLightFieldActor* actor, int bounces)
{
  Change(actor, actor->Impl->ReflectionBouncesShort, std::min(std::max(bounces, 0), 8));
}

//------------------------------------------------------------------------------
int vtkLightFieldActorTesting::GetReflectionBouncesShort(const vtkLightFieldActor* actor)
{
  return actor->Impl->ReflectionBouncesShort;
}

//------------------------------------------------------------------------------
void vtkLightFieldActorTesting::SetIgnoreObject(vtkLightFieldActor* actor, bool ignore)
{
  Change(actor, actor->Impl->IgnoreObject, ignore);
}

//------------------------------------------------------------------------------
bool vtkLightFieldActorTesting::GetIgnoreObject(const vtkLightFieldActor* actor)
{
  return actor->Impl->IgnoreObject;
}

//------------------------------------------------------------------------------
void vtkLightFieldActorTesting::SetShadowBackProjectionRemoval(
  vtkLightFieldActor* actor, bool remove)
{
  actor->Impl->Shadows.SetBackProjectionRemoval(remove);
}

//------------------------------------------------------------------------------
bool vtkLightFieldActorTesting::GetShadowBackProjectionRemoval(const vtkLightFieldActor* actor)
{
  return actor->Impl->Shadows.GetSettings().RemoveBackProjection;
}

//------------------------------------------------------------------------------
void vtkLightFieldActorTesting::SetShadowCaster(
  vtkLightFieldActor* actor, const mesolight::vlf::ObjectMesh* unitMesh)
{
  if (unitMesh)
  {
    actor->Impl->Shadows.SetCaster(*unitMesh);
  }
  else
  {
    actor->Impl->Shadows.ClearCaster();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldActorTesting::SetShadowCodeAlways(vtkLightFieldActor* actor, bool always)
{
  Change(actor, actor->Impl->ShadowCodeAlways, always);
}

//------------------------------------------------------------------------------
bool vtkLightFieldActorTesting::GetShadowCodeAlways(const vtkLightFieldActor* actor)
{
  return actor->Impl->ShadowCodeAlways;
}
