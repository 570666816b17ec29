// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldActor
 * @brief   a propagated virtual light field walked through inside a VTK renderer
 *
 * The walkthrough of Wither 2005 §2.4.2.2 as an actor that lives beside ordinary actors and
 * relief surfaces in one renderer. It takes a propagated field (SetLightFieldFilter with a
 * vtkVirtualLightField, or LoadLightField from a snapshot file; code built in this tree may lend
 * it a field directly through vtkLightFieldActorCore) and
 * draws the field's scene triangles (world coordinates) with its own mapper
 * (vtkLightFieldMapper) in one of four modes:
 *
 * - Geometry (§2.4.2.2.1): the triangles with plain VTK shading, coloured by their Kd.
 * - Raytrace (§2.4.2.2.2): per pixel, the first hit's radiance leaving toward the eye, looked up
 *   in the field (three nearest directions with spherical weights, 8-neighbour cells), computed
 *   on the CPU (Embree, mesolight::ParallelFor over tiles) and shown through a screen-space
 * texture.
 * - Progressive (§2.4.2.2.3): diffuse surfaces drawn by the GPU from one texture atlas of all
 *   total diffuse textures (uploaded once, bilinear, gutters so no seams). Mirror pixels (Ks > 0)
 *   are filled by a field lookup in the reflected direction (nearest direction and cell) while
 *   the view changes, and replaced by reflections traced to the first diffuse hit (its texture)
 *   once a worker thread has finished them for the current view.
 * - Coherent (§2.4.2.2.4): progressive with the reflections traced at once, as 16-ray Embree
 *   packets over 4 x 4 pixel tiles on all cores.
 *
 * Mirror and raytrace values reach the GPU as a float texture over the screen rectangle the
 * mirrors cover, read by the actor's fragments at gl_FragCoord: the depth test therefore decides
 * occlusion against every other actor, and the composite is by alpha (only fragments of mirror
 * surfaces take the screen value where it has one). Exposure and tone mapping (clamp or
 * Reinhard, then sRGB) are applied in GLSL to every radiance mode.
 *
 * The scene is static: the actor's own transform must stay the identity (the field is baked in
 * world coordinates). One movable object (Wither 2005, "Interactive dynamic objects in a virtual
 * light field") can be placed in it: SetMovableObject(an ordinary vtkActor). Each frame the
 * actor reads that actor's polydata and matrix, places the object in the field and in the
 * tracer's Embree scene as an instanced geometry (only its transform changes when it moves),
 * gathers the field's light at its points when it moved (mesolight::vlf::ObjectGatherer), and
 * then every radiance mode shows it occluding mirror pixels and reflected in mirrors. The object
 * is drawn by its own actor; vtkLightFieldObjectMapper shades it from the field.
 */
#ifndef vtkLightFieldActor_h
#define vtkLightFieldActor_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkOpenGLActor.h"

#include <cstddef> // For std::size_t
#include <cstdint> // For std::uint64_t
#include <memory>  // For std::unique_ptr
#include <string>  // For std::string

class vtkActor;
class vtkRenderer;
class vtkVirtualLightField;

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldActor : public vtkOpenGLActor
{
public:
  static vtkLightFieldActor* New();
  vtkTypeMacro(vtkLightFieldActor, vtkOpenGLActor);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Bring the field up to date (a filter's update) before culling and drawing use the scene. */
  void Render(vtkRenderer* ren, vtkMapper* mapper) override;
  using Superclass::GetBounds;
  double* GetBounds() override;
  ///@}

  enum RenderModes
  {
    Geometry = 0,
    Raytrace = 1,
    Progressive = 2,
    Coherent = 3
  };
  ///@{
  /** Display mode (default Progressive). */
  vtkSetClampMacro(RenderMode, int, Geometry, Coherent);
  vtkGetMacro(RenderMode, int);
  void SetRenderModeToGeometry() { this->SetRenderMode(Geometry); }
  void SetRenderModeToRaytrace() { this->SetRenderMode(Raytrace); }
  void SetRenderModeToProgressive() { this->SetRenderMode(Progressive); }
  void SetRenderModeToCoherent() { this->SetRenderMode(Coherent); }
  /** "geometry", "raytrace", "progressive", "coherent". */
  static const char* GetRenderModeAsString(int mode);
  /** The mode of a name above, or -1. */
  static int GetRenderModeFromString(const std::string& name);
  ///@}

  enum ToneMaps
  {
    Clamp = 0,
    Reinhard = 1
  };
  ///@{
  /** Radiance scale before tone mapping (default 1) and the operator (default Clamp). */
  vtkSetClampMacro(Exposure, double, 0.0, 1e9);
  vtkGetMacro(Exposure, double);
  vtkSetClampMacro(ToneMap, int, Clamp, Reinhard);
  vtkGetMacro(ToneMap, int);
  ///@}

  ///@{
  /** Mirror bounces followed by traced reflections (default 8). */
  vtkSetClampMacro(MaximumReflectionDepth, int, 1, 64);
  vtkGetMacro(MaximumReflectionDepth, int);
  ///@}

  /** Shows the field of a vtkVirtualLightField (updated, and its field taken, at each render). */
  void SetLightFieldFilter(vtkVirtualLightField* filter);
  /**
   * Reads a field snapshot (`mesolight vlf propagate --out FILE`). False on failure, reported
   * with vtkErrorMacro (missing, foreign, truncated or other-version file, a field that cannot
   * be shown): observe ErrorEvent to show it as the program's own message.
   */
  bool LoadLightField(const std::string& fileName);
  /** True when the field has surfaces with Ks > 0. */
  bool HasMirrors() const;

  ///@{
  /**
   * Surfaces of the field's scene left out of the drawing in every mode, by name (an OBJ g/o
   * name or a Cornell box name, as vtkLightFieldReliefSurface takes them): e.g. a surface a
   * relief actor draws instead (`mesolight vlf view --relief`). The field and its tracer keep
   * them: mirrors still reflect them as flat surfaces. A name the field's scene does not have is
   * reported with vtkErrorMacro (listing the names it has) and ignored.
   */
  void AddHiddenSurface(const std::string& name);
  /** Shows the surface of that name again (nothing if it is not hidden). */
  void RemoveHiddenSurface(const std::string& name);
  void RemoveAllHiddenSurfaces();
  int GetNumberOfHiddenSurfaces() const;
  ///@}

  /**
   * Progressive mode: the camera rests. Starts tracing the reflections of the last rendered view
   * (if not done or under way), waits until they are ready or `seconds` passed, and returns
   * whether they are ready; the next Render() shows them. With 0 seconds it only polls (and
   * starts the trace). True at once in the other modes. Rendering the same view twice also
   * starts the trace.
   */
  bool WaitForTracedReflections(double seconds = 60.0);
  /** The last frame showed traced (sharp) reflections for its view. */
  bool GetLastFrameConverged() const { return this->LastFrameConverged; }

  ///@{
  /** Figures of the last frame: CPU seconds of the screen-space pass, texture upload seconds,
   * pixels given a screen value, and the screen rectangle (x0, y0, x1, y1, viewport pixels). */
  double GetLastSpecularSeconds() const { return this->LastSpecularSeconds; }
  double GetLastUploadSeconds() const { return this->LastUploadSeconds; }
  vtkIdType GetLastScreenPixels() const { return this->LastScreenPixels; }
  void GetLastScreenRect(int rect[4]) const;
  ///@}

  ///@{
  /**
   * The movable object: an ordinary actor of the same renderer (any mapper whose input is
   * vtkPolyData; polygons and strips are triangulated, missing normals computed). Its matrix
   * (position, orientation, scale, user matrix) places it; its property's diffuse colour is its
   * reflectance. nullptr removes it. Held weakly (vtkWeakPointer): the renderer or the caller
   * owns it, and vtkLightFieldObjectMapper on it holds this actor weakly too, so neither keeps
   * the other alive (no reference cycle). One object at a time.
   */
  void SetMovableObject(vtkActor* object);
  vtkActor* GetMovableObject();
  /** Midpoint subdivision levels (0-3) of the object's gathering (GatherSettings::Subdivision);
   * vtkLightFieldObjectMapper sets it. Default 0. */
  vtkSetClampMacro(ObjectSubdivision, int, 0, 3);
  vtkGetMacro(ObjectSubdivision, int);
  /** The directions the object's gather reads (GatherSettings::Directions): AllDirections
   * (default), HalfDirections (every other one) or ImportanceDirections (half, drawn by the
   * field's radiance): about half the cost at a few tenths of a point more error
   * (docs/vlf.md). vtkLightFieldObjectMapper sets it. */
  enum GatherDirectionSets
  {
    AllDirections = 0,
    HalfDirections = 1,
    ImportanceDirections = 2
  };
  vtkSetClampMacro(ObjectGatherDirections, int, AllDirections, ImportanceDirections);
  vtkGetMacro(ObjectGatherDirections, int);
  /** The set of a name "all", "half" or "importance", or -1. */
  static int GetGatherDirectionsFromString(const std::string& name);
  /** The object's irradiance from a precomputed irradiance volume (mesolight::vlf::
   * IrradianceVolume): 0 (default) gathers at every vertex along the directions; N >= 2 reads
   * a volume of N grid points along the scene's longest side instead, built once per field
   * (seconds) and then about a microsecond per vertex, at a few points more error near
   * surfaces (docs/walkthrough.md). */
  vtkSetClampMacro(ObjectIrradianceVolume, int, 0, 128);
  vtkGetMacro(ObjectIrradianceVolume, int);
  /**
   * Brings the object up to date for the current field: rereads its polydata when its MTime
   * changed, places it, updates the tracer's instance and gathers its shading when anything
   * moved. Cheap when nothing changed (PrepareFrame and vtkLightFieldObjectMapper both call it;
   * one gather per change). False when there is no usable object (none set, no field, or a
   * mesh the checks refuse: reported with vtkErrorMacro). A usable object that is placed
   * outside the field or through a wall is reported with vtkWarningMacro; each problem once,
   * until the object or its problem changes.
   */
  bool UpdateMovableObject();
  /** Bumped whenever the object's mesh, placement or shading changed. */
  unsigned long GetObjectVersion() const;
  /** Seconds of the last object update that did work (placement, gather, instance; see
   * GetObjectVersion for whether one happened) and of its gather alone. */
  double GetLastObjectSeconds() const;
  double GetLastGatherSeconds() const;
  ///@}

  ///@{
  /**
   * Shadows of the movable object on the scene (Wither 2005 ch. 4; the algorithm and its modes:
   * mesolight::vlf::ObjectShadows in core/ObjectShadows.h). Shadow maps from the field's
   * significant emitters (at most ShadowEmitterCount, default 4), each placed at the emitter
   * and fitted to the object, ShadowMapResolution texels a side (default 256). Modes: None;
   * Black and Blend (Wither's fixed alpha 0.5) darken the radiance; Field (default) removes
   * the direct light the object blocks and keeps the field's indirect light; PCF filters
   * ShadowPCFKernel x ShadowPCFKernel texels (default 3); Soft samples each emitter's area by
   * ShadowAreaSamples^2 points (default 3 x 3), a map each. Drawn on the GPU in the progressive
   * and coherent modes, applied to the CPU's diffuse pixels in raytrace mode.
   */
  enum ShadowModes
  {
    ShadowNone = 0,
    ShadowBlack = 1,
    ShadowBlend = 2,
    ShadowField = 3,
    ShadowPCF = 4,
    ShadowSoft = 5
  };
  void SetShadowMode(int mode);
  int GetShadowMode() const;
  /** "none", "black", "blend", "field", "pcf", "soft"; FromString gives -1 for others. */
  static const char* GetShadowModeAsString(int mode);
  static int GetShadowModeFromString(const std::string& name);
  void SetShadowMapResolution(int texels); // clamped to [16, 4096]
  int GetShadowMapResolution() const;
  void SetShadowEmitterCount(int count); // clamped to [1, 8]
  int GetShadowEmitterCount() const;
  void SetShadowAreaSamples(int perSide); // clamped to [1, 4]
  int GetShadowAreaSamples() const;
  void SetShadowPCFKernel(int texels); // odd, clamped to [1, 9]
  int GetShadowPCFKernel() const;
  /** Why the object casts no shadow ("" when it does or there is no object). */
  std::string GetShadowProblem() const;
  /** CPU seconds of the last rebuild of the maps (placement and fill). */
  double GetLastShadowSeconds() const;
  ///@}

protected:
  vtkLightFieldActor();
  ~vtkLightFieldActor() override;

private:
  vtkLightFieldActor(const vtkLightFieldActor&) = delete;
  void operator=(const vtkLightFieldActor&) = delete;

  // The core objects (field, shaded object, maps) and the frame for code built in this tree
  // (vtkLightFieldActorCore.h), and the negative tests' hooks (vtkLightFieldActorTesting.h):
  // neither header is installed.
  friend class vtkLightFieldActorCore;
  friend class vtkLightFieldActorTesting;

  void RefreshField(); // updates the filter, takes its field when it changed
  // Updates the field, the object, its shadows and the screen image for the renderer's view;
  // false when there is nothing to draw in a radiance mode (no field).
  bool PrepareFrame(vtkRenderer* renderer);
  // The screen image of each radiance mode; each returns the pixels given a value.
  std::size_t ShadeRaytrace();
  std::size_t ShadeMirrors(bool objectMoved);
  // Starts the worker on the last view's reflections unless it has them or is on them.
  void TraceAtRest();
  // Identifies the trace options, the object's state and its shadows.
  std::uint64_t TraceKey() const;

  int RenderMode = Progressive;
  double Exposure = 1.0;
  int ToneMap = Clamp;
  int MaximumReflectionDepth = 8;
  int ObjectSubdivision = 0;
  int ObjectGatherDirections = AllDirections;
  int ObjectIrradianceVolume = 0;
  bool LastFrameConverged = false;
  double LastSpecularSeconds = 0.0;
  double LastUploadSeconds = 0.0;
  vtkIdType LastScreenPixels = 0;
  struct Internals; // the parts the actor is composed of (vtkLightFieldActorInternals.h)
  std::unique_ptr<Internals> Impl;
};

#endif
