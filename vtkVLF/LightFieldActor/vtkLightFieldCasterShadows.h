// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldCasterShadows
 * @brief   the shadow maps of a movable object given as data: Light Field Gather's output, which
 *          carries the field's emitters and its world-to-unit-sphere normalisation
 *
 * Wither 2005, "Interactive dynamic objects in a virtual light field", chapter 4: the maps of
 * mesolight::vlf::ObjectShadows, packed for the GPU by PackShadowsForGpu and read by
 * glsl/vtkLightFieldShadowFS.glsl, built from a caster polydata instead of a vtkLightFieldActor's
 * object. What ParaView draws a Shadow Caster with, on the scene (vtkCompositeLightFieldMapper)
 * and on a relief lit by the same field (vtkLightFieldReliefShadowHook). Update() rebuilds the
 * maps only when the caster (or its modification time) or a setting changed.
 */
#ifndef vtkLightFieldCasterShadows_h
#define vtkLightFieldCasterShadows_h

#include "MesolightLightFieldActorModule.h" // For export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <memory> // For std::unique_ptr
#include <string> // For the problem

namespace mesolight
{
namespace vlf
{
struct ShadowGpuData;
}
}
class vtkPolyData;

class MESOLIGHTLIGHTFIELDACTOR_EXPORT vtkLightFieldCasterShadows : public vtkObject
{
public:
  static vtkLightFieldCasterShadows* New();
  vtkTypeMacro(vtkLightFieldCasterShadows, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  ///@{
  /**
   * The movable object (nullptr: none): Light Field Gather's output or a filter after it, in
   * world coordinates. Kept by reference; its modification time rebuilds the maps.
   */
  void SetCaster(vtkPolyData* caster);
  vtkPolyData* GetCaster();
  ///@}

  ///@{
  /** vtkLightFieldActor::ShadowModes (0 none ... 5 soft; default 3, field-derived). */
  void SetMode(int mode);
  vtkGetMacro(Mode, int);
  ///@}

  ///@{
  /** Texels per shadow map side, [16, 4096] (default 256). */
  void SetResolution(int texels);
  vtkGetMacro(Resolution, int);
  ///@}

  /**
   * Rebuilds the maps if the caster or a setting changed. A caster that casts no shadow (no
   * emitters, no polygons) is warned about once per cause, through `reporter` (the mapper or
   * representation the user sees; this object when null).
   */
  void Update(vtkObject* reporter);

  ///@{
  /**
   * The field the shadow is drawn in, as its world to unit sphere normalisation (centre, scale:
   * vtkVirtualLightField::GetAttachedUnitSphere of the field's output). A caster gathered from
   * another field (another scene, or the same one moved or scaled) carries that field's emitters
   * and unit sphere, so its shadow would fall in the wrong place with the wrong lamps: it then
   * casts none and Update says why. Scale 0 (the default, ClearFieldUnitSphere): not checked.
   */
  void SetFieldUnitSphere(const double centre[3], double scale);
  void ClearFieldUnitSphere();
  ///@}

  /** There are maps to draw. */
  bool HasShadows() const;
  /** The packed maps (valid until the next Update). */
  const mesolight::vlf::ShadowGpuData& GetGpu() const;
  /** Bumped whenever the maps change (what draws them uploads them again). */
  unsigned long GetVersion() const { return this->Version; }
  /**
   * World coordinates to the field's unit sphere (where the maps live), as a column-major 4 x 4
   * matrix: a scale about the field's centre.
   */
  void GetWorldToUnitSphere(float columnMajor[16]) const;
  /** Why the last build gave no shadow although a caster was set ("" when it did). */
  const char* GetProblem() const { return this->Problem.c_str(); }

protected:
  vtkLightFieldCasterShadows();
  ~vtkLightFieldCasterShadows() override;

  vtkSmartPointer<vtkPolyData> Caster;
  int Mode = 3;
  int Resolution = 256;
  const void* BuiltCaster = nullptr;
  vtkMTimeType BuiltTime = 0;
  int BuiltMode = -1;
  int BuiltResolution = -1;
  unsigned long Version = 0;
  double Centre[3] = { 0.0, 0.0, 0.0 };
  double Scale = 1.0;
  double FieldCentre[3] = { 0.0, 0.0, 0.0 };
  double FieldScale = 0.0; // 0: the field is not known, nothing checked
  double BuiltFieldCentre[3] = { 0.0, 0.0, 0.0 };
  double BuiltFieldScale = -1.0;
  std::string Problem;
  struct Maps;
  std::unique_ptr<Maps> Built;

  // The caster's unit sphere (Centre, Scale) is the field's (FieldCentre, FieldScale).
  bool SameUnitSphere() const;

private:
  vtkLightFieldCasterShadows(const vtkLightFieldCasterShadows&) = delete;
  void operator=(const vtkLightFieldCasterShadows&) = delete;
};

#endif
