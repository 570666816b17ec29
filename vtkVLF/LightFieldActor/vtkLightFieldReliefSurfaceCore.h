// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldReliefSurfaceCore
 * @brief   vtkLightFieldReliefSurface's SH9 probes as computed, for code built in this tree
 *
 * Private to Mesolight::LightFieldActor (header not installed: the core types' headers are not
 * either), as vtkLightFieldActorCore is for the actor. The walkthrough's mirrors shade a relief
 * with the CPU reference (application/LightFieldReliefs.cxx), which takes the probes in double
 * precision: it reads them here instead of computing them a second time.
 */
#ifndef vtkLightFieldReliefSurfaceCore_h
#define vtkLightFieldReliefSurfaceCore_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkLightFieldReliefSurface.h"

#include <vector>

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldReliefSurfaceCore
{
public:
  /**
   * The probes of the filter's last update of a named surface (SurfaceName):
   * ProbesPerSide x ProbesPerSide SH9 radiance projections, row-major, j slowest, as
   * mesolight::vlf::ReliefSurfaceProbes returned them (port 1 holds them as floats). nullptr
   * before, after a failed or stopped update, and for a surface of input port 1.
   */
  static const std::vector<mesolight::SH9>* GetProbes(const vtkLightFieldReliefSurface* surface);
};

#endif
