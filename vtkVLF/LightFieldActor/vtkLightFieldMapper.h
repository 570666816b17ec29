// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldMapper
 * @brief   draws a vtkLightFieldActor's scene: VTK shading, or the field's radiance in GLSL
 *
 * The mapper vtkLightFieldActor creates for itself. Geometry mode (or any actor that is not a
 * vtkLightFieldActor) is plain vtkOpenGLPolyDataMapper drawing with the scene's Kd colours. The
 * radiance modes replace VTK's lighting by glsl/vtkLightFieldFS.glsl: the texture atlas of total
 * diffuse radiance (uploaded once per field, bilinear) at the per-vertex atlas coordinates, and
 * the actor's screen-space image (uploaded per frame, only the rectangle it covers) at
 * gl_FragCoord, composited by alpha on mirror fragments, then exposure and tone mapping.
 */
#ifndef vtkLightFieldMapper_h
#define vtkLightFieldMapper_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <functional> // For std::function
#include <map>        // For std::map

namespace mesolight
{
namespace vlf
{
struct ShadowGpuData;
}
}

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkLightFieldMapper* New();
  vtkTypeMacro(vtkLightFieldMapper, vtkOpenGLPolyDataMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Name of the point array holding atlas texture coordinates (vertex attribute mlAtlasTC). */
  static const char* GetAtlasCoordinatesName() { return "mlAtlasTC"; }

  void ReleaseGraphicsResources(vtkWindow* window) override;

  ///@{
  /**
   * The radiance shading written once for this mapper and vtkCompositeLightFieldMapper's helper:
   * the shader edits around the superclass' own (`superclass` fills VTK's tags; VTK's lighting
   * gives way to the field's radiance; vertexRadiance: the per-vertex attribute mlVertexRadiance
   * instead of the atlas, for surfaces shaded by Light Field Gather), and the uniforms of one
   * draw.
   */
  static void ReplaceRadianceShaderValues(std::map<vtkShader::Type, vtkShader*>& shaders,
    const std::function<void()>& superclass, bool vertexRadiance = false);
  struct RadianceUniforms
  {
    int AtlasUnit = 0;
    int ScreenUnit = 0;
    int ScreenOrigin[2] = { 0, 0 };
    int ScreenSize[2] = { 0, 0 }; // 0 x 0: no screen-space values
    float Exposure = 1.0f;
    int ToneMap = 0;
    bool AllScreen = false;
    bool Overwrite = false;
  };
  static void SetRadianceUniforms(vtkShaderProgram* program, const RadianceUniforms& uniforms);
  /** Uploads an RGBA float atlas (creating the texture if needed); false if the upload failed. */
  static bool UploadAtlasTexture(vtkSmartPointer<vtkTextureObject>& texture,
    vtkOpenGLRenderWindow* window, int width, int height, const float* rgba);
  /**
   * The movable object's shadow maps (glsl/vtkLightFieldShadowFS.glsl), written once for this
   * mapper and vtkCompositeLightFieldMapper: uploads the maps' depth tiles (creating the texture
   * if needed; false if the upload failed), and sets the shadow uniforms of one draw (gpu null:
   * no shadows; textureUnit then any unit holding a 2D texture, e.g. the atlas').
   */
  static bool UploadShadowTexture(vtkSmartPointer<vtkTextureObject>& texture,
    vtkOpenGLRenderWindow* window, const mesolight::vlf::ShadowGpuData& gpu);
  static void SetShadowUniforms(
    vtkShaderProgram* program, const mesolight::vlf::ShadowGpuData* gpu, int textureUnit);
  ///@}

protected:
  vtkLightFieldMapper();
  ~vtkLightFieldMapper() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

private:
  vtkLightFieldMapper(const vtkLightFieldMapper&) = delete;
  void operator=(const vtkLightFieldMapper&) = delete;

  bool UploadAtlas(vtkRenderer* ren, vtkActor* act);

  ///@{
  /** Shadows of the movable object (vtkLightFieldActor::SetShadowMode): the maps' texture,
   * uploaded when the actor rebuilds them, and their uniforms (mode 0 when there are none). */
  bool UploadShadows(vtkRenderer* ren, vtkActor* act);
  void SetShadowUniforms(vtkShaderProgram* program, vtkActor* act);
  vtkSmartPointer<vtkTextureObject> ShadowTexture;
  unsigned long ShadowVersion = 0;
  bool Shadowing = false; // this draw reads ShadowTexture
  ///@}
  bool UploadScreen(vtkRenderer* ren, vtkActor* act);

  bool Radiance = false;                     // this draw replaces VTK's lighting
  std::map<const void*, bool> BuiltRadiance; // per cellBO: the variant its shader was built for
  vtkSmartPointer<vtkTextureObject> AtlasTexture;
  vtkSmartPointer<vtkTextureObject> ScreenTexture;
  unsigned long AtlasVersion = 0;
  bool AtlasFlipped = false;
  int ScreenOrigin[2] = { 0, 0 };
  int ScreenSize[2] = { 0, 0 };
  bool AllScreen = false;
  bool Overwrite = false;
  float Exposure = 1.0f;
  int ToneMap = 0;
};

#endif
