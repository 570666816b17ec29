// SPDX-License-Identifier: BSD-3-Clause
#include "TraceObjScene.h"

#include "CommandLine.h"
#include "CornellRegions.h" // WriteLinearImage
#include "LightFieldCamera.h"
#include "OutputFile.h"
#include "Timing.h"
#include "TraceCommand.h" // ToDisplayBytes, WritePng
#include "TraceRelief.h"

#include "EmbreeScene.h"
#include "ObjScene.h"
#include "PathTracer.h"
#include "PinholeCamera.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <iomanip>
#include <iostream>

namespace mesolight
{

bool IsObjSceneName(const std::string& scene)
{
  return HasExtension(scene, ".obj");
}

void AddTraceObjOptions(CommandLine& cl)
{
  AddLightFieldCameraOptions(cl);
  AddTraceReliefOptions(cl);
  cl.AddValue("--bounces", "N",
    "FILE.obj: most bounces of a path (Russian roulette ends most paths long before)", "1000");
}

int TraceObjScene(const CommandLine& cl, int width, int height, int threads)
{
  const char* command = "mesolight trace";
  std::string error;
  int samples = 64, seed = 1, bounces = 1000;
  double fov = 39.3077;
  if (!cl.GetInt("--samples", 1, 1 << 20, samples, error) ||
    !cl.GetInt("--seed", 0, 1 << 30, seed, error) ||
    !cl.GetInt("--bounces", 1, 100000, bounces, error) || !ReadViewAngle(cl, fov, error))
  {
    return cl.UsageError(error);
  }
  const std::string path = cl.Get("--scene");
  ObjSceneRead read;
  if (path == "cornell")
  {
    read.Scene = MakeCornellBox(); // the built-in box, seen from a walkthrough camera
  }
  else
  {
    try
    {
      ObjReadOptions options;
      options.RequireEmitter = true; // without an emitter every pixel is black
      read = ReadObjScene(path, options);
    }
    catch (const std::exception& e)
    {
      std::cerr << command << ": " << e.what() << "\n";
      return 1;
    }
  }
  for (const std::string& warning : read.Warnings)
  {
    std::cerr << command << ": warning: " << warning << "\n";
  }
  glm::vec3 lower, upper, eye, focal;
  double up[3] = { 0.0, 1.0, 0.0 };
  if (!SceneBounds(read.Scene, lower, upper))
  {
    std::cerr << command << ": " << path << " has no triangles\n";
    return 1;
  }
  if (!ReadCameraOptions(cl, lower, upper, eye, focal, up, error))
  {
    return cl.UsageError(error);
  }
  // The relief after the camera: its default view is the scene's without the relief behind it.
  std::string reliefSurface;
  if (!ApplyTraceRelief(cl, read.Scene, reliefSurface, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 1;
  }
  PinholeCamera camera;
  camera.Position = eye;
  camera.FocalPoint = focal;
  camera.ViewUp = glm::vec3(up[0], up[1], up[2]);
  camera.ViewAngleDegrees = static_cast<float>(fov);
  try
  {
    const EmbreeScene embree(read.Scene);
    PathTracerSettings settings;
    settings.Threads = threads;
    settings.MaxDepth = bounces;
    const PathTracer tracer(embree, settings);
    const auto start = std::chrono::steady_clock::now();
    const RgbImage image =
      tracer.RenderImage(camera, width, height, samples, static_cast<std::uint64_t>(seed));
    const double seconds = SecondsSince(start);
    if (image.Width == 0)
    {
      std::cerr << command << ": path tracing failed\n";
      return 1;
    }
    std::cout << path << ": " << read.Scene.TriangleCount() << " triangles, "
              << tracer.EmitterCount() << " emitter triangles; " << width << "x" << height << ", "
              << samples << " paths per pixel in " << std::fixed << std::setprecision(2) << seconds
              << " s (" << std::setprecision(3)
              << static_cast<double>(width) * height * samples / seconds / 1e6 << " M paths/s)\n";
    // The PNG: exposure 1, clamp, sRGB (the light field's default display).
    if (!WritePng(ToDisplayBytes(image), cl.Get("--out")))
    {
      std::cerr << command << ": cannot write " << cl.Get("--out") << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--out") << "\n";
    WarnIfAllBlack(command, image.Rgb, cl);
    if (cl.Has("--exr"))
    {
      if (!WriteLinearImage(image, cl.Get("--exr"), error))
      {
        std::cerr << command << ": " << error << "\n";
        return 1;
      }
      std::cout << "wrote " << cl.Get("--exr") << " (linear radiance)\n";
    }
    if (cl.Has("--relief-mask"))
    {
      const RgbImage mask = SurfaceMask(read.Scene, embree, reliefSurface, camera, width, height);
      if (!WriteLinearImage(mask, cl.Get("--relief-mask"), error))
      {
        std::cerr << command << ": " << error << "\n";
        return 1;
      }
      std::cout << "wrote " << cl.Get("--relief-mask") << " (relief coverage per pixel)\n";
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << command << ": " << e.what() << "\n";
    return 1;
  }
  return 0;
}

} // namespace mesolight
