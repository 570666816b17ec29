// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkIrradianceProbesTexture
 * @brief   A grid of SH9 radiance probes on the GPU, for relief shading by a light field.
 *
 * The probes come as vtkReliefMapper::SetIrradianceProbesData describes them: a (9 x Nu) x Nv
 * image of 3 (or more; the first 3 are read) float components, coefficient k of probe (i, j) at
 * pixel (9 i + k, j), the real SH basis of Ramamoorthi and Hanrahan ("An efficient representation
 * for irradiance environment maps") in world coordinates. They are uploaded as an Nu x (7 Nv)
 * float RGBA texture with linear filtering, seven blocks of Nv rows holding the 27 numbers of
 * every probe (blocks 0-1 red's coefficients 0-7, 2-3 green's, 4-5 blue's, 6 the three
 * coefficients 8), so one filtered fetch per block interpolates four coefficients bilinearly
 * between the four nearest probes, seven fetches per pixel (vtkReliefIrradianceProbesFS.glsl
 * clamps each fetch inside its block, which is the clamp at the grid's border). Uploads are
 * keyed by the scalar array and its
 * modification time; a malformed image is reported once per array and modification.
 *
 * Two optional parts make the relief's own occlusion and the scene's shadows cheap per pixel,
 * both computed once on the CPU (vtkLightFieldReliefSurface, for the walkthrough's reliefs and
 * ParaView's Relief Surface):
 * - a fourth component: pixel (9 i + k, j) holds the factor (in [0, MaxLightFactor]) by which
 *   the renderer's light k (k < 8) is multiplied at probe (i, j), uploaded as blocks 7-8 (lights
 *   0-3, 4-7), bilinear between probes, and multiplied into that light's contribution (1
 *   without it): the scene's shadow of the light, and the ratio of the emitters' irradiance it
 *   stands for to its own as a point light (mesolight::vlf::EmitterLightFactors);
 * - the relief's cosine-weighted visible share over its texture (ReliefVisibleShareMap in
 *   reliefcore/core/ReliefShading.h: per cell V and V over the share of directions above the
 *   macro plane; optionally a third value, the visible share Vs of the relief the occluded
 *   directions meet, ReliefSeenShareMap) as the two- or three-component field-data array
 *   GetVisibleShareName() (W x H tuples, row 0 at v ~ 0) with the field-data array
 *   GetVisibleShareSizeName() = (W, H): a second, four-channel linear texture (Vs = V for
 *   pairs). The shader scales the probes' irradiance by the second value and adds the relief's
 *   multi-bounce inter-reflection of V at Vs (ReliefInterReflected). Without it all are 1. An
 *   optional fourth value per cell is the share of the renderer's light 0 (an area emitter)
 *   that the relief's own shadow lets through (ReliefEmitterShadowMap, the area's penumbra):
 *   the shader then multiplies that light by it instead of marching one hard shadow ray.
 * - the side walls of a walled relief (ReliefWallShareMap): the field-data array
 *   GetWallShareName(), as many values per cell as the visible share, 4 x D rows of W cells
 *   (walls u = 0, u = 1, v = 0, v = 1, D rows each from the lip down; cell i at (i + 1/2) / W
 *   along the wall, row l at (l + 1/2) / D of the wall's depth there), appended to the share
 *   texture below its H rows. A view ray that meets a wall (mlSideWall) then reads the wall's
 *   own values at its depth; without it the texel row beside the border.
 */

#ifndef vtkIrradianceProbesTexture_h
#define vtkIrradianceProbesTexture_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for TextureObject

class vtkDataArray;
class vtkDataObject;
class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class MESOLIGHTRELIEF_EXPORT vtkIrradianceProbesTexture : public vtkObject
{
public:
  static vtkIrradianceProbesTexture* New();
  vtkTypeMacro(vtkIrradianceProbesTexture, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Uploads the probes unless they are already on the GPU of this window; null means no probes.
   * A malformed image (width not a multiple of 9, empty, fewer than 3 components, a non-finite
   * coefficient) or a failed upload is reported with an error and leaves no probes: the relief
   * is then drawn without them.
   */
  void Update(vtkOpenGLRenderWindow* renWin, vtkImageData* probes);

  /** Whether the last Update left probes to shade with. */
  vtkGetMacro(HasProbes, bool);

  /** The probe grid (Nu, Nv) of the last upload. */
  vtkGetVector2Macro(GridSize, int);

  /** The texture; null before the first upload. */
  vtkTextureObject* GetTextureObject();

  /** Whether the last upload had a visible-share map (else V = 1). */
  vtkGetMacro(HasVisibleShare, bool);
  /** Whether the map holds light 0's shadow by the relief (a fourth value per cell). */
  vtkGetMacro(HasLightShadow, bool);

  /** The largest light factor a probe may carry (the fourth component, see above). */
  static constexpr double MaxLightFactor = 8.0;

  /** The field-data arrays of the relief's visible share and its grid size (see above). */
  static const char* GetVisibleShareName() { return "ReliefVisibleShare"; }
  static const char* GetVisibleShareSizeName() { return "ReliefVisibleShareSize"; }
  static const char* GetWallShareName() { return "ReliefWallShare"; }

  /**
   * Puts a visible-share map into the probes' field data as Update reads it: `share` (one tuple
   * per cell, row by row) under GetVisibleShareName(), and its grid (w, h) as the two-value
   * integer array GetVisibleShareSizeName(). Every producer writes the map this way. A null
   * argument is reported with a warning and attaches nothing.
   */
  static void AttachVisibleShare(vtkDataObject* probes, vtkDataArray* share, int w, int h);

  /** The depth levels per side wall of the last upload's wall map; 0 without one. */
  vtkGetMacro(WallLevels, int);

  ///@{
  /** Binds both textures and sets the shader's uniforms (after an Update that left probes). */
  void Activate();
  void Deactivate();
  void SetUniforms(vtkShaderProgram* program);
  ///@}

  void ReleaseGraphicsResources(vtkWindow* win);

protected:
  vtkIrradianceProbesTexture();
  ~vtkIrradianceProbesTexture() override;

  static constexpr int Blocks = 9; // seven of SH9 coefficients, two of light visibility
  bool UploadVisibleShare(vtkOpenGLRenderWindow* renWin, vtkDataArray* share,
    vtkDataArray* shareSize, vtkDataArray* walls);

  vtkSmartPointer<vtkTextureObject> TextureObject;
  vtkSmartPointer<vtkTextureObject> ShareTexture;
  bool HasVisibleShare = false;
  bool HasLightShadow = false;
  int WallLevels = 0;
  int ShareRows = 1; // the share texture's rows of the texture square (below them the walls')
  vtkDataArray* Uploaded = nullptr; // not referenced: only compared
  vtkImageData* UploadedImage = nullptr;
  vtkMTimeType UploadTime = 0;
  int GridSize[2] = { 0, 0 };
  bool Valid = false;
  bool HasProbes = false;

private:
  vtkIrradianceProbesTexture(const vtkIrradianceProbesTexture&) = delete;
  void operator=(const vtkIrradianceProbesTexture&) = delete;
};

#endif
