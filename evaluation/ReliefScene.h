// SPDX-License-Identifier: BSD-3-Clause
// The default relief scene of the `mesolight` tool, and its independent reference.
//
// One description (ReliefSceneOptions) builds two renderings of the same height field:
//  - the relief surface: a coarse plane drawn by vtkReliefMapper with a relief texture;
//  - the dense reference: one vertex per texel (vtkHeightFieldMeshFilter) drawn by VTK's stock
//    mapper with the same albedo texture, normals, lights and camera.
// The tool renders the first; tests and benchmarks compare the two.
#ifndef mesolight_ReliefScene_h
#define mesolight_ReliefScene_h

#include "MesolightEvaluationModule.h" // for the export macro

#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>

#include <string>

namespace mesolight
{

struct ReliefSceneOptions
{
  std::string Pattern = "Bricks";  // vtkProceduralReliefSource pattern name
  std::string DepthFile;           // a depth image instead of the procedural pattern
  bool DepthFileIsHeight = false;  // the file stores height (white = high), not depth
  bool NormalizeDepthFile = false; // stretch the file's value range to [0, 1] (DEMs in metres)
  bool UseNoDataValue = false;     // texels holding NoDataValue have no data (DEMs)
  double NoDataValue = 0.0;
  bool UseFileNoDataValue = true; // else the value a GeoTIFF names (GDAL_NODATA) is data too
  int Resolution = 512;           // texels per side of the procedural map
  double DepthScale = 0.04;       // world depth of depth 1 / world width of the wall
  // > 0: a georeferenced elevation map at its true vertical scale times this, in place of
  // DepthScale (vtkReliefTextureFilter::UseTrueDepthScale; needs NormalizeDepthFile).
  double VerticalExaggeration = 0.0;
  std::string Method = "relief"; // vtkReliefMapper::SetMethodByName
  int LinearSteps = 10;
  int RefinementSteps = 8;
  bool SelfShadowing = true;
  bool Silhouettes = true;
  bool SurfaceCurvature = true; // the curved-mesh march on curved meshes (vtkReliefProperty)
  bool WriteDepth = true;
  bool AdaptiveSteps = false;
  bool LevelOfDetail = false;
  int NormalFilter = -1; // vtkReliefProperty::NormalFilterKind; -1: the property's default
  int FarViewRays = 0;   // vtkReliefProperty::FarViewRays; 0: the property's default
  int Width = 800;
  int Height = 800;
  double ViewAngle = 55.0; // camera angle from the wall's normal, degrees
  double ViewAzimuth = 20.0;
  double ViewDistance = 2.6; // in wall widths (heights for a wall taller than wide)
  // Stretch and centre the projection so the wall's footprint (relief depth included) fills the
  // viewport: at grazing angles the wall is otherwise a thin strip of the frame, and a frame time
  // would measure mostly the fixed per-frame cost, not the march. Pixels are then not square.
  bool FillViewport = false;
  int Lights = 2; // 0: none; 1: key light; 2: key + fill
  // Image-based lighting: "" (none), "procedural:sky", "procedural:sun" or an HDR file; its
  // median-cut lights light the relief (vtkReliefMapper light set).
  std::string Environment;
  int EnvironmentLights = 128;
  bool EnvironmentVarianceCuts = true; // vtkMedianCutLights' default; false: even-energy cuts
  // The environment's light set when already made (MakeEnvironmentLights from these options):
  // scenes built from it share one median cut, and its warnings are reported once.
  vtkSmartPointer<vtkImageData> EnvironmentLightSet;
  // A light set written by `mesolight lights` (CSV, vtkLightSetReader) instead of Environment.
  std::string LightsCsv;
  double Exposure = 1.0;
  bool ToneMapping = false;
  double LightElevation = 35.0; // key light elevation above the wall, degrees
};

/** The pieces of a built scene, for callers that change them interactively. */
struct ReliefScene
{
  vtkSmartPointer<vtkRenderer> Renderer;
  vtkSmartPointer<vtkActor> Actor;
  vtkSmartPointer<vtkReliefMapper> Mapper;     // null for the dense reference
  vtkSmartPointer<vtkImageData> ReliefTexture; // normal + depth, as uploaded
  vtkSmartPointer<vtkTexture> Albedo;
  vtkSmartPointer<vtkImageData> LightSet; // median-cut lights of the environment, if any
};

/** An environment map: "procedural:sky", "procedural:sun" or an HDR file (lat-long). */
MESOLIGHTEVALUATION_EXPORT vtkSmartPointer<vtkImageData> LoadEnvironment(
  const std::string& spec, std::string& error);

/** The options' environment as a light set (vtkMedianCutLights' N x 2 light texture). */
MESOLIGHTEVALUATION_EXPORT vtkSmartPointer<vtkImageData> MakeEnvironmentLights(
  const ReliefSceneOptions& options, std::string& error);

/**
 * Builds the relief texture and albedo described by the options; with a cone map kind
 * (vtkReliefMapper::ConeMapKind) the texture is vtkConeMapFilter's cone-packed one. Returns false
 * and fills error when the depth file cannot be read or the texture cannot be baked.
 */
MESOLIGHTEVALUATION_EXPORT bool BuildReliefTextures(const ReliefSceneOptions& options,
  vtkSmartPointer<vtkImageData>& relief, vtkSmartPointer<vtkTexture>& albedo, std::string& error,
  int coneMap = vtkReliefProperty::NoConeMap);

/** The relief scene: a coarse plane with vtkReliefMapper. */
MESOLIGHTEVALUATION_EXPORT bool BuildReliefScene(
  const ReliefSceneOptions& options, ReliefScene& scene, std::string& error);

/** The same scene as a dense displaced mesh drawn by the stock mapper (the reference). */
MESOLIGHTEVALUATION_EXPORT bool BuildDenseReferenceScene(
  const ReliefSceneOptions& options, ReliefScene& scene, std::string& error);

/** The same scene as a plain textured plane (stock mapper, no relief): the cheapest baseline. */
MESOLIGHTEVALUATION_EXPORT bool BuildTexturedPlaneScene(
  const ReliefSceneOptions& options, ReliefScene& scene, std::string& error);

/**
 * Places camera and lights as the options say, aimed at the middle of a wall `wallHeight` high
 * for a width of 1 (the relief texture's vtkReliefPlaneFilter::GetGroundProportions, as every
 * scene variant and the CPU references take it); every scene variant uses this.
 */
MESOLIGHTEVALUATION_EXPORT void SetupCameraAndLights(
  const ReliefSceneOptions& options, vtkRenderer* renderer, double wallHeight = 1.0);

/** An offscreen window of the options' size holding the renderer. */
MESOLIGHTEVALUATION_EXPORT vtkSmartPointer<vtkRenderWindow> MakeOffscreenWindow(
  const ReliefSceneOptions& options, vtkRenderer* renderer);

/** Whether an X display is available for an interactive window. */
MESOLIGHTEVALUATION_EXPORT bool HasDisplay();

} // namespace mesolight

#endif
