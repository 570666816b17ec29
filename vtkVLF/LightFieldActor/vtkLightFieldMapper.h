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
 * gl_FragCoord, composited by alpha on mirror fragments, then exposure and tone mapping. The
 * shader edits and uniforms are vtkLightFieldShading's, shared with vtkCompositeLightFieldMapper.
 */
#ifndef vtkLightFieldMapper_h
#define vtkLightFieldMapper_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <map> // For std::map

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
  // The benchmark's "before" row: the shadow code compiled in without a caster.
  bool ShadowCodeAlways = false;
  ///@}
  bool UploadScreen(vtkRenderer* ren, vtkActor* act);

  bool Radiance = false; // this draw replaces VTK's lighting
  // The shader variant: VTK's lighting (0), radiance without (1) or with (3) the shadow code.
  int Variant() const
  {
    return !this->Radiance ? 0 : (this->Shadowing || this->ShadowCodeAlways ? 3 : 1);
  }
  std::map<const void*, int> BuiltRadiance; // per cellBO: the variant its shader was built for
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
