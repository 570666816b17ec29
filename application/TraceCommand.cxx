// SPDX-License-Identifier: BSD-3-Clause
#include "TraceCommand.h"

#include "CommandLine.h"
#include "CornellRegions.h"
#include "DisplayTransform.h"
#include "OutputFile.h"
#include "ReliefScene.h" // HasDisplay
#include "Timing.h"
#include "TraceObjScene.h"
#include "TraceScenes.h"

#include "EmbreeScene.h"
#include "ObjScene.h"
#include "PathTracer.h"
#include "TexturedRayTracer.h"
#include "TriangleScene.h"
#include "vtkEmbreeRayTracer.h"

#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkImageActor.h>
#include <vtkImageData.h>
#include <vtkImageMapper3D.h>
#include <vtkInteractorStyleImage.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkUnsignedCharArray.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>

namespace mesolight
{

vtkSmartPointer<vtkImageData> ToDisplayBytes(const RgbImage& image)
{
  auto bytes = vtkSmartPointer<vtkImageData>::New();
  bytes->SetDimensions(image.Width, image.Height, 1);
  bytes->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  auto* out = static_cast<unsigned char*>(bytes->GetScalarPointer());
  const DisplayTransform display{}; // exposure 1, clamp, sRGB
  for (std::size_t v = 0; v < image.Rgb.size(); ++v)
  {
    const float linear = std::isfinite(image.Rgb[v]) ? image.Rgb[v] : 0.0f;
    out[v] = static_cast<unsigned char>(ApplyDisplayTransform(display, linear) * 255.0f + 0.5f);
  }
  return bytes;
}

bool WritePng(vtkImageData* image, const std::string& fileName)
{
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(fileName.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

namespace
{
// A window showing an image pixel for pixel.
struct ImageWindow
{
  vtkNew<vtkImageData> Shown;
  vtkNew<vtkImageActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  vtkNew<vtkRenderWindowInteractor> Interactor;

  ImageWindow(int width, int height, const char* title)
  {
    this->Shown->SetDimensions(width, height, 1);
    this->Shown->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
    std::fill_n(
      static_cast<unsigned char*>(this->Shown->GetScalarPointer()), 3 * width * height, 0);
    this->Actor->GetMapper()->SetInputData(this->Shown);
    this->Renderer->AddActor(this->Actor);
    this->Window->AddRenderer(this->Renderer);
    this->Window->SetSize(width, height);
    this->Window->SetWindowName(title);
    this->Interactor->SetRenderWindow(this->Window);
    vtkNew<vtkInteractorStyleImage> style;
    this->Interactor->SetInteractorStyle(style);
    vtkCamera* camera = this->Renderer->GetActiveCamera();
    camera->ParallelProjectionOn();
    camera->SetFocalPoint(0.5 * (width - 1), 0.5 * (height - 1), 0.0);
    camera->SetPosition(0.5 * (width - 1), 0.5 * (height - 1), 1000.0);
    camera->SetViewUp(0.0, 1.0, 0.0);
    camera->SetParallelScale(0.5 * height);
    this->Renderer->ResetCameraClippingRange();
    this->Interactor->Initialize();
  }
  void Show(vtkImageData* image)
  {
    this->Shown->DeepCopy(image);
    this->Shown->Modified();
    this->Window->Render();
  }
};

int TraceCornell(const CommandLine& cl, int width, int height, int threads, bool interactive)
{
  std::string error;
  int samples = 64;
  int seed = 1;
  if (!cl.GetInt("--samples", 1, 1 << 20, samples, error) ||
    !cl.GetInt("--seed", 0, 1 << 30, seed, error))
  {
    std::cerr << "mesolight trace: " << error << "\n";
    return 2;
  }
  const TriangleScene box = MakeCornellBox();
  if (cl.Has("--export-obj"))
  {
    // The project's one OBJ writer (temporary files renamed into place, nothing overwritten),
    // read by other renderers (the Cycles comparison).
    try
    {
      mesolight::WriteObjScene(box, cl.Get("--export-obj"), false,
        "Mesolight's Cornell box (millimetres, y up, faces counter-clockwise from the front)");
    }
    catch (const std::exception& e)
    {
      std::cerr << "mesolight trace: " << e.what() << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--export-obj") << " and its .mtl\n";
    return 0;
  }
  const EmbreeScene embree(box);
  PathTracerSettings settings;
  settings.Threads = threads;
  const PathTracer tracer(embree, settings);
  const auto start = std::chrono::steady_clock::now();
  const RgbImage image = tracer.RenderImage(
    PinholeCamera(CornellCamera{}), width, height, samples, static_cast<std::uint64_t>(seed));
  const double seconds = SecondsSince(start);
  if (image.Width == 0)
  {
    std::cerr << "mesolight trace: path tracing failed\n";
    return 1;
  }
  std::cout << "cornell: " << width << "x" << height << ", " << samples << " paths per pixel in "
            << std::fixed << std::setprecision(2) << seconds << " s (" << std::setprecision(3)
            << static_cast<double>(width) * height * samples / seconds / 1e6 << " M paths/s)\n";
  auto bytes = ToDisplayBytes(image);
  const std::string out = cl.Get("--out");
  if (!WritePng(bytes, out))
  {
    std::cerr << "mesolight trace: cannot write " << out << "\n";
    return 1;
  }
  std::cout << "wrote " << out << "\n";
  if (cl.Has("--exr"))
  {
    if (!WriteLinearImage(image, cl.Get("--exr"), error))
    {
      std::cerr << "mesolight trace: " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--exr") << " (linear radiance)\n";
  }
  if (cl.Has("--compare-exr"))
  {
    RgbImage theirs;
    if (!ReadLinearImage(cl.Get("--compare-exr"), theirs, error))
    {
      std::cerr << "mesolight trace: " << error << "\n";
      return 1;
    }
    double tolerance = 0.05;
    if (!cl.GetDouble("--tolerance", 0.0, 10.0, tolerance, error))
    {
      std::cerr << "mesolight trace: " << error << "\n";
      return 2;
    }
    if (!CompareCornellRegions(box, image, theirs, tolerance))
    {
      return 1;
    }
  }
  if (interactive)
  {
    ImageWindow window(width, height, "mesolight trace: Cornell box (path traced)");
    window.Show(bytes);
    window.Interactor->Start();
  }
  return 0;
}
} // namespace

int RunTraceCommand(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight trace",
    "mesolight trace [options]\n\nRay traces a built-in scene on the CPU with Embree "
    "(Ahern 1999: texture-mapped\nmaterial channels, glossy reflection, adaptive supersampling, "
    "progressive\nrefinement), or path traces the Cornell box or any OBJ + MTL scene (Kd, Ks, "
    "emitters from Ke)\nfrom a walkthrough camera (the same --camera and --fov as `vlf render`) "
    "to linear EXR.\n");
  cl.AddValue("--scene", "NAME",
    "spheres (textured spheres on a checker), ring (bump + roughness maps), "
    "cornell (path-traced reference; from a walkthrough camera with --camera or --relief), "
    "or FILE.obj (path traced, with its .mtl)",
    "spheres");
  cl.AddValue("--size", "WxH",
    "image size in pixels, as `render` and `vlf render` take it (default: 640x480)");
  cl.AddValue("--width", "N", "image width in pixels (the W of --size)", "640");
  cl.AddValue("--height", "N", "image height in pixels (the H of --size)", "480");
  cl.AddValue("--samples", "N", "cornell, FILE.obj: paths per pixel", "64");
  cl.AddValue("--seed", "N", "cornell, FILE.obj: random seed of the paths", "1");
  cl.AddFlag(
    "--adaptive", "adaptive supersampling: 3x3 rays where a pixel differs from a neighbour");
  cl.AddValue(
    "--threshold", "X", "adaptive supersampling threshold (largest RGB difference, 0..1)", "0.1");
  cl.AddFlag(
    "--progressive", "progressive refinement: 1 ray, 2x2 blocks, 4x4 ... (shown as it happens)");
  cl.AddFlag("--nearest", "nearest texture lookups instead of bilinear");
  cl.AddValue("--glossy-samples", "N", "distributed rays per rough reflection", "16");
  cl.AddValue("--max-depth", "N", "reflection recursion limit", "5");
  cl.AddValue("--threads", "N", "worker threads (0: all cores)", "0");
  cl.AddValue("--out", "FILE.png", "where to write the image", "mesolight-trace.png");
  cl.AddValue("--exr", "FILE.exr", "cornell, FILE.obj: also write the linear radiance");
  AddTraceObjOptions(cl);
  cl.AddValue("--export-obj", "FILE.obj", "cornell: write the box as OBJ + MTL and stop");
  cl.AddValue("--compare-exr", "FILE.exr",
    "cornell: compare mean radiance per wall with another renderer's "
    "linear image of the same view (exit 1 when they differ)");
  cl.AddValue("--tolerance", "X", "relative tolerance of --compare-exr", "0.05");
  cl.AddFlag("--offscreen", "only write the image, never open a window");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  int width = 0, height = 0, glossy = 0, depth = 0, threads = 0;
  double threshold = 0.0;
  if (cl.Has("--size") && (cl.Has("--width") || cl.Has("--height")))
  {
    return cl.UsageError("give --size WxH or --width and --height, not both");
  }
  const bool sized = cl.Has("--size");
  if ((sized && !cl.GetSize("--size", 1, 16384, width, height, error)) ||
    (!sized && !cl.GetInt("--width", 1, 16384, width, error)) ||
    (!sized && !cl.GetInt("--height", 1, 16384, height, error)) ||
    !cl.GetInt("--glossy-samples", 1, 1024, glossy, error) ||
    !cl.GetInt("--max-depth", 0, 64, depth, error) ||
    !cl.GetInt("--threads", 0, 1024, threads, error) ||
    !cl.GetDouble("--threshold", 0.0, 10.0, threshold, error))
  {
    return cl.UsageError(error);
  }
  // Every option and every output is checked before anything is traced or written.
  int samples = 64, seed = 1;
  double tolerance = 0.05;
  if (!cl.GetInt("--samples", 1, 1 << 20, samples, error) ||
    !cl.GetInt("--seed", 0, 1 << 30, seed, error) ||
    !cl.GetDouble("--tolerance", 0.0, 10.0, tolerance, error))
  {
    return cl.UsageError(error);
  }
  const std::string compare = cl.Get("--compare-exr");
  std::string problem;
  if (cl.Has("--export-obj"))
  {
    const std::string obj = cl.Get("--export-obj");
    problem = CheckOutputFile(obj, { compare });
    if (problem.empty()) // the .mtl written beside it
    {
      problem = CheckOutputFile(mesolight::MaterialFileOf(obj), { compare, obj });
    }
  }
  else
  {
    // An OBJ scene and its material file are inputs the outputs must not replace.
    const std::string sceneFile = IsObjSceneName(cl.Get("--scene")) ? cl.Get("--scene") : "";
    const std::string materialFile = sceneFile.empty() ? "" : MaterialFileOf(sceneFile);
    problem = CheckOutputFile(cl.Get("--out"),
      { compare, cl.Get("--exr"), cl.Get("--relief-mask"), sceneFile, materialFile });
    if (problem.empty() && cl.Has("--exr"))
    {
      problem = CheckOutputFile(cl.Get("--exr"),
        { compare, cl.Get("--out"), cl.Get("--relief-mask"), sceneFile, materialFile });
    }
    if (problem.empty() && cl.Has("--relief-mask"))
    {
      problem = CheckOutputFile(cl.Get("--relief-mask"),
        { compare, cl.Get("--out"), cl.Get("--exr"), sceneFile, materialFile });
    }
  }
  if (problem.empty())
  {
    problem = CheckImageOutputNames(cl);
  }
  if (!problem.empty())
  {
    return cl.UsageError(problem);
  }
  const std::string sceneName = cl.Get("--scene");
  const bool interactive = !cl.Has("--offscreen") && HasDisplay();
  // The built-in box from a walkthrough camera, or with a relief: the OBJ scenes' path.
  bool cornellAsObj = false;
  for (const char* walkthrough :
    { "--camera", "--view-up", "--fov", "--view-angle", "--bounces", "--relief" })
  {
    cornellAsObj = cornellAsObj || (sceneName == "cornell" && cl.Has(walkthrough));
  }
  if (IsObjSceneName(sceneName) || cornellAsObj)
  {
    if (cl.Has("--export-obj") || cl.Has("--compare-exr"))
    {
      return cl.UsageError("--export-obj and --compare-exr are for --scene cornell only");
    }
    return TraceObjScene(cl, width, height, threads);
  }
  // The walkthrough camera and the path length belong to OBJ scenes; the built-in scenes have
  // their own cameras (the Cornell box's is the published one its comparisons assume).
  for (const char* objOnly :
    { "--camera", "--view-up", "--fov", "--view-angle", "--bounces", "--relief", "--relief-mask" })
  {
    if (cl.Has(objOnly))
    {
      return cl.UsageError(std::string(objOnly) +
        " applies to --scene FILE.obj or cornell only; the '" + sceneName +
        "' scene has its own camera");
    }
  }
  if (sceneName == "cornell")
  {
    return TraceCornell(cl, width, height, threads, interactive);
  }
  vtkNew<vtkRenderer> scene;
  vtkNew<vtkEmbreeRayTracer> tracer;
  if (sceneName == "spheres")
  {
    BuildSpheresScene(scene, tracer);
  }
  else if (sceneName == "ring")
  {
    BuildRingScene(scene, tracer);
  }
  else
  {
    std::cerr << "mesolight trace: unknown scene '" << sceneName
              << "' (spheres, ring, cornell, or an OBJ file FILE.obj)\n";
    return 2;
  }
  tracer->SetRenderer(scene);
  tracer->SetWidth(width);
  tracer->SetHeight(height);
  tracer->SetAdaptiveSupersampling(cl.Has("--adaptive"));
  tracer->SetAdaptiveThreshold(threshold);
  tracer->SetProgressive(cl.Has("--progressive"));
  tracer->SetBilinearTextures(!cl.Has("--nearest"));
  tracer->SetGlossySamples(glossy);
  tracer->SetMaxDepth(depth);
  tracer->SetNumberOfThreads(threads);

  std::unique_ptr<ImageWindow> window;
  vtkNew<vtkCallbackCommand> refinement;
  if (interactive)
  {
    window.reset(new ImageWindow(width, height, "mesolight trace"));
    window->Window->Render();
    refinement->SetClientData(window.get());
    refinement->SetCallback(
      [](vtkObject* caller, unsigned long, void* client, void*)
      {
        auto* shown = static_cast<ImageWindow*>(client);
        shown->Show(static_cast<vtkEmbreeRayTracer*>(caller)->GetPartialImage());
      });
    tracer->AddObserver(vtkEmbreeRayTracer::RefinementEvent, refinement);
  }
  const auto start = std::chrono::steady_clock::now();
  tracer->Update();
  const double seconds = SecondsSince(start);
  vtkImageData* image = tracer->GetOutput();
  int dims[3];
  image->GetDimensions(dims);
  if (dims[0] != width || dims[1] != height || !image->GetPointData()->GetScalars())
  {
    std::cerr << "mesolight trace: ray tracing failed\n";
    return 1;
  }
  std::cout << sceneName << ": " << width << "x" << height << " in " << std::fixed
            << std::setprecision(2) << seconds << " s; " << tracer->GetPrimaryRays() << " primary, "
            << tracer->GetShadowRays() << " shadow, " << tracer->GetSecondaryRays()
            << " reflection rays; " << tracer->GetSupersampledPixels() << " pixels supersampled; "
            << tracer->GetAnalyticSphereCount() << " spheres, " << tracer->GetTriangleCount()
            << " triangles\n";
  const std::string out = cl.Get("--out");
  // Only the RGB bytes go to the PNG.
  vtkNew<vtkImageData> bytes;
  bytes->SetDimensions(width, height, 1);
  bytes->GetPointData()->SetScalars(image->GetPointData()->GetScalars());
  if (!WritePng(bytes, out))
  {
    std::cerr << "mesolight trace: cannot write " << out << "\n";
    return 1;
  }
  std::cout << "wrote " << out << "\n";
  if (window)
  {
    window->Show(bytes);
    window->Interactor->Start();
  }
  return 0;
}

} // namespace mesolight
