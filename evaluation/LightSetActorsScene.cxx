// SPDX-License-Identifier: BSD-3-Clause
#include "LightSetActorsScene.h"

#include "EmbreeScene.h"
#include "EnvironmentMaps.h"
#include "ImageCompare.h"
#include "LightSetSplit.h"
#include "MathConstants.h"
#include "ParallelFor.h"
#include "PathTracer.h"
#include "PinholeCamera.h"
#include "ReliefScene.h"
#include "TriangleScene.h"
#include "vtkLightSetLighting.h"
#include "vtkMedianCutLights.h"
#include "vtkProceduralEnvironmentSource.h"
#include "vtkTriangleSceneConverter.h"

#include <vtkActor.h>
#include <vtkAppendPolyData.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTriangleFilter.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mesolight
{
namespace
{
vtkSmartPointer<vtkImageData> Environment(const LightSetActorsOptions& o, std::string& error)
{
  if (o.Environment == "procedural:sky" || o.Environment == "procedural:sun")
  {
    vtkNew<vtkProceduralEnvironmentSource> sky;
    sky->SetResolution(o.MapWidth, o.MapWidth / 2);
    if (o.Environment == "procedural:sun")
    {
      sky->SetMapToSunSky();
      sky->WindowOn();
    }
    sky->Update();
    auto map = vtkSmartPointer<vtkImageData>::New();
    map->DeepCopy(sky->GetOutput());
    return map;
  }
  return LoadEnvironment(o.Environment, error);
}

RgbImage ToRgb(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  RgbImage out(dims[0], dims[1]);
  vtkDataArray* s = image->GetPointData()->GetScalars();
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1];
  for (vtkIdType k = 0; k < n; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.Rgb[3 * k + c] = static_cast<float>(s->GetComponent(k, c));
    }
  }
  return out;
}

std::vector<SetLight> ToSetLights(vtkPolyData* lights)
{
  std::vector<SetLight> out(static_cast<size_t>(lights->GetNumberOfPoints()));
  vtkDataArray* e = lights->GetPointData()->GetArray("Irradiance");
  for (vtkIdType k = 0; k < lights->GetNumberOfPoints(); ++k)
  {
    lights->GetPoint(k, out[k].Direction);
    e->GetTuple(k, out[k].Irradiance);
  }
  return out;
}

PinholeCamera Pinhole(const LightSetActorsOptions& o)
{
  vtkNew<vtkCamera> camera;
  SetLightSetActorsCamera(o, camera);
  PinholeCamera p;
  double v[3];
  camera->GetPosition(v);
  p.Position = glm::vec3(v[0], v[1], v[2]);
  camera->GetFocalPoint(v);
  p.FocalPoint = glm::vec3(v[0], v[1], v[2]);
  camera->GetViewUp(v);
  p.ViewUp = glm::vec3(v[0], v[1], v[2]);
  p.ViewAngleDegrees = static_cast<float>(camera->GetViewAngle());
  return p;
}

TriangleScene ToTriangles(const LightSetActorsScene& scene)
{
  TriangleScene t;
  SceneMaterial material;
  material.Diffuse = glm::vec3(static_cast<float>(scene.Options.Albedo));
  const auto id = t.AddMaterial(material);
  vtkTriangleSceneConverter::ToTriangleMesh(scene.Geometry, t);
  for (glm::vec3& n : t.Normals)
  {
    n = glm::normalize(n);
  }
  t.MaterialIds.assign(t.Triangles.size(), id);
  return t;
}

// The primary hit of each pixel centre: position and interpolated unit normal (facing the
// camera); Hit false for misses.
struct PixelHit
{
  bool Hit = false;
  glm::vec3 Position{ 0.0f };
  glm::vec3 Normal{ 0.0f };
};

std::vector<PixelHit> PrimaryHits(
  const LightSetActorsScene& scene, const TriangleScene& t, const EmbreeScene& embree)
{
  const int size = scene.Options.Size;
  const PinholeCamera camera = Pinhole(scene.Options);
  std::vector<PixelHit> hits(static_cast<size_t>(size) * size);
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const SceneRay ray = camera.Ray(i + 0.5f, j + 0.5f, size, size);
      const SceneHit hit = embree.Intersect(ray);
      if (hit.Triangle == SceneHit::None)
      {
        continue;
      }
      PixelHit& h = hits[static_cast<size_t>(j) * size + i];
      h.Hit = true;
      h.Position = ray.Origin + hit.T * ray.Direction;
      const glm::uvec3 tri = t.Triangles[hit.Triangle];
      glm::vec3 n = (1.0f - hit.U - hit.V) * t.Normals[tri[0]] + hit.U * t.Normals[tri[1]] +
        hit.V * t.Normals[tri[2]];
      n = glm::normalize(n);
      h.Normal = glm::dot(n, ray.Direction) > 0.0f ? -n : n;
    }
  }
  return hits;
}
} // namespace

//------------------------------------------------------------------------------
bool BuildLightSetActorsScene(
  const LightSetActorsOptions& options, LightSetActorsScene& scene, std::string& error)
{
  scene.Options = options;
  scene.Environment = Environment(options, error);
  if (!scene.Environment)
  {
    return false;
  }
  vtkNew<vtkMedianCutLights> cut;
  cut->SetInputData(scene.Environment);
  cut->SetNumberOfLights(options.Lights);
  cut->Update();
  if (cut->GetOutput()->GetNumberOfPoints() < 1)
  {
    error = "the median cut gave no lights";
    return false;
  }
  scene.Lights = vtkSmartPointer<vtkPolyData>::New();
  scene.Lights->DeepCopy(cut->GetOutput());

  vtkNew<vtkSphereSource> sphere;
  sphere->SetThetaResolution(256);
  sphere->SetPhiResolution(128);
  sphere->SetRadius(1.0);
  vtkNew<vtkAppendPolyData> append;
  append->AddInputConnection(sphere->GetOutputPort());
  vtkNew<vtkPlaneSource> plane;
  if (options.Plane)
  {
    sphere->SetRadius(0.6);
    sphere->SetCenter(0.0, 0.0, 0.9);
    plane->SetOrigin(-2.5, -2.5, 0.0);
    plane->SetPoint1(2.5, -2.5, 0.0);
    plane->SetPoint2(-2.5, 2.5, 0.0);
    append->AddInputConnection(plane->GetOutputPort());
  }
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputConnection(append->GetOutputPort());
  triangles->Update();
  scene.Geometry = vtkSmartPointer<vtkPolyData>::New();
  scene.Geometry->DeepCopy(triangles->GetOutput());

  // Exposure: the brightest unshadowed surface at 85% of white.
  const std::vector<SetLight> lights = ToSetLights(scene.Lights);
  double brightest = 0.0;
  const int normals = 4000;
  const double golden = Pi<double> * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < normals; ++k)
  {
    const double z = 1.0 - (k + 0.5) * 2.0 / normals;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    const double n[3] = { r * std::cos(golden * k), r * std::sin(golden * k), z };
    double e[3];
    LightSetIrradiance(lights, n, e);
    brightest = std::max({ brightest, e[0], e[1], e[2] });
  }
  scene.Exposure = 0.85 / std::max(1e-30, options.Albedo / Pi<double> * brightest);
  return true;
}

//------------------------------------------------------------------------------
void SetLightSetActorsCamera(const LightSetActorsOptions& options, vtkCamera* camera)
{
  camera->SetViewUp(0.0, 0.0, 1.0);
  if (options.Plane)
  {
    camera->SetFocalPoint(0.0, 0.0, 0.4);
    camera->SetPosition(0.0, -5.5, 3.6);
    camera->SetViewAngle(38.0);
  }
  else
  {
    const double elevation = 20.0 * Pi<double> / 180.0;
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetPosition(0.0, -4.5 * std::cos(elevation), 4.5 * std::sin(elevation));
    camera->SetViewAngle(30.0);
  }
}

//------------------------------------------------------------------------------
LightSetActorsView MakeLightSetActorsView(
  const LightSetActorsScene& scene, const LightSetActorsVariant& variant, std::string& error)
{
  LightSetActorsView view;
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(scene.Geometry);
  mapper->ScalarVisibilityOff();
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkProperty* p = actor->GetProperty();
  p->SetColor(scene.Options.Albedo, scene.Options.Albedo, scene.Options.Albedo);
  p->SetDiffuse(1.0);
  p->SetAmbient(0.0);
  p->SetSpecular(0.0);
  p->SetInterpolationToPhong();

  vtkNew<vtkRenderer> renderer;
  renderer->SetBackground(0.0, 0.0, 0.0);
  renderer->AddActor(actor);
  SetLightSetActorsCamera(scene.Options, renderer->GetActiveCamera());
  renderer->ResetCameraClippingRange();

  view.Window = vtkSmartPointer<vtkRenderWindow>::New();
  vtkRenderWindow* window = view.Window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(scene.Options.Size, scene.Options.Size);
  window->AddRenderer(renderer);
  if (variant.HeadlightOnly)
  {
    return view;
  }
  vtkSmartPointer<vtkPolyData> lights = scene.Lights;
  if (variant.FlippedUp)
  {
    lights = vtkSmartPointer<vtkPolyData>::New();
    lights->DeepCopy(scene.Lights);
    for (vtkIdType k = 0; k < lights->GetNumberOfPoints(); ++k)
    {
      double d[3];
      lights->GetPoint(k, d);
      lights->GetPoints()->SetPoint(k, d[0], d[2], d[1]);
    }
  }
  vtkNew<vtkLightSetLighting> lighting;
  lighting->SetLightSet(lights);
  lighting->SetNumberOfDirectionalLights(variant.DirectionalLights);
  lighting->SetRemainder(variant.Remainder);
  lighting->SetExposure(scene.Exposure);
  lighting->SetShadows(variant.Shadows);
  lighting->SetShadowMapResolution(variant.ShadowMapResolution);
  if (!lighting->Apply(renderer))
  {
    error = "vtkLightSetLighting::Apply failed";
    return LightSetActorsView();
  }
  view.Lighting = lighting;
  return view;
}

//------------------------------------------------------------------------------
std::vector<float> PathTracedLightSetActors(const LightSetActorsScene& scene, int samplesPerPixel)
{
  const TriangleScene t = ToTriangles(scene);
  const EmbreeScene embree(t);
  PathTracerSettings settings;
  settings.MaxDepth = 1; // direct light only, as VTK draws it
  PathTracer tracer(embree, settings);
  EnvironmentLight environment;
  environment.Map = ToRgb(scene.Environment);
  tracer.SetEnvironment(environment);
  const int size = scene.Options.Size;
  const RgbImage image = tracer.RenderImage(Pinhole(scene.Options), size, size, samplesPerPixel, 7);
  const std::vector<PixelHit> hits = PrimaryHits(scene, t, embree);
  std::vector<float> out(3 * hits.size(), -1.0f);
  for (size_t k = 0; k < hits.size(); ++k)
  {
    if (hits[k].Hit && image.Width == size)
    {
      std::copy(image.Rgb.begin() + 3 * k, image.Rgb.begin() + 3 * k + 3, out.begin() + 3 * k);
    }
  }
  return out;
}

//------------------------------------------------------------------------------
std::vector<float> ExactEnvironmentLightSetActors(const LightSetActorsScene& scene)
{
  const TriangleScene t = ToTriangles(scene);
  const EmbreeScene embree(t);
  const std::vector<PixelHit> hits = PrimaryHits(scene, t, embree);
  const ExactIrradiance exact(ToRgb(scene.Environment));
  const double k = scene.Options.Albedo / Pi<double>;
  std::vector<float> out(3 * hits.size(), -1.0f);
  ParallelFor(0, hits.size(), 16,
    [&](size_t begin, size_t end)
    {
      for (size_t p = begin; p < end; ++p)
      {
        if (!hits[p].Hit)
        {
          continue;
        }
        const double n[3] = { hits[p].Normal.x, hits[p].Normal.y, hits[p].Normal.z };
        double e[3];
        exact.Evaluate(n, e);
        for (int c = 0; c < 3; ++c)
        {
          out[3 * p + c] = static_cast<float>(k * e[c]);
        }
      }
    });
  return out;
}

//------------------------------------------------------------------------------
std::vector<float> ExactLightSetLightSetActors(const LightSetActorsScene& scene)
{
  const TriangleScene t = ToTriangles(scene);
  const EmbreeScene embree(t);
  const std::vector<PixelHit> hits = PrimaryHits(scene, t, embree);
  const std::vector<SetLight> lights = ToSetLights(scene.Lights);
  const float epsilon = 1e-4f;
  const double k = scene.Options.Albedo / Pi<double>;
  std::vector<float> out(3 * hits.size(), -1.0f);
  ParallelFor(0, hits.size(), 16,
    [&](size_t begin, size_t end)
    {
      for (size_t p = begin; p < end; ++p)
      {
        if (!hits[p].Hit)
        {
          continue;
        }
        double e[3] = { 0.0, 0.0, 0.0 };
        for (const SetLight& l : lights)
        {
          const glm::vec3 d(l.Direction[0], l.Direction[1], l.Direction[2]);
          const float c = glm::dot(hits[p].Normal, d);
          if (!(c > 0.0f))
          {
            continue;
          }
          SceneRay shadow;
          shadow.Origin = hits[p].Position + epsilon * hits[p].Normal;
          shadow.Direction = d;
          if (embree.Occluded(shadow))
          {
            continue;
          }
          for (int i = 0; i < 3; ++i)
          {
            e[i] += c * l.Irradiance[i];
          }
        }
        for (int i = 0; i < 3; ++i)
        {
          out[3 * p + i] = static_cast<float>(k * e[i]);
        }
      }
    });
  return out;
}

//------------------------------------------------------------------------------
LightSetActorsError CompareLightSetActors(
  const Frame& frame, const std::vector<float>& reference, double exposure)
{
  LightSetActorsError result;
  const int w = frame.Width;
  const int h = frame.Height;
  if (reference.size() != 3 * static_cast<size_t>(w) * h)
  {
    return result;
  }
  auto covered = [&](int i, int j)
  {
    const size_t p = static_cast<size_t>(j) * w + i;
    return i >= 0 && j >= 0 && i < w && j < h && frame.Covered(p) && reference[3 * p] >= 0.0f;
  };
  std::vector<size_t> pixels;
  double meanReference = 0.0;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      if (covered(i, j) && covered(i - 1, j) && covered(i + 1, j) && covered(i, j - 1) &&
        covered(i, j + 1))
      {
        const size_t p = static_cast<size_t>(j) * w + i;
        pixels.push_back(p);
        meanReference +=
          255.0 * exposure * (reference[3 * p] + reference[3 * p + 1] + reference[3 * p + 2]);
      }
    }
  }
  if (pixels.empty())
  {
    return result;
  }
  meanReference /= static_cast<double>(pixels.size());
  std::vector<double> errors;
  errors.reserve(pixels.size());
  for (size_t p : pixels)
  {
    double r = 0.0;
    double v = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      r += std::min(255.0, 255.0 * exposure * reference[3 * p + c]);
      v += frame.Rgb[3 * p + c];
    }
    errors.push_back(std::abs(v - r) / std::max(r, 0.1 * meanReference));
  }
  double sum = 0.0;
  for (double e : errors)
  {
    sum += e;
  }
  result.Mean = sum / static_cast<double>(errors.size());
  std::sort(errors.begin(), errors.end());
  result.P95 = errors[static_cast<size_t>(0.95 * static_cast<double>(errors.size() - 1))];
  result.Pixels = static_cast<long long>(errors.size());
  return result;
}

//------------------------------------------------------------------------------
Frame ReferenceFrame(const std::vector<float>& reference, int size, double exposure)
{
  Frame f;
  f.Width = size;
  f.Height = size;
  const size_t n = static_cast<size_t>(size) * size;
  f.Rgb.assign(3 * n, 0);
  f.Depth.assign(n, 1.0f);
  for (size_t p = 0; p < n && 3 * p + 2 < reference.size(); ++p)
  {
    if (reference[3 * p] < 0.0f)
    {
      continue;
    }
    f.Depth[p] = 0.5f;
    for (int c = 0; c < 3; ++c)
    {
      const double v = 255.0 * exposure * reference[3 * p + c] + 0.5;
      f.Rgb[3 * p + c] = static_cast<unsigned char>(std::clamp(v, 0.0, 255.0));
    }
  }
  return f;
}

} // namespace mesolight
