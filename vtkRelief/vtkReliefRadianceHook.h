// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefRadianceHook
 * @brief   code another module adds to a relief's shading: a change of the linear radiance at the
 *          relief's hit point, before exposure and tone mapping
 *
 * The one extension point of the relief shader (glsl/vtkReliefImplFS.glsl, ML_RADIANCE_HOOK):
 * a subclass supplies GLSL that defines ML_RADIANCE_HOOK and
 *
 *     vec3 mlRadianceHook(vec3 radiance, vec3 pointVC, vec3 normalVC, vec3 kd)
 *
 * (the relief's linear radiance at its displaced hit point in view coordinates, the surface's
 * macro normal, the albedo), and binds what that code reads around each draw. vtkReliefMapper
 * and vtkCompositeReliefMapper call it the same way (SetRadianceHook): e.g. the shadow a light
 * field's movable object casts on a relief (Mesolight::LightFieldActor's
 * vtkLightFieldReliefShadowHook). A draw whose StartDraw returns false leaves the hook's code out
 * of the shader (a software rasteriser would pay for it on every fragment).
 */
#ifndef vtkReliefRadianceHook_h
#define vtkReliefRadianceHook_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"

#include <string> // for GetFragmentDeclarations

class vtkOpenGLRenderWindow;
class vtkRenderer;
class vtkShaderProgram;
class vtkWindow;

class MESOLIGHTRELIEF_EXPORT vtkReliefRadianceHook : public vtkObject
{
public:
  vtkTypeMacro(vtkReliefRadianceHook, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /**
   * Before a draw: brings what the hook's code reads up to date and binds it. False: nothing to
   * do in this draw (the code is left out of the shader, nothing is bound).
   */
  virtual bool StartDraw(vtkOpenGLRenderWindow* window) = 0;

  /**
   * The GLSL declarations of a draw StartDraw accepted, inserted after the relief's own
   * declarations; a change of this text rebuilds the shader. Asked on every draw: a reference to
   * text the hook keeps, not built anew each time.
   */
  virtual const std::string& GetFragmentDeclarations() = 0;

  /** The hook's uniforms for one draw. */
  virtual void SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren) = 0;

  /** After a draw StartDraw accepted: unbinds what it bound. */
  virtual void FinishDraw() = 0;

  /** Frees the hook's GPU resources for the window. */
  virtual void ReleaseGraphicsResources(vtkWindow* window);

protected:
  vtkReliefRadianceHook();
  ~vtkReliefRadianceHook() override;

private:
  vtkReliefRadianceHook(const vtkReliefRadianceHook&) = delete;
  void operator=(const vtkReliefRadianceHook&) = delete;
};

#endif
