// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldReliefSurface
 * @brief   a named surface of a light field's scene, made ready for vtkReliefMapper lit by the
 *          field: its polygons, its indirect light as SH9 probes, the emitters as VTK lights
 *
 * The light field comes from a vtkLightFieldActor (SetLightFieldActor: the field it shows, e.g.
 * loaded from a snapshot) or from a vtkVirtualLightField connected to input port 0
 * (SetLightFieldConnection; its scene came as polydata, whose names vtkTriangleSceneConverter
 * carries when the source gave them). SurfaceName names one planar surface of the field's scene: an
 * OBJ `g`/`o` name or a Cornell box name (floor, ceiling, back, left, right, short, tall). Outputs:
 *
 * - port 0: the surface's triangles in world coordinates with point normals (its front side)
 *   and texture coordinates: the scene's own when it has them (one affine map of the plane),
 *   else from its plane, u along its horizontal and v up it over its bounding rectangle (the
 *   rule of `mesolight vlf render --relief`: both use mesolight::vlf::FindReliefSurface,
 *   core/ReliefSurface.h). The input of a vtkReliefMapper.
 * - port 1: the field's indirect light over that texture, the emitters' own radiance left out,
 *   as vtkReliefMapper::SetIrradianceProbesData takes it: a (9 ProbesPerSide) x ProbesPerSide
 *   float image of 3 components, pixel (9 i + k, j) SH9 coefficient k of probe (i, j) at texture
 *   ((i + 1/2) / n, (j + 1/2) / n) (mesolight::vlf::ReliefSurfaceProbes).
 * - GetEmitterLights(): the field's emitters as VTK lights (mesolight::vlf::EstimateEmitterLights,
 *   one per lamp -- a connected piece of an emitting surface -- at its centroid, world
 *   coordinates), each set up by vtkReliefMapper::ConfigureEmitterLight from the radiant
 *   intensity Le x Area in world units (a cosine-lobe spot light falling off as 1 / d^2,
 *   intensity divided by pi: VTK shades Kd x intensity x cos without the Lambertian 1 / pi).
 *   More lamps than the relief shades (vtkReliefMapper::GetMaximumNumberOfLights, 8) are merged
 *   down to that count (Lightcuts' metric, the lamps farthest from this surface first), so no
 *   lamp's light is dropped. Give them to the relief (vtkReliefProperty::SetLights): the scene
 *   visibility below is per light of this list.
 *
 * Any planar surface instead of a named one (e.g. ParaView's Relief Surface lit by a Virtual
 * Light Field): polydata in world coordinates on input port 1 (SetSurfaceConnection /
 * SetSurfaceData); SurfaceName is then ignored. Its own texture coordinates give the texture
 * frame when it has them (one affine map of its plane), else its plane does (as above); it may
 * lie on a scene wall (the probes then ignore that wall as they do for the wall itself, and
 * GetSurfaceDiffuse() is the wall's Kd) or anywhere in the field. Port 0 is then that input with
 * point normals and, when it had none, the plane's texture coordinates. With several MPI ranks
 * (the global controller) every rank must update together: the surface's pieces are gathered
 * onto every rank (one texture frame for all), and the probes are summed over the ranks of a
 * field whose directions are split between them (vtkVirtualLightField's DistributeDirections),
 * or computed by the rank that holds the whole field and sent to the others; every rank ends
 * with the same probes and emitter lights.
 *
 * What makes the relief mapper shade like the CPU reference (`mesolight vlf render --relief`,
 * vtkIrradianceProbesTexture), both optional and computed once per change, not per frame:
 * - SceneOcclusion on: port 1 gets a fourth component, pixel (9 i + k, j) the factor of emitter
 *   light k (k < 9, GetEmitterLights' order; the mapper reads lights 0-7) at probe (i, j): the
 *   flat wall's irradiance there from the CPU reference's emitter samples the light stands for,
 *   past the scene (Embree), over the light's own as a point light
 *   (mesolight::vlf::EmitterLightFactors, core/ReliefOcclusion.h). It carries the scene's shadow
 *   and corrects a light that stands for several merged lamps.
 * - a relief texture given (SetReliefTextureData, vtkReliefMapper's form: depth in A, 0 = top,
 *   1 = deepest; ReliefDepthScale its depth scale): port 1's field data gets the relief's
 *   visible-share map over its texture (ReliefVisibleShareMap on the exact height-field
 *   intersector, Mesolight::ReliefCore; vtkIrradianceProbesTexture::GetVisibleShareName() and
 *   GetVisibleShareSizeName()), from which the mapper draws the relief's occlusion of its own
 *   indirect light and its multi-bounce inter-reflection. Without it, and at depth scale 0 (a
 *   flat relief hides nothing), V = 1 (no occlusion). A change of the relief texture, its depth
 *   scale or WalledRelief recomputes the map only: for a surface of input port 1 the probes of
 *   an unchanged field and surface are kept. Under MPI (a surface of input port 1) the ranks
 *   split the map's rows, every ranks-th row each, and two sums over the ranks give every rank
 *   the whole map, the one-rank map bit for bit (mesolight::vlf::ReliefVisibleShareGrid with a
 *   Reducer, the final gather's convention; GetVisibleShareRanks()); when the ranks' relief
 *   textures differ in size (a rank without one) each rank makes its own map instead. A stop on
 *   one rank stops all (empty outputs on every rank).
 *
 * GetSurfaceDiffuse() is the surface's Kd (the relief actor's colour). An unknown name (the
 * message lists the scene's surfaces), a non-planar surface without texture coordinates, a
 * mirror, or no field are errors (vtkErrorMacro, empty outputs); a relief texture without depth
 * is an error too (the probes are still made, without the map). Probe and map computation report
 * progress; AbortExecute stops them (empty outputs, no error).
 */
#ifndef vtkLightFieldReliefSurface_h
#define vtkLightFieldReliefSurface_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkNew.h"                         // For vtkNew
#include "vtkPolyDataAlgorithm.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <memory> // For std::unique_ptr
#include <string> // For std::string
#include <vector> // For std::vector

class vtkAlgorithmOutput;
class vtkImageData;
class vtkLight;
class vtkLightCollection;
class vtkLightFieldActor;
class vtkMultiProcessController;
class vtkPolyData;
class vtkVirtualLightField;
namespace mesolight
{
struct SH9;
}

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldReliefSurface : public vtkPolyDataAlgorithm
{
public:
  static vtkLightFieldReliefSurface* New();
  vtkTypeMacro(vtkLightFieldReliefSurface, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The field: the one a walkthrough actor shows (takes precedence), or a vtkVirtualLightField
   * connected to input port 0. */
  void SetLightFieldActor(vtkLightFieldActor* actor);
  vtkLightFieldActor* GetLightFieldActor() { return this->LightFieldActor; }
  void SetLightFieldConnection(vtkAlgorithmOutput* output);
  /** Or the vtkVirtualLightField itself, already updated (e.g. found upstream of another
   * consumer's input: vtkVirtualLightField::FindUpstream); takes precedence over port 0 and
   * updates nothing upstream. Only for the surface of input port 1. */
  void SetLightFieldProducer(vtkVirtualLightField* producer);
  vtkVirtualLightField* GetLightFieldProducer() { return this->LightFieldProducer; }
  ///@}

  ///@{
  /** The surface's name in the field's scene. */
  vtkSetStdStringFromCharMacro(SurfaceName);
  vtkGetCharFromStdStringMacro(SurfaceName);
  ///@}

  ///@{
  /** A planar polygonal surface in world coordinates (input port 1, optional; see above). */
  void SetSurfaceConnection(vtkAlgorithmOutput* output);
  void SetSurfaceData(vtkPolyData* surface);
  ///@}

  ///@{
  /**
   * SH9 probes per side of the texture; 0 (the default) chooses from the field and the surface:
   * one per field line cell across the surface, 8 to 64 (mesolight::vlf::ReliefProbesPerSide),
   * so that the scene's shadows on a large surface are not averaged away.
   */
  vtkSetClampMacro(ProbesPerSide, int, 0, 256);
  vtkGetMacro(ProbesPerSide, int);
  /** The probes per side of the last execution (ProbesPerSide, or the automatic choice). */
  vtkGetMacro(ProbesPerSideUsed, int);
  ///@}

  ///@{
  /**
   * The relief drawn on the surface, for its visible-share map (see above): an RGBA image of
   * float or unsigned char (vtkReliefTextureFilter's output), depth in A; null (the default)
   * for none. Its depth scale is ReliefDepthScale (vtkReliefProperty's convention, default
   * 0.05, clamped to [0, 10]).
   */
  void SetReliefTextureData(vtkImageData* texture);
  vtkImageData* GetReliefTextureData();
  vtkSetClampMacro(ReliefDepthScale, double, 0.0, 10.0);
  vtkGetMacro(ReliefDepthScale, double);
  ///@}

  ///@{
  /**
   * Whether the relief is recessed into its surface (side walls at its texture's border, what
   * vtkReliefProperty's Silhouettes off draws and the command line's reliefs are) rather than
   * continued beyond it (mesolight::HeightField::Edge). Default on.
   */
  vtkSetMacro(WalledRelief, bool);
  vtkGetMacro(WalledRelief, bool);
  vtkBooleanMacro(WalledRelief, bool);
  ///@}

  ///@{
  /** The scene's visibility of each emitter light per probe in port 1 (see above). Default off. */
  vtkSetMacro(SceneOcclusion, bool);
  vtkGetMacro(SceneOcclusion, bool);
  vtkBooleanMacro(SceneOcclusion, bool);
  ///@}

  /**
   * Adds the visible-share map of the relief texture (SetReliefTextureData, ReliefDepthScale,
   * WalledRelief) over a texture frame (origin, u axis, v axis, unit normal: the field's unit
   * sphere in an update) to a probe image, as port 1 gets it (vtkIrradianceProbesTexture's
   * visible-share arrays, mesolight::vlf::ReliefVisibleShareGrid), computed once per texture,
   * depth scale and frame and kept. It needs no field (probes of one's own get the map this
   * way). With a controller of several ranks (collective: every rank calls it) the ranks split
   * the map's rows. True when added or when there is nothing to add (no texture, depth scale 0,
   * or a texture without depth: vtkErrorMacro says so); false when stopped (AbortExecute).
   */
  bool AddVisibleShare(
    vtkImageData* probes, const double frame[12], vtkMultiProcessController* controller = nullptr);

  /** Probe gatherings and visible-share maps computed so far (tests check what is kept). */
  vtkGetMacro(ProbeComputations, int);
  vtkGetMacro(VisibleShareComputations, int);

  /** The ranks the last visible-share map was split over (1: computed whole), the seconds it
   * took this rank, sums over the ranks included, and the processor seconds this process spent
   * on it, all its threads (std::clock; 0 before the first map). */
  vtkGetMacro(VisibleShareRanks, int);
  vtkGetMacro(VisibleShareSeconds, double);
  vtkGetMacro(VisibleShareCpuSeconds, double);

  /** The probe image (output port 1). */
  vtkImageData* GetProbesOutput();

  /** The emitters as VTK lights, rebuilt by every update (empty when it failed). */
  vtkLightCollection* GetEmitterLights() { return this->EmitterLights; }

  /**
   * The field's emitter lights for the field `actor` shows, added to `lights` without a surface
   * (e.g. for a relief-mapped movable object): merged as above, but for no receiver in
   * particular (neighbouring lamps first). False when the actor shows no field.
   */
  static bool GetEmitterLights(vtkLightFieldActor* actor, vtkLightCollection* lights);

  /**
   * Every rank's `local` piece appended into one polydata on every rank (a collective: every
   * rank of `controller` must call it); `local` itself without a controller or with one rank.
   * Pieces without polygons are left out. Used where one texture frame must fit the whole surface.
   */
  static vtkSmartPointer<vtkPolyData> GatherWholeSurface(
    vtkPolyData* local, vtkMultiProcessController* controller);

  /** The surface's diffuse reflectance (Kd) after an update. */
  vtkGetVector3Macro(SurfaceDiffuse, double);

  /**
   * The radiance the surface emits (its material's Ke, 0 unless it is an emitter) after an
   * update: the relief drawn over a lamp or a window shows it (vtkReliefProperty::SetEmission).
   */
  vtkGetVector3Macro(SurfaceEmission, double);

  /**
   * For a surface of input port 1 mounted on a scene surface (facing the same way, up to 5% of
   * the scene radius in front of it: mesolight::vlf::ReliefSurfaceFromTriangles), after an
   * update: the plane halfway between the two, world coordinates (a point, the front normal).
   * A relief drawn on the surface should write no depth behind it
   * (vtkReliefProperty::SetDepthLimitPlane): its depth lies behind its own plane by up to the
   * depth scale, so deeper than a wall a few mm behind, which would hide it. False when the
   * surface is mounted on none, and for a named surface (the wall itself, hidden by
   * vtkLightFieldActor::AddHiddenSurface instead).
   */
  bool GetDepthLimitPlane(double origin[3], double normal[3]) const;

  /**
   * After an update, the field's world to unit sphere normalisation (centre, scale; every rank
   * has it), what a movable object's shadow on this surface must have been gathered with
   * (vtkLightFieldCasterShadows::SetFieldUnitSphere). False before a successful update.
   */
  bool GetFieldUnitSphere(double centre[3], double* scale) const;

  vtkMTimeType GetMTime() override;

protected:
  vtkLightFieldReliefSurface();
  ~vtkLightFieldReliefSurface() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int FillOutputPortInformation(int port, vtkInformation* info) override;
  int RequestInformation(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;
  int RequestData(vtkInformation* request, vtkInformationVector** inputVector,
    vtkInformationVector* outputVector) override;

private:
  vtkLightFieldReliefSurface(const vtkLightFieldReliefSurface&) = delete;
  // The route of input port 1 (any planar surface), MPI included.
  int RequestSurfaceData(vtkPolyData* input, vtkPolyData* output, vtkImageData* probesOutput);
  // Where the map's share of the progress starts (the probes report before it): 0.5 when there
  // is a map to make, else 1.
  double MapProgress() const;
  void operator=(const vtkLightFieldReliefSurface&) = delete;
  friend class vtkLightFieldReliefSurfaceCore;

  vtkLightFieldActor* LightFieldActor = nullptr;
  vtkVirtualLightField* LightFieldProducer = nullptr;
  std::string SurfaceName;
  int ProbesPerSide;
  int ProbesPerSideUsed = 0;
  double ReliefDepthScale = 0.05;
  bool WalledRelief = true;
  bool SceneOcclusion = false;
  int ProbeComputations = 0;
  int VisibleShareComputations = 0;
  int VisibleShareRanks = 0;
  double VisibleShareSeconds = 0.0;
  double VisibleShareCpuSeconds = 0.0;
  struct vtkInternals; // what the last update computed, kept while its inputs do not change
  std::unique_ptr<vtkInternals> Internals;
  double SurfaceDiffuse[3] = { 0.0, 0.0, 0.0 };
  double SurfaceEmission[3] = { 0.0, 0.0, 0.0 };
  double DepthLimit[7] = { 0.0, 0.0, 0.0, 0.0, 0.0, 0.0, 0.0 }; // point, normal, mounted
  double FieldUnitSphere[4] = { 0.0, 0.0, 0.0, 0.0 };           // centre, scale (0: none)
  vtkNew<vtkLightCollection> EmitterLights;
  const void* ExecutedField = nullptr; // the actor's field the outputs were made from
  // A named surface's probes as computed (port 1 has them as floats); null otherwise.
  std::unique_ptr<std::vector<mesolight::SH9>> NamedProbes;
};

#endif
