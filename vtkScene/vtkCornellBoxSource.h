// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkCornellBoxSource
 * @brief   the Cornell box (published dimensions and colours) as vtkPolyData with materials
 *
 * The light field's default scene: mesolight::MakeCornellBox() (vtkScene/core/TriangleScene.h;
 * https://www.graphics.cornell.edu/online/box/data.html: millimetres, y up, the ceiling light
 * emitting radiance (17, 12, 4)) with the cell arrays "Diffuse", "Specular", "Emission",
 * "MaterialId" and field data "MaterialNames", as vtkOBJSceneReader gives for an OBJ file
 * (examples/data/cornell-box.obj is the same box). With NormalizeToUnitSphere on, the box is
 * translated and scaled into the unit sphere, as the light field assumes (Wither 2005 §2.4.1).
 */
#ifndef vtkCornellBoxSource_h
#define vtkCornellBoxSource_h

#include "MesolightSceneModule.h" // For export macro
#include "vtkPolyDataAlgorithm.h"

class MESOLIGHTSCENE_EXPORT vtkCornellBoxSource : public vtkPolyDataAlgorithm
{
public:
  static vtkCornellBoxSource* New();
  vtkTypeMacro(vtkCornellBoxSource, vtkPolyDataAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * Centre the box at the origin and scale its bounding box's diagonal to 2 (bounding sphere of
   * radius 1). Default off: the published millimetres.
   */
  vtkSetMacro(NormalizeToUnitSphere, bool);
  vtkGetMacro(NormalizeToUnitSphere, bool);
  vtkBooleanMacro(NormalizeToUnitSphere, bool);
  ///@}

protected:
  vtkCornellBoxSource();
  ~vtkCornellBoxSource() override = default;

  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

private:
  vtkCornellBoxSource(const vtkCornellBoxSource&) = delete;
  void operator=(const vtkCornellBoxSource&) = delete;

  bool NormalizeToUnitSphere = false;
};

#endif
