// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightSetLighting
 * @brief   lights ordinary VTK actors by a light set (median-cut lights of an environment)
 *
 * vtkLightSetLighting takes a light set (output port 0 of vtkMedianCutLights or
 * vtkLightSetReader: one vertex per light at its unit direction, point data "Irradiance")
 * and applies it to a vtkRenderer, so that surfaces drawn by VTK's own OpenGL polydata mappers
 * (measured with vtkPolyDataMapper; its OpenGL subclasses get the same shader edit) are lit by
 * the same environment as relief surfaces:
 *  - the NumberOfDirectionalLights lights of largest luminance become directional scene
 *    vtkLights (SetPositional(false)) whose colour x intensity is Exposure x Irradiance / pi, so
 *    a white Lambertian surface (Diffuse 1, DiffuseColor 1) shows Exposure x albedo / pi x E,
 *    E = sum E_i max(0, n.d_i): the radiance the path tracer computes, scaled by Exposure;
 *  - the other lights become one low-frequency term (core/LightSetSplit.h): by default their
 *    9-coefficient spherical-harmonic irradiance, added in the fragment shader of every lit
 *    actor (a vtkShaderProperty replacement after VTK's lighting, scaled by the actor's diffuse
 *    colour, so colour textures and scalars are lit too); or a constant (their average over all
 *    normals); or nothing;
 *  - with Shadows on, the renderer draws with vtkShadowMapPass: every directional light casts a
 *    shadow map (vtkShadowMapBakerPass bakes directional lights as well as spot lights). The
 *    remainder casts no shadow. Apply() then sets the renderer's render pass (a vtkCameraPass
 *    over the baker and the shadow pass, as VTK's own shadow example does), replacing one the
 *    renderer had; that pass draws opaque geometry only (lights + opaque pass), no translucent
 *    props, volumes or overlays. Apply() with Shadows off removes the pass it set.
 * Why this split and how good it is against the path tracer: docs/light-set-actors.md.
 *
 * Apply() replaces the renderer's lights (automatic light creation is turned off) and injects
 * the remainder into the actors present then (call it again after adding actors, or
 * ApplyToActor()). Actors with lighting off and vtkReliefMapper actors (they take the light set
 * themselves, vtkReliefMapper::SetLightSetConnection) get no shader replacement. The
 * replacement of "//VTK::Light::Impl" replaces one the actor's shader property had for that tag.
 *
 * Errors (vtkErrorMacro, Apply returns false, the renderer is left unchanged): no light set; a
 * light set without points or without a 3-component "Irradiance" array of one tuple per point;
 * non-finite or negative values.
 */
#ifndef vtkLightSetLighting_h
#define vtkLightSetLighting_h

#include "MesolightLightingModule.h" // For export macro
#include "vtkObject.h"

#include <memory> // For std::unique_ptr

class vtkActor;
class vtkPolyData;
class vtkRenderer;

class MESOLIGHTLIGHTING_EXPORT vtkLightSetLighting : public vtkObject
{
public:
  static vtkLightSetLighting* New();
  vtkTypeMacro(vtkLightSetLighting, vtkObject)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum RemainderModes
  {
    RemainderNone = 0,
    RemainderAmbient = 1,
    RemainderSphericalHarmonics = 2
  };

  ///@{
  /** The light set: vtkMedianCutLights' or vtkLightSetReader's output port 0. */
  void SetLightSet(vtkPolyData* lights);
  vtkPolyData* GetLightSet();
  ///@}

  ///@{
  /** Lights drawn as directional vtkLights (the strongest). Default 4. */
  vtkSetClampMacro(NumberOfDirectionalLights, int, 0, 64);
  vtkGetMacro(NumberOfDirectionalLights, int);
  ///@}

  ///@{
  /** How the other lights are drawn. Default RemainderSphericalHarmonics. */
  vtkSetClampMacro(Remainder, int, RemainderNone, RemainderSphericalHarmonics);
  vtkGetMacro(Remainder, int);
  void SetRemainderToNone() { this->SetRemainder(RemainderNone); }
  void SetRemainderToAmbient() { this->SetRemainder(RemainderAmbient); }
  void SetRemainderToSphericalHarmonics() { this->SetRemainder(RemainderSphericalHarmonics); }
  ///@}

  ///@{
  /** Scale of the lighting (the relief mapper's Exposure). Default 1. */
  vtkSetClampMacro(Exposure, double, 0.0, 1e30);
  vtkGetMacro(Exposure, double);
  ///@}

  ///@{
  /** Shadow maps for the directional lights (vtkShadowMapPass). Default off. */
  vtkSetMacro(Shadows, bool);
  vtkGetMacro(Shadows, bool);
  vtkBooleanMacro(Shadows, bool);
  ///@}

  ///@{
  /** Shadow map size in texels. Default 1024. */
  vtkSetClampMacro(ShadowMapResolution, int, 16, 8192);
  vtkGetMacro(ShadowMapResolution, int);
  ///@}

  /** Lights the renderer and its actors. False with an error when the light set is unusable. */
  bool Apply(vtkRenderer* renderer);

  /** Adds the remainder term to one more actor of a renderer already passed to Apply(). */
  void ApplyToActor(vtkActor* actor);

  /**
   * Irradiance the applied lighting gives a surface of unit normal n without shadows (the K
   * lights plus the remainder, before Exposure): a Lambertian surface of albedo a shows
   * Exposure x a / pi x this. False when the light set is unusable.
   */
  bool EvaluateIrradiance(const double n[3], double e[3]);

protected:
  vtkLightSetLighting();
  ~vtkLightSetLighting() override;

  int NumberOfDirectionalLights = 4;
  int Remainder = RemainderSphericalHarmonics;
  double Exposure = 1.0;
  bool Shadows = false;
  int ShadowMapResolution = 1024;

private:
  struct Internals;
  std::unique_ptr<Internals> Internal;
  // Reads and splits the light set; false with an error.
  bool Split();
  // Sets the view rotation uniform of every injected actor (each frame, on StartEvent).
  void UpdateViewUniforms();

  vtkLightSetLighting(const vtkLightSetLighting&) = delete;
  void operator=(const vtkLightSetLighting&) = delete;
};

#endif
