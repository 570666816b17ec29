// SPDX-License-Identifier: BSD-3-Clause
// A relief on the movable object of `mesolight vlf view` and `vlf render --mode` (--object-relief
// DEPTH_IMAGE): where the light-field side (vtkLightFieldObjectReliefProbes: the object's charts
// and the field's SH9 probes over them) and the relief side (vtkReliefMapper) meet
// (docs/dev/architecture.md). One relief actor per chart draws the object in its place, at the
// object's matrix, lit per pixel at the relief's perturbed normal; the object itself stays the
// scene actor's movable object (macro geometry: its shadow, its reflections, its gather) but is
// not drawn.
#ifndef mesolight_LightFieldObjectRelief_h
#define mesolight_LightFieldObjectRelief_h

#include "vtkLightFieldObjectReliefProbes.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkSmartPointer.h>

#include <string>
#include <vector>

class vtkLightFieldActor;
class vtkRenderer;

namespace mesolight
{
class CommandLine;

// --object-relief, --object-relief-depth-scale.
void AddObjectReliefOptions(CommandLine& cl);

struct ObjectRelief
{
  vtkNew<vtkLightFieldObjectReliefProbes> Probes;
  vtkSmartPointer<vtkImageData> Texture;         // the baked relief texture of the depth image
  std::vector<vtkSmartPointer<vtkActor>> Actors; // one per chart
  vtkNew<vtkCallbackCommand> Sync;               // the renderer's StartEvent: probes, matrices
  vtkActor* Object = nullptr;                    // the movable object (owned by MovableObject)
  bool Active = false;
  // Per frame that moved the object: seconds of the probes' update, probes gathered.
  double ProbeSeconds = 0.0;
  long long GatheredProbes = 0;
  int Moves = 0;
};

// Checks the relief options before the object is set up: 0, or the exit code (the message is
// printed). `hasTextureCoordinates`: the object's mesh has them.
int CheckObjectRelief(const CommandLine& cl, const char* command, const std::string& objectName,
  bool hasTextureCoordinates);

// Bakes the depth image and puts one relief actor per chart of `object` (the scene actor's
// movable object, already placed) into `renderer` (the reliefs' layer, ReliefLayer); hides the
// object's own drawing. 0, or the exit code (the message is printed).
int SetUpObjectRelief(const CommandLine& cl, const char* command, vtkLightFieldActor* scene,
  vtkRenderer* renderer, vtkActor* object, ObjectRelief& relief);

} // namespace mesolight

#endif
