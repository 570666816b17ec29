// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldRepresentation
 * @brief   ParaView's "Light Field": a surface representation that draws Virtual Light Field's
 *          output with its diffuse radiance per pixel, exposed and tone-mapped
 *
 * The mapper and the LOD mapper are vtkCompositeLightFieldMapper: the radiance atlas and the
 * atlas coordinates come with the data (vtkVirtualLightField puts them there), so every MPI rank
 * draws its piece with the whole atlas, and state files need nothing more. The Virtual Light
 * Field proxy names this representation as its default (a Representation hint), so Apply shows
 * the radiance as colours. The setters are the proxy's commands (MesolightVLF.xml).
 */
#ifndef vtkLightFieldRepresentation_h
#define vtkLightFieldRepresentation_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"

class MESOLIGHTPARAVIEWRELIEF_EXPORT vtkLightFieldRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkLightFieldRepresentation* New();
  vtkTypeMacro(vtkLightFieldRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Radiance scale before tone mapping; 0 clamp, 1 Reinhard (vtkCompositeLightFieldMapper). */
  void SetExposure(double exposure);
  void SetToneMapping(int mode);
  void SetAutoExposure(bool on);
  ///@}

protected:
  vtkLightFieldRepresentation();
  ~vtkLightFieldRepresentation() override = default;

private:
  vtkLightFieldRepresentation(const vtkLightFieldRepresentation&) = delete;
  void operator=(const vtkLightFieldRepresentation&) = delete;
};

#endif
