// SPDX-License-Identifier: BSD-3-Clause
// The smallest complete Mesolight pipeline: a procedural depth map is baked into a relief
// texture and drawn on a single quad by vtkReliefMapper, lit by one VTK light.
//
//   ReliefWall [output.png]     writes the image offscreen; without an argument opens a window.
#include "vtkProceduralReliefSource.h"
#include "vtkReliefMapper.h"
#include "vtkReliefTextureFilter.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlaneSource.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

int main(int argc, char* argv[])
{
  // images -> filters -> textures
  vtkNew<vtkProceduralReliefSource> source;
  source->SetPatternToBricks();
  source->SetResolution(512, 512);
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputConnection(source->GetOutputPort(0)); // depth map
  relief->SetDepthScale(0.04);
  vtkNew<vtkTexture> albedo;
  albedo->SetInputConnection(source->GetOutputPort(1)); // matching colours
  albedo->InterpolateOn();
  albedo->MipmapOn();

  // textures -> mapper: a quad with texture coordinates is all the geometry there is
  vtkNew<vtkPlaneSource> wall;
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetInputConnection(wall->GetOutputPort());
  mapper->SetReliefTextureConnection(relief->GetOutputPort());
  mapper->GetReliefProperty()->SetDepthScale(0.04);
  // The default method: the exact first hit (maximum-mipmap traversal), self-shadowed.

  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(albedo);
  actor->GetProperty()->SetAmbient(0.1);
  actor->GetProperty()->SetSpecular(0.2);

  // -> lights
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLight> sun;
  sun->SetLightTypeToSceneLight();
  sun->SetPosition(-1.0, 1.0, 0.8);
  sun->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->AddLight(sun);
  renderer->GetActiveCamera()->SetPosition(0.3, -1.2, 1.0);
  renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
  renderer->ResetCamera();

  vtkNew<vtkRenderWindow> window;
  window->SetSize(800, 800);
  window->AddRenderer(renderer);
  if (argc > 1)
  {
    window->SetOffScreenRendering(1);
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    vtkNew<vtkPNGWriter> png;
    png->SetInputConnection(grab->GetOutputPort());
    png->SetFileName(argv[1]);
    png->Write();
    return png->GetErrorCode() == 0 ? 0 : 1;
  }
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  interactor->Start();
  return 0;
}
