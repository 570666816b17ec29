// SPDX-License-Identifier: BSD-3-Clause
// Tests of vtkEmbreeRayTracer on ordinary VTK scenes (no window needed): an analytic sphere
// (vtkSphereSource) under a vtkLight is Lambertian at the centre pixel, the triangulated
// sphere agrees, shadows, actor textures with nearest and bilinear lookups, material maps,
// progressive refinement events, and bad input reported through VTK's error events.
#include "vtkEmbreeRayTracer.h"

#include "vtkActor.h"
#include "vtkCallbackCommand.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkTexture.h"
#include "vtkUnsignedCharArray.h"

#include "MessageCapture.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>

namespace
{
struct Scene
{
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkEmbreeRayTracer> Tracer;
  vtkNew<mesolight_test::MessageCapture> Messages;
  Scene()
  {
    this->Tracer->SetRenderer(this->Renderer);
    this->Tracer->SetWidth(41);
    this->Tracer->SetHeight(31);
    this->Messages->Watch(this->Tracer);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->SetPosition(0.0, 0.0, 5.0);
    camera->SetFocalPoint(0.0, 0.0, 0.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetViewAngle(30.0);
  }
  void AddSun(double x, double y, double z)
  {
    vtkNew<vtkLight> light;
    light->SetLightTypeToSceneLight();
    light->SetPosition(x, y, z);
    light->SetFocalPoint(0.0, 0.0, 0.0);
    this->Renderer->AddLight(light);
  }
  vtkActor* AddSphere(int resolution = 16)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetThetaResolution(resolution);
    sphere->SetPhiResolution(resolution);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(sphere->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetDiffuseColor(1.0, 0.5, 0.25);
    actor->GetProperty()->SetDiffuse(0.8);
    actor->GetProperty()->SetAmbient(0.0);
    actor->GetProperty()->SetSpecular(0.0);
    this->Renderer->AddActor(actor);
    return actor;
  }
  vtkActor* AddPlane(double size, double z)
  {
    vtkNew<vtkPlaneSource> plane;
    plane->SetOrigin(-size, -size, z);
    plane->SetPoint1(size, -size, z);
    plane->SetPoint2(-size, size, z);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputConnection(plane->GetOutputPort());
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    actor->GetProperty()->SetSpecular(0.0);
    this->Renderer->AddActor(actor);
    return actor;
  }
  const float* Radiance(int i, int j)
  {
    auto* radiance = this->Tracer->GetOutput()->GetPointData()->GetArray("Radiance");
    static float rgb[3];
    for (int c = 0; c < 3; ++c)
    {
      rgb[c] = static_cast<float>(radiance->GetComponent(static_cast<vtkIdType>(j) * 41 + i, c));
    }
    return rgb;
  }
};

TEST(vtkEmbreeRayTracer, AnalyticSphereIsLambertianAtTheCentrePixel)
{
  Scene scene;
  scene.AddSphere();
  scene.AddSun(1.0, 0.0, 1.0); // light travelling along (-1, 0, -1)
  scene.Tracer->Update();
  ASSERT_TRUE(scene.Messages->Errors.empty()) << scene.Messages->AllErrors();
  EXPECT_EQ(scene.Tracer->GetAnalyticSphereCount(), 1);
  EXPECT_EQ(scene.Tracer->GetTriangleCount(), 0);
  int dims[3];
  scene.Tracer->GetOutput()->GetDimensions(dims);
  EXPECT_EQ(dims[0], 41);
  EXPECT_EQ(dims[1], 31);
  // Pixel (20, 15)'s centre ray is the view axis: it hits the sphere (radius 0.5) at normal
  // (0, 0, 1); N.L = cos 45 degrees.
  const float* rgb = scene.Radiance(20, 15);
  const float lambert = 0.8f * std::sqrt(0.5f);
  EXPECT_NEAR(rgb[0], lambert, 1e-4f);
  EXPECT_NEAR(rgb[1], 0.5f * lambert, 1e-4f);
  auto* bytes =
    vtkUnsignedCharArray::SafeDownCast(scene.Tracer->GetOutput()->GetPointData()->GetScalars());
  ASSERT_NE(bytes, nullptr);
  EXPECT_EQ(
    bytes->GetValue(3 * (15 * 41 + 20)), static_cast<unsigned char>(lambert * 255.0f + 0.5f));
  // A corner pixel shows the renderer's background.
  EXPECT_NEAR(
    scene.Radiance(0, 0)[0], static_cast<float>(scene.Renderer->GetBackground()[0]), 1e-6f);

  // The same sphere as triangles: close to the analytic value at the centre.
  scene.Tracer->AnalyticSpheresOff();
  scene.Tracer->Update();
  EXPECT_EQ(scene.Tracer->GetAnalyticSphereCount(), 0);
  EXPECT_GT(scene.Tracer->GetTriangleCount(), 100);
  EXPECT_NEAR(scene.Radiance(20, 15)[0], lambert, 0.03f);
}

TEST(vtkEmbreeRayTracer, SphereShadowsThePlaneBehindIt)
{
  Scene scene;
  vtkActor* sphere = scene.AddSphere();
  sphere->SetPosition(0.0, 0.0, 1.0);
  vtkActor* plane = scene.AddPlane(3.0, 0.0);
  plane->GetProperty()->SetAmbient(0.1);
  plane->GetProperty()->SetDiffuse(0.5);
  scene.AddSun(0.0, 0.0, 1.0); // straight down
  // Look from the side so the plane point right below the sphere is visible.
  scene.Renderer->GetActiveCamera()->SetPosition(0.0, -4.0, 4.0);
  scene.Renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.6, 0.0);
  scene.Tracer->Update();
  ASSERT_TRUE(scene.Messages->Errors.empty()) << scene.Messages->AllErrors();
  // Find a pixel on the plane just beyond the sphere: it should hold either ambient only
  // (shadowed) or ambient + diffuse (lit); both must occur, and the shadow must vanish
  // without shadows.
  int shadowed = 0, lit = 0;
  for (int j = 0; j < 31; ++j)
  {
    for (int i = 0; i < 41; ++i)
    {
      const float r = scene.Radiance(i, j)[0];
      shadowed += std::abs(r - 0.1f) < 1e-4f;
      lit += std::abs(r - 0.6f) < 1e-4f;
    }
  }
  EXPECT_GT(shadowed, 5);
  EXPECT_GT(lit, 100);
  scene.Tracer->ShadowsOff();
  scene.Tracer->Update();
  int shadowedWithout = 0;
  for (int j = 0; j < 31; ++j)
  {
    for (int i = 0; i < 41; ++i)
    {
      shadowedWithout += std::abs(scene.Radiance(i, j)[0] - 0.1f) < 1e-4f;
    }
  }
  EXPECT_EQ(shadowedWithout, 0);
}

vtkSmartPointer<vtkImageData> TwoByTwoImage()
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(2, 2, 1);
  image->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  const unsigned char values[4] = { 0, 255, 64, 128 };
  for (int p = 0; p < 4; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      image->GetPointData()->GetScalars()->SetComponent(p, c, values[p]);
    }
  }
  return image;
}

TEST(vtkEmbreeRayTracer, ActorTextureIsSampledNearestOrBilinear)
{
  Scene scene;
  vtkActor* plane = scene.AddPlane(1.0, 0.0); // tcoords (0,0)..(1,1) over [-1, 1]^2
  plane->GetProperty()->SetAmbient(1.0);
  plane->GetProperty()->SetDiffuse(0.0);
  vtkNew<vtkTexture> texture;
  texture->SetInputData(TwoByTwoImage());
  plane->SetTexture(texture);
  scene.Renderer->AutomaticLightCreationOff();
  // Ambient maps show the texture unlit: use the texture as the ambient map as well.
  scene.Tracer->SetMaterialMap(plane, vtkEmbreeRayTracer::AMBIENT_MAP, TwoByTwoImage());
  scene.Tracer->Update();
  ASSERT_TRUE(scene.Messages->Errors.empty()) << scene.Messages->AllErrors();
  // The centre pixel looks at (0, 0, 0): (s, t) = (0.5, 0.5), the mean of the four texels.
  const float mean = (0.0f + 1.0f + 64.0f / 255.0f + 128.0f / 255.0f) / 4.0f;
  EXPECT_NEAR(scene.Radiance(20, 15)[0], mean, 2e-3f);
  scene.Tracer->BilinearTexturesOff();
  scene.Tracer->Update();
  // Nearest: the centre ray lands on a texel boundary; either neighbouring texel is fine, but
  // never the bilinear mean.
  const float nearest = scene.Radiance(20, 15)[0];
  EXPECT_GT(std::abs(nearest - mean), 0.05f);
}

// The actor's own texture is its diffuse map, lit: under a sun along the view the centre pixel
// is Kd x diffuse colour x the texture's bilinear mean there; without the texture (negative)
// it is Kd x diffuse colour.
TEST(vtkEmbreeRayTracer, ActorTextureIsTheLitDiffuseMap)
{
  for (const bool textured : { true, false })
  {
    Scene scene;
    vtkActor* plane = scene.AddPlane(1.0, 0.0);
    plane->GetProperty()->SetAmbient(0.0);
    plane->GetProperty()->SetDiffuse(0.8);
    plane->GetProperty()->SetDiffuseColor(1.0, 1.0, 1.0);
    if (textured)
    {
      vtkNew<vtkTexture> texture;
      texture->SetInputData(TwoByTwoImage());
      plane->SetTexture(texture);
    }
    scene.Renderer->AutomaticLightCreationOff();
    scene.AddSun(0.0, 0.0, 1.0);
    scene.Tracer->Update();
    ASSERT_TRUE(scene.Messages->Errors.empty()) << scene.Messages->AllErrors();
    const float mean = (0.0f + 1.0f + 64.0f / 255.0f + 128.0f / 255.0f) / 4.0f;
    EXPECT_NEAR(scene.Radiance(20, 15)[0], 0.8f * (textured ? mean : 1.0f), 2e-3f) << textured;
  }
}

TEST(vtkEmbreeRayTracer, ProgressiveRefinementFiresEventsAndTracesEachPixelOnce)
{
  Scene scene;
  scene.AddSphere();
  scene.AddSun(0.0, 0.0, 1.0);
  scene.Tracer->ProgressiveOn();
  int events = 0;
  vtkNew<vtkCallbackCommand> callback;
  callback->SetClientData(&events);
  callback->SetCallback(
    [](vtkObject* caller, unsigned long, void* client, void*)
    {
      auto* tracer = static_cast<vtkEmbreeRayTracer*>(caller);
      ++*static_cast<int*>(client);
      int dims[3];
      tracer->GetPartialImage()->GetDimensions(dims);
      EXPECT_EQ(dims[0], 41);
    });
  scene.Tracer->AddObserver(vtkEmbreeRayTracer::RefinementEvent, callback);
  scene.Tracer->Update();
  EXPECT_EQ(events, 7); // blocks of 64, 32, 16, 8, 4, 2, 1
  EXPECT_EQ(scene.Tracer->GetPrimaryRays(), 41u * 31u);
}

TEST(vtkEmbreeRayTracer, BadInputGivesErrorsNotCrashes)
{
  {
    vtkNew<vtkEmbreeRayTracer> tracer;
    vtkNew<mesolight_test::MessageCapture> messages;
    messages->Watch(tracer);
    tracer->Update(); // no renderer
    EXPECT_FALSE(messages->Errors.empty());
    EXPECT_TRUE(messages->HasError("No renderer"));
  }
  {
    Scene empty;
    empty.Tracer->Update();
    EXPECT_FALSE(empty.Messages->Errors.empty());
    EXPECT_TRUE(empty.Messages->HasError("empty")) << empty.Messages->AllErrors();
  }
  {
    Scene scene;
    vtkActor* plane = scene.AddPlane(1.0, 0.0);
    vtkNew<vtkTexture> missing; // a texture without an image
    plane->SetTexture(missing);
    scene.Tracer->SetMaterialMap(plane, 42, TwoByTwoImage()); // no such channel
    EXPECT_EQ(scene.Messages->Errors.size(), 1u);
    scene.Tracer->SetMaterialMap(
      plane, vtkEmbreeRayTracer::BUMP_MAP, vtkNew<vtkImageData>()); // empty map
    scene.Tracer->Update();
    EXPECT_EQ(scene.Messages->Errors.size(), 1u) << scene.Messages->AllErrors();
    EXPECT_GE(scene.Messages->Warnings.size(), 2u); // missing texture image, empty bump map
  }
  {
    // Degenerate triangles only: nothing to trace.
    Scene scene;
    vtkNew<vtkPolyData> flat;
    vtkNew<vtkPoints> points;
    points->InsertNextPoint(0, 0, 0);
    points->InsertNextPoint(1, 0, 0);
    points->InsertNextPoint(2, 0, 0);
    flat->SetPoints(points);
    vtkNew<vtkCellArray> polys;
    const vtkIdType triangle[3] = { 0, 1, 2 };
    polys->InsertNextCell(3, triangle);
    flat->SetPolys(polys);
    vtkNew<vtkPolyDataMapper> mapper;
    mapper->SetInputData(flat);
    vtkNew<vtkActor> actor;
    actor->SetMapper(mapper);
    scene.Renderer->AddActor(actor);
    scene.Tracer->Update();
    EXPECT_FALSE(scene.Messages->Errors.empty());
    EXPECT_TRUE(scene.Messages->HasError("degenerate")) << scene.Messages->AllErrors();
  }
  {
    // A degenerate camera.
    Scene scene;
    scene.AddSphere();
    scene.Renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
    scene.Tracer->Update();
    EXPECT_FALSE(scene.Messages->Errors.empty());
  }
}

} // namespace
