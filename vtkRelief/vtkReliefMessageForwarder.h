// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefMessageForwarder
 * @brief   Passes the errors and warnings of the objects a relief mapper is built from on to
 *          the mapper's observers.
 *
 * A relief mapper does its work in several helper objects (vtkReliefShading and the caches and
 * textures it composes, vtkReliefProperty). Users watch the mapper, as for any VTK algorithm:
 * this command, observing ErrorEvent and WarningEvent on each helper (Watch()), invokes the same
 * event on the owner when the owner has observers for it, and otherwise displays the message as
 * vtkErrorMacro / vtkWarningMacro would have. Either way the text names the owner, not the
 * helper ("vtkReliefMapper (0x...): ..."): users never made the helpers.
 */

#ifndef vtkReliefMessageForwarder_h
#define vtkReliefMessageForwarder_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkCommand.h"
#include "vtkWeakPointer.h" // for Owner

class MESOLIGHTRELIEF_EXPORT vtkReliefMessageForwarder : public vtkCommand
{
public:
  static vtkReliefMessageForwarder* New();
  vtkTypeMacro(vtkReliefMessageForwarder, vtkCommand);

  ///@{
  /** The object whose observers hear the messages. Not referenced (a weak pointer). */
  void SetOwner(vtkObject* owner) { this->Owner = owner; }
  vtkObject* GetOwner() { return this->Owner; }
  ///@}

  /** Forward the errors and warnings of this object from now on. */
  void Watch(vtkObject* source);

  void Execute(vtkObject* caller, unsigned long event, void* callData) override;

protected:
  vtkReliefMessageForwarder() = default;
  ~vtkReliefMessageForwarder() override = default;

  vtkWeakPointer<vtkObject> Owner;

private:
  vtkReliefMessageForwarder(const vtkReliefMessageForwarder&) = delete;
  void operator=(const vtkReliefMessageForwarder&) = delete;
};

#endif
