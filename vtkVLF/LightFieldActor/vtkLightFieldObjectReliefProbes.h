// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldObjectReliefProbes
 * @brief   the light field's irradiance probes over a textured movable object, for reliefs
 *          mapped on it
 *
 * A vtkLightFieldActor's movable object may carry a relief: its polydata has texture
 * coordinates, and a relief mapper (vtkReliefMapper) draws a depth image over them. The relief
 * is lit per pixel at its perturbed normal from the field's gathered light, as a relief on a
 * static surface is: the field's indirect light as SH9 radiance probes over the texture
 * (Ramamoorthi and Hanrahan, "An efficient representation for irradiance environment maps"),
 * the emitters as lights. This class makes the probes; it knows no relief (the caller joins the
 * two, docs/dev/architecture.md).
 *
 * One probe grid covers the texture square, so the object is split into charts whose texture
 * coordinates do not overlap (a box whose six faces each map [0,1]^2 gives six): one relief
 * actor and one probe image per chart. GetChart(i) is chart i's triangles in the object's model
 * coordinates (points, point normals, texture coordinates: draw it with the object's matrix);
 * GetProbes(i) its probes, the layout of vtkReliefMapper::SetIrradianceProbesData: a
 * (9 x N) x N float image, 3 components, probe (i, j) at texture coordinates ((i + 0.5) / N,
 * (j + 0.5) / N), its coefficient k at pixel (9 i + k, j), world directions. Each probe is the
 * field's incident radiance at the surface point under its texture coordinates (in front of the
 * surface; directions behind it are the object's own body), the emitters' own radiance left out,
 * projected on SH9 (mesolight::vlf::ObjectReliefProbes).
 *
 * Update() follows the scene actor's movable object: the charts when its polydata changes (cached
 * while it only moves), the probes when it moved (probes that moved less than a quarter of a
 * field cell keep their value). The scene actor is held weakly.
 */
#ifndef vtkLightFieldObjectReliefProbes_h
#define vtkLightFieldObjectReliefProbes_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer
#include "vtkWeakPointer.h"  // For vtkWeakPointer

#include <memory> // For std::unique_ptr
#include <vector> // For std::vector

class vtkImageData;
class vtkLightFieldActor;
class vtkPolyData;
namespace mesolight
{
namespace vlf
{
class LightField;
class ObjectReliefProbes;
}
}

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldObjectReliefProbes : public vtkObject
{
public:
  static vtkLightFieldObjectReliefProbes* New();
  vtkTypeMacro(vtkLightFieldObjectReliefProbes, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The scene actor whose field and movable object the probes are made for (held weakly). */
  void SetLightFieldActor(vtkLightFieldActor* scene);
  vtkLightFieldActor* GetLightFieldActor();

  ///@{
  /** Probes per side of each chart's texture (default 8, as a static surface's relief). */
  vtkSetClampMacro(ProbesPerSide, int, 1, 64);
  vtkGetMacro(ProbesPerSide, int);
  ///@}

  /**
   * Brings the charts and the probes up to date with the scene actor's field and movable object
   * (it updates the object first). False, reported with vtkErrorMacro, when there is no field,
   * no object, or an object without texture coordinates.
   */
  bool Update();

  int GetNumberOfCharts() const;
  /** Chart i: its triangles in model coordinates with point normals and texture coordinates. */
  vtkPolyData* GetChart(int i);
  /** Chart i's probes (see above). */
  vtkImageData* GetProbes(int i);
  /** Bumped when the charts were rebuilt (a new mesh or probe count): rebuild their actors. */
  unsigned long GetChartsVersion() const { return this->ChartsVersion; }
  /** Probes under two triangles of their chart (a texture folding over itself), all charts. */
  vtkIdType GetOverlappingProbes() const;

  ///@{
  /** The last Update that gathered: seconds, probes gathered (the others kept their value). */
  double GetLastSeconds() const { return this->LastSeconds; }
  vtkIdType GetLastGatheredProbes() const { return this->LastGatheredProbes; }
  vtkIdType GetNumberOfProbes() const;
  ///@}

protected:
  vtkLightFieldObjectReliefProbes();
  ~vtkLightFieldObjectReliefProbes() override;

private:
  vtkLightFieldObjectReliefProbes(const vtkLightFieldObjectReliefProbes&) = delete;
  void operator=(const vtkLightFieldObjectReliefProbes&) = delete;

  bool Fail(const char* why);

  vtkWeakPointer<vtkLightFieldActor> Scene;
  int ProbesPerSide = 8;
  const mesolight::vlf::LightField* Field = nullptr;
  std::unique_ptr<mesolight::vlf::ObjectReliefProbes> Probes;
  vtkPolyData* Data = nullptr; // identity only
  vtkMTimeType DataTime = 0;
  int ChartsPerSide = 0;
  unsigned long ObjectVersion = 0;
  unsigned long ChartsVersion = 0;
  std::vector<vtkSmartPointer<vtkPolyData>> Charts;
  std::vector<vtkSmartPointer<vtkImageData>> Images;
  double LastSeconds = 0.0;
  vtkIdType LastGatheredProbes = 0;
};

#endif
