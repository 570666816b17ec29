// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldShading (private): the light field's radiance and shadow shading, written once for
// the two mappers that draw a field, vtkLightFieldMapper (vtkLightFieldActor's) and
// vtkCompositeLightFieldMapper (ParaView's Light Field representation): the shader edits
// (glsl/vtkLightFieldFS.glsl, glsl/vtkLightFieldShadowFS.glsl), the uniforms of one draw and the
// uploads of the atlas and shadow-map textures. Not installed: it names the cores' ShadowGpuData.
#ifndef vtkLightFieldShading_h
#define vtkLightFieldShading_h

#include "vtkShader.h"       // For vtkShader::Type
#include "vtkSmartPointer.h" // For vtkSmartPointer

#include <functional> // For std::function
#include <map>        // For std::map

namespace mesolight
{
namespace vlf
{
struct ShadowGpuData;
}
}

class vtkOpenGLRenderWindow;
class vtkShaderProgram;
class vtkTextureObject;

class vtkLightFieldShading
{
public:
  /**
   * The radiance shading: the shader edits around the superclass' own (`superclass` fills VTK's
   * tags; VTK's lighting gives way to the field's radiance; vertexRadiance: the per-vertex
   * attribute mlVertexRadiance instead of the atlas, for surfaces shaded by Light Field Gather),
   * and the uniforms of one draw. shadowCode: the movable object's shadows
   * (glsl/vtkLightFieldShadowFS.glsl) are compiled in; without them mlShadowed is the identity.
   * A draw without a shadow caster must be built without: a software rasteriser (Mesa
   * llvmpipe) runs both sides of a branch under an execution mask, so the shadow loops, their
   * uniform-array reads and depth fetches cost every fragment even when mlShadowMode is 0
   * (measured: the diffuse walkthrough frame 18x the geometry mode's with them, see
   * docs/walkthrough.md).
   */
  static void ReplaceRadianceShaderValues(std::map<vtkShader::Type, vtkShader*>& shaders,
    const std::function<void()>& superclass, bool vertexRadiance, bool shadowCode);
  struct RadianceUniforms
  {
    int AtlasUnit = 0;
    int ScreenUnit = 0;
    int ScreenOrigin[2] = { 0, 0 };
    int ScreenSize[2] = { 0, 0 }; // 0 x 0: no screen-space values
    float Exposure = 1.0f;
    int ToneMap = 0;
    bool AllScreen = false;
    bool Overwrite = false;
  };
  static void SetRadianceUniforms(vtkShaderProgram* program, const RadianceUniforms& uniforms);
  /** Uploads an RGBA float atlas (creating the texture if needed); false if the upload failed. */
  static bool UploadAtlasTexture(vtkSmartPointer<vtkTextureObject>& texture,
    vtkOpenGLRenderWindow* window, int width, int height, const float* rgba);
  /**
   * The movable object's shadow maps (glsl/vtkLightFieldShadowFS.glsl): uploads the maps' depth
   * tiles (creating the texture if needed; false if the upload failed), and sets the shadow
   * uniforms of one draw (gpu null: no shadows; textureUnit then any unit holding a 2D texture,
   * e.g. the atlas').
   */
  static bool UploadShadowTexture(vtkSmartPointer<vtkTextureObject>& texture,
    vtkOpenGLRenderWindow* window, const mesolight::vlf::ShadowGpuData& gpu);
  static void SetShadowUniforms(
    vtkShaderProgram* program, const mesolight::vlf::ShadowGpuData* gpu, int textureUnit);
};

#endif
