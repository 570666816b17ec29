// SPDX-License-Identifier: BSD-3-Clause
#include "WalkthroughBenchmark.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "LightFieldCamera.h"
#include "OutputFile.h"
#include "Timing.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldActorTesting.h"
#include "vtkLightFieldObjectMapper.h"

#include "ObjScene.h"
#include "ObjectGatherer.h"
#include "ObjectMesh.h"

#include "LightField.h"
#include "PatchComparison.h"
#include "Propagation.h"
#include "Snapshot.h"
#include "TriangleScene.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace mesolight
{
namespace
{
namespace vlf = mesolight::vlf;
using Clock = std::chrono::steady_clock;

struct BenchRow
{
  std::string Mode;
  int Frames = 0;
  double FrameMs = 0.0;
  double SpecularMs = 0.0;
  double UploadMs = 0.0;
  double Coverage = 0.0; // fraction of the view given a CPU (screen-space) value
  double GoalMs = 0.0;   // frame time goal (convergence time for progressive-rest)
  std::string Goal;
  double DrawMs() const
  {
    const double ms = this->FrameMs - this->SpecularMs - this->UploadMs;
    return ms > 1e-6 ? ms : 0.0;
  }
  bool Met() const { return this->FrameMs <= this->GoalMs; }
  // The CPU screen-space pass per pixel it gave a value (the mirrors' pixels; raytrace: every
  // pixel the scene covers), microseconds; 0 without such pixels.
  double PassUsPerPixel(double windowPixels) const
  {
    const double valued = this->Coverage * windowPixels;
    return valued >= 1.0 ? 1000.0 * this->SpecularMs / valued : 0.0;
  }
};

// Renders `frames` frames turning the camera a little each (every frame a new view: the
// progressive mode never rests), after two warm-up frames.
BenchRow TimeFrames(vtkRenderWindow* window, vtkRenderer* renderer, vtkLightFieldActor* actor,
  int mode, int frames, const std::string& name)
{
  actor->SetRenderMode(mode);
  vtkCamera* camera = renderer->GetActiveCamera();
  BenchRow row;
  row.Mode = name;
  const int* size = window->GetSize();
  const double pixels = static_cast<double>(size[0]) * size[1];
  for (int f = -2; f < frames; ++f)
  {
    camera->Azimuth(f % 2 ? 0.25 : -0.125);
    renderer->ResetCameraClippingRange();
    const Clock::time_point start = Clock::now();
    window->Render();
    WaitForGpu(window);
    const double ms = 1000.0 * SecondsSince(start);
    if (f < 0)
    {
      continue;
    }
    row.FrameMs += ms;
    row.SpecularMs += 1000.0 * actor->GetLastSpecularSeconds();
    row.UploadMs += 1000.0 * actor->GetLastUploadSeconds();
    row.Coverage += static_cast<double>(actor->GetLastScreenPixels()) / pixels;
    ++row.Frames;
  }
  row.FrameMs /= row.Frames;
  row.SpecularMs /= row.Frames;
  row.UploadMs /= row.Frames;
  row.Coverage /= row.Frames;
  return row;
}

int Bench(const std::vector<std::string>& args)
{
  const char* command = "mesolight bench walkthrough";
  CommandLine cl(command,
    "mesolight bench walkthrough [FIELD] [options]\n\n"
    "Frame time of every walkthrough mode (vtkLightFieldActor) in an offscreen window: "
    "the Cornell box\nwith a mirror wall (or FIELD) and the plain Cornell box for the "
    "diffuse-only row, split into\nstages (CPU screen-space pass, texture upload, draw "
    "and composite).\n");
  cl.AddValue("--size", "WxH", "window size", "800x800");
  cl.AddValue("--frames", "N", "frames timed per mode (raytrace and rest: at most 5)", "30");
  cl.AddValue("--directions", "N", "directions of the built-in fields", "2049");
  cl.AddValue("--rays", "N", "rays per subfield side", "32");
  cl.AddValue("--iterations", "K", "propagation iterations", "6");
  cl.AddValue("--csv", "FILE", "write the table as CSV");
  cl.AddValue("--plot", "FILE.png", "write a chart of the stages (VTK charts)");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, cl.Positional());
      !problem.empty())
  {
    return cl.UsageError(problem);
  }
  std::string error;
  int width = 0, height = 0, frames = 0, directions = 0, rays = 0, iterations = 0;
  if (!cl.GetSize("--size", 1, 16384, width, height, error))
  {
    return cl.UsageError(error);
  }
  if (!cl.GetInt("--frames", 1, 100000, frames, error) ||
    !cl.GetInt("--directions", 5, 1 << 20, directions, error) ||
    !cl.GetInt("--rays", 4, 4096, rays, error) ||
    !cl.GetInt("--iterations", 1, 1000, iterations, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 2;
  }
  std::unique_ptr<vlf::LightField> mirrorField, diffuseField;
  try
  {
    const Clock::time_point start = Clock::now();
    if (cl.Positional().size() == 1)
    {
      mirrorField = vlf::ReadSnapshot(cl.Positional()[0]);
    }
    else
    {
      mirrorField = BenchField(MakeCornellBoxWithMirror(), directions, rays, iterations);
    }
    diffuseField = BenchField(MakeCornellBox(), directions, rays, iterations);
    std::cout << "fields ready in " << SecondsSince(start) << " s ("
              << mirrorField->Directions().Size() << " directions, "
              << mirrorField->Settings().RaysPerSide << " rays per side)\n";
  }
  catch (const std::exception& e)
  {
    std::cerr << command << ": " << e.what() << "\n";
    return 1;
  }
  const std::size_t fieldDirections = mirrorField->Directions().Size();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkLightFieldActor> actor;
  vtkLightFieldActorCore::SetLightField(actor, mirrorField.get());
  renderer->AddActor(actor);
  auto resetCamera = [&]()
  {
    SetCornellCamera(renderer->GetActiveCamera());
    renderer->ResetCameraClippingRange();
  };
  std::vector<BenchRow> rows;
  resetCamera();
  rows.push_back(
    TimeFrames(window, renderer, actor, vtkLightFieldActor::Geometry, frames, "geometry"));
  rows.back().GoalMs = 1000.0 / 30.0;
  rows.back().Goal = ">= 30 fps";
  vtkLightFieldActorCore::SetLightField(actor, diffuseField.get());
  resetCamera();
  rows.push_back(
    TimeFrames(window, renderer, actor, vtkLightFieldActor::Progressive, frames, "diffuse-only"));
  rows.back().GoalMs = std::max(1000.0 / 30.0, 2.0 * rows[0].FrameMs);
  rows.back().Goal = ">= 30 fps or <= 2x geometry";
  // The same draw with the shadow code compiled in although nothing casts a shadow (every
  // radiance draw before the code was left out of such draws): the before of the same run.
  resetCamera();
  vtkLightFieldActorTesting::SetShadowCodeAlways(actor, true);
  BenchRow before = TimeFrames(
    window, renderer, actor, vtkLightFieldActor::Progressive, frames, "diffuse-shadow-code");
  vtkLightFieldActorTesting::SetShadowCodeAlways(actor, false);
  before.GoalMs = rows.back().GoalMs;
  before.Goal = rows.back().Goal;
  // And the geometry mode again: the load of the machine moves between rows.
  vtkLightFieldActorCore::SetLightField(actor, mirrorField.get());
  resetCamera();
  BenchRow geometryAgain =
    TimeFrames(window, renderer, actor, vtkLightFieldActor::Geometry, frames, "geometry-again");
  geometryAgain.GoalMs = 1000.0 / 30.0;
  geometryAgain.Goal = ">= 30 fps";
  vtkLightFieldActorCore::SetLightField(actor, mirrorField.get());
  resetCamera();
  rows.push_back(TimeFrames(
    window, renderer, actor, vtkLightFieldActor::Raytrace, std::min(frames, 5), "raytrace"));
  rows.back().GoalMs = 1000.0;
  rows.back().Goal = ">= 1 fps";
  resetCamera();
  rows.push_back(TimeFrames(
    window, renderer, actor, vtkLightFieldActor::Progressive, frames, "progressive-moving"));
  rows.back().GoalMs = 50.0;
  rows.back().Goal = ">= 20 fps";
  resetCamera();
  rows.push_back(
    TimeFrames(window, renderer, actor, vtkLightFieldActor::Coherent, frames, "coherent"));
  rows.back().GoalMs = 50.0;
  rows.back().Goal = ">= 20 fps";
  {
    // At rest: from the first frame of a new view to the frame showing its traced reflections.
    BenchRow rest;
    rest.Mode = "progressive-rest";
    resetCamera();
    actor->SetRenderMode(vtkLightFieldActor::Progressive);
    const int views = std::min(frames, 5);
    for (int v = 0; v < views; ++v)
    {
      renderer->GetActiveCamera()->Azimuth(0.5);
      renderer->ResetCameraClippingRange();
      const Clock::time_point start = Clock::now();
      window->Render();
      actor->WaitForTracedReflections(60.0);
      window->Render();
      WaitForGpu(window);
      rest.FrameMs += 1000.0 * SecondsSince(start);
      rest.UploadMs += 1000.0 * actor->GetLastUploadSeconds();
      rest.Coverage +=
        static_cast<double>(actor->GetLastScreenPixels()) / (static_cast<double>(width) * height);
      ++rest.Frames;
    }
    rest.FrameMs /= rest.Frames;
    rest.UploadMs /= rest.Frames;
    rest.Coverage /= rest.Frames;
    rest.SpecularMs = std::max(0.0, rest.FrameMs - rest.UploadMs); // the worker's trace dominates
    rest.GoalMs = 1000.0;
    rest.Goal = "converges <= 1 s";
    rows.push_back(rest);
  }
  rows.push_back(before);
  rows.push_back(geometryAgain);
  const double windowPixels = static_cast<double>(width) * height;

  // Stages: static diffuse = the diffuse-only row's draw (same shader and geometry, no screen
  // values); specular viewport = CPU pass + upload; composite = what a mode's draw adds to that.
  const double staticDiffuseMs = rows[1].DrawMs();
  std::cout << std::fixed << std::setprecision(2);
  std::cout << "\n"
            << width << "x" << height << ", " << fieldDirections
            << " directions; ms per frame (progressive-rest: ms to converge)\n";
  std::cout
    << "mode                 frames  frame ms     fps  specular ms  upload ms  draw+composite ms  "
       "(composite over static diffuse)  CPU-pass coverage  us/pass pixel  goal\n";
  for (const BenchRow& r : rows)
  {
    std::cout << std::left << std::setw(20) << r.Mode << std::right << std::setw(7) << r.Frames
              << std::setw(10) << r.FrameMs << std::setw(8) << 1000.0 / r.FrameMs << std::setw(13)
              << r.SpecularMs << std::setw(11) << r.UploadMs << std::setw(19) << r.DrawMs()
              << std::setw(33)
              << (r.Mode == "progressive-rest" ? 0.0 : r.DrawMs() - staticDiffuseMs)
              << std::setw(17) << 100.0 * r.Coverage << "%" << std::setw(15)
              << r.PassUsPerPixel(windowPixels) << "  " << r.Goal
              << (r.Met() ? " (met)" : " (NOT met)") << "\n";
  }
  {
    const double geometryMs = 0.5 * (rows[0].FrameMs + geometryAgain.FrameMs);
    std::cout << "diffuse walkthrough frame / geometry frame (mean of the two geometry rows): "
              << rows[1].FrameMs / geometryMs
              << " (goal <= 2); with the shadow code compiled in: " << before.FrameMs / geometryMs
              << "\n";
    for (const BenchRow& r : rows)
    {
      if (r.Mode == "progressive-moving" || r.Mode == "coherent")
      {
        std::cout << r.Mode << ": CPU pass " << r.PassUsPerPixel(windowPixels)
                  << " us per mirror pixel (" << r.SpecularMs << " ms over " << std::setprecision(0)
                  << r.Coverage * windowPixels << std::setprecision(2) << " pixels)\n";
      }
    }
  }
  if (cl.Has("--csv"))
  {
    std::ofstream csv(cl.Get("--csv"));
    csv << "mode,frames,frame_ms,fps,specular_ms,upload_ms,draw_composite_ms,static_diffuse_ms,"
           "composite_ms,"
           "cpu_pass_coverage,cpu_pass_us_per_pixel,goal,met,width,height,directions\n";
    for (const BenchRow& r : rows)
    {
      csv << r.Mode << "," << r.Frames << "," << r.FrameMs << "," << 1000.0 / r.FrameMs << ","
          << r.SpecularMs << "," << r.UploadMs << "," << r.DrawMs() << "," << staticDiffuseMs << ","
          << (r.Mode == "progressive-rest" ? 0.0 : r.DrawMs() - staticDiffuseMs) << ","
          << r.Coverage << "," << r.PassUsPerPixel(windowPixels) << "," << r.Goal << ","
          << (r.Met() ? 1 : 0) << "," << width << "," << height << "," << fieldDirections << "\n";
    }
    if (!csv)
    {
      std::cerr << command << ": could not write '" << cl.Get("--csv") << "'\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--csv") << "\n";
  }
  if (cl.Has("--plot"))
  {
    ScatterChart chart;
    chart.Title = "Light field walkthrough, " + std::to_string(width) + "x" +
      std::to_string(height) + ", " + std::to_string(fieldDirections) +
      " directions\n(0 geometry, 1 diffuse-only, 2 raytrace, 3 progressive-moving, 4 coherent, "
      "\n5 progressive-rest: time to converge, 6 diffuse-only with the shadow code, 7 geometry "
      "again)";
    chart.XLabel = "mode";
    chart.YLabel = "milliseconds (log scale)";
    chart.LogY = true;
    chart.YFloor = 0.01;
    ChartSeries frame{ "frame", {}, {} }, specular{ "CPU screen pass", {}, {} },
      upload{ "texture upload", {}, {} }, draw{ "draw + composite", {}, {} };
    chart.Line.Name = "goal";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      const double x = static_cast<double>(i);
      frame.X.push_back(x);
      frame.Y.push_back(rows[i].FrameMs);
      specular.X.push_back(x);
      specular.Y.push_back(rows[i].SpecularMs);
      upload.X.push_back(x);
      upload.Y.push_back(rows[i].UploadMs);
      draw.X.push_back(x);
      draw.Y.push_back(rows[i].DrawMs());
      chart.Line.X.push_back(x);
      chart.Line.Y.push_back(rows[i].GoalMs);
    }
    chart.Points = { frame, specular, upload, draw };
    if (!WriteScatterChartPng(chart, cl.Get("--plot"), error))
    {
      std::cerr << command << ": " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--plot") << "\n";
  }
  return 0;
}

} // namespace

std::unique_ptr<vlf::LightField> BenchField(
  const TriangleScene& scene, int directions, int rays, int iterations)
{
  vlf::LightFieldSettings settings;
  settings.Directions = static_cast<std::size_t>(directions);
  settings.RaysPerSide = rays;
  settings.TilesPerSide = std::max(1, rays / 8);
  std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(scene, settings);
  vlf::Propagate(*field, iterations);
  return field;
}

void WaitForGpu(vtkRenderWindow* window)
{
  if (vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window))
  {
    gl->WaitForCompletion();
  }
}

int RunWalkthroughBenchmark(const std::vector<std::string>& args)
{
  return Bench(args);
}

} // namespace mesolight
