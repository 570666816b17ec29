// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSMReliefSurfaceRepresentationProxy
 * @brief   The server-manager (client-side) proxy of the Relief Surface representation: what the
 *          GUI needs from it that proxy XML cannot say, without Qt.
 *
 * After every update of a view showing it (ViewUpdated):
 * - LightSetAttached becomes 1 when the shown data carries a light set (the field array
 *   MesolightLightSet that Attach Relief Texture adds), else 0; LightFieldAttached 1 when a Light
 *   Field input is set. The panel's decorators show Light Set Threshold and Shadowed Lights with
 *   a light set, the Light Field's own settings with a field, Exposure and Tone Mapping with
 *   either (ParaView's decorators test properties of the representation proxy, not the data's
 *   field arrays).
 * - With a Light Field and ReliefLightFieldSceneDisplay on (the default), the relief's Exposure,
 *   Tone Mapping and Light Field Auto Exposure are copied from the field's own display in the
 *   view (its LightFieldExposure, LightFieldToneMapping, LightFieldAutoExposure), so a relief on
 *   a wall stays continuous with the scene when the scene's display settings change; and its
 *   ReliefShadowCaster, ReliefShadowMode and ReliefShadowMapResolution from the display's
 *   ShadowCaster, LightFieldShadowMode and LightFieldShadowMapResolution, so the movable object
 *   shadows the relief as it shadows the scene.
 * - At the first update that shows the relief, if it is then the only visible data of a render
 *   view left in 2D interaction, the view goes to 3D and its camera is reset. ParaView 5.11
 *   chooses the mode in pqRenderView::updateInteractionMode, called by
 *   pqApplyBehavior::showData only while the applied output is the only visible data: 2D when
 *   its bounds are flat along an axis. In the README pipeline that is the Plane's Apply; at
 *   Attach Relief Texture's Apply the plane is still visible (replace_input hides it
 *   afterwards), so the rule never sees the relief, which has depth. This applies ParaView's
 *   rule for non-flat data at that moment, once per representation, only with Edit > Settings >
 *   Render View > Default Interaction Mode on Automatic, and never for a representation loaded
 *   from a state file (its saved camera and mode stand).
 * - In the GUI, the images the relief is made from are hidden in that view: every image output
 *   upstream of the relief (the depth image and the environment, whatever reader opened them,
 *   shown as a Slice by their own Apply) that is visible when it first becomes upstream.
 *   ParaView's replace_input hint hides only a filter's direct inputs (the Plane, Relief
 *   Texture), so a user's own depth image, two steps up, stayed on screen 512 units wide with
 *   the unit relief a dot in its corner; likewise the environment when a light set is attached
 *   later. Then, if the relief is the only visible data, the view is framed (and set to 3D as
 *   above). Each image is hidden once: shown again with the eye icon it stays. Only in the GUI
 *   (the application keeps an undo stack, vtkSMProxyManager::GetUndoStackBuilder), where Apply
 *   hides inputs; a Python Show() hides nothing, so neither does this. Not for state files.
 */

#ifndef vtkSMReliefSurfaceRepresentationProxy_h
#define vtkSMReliefSurfaceRepresentationProxy_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkSMRepresentationProxy.h"

#include <set>     // for std::set
#include <utility> // for std::pair

class MESOLIGHTPARAVIEWRELIEF_EXPORT vtkSMReliefSurfaceRepresentationProxy
  : public vtkSMRepresentationProxy
{
public:
  static vtkSMReliefSurfaceRepresentationProxy* New();
  vtkTypeMacro(vtkSMReliefSurfaceRepresentationProxy, vtkSMRepresentationProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Updates LightSetAttached, LightFieldAttached and, once, the view's interaction mode (see
   * the class comment). */
  void ViewUpdated(vtkSMProxy* view) override;

  /** The field array whose presence means a light set is attached. */
  static const char* LightSetArrayName() { return "MesolightLightSet"; }

protected:
  vtkSMReliefSurfaceRepresentationProxy();
  ~vtkSMReliefSurfaceRepresentationProxy() override = default;

  /** Notes whether the proxy is being created by loading a state file. */
  void CreateVTKObjects() override;

private:
  vtkSMReliefSurfaceRepresentationProxy(const vtkSMReliefSurfaceRepresentationProxy&) = delete;
  void operator=(const vtkSMReliefSurfaceRepresentationProxy&) = delete;

  void UpdateLightSetAttached(vtkSMProxy* composite);
  /** With a Light Field and ReliefLightFieldSceneDisplay on: the field's display in `view` gives
   * the relief's Exposure, Tone Mapping, Light Field Auto Exposure and Shadow Caster with its
   * mode and resolution (see the class comment). */
  void FollowSceneDisplay(vtkSMProxy* view);
  /** Hides newly upstream visible images (see the class comment); true if it hid any. */
  bool HideUpstreamImages(vtkSMProxy* composite, vtkSMProxy* view);
  void UpdateInteractionMode(vtkSMProxy* composite, vtkSMProxy* view, bool imagesHidden);

  bool LoadedFromState = false;
  bool UpdatingForCaster = false; // FollowSceneDisplay's nested view update
  bool InteractionModeChecked = false;
  // Upstream output ports already considered (source proxy global id, port).
  std::set<std::pair<vtkTypeUInt32, int>> UpstreamPortsSeen;
};

#endif
