// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkReliefShading
 * @brief   The relief drawing shared by vtkReliefMapper and vtkCompositeReliefMapper: composes
 *          the prepared geometry, the GPU textures and the shader edits, and sets the uniforms.
 *
 * A relief surface is drawn by a vtkOpenGLPolyDataMapper whose shaders are edited in two steps
 * around the superclass' own edits (ReplaceShaderValues), with extra textures bound around the
 * draw (RenderPieceStart/Finish) and extra uniforms set per draw (SetMapperShaderParameters).
 * vtkReliefMapper is such a mapper; vtkCompositeReliefMapper's helper (a
 * vtkCompositeMapperHelper2, how ParaView's geometry representations draw) is another. Both make
 * the same calls on one vtkReliefShading, so the two draw the same pixels:
 *  - BeginFrame / FrameFailed: whether a frame is tried at all (a relief texture, and no error
 *    already reported for the same inputs);
 *  - GetGeometryCache()->Prepare(input): the geometry the shader reads (vtkReliefGeometryCache);
 *  - StartDraw / FinishDraw: the relief texture and its min-depth pyramid
 *    (vtkReliefTextureCache, vtkMinDepthPyramidTexture), the light set (vtkLightSetTexture) and
 *    the irradiance probes (vtkIrradianceProbesTexture) brought up to date and bound, for the
 *    settings of a vtkReliefProperty;
 *  - ShaderKeyChanged, ReplaceShaderValuesBefore/After: the shader edits
 *    (vtkReliefShaderSource);
 *  - SetShaderParameters: the uniforms of one draw.
 * A vtkReliefRadianceHook (SetRadianceHook) takes part in the last three: bound in StartDraw, its
 * GLSL in the shader while it draws, its uniforms set with the relief's.
 * The settings are a vtkReliefProperty held here for the mapper (GetReliefProperty), which this
 * class only reads.
 */

#ifndef vtkReliefShading_h
#define vtkReliefShading_h

#include "MesolightReliefModule.h" // for export macro
#include "vtkNew.h"                // for members
#include "vtkObject.h"
#include "vtkSmartPointer.h" // for Property

#include <map>     // for FailedFrames
#include <string>  // for the shader sources
#include <utility> // for FrameInputs
#include <vector>  // for FrameInputs

class vtkActor;
class vtkImageData;
class vtkIrradianceProbesTexture;
class vtkLightSetTexture;
class vtkOpenGLRenderWindow;
class vtkReliefGeometryCache;
class vtkReliefMessageForwarder;
class vtkReliefProperty;
class vtkReliefRadianceHook;
class vtkReliefShaderSource;
class vtkReliefTextureCache;
class vtkRenderer;
class vtkShaderProgram;
class vtkWindow;

class MESOLIGHTRELIEF_EXPORT vtkReliefShading : public vtkObject
{
public:
  static vtkReliefShading* New();
  vtkTypeMacro(vtkReliefShading, vtkObject);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  /** Maximum number of VTK lights shaded per fragment; further lights are ignored with a warning.
   */
  static constexpr int MaximumNumberOfLights = 8;

  ///@{
  /**
   * The mapper's settings, behind its GetReliefProperty/SetReliefProperty/GetMTime:
   * GetReliefProperty makes a new default property (reporting to the message owner) when there is
   * none; SetReliefProperty returns whether the property changed (the mapper is then modified);
   * GetReliefPropertyMTime is 0 without a property.
   */
  vtkReliefProperty* GetReliefProperty();
  bool SetReliefProperty(vtkReliefProperty* property);
  vtkMTimeType GetReliefPropertyMTime();
  ///@}

  /** The mapper's part of its PrintSelf: its relief property (if any), then this shading. */
  void PrintForMapper(ostream& os, vtkIndent indent);

  /** The prepared copies of the mapper's inputs. */
  vtkReliefGeometryCache* GetGeometryCache();

  /** The relief's textures on the GPU (formats, bytes uploaded). */
  vtkReliefTextureCache* GetReliefTextureCache();

  ///@{
  /**
   * The frame's first check, before the geometry is prepared: false when it cannot be drawn.
   * Without a relief texture it reports that (the first thing a relief surface needs, so it is
   * what a user hears first). After a frame of the same `drawer` that failed (FrameFailed) it
   * returns false without a word while `inputs`, everything that decides whether the frame can be
   * drawn (the relief property, the polydata, the relief texture, light set, probes, albedo
   * texture and image; null entries allowed), are the same objects, unmodified: each error is
   * reported once, not at every render (an interactor or ParaView's view renders many times), and
   * again once any of them changes. `drawer` tells apart the callers sharing this shading (the
   * composite mapper's helpers, each with its own blocks); it is only compared.
   */
  bool BeginFrame(const void* drawer, vtkImageData* relief, const std::vector<vtkObject*>& inputs);
  void FrameFailed();
  ///@}

  /**
   * Uploads the relief texture, the light set and the irradiance probes (null: none) when they
   * changed, and activates the textures for a draw with these settings and this actor. False
   * (with an error) if nothing can be drawn. Malformed probes are reported and left out: the
   * relief is drawn without them.
   */
  bool StartDraw(vtkOpenGLRenderWindow* renWin, vtkReliefProperty* property, vtkImageData* relief,
    vtkImageData* lights, vtkImageData* probes, vtkActor* actor);
  /**
   * Whether the geometry of the next draws is curved (every prepared input carries quadrics,
   * vtkReliefGeometryCache::IsCurved): with the property's SurfaceCurvature, the shader then
   * marches the curved relief layer.
   */
  void SetCurvedGeometry(bool curved);

  /** Deactivates what StartDraw activated. */
  void FinishDraw();

  ///@{
  /** The shader edits of the current draw (see vtkReliefShaderSource). */
  bool ShaderKeyChanged(const void* cellBO) const;
  void ReplaceShaderValuesBefore(std::string& vs, std::string& fs, bool noVTKLights);
  void ReplaceShaderValuesAfter(std::string& fs, const void* cellBO);
  ///@}

  ///@{
  /** Code that changes the relief's radiance at its hit (null, the default: none). */
  bool SetRadianceHook(vtkReliefRadianceHook* hook);
  vtkReliefRadianceHook* GetRadianceHook();
  ///@}

  /** Uniforms of one draw (textures, settings, camera, tangent frame, VTK lights). */
  void SetShaderParameters(vtkShaderProgram* program, vtkRenderer* ren, vtkActor* actor);

  void ReleaseGraphicsResources(vtkWindow* win);

  /**
   * Errors and warnings of this shading and of the objects it composes reach observers of the
   * owner (the mapper), so users watch the mapper as before; without such observers they are
   * displayed as usual. The owner is not referenced.
   */
  void SetMessageOwner(vtkObject* owner);

protected:
  vtkReliefShading();
  ~vtkReliefShading() override;

  void SetLightUniforms(vtkShaderProgram* program, vtkRenderer* ren);

  vtkNew<vtkReliefGeometryCache> GeometryCache;
  vtkNew<vtkReliefTextureCache> ReliefTexture;
  vtkNew<vtkLightSetTexture> LightSet;
  vtkNew<vtkIrradianceProbesTexture> Probes;
  vtkNew<vtkReliefShaderSource> ShaderSource;
  vtkNew<vtkReliefMessageForwarder> Messages;

  vtkSmartPointer<vtkReliefProperty> ReliefProperty; // the mapper's settings
  vtkSmartPointer<vtkReliefProperty> Property;       // the settings of the current draw
  vtkSmartPointer<vtkReliefRadianceHook> RadianceHook;
  bool RadianceHookActive = false; // the hook takes part in the current draw
  bool Drawing = false;
  bool PyramidActive = false;
  bool LightSetActive = false;
  bool ProbesActive = false;
  bool WarnedTooManyLights = false;
  // The albedo texture image last checked for NaN/Inf texels, and when (its MTime).
  vtkImageData* CheckedAlbedo = nullptr;
  vtkMTimeType CheckedAlbedoTime = 0;
  // The drawer and inputs of the frame under way (BeginFrame), and per drawer the inputs of its
  // last frame if it failed: each object's address (only compared) and modification time.
  using FrameInputList = std::vector<std::pair<const void*, vtkMTimeType>>;
  const void* FrameDrawer = nullptr;
  FrameInputList FrameInputs;
  std::map<const void*, FrameInputList> FailedFrames;

private:
  vtkReliefShading(const vtkReliefShading&) = delete;
  void operator=(const vtkReliefShading&) = delete;
};

#endif
