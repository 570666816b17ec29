// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldReliefShadowHook
 * @brief   darkens a relief lit by a light field by the shadow of the field's movable object, as
 *          the field's flat walls are darkened
 *
 * A vtkReliefRadianceHook (vtkReliefMapper / vtkCompositeReliefMapper::SetRadianceHook): the
 * relief's linear radiance at its hit point is shaded by the walkthrough's own shadow code
 * (glsl/vtkLightFieldShadowFS.glsl, through glsl/vtkLightFieldReliefShadowFS.glsl): the same
 * maps, mode and share of the lighting as the walls (Wither 2005, "Interactive dynamic objects in
 * a virtual light field", ch. 4; mesolight::vlf::ObjectShadows), at the displaced point the relief
 * shows and the wall's macro normal, so relief and flat wall darken alike.
 *
 * The maps come from a vtkLightFieldActor (SetLightFieldActor: while it draws the object's shadow,
 * in a radiance mode) or from a Shadow Caster given as data (SetCasterShadows: ParaView's Relief
 * Surface). Without maps the hook takes no part in the draw and the relief draws as without it.
 * The relief's actor is placed at the identity, as the field's walls are. Not for a relief on the
 * movable object itself (it would shadow itself with its own maps).
 */
#ifndef vtkLightFieldReliefShadowHook_h
#define vtkLightFieldReliefShadowHook_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkReliefRadianceHook.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkWeakPointer.h"  // For vtkWeakPointer

namespace mesolight
{
namespace vlf
{
struct ShadowGpuData;
}
}
class vtkLightFieldActor;
class vtkLightFieldCasterShadows;
class vtkTextureObject;

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldReliefShadowHook : public vtkReliefRadianceHook
{
public:
  static vtkLightFieldReliefShadowHook* New();
  vtkTypeMacro(vtkLightFieldReliefShadowHook, vtkReliefRadianceHook);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** The walkthrough whose object's shadow falls on the relief (not held; null: none). */
  void SetLightFieldActor(vtkLightFieldActor* actor);
  vtkLightFieldActor* GetLightFieldActor();
  ///@}

  ///@{
  /** Or the maps of a Shadow Caster given as data (held; null: none). The actor wins. */
  void SetCasterShadows(vtkLightFieldCasterShadows* shadows);
  vtkLightFieldCasterShadows* GetCasterShadows();
  ///@}

  /** Whether the last draw drew the object's shadow on the relief. */
  vtkGetMacro(Shadowing, bool);

  bool StartDraw(vtkOpenGLRenderWindow* window) override;
  const std::string& GetFragmentDeclarations() override;
  void SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren) override;
  void FinishDraw() override;
  void ReleaseGraphicsResources(vtkWindow* window) override;

protected:
  vtkLightFieldReliefShadowHook();
  ~vtkLightFieldReliefShadowHook() override;

  vtkWeakPointer<vtkLightFieldActor> LightFieldActor;
  vtkSmartPointer<vtkLightFieldCasterShadows> CasterShadows;
  vtkSmartPointer<vtkTextureObject> ShadowTexture;
  const void* UploadedFrom = nullptr; // the maps' owner and version the texture holds
  unsigned long UploadedVersion = 0;
  bool Shadowing = false;
  // This draw's maps and world -> unit sphere (column-major).
  const mesolight::vlf::ShadowGpuData* DrawnGpu = nullptr;
  float WorldToUnit[16] = {};

private:
  vtkLightFieldReliefShadowHook(const vtkLightFieldReliefShadowHook&) = delete;
  void operator=(const vtkLightFieldReliefShadowHook&) = delete;
};

#endif
