// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor's parts (private header, not installed), each a class with one job: where
// the field comes from, what is built from it, the camera's view, the frame's screen image, the
// progressive worker, the movable object and its shadows. vtkLightFieldMapper reads the screen
// image, the atlas and the shadow maps from here (through vtkLightFieldActorCore).
#ifndef vtkLightFieldActorInternals_h
#define vtkLightFieldActorInternals_h

#include "vtkLightFieldActor.h"

#include "vtkLightFieldCameraView.h"
#include "vtkLightFieldInput.h"
#include "vtkLightFieldMovableObject.h"
#include "vtkLightFieldObjectShadows.h"
#include "vtkLightFieldReflectionWorker.h"
#include "vtkLightFieldSceneCache.h"
#include "vtkLightFieldScreenImage.h"

#include <functional>
#include <string>
#include <vector>

struct vtkLightFieldActor::Internals
{
  explicit Internals(vtkLightFieldActor* owner)
    : View(owner)
    , Object(owner)
    , Shadows(owner)
  {
  }

  // Shows a field (nullptr: none): rebuilds what is drawn and traced from it, forgets what
  // belonged to the old one. False (reported with vtkErrorMacro) when it cannot be shown.
  bool UseField(vtkLightFieldActor& actor, const mesolight::vlf::LightField* field);
  // Gives the mapper the scene polydata without the hidden surfaces (reports unknown names).
  void ApplyHiddenSurfaces(vtkLightFieldActor& actor);
  // Stops the worker: it reads the field, the tracer, the object's instance and the maps.
  std::function<void()> StopReaders()
  {
    return [this]() { this->Worker.Stop(); };
  }

  // Declared in destruction order's reverse: the worker stops before what it reads goes away,
  // the object's gatherer before the field it reads.
  vtkLightFieldInput Input;
  vtkLightFieldSceneCache Scene;
  vtkLightFieldCameraView View;
  vtkLightFieldScreenImage Screen;
  vtkLightFieldMovableObject Object;
  vtkLightFieldObjectShadows Shadows;
  vtkLightFieldReflectionWorker Worker;
  bool WarnedNoMirrors = false;
  std::vector<std::string> HiddenSurfaces; // vtkLightFieldActor::AddHiddenSurface

  // Negative tests' hooks (vtkLightFieldActorTesting): upload the atlas upside down; paste the
  // screen rectangle over every fragment in it without alpha; trace reflections this many
  // bounces short.
  bool FlipAtlas = false;
  bool OverwriteComposite = false;
  int ReflectionBouncesShort = 0;
  bool IgnoreObject = false;
  // Benchmark only (vtkLightFieldActorTesting::SetShadowCodeAlways): the radiance shader keeps
  // the shadow code without a caster, as it did before it was left out of such draws.
  bool ShadowCodeAlways = false;
};

#endif
