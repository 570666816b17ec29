// SPDX-License-Identifier: BSD-3-Clause
#include "TraceScenes.h"

#include "MathConstants.h"
#include "vtkEmbreeRayTracer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCylinderSource.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <cmath>

namespace mesolight
{

namespace
{

vtkSmartPointer<vtkImageData> NewRgbImage(int width, int height)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(width, height, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  return image;
}

unsigned char Byte(double value)
{
  return static_cast<unsigned char>(std::min(255.0, std::max(0.0, value * 255.0 + 0.5)));
}

void SetPixel(vtkImageData* image, int i, int j, double r, double g, double b)
{
  auto* p = static_cast<unsigned char*>(image->GetScalarPointer(i, j, 0));
  p[0] = Byte(r);
  p[1] = Byte(g);
  p[2] = Byte(b);
}

vtkSmartPointer<vtkActor> SphereActor(double x, double y, double z, double radius)
{
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(radius);
  sphere->SetThetaResolution(48);
  sphere->SetPhiResolution(24);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(sphere->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->SetPosition(x, y, z);
  return actor;
}

vtkSmartPointer<vtkActor> GroundActor(double size, double repeats)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-size, 0.0, size);
  plane->SetPoint1(size, 0.0, size);
  plane->SetPoint2(-size, 0.0, -size);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  // Texture coordinates 0..1 repeated `repeats` times: scale them with the texture transform
  // is GL-only, so stretch the plane's coordinates instead.
  plane->Update();
  auto* tcoords = plane->GetOutput()->GetPointData()->GetTCoords();
  for (vtkIdType p = 0; p < tcoords->GetNumberOfTuples(); ++p)
  {
    tcoords->SetComponent(p, 0, tcoords->GetComponent(p, 0) * repeats);
    tcoords->SetComponent(p, 1, tcoords->GetComponent(p, 1) * repeats);
  }
  return actor;
}

void AddLight(vtkRenderer* renderer, double x, double y, double z, double intensity)
{
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetConeAngle(180.0);
  light->SetPosition(x, y, z);
  light->SetFocalPoint(0.0, 0.0, 0.0);
  light->SetIntensity(intensity);
  renderer->AddLight(light);
}

// The scenes' camera: from (x, y, z) toward (fx, fy, fz), +y up, a 40 degree view angle.
void LookAt(vtkRenderer* renderer, double x, double y, double z, double fx, double fy, double fz)
{
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(x, y, z);
  camera->SetFocalPoint(fx, fy, fz);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(40.0);
}
} // namespace

vtkSmartPointer<vtkImageData> MakeCheckerImage(int size, int squares, double dark, double light)
{
  auto image = NewRgbImage(size, size);
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const bool odd = ((i * squares / size) + (j * squares / size)) % 2 != 0;
      const double v = odd ? light : dark;
      SetPixel(image, i, j, v, v, v);
    }
  }
  return image;
}

vtkSmartPointer<vtkImageData> MakeGlobeImage(int height)
{
  const int width = 2 * height;
  auto image = NewRgbImage(width, height);
  for (int j = 0; j < height; ++j)
  {
    const double latitude = Pi<double> * ((j + 0.5) / height - 0.5);
    for (int i = 0; i < width; ++i)
    {
      const double longitude = 2.0 * Pi<double> * (i + 0.5) / width;
      const double land =
        std::sin(3.0 * longitude + 1.3 * std::sin(2.0 * latitude)) * std::cos(latitude) +
        0.6 * std::sin(5.0 * longitude - 2.0 * latitude) * std::cos(3.0 * latitude) - 0.25;
      const bool ice = std::abs(latitude) > 0.42 * Pi<double>;
      if (ice)
      {
        SetPixel(image, i, j, 0.95, 0.95, 0.97);
      }
      else if (land > 0.0)
      {
        SetPixel(image, i, j, 0.25 + 0.3 * land, 0.55, 0.2);
      }
      else
      {
        SetPixel(image, i, j, 0.05, 0.2, 0.6 + 0.3 * land);
      }
    }
  }
  return image;
}

vtkSmartPointer<vtkImageData> MakeKnotBumpImage(int width, int height, double strength)
{
  // Height: two families of raised sinusoidal bands crossing over and under each other.
  auto heightAt = [](double s, double t)
  {
    const double a = 0.5 + 0.5 * std::cos(2.0 * Pi<double> * (6.0 * s + 2.0 * t));
    const double b = 0.5 + 0.5 * std::cos(2.0 * Pi<double> * (6.0 * s - 2.0 * t));
    const double bandA = std::pow(a, 8.0);
    const double bandB = std::pow(b, 8.0);
    const double over = std::sin(2.0 * Pi<double> * 12.0 * s) > 0.0 ? 1.0 : 0.6; // over/under weave
    return std::max(bandA * over, bandB * (1.6 - over));
  };
  auto image = NewRgbImage(width, height);
  const double ds = 1.0 / width;
  const double dt = 1.0 / height;
  for (int j = 0; j < height; ++j)
  {
    for (int i = 0; i < width; ++i)
    {
      const double s = (i + 0.5) * ds;
      const double t = (j + 0.5) * dt;
      const double gs = (heightAt(s + ds, t) - heightAt(s - ds, t)) / (2.0 * width * ds);
      const double gt = (heightAt(s, t + dt) - heightAt(s, t - dt)) / (2.0 * height * dt);
      // The normal of a height field tilts against the slope.
      SetPixel(image, i, j, 0.5 - 0.5 * strength * gs * width / 64.0,
        0.5 - 0.5 * strength * gt * height / 64.0, 1.0);
    }
  }
  return image;
}

bool BuildSpheresScene(vtkRenderer* renderer, vtkEmbreeRayTracer* tracer)
{
  // Ahern 1999 §1's picture: a checker ground (diffuse map); left sphere: the checker as
  // shininess map (highlights of changing size); middle: the checker as specular map
  // (alternating reflectivity); right: a globe as ambient map.
  auto checker = MakeCheckerImage(256, 8, 0.05, 1.0);
  auto ground = GroundActor(6.0, 4.0);
  vtkNew<vtkTexture> checkerTexture;
  checkerTexture->SetInputData(checker);
  ground->SetTexture(checkerTexture);
  ground->GetProperty()->SetDiffuse(0.8);
  ground->GetProperty()->SetAmbient(0.05);
  renderer->AddActor(ground);

  auto left = SphereActor(-2.2, 1.0, 0.0, 1.0);
  left->GetProperty()->SetDiffuseColor(0.7, 0.15, 0.1);
  left->GetProperty()->SetSpecular(0.6);
  left->GetProperty()->SetSpecularPower(200.0);
  renderer->AddActor(left);
  tracer->SetMaterialMap(
    left, vtkEmbreeRayTracer::SHININESS_MAP, MakeCheckerImage(256, 8, 0.02, 1.0));

  auto middle = SphereActor(0.0, 1.0, 0.0, 1.0);
  middle->GetProperty()->SetDiffuseColor(0.1, 0.1, 0.12);
  middle->GetProperty()->SetSpecular(0.9);
  middle->GetProperty()->SetSpecularPower(60.0);
  renderer->AddActor(middle);
  tracer->SetMaterialMap(middle, vtkEmbreeRayTracer::SPECULAR_MAP, checker);

  auto right = SphereActor(2.2, 1.0, 0.0, 1.0);
  right->RotateX(-90.0); // the globe's axis (actor z) points up (world y)
  right->GetProperty()->SetAmbient(0.6);
  right->GetProperty()->SetDiffuse(0.4);
  right->GetProperty()->SetDiffuseColor(0.5, 0.5, 0.5);
  right->GetProperty()->SetSpecular(0.0);
  renderer->AddActor(right);
  tracer->SetMaterialMap(right, vtkEmbreeRayTracer::AMBIENT_MAP, MakeGlobeImage(128));

  // Four lights: four highlights on the left sphere.
  AddLight(renderer, -6.0, 8.0, 8.0, 0.35);
  AddLight(renderer, 6.0, 8.0, 8.0, 0.35);
  AddLight(renderer, -3.0, 10.0, 4.0, 0.3);
  AddLight(renderer, 3.0, 6.0, 10.0, 0.3);
  renderer->SetBackground(0.3, 0.4, 0.6);
  LookAt(renderer, 0.0, 3.2, 8.5, 0.0, 0.8, 0.0);
  return true;
}

bool BuildRingScene(vtkRenderer* renderer, vtkEmbreeRayTracer* tracer)
{
  // Ahern 1999 §5: a ring (a cylinder with smooth normals) whose knots exist only in its bump
  // map, with a roughness map, on a glossy floor whose roughness alternates (§2's picture).
  vtkNew<vtkCylinderSource> cylinder;
  cylinder->SetRadius(1.0);
  cylinder->SetHeight(0.7);
  cylinder->SetResolution(128);
  cylinder->CappingOff();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(cylinder->GetOutputPort());
  vtkNew<vtkActor> ring;
  ring->SetMapper(mapper);
  ring->SetPosition(0.0, 0.35, 0.0);
  ring->GetProperty()->SetDiffuseColor(0.55, 0.42, 0.12);
  ring->GetProperty()->SetDiffuse(0.6);
  ring->GetProperty()->SetSpecularColor(1.0, 0.85, 0.5);
  ring->GetProperty()->SetSpecular(0.5);
  ring->GetProperty()->SetSpecularPower(40.0);
  ring->GetProperty()->SetAmbient(0.05);
  ring->GetProperty()->SetNormalScale(1.0);
  renderer->AddActor(ring);
  tracer->SetMaterialMap(ring, vtkEmbreeRayTracer::BUMP_MAP, MakeKnotBumpImage(512, 128, 1.0));
  tracer->SetMaterialMap(
    ring, vtkEmbreeRayTracer::ROUGHNESS_MAP, MakeCheckerImage(64, 16, 0.0, 0.25));

  auto floor = GroundActor(5.0, 3.0);
  vtkNew<vtkTexture> wood;
  wood->SetInputData(MakeCheckerImage(256, 2, 0.35, 0.55));
  floor->SetTexture(wood);
  floor->GetProperty()->SetDiffuse(0.7);
  floor->GetProperty()->SetSpecular(0.35);
  floor->GetProperty()->SetSpecularPower(30.0);
  renderer->AddActor(floor);
  tracer->SetMaterialMap(
    floor, vtkEmbreeRayTracer::ROUGHNESS_MAP, MakeCheckerImage(256, 8, 0.0, 0.3));

  AddLight(renderer, -4.0, 6.0, 5.0, 0.7);
  AddLight(renderer, 5.0, 4.0, 3.0, 0.4);
  renderer->SetBackground(0.15, 0.15, 0.2);
  LookAt(renderer, 0.0, 2.6, 4.2, 0.0, 0.3, 0.0);
  return true;
}

} // namespace mesolight
