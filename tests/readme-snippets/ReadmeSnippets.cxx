// SPDX-License-Identifier: BSD-3-Clause
// The README's C++ snippets run as written (snippet-1.inc, snippet-2.inc: copied out of README.md
// by this directory's CMakeLists.txt), between the variables the README leaves to the reader,
// and the exposure of the image they give checked: a user following the README must get a
// correctly exposed first image, so at most 1% of the relief's pixels may be saturated (a
// channel at 250 or more of 255), and the relief must cover the view and not be black.
//
//   ReadmeSnippets [--old-defaults] [--headlight] [--environment FILE.exr] [output.png]
//
// Run in a scratch directory: it writes the depth image the first snippet reads
// (wall-depth.exr). --old-defaults turns tone mapping off after the snippets (clamped shading,
// the relief property's former default) so that a test can show the check failing there;
// --headlight turns VTK's automatic light back on (lit by the environment "as well");
// --environment replaces the procedural sunny sky with a lat-long HDR file.
#include "vtkMedianCutLights.h"
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"
#include "vtkProceduralEnvironmentSource.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"
#include "vtkReliefTextureFilter.h"

#include <vtkActor.h>
#include <vtkAlgorithm.h>
#include <vtkCamera.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkTexture.h>
#include <vtkUnsignedCharArray.h>
#include <vtkWindowToImageFilter.h>

#include <algorithm>
#include <cstdio>
#include <cstring>
#include <string>

int main(int argc, char* argv[])
{
  bool oldDefaults = false;
  bool headlight = false;
  std::string environment;
  std::string png;
  for (int i = 1; i < argc; ++i)
  {
    if (std::strcmp(argv[i], "--old-defaults") == 0)
    {
      oldDefaults = true;
    }
    else if (std::strcmp(argv[i], "--headlight") == 0)
    {
      headlight = true;
    }
    else if (std::strcmp(argv[i], "--environment") == 0 && i + 1 < argc)
    {
      environment = argv[++i];
    }
    else
    {
      png = argv[i];
    }
  }

  // The user's own files and scene, which the README takes as given.
  vtkNew<vtkProceduralReliefSource> userData;
  userData->SetPatternToStone();
  userData->SetResolution(256, 256);
  vtkNew<vtkOIIOImageWriter> exr;
  exr->SetInputConnection(userData->GetOutputPort(0));
  exr->SetFileName("wall-depth.exr");
  exr->Write();
  if (exr->GetErrorCode() != 0)
  {
    std::fprintf(stderr, "cannot write wall-depth.exr in the working directory\n");
    return 1;
  }
  vtkNew<vtkPlaneSource> mesh;
  vtkNew<vtkActor> actor;
  // A white colour texture (as white as a surface without one): shading the tone map would
  // clip shows as 255, not hidden under a darker albedo.
  vtkNew<vtkImageData> white;
  white->SetDimensions(4, 4, 1);
  white->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  std::fill_n(static_cast<unsigned char*>(white->GetScalarPointer()), 4 * 4 * 3, 255);
  vtkNew<vtkTexture> colourTexture;
  colourTexture->SetInputData(white);
  vtkNew<vtkRenderer> renderer;
  // A lat-long HDR: the file given with --environment, else a procedural sky with a sun.
  vtkSmartPointer<vtkAlgorithm> environmentReader;
  if (!environment.empty())
  {
    vtkNew<vtkOIIOImageReader> reader;
    reader->SetFileName(environment.c_str());
    environmentReader = reader;
  }
  else
  {
    vtkNew<vtkProceduralEnvironmentSource> sky;
    sky->SetMapToSunSky();
    environmentReader = sky;
  }

  {
#include "snippet-1.inc"
    {
#include "snippet-2.inc"
      if (oldDefaults)
      {
        settings->ToneMappingOff();
      }
      if (headlight)
      {
        renderer->AutomaticLightCreationOn();
      }
      renderer->AddActor(actor);
      renderer->GetActiveCamera()->SetPosition(0.3, -1.2, 1.0);
      renderer->GetActiveCamera()->SetViewUp(0.0, 0.0, 1.0);
      renderer->ResetCamera();

      vtkNew<vtkRenderWindow> window;
      window->SetSize(400, 400);
      window->SetOffScreenRendering(1);
      window->AddRenderer(renderer);
      window->Render();
      vtkNew<vtkWindowToImageFilter> grab;
      grab->SetInput(window);
      grab->Update();
      vtkNew<vtkFloatArray> z;
      window->GetZbufferData(0, 0, 399, 399, z);
      auto* rgb =
        vtkUnsignedCharArray::SafeDownCast(grab->GetOutput()->GetPointData()->GetScalars());
      if (!rgb || rgb->GetNumberOfTuples() != z->GetNumberOfTuples())
      {
        std::fprintf(stderr, "no colour image to check\n");
        return 1;
      }
      long long relief = 0;
      long long saturated = 0;
      double sum = 0.0;
      const int channels = rgb->GetNumberOfComponents();
      for (vtkIdType p = 0; p < rgb->GetNumberOfTuples(); ++p)
      {
        if (z->GetValue(p) >= 1.0f)
        {
          continue; // background
        }
        ++relief;
        int peak = 0;
        for (int c = 0; c < 3; ++c)
        {
          const int v = rgb->GetValue(p * channels + c);
          peak = std::max(peak, v);
          sum += v / 3.0;
        }
        saturated += peak >= 250 ? 1 : 0;
      }
      const double cover = 100.0 * relief / static_cast<double>(z->GetNumberOfTuples());
      const double white = relief > 0 ? 100.0 * saturated / static_cast<double>(relief) : 0.0;
      const double mean = relief > 0 ? sum / static_cast<double>(relief) : 0.0;
      std::printf("%s: relief covers %.1f%% of the view, %.2f%% of its pixels saturated (a channel "
                  ">= 250), mean level %.1f\n",
        oldDefaults ? "tone mapping off" : "README defaults", cover, white, mean);
      std::printf("(%s)\n", headlight ? "with VTK's headlight" : "environment only");
      if (!png.empty())
      {
        vtkNew<vtkPNGWriter> writer;
        writer->SetInputConnection(grab->GetOutputPort());
        writer->SetFileName(png.c_str());
        writer->Write();
      }
      if (cover < 20.0 || mean < 20.0)
      {
        std::printf("FAILED: the relief is missing or black\n");
        return 1;
      }
      if (white > 1.0)
      {
        std::printf("FAILED: over-exposed (more than 1%% of the relief saturated)\n");
        return 1;
      }
      std::printf("exposure OK\n");
    }
  }
  return 0;
}
