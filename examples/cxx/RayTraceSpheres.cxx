// SPDX-License-Identifier: BSD-3-Clause
// RayTraceSpheres: ray trace an ordinary VTK scene on the CPU with Embree. A vtkSphereSource
// actor (traced as an exact sphere) with a checker texture as its specular (reflectivity) map
// stands on a plane lit by one positional light with shadows; adaptive supersampling smooths
// the edges. Writes ray-traced-spheres.png (or the file given as the first argument).
#include "vtkEmbreeRayTracer.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>

#include <iostream>

int main(int argc, char* argv[])
{
  vtkNew<vtkRenderer> renderer; // no window needed: the tracer reads the scene
  renderer->SetBackground(0.2, 0.3, 0.5);

  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkPolyDataMapper> sphereMapper;
  sphereMapper->SetInputConnection(sphere->GetOutputPort());
  vtkNew<vtkActor> ball;
  ball->SetMapper(sphereMapper);
  ball->SetPosition(0.0, 0.5, 0.0);
  ball->GetProperty()->SetDiffuseColor(0.8, 0.2, 0.1);
  ball->GetProperty()->SetSpecular(0.7);
  ball->GetProperty()->SetSpecularPower(50.0);
  renderer->AddActor(ball);

  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(-3.0, 0.0, 3.0);
  plane->SetPoint1(3.0, 0.0, 3.0);
  plane->SetPoint2(-3.0, 0.0, -3.0);
  vtkNew<vtkPolyDataMapper> planeMapper;
  planeMapper->SetInputConnection(plane->GetOutputPort());
  vtkNew<vtkActor> ground;
  ground->SetMapper(planeMapper);
  ground->GetProperty()->SetSpecular(0.0);
  renderer->AddActor(ground);

  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPositional(true);
  light->SetConeAngle(180.0);
  light->SetPosition(-3.0, 5.0, 4.0);
  renderer->AddLight(light);

  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(0.0, 2.0, 4.0);
  camera->SetFocalPoint(0.0, 0.4, 0.0);
  camera->SetViewAngle(40.0);

  // An 8 x 8 checker as the sphere's specular map: alternating reflective and matte squares.
  vtkNew<vtkImageData> checker;
  checker->SetDimensions(128, 128, 1);
  checker->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* texels = static_cast<unsigned char*>(checker->GetScalarPointer());
  for (int j = 0; j < 128; ++j)
  {
    for (int i = 0; i < 128; ++i)
    {
      const unsigned char v = ((i / 16 + j / 16) % 2) ? 255 : 30;
      texels[3 * (j * 128 + i) + 0] = texels[3 * (j * 128 + i) + 1] =
        texels[3 * (j * 128 + i) + 2] = v;
    }
  }

  vtkNew<vtkEmbreeRayTracer> tracer;
  tracer->SetRenderer(renderer);
  tracer->SetWidth(640);
  tracer->SetHeight(480);
  tracer->SetMaterialMap(ball, vtkEmbreeRayTracer::SPECULAR_MAP, checker);
  tracer->AdaptiveSupersamplingOn();
  tracer->Update();
  std::cout << tracer->GetPrimaryRays() << " primary, " << tracer->GetShadowRays() << " shadow and "
            << tracer->GetSecondaryRays() << " reflection rays\n";

  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(tracer->GetOutputPort());
  writer->SetFileName(argc > 1 ? argv[1] : "ray-traced-spheres.png");
  writer->Write();
  return writer->GetErrorCode() == 0 ? 0 : 1;
}
