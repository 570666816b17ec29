// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldObjectMapper
 * @brief   draws a vtkLightFieldActor's movable object shaded by the light field
 *
 * Set on the vtkActor given to vtkLightFieldActor::SetMovableObject (the scene actor), so that
 * the object looks lit by the propagated field (Wither 2005, "Interactive dynamic objects in a
 * virtual light field", §3.5-3.6), in three levels:
 *
 * - Flat: the actor's diffuse colour, unlit.
 * - Lights: point lights estimated from the field's emitters plus an ambient term from its mean
 *   radiance (mesolight::vlf::EstimateEmitterLights, ShadeWithLights), per vertex.
 * - Gather: the irradiance gathered from the field at every vertex (mesolight::vlf::
 *   ObjectGatherer, the scene actor's one gather per change, shared with its reflections), with
 *   the object subdivided SetSubdivision(0-3) levels.
 *
 * Colours go through the scene actor's exposure and tone map (mesolight::vlf::ToneMap, the
 * twin of its shader), so object and scene share one display transform, and are drawn per
 * vertex (Gouraud) without VTK lighting. The user's input polydata is never modified: the
 * shaded (possibly subdivided) mesh is a private copy in world coordinates drawn by an internal
 * mapper. Without a scene actor, a field or a usable object the actor is drawn as a plain
 * vtkOpenGLPolyDataMapper would draw it.
 *
 * The scene actor is held weakly (vtkWeakPointer): the scene actor holds the object weakly too,
 * so neither keeps the other alive. A scene actor without an object takes the first actor this
 * mapper draws as its object; an actor that is not the scene actor's object is drawn plainly
 * (with a warning). The shaded copy is drawn by an internal mapper and actor, so hardware
 * picking does not report the user's actor.
 */
#ifndef vtkLightFieldObjectMapper_h
#define vtkLightFieldObjectMapper_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkLightFieldActor.h"             // For GatherDirectionSets
#include "vtkNew.h"                         // For vtkNew
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkWeakPointer.h" // For vtkWeakPointer

#include <string> // For std::string

class vtkActor;
class vtkPolyData;

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldObjectMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkLightFieldObjectMapper* New();
  vtkTypeMacro(vtkLightFieldObjectMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The scene actor whose field shades the object (held weakly). */
  void SetLightFieldActor(vtkLightFieldActor* scene);
  vtkLightFieldActor* GetLightFieldActor();

  enum Shadings
  {
    Flat = 0,
    Lights = 1,
    Gather = 2
  };
  ///@{
  /** Shading level (default Gather). */
  vtkSetClampMacro(Shading, int, Flat, Gather);
  vtkGetMacro(Shading, int);
  void SetShadingToFlat() { this->SetShading(Flat); }
  void SetShadingToLights() { this->SetShading(Lights); }
  void SetShadingToGather() { this->SetShading(Gather); }
  /** "flat", "lights", "gather". */
  static const char* GetShadingAsString(int shading);
  /** The shading of a name above, or -1. */
  static int GetShadingFromString(const std::string& name);
  ///@}

  ///@{
  /** Midpoint subdivision levels (0-3) of the gathered object (Gather shading; default 0). */
  vtkSetClampMacro(Subdivision, int, 0, 3);
  vtkGetMacro(Subdivision, int);
  /** Gather: the directions read (vtkLightFieldActor::GatherDirectionSets; default all). */
  vtkSetClampMacro(GatherDirections, int, vtkLightFieldActor::AllDirections,
    vtkLightFieldActor::ImportanceDirections);
  vtkGetMacro(GatherDirections, int);
  ///@}

  /** The mesh last drawn: world coordinates, per-point display colours ("ObjectColour"). */
  vtkPolyData* GetShadedMesh();
  /** Seconds spent building the shaded mesh in the last frame (0 when it was reused). */
  double GetLastShadingSeconds() const { return this->LastShadingSeconds; }

  void RenderPiece(vtkRenderer* ren, vtkActor* act) override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkLightFieldObjectMapper();
  ~vtkLightFieldObjectMapper() override;

private:
  vtkLightFieldObjectMapper(const vtkLightFieldObjectMapper&) = delete;
  void operator=(const vtkLightFieldObjectMapper&) = delete;

  // Rebuilds the shaded mesh when the object, the shading or the display transform changed;
  // false when the object cannot be shaded from the field (then drawn plainly).
  bool UpdateShadedMesh(vtkActor* act);

  vtkWeakPointer<vtkLightFieldActor> Scene;
  int Shading = Gather;
  int Subdivision = 0;
  int GatherDirections = vtkLightFieldActor::AllDirections;
  double LastShadingSeconds = 0.0;
  std::string ShadedKey;
  bool WarnedForeign = false;
  bool WarnedNoEmitters = false;
  vtkNew<vtkOpenGLPolyDataMapper> Delegate;
  vtkNew<vtkActor> DrawActor;
  vtkNew<vtkPolyData> Shaded;
};

#endif
