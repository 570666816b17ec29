// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldRepresentation
 * @brief   ParaView's "Light Field": a surface representation that draws Virtual Light Field's
 *          output with its diffuse radiance per pixel, exposed and tone-mapped, and the shadow a
 *          movable object casts on it
 *
 * The mapper and the LOD mapper are vtkCompositeLightFieldMapper: the radiance atlas and the
 * atlas coordinates come with the data (vtkVirtualLightField puts them there), so every MPI rank
 * draws its piece with the whole atlas, and state files need nothing more. The Virtual Light
 * Field proxy names this representation as its default (a Representation hint), so Apply shows
 * the radiance as colours; Light Field Gather's output too (its per-vertex radiance, exposed
 * like the scene). The setters are the proxy's commands (MesolightLightField.xml).
 *
 * Input port 1 (optional, the proxy's "Shadow Caster"): the movable object, Light Field
 * Gather's output (its field data carries the field's emitters). Its pieces are gathered from
 * every rank (the maps need the whole object), then the mappers darken the scene with
 * vtkLightFieldActor's shadow code (ShadowMode, default field-derived).
 */
#ifndef vtkLightFieldRepresentation_h
#define vtkLightFieldRepresentation_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkSmartPointer.h" // for vtkSmartPointer

class vtkPolyData;

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

  ///@{
  /** The movable object's shadow (vtkCompositeLightFieldMapper::SetShadowMode, ...). */
  void SetShadowMode(int mode);
  void SetShadowMapResolution(int texels);
  ///@}

  /** The whole caster of the last update (all ranks' pieces), null without one. */
  vtkPolyData* GetShadowCaster();

  /**
   * A Shadow Caster as its maps need it: every rank's piece appended, the field's emitters kept
   * (field data), on every rank; null when no rank has one. Collective: every rank calls it in
   * the same update (what the Relief Surface's Shadow Caster is gathered with too).
   */
  static vtkSmartPointer<vtkPolyData> GatherShadowCaster(vtkPolyData* piece);

protected:
  vtkLightFieldRepresentation();
  ~vtkLightFieldRepresentation() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkLightFieldRepresentation(const vtkLightFieldRepresentation&) = delete;
  void operator=(const vtkLightFieldRepresentation&) = delete;

  vtkSmartPointer<vtkPolyData> Caster;
};

#endif
