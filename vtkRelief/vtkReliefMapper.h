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
 * The relief texture comes either as data (SetReliefTextureData) or from a pipeline
 * (SetReliefTextureConnection, input port 1).
 */

#ifndef vtkReliefMapper_h
#define vtkReliefMapper_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPolyData.h"     // for GetPreparedInput
#include "vtkSmartPointer.h" // for members

#include <map>    // for ShaderKeys
#include <string> // for ShaderKey
#include <vector> // for UpdatePyramid

class vtkAlgorithmOutput;
class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkTextureObject;

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
    TextureMapping = 0,
    Bump,
    Parallax,
    ParallaxOffsetLimiting,
    ParallaxSlope,
    IterativeParallax,
    BinarySearch,
    Secant,
    LinearSearch,
    ParallaxOcclusion,
    Relief,
    Interval,
    RelaxedConeBinary,
    RelaxedConeInterval,
    ConservativeCone,
    MaximumMipmap,
    NumberOfMethods
  };

  enum ConeMapKind
  {
    NoConeMap = 0,
    RelaxedConeMap = 1,
    ConservativeConeMap = 2
  };

  ///@{
  /**
   * Height-field intersection method. Default: Relief.
   */
  vtkSetClampMacro(Method, int, TextureMapping, NumberOfMethods - 1);
  vtkGetMacro(Method, int);
  void SetMethodToTextureMapping() { this->SetMethod(TextureMapping); }
  void SetMethodToSteepParallax() { this->SetMethod(LinearSearch); }
  void SetMethodToParallaxOcclusion() { this->SetMethod(ParallaxOcclusion); }
  void SetMethodToRelief() { this->SetMethod(Relief); }
  /** Short names used on the command line: "texture", "bump", "parallax", "parallax-limit",
   * "parallax-slope", "iterative-parallax", "binary", "secant", "linear" (also "steep"), "pom",
   * "relief", "interval", "relaxed-cone", "relaxed-cone-interval", "cone", "max-mipmap". */
  static const char* GetMethodName(int method);
  /** Set the method from its name; false if unknown. */
  bool SetMethodByName(const char* name);
  /** The cone map a method needs in the relief texture (ConeMapKind). */
  static int GetRequiredConeMap(int method);
  ///@}

  ///@{
  /**
   * Number of linear-search steps from the surface to depth 1 (default 10) and of refinement
   * steps (binary search; default 8). Clamped to [1, 1024] and [0, 64]. For iterative parallax
   * LinearSteps counts iterations, for cone stepping cone steps, and for MaximumMipmap it is
   * the iteration budget of the traversal (give it 64 or more).
   */
  vtkSetClampMacro(LinearSteps, int, 1, 1024);
  vtkGetMacro(LinearSteps, int);
  vtkSetClampMacro(RefinementSteps, int, 0, 64);
  vtkGetMacro(RefinementSteps, int);
  ///@}

  ///@{
  /**
   * View-angle adaptive step counts (Tatarchuk 2006): LinearSteps at grazing angles down to
   * MinimumSteps head-on. Default off.
   */
  vtkSetMacro(AdaptiveSteps, bool);
  vtkGetMacro(AdaptiveSteps, bool);
  vtkBooleanMacro(AdaptiveSteps, bool);
  vtkSetClampMacro(MinimumSteps, int, 1, 1024);
  vtkGetMacro(MinimumSteps, int);
  ///@}

  ///@{
  /**
   * Sample the height field at the pixel footprint's mipmap level (the relief texture gets
   * mipmaps), so distant relief is filtered rather than aliased. Cone ratios are always read at
   * the base level. Default off.
   */
  vtkSetMacro(LevelOfDetail, bool);
  vtkGetMacro(LevelOfDetail, bool);
  vtkBooleanMacro(LevelOfDetail, bool);
  ///@}

  ///@{
  /**
   * Depth of depth = 1 relative to the world width of the texture (dimensionless, default 0.05).
   * 0 renders a flat (normal-mapped) surface. Clamped to [0, 10]; NaN is refused with an error.
   */
  void SetDepthScale(double depthScale);
  vtkGetMacro(DepthScale, double);
  ///@}

  ///@{
  /** Hard self-shadowing toward each light by marching the height field. Default on. */
  vtkSetMacro(SelfShadowing, bool);
  vtkGetMacro(SelfShadowing, bool);
  vtkBooleanMacro(SelfShadowing, bool);
  ///@}

  ///@{
  /** Discard fragments whose hit point leaves the [0,1]^2 texture domain. Default on. */
  vtkSetMacro(Silhouettes, bool);
  vtkGetMacro(Silhouettes, bool);
  vtkBooleanMacro(Silhouettes, bool);
  ///@}

  ///@{
  /** Write gl_FragDepth from the hit point instead of the mesh surface. Default on. */
  vtkSetMacro(WriteDepth, bool);
  vtkGetMacro(WriteDepth, bool);
  vtkBooleanMacro(WriteDepth, bool);
  ///@}

  ///@{
  /** Repeat the relief texture outside [0,1] (tiling) instead of clamping. Default off. */
  vtkSetMacro(RepeatTexture, bool);
  vtkGetMacro(RepeatTexture, bool);
  vtkBooleanMacro(RepeatTexture, bool);
  ///@}

  enum OutputType
  {
    ShadedOutput = 0,          ///< the lit surface (default)
    HitUOutput = 1,            ///< hit u as 24-bit fixed point in RGB, for measurements
    HitVOutput = 2,            ///< hit v, likewise
    LightVisibilityOutput = 3, ///< white where the first light reaches the hit point, else black
    NonFiniteCheckOutput = 4,  ///< red where a NaN or Inf arose on the way to the colour, else green
    NumberOfOutputs
  };

  ///@{
  /**
   * What the fragments show: the shaded surface, or measurement outputs that tests and
   * benchmarks compare with exact CPU references (see mesolight::DecodeHitCoordinate).
   */
  vtkSetClampMacro(Output, int, ShadedOutput, NumberOfOutputs - 1);
  vtkGetMacro(Output, int);
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
  vtkSetClampMacro(Exposure, double, 0.0, 1e6);
  vtkGetMacro(Exposure, double);
  vtkSetMacro(ToneMapping, bool);
  vtkGetMacro(ToneMapping, bool);
  vtkBooleanMacro(ToneMapping, bool);
  ///@}

  ///@{
  /**
   * Skips for light sets, each measurable (mesolight bench ibl): lights whose luminance is below
   * LightSetThreshold times the strongest light's are skipped entirely (default 0: none);
   * with ShadowedLights = K > 0 only the K strongest lights facing a pixel march their shadows,
   * the rest are weighted by the visible fraction of those K (default 0: all march).
   */
  vtkSetClampMacro(LightSetThreshold, double, 0.0, 1.0);
  vtkGetMacro(LightSetThreshold, double);
  vtkSetClampMacro(ShadowedLights, int, 0, 1 << 16);
  vtkGetMacro(ShadowedLights, int);
  /**
   * Lights behind the shading normal contribute nothing and skip their shadow march (default
   * on). Off marches them anyway, only to measure what the culling saves.
   */
  vtkSetMacro(ShadowCulling, bool);
  vtkGetMacro(ShadowCulling, bool);
  vtkBooleanMacro(ShadowCulling, bool);
  ///@}

  /**
   * Maximum number of VTK lights shaded per fragment; further lights are ignored with a warning.
   */
  static constexpr int MaximumNumberOfLights = 8;

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

  /** Adds normals/tangents when missing; null (with an error) if the input cannot be used. */
  vtkPolyData* PrepareInput(vtkPolyData* input);
  /** Uploads the relief texture when it changed; false (with an error) if unusable. */
  bool UpdateReliefTexture(vtkRenderer* ren);
  void SetLightUniforms(vtkShaderProgram* program, vtkRenderer* ren);
  /** Options compiled into the shader; a change rebuilds it. */
  std::string ShaderKey() const;

  int Method = Relief;
  int LinearSteps = 10;
  int RefinementSteps = 8;
  double DepthScale = 0.05;
  bool SelfShadowing = true;
  bool Silhouettes = true;
  bool WriteDepth = true;
  bool RepeatTexture = false;
  int Output = ShadedOutput;
  bool AdaptiveSteps = false;
  int MinimumSteps = 4;
  bool LevelOfDetail = false;
  bool ConePacked = false; // the relief texture carries cone ratios in B (vtkConeMapFilter)
  int ConeType = NoConeMap;
  bool UploadedWithMipmaps = false;
  vtkSmartPointer<vtkTextureObject> PyramidTextureObject;
  int PyramidLevels = 0;
  std::vector<int> PyramidSizes; // cells per level, (w, h) pairs
  bool UpdatePyramid(vtkOpenGLRenderWindow* renWin, const std::vector<float>& depth);
  /** Uploads the light set when it changed; false (with an error) if unusable. */
  bool UpdateLightSet(vtkOpenGLRenderWindow* renWin);
  double Exposure = 1.0;
  bool ToneMapping = false;
  double LightSetThreshold = 0.0;
  int ShadowedLights = 0;
  bool ShadowCulling = true;
  vtkSmartPointer<vtkTextureObject> LightSetTextureObject;
  vtkImageData* LightSetUploaded = nullptr;
  vtkMTimeType LightSetUploadTime = 0;
  int LightSetCount = 0;
  float LightSetMaximum = 0.0f; // luminance of the strongest light
  bool HasLightSet = false;

  vtkSmartPointer<vtkImageData> ReliefTextureData;
  vtkSmartPointer<vtkPolyData> PreparedInput;
  vtkMTimeType PreparedInputSourceTime = 0;
  vtkPolyData* PreparedInputSource = nullptr;

  vtkSmartPointer<vtkTextureObject> ReliefTextureObject;
  vtkMTimeType ReliefTextureUploadTime = 0;
  vtkImageData* ReliefTextureUploaded = nullptr;
  int ReliefTextureSize[2] = { 0, 0 };
  double BakedDepthScale = 0.0; // 0 = unknown: normals taken as consistent with DepthScale
  bool ReliefTextureReady = false;
  bool WarnedTooManyLights = false;
  bool HasAlbedoTexture = false;
  bool ReadyToDraw = false;
  std::map<const vtkOpenGLHelper*, std::string> ShaderKeys;

private:
  vtkReliefMapper(const vtkReliefMapper&) = delete;
  void operator=(const vtkReliefMapper&) = delete;
};

#endif
