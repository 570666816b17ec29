// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkVirtualLightFieldCore
 * @brief   vtkVirtualLightField's mesolight::vlf::LightField, for code built in this tree
 *
 * Private to Mesolight::LightField (header not installed: the core's headers are not either),
 * as vtkLightFieldActorCore is for the actor. The light field actor, vtkLightFieldGatherFilter,
 * the mesolight tool and the tests read the propagated field here for lookups
 * (mesolight::vlf::Lookup).
 */
#ifndef vtkVirtualLightFieldCore_h
#define vtkVirtualLightFieldCore_h

#include "MesolightLightFieldModule.h" // For export macro
#include "vtkVirtualLightField.h"

class MESOLIGHTLIGHTFIELD_EXPORT vtkVirtualLightFieldCore
{
public:
  /** The field of the filter's last successful update (nullptr before, or for no filter). */
  static const mesolight::vlf::LightField* GetLightField(const vtkVirtualLightField* filter);
};

#endif
