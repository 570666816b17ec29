// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefSurfaceRepresentation
 * @brief   ParaView's "Relief Surface": a surface representation that draws polydata as relief
 *          surfaces with vtkCompositeReliefMapper.
 *
 * The relief texture and the optional light set come with the data, attached as field data by
 * vtkAttachReliefTexture ("Attach Relief Texture" filter), so every MPI rank draws its piece
 * with the whole texture and writes the relief's depth, which IceT composites.
 * A colour image attached the same way (Attach Relief Texture's Color Texture input, e.g. the
 * albedo of Depth Hallucination) becomes the actor's texture, unless the user chose a Texture:
 * ParaView's own texture property only takes images its readers load, and those read no EXR.
 * The mapper and the LOD mapper share one vtkReliefProperty (GetReliefProperty()); the setters
 * below are the ParaView proxy's commands (MesolightRelief.xml), each setting that property.
 */

#ifndef vtkReliefSurfaceRepresentation_h
#define vtkReliefSurfaceRepresentation_h

#include "MesolightParaViewReliefModule.h" // for export macro
#include "vtkGeometryRepresentationWithFaces.h"
#include "vtkNew.h"     // for ReliefProperty
#include "vtkTexture.h" // for vtkNew<vtkTexture>

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

  /** The user's Texture; it wins over an attached colour texture. */
  void SetTexture(vtkTexture* texture) override;

  /** On render requests: the attached colour texture becomes the actor's texture. */
  int ProcessViewRequest(vtkInformationRequestKey* requestType, vtkInformation* inInfo,
    vtkInformation* outInfo) override;

protected:
  vtkReliefSurfaceRepresentation();
  ~vtkReliefSurfaceRepresentation() override = default;

  vtkNew<vtkReliefProperty> ReliefProperty;
  vtkNew<vtkTexture> AttachedColorTexture;
  vtkTexture* UserTexture = nullptr; // not owned: the superclass' actor holds it

  /** Shows the colour image attached to the mapper's input, or removes the one shown. */
  void UpdateAttachedColorTexture();

private:
  vtkReliefSurfaceRepresentation(const vtkReliefSurfaceRepresentation&) = delete;
  void operator=(const vtkReliefSurfaceRepresentation&) = delete;
};

#endif
