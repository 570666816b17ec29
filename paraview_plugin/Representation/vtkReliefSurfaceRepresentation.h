// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefSurfaceRepresentation
 * @brief   ParaView's "Relief Surface": a surface representation that draws polydata as relief
 *          surfaces with vtkCompositeReliefMapper.
 *
 * The relief texture and the optional light set come with the data, attached as field data by
 * vtkAttachReliefTexture ("Attach Relief Texture" filter), so every MPI rank draws its piece
 * with the whole texture and writes the relief's depth, which IceT composites.
 * The mapper and the LOD mapper share one vtkReliefProperty (GetReliefProperty()); the setters
 * below are the ParaView proxy's commands (MesolightRelief.xml), each setting that property.
 */

#ifndef vtkReliefSurfaceRepresentation_h
#define vtkReliefSurfaceRepresentation_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkNew.h" // for ReliefProperty

class vtkReliefProperty;

class MESOLIGHTPARAVIEWRELIEF_EXPORT vtkReliefSurfaceRepresentation
  : public vtkGeometryRepresentationWithFaces
{
public:
  static vtkReliefSurfaceRepresentation* New();
  vtkTypeMacro(vtkReliefSurfaceRepresentation, vtkGeometryRepresentationWithFaces);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /** Relief settings (see vtkReliefMapper). */
  void SetReliefMethod(int method);
  void SetLinearSteps(int steps);
  void SetRefinementSteps(int steps);
  void SetAdaptiveSteps(bool on);
  void SetMinimumSteps(int steps);
  void SetReliefDepthScale(double scale);
  /** Off (the default): the depth scale the relief texture was baked with; on: ReliefDepthScale. */
  void SetOverrideDepthScale(bool on);
  void SetSelfShadowing(bool on);
  void SetSilhouettes(bool on);
  void SetWriteDepth(bool on);
  void SetRepeatTexture(bool on);
  void SetLevelOfDetail(bool on);
  void SetExposure(double exposure);
  void SetToneMapping(bool on);
  void SetLightSetThreshold(double threshold);
  void SetShadowedLights(int count);
  ///@}

  /** The relief settings of both the mapper and the LOD mapper. */
  vtkReliefProperty* GetReliefProperty();

protected:
  vtkReliefSurfaceRepresentation();
  ~vtkReliefSurfaceRepresentation() override = default;

  vtkNew<vtkReliefProperty> ReliefProperty;

private:
  vtkReliefSurfaceRepresentation(const vtkReliefSurfaceRepresentation&) = delete;
  void operator=(const vtkReliefSurfaceRepresentation&) = delete;
};

#endif
