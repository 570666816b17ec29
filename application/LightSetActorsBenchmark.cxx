// SPDX-License-Identifier: BSD-3-Clause
#include "LightSetActorsBenchmark.h"

#include "CommandLine.h"
#include "ImageCompare.h"
#include "LightSetActorsScene.h"
#include "Timing.h"
#include "vtkLightSetLighting.h"

#include <vtkRenderWindow.h>

#include <algorithm>
#include <chrono>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace mesolight
{
namespace
{
// The median frame time after a warm-up frame (shader compilation, uploads); each frame waits
// for the GPU.
double MedianFrameMs(vtkRenderWindow* window, int frames)
{
  const auto frame = [window]()
  {
    window->Render();
    window->WaitForCompletion();
  };
  frame();
  return MedianMilliseconds(frames, frame);
}

const char* RemainderName(int remainder)
{
  return remainder == vtkLightSetLighting::RemainderNone
    ? "none"
    : (remainder == vtkLightSetLighting::RemainderAmbient ? "ambient" : "sh9");
}

struct Row
{
  std::string Scene;
  std::string Variant;
  int K = 0;
  std::string Remainder;
  bool Shadows = false;
  LightSetActorsError Exact;      // against the exact reference (environment or light set)
  LightSetActorsError PathTraced; // against the path tracer
  double Ms = 0.0;
};
} // namespace

//------------------------------------------------------------------------------
int RunLightSetActorsBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench light-set-actors",
    "mesolight bench light-set-actors [options]\n\nA white Lambertian sphere drawn by "
    "vtkPolyDataMapper, lit by the median-cut lights of\nan environment through "
    "vtkLightSetLighting: K strongest lights as directional VTK\nlights, the rest as SH9 "
    "(or a constant, or nothing), optionally with shadow maps.\nScene 'sphere': the sphere "
    "alone, against the exact irradiance of the map and the\npath tracer; scene 'plane': the "
    "sphere above a plane, against the light set with\nexact visibility and the path tracer "
    "(direct light). Errors: mean and p95 relative\nerror over the object; frame time at "
    "--frame-size.\n");
  cl.AddValue("--environment", "SPEC", "procedural:sky, procedural:sun or a lat-long HDR file",
    "procedural:sun");
  cl.AddValue("--lights", "N", "median-cut lights of the environment", "256");
  cl.AddValue("--counts", "K,K,..", "directional VTK lights", "0,1,2,4,8,16");
  cl.AddValue("--size", "N", "compared image size (N x N)", "128");
  cl.AddValue("--samples", "N", "path-traced samples per pixel", "256");
  cl.AddValue("--frame-size", "N", "timed window size (N x N)", "512");
  cl.AddValue("--frames", "N", "timed frames per configuration (median)", "20");
  cl.AddValue("--shadow-map", "N", "shadow map resolution", "2048");
  cl.AddValue("--csv", "FILE", "also write the rows as CSV");
  int exitCode = 0;
  if (!cl.ParseArguments(args, { "--csv" }, { "--environment" }, exitCode))
  {
    return exitCode;
  }
  std::string error;
  int lights = 0, size = 0, samples = 0, frameSize = 0, frames = 0, shadowMap = 0;
  std::vector<int> counts;
  if (!cl.GetInts({ { "--lights", 1, 4096, &lights }, { "--size", 16, 2048, &size },
                    { "--samples", 1, 1 << 16, &samples }, { "--frame-size", 16, 4096, &frameSize },
                    { "--frames", 1, 1000, &frames }, { "--shadow-map", 16, 8192, &shadowMap } },
        error) ||
    !cl.GetIntList("--counts", 0, 64, counts, error))
  {
    return cl.UsageError(error);
  }

  std::vector<Row> rows;
  for (const bool plane : { false, true })
  {
    LightSetActorsOptions options;
    options.Environment = cl.Get("--environment");
    options.Lights = lights;
    options.Plane = plane;
    options.Size = size;
    LightSetActorsScene scene;
    if (!BuildLightSetActorsScene(options, scene, error))
    {
      std::cerr << "mesolight bench light-set-actors: " << error << "\n";
      return 1;
    }
    const auto start = std::chrono::steady_clock::now();
    const std::vector<float> exact =
      plane ? ExactLightSetLightSetActors(scene) : ExactEnvironmentLightSetActors(scene);
    const std::vector<float> traced = PathTracedLightSetActors(scene, samples);
    std::cout << (plane ? "plane" : "sphere") << ": references in " << std::fixed
              << std::setprecision(1) << SecondsSince(start) << " s\n";
    LightSetActorsScene timedScene = scene;
    timedScene.Options.Size = frameSize;

    auto measure = [&](const std::string& variantName, const LightSetActorsVariant& v)
    {
      Row row;
      row.Scene = plane ? "plane" : "sphere";
      row.Variant = variantName;
      row.K = v.HeadlightOnly ? 0 : v.DirectionalLights;
      row.Remainder = v.HeadlightOnly ? "-" : RemainderName(v.Remainder);
      row.Shadows = v.Shadows;
      LightSetActorsView view = MakeLightSetActorsView(scene, v, error);
      if (!view.Window)
      {
        return false;
      }
      const Frame frame = CaptureFrame(view.Window);
      row.Exact = CompareLightSetActors(frame, exact, scene.Exposure);
      row.PathTraced = CompareLightSetActors(frame, traced, scene.Exposure);
      LightSetActorsView timed = MakeLightSetActorsView(timedScene, v, error);
      row.Ms = MedianFrameMs(timed.Window, frames);
      rows.push_back(row);
      return true;
    };
    for (int k : counts)
    {
      for (const bool shadows : { false, true })
      {
        if (shadows && (!plane || k == 0))
        {
          continue; // the sphere alone casts no shadow on itself; K = 0 has no shadowed light
        }
        LightSetActorsVariant v;
        v.DirectionalLights = k;
        v.Shadows = shadows;
        v.ShadowMapResolution = shadowMap;
        if (!measure("light set", v))
        {
          std::cerr << "mesolight bench light-set-actors: " << error << "\n";
          return 1;
        }
      }
    }
    const int k = 8;
    for (const int remainder :
      { int(vtkLightSetLighting::RemainderAmbient), int(vtkLightSetLighting::RemainderNone) })
    {
      LightSetActorsVariant v;
      v.DirectionalLights = k;
      v.Remainder = remainder;
      v.Shadows = plane;
      v.ShadowMapResolution = shadowMap;
      measure("light set", v);
    }
    LightSetActorsVariant headlight;
    headlight.HeadlightOnly = true;
    measure("headlight only (negative)", headlight);
    LightSetActorsVariant flipped;
    flipped.DirectionalLights = k;
    flipped.FlippedUp = true;
    measure("lights read y-up (negative)", flipped);
  }

  std::cout << "\nenvironment " << cl.Get("--environment") << ", " << lights
            << " median-cut lights, " << size << "x" << size << " compared, " << samples
            << " path samples/pixel, frame time at " << frameSize << "x" << frameSize << "\n";
  std::cout << std::left << std::setw(7) << "scene" << std::setw(29) << "variant" << std::right
            << std::setw(3) << "K" << std::setw(9) << "rest" << std::setw(8) << "shadows"
            << std::setw(11) << "exact mean" << std::setw(10) << "exact p95" << std::setw(9)
            << "PT mean" << std::setw(9) << "PT p95" << std::setw(10) << "ms/frame"
            << "\n";
  for (const Row& r : rows)
  {
    std::cout << std::left << std::setw(7) << r.Scene << std::setw(29) << r.Variant << std::right
              << std::setw(3) << r.K << std::setw(9) << r.Remainder << std::setw(8)
              << (r.Shadows ? "on" : "off") << std::fixed << std::setprecision(1) << std::setw(10)
              << 100.0 * r.Exact.Mean << "%" << std::setw(9) << 100.0 * r.Exact.P95 << "%"
              << std::setw(8) << 100.0 * r.PathTraced.Mean << "%" << std::setw(8)
              << 100.0 * r.PathTraced.P95 << "%" << std::setprecision(2) << std::setw(10) << r.Ms
              << "\n";
  }
  std::cout << "exact: sphere = the map's exact irradiance; plane = the light set with exact "
               "visibility.\nPT: the path tracer, direct light (noise included).\n";

  if (cl.Has("--csv"))
  {
    std::ofstream csv(cl.Get("--csv"));
    csv << "scene,variant,k,remainder,shadows,exact_mean,exact_p95,pt_mean,pt_p95,ms_per_frame,"
           "pixels\n";
    for (const Row& r : rows)
    {
      csv << r.Scene << ',' << r.Variant << ',' << r.K << ',' << r.Remainder << ','
          << (r.Shadows ? 1 : 0) << ',' << r.Exact.Mean << ',' << r.Exact.P95 << ','
          << r.PathTraced.Mean << ',' << r.PathTraced.P95 << ',' << r.Ms << ',' << r.Exact.Pixels
          << '\n';
    }
    if (!csv)
    {
      std::cerr << "mesolight bench light-set-actors: cannot write " << cl.Get("--csv") << "\n";
      return 1;
    }
  }
  return 0;
}

} // namespace mesolight
