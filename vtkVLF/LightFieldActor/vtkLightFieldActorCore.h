// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldActorCore
 * @brief   vtkLightFieldActor's mesolight::vlf core objects, for code built in this tree
 *
 * Private to Mesolight::LightFieldActor (header not installed: the core types' headers are not
 * either). The mesolight tool, the tests and the module's mappers lend the actor a field and read
 * what it computed: the field, the movable object as gathered, the emitters' point lights, the
 * shadow maps; vtkLightFieldMapper prepares each frame and reads its parts here.
 */
#ifndef vtkLightFieldActorCore_h
#define vtkLightFieldActorCore_h

#include "vtkLightFieldActor.h"

#include <glm/mat4x4.hpp>

#include <memory> // For std::shared_ptr

namespace mesolight
{
namespace vlf
{
class LightField;
class ObjectShadows;
class TracedReliefs;
struct LightApproximation;
struct ShadedObject;
}
}
class vtkMatrix4x4;
class vtkRenderer;

class vtkLightFieldActorCore
{
public:
  /**
   * The field to show, borrowed: it must outlive the actor's use of it (e.g. held by a
   * vtkVirtualLightField). nullptr clears it.
   */
  static void SetLightField(vtkLightFieldActor* actor, const mesolight::vlf::LightField* field);
  static const mesolight::vlf::LightField* GetLightField(const vtkLightFieldActor* actor);
  /** The object as last gathered (unit-sphere mesh with per-point radiance), or nullptr. */
  static const mesolight::vlf::ShadedObject* GetShadedObject(const vtkLightFieldActor* actor);
  /** Point lights estimated from the field's emitters (computed once per field), or nullptr. */
  static const mesolight::vlf::LightApproximation* GetEmitterLights(vtkLightFieldActor* actor);
  /** The shadow maps of the last frame (nullptr when no object casts shadows). */
  static const mesolight::vlf::ObjectShadows* GetObjectShadows(const vtkLightFieldActor* actor);
  /**
   * Reliefs drawn on the shown field's surfaces (the walkthrough's --relief): the mirrors show
   * them where their rays land (WalkthroughTracer::SetReliefs; nullptr: the flat surfaces). For
   * the current field (a new field drops them); stops the reflection worker and forgets its
   * image first.
   */
  static void SetTracedReliefs(
    vtkLightFieldActor* actor, std::shared_ptr<const mesolight::vlf::TracedReliefs> reliefs);

  /**
   * A movable object's placement in the field's unit sphere: its world matrix (a vtkProp3D's
   * GetMatrix()) followed by the field's world-to-unit-sphere transform.
   */
  static glm::mat4 UnitSpherePlacement(
    const mesolight::vlf::LightField& field, vtkMatrix4x4* objectMatrix);

  ///@{
  /** For vtkLightFieldMapper: prepares the frame (false when a radiance mode has nothing to
   * draw), then reads its parts; reports the upload's seconds. */
  static bool PrepareFrame(vtkLightFieldActor* actor, vtkRenderer* renderer);
  static vtkLightFieldActor::Internals& GetInternals(vtkLightFieldActor* actor);
  static void SetLastUploadSeconds(vtkLightFieldActor* actor, double seconds);
  ///@}
};

#endif
