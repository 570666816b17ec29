// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefMapper
 * @brief   Renders a coarse mesh as if it carried a fine height field, by ray marching a
 *          relief texture per fragment in tangent space.
 *
 * The relief texture (see vtkReliefTextureFilter) stores the tangent-space normal in RGB and the
 * depth in A (0 = the mesh surface, 1 = deepest), as in Méndez Fernández's thesis (§4). For each
 * fragment the mapper casts the view ray into the height field below the mesh, finds its first
 * intersection (by default exactly: maximum-mipmap tracing, Tevs, Ihrke and Seidel 2008; other
 * methods march and refine), and shades the hit point with every light
 * of the renderer, using the actor's vtkProperty (ambient, diffuse, specular, specular power) and
 * the actor's colour texture sampled at the displaced texture coordinate. Optionally it
 *  - marches toward each light for hard self-shadows (the same march, Méndez Fernández's thesis
 * §4.3),
 *  - discards fragments whose hit leaves the texture domain (silhouettes),
 *  - writes gl_FragDepth from the hit point so other geometry intersects the relief correctly.
 *
 * The settings (method, steps, depth scale, shadows, silhouettes, depth write, outputs, light-set
 * shading) are a vtkReliefProperty: mapper->GetReliefProperty()->SetMethodToRelief(), and so on.
 * Several mappers can share one property (SetReliefProperty()), as actors share a vtkProperty.
 * Methods (vtkReliefProperty lists them all, GetMethodName gives their names), among them:
 *  - MaximumMipmap (the default): exact traversal of a min-depth pyramid (Tevs, Ihrke and
 *    Seidel 2008), within LinearSteps iterations (64); docs/relief-methods.md measures it.
 *  - Relief: linear search + binary search (Policarpo et al. 2005; the thesis uses 10 + 8).
 *  - ParallaxOcclusion: linear search + one secant step between the last two samples (Tatarchuk
 *    2006).
 *  - LinearSearch ("linear"; SetMethodToSteepParallax): linear search only, steep parallax
 *    (McGuire & McGuire 2005).
 *  - TextureMapping: no march (plain texture and normal mapping); useful as a baseline.
 *
 * Geometry: any triangulated vtkPolyData with point texture coordinates. Point normals and
 * tangents are generated (vtkPolyDataNormals, vtkPolyDataTangents) when the input lacks them.
 * The world size of a texture unit and the tangent-frame handedness are taken per fragment from
 * screen-space derivatives, so non-uniform parameterizations march at the right scale.
 *
 * Units: DepthScale is dimensionless: the world depth of depth = 1 divided by the world length of
 * one unit of u (the texture's width on the mesh). The same convention is used when baking the
 * normals; if the relief texture carries a different "MesolightDepthScale" field value, the mapper
 * rescales its normals so shading stays consistent with the marched geometry.
 *
 * Shading normal: when the texture's normals are its depth's own (the Sobel normals
 * vtkReliefTextureFilter bakes at the "MesolightDepthScale" it records; checked at upload,
 * mesolight::NormalsAreTheDepths), the hit is shaded with the gradient of the surface marched, the
 * bilinear interpolation of the depth texels, as the exact CPU intersector and the path tracer's
 * dense displaced mesh shade it, and level of detail filters that surface's normals. The 3 x 3
 * Sobel stencil flattens detail a texel or two wide and brightened it (docs/relief-methods.md,
 * "The shading normal"). Normals made apart (a normal map) are shaded as given.
 *
 * The relief texture comes either as data (SetReliefTextureData), from a pipeline
 * (SetReliefTextureConnection, input port 1), or attached to the input polydata as field data
 * (vtkAttachReliefTexture); likewise the light set (input port 2). Irradiance probes (input
 * port 3, as data or from a pipeline) light it with a virtual light field's indirect light; the
 * field's emitters become VTK lights through ConfigureEmitterLight (docs/vlf.md, "On the GPU").
 *
 * Up to GetMaximumNumberOfLights() (8) of the renderer's lights are shaded; further lights are
 * ignored with a warning (a light field's emitter lights are merged down to that count,
 * vtkLightFieldReliefSurface). The relief drawing (geometry, textures, shader edits,
 * uniforms) is done by a vtkReliefShading, the same as vtkCompositeReliefMapper's.
 */

#ifndef vtkReliefMapper_h
#define vtkReliefMapper_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkNew.h"                // for Shading
#include "vtkOpenGLPolyDataMapper.h"
#include "vtkPolyData.h"       // for GetPreparedInput
#include "vtkReliefProperty.h" // for GetReliefProperty: callers set the relief through it
#include "vtkShaderProgram.h"  // for NoProgram

class vtkAlgorithmOutput;
class vtkImageData;
class vtkLight;
class vtkReliefRadianceHook;
class vtkReliefShading;

class MESOLIGHTRELIEF_EXPORT vtkReliefMapper : public vtkOpenGLPolyDataMapper
{
public:
  static vtkReliefMapper* New();
  vtkTypeMacro(vtkReliefMapper, vtkOpenGLPolyDataMapper);
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
  /**
   * The relief texture: float or unsigned char RGBA image, normal packed in RGB as (n+1)/2,
   * depth in A. Either as data or as a pipeline connection (input port 1).
   */
  void SetReliefTextureData(vtkImageData* image);
  void SetReliefTextureConnection(vtkAlgorithmOutput* output);
  vtkImageData* GetReliefTexture();
  ///@}

  /**
   * Bytes the relief's textures took on the GPU at the last render (depth, normals, cones,
   * pyramid, all mip levels, as OpenGL reports their sizes and formats); 0 before it. What is
   * uploaded depends on the method and vtkReliefProperty::FloatTextures.
   */
  vtkIdType GetReliefTextureBytes();

  ///@{
  /**
   * An image-based light set, lighting the surface besides the renderer's lights: an N x 2 float
   * image (vtkMedianCutLights' light texture), row 0 the unit directions toward the lights in
   * world coordinates, row 1 the irradiance each delivers at normal incidence (RGB). Each light
   * shades (Lambertian, albedo / pi) and self-shadows the height field. Input port 2.
   * Lit by the environment only: renderer->AutomaticLightCreationOff(), or VTK adds a headlight
   * at the first render of a renderer without lights.
   */
  void SetLightSetData(vtkImageData* lights);
  void SetLightSetConnection(vtkAlgorithmOutput* output);
  vtkImageData* GetLightSet();
  ///@}

  ///@{
  /**
   * Irradiance probes: the incident light over the relief's texture as a grid of nine-coefficient
   * spherical-harmonic radiance projections (Ramamoorthi and Hanrahan, "An efficient
   * representation for irradiance environment maps"), e.g. a virtual light field's indirect
   * light at the surface. A (9 x Nu) x Nv float image, 3 components (RGB): probe (i, j) stands at
   * texture coordinates ((i + 0.5) / Nu, (j + 0.5) / Nv) and its coefficient k (k = l^2 + l + m,
   * world coordinates, the real SH basis of FieldIrradiance.h) is pixel (9 i + k, j). The relief
   * is lit by the probes' irradiance at its perturbed normal (interpolated bilinearly between
   * probes), albedo / pi, besides the renderer's lights and the light set. Input port 3.
   * Optional parts, described in vtkIrradianceProbesTexture.h: a fourth component, a factor per
   * probe for each of the renderer's lights 0-7, and the relief's own occlusion of the probes'
   * light as a visible-share map in the field data; without the map that occlusion is not
   * modelled (the CPU evaluation's ReliefLighting::OcclusionDirections = 0). Like the light set,
   * the sum is scaled by the property's Exposure and tone mapped when ToneMapping is on (the
   * default); turn it off to read radiance. A malformed image (width not a multiple of 9, empty,
   * non-finite coefficients) is reported with an error and the relief is drawn without probes.
   */
  void SetIrradianceProbesData(vtkImageData* probes);
  void SetIrradianceProbesConnection(vtkAlgorithmOutput* output);
  vtkImageData* GetIrradianceProbes();
  ///@}

  ///@{
  /**
   * Code that changes the relief's linear radiance at its hit point (vtkReliefRadianceHook; null,
   * the default: none), e.g. a light field's movable object's shadow.
   */
  void SetRadianceHook(vtkReliefRadianceHook* hook);
  vtkReliefRadianceHook* GetRadianceHook();
  ///@}

  /**
   * Makes `light` the relief's stand-in for a small emitter of a light field (a diffuse area
   * light far from the relief compared with its size, vtkVLF's EmitterLights): a point at
   * `position` whose radiant intensity is `intensityRGB` (Le x Area) along the unit `normal` and
   * falls off as cos(theta) away from it, with 1 / d^2 attenuation. In VTK's terms a positional
   * scene light, a spot light with a 90 degree cone and exponent 1 (the cosine lobe) and
   * attenuation (0, 0, 1); colour intensityRGB / max component, intensity max component / pi.
   * The pi: VTK lights shade albedo x colour x intensity x cos (no 1 / pi), so a point at
   * distance d of normal n reflects albedo / pi x Le A cos(theta_emitter) cos(theta_n) / d^2,
   * the Lambertian radiance under that emitter, in the units of the irradiance probes' shading.
   * The relief's self-shadowing applies to it as to any VTK light.
   */
  static void ConfigureEmitterLight(vtkLight* light, const double position[3],
    const double normal[3], const double intensityRGB[3]);

  /** How many of the renderer's (or the property's) switched-on lights the relief shades: 8. */
  static int GetMaximumNumberOfLights();

  /** Includes the relief property's modification time. */
  vtkMTimeType GetMTime() override;

  void ReleaseGraphicsResources(vtkWindow* win) override;

  /**
   * Whether the relief shader of the last frame failed to compile: nothing was drawn, and the
   * GLSL compiler's message went to VTK's error output with an error of this mapper's.
   */
  vtkGetMacro(ShaderFailed, bool);

  /** The polydata actually drawn (input plus generated normals/tangents). For tests. */
  vtkPolyData* GetPreparedInput() { return this->PreparedInput; }

protected:
  vtkReliefMapper();
  ~vtkReliefMapper() override;

  int FillInputPortInformation(int port, vtkInformation* info) override;

  void RenderPieceStart(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceDraw(vtkRenderer* ren, vtkActor* act) override;
  void RenderPieceFinish(vtkRenderer* ren, vtkActor* act) override;
  bool GetNeedToRebuildShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void ReplaceShaderValues(
    std::map<vtkShader::Type, vtkShader*> shaders, vtkRenderer* ren, vtkActor* act) override;
  void SetMapperShaderParameters(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;
  void UpdateShaders(vtkOpenGLHelper& cellBO, vtkRenderer* ren, vtkActor* act) override;

  vtkNew<vtkReliefShading> Shading;
  vtkPolyData* PreparedInput = nullptr;
  bool ReadyToDraw = false;
  bool ShaderFailed = false;
  // What the failed shader was built from (ShaderInputsTime); no build is tried again before it
  // changes.
  vtkMTimeType FailedShaderInputsTime = 0;
  // Stands in for a missing program while shaders are built (UpdateShaders).
  vtkNew<vtkShaderProgram> NoProgram;

private:
  // The latest modification of anything a shader is built from: this mapper and its relief
  // property, the actor, its property and shader property, the drawn polydata.
  vtkMTimeType ShaderInputsTime(vtkActor* actor);
  // After a failed build: true while the same inputs would fail again, or the relief's shader key
  // (textures, lights, probes present) is unchanged for every primitive.
  bool ShaderStillFailing(vtkActor* actor);

  vtkReliefMapper(const vtkReliefMapper&) = delete;
  void operator=(const vtkReliefMapper&) = delete;
};

#endif
