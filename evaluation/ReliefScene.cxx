// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefScene.h"

#include "vtkConeMapFilter.h"
#include "vtkHeightFieldMeshFilter.h"
#include "vtkLightSetReader.h"
#include "vtkMedianCutLights.h"
#include "vtkMessageCollector.h"
#include "vtkOIIOImageReader.h"
#include "vtkProceduralEnvironmentSource.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefMapper.h"
#include "vtkReliefPlaneFilter.h"
#include "vtkReliefTextureFilter.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkMapper.h>
#include <vtkMath.h>
#include <vtkMatrix4x4.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <sstream>
#include <string>

namespace mesolight
{
namespace
{
// The coarse wall: a few quads spanning the texel centres of the relief texture, exactly the
// extent of the dense reference mesh (one vertex per texel centre), with u,v = texture position.
vtkSmartPointer<vtkPolyData> MakeWall(vtkImageData* relief)
{
  int dims[3];
  relief->GetDimensions(dims);
  const double h = vtkReliefPlaneFilter::GetGroundProportions(relief);
  const double du = 0.5 / dims[0], dv = 0.5 / dims[1];
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(du, dv * h, 0.0);
  plane->SetPoint1(1.0 - du, dv * h, 0.0);
  plane->SetPoint2(du, (1.0 - dv) * h, 0.0);
  plane->SetResolution(4, 4);
  plane->Update();
  auto wall = vtkSmartPointer<vtkPolyData>::New();
  wall->DeepCopy(plane->GetOutput());
  vtkDataArray* tcoords = wall->GetPointData()->GetTCoords();
  if (!tcoords)
  {
    return nullptr; // a degenerate plane: BuildReliefTextures refuses such textures first
  }
  for (vtkIdType i = 0; i < tcoords->GetNumberOfTuples(); ++i)
  {
    tcoords->SetComponent(i, 0, du + tcoords->GetComponent(i, 0) * (1.0 - 2.0 * du));
    tcoords->SetComponent(i, 1, dv + tcoords->GetComponent(i, 1) * (1.0 - 2.0 * dv));
  }
  return wall;
}

void ApplyMaterial(vtkActor* actor);

// The options with the depth scale the relief texture was baked with: DepthScale, or a DEM's
// true vertical scale times VerticalExaggeration.
ReliefSceneOptions WithBakedDepthScale(const ReliefSceneOptions& options, vtkImageData* relief)
{
  ReliefSceneOptions baked = options;
  vtkDataArray* scale = relief ? relief->GetFieldData()->GetArray("MesolightDepthScale") : nullptr;
  if (options.VerticalExaggeration > 0.0 && scale && scale->GetNumberOfTuples() == 1)
  {
    baked.DepthScale = scale->GetComponent(0, 0);
  }
  return baked;
}

// Every scene variant: the same actor material, albedo, camera and lights.
void FinishScene(const ReliefSceneOptions& options, vtkMapper* mapper, ReliefScene& scene)
{
  scene.Actor = vtkSmartPointer<vtkActor>::New();
  scene.Actor->SetMapper(mapper);
  scene.Actor->SetTexture(scene.Albedo);
  ApplyMaterial(scene.Actor);
  scene.Renderer = vtkSmartPointer<vtkRenderer>::New();
  scene.Renderer->AddActor(scene.Actor);
  SetupCameraAndLights(
    options, scene.Renderer, vtkReliefPlaneFilter::GetGroundProportions(scene.ReliefTexture));
}

void ApplyMaterial(vtkActor* actor)
{
  vtkProperty* property = actor->GetProperty();
  property->SetColor(1.0, 1.0, 1.0);
  property->SetAmbient(0.08);
  property->SetDiffuse(0.9);
  property->SetSpecular(0.15);
  property->SetSpecularPower(24.0);
}
} // namespace

//------------------------------------------------------------------------------
bool BuildReliefTextures(const ReliefSceneOptions& options, vtkSmartPointer<vtkImageData>& relief,
  vtkSmartPointer<vtkTexture>& albedo, std::string& error, int coneMap)
{
  vtkNew<MessageCollector> errors;
  vtkNew<vtkReliefTextureFilter> bake;
  bake->AddObserver(vtkCommand::ErrorEvent, errors);
  bake->SetDepthScale(options.DepthScale);
  vtkNew<vtkProceduralReliefSource> source;
  source->AddObserver(vtkCommand::ErrorEvent, errors);
  vtkNew<vtkOIIOImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);

  albedo = vtkSmartPointer<vtkTexture>::New();
  albedo->InterpolateOn();
  albedo->MipmapOn();
  albedo->RepeatOff();
  albedo->EdgeClampOn();

  if (!options.DepthFile.empty())
  {
    reader->SetFileName(options.DepthFile.c_str());
    bake->SetInputConnection(reader->GetOutputPort());
    bake->SetInvertInput(options.DepthFileIsHeight);
    bake->SetNormalizeRange(options.NormalizeDepthFile);
    bake->SetUseNoDataValue(options.UseNoDataValue);
    bake->SetNoDataValue(options.NoDataValue);
    bake->SetUseInputNoDataValue(options.UseFileNoDataValue);
    bake->SetUseTrueDepthScale(options.VerticalExaggeration > 0.0);
    bake->SetVerticalExaggeration(options.VerticalExaggeration);
    // A depth file comes without colour: a light grey albedo shows the relief itself.
    vtkNew<vtkImageData> grey;
    grey->SetDimensions(1, 1, 1);
    grey->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    auto* px = static_cast<unsigned char*>(grey->GetScalarPointer());
    px[0] = px[1] = px[2] = 200;
    albedo->SetInputData(grey);
  }
  else
  {
    if (!source->SetPatternByName(options.Pattern.c_str()))
    {
      error = "unknown pattern '" + options.Pattern + "'";
      return false;
    }
    source->SetResolution(options.Resolution, options.Resolution);
    bake->SetInputConnection(source->GetOutputPort(0));
    source->Update();
    vtkNew<vtkImageData> albedoImage;
    albedoImage->DeepCopy(source->GetOutput(1));
    albedo->SetInputData(albedoImage);
  }
  bake->Update();
  if (!errors->Errors.empty() || !bake->GetOutput() || bake->GetOutput()->GetNumberOfPoints() == 0)
  {
    error = errors->Errors.empty() ? "could not bake the relief texture" : errors->ErrorText();
    return false;
  }
  int dims[3];
  bake->GetOutput()->GetDimensions(dims);
  if (dims[0] < 2 || dims[1] < 2)
  {
    // The wall spans the texel centres: one texel across leaves a plane of zero width.
    error = "the relief texture is " + std::to_string(dims[0]) + "x" + std::to_string(dims[1]) +
      " texels; a relief wall needs at least 2x2";
    return false;
  }
  relief = vtkSmartPointer<vtkImageData>::New();
  relief->DeepCopy(bake->GetOutput());
  if (coneMap != vtkReliefProperty::NoConeMap)
  {
    vtkNew<vtkConeMapFilter> cones;
    cones->AddObserver(vtkCommand::ErrorEvent, errors);
    cones->SetInputData(relief);
    cones->SetDepthScale(bake->GetAppliedDepthScale()); // the relief texture's normals, kept
    if (coneMap == vtkReliefProperty::ConservativeConeMap)
    {
      cones->SetConeTypeToConservative();
    }
    else
    {
      cones->SetConeTypeToRelaxed();
    }
    cones->Update();
    if (!errors->Errors.empty())
    {
      error = errors->ErrorText();
      return false;
    }
    relief = vtkSmartPointer<vtkImageData>::New();
    relief->DeepCopy(cones->GetOutput());
  }
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> LoadEnvironment(const std::string& spec, std::string& error)
{
  vtkNew<MessageCollector> errors;
  auto map = vtkSmartPointer<vtkImageData>::New();
  if (spec == "procedural:sky" || spec == "procedural:sun")
  {
    vtkNew<vtkProceduralEnvironmentSource> sky;
    sky->SetResolution(1024, 512);
    if (spec == "procedural:sun")
    {
      sky->SetMapToSunSky();
    }
    sky->Update();
    map->DeepCopy(sky->GetOutput());
    return map;
  }
  if (spec.rfind("procedural:", 0) == 0)
  {
    error = "unknown procedural map '" + spec + "' (expected procedural:sky or procedural:sun)";
    return nullptr;
  }
  vtkNew<vtkOIIOImageReader> reader;
  reader->AddObserver(vtkCommand::ErrorEvent, errors);
  reader->SetFileName(spec.c_str());
  reader->Update();
  if (!errors->Errors.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
  {
    error = errors->Errors.empty() ? "could not read the environment " + spec : errors->ErrorText();
    return nullptr;
  }
  map->DeepCopy(reader->GetOutput());
  return map;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkImageData> MakeEnvironmentLights(
  const ReliefSceneOptions& options, std::string& error)
{
  vtkSmartPointer<vtkImageData> map = LoadEnvironment(options.Environment, error);
  if (!map)
  {
    return nullptr;
  }
  vtkNew<MessageCollector> errors;
  vtkNew<vtkMedianCutLights> cut;
  cut->AddObserver(vtkCommand::ErrorEvent, errors);
  cut->SetInputData(map);
  cut->SetNumberOfLights(options.EnvironmentLights);
  cut->SetVarianceMinimization(options.EnvironmentVarianceCuts);
  cut->Update();
  if (!errors->Errors.empty() || !cut->GetLightTexture())
  {
    error = errors->Errors.empty() ? "median cut failed" : errors->ErrorText();
    return nullptr;
  }
  auto lights = vtkSmartPointer<vtkImageData>::New();
  lights->DeepCopy(cut->GetLightTexture());
  return lights;
}

//------------------------------------------------------------------------------
static void FillViewportWithWall(vtkCamera* camera, double height, double depthScale)
{
  // Bounding box, in normalized device coordinates at aspect 1, of the wall's box (the relief
  // reaches depthScale below it). It is a convex solid, so its 8 corners bound the projection.
  camera->UseExplicitAspectRatioOn();
  camera->SetExplicitAspectRatio(1.0);
  vtkMatrix4x4* m = camera->GetCompositeProjectionTransformMatrix(1.0, -1.0, 1.0);
  double lo[2] = { VTK_DOUBLE_MAX, VTK_DOUBLE_MAX };
  double hi[2] = { -VTK_DOUBLE_MAX, -VTK_DOUBLE_MAX };
  for (int corner = 0; corner < 8; ++corner)
  {
    const double p[4] = { double(corner & 1), (corner & 2) ? height : 0.0,
      (corner & 4) ? -depthScale : 0.0, 1.0 };
    double q[4];
    m->MultiplyPoint(p, q);
    for (int k = 0; k < 2; ++k)
    {
      const double ndc = q[k] / q[3];
      lo[k] = std::min(lo[k], ndc);
      hi[k] = std::max(hi[k], ndc);
    }
  }
  // Half extents with a 2% margin, so silhouettes stay inside the frame.
  const double sx = 0.51 * (hi[0] - lo[0]);
  const double sy = 0.51 * (hi[1] - lo[1]);
  if (!(sx > 1e-6 && sy > 1e-6))
  {
    camera->UseExplicitAspectRatioOff();
    return;
  }
  // Narrowing the vertical view angle by sy scales NDC by 1 / sy; the aspect ratio sx / sy maps
  // the horizontal extent to [-1, 1]; the window centre (in NDC of the new frustum) recentres.
  const double halfAngle =
    std::atan(std::tan(vtkMath::RadiansFromDegrees(0.5 * camera->GetViewAngle())) * sy);
  camera->SetViewAngle(2.0 * vtkMath::DegreesFromRadians(halfAngle));
  camera->SetExplicitAspectRatio(sx / sy);
  camera->SetWindowCenter(0.5 * (lo[0] + hi[0]) / sx, 0.5 * (lo[1] + hi[1]) / sy);
}

//------------------------------------------------------------------------------
void SetupCameraAndLights(const ReliefSceneOptions& options, vtkRenderer* renderer, double height)
{
  // Aim at the wall's centre from ViewAngle off its normal, turned by ViewAzimuth about it.
  const double centre[3] = { 0.5, 0.5 * height, 0.0 };
  const double a = vtkMath::RadiansFromDegrees(options.ViewAngle);
  const double b = vtkMath::RadiansFromDegrees(options.ViewAzimuth);
  const double d = options.ViewDistance * std::max(1.0, height); // the whole of a tall wall in view
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetFocalPoint(centre);
  camera->SetPosition(centre[0] + d * std::sin(a) * std::sin(b),
    centre[1] - d * std::sin(a) * std::cos(b), centre[2] + d * std::cos(a));
  camera->SetViewUp(0.0, 0.0, 1.0);
  if (options.ViewAngle < 1.0)
  {
    camera->SetViewUp(0.0, 1.0, 0.0);
  }
  camera->SetViewAngle(30.0);
  // The same clipping range for every variant, so depth buffers compare.
  camera->SetClippingRange(0.25 * d, 2.5 * d);
  camera->SetWindowCenter(0.0, 0.0);
  camera->UseExplicitAspectRatioOff();
  if (options.FillViewport)
  {
    FillViewportWithWall(camera, height, options.DepthScale);
  }

  renderer->SetBackground(0.08, 0.09, 0.11);
  renderer->RemoveAllLights();
  renderer->AutomaticLightCreationOff();
  if (options.Lights < 1)
  {
    return;
  }
  const double e = vtkMath::RadiansFromDegrees(options.LightElevation);
  vtkNew<vtkLight> key;
  key->SetLightTypeToSceneLight();
  key->PositionalOff();
  key->SetFocalPoint(centre);
  key->SetPosition(centre[0] - std::cos(e) * 0.8, centre[1] + std::cos(e) * 0.6, std::sin(e));
  key->SetColor(1.0, 0.96, 0.9);
  key->SetIntensity(1.0);
  renderer->AddLight(key);
  if (options.Lights > 1)
  {
    vtkNew<vtkLight> fill;
    fill->SetLightTypeToSceneLight();
    fill->PositionalOff();
    fill->SetFocalPoint(centre);
    fill->SetPosition(centre[0] + 0.5, centre[1] - 0.7, 0.9);
    fill->SetColor(0.75, 0.85, 1.0);
    fill->SetIntensity(0.3);
    renderer->AddLight(fill);
  }
}

//------------------------------------------------------------------------------
bool BuildReliefScene(const ReliefSceneOptions& requested, ReliefScene& scene, std::string& error)
{
  const int method = vtkReliefProperty::GetMethodFromName(requested.Method.c_str());
  if (method < 0)
  {
    error = "unknown method '" + requested.Method + "'";
    return false;
  }
  if (!BuildReliefTextures(requested, scene.ReliefTexture, scene.Albedo, error,
        vtkReliefProperty::GetRequiredConeMap(method)))
  {
    return false;
  }
  const ReliefSceneOptions options = WithBakedDepthScale(requested, scene.ReliefTexture);
  vtkSmartPointer<vtkPolyData> wall = MakeWall(scene.ReliefTexture);
  if (!wall)
  {
    error = "could not build the wall for the relief texture";
    return false;
  }
  scene.Mapper = vtkSmartPointer<vtkReliefMapper>::New();
  scene.Mapper->SetInputData(wall);
  scene.Mapper->SetReliefTextureData(scene.ReliefTexture);
  scene.Mapper->GetReliefProperty()->SetMethod(method);
  scene.Mapper->GetReliefProperty()->SetDepthScale(options.DepthScale);
  scene.Mapper->GetReliefProperty()->SetLinearSteps(options.LinearSteps);
  scene.Mapper->GetReliefProperty()->SetRefinementSteps(options.RefinementSteps);
  scene.Mapper->GetReliefProperty()->SetSelfShadowing(options.SelfShadowing);
  scene.Mapper->GetReliefProperty()->SetSilhouettes(options.Silhouettes);
  scene.Mapper->GetReliefProperty()->SetSurfaceCurvature(options.SurfaceCurvature);
  scene.Mapper->GetReliefProperty()->SetWriteDepth(options.WriteDepth);
  scene.Mapper->GetReliefProperty()->SetAdaptiveSteps(options.AdaptiveSteps);
  scene.Mapper->GetReliefProperty()->SetLevelOfDetail(options.LevelOfDetail);
  if (options.NormalFilter >= 0)
  {
    scene.Mapper->GetReliefProperty()->SetNormalFilter(options.NormalFilter);
  }
  if (options.FarViewRays > 0)
  {
    scene.Mapper->GetReliefProperty()->SetFarViewRays(options.FarViewRays);
  }
  scene.Mapper->GetReliefProperty()->SetExposure(options.Exposure);
  scene.Mapper->GetReliefProperty()->SetToneMapping(options.ToneMapping);
  if (!options.Environment.empty())
  {
    scene.LightSet = options.EnvironmentLightSet ? options.EnvironmentLightSet
                                                 : MakeEnvironmentLights(options, error);
    if (!scene.LightSet)
    {
      return false;
    }
    scene.Mapper->SetLightSetData(scene.LightSet);
  }
  else if (!options.LightsCsv.empty())
  {
    vtkNew<MessageCollector> errors;
    vtkNew<vtkLightSetReader> reader;
    reader->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkNew<MessageCollector> executiveNoise; // the executive's "returned failure" follow-up
    reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, executiveNoise);
    reader->SetFileName(options.LightsCsv.c_str());
    reader->Update();
    if (!errors->Errors.empty() || reader->GetOutput()->GetNumberOfPoints() == 0)
    {
      error = errors->Errors.empty() ? "could not read " + options.LightsCsv : errors->ErrorText();
      return false;
    }
    scene.LightSet = vtkSmartPointer<vtkImageData>::New();
    scene.LightSet->DeepCopy(reader->GetLightTexture());
    scene.Mapper->SetLightSetData(scene.LightSet);
  }

  FinishScene(options, scene.Mapper, scene);
  return true;
}

//------------------------------------------------------------------------------
bool BuildDenseReferenceScene(
  const ReliefSceneOptions& requested, ReliefScene& scene, std::string& error)
{
  if (!BuildReliefTextures(requested, scene.ReliefTexture, scene.Albedo, error))
  {
    return false;
  }
  const ReliefSceneOptions options = WithBakedDepthScale(requested, scene.ReliefTexture);
  vtkNew<vtkHeightFieldMeshFilter> dense;
  dense->SetInputData(scene.ReliefTexture);
  dense->SetOrigin(0.0, 0.0, 0.0);
  dense->SetPoint1(1.0, 0.0, 0.0);
  dense->SetPoint2(0.0, vtkReliefPlaneFilter::GetGroundProportions(scene.ReliefTexture), 0.0);
  dense->SquareTexelsOff(); // the wall's own proportions, as the relief's (a map's on the ground)
  dense->UseInputDepthScaleOff();
  dense->SetDepthScale(options.DepthScale);
  dense->Update();
  // Shaded with its triangles' own normals (VTK derives them per fragment when the mesh has
  // none), as the path tracer shades it and as the relief mapper shades the surface it marches.
  vtkNew<vtkPolyData> mesh;
  mesh->ShallowCopy(dense->GetOutput());
  mesh->GetPointData()->RemoveArray("Normals");

  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(mesh);
  mapper->ScalarVisibilityOff();
  scene.Mapper = nullptr;
  FinishScene(options, mapper, scene);
  return true;
}

//------------------------------------------------------------------------------
bool BuildTexturedPlaneScene(
  const ReliefSceneOptions& options, ReliefScene& scene, std::string& error)
{
  if (!BuildReliefTextures(options, scene.ReliefTexture, scene.Albedo, error))
  {
    return false;
  }
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(MakeWall(scene.ReliefTexture));
  scene.Mapper = nullptr;
  FinishScene(options, mapper, scene);
  return true;
}

//------------------------------------------------------------------------------
vtkSmartPointer<vtkRenderWindow> MakeOffscreenWindow(
  const ReliefSceneOptions& options, vtkRenderer* renderer)
{
  auto window = vtkSmartPointer<vtkRenderWindow>::New();
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(options.Width, options.Height);
  window->AddRenderer(renderer);
  return window;
}

//------------------------------------------------------------------------------
bool HasDisplay()
{
  const char* display = std::getenv("DISPLAY");
  return display && display[0] != '\0';
}

} // namespace mesolight
