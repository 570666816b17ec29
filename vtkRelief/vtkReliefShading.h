/**
 * @class   vtkReliefShading
 * @brief   The relief rendering shared by vtkReliefMapper and vtkCompositeReliefMapper: the
 *          settings, the GPU textures (relief texture, min-depth pyramid, light set), the
 *          prepared geometry, the shader source edits and the uniforms.
 *
 * A relief surface is drawn by a vtkOpenGLPolyDataMapper whose shaders are edited in two steps
 * around the superclass' own edits (ReplaceShaderValues), with extra textures bound around the
 * draw (RenderPieceStart/Finish) and extra uniforms set per draw (SetMapperShaderParameters).
 * vtkReliefMapper is such a mapper; vtkCompositeReliefMapper's helper (a
 * vtkCompositeMapperHelper2, how ParaView's geometry representations draw) is another. Both
 * delegate every relief-specific step to one vtkReliefShading, so the two draw the same pixels.
 * See vtkReliefMapper for what the settings mean.
 */

#ifndef vtkReliefShading_h
#define vtkReliefShading_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for members

#include <map>    // for ShaderKeys, Prepared
#include <string> // for ShaderKey
#include <vector> // for PyramidSizes

class vtkActor;
class vtkDataArray;
class vtkImageData;
class vtkOpenGLRenderWindow;
class vtkPolyData;
class vtkRenderer;
class vtkShaderProgram;
class vtkTextureObject;
class vtkWindow;

class MESOLIGHTRELIEF_EXPORT vtkReliefShading : public vtkObject
{
public:
  static vtkReliefShading* New();
  vtkTypeMacro(vtkReliefShading, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Height-field intersection methods; see vtkReliefMapper. */
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

  enum OutputType
  {
    ShadedOutput = 0,
    HitUOutput = 1,
    HitVOutput = 2,
    LightVisibilityOutput = 3,
    NonFiniteCheckOutput = 4,
    SampleCountOutput = 5,
    NumberOfOutputs
  };

  /** Maximum number of VTK lights shaded per fragment. */
  static constexpr int MaximumNumberOfLights = 8;

  ///@{
  /** Settings; documented in vtkReliefMapper. */
  vtkSetClampMacro(Method, int, TextureMapping, NumberOfMethods - 1);
  vtkGetMacro(Method, int);
  static const char* GetMethodName(int method);
  bool SetMethodByName(const char* name);
  static int GetRequiredConeMap(int method);
  vtkSetClampMacro(LinearSteps, int, 1, 1024);
  vtkGetMacro(LinearSteps, int);
  vtkSetClampMacro(RefinementSteps, int, 0, 64);
  vtkGetMacro(RefinementSteps, int);
  vtkSetMacro(AdaptiveSteps, bool);
  vtkGetMacro(AdaptiveSteps, bool);
  vtkBooleanMacro(AdaptiveSteps, bool);
  vtkSetClampMacro(MinimumSteps, int, 1, 1024);
  vtkGetMacro(MinimumSteps, int);
  vtkSetMacro(LevelOfDetail, bool);
  vtkGetMacro(LevelOfDetail, bool);
  vtkBooleanMacro(LevelOfDetail, bool);
  void SetDepthScale(double depthScale);
  vtkGetMacro(DepthScale, double);
  vtkSetMacro(SelfShadowing, bool);
  vtkGetMacro(SelfShadowing, bool);
  vtkBooleanMacro(SelfShadowing, bool);
  vtkSetMacro(Silhouettes, bool);
  vtkGetMacro(Silhouettes, bool);
  vtkBooleanMacro(Silhouettes, bool);
  vtkSetMacro(WriteDepth, bool);
  vtkGetMacro(WriteDepth, bool);
  vtkBooleanMacro(WriteDepth, bool);
  vtkSetMacro(RepeatTexture, bool);
  vtkGetMacro(RepeatTexture, bool);
  vtkBooleanMacro(RepeatTexture, bool);
  vtkSetClampMacro(Output, int, ShadedOutput, NumberOfOutputs - 1);
  vtkGetMacro(Output, int);
  vtkSetClampMacro(Exposure, double, 0.0, 1e6);
  vtkGetMacro(Exposure, double);
  vtkSetMacro(ToneMapping, bool);
  vtkGetMacro(ToneMapping, bool);
  vtkBooleanMacro(ToneMapping, bool);
  vtkSetClampMacro(LightSetThreshold, double, 0.0, 1.0);
  vtkGetMacro(LightSetThreshold, double);
  vtkSetClampMacro(ShadowedLights, int, 0, 1 << 16);
  vtkGetMacro(ShadowedLights, int);
  vtkSetMacro(ShadowCulling, bool);
  vtkGetMacro(ShadowCulling, bool);
  vtkBooleanMacro(ShadowCulling, bool);
  ///@}

  /**
   * The geometry the relief shader needs: triangles, point normals, float point tangents and
   * the texture coordinates copied to the attribute the shader reads (VTK uploads "tcoord" only
   * when the actor has a texture). Cached per input polydata; null (with an error) if the input
   * cannot carry a relief (no texture coordinates, no polygons, non-finite coordinates).
   */
  vtkPolyData* PrepareInput(vtkPolyData* input);
  /** Forget prepared copies of inputs other than these (composite inputs change). */
  void KeepPreparedInputs(const std::vector<vtkPolyData*>& inputs);
  /** Name of the float texture-coordinate array PrepareInput adds (vertex attribute mlTCoordMC). */
  static const char* GetReliefTCoordsName();

  /**
   * Uploads the relief texture and the light set (null: none) when they changed, and activates
   * the textures for a draw with this actor. False (with an error) if nothing can be drawn.
   */
  bool StartDraw(vtkOpenGLRenderWindow* renWin, vtkImageData* relief, vtkImageData* lights,
    vtkActor* actor);
  /** Deactivates what StartDraw activated. */
  void FinishDraw();

  /** Whether shaders built with the key recorded for this helper (cellBO) are out of date. */
  bool ShaderKeyChanged(const void* cellBO) const;
  /**
   * The shader edits before the mapper's superclass fills VTK's tags: tangents and relief
   * texture coordinates in the vertex shader, our placeholders in the fragment shader.
   * noVTKLights: the mapper shades without VTK lights (light complexity 0), so VTK declares no
   * normal and no view-space position; they are declared here.
   */
  void ReplaceShaderValuesBefore(std::string& vs, std::string& fs, bool noVTKLights);
  /** The shader edits after the superclass: the relief implementation. */
  void ReplaceShaderValuesAfter(std::string& fs, const void* cellBO);
  /** Uniforms of one draw (textures, settings, camera, tangent frame, VTK lights). */
  void SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* actor);

  void ReleaseGraphicsResources(vtkWindow* win);

  /**
   * Errors and warnings of this shading reach observers of the owner (the mapper), so users
   * watch the mapper as before; without such observers they are displayed as usual.
   */
  void SetMessageOwner(vtkObject* owner);

protected:
  vtkReliefShading();
  ~vtkReliefShading() override;

  bool UpdateReliefTexture(vtkOpenGLRenderWindow* renWin, vtkImageData* image);
  bool UpdatePyramid(vtkOpenGLRenderWindow* renWin, const std::vector<float>& depth);
  bool UpdateLightSet(vtkOpenGLRenderWindow* renWin, vtkImageData* lights);
  void SetLightUniforms(vtkShaderProgram* program, vtkRenderer* ren);
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
  double Exposure = 1.0;
  bool ToneMapping = false;
  double LightSetThreshold = 0.0;
  int ShadowedLights = 0;
  bool ShadowCulling = true;

  // Relief texture on the GPU; uploads are keyed by the scalar array and its modification time
  // (images rebuilt from field data wrap the same array).
  bool ConePacked = false; // the relief texture carries cone ratios in B (vtkConeMapFilter)
  int ConeType = NoConeMap;
  bool UploadedWithMipmaps = false;
  vtkSmartPointer<vtkTextureObject> ReliefTextureObject;
  vtkDataArray* ReliefTextureUploaded = nullptr;
  vtkMTimeType ReliefTextureUploadTime = 0;
  int ReliefTextureSize[2] = { 0, 0 };
  double BakedDepthScale = 0.0; // < 0 = unknown: normals taken as consistent with DepthScale
  bool ReliefTextureReady = false;
  vtkSmartPointer<vtkTextureObject> PyramidTextureObject;
  int PyramidLevels = 0;
  std::vector<int> PyramidSizes; // cells per level, (w, h) pairs

  // Light set on the GPU.
  vtkSmartPointer<vtkTextureObject> LightSetTextureObject;
  vtkDataArray* LightSetUploaded = nullptr;
  vtkMTimeType LightSetUploadTime = 0;
  int LightSetCount = 0;
  float LightSetMaximum = 0.0f; // luminance of the strongest light
  bool HasLightSet = false;

  struct PreparedGeometry
  {
    vtkMTimeType SourceTime = 0;
    vtkSmartPointer<vtkPolyData> Prepared;
  };
  std::map<vtkPolyData*, PreparedGeometry> Prepared;

  bool WarnedTooManyLights = false;
  bool HasAlbedoTexture = false;
  bool Drawing = false;
  std::map<const void*, std::string> ShaderKeys;
  vtkObject* MessageOwner = nullptr; // not referenced: the owner holds this shading
  static void ForwardMessage(vtkObject*, unsigned long event, void* self, void* text);

private:
  vtkReliefShading(const vtkReliefShading&) = delete;
  void operator=(const vtkReliefShading&) = delete;
};

#endif
