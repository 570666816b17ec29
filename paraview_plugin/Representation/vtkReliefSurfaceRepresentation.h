// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefSurfaceRepresentation
 * @brief   ParaView's "Relief Surface": a surface representation that draws polydata as relief
 *          surfaces with vtkCompositeReliefMapper.
 *
 * The relief texture and the optional light set come with the data, attached as field data by
 * vtkAttachReliefTexture ("Attach Relief Texture" filter), so every MPI rank draws its piece
 * with the whole texture and writes the relief's depth, which IceT composites.
 * A colour image attached the same way (Attach Relief Texture's Color Texture input, e.g. the
 * albedo of Depth Hallucination) becomes the actor's texture, unless the user chose a Texture:
 * ParaView's own texture property only takes images its readers load, and those read no EXR.
 * The mapper and the LOD mapper share one vtkReliefProperty (GetReliefProperty()); the setters
 * below are the ParaView proxy's commands (MesolightRelief.xml), each setting that property.
 *
 * Input port 1 (optional, the proxy's "Light Field"): the output of a Virtual Light Field
 * filter (or a pass-through filter after it). The relief is then lit by the field instead of the
 * view's lights: SH9 irradiance probes of the field's indirect light gathered over the relief's
 * texture (vtkLightFieldReliefSurface on the shown surface: its texture coordinates, or its plane
 * without them; a surface on a scene wall ignores that wall as the wall itself would), plus the
 * field's emitters as the relief's own lights, with its self-shadowing
 * (vtkReliefProperty::SetLights), then the Light Field representation's display transform:
 * exposure (0.18 / the field's log-average luminance with LightFieldAutoExposure, times
 * Exposure), Reinhard tone mapping (ToneMapping) and sRGB, so a relief on a wall of the scene
 * shows the same radiance as the same pixel value as the scene beside it (the proxy class copies
 * the field display's exposure and tone mapping: vtkSMReliefSurfaceRepresentationProxy). A
 * relief mounted on a wall takes the wall's Kd as its albedo in place of Solid Color
 * (SetLightFieldAlbedo). A surface mounted on a scene wall writes no depth behind the plane
 * halfway to the wall
 * (vtkLightFieldReliefSurface::GetDepthLimitPlane, vtkReliefProperty::SetDepthLimitPlane): the
 * relief, which lies behind its surface by up to its depth, replaces the wall drawn by the Light
 * Field representation instead of being hidden by it. The probes are
 * gathered again only when the field (a new propagation) or the shown geometry changes. Under
 * MPI every rank updates together (vtkLightFieldReliefSurface gathers the surface's pieces and
 * sums a distributed field's probes over the ranks). Problems (no field upstream, a field that
 * did not propagate, a surface that is not planar...) are reported as errors; the relief is then
 * drawn the ordinary way. With LightFieldOcclusion (default on) the relief also occludes its own
 * indirect light and inter-reflects (the visible-share map of its relief texture on the exact
 * height-field intersector, recomputed when the texture, its depth scale or its edge rule
 * change, not per frame) and the scene shadows the emitter lights per probe (Embree), as the
 * walkthrough's relief (`mesolight vlf view --relief`) does.
 *
 * Input port 2 (optional, the proxy's "ReliefShadowCaster", which follows the Shadow Caster of the
 * field's own display): with a Light Field, the movable object (Light Field Gather's output)
 * darkens the relief by the same shadow maps, mode and share of the lighting as the scene's walls
 * (vtkLightFieldCasterShadows, drawn on the relief by vtkLightFieldReliefShadowHook), at the
 * displaced point the relief shows; under MPI every rank's piece of the caster is gathered
 * (vtkLightFieldRepresentation::GatherShadowCaster). Without a Light Field it casts nothing.
 *
 * A display transform (Translation, Scale, Orientation) of a relief lit by a Light Field is warned
 * about: the lighting is the field's where the data lies.
 *
 * A planar surface without texture coordinates gets those of its plane (the rule of the
 * command line's reliefs: SurfacePlaneOf in vtkScene/core/SurfaceRelief.h, the depth image once
 * over the surface's bounding rectangle in its plane, upright), computed over the whole surface
 * (every rank's pieces under MPI), so no Texture Map to Plane is needed; a non-planar one is an
 * error saying so (apply Texture Map to Plane / Cylinder / Sphere to it).
 */

#ifndef vtkReliefSurfaceRepresentation_h
#define vtkReliefSurfaceRepresentation_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkLightCollection.h"         // for vtkNew<vtkLightCollection>
#include "vtkLightFieldReliefSurface.h" // for vtkNew<vtkLightFieldReliefSurface>
#include "vtkNew.h"                     // for ReliefProperty
#include "vtkSmartPointer.h"            // for ShownReliefTexture
#include "vtkTexture.h"                 // for vtkNew<vtkTexture>

class vtkDataArray;
class vtkDoubleArray;
class vtkLightFieldCasterShadows;
class vtkLightFieldReliefShadowHook;
class vtkReliefProperty;
class vtkVirtualLightField;

class MESOLIGHTPARAVIEWRELIEF_EXPORT vtkReliefSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkReliefSurfaceRepresentation* New();
  vtkTypeMacro(vtkReliefSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Relief settings (see vtkReliefMapper). */
  void SetReliefMethod(int method);
  void SetLinearSteps(int steps);
  void SetRefinementSteps(int steps);
  void SetAdaptiveSteps(bool on);
  void SetMinimumSteps(int steps);
  void SetReliefDepthScale(double scale);
  /** Off (the default): the depth scale the relief texture was baked with; on: ReliefDepthScale. */
  void SetOverrideDepthScale(bool on);
  void SetSelfShadowing(bool on);
  void SetSilhouettes(bool on);
  void SetSurfaceCurvature(bool on);
  void SetWriteDepth(bool on);
  void SetRepeatTexture(bool on);
  void SetLevelOfDetail(bool on);
  void SetNormalFilter(int filter);
  void SetFarViewRays(int rays);
  void SetExposure(double exposure);
  void SetToneMapping(bool on);
  void SetLightSetThreshold(double threshold);
  void SetShadowedLights(int count);
  ///@}

  ///@{
  /**
   * With a Light Field and a Shadow Caster: vtkLightFieldActor::ShadowModes (default 3, Field)
   * and texels per shadow map side (default 256), as the Light Field representation's.
   */
  void SetShadowMode(int mode);
  void SetShadowMapResolution(int texels);
  ///@}

  /** With a Light Field: the field's automatic exposure (see above; default on). */
  void SetLightFieldAutoExposure(bool on);

  /**
   * With a Light Field (default on): a relief mounted on a wall of the field's scene takes the
   * wall's Kd as its albedo, as the walkthrough's relief on that wall does, so the relief a user
   * adds looks like the wall around it without looking up the wall's material. Only where Solid
   * Color would apply: a relief coloured by an array or a texture (a photograph's albedo) keeps
   * its colours. Off, or not mounted on a wall: Solid Color (DiffuseColor).
   */
  void SetLightFieldAlbedo(bool on);

  /** Solid Color: the relief's albedo unless the Light Field's wall gives it (above). */
  void SetDiffuseColor(double r, double g, double b) override;

  /**
   * With a Light Field: the relief's occlusion of its own indirect light with its multi-bounce
   * inter-reflection (the visible-share map of its relief texture, vtkLightFieldReliefSurface)
   * and the scene's shadows of the emitter lights per probe, as `mesolight vlf view --relief`
   * draws them (default on; off: neither, for comparison).
   */
  void SetLightFieldOcclusion(bool on);

  /** Visible-share maps computed so far (once per relief texture, depth scale, edge rule). */
  int GetVisibleShareMaps();

  /**
   * The last visible-share map as this rank holds it: its values (three or four per cell,
   * row-major, vtkIrradianceProbesTexture's visible-share array) after its width and height, empty
   * without a map; the ranks it was split over (1: computed whole); the seconds it took and the
   * processor seconds this process spent on it. What tests compare between one and several
   * ranks, and benchmarks time.
   */
  vtkDoubleArray* GetVisibleShareValues();
  int GetVisibleShareRanks();
  double GetVisibleShareSeconds();
  double GetVisibleShareCpuSeconds();

  /** Probe gatherings so far (each new field or geometry makes one): how tests check that
   * renders alone gather nothing. */
  vtkGetMacro(ProbeGatherings, int);

  /** The emitter lights the relief is lit by (empty without a Light Field). */
  vtkLightCollection* GetFieldLights();

  /** The relief settings of both the mapper and the LOD mapper. */
  vtkReliefProperty* GetReliefProperty();

  /** The user's Texture; it wins over an attached colour texture. */
  void SetTexture(vtkTexture* texture) override;

  /** On render requests: the attached colour texture becomes the actor's texture. */
  int ProcessViewRequest(vtkInformationRequestKey* requestType, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkReliefSurfaceRepresentation();
  ~vtkReliefSurfaceRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  /** Plane texture coordinates for shown pieces without any (class comment). */
  void AddPlaneTextureCoordinates();

  /** Lighting by the field of input port 1 (class comment), or none when it is not connected. */
  void UpdateFieldLighting(vtkInformationVector* fieldInput);
  /** The field surface's probes, lights and depth limit on the mappers (after its update). */
  void UseFieldSurfaceOutputs(bool updated);
  /** The Shadow Caster of input port 2 on the relief (with a Light Field), or none. */
  void UpdateShadowCaster(vtkInformationVector* casterInput);
  /** The relief property's exposure, tone map and sRGB for the current lighting. */
  void UpdateDisplayTransform();
  /** The actor's diffuse colour: the mounted wall's Kd or Solid Color (SetLightFieldAlbedo). */
  void UpdateAlbedo();

  vtkNew<vtkReliefProperty> ReliefProperty;
  vtkNew<vtkTexture> AttachedColorTexture;
  vtkTexture* UserTexture = nullptr; // not owned: the superclass' actor holds it

  vtkNew<vtkLightFieldReliefSurface> FieldSurface;
  vtkSmartPointer<vtkLightFieldCasterShadows> CasterShadows;
  vtkSmartPointer<vtkLightFieldReliefShadowHook> ObjectShadow;
  vtkNew<vtkLightCollection> FieldLights;
  vtkSmartPointer<vtkDoubleArray> VisibleShareValues; // GetVisibleShareValues' answer
  bool FieldLit = false;
  bool WarnedDisplayTransform = false; // the display transform warned about (once)
  bool LightFieldAutoExposure = true;
  double UserExposure = 1.0;
  double FieldLogAverage = 0.0; // 0: none
  int ProbeGatherings = 0;
  // What the probes were gathered for: the field's producer and its propagation, the geometry.
  vtkAlgorithm* GatheredInput = nullptr;            // the Light Field connected; compared only
  vtkVirtualLightField* GatheredProducer = nullptr; // not owned, compared only
  int GatheredPropagation = -1;
  vtkMTimeType GatheredGeometryTime = 0;
  bool LightFieldOcclusion = true;
  bool LightFieldAlbedo = true;
  double UserDiffuseColor[3] = { 1.0, 1.0, 1.0 }; // Solid Color
  // What the visible-share map was computed for: the relief texture, its depth scale, its edge.
  vtkDataArray* SharedTexture = nullptr; // its texels; not owned, compared only
  vtkMTimeType SharedTextureTime = 0;
  double SharedDepthScale = -1.0;
  int SharedEdge = -1; // 1 walled, 0 clamped, 2 no occlusion

  /** The relief texture shown, its effective depth scale and whether it is walled. */
  vtkSmartPointer<vtkImageData> ShownReliefTexture(double& depthScale, bool& walled);

  /** Shows the colour image attached to the mapper's input, or removes the one shown. */
  void UpdateAttachedColorTexture();

private:
  vtkReliefSurfaceRepresentation(const vtkReliefSurfaceRepresentation&) = delete;
  void operator=(const vtkReliefSurfaceRepresentation&) = delete;
};

#endif
