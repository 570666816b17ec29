/**
 * @class   vtkReliefMapper
 * @brief   Renders a coarse mesh as if it carried a fine height field, by ray marching a
 *          relief texture per fragment in tangent space.
 *
 * The relief texture (see vtkReliefTextureFilter) stores the tangent-space normal in RGB and the
 * depth in A (0 = the mesh surface, 1 = deepest), as in the relief thesis (seed 000, §4). For each
 * fragment the mapper casts the view ray into the height field below the mesh, finds its first
 * intersection (linear search then a refinement step), and shades the hit point with every light
 * of the renderer, using the actor's vtkProperty (ambient, diffuse, specular, specular power) and
 * the actor's colour texture sampled at the displaced texture coordinate. Optionally it
 *  - marches toward each light for hard self-shadows (the same march, seed 000 §4.3),
 *  - discards fragments whose hit leaves the texture domain (silhouettes),
 *  - writes gl_FragDepth from the hit point so other geometry intersects the relief correctly.
 *
 * Methods (one march skeleton, method-specific refinement):
 *  - Relief: linear search + binary search (Policarpo et al. 2005; the thesis uses 10 + 8).
 *  - ParallaxOcclusion: linear search + one secant step between the last two samples (Tatarchuk 2006).
 *  - SteepParallax: linear search only (McGuire & McGuire 2005).
 *  - TextureMapping: no march (plain texture and normal mapping); useful as a baseline.
 *
 * Geometry: any triangulated vtkPolyData with point texture coordinates. Point normals and
 * tangents are generated (vtkPolyDataNormals, vtkPolyDataTangents) when the input lacks them.
 * The world size of a texture unit and the tangent-frame handedness are taken per fragment from
 * screen-space derivatives, so non-uniform parameterizations march at the right scale.
 *
 * Units: DepthScale is dimensionless: the world depth of depth = 1 divided by the world length of
 * one unit of u (the texture's width on the mesh). The same convention is used when baking the
 * normals; if the relief texture carries a different "MesolightDepthScale" field value, the mapper
 * rescales its normals so shading stays consistent with the marched geometry.
 *
 * The relief texture comes either as data (SetReliefTextureData), from a pipeline
 * (SetReliefTextureConnection, input port 1), or attached to the input polydata as field data
 * (vtkAttachReliefTexture); likewise the light set (input port 2).
 *
 * The relief work (settings, textures, shader edits, uniforms) is done by a vtkReliefShading
 * (GetShading()) that vtkCompositeReliefMapper shares; the setters here forward to it.
 */

#ifndef vtkReliefMapper_h
#define vtkReliefMapper_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkNew.h"            // for Shading
#include "vtkPolyData.h"       // for GetPreparedInput
#include "vtkReliefShading.h"  // for the forwarded settings
#include "vtkSmartPointer.h"   // for members

class vtkAlgorithmOutput;
class vtkImageData;

class MESOLIGHTRELIEF_EXPORT vtkReliefMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkReliefMapper* New();
  vtkTypeMacro(vtkReliefMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Height-field intersection methods (seed 000, §4), all sharing one march skeleton.
   * Non-iterative: TextureMapping (no displacement), Bump (normals only), Parallax,
   * ParallaxOffsetLimiting, ParallaxSlope. Unsafe iterative: IterativeParallax, BinarySearch,
   * Secant. Safe iterative: LinearSearch (steep parallax), ParallaxOcclusion (linear + one secant
   * step), Relief (linear + binary), Interval (linear + interval steps, seed eq. 3).
   * Empty-space skipping: RelaxedConeBinary and RelaxedConeInterval need a relaxed cone map,
   * ConservativeCone a conservative one (vtkConeMapFilter output as the relief texture);
   * MaximumMipmap traces exactly through a min-depth pyramid the mapper builds itself.
   */
  enum MethodType
  {
    TextureMapping = vtkReliefShading::TextureMapping,
    Bump = vtkReliefShading::Bump,
    Parallax = vtkReliefShading::Parallax,
    ParallaxOffsetLimiting = vtkReliefShading::ParallaxOffsetLimiting,
    ParallaxSlope = vtkReliefShading::ParallaxSlope,
    IterativeParallax = vtkReliefShading::IterativeParallax,
    BinarySearch = vtkReliefShading::BinarySearch,
    Secant = vtkReliefShading::Secant,
    LinearSearch = vtkReliefShading::LinearSearch,
    ParallaxOcclusion = vtkReliefShading::ParallaxOcclusion,
    Relief = vtkReliefShading::Relief,
    Interval = vtkReliefShading::Interval,
    RelaxedConeBinary = vtkReliefShading::RelaxedConeBinary,
    RelaxedConeInterval = vtkReliefShading::RelaxedConeInterval,
    ConservativeCone = vtkReliefShading::ConservativeCone,
    MaximumMipmap = vtkReliefShading::MaximumMipmap,
    NumberOfMethods = vtkReliefShading::NumberOfMethods
  };

  enum ConeMapKind
  {
    NoConeMap = vtkReliefShading::NoConeMap,
    RelaxedConeMap = vtkReliefShading::RelaxedConeMap,
    ConservativeConeMap = vtkReliefShading::ConservativeConeMap
  };

  ///@{
  /**
   * Height-field intersection method. Default: Relief.
   */
  void SetMethod(int value) { this->Shading->SetMethod(value); }
  int GetMethod() { return this->Shading->GetMethod(); }
  void SetMethodToTextureMapping() { this->SetMethod(TextureMapping); }
  void SetMethodToSteepParallax() { this->SetMethod(LinearSearch); }
  void SetMethodToParallaxOcclusion() { this->SetMethod(ParallaxOcclusion); }
  void SetMethodToRelief() { this->SetMethod(Relief); }
  /** Short names used on the command line: "texture", "bump", "parallax", "parallax-limit",
   * "parallax-slope", "iterative-parallax", "binary", "secant", "linear" (also "steep"), "pom",
   * "relief", "interval", "relaxed-cone", "relaxed-cone-interval", "cone", "max-mipmap". */
  static const char* GetMethodName(int method) { return vtkReliefShading::GetMethodName(method); }
  /** Set the method from its name; false if unknown. */
  bool SetMethodByName(const char* name);
  /** The cone map a method needs in the relief texture (ConeMapKind). */
  static int GetRequiredConeMap(int method) { return vtkReliefShading::GetRequiredConeMap(method); }
  ///@}

  ///@{
  /**
   * Number of linear-search steps from the surface to depth 1 (default 10) and of refinement
   * steps (binary search; default 8). Clamped to [1, 1024] and [0, 64]. For iterative parallax
   * LinearSteps counts iterations, for cone stepping cone steps, and for MaximumMipmap it is
   * the iteration budget of the traversal (give it 64 or more).
   */
  void SetLinearSteps(int value) { this->Shading->SetLinearSteps(value); }
  int GetLinearSteps() { return this->Shading->GetLinearSteps(); }
  void SetRefinementSteps(int value) { this->Shading->SetRefinementSteps(value); }
  int GetRefinementSteps() { return this->Shading->GetRefinementSteps(); }
  ///@}

  ///@{
  /**
   * View-angle adaptive step counts (Tatarchuk 2006): LinearSteps at grazing angles down to
   * MinimumSteps head-on. Default off.
   */
  void SetAdaptiveSteps(bool value) { this->Shading->SetAdaptiveSteps(value); }
  bool GetAdaptiveSteps() { return this->Shading->GetAdaptiveSteps(); }
  void AdaptiveStepsOn() { this->SetAdaptiveSteps(true); }
  void AdaptiveStepsOff() { this->SetAdaptiveSteps(false); }
  void SetMinimumSteps(int value) { this->Shading->SetMinimumSteps(value); }
  int GetMinimumSteps() { return this->Shading->GetMinimumSteps(); }
  ///@}

  ///@{
  /**
   * Sample the height field at the pixel footprint's mipmap level (the relief texture gets
   * mipmaps), so distant relief is filtered rather than aliased. Cone ratios are always read at
   * the base level. Default off.
   */
  void SetLevelOfDetail(bool value) { this->Shading->SetLevelOfDetail(value); }
  bool GetLevelOfDetail() { return this->Shading->GetLevelOfDetail(); }
  void LevelOfDetailOn() { this->SetLevelOfDetail(true); }
  void LevelOfDetailOff() { this->SetLevelOfDetail(false); }
  ///@}

  ///@{
  /**
   * Depth of depth = 1 relative to the world width of the texture (dimensionless, default 0.05).
   * 0 renders a flat (normal-mapped) surface. Clamped to [0, 10]; NaN is refused with an error.
   */
  void SetDepthScale(double depthScale)
  {
    this->Shading->SetDepthScale(depthScale);
  }
  double GetDepthScale() { return this->Shading->GetDepthScale(); }
  ///@}

  ///@{
  /** Hard self-shadowing toward each light by marching the height field. Default on. */
  void SetSelfShadowing(bool value) { this->Shading->SetSelfShadowing(value); }
  bool GetSelfShadowing() { return this->Shading->GetSelfShadowing(); }
  void SelfShadowingOn() { this->SetSelfShadowing(true); }
  void SelfShadowingOff() { this->SetSelfShadowing(false); }
  ///@}

  ///@{
  /** Discard fragments whose hit point leaves the [0,1]^2 texture domain. Default on. */
  void SetSilhouettes(bool value) { this->Shading->SetSilhouettes(value); }
  bool GetSilhouettes() { return this->Shading->GetSilhouettes(); }
  void SilhouettesOn() { this->SetSilhouettes(true); }
  void SilhouettesOff() { this->SetSilhouettes(false); }
  ///@}

  ///@{
  /** Write gl_FragDepth from the hit point instead of the mesh surface. Default on. */
  void SetWriteDepth(bool value) { this->Shading->SetWriteDepth(value); }
  bool GetWriteDepth() { return this->Shading->GetWriteDepth(); }
  void WriteDepthOn() { this->SetWriteDepth(true); }
  void WriteDepthOff() { this->SetWriteDepth(false); }
  ///@}

  ///@{
  /** Repeat the relief texture outside [0,1] (tiling) instead of clamping. Default off. */
  void SetRepeatTexture(bool value) { this->Shading->SetRepeatTexture(value); }
  bool GetRepeatTexture() { return this->Shading->GetRepeatTexture(); }
  void RepeatTextureOn() { this->SetRepeatTexture(true); }
  void RepeatTextureOff() { this->SetRepeatTexture(false); }
  ///@}

  enum OutputType
  {
    ShadedOutput = vtkReliefShading::ShadedOutput, ///< the lit surface (default)
    HitUOutput = vtkReliefShading::HitUOutput, ///< hit u as 24-bit fixed point in RGB
    HitVOutput = vtkReliefShading::HitVOutput, ///< hit v, likewise
    /// white where the first light reaches the hit point, else black
    LightVisibilityOutput = vtkReliefShading::LightVisibilityOutput,
    /// red where a NaN or Inf arose on the way to the colour, else green
    NonFiniteCheckOutput = vtkReliefShading::NonFiniteCheckOutput,
    /// relief-texture samples the fragment took, as a 16-bit count in R (high) and G (low)
    /// bytes: the march's cost, independent of the machine (mesolight::DecodeSampleCount)
    SampleCountOutput = vtkReliefShading::SampleCountOutput,
    NumberOfOutputs = vtkReliefShading::NumberOfOutputs
  };

  ///@{
  /**
   * What the fragments show: the shaded surface, or measurement outputs that tests and
   * benchmarks compare with exact CPU references (see mesolight::DecodeHitCoordinate).
   */
  void SetOutput(int value) { this->Shading->SetOutput(value); }
  int GetOutput() { return this->Shading->GetOutput(); }
  ///@}

  ///@{
  /**
   * The relief texture: float or unsigned char RGBA image, normal packed in RGB as (n+1)/2,
   * depth in A. Either as data or as a pipeline connection (input port 1).
   */
  void SetReliefTextureData(vtkImageData* image);
  void SetReliefTextureConnection(vtkAlgorithmOutput* output);
  vtkImageData* GetReliefTexture();
  ///@}

  ///@{
  /**
   * An image-based light set, lighting the surface besides the renderer's lights: an N x 2 float
   * image (vtkMedianCutLights' light texture), row 0 the unit directions toward the lights in
   * world coordinates, row 1 the irradiance each delivers at normal incidence (RGB). Each light
   * shades (Lambertian, albedo / pi) and self-shadows the height field. Input port 2.
   */
  void SetLightSetData(vtkImageData* lights);
  void SetLightSetConnection(vtkAlgorithmOutput* output);
  vtkImageData* GetLightSet();
  ///@}

  ///@{
  /** Scale of the light-set shading (default 1) and Reinhard tone mapping (default off). */
  void SetExposure(double value) { this->Shading->SetExposure(value); }
  double GetExposure() { return this->Shading->GetExposure(); }
  void SetToneMapping(bool value) { this->Shading->SetToneMapping(value); }
  bool GetToneMapping() { return this->Shading->GetToneMapping(); }
  void ToneMappingOn() { this->SetToneMapping(true); }
  void ToneMappingOff() { this->SetToneMapping(false); }
  ///@}

  ///@{
  /**
   * Skips for light sets, each measurable (mesolight bench ibl): lights whose luminance is below
   * LightSetThreshold times the strongest light's are skipped entirely (default 0: none);
   * with ShadowedLights = K > 0 only the K strongest lights facing a pixel march their shadows,
   * the rest are weighted by the visible fraction of those K (default 0: all march).
   */
  void SetLightSetThreshold(double value) { this->Shading->SetLightSetThreshold(value); }
  double GetLightSetThreshold() { return this->Shading->GetLightSetThreshold(); }
  void SetShadowedLights(int value) { this->Shading->SetShadowedLights(value); }
  int GetShadowedLights() { return this->Shading->GetShadowedLights(); }
  /**
   * Lights behind the shading normal contribute nothing and skip their shadow march (default
   * on). Off marches them anyway, only to measure what the culling saves.
   */
  void SetShadowCulling(bool value) { this->Shading->SetShadowCulling(value); }
  bool GetShadowCulling() { return this->Shading->GetShadowCulling(); }
  void ShadowCullingOn() { this->SetShadowCulling(true); }
  void ShadowCullingOff() { this->SetShadowCulling(false); }
  ///@}

  /**
   * Maximum number of VTK lights shaded per fragment; further lights are ignored with a warning.
   */
  static constexpr int MaximumNumberOfLights = vtkReliefShading::MaximumNumberOfLights;

  /** The relief work shared with vtkCompositeReliefMapper; holds every setting above. */
  vtkReliefShading* GetShading() { return this->Shading; }

  /** Includes the shading's modification time. */
  vtkMTimeType GetMTime() override;

  void ReleaseGraphicsResources(vtkWindow* win) override;

  /** The polydata actually drawn (input plus generated normals/tangents). For tests. */
  vtkPolyData* GetPreparedInput() { return this->PreparedInput; }

protected:
  vtkReliefMapper();
  ~vtkReliefMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  vtkNew<vtkReliefShading> Shading;
  vtkPolyData* PreparedInput = nullptr;
  bool ReadyToDraw = false;

private:
  vtkReliefMapper(const vtkReliefMapper&) = delete;
  void operator=(const vtkReliefMapper&) = delete;
};

#endif
