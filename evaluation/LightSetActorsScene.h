// SPDX-License-Identifier: BSD-3-Clause
// The scene on which vtkLightSetLighting (ordinary VTK actors lit by a light set) is measured:
// a white Lambertian sphere, alone or above a plane, lit by an environment; drawn by VTK's
// stock mapper and by independent references (the path tracer, the exact irradiance of the
// environment map, the exact light set with exact visibility). Used by the LightSetActors tests
// and `mesolight bench light-set-actors` (docs/light-set-actors.md).
#ifndef mesolight_LightSetActorsScene_h
#define mesolight_LightSetActorsScene_h

#include "MesolightEvaluationModule.h" // for the export macro

#include "vtkObject.h"       // for LightSetActorsView
#include "vtkSmartPointer.h" // for the scene's data

#include <string>
#include <vector>

class vtkCamera;
class vtkImageData;
class vtkPolyData;
class vtkRenderWindow;

namespace mesolight
{
struct Frame;

struct LightSetActorsOptions
{
  std::string Environment = "procedural:sky"; // procedural:sky, procedural:sun or a lat-long file
  int MapWidth = 512;                         // procedural maps: width (height = width / 2)
  int Lights = 256;                           // median-cut lights
  bool Plane = false;  // a sphere above a plane (shadows) instead of a sphere alone
  int Size = 128;      // image width = height, pixels
  double Albedo = 0.8; // of every surface
};

/** How VTK draws the scene. */
struct LightSetActorsVariant
{
  int DirectionalLights = 4;
  int Remainder = 2; // vtkLightSetLighting::RemainderModes (2: spherical harmonics)
  bool Shadows = false;
  int ShadowMapResolution = 2048;
  bool HeadlightOnly = false; // WRONG ON PURPOSE: VTK's default headlight, no light set
  bool FlippedUp = false;     // WRONG ON PURPOSE: the light set read y-up (y and z swapped)
};

struct LightSetActorsScene
{
  LightSetActorsOptions Options;
  vtkSmartPointer<vtkImageData> Environment; // lat-long, +Z up
  vtkSmartPointer<vtkPolyData> Lights;       // vtkMedianCutLights output 0
  vtkSmartPointer<vtkPolyData> Geometry;     // triangles with point normals
  double Exposure = 1.0; // the brightest unshadowed radiance x Exposure is 0.85 of white
};

/** Builds the environment, its light set and the geometry; false with a message. */
MESOLIGHTEVALUATION_EXPORT bool BuildLightSetActorsScene(
  const LightSetActorsOptions& options, LightSetActorsScene& scene, std::string& error);

/** The scene's camera (the references use the same). */
MESOLIGHTEVALUATION_EXPORT void SetLightSetActorsCamera(
  const LightSetActorsOptions& options, vtkCamera* camera);

/** A window and the lighting that must live as long as it (it updates uniforms each frame). */
struct LightSetActorsView
{
  vtkSmartPointer<vtkRenderWindow> Window;
  vtkSmartPointer<vtkObject> Lighting; // vtkLightSetLighting; null for the headlight variant
};

/**
 * An offscreen window of Size x Size drawing the geometry with vtkPolyDataMapper (white
 * Lambertian, albedo Options.Albedo), lit as the variant says by vtkLightSetLighting with the
 * scene's Exposure. Window null with a message when the lighting cannot be applied.
 */
MESOLIGHTEVALUATION_EXPORT LightSetActorsView MakeLightSetActorsView(
  const LightSetActorsScene& scene, const LightSetActorsVariant& variant, std::string& error);

/**
 * References: linear radiance, 3 floats per pixel, VTK row order; -1 where the camera ray
 * misses the geometry.
 *  - PathTracedLightSetActors: the path tracer (vtkRayTracing/core/PathTracer) with the
 *    environment, direct light only (MaxDepth 1: VTK draws no interreflection), exact
 *    visibility; samplesPerPixel jittered paths.
 *  - ExactEnvironmentLightSetActors: albedo / pi x the environment map's exact irradiance
 *    (EnvironmentMaps ExactIrradiance) at the interpolated normal, without visibility: exact
 *    for a convex object alone; independent of the median cut.
 *  - ExactLightSetLightSetActors: albedo / pi x sum E_i max(0, n.d_i) over every light of the
 *    light set, each tested for visibility with an Embree shadow ray.
 */
MESOLIGHTEVALUATION_EXPORT std::vector<float> PathTracedLightSetActors(
  const LightSetActorsScene& scene, int samplesPerPixel);
MESOLIGHTEVALUATION_EXPORT std::vector<float> ExactEnvironmentLightSetActors(
  const LightSetActorsScene& scene);
MESOLIGHTEVALUATION_EXPORT std::vector<float> ExactLightSetLightSetActors(
  const LightSetActorsScene& scene);

struct LightSetActorsError
{
  double Mean = 0.0; // mean relative error over the object
  double P95 = 0.0;  // 95th percentile of the per-pixel relative error
  long long Pixels = 0;
};

/**
 * A VTK frame against a reference: per pixel covered by both (silhouette pixels, whose
 * neighbours are not all covered, left out), |frame - 255 Exposure ref| summed over RGB,
 * relative to the reference's sum, floored at 10% of the reference's mean (so dark pixels do not
 * dominate).
 */
MESOLIGHTEVALUATION_EXPORT LightSetActorsError CompareLightSetActors(
  const Frame& frame, const std::vector<float>& reference, double exposure);

/** The reference as an 8-bit frame (for PNGs of the comparison). */
MESOLIGHTEVALUATION_EXPORT Frame ReferenceFrame(
  const std::vector<float>& reference, int size, double exposure);

} // namespace mesolight

#endif
