// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefShaderSource
 * @brief   The relief's edits of a VTK OpenGL mapper's shader sources, and the variant (the
 *          compile-time choices) each of the mapper's shaders was built for.
 *
 * The edits come in two steps around the mapper superclass' own (ReplaceShaderValues): before,
 * tangents and relief texture coordinates are passed through the vertex shader and our
 * placeholders reserved in the fragment shader; after, the relief implementation (the GLSL of
 * vtkRelief/glsl, embedded at build time) replaces VTK's lighting, with #defines for the
 * variant: the property's method, output and switches, and what the draw binds (an albedo
 * texture, a cone-packed relief texture, a light set, irradiance probes). Each shader is keyed by
 * the variant it was built for, so a change of variant rebuilds it.
 */

#ifndef vtkReliefShaderSource_h
#define vtkReliefShaderSource_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for Property

#include <map>    // for Keys
#include <string> // for the sources

class vtkReliefProperty;

class MESOLIGHTRELIEF_EXPORT vtkReliefShaderSource : public vtkObject
{
public:
  static vtkReliefShaderSource* New();
  vtkTypeMacro(vtkReliefShaderSource, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** The variant of the coming draw: the property's settings and what the draw binds. */
  void Configure(vtkReliefProperty* property, bool albedoTexture, bool conePacked, bool lightSet,
    bool irradianceProbes);

  /**
   * How the relief texture is stored (vtkReliefTextureCache): the float RGBA layout, or the
   * compact one with the normals uploaded (storedNormals) or derived from the depth; moments:
   * the normal's mip-mapped moments are uploaded (level of detail's visible normal filter).
   */
  void SetTextureLayout(
    bool floatTextures, bool storedNormals, bool moments, bool normalsFromDepth);

  /**
   * Whether the geometry drawn carries per-vertex quadrics (vtkReliefGeometryCache::IsCurved).
   * With the property's SurfaceCurvature on and a method that steps along the ray, the shaders
   * then read the vertex attribute mlQuadricMC and march the curved layer (ML_CURVED).
   */
  void SetCurvedGeometry(bool curved) { this->CurvedGeometry = curved; }
  bool GetCurvedGeometry() const { return this->CurvedGeometry; }
  /** A vtkReliefRadianceHook's declarations for this draw ("": none). */
  void SetRadianceHookSource(const std::string& source);
  /** Whether the shader of the current settings marches the curved layer. */
  bool GetCurved() const;

  /**
   * The method the shader marches with: the property's, except that MaximumMipmap (the
   * default), whose traversal has no per-step depth to bend, marches the curved layer with
   * Relief's search (LinearSteps linear and RefinementSteps binary steps) on curved geometry
   * with SurfaceCurvature on, so a curved mesh keeps its silhouettes.
   */
  static int GetMarchMethod(vtkReliefProperty* property, bool curvedGeometry);

  /** Whether the shader recorded for this helper (cellBO) was built for another variant. */
  bool KeyChanged(const void* cellBO) const;

  /**
   * The edits before the mapper's superclass fills VTK's tags. noVTKLights: the mapper shades
   * without VTK lights (light complexity 0), so VTK declares no normal and no view-space
   * position; they are declared here.
   */
  void ReplaceValuesBefore(std::string& vs, std::string& fs, bool noVTKLights);

  /** The edits after the superclass: the relief implementation of the current variant. */
  void ReplaceValuesAfter(std::string& fs, const void* cellBO);

  /** Forget which variant each shader was built for (graphics resources released). */
  void ForgetShaders() { this->Keys.clear(); }

protected:
  vtkReliefShaderSource();
  ~vtkReliefShaderSource() override;

  std::string Key() const;

  vtkSmartPointer<vtkReliefProperty> Property;
  bool HasAlbedoTexture = false;
  bool ConePacked = false;
  bool HasLightSet = false;
  bool HasIrradianceProbes = false;
  bool CurvedGeometry = false;
  bool FloatTextures = false;
  bool StoredNormals = false;
  bool NormalMoments = false;
  bool NormalsFromDepth = false;
  std::string RadianceHookSource;
  std::string RadianceHookKey = "r"; // the source's part of Key(), computed when it changes
  std::map<const void*, std::string> Keys;

private:
  vtkReliefShaderSource(const vtkReliefShaderSource&) = delete;
  void operator=(const vtkReliefShaderSource&) = delete;
};

#endif
