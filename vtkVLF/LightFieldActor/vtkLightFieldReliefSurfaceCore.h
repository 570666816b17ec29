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

#include <memory> // For std::shared_ptr
#include <vector>

namespace mesolight
{
class EmbreeScene;
namespace vlf
{
class LightField;
}
}

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

  /**
   * Lends the surface an Embree scene of `field`'s scene (unit sphere, field->Scene()) for its
   * SceneOcclusion, which otherwise builds its own every update: the walkthrough builds one for
   * its reliefs' emitter visibility and its mirrors' relief tracing (application/
   * LightFieldReliefs.cxx). Used only while the surface's field is `field`; null returns it.
   */
  static void LendEmbreeScene(vtkLightFieldReliefSurface* surface,
    const mesolight::vlf::LightField* field, std::shared_ptr<const mesolight::EmbreeScene> scene);
};

#endif
