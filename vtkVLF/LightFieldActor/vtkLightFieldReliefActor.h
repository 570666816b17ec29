// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldReliefActor
 * @brief   a named surface of a light field walkthrough drawn as a relief lit by the field: one
 *          actor to add beside the vtkLightFieldActor
 *
 * What `mesolight vlf view FIELD --relief SURFACE=DEPTH_IMAGE` draws, for VTK pipelines in C++
 * and Python: give it the walkthrough's actor (SetLightFieldActor), the surface's name in the
 * field's scene (SetSurfaceName: an OBJ `g`/`o` name or a Cornell box name) and a relief texture
 * (SetReliefTextureData: vtkReliefTextureFilter's output, depth in A), add it to the renderer
 * that shows the walkthrough, and render. Before its first frame it
 *
 * - hides the flat surface from the walkthrough (vtkLightFieldActor::AddHiddenSurface: the
 *   relief lies behind the surface's plane, which would hide it);
 * - gathers the field's indirect light over the surface as SH9 probes and takes its emitters as
 *   the relief's own lights (vtkLightFieldReliefSurface, GetReliefSurface()), with the relief's
 *   occlusion of its indirect light, its inter-reflection and the scene's shadows of the
 *   emitters (Occlusion, default on); the relief is walled at its texture's edge, as the CPU
 *   reference's (`mesolight vlf render --relief`) is recessed into its wall;
 * - colours itself with the surface's Kd and emits the surface's Ke (a relief on a lamp).
 *
 * Every frame it takes the walkthrough's display (exposure, tone map, sRGB encoding: CopyDisplay)
 * so the same radiance shows as the same pixel value beside the field, and the movable object's
 * shadow falls on it as on the walls (vtkLightFieldReliefShadowHook). Probes and lights are
 * computed again only when the field, the surface, the texture, the depth scale, the probe count or
 * Occlusion change. The relief's own settings (method, steps, self-shadowing) are
 * GetReliefProperty()'s; the actor's vtkProperty holds its colour. The relief writes no depth
 * behind its surface's plane (vtkReliefProperty::SetDepthLimitPlane): it is recessed into its
 * surface, as the CPU reference's is, so a wall a little behind the surface (a window or a panel
 * hung in front of a wall) does not show through its deeper parts.
 *
 * An unknown surface name (the message lists the scene's surfaces), a non-planar surface, no
 * field or no texture are errors of this actor (its observers hear them, once per cause: the
 * surface filter's are passed on); the actor then draws nothing, has no bounds, and the
 * walkthrough shows the flat surface again. The surface is hidden while the actor is visible
 * (SetVisibility) and shown again when the actor is renamed, hidden or deleted.
 */
#ifndef vtkLightFieldReliefActor_h
#define vtkLightFieldReliefActor_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkOpenGLActor.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkWeakPointer.h"  // For vtkWeakPointer

#include <string> // For std::string

class vtkCommand;
class vtkImageData;
class vtkLightFieldActor;
class vtkLightFieldReliefShadowHook;
class vtkLightFieldReliefSurface;
class vtkReliefMapper;
class vtkReliefProperty;

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldReliefActor : public vtkOpenGLActor
{
public:
  static vtkLightFieldReliefActor* New();
  vtkTypeMacro(vtkLightFieldReliefActor, vtkOpenGLActor);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The walkthrough whose field lights the relief and whose surface it replaces (not held). */
  void SetLightFieldActor(vtkLightFieldActor* actor);
  vtkLightFieldActor* GetLightFieldActor();
  ///@}

  ///@{
  /** The surface's name in the field's scene. */
  void SetSurfaceName(const char* name);
  const char* GetSurfaceName() const { return this->SurfaceName.c_str(); }
  ///@}

  ///@{
  /** The relief texture (vtkReliefTextureFilter's output: RGBA, depth in A, 0 = top). */
  void SetReliefTextureData(vtkImageData* texture);
  vtkImageData* GetReliefTextureData();
  ///@}

  ///@{
  /**
   * World depth of depth 1 over the world width of the texture, [0, 10]. By default the depth
   * scale the texture was baked with (vtkReliefTextureFilter's DepthScale, its field data
   * "MesolightDepthScale"; 0.05 for a texture without one), so the relief's normals and its
   * depth agree; SetDepthScale overrides it (UseTextureDepthScale off).
   */
  void SetDepthScale(double scale);
  double GetDepthScale() const { return this->DepthScale; }
  void SetUseTextureDepthScale(bool on);
  bool GetUseTextureDepthScale() const { return this->UseTextureDepthScale; }
  vtkBooleanMacro(UseTextureDepthScale, bool);
  ///@}

  ///@{
  /** SH9 probes per side; 0 (the default) chooses from the field and the surface
   * (vtkLightFieldReliefSurface::SetProbesPerSide). */
  void SetProbesPerSide(int count);
  int GetProbesPerSide() const { return this->ProbesPerSide; }
  ///@}

  ///@{
  /** The relief's occlusion of its indirect light, its inter-reflection and the scene's shadows
   * of the emitter lights (default on; off for comparison). */
  void SetOcclusion(bool on);
  bool GetOcclusion() const { return this->Occlusion; }
  vtkBooleanMacro(Occlusion, bool);
  ///@}

  /** The relief's settings (method, steps, self-shadowing...). */
  vtkReliefProperty* GetReliefProperty();

  /** The filter that gathers the probes and emitter lights (its outputs after a render). */
  vtkLightFieldReliefSurface* GetReliefSurface();

  /** The walkthrough's exposure, tone map and sRGB encoding on a relief drawn beside it. */
  static void CopyDisplay(vtkLightFieldActor* actor, vtkReliefProperty* property);

  ///@{
  /** Bring the probes, lights and display up to date before drawing (or measuring: no bounds,
   * nullptr, when there is nothing to draw). */
  void Render(vtkRenderer* renderer, vtkMapper* mapper) override;
  double* GetBounds() override;
  using vtkOpenGLActor::GetBounds;
  ///@}

  /** Hidden, the walkthrough shows the flat surface again. */
  void SetVisibility(vtkTypeBool visible) override;

protected:
  vtkLightFieldReliefActor();
  ~vtkLightFieldReliefActor() override;

private:
  vtkLightFieldReliefActor(const vtkLightFieldReliefActor&) = delete;
  void operator=(const vtkLightFieldReliefActor&) = delete;

  // Updates the surface filter and the mapper; false when there is nothing to draw.
  bool Prepare();
  // An error of this actor, said once until it changes or the relief draws.
  void Report(const std::string& problem);
  // Hides the named surface from the walkthrough once both are known (and the surface is one of
  // a loaded field's); ShowSurface undoes it.
  void HideSurface();
  void ShowSurface();

  vtkWeakPointer<vtkLightFieldActor> LightFieldActor;
  std::string SurfaceName;
  double DepthScale = 0.05;
  bool UseTextureDepthScale = true;
  int ProbesPerSide = 0;
  bool Occlusion = true;
  vtkSmartPointer<vtkImageData> ReliefTexture;
  vtkSmartPointer<vtkLightFieldReliefSurface> Surface;
  vtkSmartPointer<vtkReliefMapper> ReliefMapper;
  vtkSmartPointer<vtkLightFieldReliefShadowHook> ObjectShadow; // the walkthrough's object's
  vtkSmartPointer<vtkCommand> Forwarder;      // the surface filter's messages, as this actor's
  vtkSmartPointer<vtkCommand> ExecutiveNoise; // its executive's "returned failure", swallowed
  vtkMTimeType PreparedTime = 0;              // the surface's output time the mapper was set up for
  vtkMTimeType FailedTime = 0; // the surface's settings time of the last failed update
  bool Drawable = false;
  std::string LastProblem;
  // The surface this actor hid, and in which walkthrough.
  vtkWeakPointer<vtkLightFieldActor> HiddenIn;
  std::string HiddenName;
};

#endif
