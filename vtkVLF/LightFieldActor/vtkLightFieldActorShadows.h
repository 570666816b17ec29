// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor's shadows of the movable object (private header, shared with
// vtkLightFieldMapper): the caster in the field's unit sphere, the settings, the maps
// (mesolight::vlf::ObjectShadows) and their packing for the GPU, rebuilt when something changed.
#ifndef vtkLightFieldActorShadows_h
#define vtkLightFieldActorShadows_h

#include "vtkLightFieldActor.h"

#include "ObjectMesh.h"
#include "ObjectShadows.h"

#include <memory>
#include <string>

struct vtkLightFieldActor::ShadowState
{
  mesolight::vlf::ShadowSettings Settings;
  std::unique_ptr<mesolight::vlf::ObjectMesh> Caster; // unit sphere; null: no object
  mesolight::vlf::ObjectShadows Shadows;
  mesolight::vlf::ShadowGpuData Gpu;
  bool Dirty = true;
  const mesolight::vlf::LightField* BuiltFor = nullptr;
  unsigned long Version = 0; // bumped whenever Gpu changes (the mapper re-uploads)
  std::string Problem;       // why the last build gave no shadows ("" when it did)
  bool Active() const { return this->Gpu.Mode != 0 && this->Gpu.EmitterCount > 0; }
};

#endif
