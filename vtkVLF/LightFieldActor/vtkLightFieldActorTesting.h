// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldActorTesting
 * @brief   vtkLightFieldActor's hooks for negative tests (header not installed)
 *
 * Each hook breaks one thing on purpose, so a test can show that its check notices: the atlas
 * uploaded upside down, the screen rectangle pasted over every fragment in it without alpha,
 * reflections traced bounces short, the movable object kept out of the tracer, receivers
 * behind the light or facing away shadowed. SetShadowCaster gives the shadows a caster without a
 * movable object. Setters mark the actor modified when the value changes.
 */
#ifndef vtkLightFieldActorTesting_h
#define vtkLightFieldActorTesting_h

#include "vtkLightFieldActor.h"

namespace mesolight
{
namespace vlf
{
struct ObjectMesh;
}
}

class vtkLightFieldActorTesting
{
public:
  static void SetFlipAtlas(vtkLightFieldActor* actor, bool flip);
  static bool GetFlipAtlas(const vtkLightFieldActor* actor);
  static void SetOverwriteComposite(vtkLightFieldActor* actor, bool overwrite);
  static bool GetOverwriteComposite(const vtkLightFieldActor* actor);
  /** Clamped to [0, 8]. */
  static void SetReflectionBouncesShort(vtkLightFieldActor* actor, int bounces);
  static int GetReflectionBouncesShort(const vtkLightFieldActor* actor);
  static void SetIgnoreObject(vtkLightFieldActor* actor, bool ignore);
  static bool GetIgnoreObject(const vtkLightFieldActor* actor);
  /** False shadows receivers behind the light or facing away from it (default true). */
  static void SetShadowBackProjectionRemoval(vtkLightFieldActor* actor, bool remove);
  static bool GetShadowBackProjectionRemoval(const vtkLightFieldActor* actor);
  /**
   * Until the movable object is set through the actor: the object that casts shadows, a
   * triangle mesh in the field's unit sphere (mesolight::vlf::TransformMesh with
   * WorldToUnitSphere), copied; nullptr removes it.
   */
  static void SetShadowCaster(
    vtkLightFieldActor* actor, const mesolight::vlf::ObjectMesh* unitMesh);
  /**
   * Not a negative test but the benchmark's comparison: compile the shadow code into the
   * radiance shader even without a shadow caster (what every draw did before).
   */
  static void SetShadowCodeAlways(vtkLightFieldActor* actor, bool always);
  static bool GetShadowCodeAlways(const vtkLightFieldActor* actor);
};

#endif
