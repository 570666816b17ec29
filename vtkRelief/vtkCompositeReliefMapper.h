// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkCompositeReliefMapper
 * @brief   vtkReliefMapper's relief rendering as a vtkCompositePolyDataMapper2, for composite
 *          inputs and for ParaView's geometry representations (which draw through one).
 *
 * Draws each polydata block as a relief surface, with exactly vtkReliefMapper's shader edits,
 * textures and uniforms: both delegate them to a vtkReliefShading. The settings are a
 * vtkReliefProperty (GetReliefProperty()), which can be shared with other mappers, e.g. a
 * representation's mapper and LOD mapper.
 *
 * The relief texture and the light set come from SetReliefTextureData() / SetLightSetData()
 * when given, otherwise from the field data of the first block that carries them
 * (vtkAttachReliefTexture); the latter is how ParaView's Relief Surface representation gets
 * them, in every MPI rank.
 *
 * Only for VTK < 9.3, where vtkCompositePolyDataMapper2 draws through vtkCompositeMapperHelper2
 * (VTK 9.3 replaced it by delegators); not built otherwise.
 */

#ifndef vtkCompositeReliefMapper_h
#define vtkCompositeReliefMapper_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkCompositePolyDataMapper2.h"
#include "vtkNew.h"            // for Shading
#include "vtkReliefProperty.h" // for GetReliefProperty: callers set the relief through it
#include "vtkSmartPointer.h"   // for members

class vtkImageData;
class vtkReliefRadianceHook;
class vtkReliefShading;

class MESOLIGHTRELIEF_EXPORT vtkCompositeReliefMapper : public vtkCompositePolyDataMapper2
{
public:
  static vtkCompositeReliefMapper* New();
  vtkTypeMacro(vtkCompositeReliefMapper, vtkCompositePolyDataMapper2);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The relief settings. Every mapper starts with a property of its own, whose errors reach
   * this mapper's observers; setting one shares it, e.g. between several mappers. Null makes a
   * new default property on the next GetReliefProperty().
   */
  vtkReliefProperty* GetReliefProperty();
  void SetReliefProperty(vtkReliefProperty* property);
  ///@}

  ///@{
  /** Explicit relief texture / light set; null (default) reads them from the input's field data. */
  void SetReliefTextureData(vtkImageData* image);
  void SetLightSetData(vtkImageData* lights);
  ///@}

  ///@{
  /**
   * SH9 irradiance probes over the relief's texture, as vtkReliefMapper::SetIrradianceProbesData
   * describes them (null, the default: none).
   */
  void SetIrradianceProbesData(vtkImageData* probes);
  vtkImageData* GetIrradianceProbesData();
  ///@}

  ///@{
  /**
   * Code that changes the relief's linear radiance at its hit point (vtkReliefRadianceHook; null,
   * the default: none), e.g. a light field's movable object's shadow.
   */
  void SetRadianceHook(vtkReliefRadianceHook* hook);
  vtkReliefRadianceHook* GetRadianceHook();
  ///@}

  /** Finds the relief texture and light set of this render, then draws the blocks. */
  void Render(vtkRenderer* ren, vtkActor* actor) override;

  /** Includes the relief property's modification time. */
  vtkMTimeType GetMTime() override;

  void ReleaseGraphicsResources(vtkWindow* win) override;

protected:
  vtkCompositeReliefMapper();
  ~vtkCompositeReliefMapper() override;

  vtkCompositeMapperHelper2* CreateHelper() override;

  vtkNew<vtkReliefShading> Shading;
  vtkSmartPointer<vtkImageData> ReliefTextureData;
  vtkSmartPointer<vtkImageData> LightSetData;
  vtkSmartPointer<vtkImageData> IrradianceProbesData;
  // What the current render draws with (explicit data or the input's field data).
  vtkSmartPointer<vtkImageData> CurrentReliefTexture;
  vtkSmartPointer<vtkImageData> CurrentLightSet;

  friend class vtkCompositeReliefMapperHelper;

private:
  vtkCompositeReliefMapper(const vtkCompositeReliefMapper&) = delete;
  void operator=(const vtkCompositeReliefMapper&) = delete;
};

#endif
