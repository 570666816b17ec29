// SPDX-License-Identifier: BSD-3-Clause
// From two photographs and a geometry image to a relit model (the relief thesis' pipeline,
// Méndez Fernández, "Visualizing 3D models with fine-grain surface depth", chapters 3 and 6):
//
//  1. depth hallucination (Glencross et al. 2008): a diffuse-lit and a flash photograph of a
//     surface give its albedo and a depth map (vtkDepthHallucinationFilter);
//  2. the depth map becomes a relief texture (vtkReliefTextureFilter);
//  3. a geometry image (Gu et al. 2002; here a procedural cylinder) becomes a coarse macro mesh
//     whose texture coordinates map the textures texel for texel (vtkGeometryImageToMesh);
//  4. vtkReliefMapper draws the fine depth on the coarse mesh, with the albedo as its colour,
//     lit by 64 median-cut lights of a sun and sky (vtkMedianCutLights) with soft self-shadows.
//
//   PhotographsToRelitModel DIFFUSE FLASH [out.png]
//
// `mesolight bench hallucinate --maps Stone --photos DIR` writes such a pair of photographs
// (DIR/Stone-diffuse.exr, DIR/Stone-flash.exr): a path-traced stone wall.
#include <vtkCamera.h>
#include <vtkDepthHallucinationFilter.h>
#include <vtkGeometryImageSource.h>
#include <vtkGeometryImageToMesh.h>
#include <vtkMedianCutLights.h>
#include <vtkNew.h>
#include <vtkOIIOImageReader.h>
#include <vtkPNGWriter.h>
#include <vtkProceduralEnvironmentSource.h>
#include <vtkProperty.h>
#include <vtkReliefMapper.h>
#include <vtkReliefProperty.h>
#include <vtkReliefTextureFilter.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTexture.h>
#include <vtkWindowToImageFilter.h>

#include <cstdlib>
#include <iostream>

int main(int argc, char* argv[])
{
  if (argc < 3)
  {
    std::cerr << "usage: PhotographsToRelitModel DIFFUSE FLASH [out.png]\n";
    return EXIT_FAILURE;
  }
  // 1. Albedo and depth from the photographs (linear light: EXR, 16-bit TIFF/PNG).
  vtkNew<vtkOIIOImageReader> diffuse;
  diffuse->SetFileName(argv[1]);
  vtkNew<vtkOIIOImageReader> flash;
  flash->SetFileName(argv[2]);
  vtkNew<vtkDepthHallucinationFilter> hallucination;
  hallucination->SetDiffuseConnection(diffuse->GetOutputPort());
  hallucination->SetFlashConnection(flash->GetOutputPort());
  hallucination->Update();
  // A filter reports a failure as a VTK error (printed) and leaves its output empty; only readers
  // and writers also set an error code.
  if (hallucination->GetDepthOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "PhotographsToRelitModel: depth hallucination failed\n";
    return EXIT_FAILURE;
  }

  // 2. The relief texture: Sobel normals and depth; the relief is 3% of the texture's width deep.
  const double depthScale = 0.03;
  vtkNew<vtkReliefTextureFilter> relief;
  relief->SetInputConnection(hallucination->GetOutputPort(1));
  relief->SetDepthScale(depthScale);

  // 3. The macro mesh: a cylinder's geometry image sampled every 8 pixels.
  vtkNew<vtkGeometryImageSource> geometryImage;
  geometryImage->SetSurfaceToCylinder();
  vtkNew<vtkGeometryImageToMesh> mesh;
  mesh->SetInputConnection(geometryImage->GetOutputPort());
  mesh->SetStride(8);

  // 4. The relief on the mesh, coloured by the albedo, lit by a sky's median-cut lights.
  vtkNew<vtkProceduralEnvironmentSource> sky;
  sky->SetMapToSunSky(); // a low sun: soft relief shadows
  sky->SetSunElevation(25.0);
  vtkNew<vtkMedianCutLights> lights;
  lights->SetInputConnection(sky->GetOutputPort());
  lights->SetNumberOfLights(64);
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetInputConnection(mesh->GetOutputPort());
  mapper->SetReliefTextureConnection(relief->GetOutputPort());
  mapper->SetLightSetConnection(lights->GetOutputPort(1));
  vtkReliefProperty* settings = mapper->GetReliefProperty();
  settings->SetDepthScale(depthScale);
  // The default method: on this curved mesh the exact traversal gives way to Relief's search of
  // the curved layer (SurfaceCurvature), 64 linear + 8 binary steps, which keeps the cylinder's
  // silhouettes; on a flat mesh it would trace exactly.
  settings->ToneMappingOn();
  settings->SetExposure(1.5);
  vtkNew<vtkTexture> albedo;
  albedo->SetInputConnection(hallucination->GetOutputPort(0));
  albedo->InterpolateOn();
  albedo->SetColorModeToDirectScalars(); // float RGB in [0, 1]: colours, not scalars to map
  vtkNew<vtkActor> model;
  model->SetMapper(mapper);
  model->SetTexture(albedo);
  model->GetProperty()->SetAmbient(0.0);
  model->GetProperty()->SetDiffuse(1.0);

  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(model);
  renderer->AutomaticLightCreationOff(); // only the sky's lights
  renderer->SetBackground(0.1, 0.1, 0.12);
  renderer->ResetCamera();
  renderer->GetActiveCamera()->Elevation(20.0);
  renderer->GetActiveCamera()->Zoom(1.3);
  renderer->ResetCameraClippingRange();
  vtkNew<vtkRenderWindow> window;
  window->AddRenderer(renderer);
  window->SetSize(480, 480);
  if (argc > 3)
  {
    window->SetOffScreenRendering(1);
    window->Render();
    vtkNew<vtkWindowToImageFilter> grab;
    grab->SetInput(window);
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputConnection(grab->GetOutputPort());
    writer->SetFileName(argv[3]);
    writer->Write();
    if (writer->GetErrorCode() != 0)
    {
      std::cerr << "PhotographsToRelitModel: could not write " << argv[3] << "\n";
      return EXIT_FAILURE;
    }
    std::cout << "wrote " << argv[3] << "\n";
    return EXIT_SUCCESS;
  }
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  window->Render();
  interactor->Start();
  return EXIT_SUCCESS;
}
