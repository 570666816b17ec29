// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkCompositeLightFieldMapper
 * @brief   draws vtkVirtualLightField's output with its total diffuse radiance per pixel, as a
 *          vtkCompositePolyDataMapper2 (what ParaView's geometry representations draw through)
 *
 * The walkthrough's progressive-mode diffuse shading (Wither 2005 §2.4.2.2.3; docs/walkthrough.md)
 * for data that carries its light field with it: the radiance atlas comes from the first block's
 * field data and the atlas coordinates from its point data (vtkVirtualLightField::GetAttachedAtlas,
 * GetAtlasCoordinatesName), so every MPI rank draws its piece with the whole atlas. The fragment
 * code is vtkLightFieldMapper's (glsl/vtkLightFieldFS.glsl: the atlas bilinear, no seams thanks to
 * its gutters; then exposure, clamp or Reinhard, sRGB) without the screen-space pass, so mirrors
 * show their diffuse part only. VTK's lighting is replaced; blocks without an atlas are drawn the
 * ordinary way (with a warning).
 *
 * Surfaces shaded by vtkLightFieldGatherFilter (no atlas, a point array "Radiance" and the
 * field's log-average luminance as field data) are drawn with their per-vertex radiance through
 * the same exposure, tone mapping and sRGB, automatic exposure from the field's log-average: a
 * gathered object looks like the scene it sits in, without a colour map.
 *
 * Shadows of a movable object (SetShadowCaster: Light Field Gather's output, in world
 * coordinates, whose field data carries the field's emitters and normalisation) darken the
 * scene by vtkLightFieldActor's code: the maps of vtkLightFieldCasterShadows, read per
 * fragment by glsl/vtkLightFieldShadowFS.glsl at each receiver's
 * unit-sphere point, normal and reflectance (vtkVirtualLightField's receiver arrays).
 * ShadowMode as vtkLightFieldActor::SetShadowMode (default field-derived).
 *
 * Only for VTK < 9.3, where vtkCompositePolyDataMapper2 draws through vtkCompositeMapperHelper2.
 */
#ifndef vtkCompositeLightFieldMapper_h
#define vtkCompositeLightFieldMapper_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkCompositePolyDataMapper2.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <memory> // For std::unique_ptr

class vtkFloatArray;
class vtkPolyData;
class vtkTextureObject;

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkCompositeLightFieldMapper
  : public vtkCompositePolyDataMapper2
{
public:
  static vtkCompositeLightFieldMapper* New();
  vtkTypeMacro(vtkCompositeLightFieldMapper, vtkCompositePolyDataMapper2);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ToneMapType
  {
    Clamp = 0,
    Reinhard = 1
  };

  ///@{
  /** Radiance scale before tone mapping (default 1); with AutoExposure a factor on its scale. */
  vtkSetClampMacro(Exposure, double, 0.0, 1e9);
  vtkGetMacro(Exposure, double);
  ///@}

  ///@{
  /**
   * Scale the radiance so that the atlas' log-average luminance becomes the middle grey 0.18
   * (the key value of Reinhard et al.'s photographic tone reproduction), times Exposure: a
   * scene in any radiance units shows neither dark nor saturated. The average runs over the
   * atlas' lit texels, so it does not change with the view. Default off (Exposure alone).
   */
  vtkSetMacro(AutoExposure, bool);
  vtkGetMacro(AutoExposure, bool);
  vtkBooleanMacro(AutoExposure, bool);
  ///@}

  /** The exposure the last render used (Exposure, times the automatic scale when on). */
  vtkGetMacro(EffectiveExposure, double);

  ///@{
  /**
   * Warn when a gathered surface (Light Field Gather's output) was moved after the gather: its
   * points no longer where its light was gathered (vtkLightFieldGatherFilter's
   * GetGatheredAtName() array). Default on. ParaView's Light Field representation turns it off
   * in its mappers and says it itself (its level-of-detail mapper draws a decimated copy, whose
   * points the decimation moves).
   */
  vtkSetMacro(CheckGatheredPositions, bool);
  vtkGetMacro(CheckGatheredPositions, bool);
  vtkBooleanMacro(CheckGatheredPositions, bool);
  ///@}

  /**
   * The largest distance of a gathered surface's point from where Light Field Gather shaded it
   * (its GetGatheredAtName() array); 0 when none moved, or the surface carries no such array.
   */
  static double MovedSinceGathered(vtkPolyData* surface);

  /**
   * Warns through `reporter` when a gathered surface among `data`'s leaves moved after the
   * gather (MovedSinceGathered): what this mapper says with CheckGatheredPositions on, and what
   * ParaView's Light Field representation says for its mappers. True when it warned.
   */
  static bool WarnIfMovedSinceGathered(vtkDataObject* data, vtkObject* reporter);

  /**
   * Log-average luminance (Rec. 709 weights) of the atlas' texels with positive luminance: the
   * automatic exposure is 0.18 / this. 0 when there are none.
   */
  static double LogAverageLuminance(const float* rgba, vtkIdType texels);

  ///@{
  /** Clamp or Reinhard x / (1 + x) before the sRGB curve (default Reinhard). */
  vtkSetClampMacro(ToneMap, int, Clamp, Reinhard);
  vtkGetMacro(ToneMap, int);
  ///@}

  ///@{
  /**
   * The movable object whose shadow darkens the scene (nullptr: none): Light Field Gather's
   * output, world coordinates. Kept by reference; its modification time rebuilds the maps.
   */
  void SetShadowCaster(vtkPolyData* caster);
  vtkPolyData* GetShadowCaster();
  ///@}

  ///@{
  /** vtkLightFieldActor::ShadowModes (0 none ... 5 soft; default 3, field-derived). */
  void SetShadowMode(int mode);
  vtkGetMacro(ShadowMode, int);
  ///@}

  ///@{
  /** Texels per shadow map side, [16, 4096] (default 256). */
  void SetShadowMapResolution(int texels);
  vtkGetMacro(ShadowMapResolution, int);
  ///@}

  /** Why the last render drew no shadow although a caster was set ("" when it did). */
  const char* GetShadowProblem();

  /** Finds this render's atlas in the input, then draws the blocks. */
  void Render(vtkRenderer* ren, vtkActor* actor) override;

  void ReleaseGraphicsResources(vtkWindow* win) override;

protected:
  vtkCompositeLightFieldMapper();
  ~vtkCompositeLightFieldMapper() override;

  vtkCompositeMapperHelper2* CreateHelper() override;

  /** Uploads the current atlas when it changed; false when there is none. */
  bool PrepareAtlas(vtkRenderer* ren);
  /** Uploads the maps when they changed; false when there are none to draw. */
  bool PrepareShadowTexture(vtkRenderer* ren);
  /** A 1 x 1 texture the samplers of a gathered surface's draw point at. */
  bool PrepareBlankTexture(vtkRenderer* ren);
  vtkSmartPointer<vtkTextureObject> BlankTexture;

  bool VertexRadiance = false; // the input is a gathered surface: per-vertex Radiance
  int ShadowMode = 3;
  int ShadowMapResolution = 256;
  struct ShadowData;
  std::unique_ptr<ShadowData> Shadows;

  double Exposure = 1.0;
  bool AutoExposure = false;
  double EffectiveExposure = 1.0;
  double AtlasLogAverage = 0.0; // of KeyAtlas at KeyTime
  vtkFloatArray* KeyAtlas = nullptr;
  vtkMTimeType KeyTime = 0;
  int ToneMap = Reinhard;
  vtkSmartPointer<vtkFloatArray> CurrentAtlas;
  int CurrentAtlasSize[2] = { 0, 0 };
  vtkSmartPointer<vtkTextureObject> AtlasTexture;
  vtkFloatArray* UploadedAtlas = nullptr; // identity and time of what AtlasTexture holds
  vtkMTimeType UploadedTime = 0;
  bool WarnedNoAtlas = false;
  bool CheckGatheredPositions = true;
  vtkMTimeType MovedCheckTime = 0; // the input's time when it was last checked for a move

  friend class vtkCompositeLightFieldMapperHelper;

private:
  vtkCompositeLightFieldMapper(const vtkCompositeLightFieldMapper&) = delete;
  void operator=(const vtkCompositeLightFieldMapper&) = delete;
};

#endif
