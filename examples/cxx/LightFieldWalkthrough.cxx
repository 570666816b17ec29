// SPDX-License-Identifier: BSD-3-Clause
// A walk through a virtual light field inside an ordinary VTK renderer (Wither 2005): the
// built-in Cornell box is propagated by vtkVirtualLightField, drawn by vtkLightFieldActor, and
// an ordinary sphere actor placed in it is shaded by the light it gathers from the field.
//
//   LightFieldWalkthrough            an interactive window (the mouse moves the camera)
//   LightFieldWalkthrough out.png    renders one frame offscreen into out.png
#include <vtkCamera.h>
#include <vtkCornellBoxSource.h>
#include <vtkLightFieldActor.h>
#include <vtkLightFieldObjectMapper.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkSphereSource.h>
#include <vtkVirtualLightField.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  // The scene: the published Cornell box in millimetres (any OBJ/MTL scene works as well, read
  // by vtkOBJSceneReader).
  vtkNew<vtkCornellBoxSource> box;

  // The light field: 513 directions, 32 x 32 rays a side, 4 shooting iterations (a few seconds
  // on two cores; 2049 directions and more iterations for final images).
  vtkNew<vtkVirtualLightField> field;
  field->SetInputConnection(box->GetOutputPort());
  field->SetDirections(513);
  field->SetRaysPerSide(32);
  field->SetIterations(4);

  vtkNew<vtkLightFieldActor> scene;
  scene->SetLightFieldFilter(field); // updated when first drawn
  scene->SetRenderModeToProgressive();
  scene->SetExposure(0.6);

  // An ordinary actor in the box, shaded by the irradiance it gathers from the field.
  vtkNew<vtkSphereSource> sphere;
  sphere->SetRadius(60.0);
  sphere->SetThetaResolution(32);
  sphere->SetPhiResolution(16);
  vtkNew<vtkLightFieldObjectMapper> objectMapper;
  objectMapper->SetInputConnection(sphere->GetOutputPort());
  objectMapper->SetLightFieldActor(scene);
  vtkNew<vtkActor> object;
  object->SetMapper(objectMapper);
  object->SetPosition(400.0, 70.0, 150.0); // on the floor, before the tall block
  object->GetProperty()->SetDiffuseColor(0.8, 0.8, 0.8);
  scene->SetMovableObject(object);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(scene);
  renderer->AddActor(object);
  vtkCamera* camera = renderer->GetActiveCamera(); // the published camera
  camera->SetPosition(278.0, 273.0, -800.0);
  camera->SetFocalPoint(278.0, 273.0, 0.0);
  camera->SetViewUp(0.0, 1.0, 0.0);
  camera->SetViewAngle(39.3);
  renderer->ResetCameraClippingRange();

  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetSize(400, 400);
  if (argc > 1)
  {
    window->SetOffScreenRendering(1);
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(argv[1]);
    writer->Write();
    if (writer->GetErrorCode() != 0)
    {
      std::cerr << "LightFieldWalkthrough: could not write " << argv[1] << "\n";
      return EXIT_FAILURE;
    }
    std::cout << "wrote " << argv[1] << "\n";
    return EXIT_SUCCESS;
  }
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  interactor->Start();
  return EXIT_SUCCESS;
}
