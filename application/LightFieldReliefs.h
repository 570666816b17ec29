// SPDX-License-Identifier: BSD-3-Clause
// `--relief SURFACE=DEPTH_IMAGE` in the walkthrough (`mesolight vlf view`, `vlf render --mode`):
// each named surface of the field's scene drawn by a vtkLightFieldReliefActor (its relief texture
// baked from the depth image as `mesolight render` bakes it), lit by the field (the indirect
// light as SH9 probes, the emitters as VTK lights), the flat surface hidden from the light field
// actor. The reliefs live in a renderer of their own on the window's second layer,
// sharing the walkthrough's camera and depth buffer: the emitter lights light them only (the
// walkthrough's geometry mode is lit by its own renderer's lights).
#ifndef mesolight_LightFieldReliefs_h
#define mesolight_LightFieldReliefs_h

#include "vtkLightFieldActor.h" // for vtkWeakPointer<vtkLightFieldActor>

#include <vtkCallbackCommand.h> // for vtkNew<vtkCallbackCommand>
#include <vtkNew.h>
#include <vtkSmartPointer.h>
#include <vtkWeakPointer.h>

#include <string>
#include <vector>

class vtkActor;
class vtkLightFieldReliefSurface;
class vtkRenderer;
class vtkRenderWindow;

namespace mesolight
{
class CommandLine;

/** The --relief options (the same text as `vlf render`'s CPU reference). */
void AddReliefOptions(CommandLine& cl);
/** The depth images the --relief items name (inputs an output file must not replace). */
std::vector<std::string> ReliefInputs(const CommandLine& cl);

struct WalkthroughReliefs
{
  WalkthroughReliefs() = default;
  ~WalkthroughReliefs(); // stops following the actor
  WalkthroughReliefs(const WalkthroughReliefs&) = delete;
  WalkthroughReliefs& operator=(const WalkthroughReliefs&) = delete;
  vtkNew<vtkRenderer> Renderer; // layer 1: the reliefs and the emitter lights
  std::vector<vtkSmartPointer<vtkLightFieldReliefSurface>> Surfaces;
  std::vector<vtkSmartPointer<vtkActor>> Actors;
  // The walkthrough's exposure and tone map, copied to the reliefs whenever the actor changes
  // (the viewer's keys, the EXR capture's exposure bracketing).
  vtkNew<vtkCallbackCommand> FollowDisplay;
  vtkWeakPointer<vtkLightFieldActor> Followed;
  unsigned long FollowTag = 0;
};

/**
 * The reliefs' renderer, set up on the first call: layer 1 of `window` above `walkthrough`,
 * sharing its camera and depth buffer, lit by the field's emitters only (no headlight), every
 * relief in it following the actor's display. Static surfaces (--relief) and a relief-mapped
 * movable object (--object-relief) are drawn there.
 */
vtkRenderer* ReliefLayer(vtkLightFieldActor* actor, vtkRenderer* walkthrough,
  vtkRenderWindow* window, WalkthroughReliefs& reliefs);

/**
 * Sets up the --relief items for the walkthrough's actor (its field loaded), renderer and
 * window. 0, or the exit code after printing `command: message` (2 for bad input).
 */
int SetUpWalkthroughReliefs(const CommandLine& cl, const char* command, vtkLightFieldActor* actor,
  vtkRenderer* walkthrough, vtkRenderWindow* window, WalkthroughReliefs& reliefs);

} // namespace mesolight

#endif
