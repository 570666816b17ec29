// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkSMLightFieldRepresentationProxy
 * @brief   The server-manager (client-side) proxy of the Light Field representation: shows the
 *          radiance, not a colour array, when Apply first shows the data as Light Field.
 *
 * ParaView picks the colour array of a new display from the data's active scalars before the
 * Representation hint makes it a Light Field, so Virtual Light Field's output (whose active cell
 * scalars are the scene's Diffuse) came up coloured by "Diffuse" with a "Diffuse Magnitude"
 * legend beside an image that shows the radiance and nothing of that array. At the first view
 * update that shows the data as Light Field this turns the colouring off and hides the legend
 * (vtkSMPVRepresentationProxy::SetScalarColoring, HideScalarBarIfNotNeeded). Once per display:
 * colouring chosen afterwards stays, and a display loaded from a state file keeps its own.
 */

#ifndef vtkSMLightFieldRepresentationProxy_h
#define vtkSMLightFieldRepresentationProxy_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkSMRepresentationProxy.h"

class MESOLIGHTPARAVIEWRELIEF_EXPORT vtkSMLightFieldRepresentationProxy
  : public vtkSMRepresentationProxy
{
public:
  static vtkSMLightFieldRepresentationProxy* New();
  vtkTypeMacro(vtkSMLightFieldRepresentationProxy, vtkSMRepresentationProxy);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Turns the colour array off at the first update showing Light Field (class comment). */
  void ViewUpdated(vtkSMProxy* view) override;

protected:
  vtkSMLightFieldRepresentationProxy();
  ~vtkSMLightFieldRepresentationProxy() override = default;

  /** Notes whether the proxy is being created by loading a state file. */
  void CreateVTKObjects() override;

private:
  vtkSMLightFieldRepresentationProxy(const vtkSMLightFieldRepresentationProxy&) = delete;
  void operator=(const vtkSMLightFieldRepresentationProxy&) = delete;

  bool LoadedFromState = false;
  bool ColoringChecked = false;
};

#endif
