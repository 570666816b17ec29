// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldReliefMapper
 * @brief   a vtkReliefMapper for a relief on a wall of a light field walkthrough, darkened by the
 *          walkthrough's movable object's shadow as the flat walls are
 *
 * Private to Mesolight::LightFieldActor (header not installed): vtkLightFieldReliefActor draws a
 * static surface's relief with it, and code built in this tree a relief-mapped movable object
 * (`mesolight vlf view --object-relief`). The relief of a static surface of the field's scene
 * (vtkLightFieldReliefSurface's outputs) is drawn by vtkReliefMapper; the movable object's shadow
 * (Wither 2005, "Interactive dynamic objects in a virtual light field", ch. 4;
 * mesolight::vlf::ObjectShadows) is drawn by the light field actor's own mapper on its surfaces
 * only. This mapper follows the actor given by SetLightFieldActor: while the actor draws the
 * object's shadow (a radiance mode, an object casting shadows), the relief's linear radiance at its
 * hit point is shaded by the same shader code (glsl/vtkLightFieldShadowFS.glsl through
 * vtkReliefMapper's radiance hook, glsl/vtkLightFieldReliefShadowFS.glsl), the same maps and mode,
 * at the wall's macro normal; otherwise the shadow code is left out of the shader (a software
 * rasteriser would pay for it on every fragment) and it draws as vtkReliefMapper does. Not for a
 * relief on the movable object itself (it would shadow itself with its own maps).
 */
#ifndef vtkLightFieldReliefMapper_h
#define vtkLightFieldReliefMapper_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkReliefMapper.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkWeakPointer.h"  // For vtkWeakPointer

#include <map> // For the shaders' variants

class vtkLightFieldActor;
class vtkTextureObject;

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldReliefMapper : public vtkReliefMapper
{
public:
  static vtkLightFieldReliefMapper* New();
  vtkTypeMacro(vtkLightFieldReliefMapper, vtkReliefMapper);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The walkthrough whose object's shadow falls on the relief (not held; null: none). */
  void SetLightFieldActor(vtkLightFieldActor* actor);
  vtkLightFieldActor* GetLightFieldActor();
  ///@}

  /** Whether the last frame drew the object's shadow on the relief. */
  vtkGetMacro(Shadowing, bool);

  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkLightFieldReliefMapper();
  ~vtkLightFieldReliefMapper() override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* actor) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* actor) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  // The actor's maps uploaded for this frame (false: no shadow to draw).
  bool UploadShadows(vtkRenderer* ren);

  vtkWeakPointer<vtkLightFieldActor> LightFieldActor;
  vtkSmartPointer<vtkTextureObject> ShadowTexture;
  unsigned long ShadowVersion = 0;
  bool Shadowing = false;
  bool ShadowActive = false; // the texture is bound for this draw
  std::map<const void*, bool> BuiltWithShadows;

private:
  vtkLightFieldReliefMapper(const vtkLightFieldReliefMapper&) = delete;
  void operator=(const vtkLightFieldReliefMapper&) = delete;
};

#endif
