// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightFieldSceneCache
 * @brief   what vtkLightFieldActor builds once per field: the tracer, the texture atlas, the
 *          scene polydata its mapper draws, and the emitters' estimated point lights
 *
 * Private to Mesolight::LightFieldActor (header not installed). Build() replaces everything for a
 * new field (or clears it); the field itself is borrowed (vtkLightFieldInput holds it).
 * GetAtlasVersion() changes with every Build, so the mapper uploads the atlas once per field.
 */
#ifndef vtkLightFieldSceneCache_h
#define vtkLightFieldSceneCache_h

#include "vtkSmartPointer.h"

#include <memory>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{
class LightField;
class TextureAtlas;
class WalkthroughTracer;
struct LightApproximation;
}
}
class vtkPolyData;

class vtkLightFieldSceneCache
{
public:
  vtkLightFieldSceneCache();
  ~vtkLightFieldSceneCache();
  vtkLightFieldSceneCache(const vtkLightFieldSceneCache&) = delete;
  vtkLightFieldSceneCache& operator=(const vtkLightFieldSceneCache&) = delete;

  /**
   * Builds the tracer, atlas and scene of the field (nullptr clears them). False, with the reason
   * in error, when the field cannot be shown (then nothing is held).
   */
  bool Build(const mesolight::vlf::LightField* field, std::string& error);

  /**
   * Remakes the scene polydata without the surfaces of these names (all shown when empty).
   * False, with the reason in error, for a name the field's scene does not have (the others
   * are hidden). Nothing to do without a field.
   */
  bool SetHiddenSurfaces(const std::vector<std::string>& names, std::string& error);

  /** The field built from (nullptr: none, or its build failed). */
  const mesolight::vlf::LightField* GetField() const { return this->Field; }
  mesolight::vlf::WalkthroughTracer* GetTracer() const { return this->Tracer.get(); }
  const mesolight::vlf::TextureAtlas* GetAtlas() const { return this->Atlas.get(); }
  /** The field's triangles in world coordinates with atlas coordinates, normals, Kd colours and
   * the shadow receivers' attributes; nullptr without a field. */
  vtkPolyData* GetScene() const;
  unsigned long GetAtlasVersion() const { return this->AtlasVersion; }
  /** Point lights estimated from the field's emitters (once per field), or nullptr. */
  const mesolight::vlf::LightApproximation* GetEmitterLights();

private:
  const mesolight::vlf::LightField* Field = nullptr;
  std::unique_ptr<mesolight::vlf::WalkthroughTracer> Tracer;
  std::unique_ptr<mesolight::vlf::TextureAtlas> Atlas;
  vtkSmartPointer<vtkPolyData> Scene;
  std::vector<std::string> Hidden; // the names Scene leaves out
  unsigned long AtlasVersion = 0;  // bumped whenever the atlas changes
  std::unique_ptr<mesolight::vlf::LightApproximation> Lights;
};

#endif
