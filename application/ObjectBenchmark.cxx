// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectBenchmark.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "LightFieldCamera.h"
#include "LightFieldObjectOptions.h"
#include "OutputFile.h"
#include "WalkthroughBenchmark.h"
#include "vtkMessageCollector.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldObjectMapper.h"

#include "LightField.h"
#include "ObjectGatherer.h"
#include "ObjectMesh.h"
#include "Snapshot.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkNew.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace mesolight
{
namespace
{
namespace vlf = mesolight::vlf;
using Clock = std::chrono::steady_clock;

double MillisecondsSince(Clock::time_point t)
{
  return 1000.0 * std::chrono::duration<double>(Clock::now() - t).count();
}

struct ObjectRow
{
  std::size_t Directions = 0;
  int Subdivision = 0;
  std::string Shadows;    // the shadow mode
  std::size_t Points = 0; // the gathered (subdivided) object's points
  int Frames = 0;
  double FrameMs = 0.0;    // wall time of Render() including the GPU
  double ObjectMs = 0.0;   // placement, gather and the tracer's instance
  double GatherMs = 0.0;   // of which the gather
  double ShadowMs = 0.0;   // shadow maps placed and filled
  double SpecularMs = 0.0; // the CPU screen-space pass (mirror pixels)
  double UploadMs = 0.0;
  double GatheredFraction = 0.0; // points re-gathered per move (the rest from the cache)
  double OtherMs() const
  {
    return std::max(
      0.0, this->FrameMs - this->ObjectMs - this->ShadowMs - this->SpecularMs - this->UploadMs);
  }
};

// The object's placement at frame f: a circle above the tall block, turning about y (the path
// of docs/walkthrough.md's measurements), so every frame moves it and every run repeats.
void Place(vtkActor* object, int frame, int frames)
{
  const double a = 2.0 * 3.14159265358979323846 * frame / std::max(frames, 1);
  object->SetPosition(420.0 + 40.0 * std::cos(a), 420.0, 380.0 + 40.0 * std::sin(a));
  object->SetOrientation(0.0, 18.0 * frame, 0.0);
  object->SetScale(110.0);
}

int Bench(const std::vector<std::string>& args)
{
  const char* command = "mesolight bench object";
  CommandLine cl(command,
    "mesolight bench object [FIELD] [options]\n\n"
    "Per-frame cost of a movable object in the light field walkthrough: a sphere moving every "
    "frame\nalong a circle above the tall block of the Cornell box with a mirror wall (or in "
    "FIELD), gathered\nfrom the field, casting shadow maps and seen in the mirror; split into "
    "stages (object update and\ngather, shadow maps, CPU screen pass, upload, draw) per "
    "direction count and subdivision level.\n");
  cl.AddValue("--size", "WxH", "window size", "800x800");
  cl.AddValue("--frames", "N", "frames timed per row (after two warm-up frames)", "20");
  cl.AddValue("--directions", "N,N,..", "direction counts of the built-in fields", "513,2049");
  cl.AddValue("--subdivisions", "L,L,..", "subdivision levels of the gathered object", "0,1,2,3");
  cl.AddValue("--points", "N", "points of the sphere before subdivision (about)", "1000");
  cl.AddValue("--gather-directions", "SET", "all, half or importance", "all");
  cl.AddValue("--gather-volume", "N",
    "0: gather at every vertex; N (2-128): an irradiance volume of N points (built in the "
    "warm-up frames)",
    "0");
  cl.AddValue("--mode", "MODE", "walkthrough mode: progressive or coherent", "coherent");
  cl.AddValue("--shadows", "MODE,MODE,..",
    "none, black, blend, field, pcf or soft; several: rows of each in turn (the draw's share of "
    "each shadow lookup in one run)",
    "field");
  cl.AddValue("--rays", "N", "rays per subfield side", "32");
  cl.AddValue("--iterations", "K", "propagation iterations", "6");
  cl.AddValue("--csv", "FILE", "write the table as CSV");
  cl.AddValue("--plot", "FILE.png", "write a chart of frame and stage times (VTK charts)");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, cl.Positional());
      !problem.empty())
  {
    return cl.UsageError(problem);
  }
  std::string error;
  int width = 0, height = 0, frames = 0, points = 0, rays = 0, iterations = 0;
  std::vector<int> directionList, subdivisions;
  if (!cl.GetSize("--size", 1, 16384, width, height, error) ||
    !cl.GetInt("--frames", 1, 100000, frames, error) ||
    !cl.GetInt("--points", 8, 1 << 22, points, error) ||
    !cl.GetInt("--rays", 4, 4096, rays, error) ||
    !cl.GetInt("--iterations", 1, 1000, iterations, error) ||
    !cl.GetIntList("--directions", 3, 1 << 20, directionList, error) ||
    !cl.GetIntList("--subdivisions", 0, 3, subdivisions, error))
  {
    return cl.UsageError(error);
  }
  const int mode = vtkLightFieldActor::GetRenderModeFromString(cl.Get("--mode"));
  if (mode != vtkLightFieldActor::Progressive && mode != vtkLightFieldActor::Coherent)
  {
    return cl.UsageError("--mode '" + cl.Get("--mode") + "' is not progressive or coherent");
  }
  const std::vector<std::string> shadowNames = cl.GetStringList("--shadows");
  for (const std::string& name : shadowNames)
  {
    if (vtkLightFieldActor::GetShadowModeFromString(name) < 0)
    {
      return cl.UsageError(
        "--shadows '" + name + "' is not none, black, blend, field, pcf or soft");
    }
  }
  const std::string directionSet = cl.Get("--gather-directions");
  const int gatherDirections = vtkLightFieldActor::GetGatherDirectionsFromString(directionSet);
  if (gatherDirections < 0)
  {
    return cl.UsageError(
      "--gather-directions '" + directionSet + "' is not all, half or importance");
  }
  int gatherVolume = 0;
  if (!cl.GetInt("--gather-volume", 0, 128, gatherVolume, error) || gatherVolume == 1)
  {
    return cl.UsageError(error.empty() ? "--gather-volume 1 is not a grid: use 0 or 2-128" : error);
  }
  if (cl.Positional().size() > 1)
  {
    return cl.UsageError("give at most one FIELD");
  }
  if (cl.Positional().size() == 1)
  {
    directionList = { 0 }; // the file's
  }
  // A UV sphere of (rings + 1)(2 rings + 1) points, about --points.
  const int rings = std::max(2, static_cast<int>(std::lround(std::sqrt(points / 2.0))));
  const vlf::ObjectMesh sphere = vlf::MakeSphere(0.5f, rings, 2 * rings);

  std::vector<ObjectRow> rows;
  for (const int directions : directionList)
  {
    std::unique_ptr<vlf::LightField> field;
    try
    {
      const Clock::time_point start = Clock::now();
      field = cl.Positional().empty()
        ? BenchField(MakeCornellBoxWithMirror(), directions, rays, iterations)
        : vlf::ReadSnapshot(cl.Positional()[0]);
      std::cout << "field of " << field->Directions().Size() << " directions ready in "
                << MillisecondsSince(start) / 1000.0 << " s\n";
    }
    catch (const std::exception& e)
    {
      std::cerr << command << ": " << e.what() << "\n";
      return 1;
    }
    vtkNew<vtkRenderWindow> window;
    window->SetOffScreenRendering(1);
    window->SetMultiSamples(0);
    window->SetSize(width, height);
    vtkNew<vtkRenderer> renderer;
    window->AddRenderer(renderer);
    vtkNew<vtkLightFieldActor> scene;
    vtkNew<MessageCollector> errors; // why the object was not shaded, should it not be
    scene->AddObserver(vtkCommand::ErrorEvent, errors);
    vtkLightFieldActorCore::SetLightField(scene, field.get());
    scene->SetRenderMode(mode);
    renderer->AddActor(scene);
    vtkNew<vtkActor> object;
    vtkNew<vtkLightFieldObjectMapper> shading;
    shading->SetInputData(ObjectPolyData(sphere));
    shading->SetLightFieldActor(scene);
    shading->SetShadingToGather();
    shading->SetGatherDirections(gatherDirections);
    scene->SetObjectIrradianceVolume(gatherVolume);
    object->SetMapper(shading);
    object->GetProperty()->SetDiffuseColor(0.7, 0.7, 0.7);
    scene->SetMovableObject(object);
    renderer->AddActor(object);
    SetCornellCamera(renderer->GetActiveCamera());
    for (const int level : subdivisions)
    {
      shading->SetSubdivision(level);
      for (const std::string& shadowName : shadowNames)
      {
        scene->SetShadowMode(vtkLightFieldActor::GetShadowModeFromString(shadowName));
        ObjectRow row;
        row.Directions = field->Directions().Size();
        row.Subdivision = level;
        row.Shadows = shadowName;
        for (int f = -2; f < frames; ++f)
        {
          Place(object, f + 2, frames + 2);
          renderer->ResetCameraClippingRange();
          const Clock::time_point start = Clock::now();
          window->Render();
          WaitForGpu(window);
          const double ms = MillisecondsSince(start);
          if (f < 0)
          {
            continue;
          }
          const vlf::ShadedObject* shaded = vtkLightFieldActorCore::GetShadedObject(scene);
          if (!shaded)
          {
            std::cerr << command << ": the object was not shaded: "
                      << (errors->Errors.empty() ? "no reason reported" : errors->Errors.back())
                      << "\n";
            return 1;
          }
          row.Points = shaded->Mesh.Positions.size();
          row.GatheredFraction +=
            static_cast<double>(shaded->GatheredPoints) / std::max<std::size_t>(1, row.Points);
          row.FrameMs += ms;
          row.ObjectMs += 1000.0 * scene->GetLastObjectSeconds();
          row.GatherMs += 1000.0 * scene->GetLastGatherSeconds();
          row.ShadowMs += 1000.0 * scene->GetLastShadowSeconds();
          row.SpecularMs += 1000.0 * scene->GetLastSpecularSeconds();
          row.UploadMs += 1000.0 * scene->GetLastUploadSeconds();
          ++row.Frames;
        }
        for (double* v : { &row.FrameMs, &row.ObjectMs, &row.GatherMs, &row.ShadowMs,
               &row.SpecularMs, &row.UploadMs, &row.GatheredFraction })
        {
          *v /= row.Frames;
        }
        rows.push_back(row);
      }
    }
  }

  std::cout << std::fixed << std::setprecision(2) << "\n"
            << width << "x" << height << ", " << cl.Get("--mode") << ", shadows "
            << cl.Get("--shadows") << ", gather directions " << directionSet
            << ", the object moving every frame; ms per frame\n"
            << "directions  subdiv   points  frame ms     fps  object ms  (gather ms)  shadow ms  "
               "specular ms  upload ms  draw+other ms  re-gathered  shadows\n";
  for (const ObjectRow& r : rows)
  {
    std::cout << std::setw(10) << r.Directions << std::setw(8) << r.Subdivision << std::setw(9)
              << r.Points << std::setw(10) << r.FrameMs << std::setw(8) << 1000.0 / r.FrameMs
              << std::setw(11) << r.ObjectMs << std::setw(13) << r.GatherMs << std::setw(11)
              << r.ShadowMs << std::setw(13) << r.SpecularMs << std::setw(11) << r.UploadMs
              << std::setw(15) << r.OtherMs() << std::setw(12) << 100.0 * r.GatheredFraction
              << "%  " << r.Shadows << "\n";
  }
  std::cout << "goal: >= 15 frames/s with a moving ~1000-point object gathered at "
               "2049 directions, coherent mode\n";
  if (cl.Has("--csv"))
  {
    std::ofstream csv(cl.Get("--csv"));
    csv << "directions,subdivision,points,frames,frame_ms,fps,object_ms,gather_ms,shadow_ms,"
           "specular_ms,upload_ms,draw_other_ms,regathered_fraction,width,height,mode,shadows\n";
    for (const ObjectRow& r : rows)
    {
      csv << r.Directions << "," << r.Subdivision << "," << r.Points << "," << r.Frames << ","
          << r.FrameMs << "," << 1000.0 / r.FrameMs << "," << r.ObjectMs << "," << r.GatherMs << ","
          << r.ShadowMs << "," << r.SpecularMs << "," << r.UploadMs << "," << r.OtherMs() << ","
          << r.GatheredFraction << "," << width << "," << height << "," << cl.Get("--mode") << ","
          << r.Shadows << "\n";
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
    chart.Title = "Movable object in the walkthrough, " + std::to_string(width) + "x" +
      std::to_string(height) + ", " + cl.Get("--mode") + ", object moving every frame";
    chart.XLabel = "object points (after subdivision)";
    chart.YLabel = "milliseconds per frame (log scale)";
    chart.LogY = true;
    chart.YFloor = 0.01;
    for (const int d : directionList)
    {
      ChartSeries frame{ "frame", {}, {} }, gather{ "gather", {}, {} },
        shadow{ "shadow maps", {}, {} }, specular{ "CPU screen pass", {}, {} };
      std::string suffix;
      for (const ObjectRow& r : rows)
      {
        if (d != 0 && r.Directions != static_cast<std::size_t>(d))
        {
          continue;
        }
        suffix = ", " + std::to_string(r.Directions) + " dirs";
        const double x = static_cast<double>(r.Points);
        frame.X.push_back(x);
        frame.Y.push_back(r.FrameMs);
        gather.X.push_back(x);
        gather.Y.push_back(r.GatherMs);
        shadow.X.push_back(x);
        shadow.Y.push_back(r.ShadowMs);
        specular.X.push_back(x);
        specular.Y.push_back(r.SpecularMs);
      }
      for (ChartSeries* s : { &frame, &gather, &shadow, &specular })
      {
        s->Name += suffix;
        chart.Points.push_back(*s);
      }
    }
    chart.Line.Name = "15 frames/s";
    chart.Line.X = { 0.0, static_cast<double>(rows.empty() ? 1 : rows.back().Points) };
    chart.Line.Y = { 1000.0 / 15.0, 1000.0 / 15.0 };
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

int RunObjectBenchmark(const std::vector<std::string>& args)
{
  return Bench(args);
}

} // namespace mesolight
