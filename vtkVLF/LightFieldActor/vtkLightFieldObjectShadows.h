// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldObjectShadows
 * @brief   the shadows vtkLightFieldActor's movable object casts on the static scene
 *
 * Private to Mesolight::LightFieldActor (header not installed). Wither 2005, "Interactive
 * dynamic objects in a virtual light field", chapter 4; the algorithm and its modes are
 * mesolight::vlf::ObjectShadows (core/ObjectShadows.h). This holds the settings, the caster (the
 * object as a triangle mesh in the field's unit sphere), the maps and their packing for the GPU
 * (glsl/vtkLightFieldShadowFS.glsl), rebuilt by Prepare() when the caster, the settings or the
 * field changed, and darkens the raytrace mode's CPU pixels the same way (ApplyToScreen).
 * Changes mark the owner (the actor) modified, as its own settings do.
 */
#ifndef vtkLightFieldObjectShadows_h
#define vtkLightFieldObjectShadows_h

#include "ObjectMesh.h"    // For ObjectMesh
#include "ObjectShadows.h" // For ObjectShadows, ShadowSettings, ShadowGpuData

#include <functional>
#include <memory>
#include <string>

namespace mesolight
{
namespace vlf
{
class LightField;
class WalkthroughTracer;
struct ViewFrame;
}
}
class vtkLightFieldScreenImage;
class vtkObject;

class vtkLightFieldObjectShadows
{
public:
  /** owner: the object marked modified and warnings are reported for (the actor). */
  explicit vtkLightFieldObjectShadows(vtkObject* owner);
  ~vtkLightFieldObjectShadows();
  vtkLightFieldObjectShadows(const vtkLightFieldObjectShadows&) = delete;
  vtkLightFieldObjectShadows& operator=(const vtkLightFieldObjectShadows&) = delete;

  ///@{
  /** The settings (mesolight::vlf::ShadowSettings), clamped as vtkLightFieldActor documents. */
  void SetMode(int mode);
  void SetResolution(int texels);
  void SetEmitterCount(int count);
  void SetAreaSamples(int perSide);
  void SetPCFKernel(int texels);
  void SetBackProjectionRemoval(bool remove);
  const mesolight::vlf::ShadowSettings& GetSettings() const { return this->Settings; }
  ///@}

  /** The caster moved or changed (a triangle mesh in the field's unit sphere, copied). */
  void SetCaster(const mesolight::vlf::ObjectMesh& unitMesh);
  /** No caster any more. */
  void ClearCaster();
  bool HasCaster() const { return this->Caster != nullptr; }
  /** The maps need a rebuild (a new field: they belong to its emitters and unit sphere). */
  void Invalidate() { this->Dirty = true; }

  /**
   * Rebuilds the maps if anything changed and hands them to the tracer (its mirrors show
   * darkened diffuse points too). stopReaders runs before the maps the progressive worker may
   * be reading change.
   */
  void Prepare(const mesolight::vlf::LightField* field, mesolight::vlf::WalkthroughTracer* tracer,
    const std::function<void()>& stopReaders);
  /** Raytrace mode: darkens the screen's diffuse pixels as the GPU does. */
  void ApplyToScreen(const mesolight::vlf::LightField& field,
    const mesolight::vlf::WalkthroughTracer& tracer, const mesolight::vlf::ViewFrame& view,
    vtkLightFieldScreenImage& screen) const;

  /** The maps (nullptr when no object casts shadows). */
  const mesolight::vlf::ObjectShadows* GetMaps() const;
  /** There are maps for the GPU. */
  bool Active() const { return this->Gpu.Mode != 0 && this->Gpu.EmitterCount > 0; }
  const mesolight::vlf::ShadowGpuData& GetGpu() const { return this->Gpu; }
  /** Bumped whenever the maps change (the mapper re-uploads; traced reflections are redone). */
  unsigned long GetVersion() const { return this->Version; }
  /** Why the last build gave no shadows ("" when it did). */
  const std::string& GetProblem() const { return this->Problem; }
  /** CPU seconds of the last build (placement and fill). */
  double GetFillSeconds() const { return this->Shadows.FillSeconds(); }

private:
  template <typename T>
  void Change(T& setting, T value);

  vtkObject* Owner;
  mesolight::vlf::ShadowSettings Settings;
  std::unique_ptr<mesolight::vlf::ObjectMesh> Caster; // unit sphere; null: no object
  mesolight::vlf::ObjectShadows Shadows;
  mesolight::vlf::ShadowGpuData Gpu;
  bool Dirty = true;
  const mesolight::vlf::LightField* BuiltFor = nullptr;
  unsigned long Version = 0;
  std::string Problem;
};

#endif
