// SPDX-License-Identifier: BSD-3-Clause
#include "LightSetBenchmark.h"

#include "CommandLine.h"
#include "ImageCompare.h"
#include "LightSetReference.h"
#include "MathConstants.h"
#include "OutputFile.h"
#include "ReliefReference.h"
#include "ReliefScene.h"
#include "Timing.h"
#include "vtkReliefMapper.h"

#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace mesolight
{
namespace
{

struct Timing
{
  double MedianMs = 0.0;
};

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

} // namespace

//------------------------------------------------------------------------------
int RunLightSetBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench ibl",
    "mesolight bench ibl [options]\n\nA relief (--map, relief 16+8, self-shadowed) "
    "lit only by median-cut light\nsets of an environment: frame time per light "
    "count, the effect of each skip, the error\nagainst a Monte Carlo reference with "
    "exact height-field visibility, and relief vs relaxed\ncone stepping at equal "
    "error against the exact render of the same lights\n(--compare-count "
    "lights).\n");
  cl.AddValue("--environment", "SPEC", "procedural:sky, procedural:sun or a lat-long HDR file",
    "procedural:sun");
  cl.AddValue("--counts", "N,N,..", "light counts (one run for all)", "32,64,128,256,512,1024");
  cl.AddValue("--skip-count", "N", "light count of the skip measurements", "256");
  cl.AddValue("--frames", "N", "timed frames per configuration (median)", "10");
  cl.AddValue("--size", "WxH", "window size", "512x512");
  cl.AddValue("--samples", "N", "Monte Carlo samples per reference pixel", "2048");
  cl.AddValue("--csv", "FILE", "also write the rows as CSV");
  cl.AddValue("--map", "PATTERN", "procedural height map (HemisphereTorus, Bricks, Stone, ...)",
    "HemisphereTorus");
  cl.AddValue("--compare-count", "N",
    "light count of the relief vs relaxed-cone comparison at equal error (0: skip it)", "64");
  std::string error;
  int frames = 10, samples = 2048, skipCount = 256, compareCount = 64;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv" }, { cl.Get("--environment") });
      !problem.empty())
  {
    return cl.UsageError(problem);
  }
  if (!cl.GetInt("--frames", 1, 1000, frames, error) ||
    !cl.GetInt("--samples", 16, 1 << 20, samples, error) ||
    !cl.GetInt("--skip-count", 1, 4096, skipCount, error) ||
    !cl.GetInt("--compare-count", 0, 4096, compareCount, error))
  {
    return cl.UsageError(error);
  }
  std::vector<int> counts;
  if (!cl.GetIntList("--counts", 1, 4096, counts, error))
  {
    return cl.UsageError(error);
  }
  ReliefSceneOptions o;
  o.Pattern = cl.Get("--map");
  o.Resolution = 256;
  o.DepthScale = 0.12;
  o.ViewAngle = 40.0;
  o.ViewDistance = 2.2;
  o.Lights = 0;
  o.LinearSteps = 16;
  o.RefinementSteps = 8;
  o.Environment = cl.Get("--environment");
  o.EnvironmentLights = counts.front();
  if (!cl.GetSize("--size", 16, 8192, o.Width, o.Height, error))
  {
    return cl.UsageError(error);
  }

  ReliefScene scene;
  if (!BuildReliefScene(o, scene, error))
  {
    std::cerr << "mesolight bench ibl: " << error << "\n";
    return 1;
  }
  // White Lambertian surface, lit by the environment only: the reference is albedo / pi x E.
  scene.Actor->SetTexture(nullptr);
  scene.Actor->GetProperty()->SetAmbient(0.0);
  scene.Actor->GetProperty()->SetDiffuse(1.0);
  scene.Actor->GetProperty()->SetSpecular(0.0);
  vtkSmartPointer<vtkImageData> environment = LoadEnvironment(o.Environment, error);
  if (!environment)
  {
    std::cerr << "mesolight bench ibl: " << error << "\n";
    return 1;
  }
  ReliefReference hits;
  if (!ComputeReliefReference(MakeReliefReferenceInput(scene, o), hits, error))
  {
    std::cerr << "mesolight bench ibl: " << error << "\n";
    return 1;
  }
  const auto referenceStart = std::chrono::steady_clock::now();
  const std::vector<EnvironmentIrradianceSample> reference = ComputeEnvironmentReference(
    hits, scene.ReliefTexture, environment, o.DepthScale, 3000, samples, true);
  const double referenceSeconds = SecondsSince(referenceStart);
  // Exposure: the brightest reference pixel at about 200 of 255.
  double brightest = 0.0;
  for (const auto& s : reference)
  {
    brightest = std::max(brightest, (s.Irradiance[0] + s.Irradiance[1] + s.Irradiance[2]) / 3.0);
  }
  const double exposure = brightest > 0.0 ? 200.0 / 255.0 * Pi<double> / brightest : 1.0;
  scene.Mapper->GetReliefProperty()->SetExposure(exposure);

  auto window = MakeOffscreenWindow(o, scene.Renderer);
  struct Row
  {
    std::string Config;
    int Lights;
    double Ms;
    double ErrorMc;
    double DiffFull; // mean |difference| to the unskipped render, 8-bit levels (-1: n/a)
  };
  std::vector<Row> rows;
  auto setLights = [&](int count)
  {
    ReliefSceneOptions lo = o;
    lo.EnvironmentLights = count;
    vtkSmartPointer<vtkImageData> lights = MakeEnvironmentLights(lo, error);
    scene.Mapper->SetLightSetData(lights);
    return lights;
  };
  auto measure = [&](const std::string& config, int count, const Frame* full)
  {
    const double ms = MedianFrameMs(window, frames);
    const Frame frame = CaptureFrame(window);
    rows.push_back({ config, count, ms, EnvironmentError(frame, reference, exposure),
      full ? CompareFrames(frame, *full, 1e30).MeanColorError : -1.0 });
    return frame;
  };

  for (int count : counts)
  {
    setLights(count);
    measure("every light marches its shadow", count, nullptr);
  }
  scene.Mapper->GetReliefProperty()->SetShadowedLights(32);
  for (int count : counts)
  {
    setLights(count);
    measure("shadows for the 32 strongest facing lights", count, nullptr);
  }
  scene.Mapper->GetReliefProperty()->SetShadowedLights(0);
  setLights(skipCount);
  const Frame full = measure("reference configuration", skipCount, nullptr);
  scene.Mapper->GetReliefProperty()->ShadowCullingOff();
  measure("no culling of lights behind the normal", skipCount, &full);
  scene.Mapper->GetReliefProperty()->ShadowCullingOn();
  for (double threshold : { 0.01, 0.05 })
  {
    scene.Mapper->GetReliefProperty()->SetLightSetThreshold(threshold);
    std::ostringstream label;
    label << "skip lights < " << threshold * 100 << "% of the strongest";
    measure(label.str(), skipCount, &full);
  }
  scene.Mapper->GetReliefProperty()->SetLightSetThreshold(0.0);
  for (int k : { 8, 32 })
  {
    scene.Mapper->GetReliefProperty()->SetShadowedLights(k);
    measure("shadows for the " + std::to_string(k) + " strongest lights only", skipCount, &full);
  }
  scene.Mapper->GetReliefProperty()->SetShadowedLights(0);
  scene.Mapper->GetReliefProperty()->SelfShadowingOff();
  measure("no self-shadowing (negative reference)", skipCount, &full);
  scene.Mapper->GetReliefProperty()->SelfShadowingOn();

  // Relief vs relaxed cone stepping under many self-shadowing lights (the relief thesis'
  // multi-light table: relaxed cone 1.8-1.9x relief's frame rate at 32-1024 lights, 10 linear or
  // cone steps + 8 binary). Every light marches its shadow, with the method's search; each
  // setting's time, its relief-texture samples per pixel, its error against the exact render of the
  // same lights (the method's own error: hits and visibility), and against the Monte Carlo
  // reference of the whole environment (which adds the light set's sampling error, the same for
  // both methods).
  struct MethodRow
  {
    int Method;
    int Steps;
    double Ms, ErrorLights, ErrorMc, Samples;
  };
  double lightsReferenceSeconds = 0.0;
  std::vector<MethodRow> methodRows;
  vtkSmartPointer<vtkImageData> coneRelief;
  vtkSmartPointer<vtkTexture> unusedAlbedo;
  if (compareCount > 0 &&
    !BuildReliefTextures(o, coneRelief, unusedAlbedo, error, vtkReliefProperty::RelaxedConeMap))
  {
    std::cerr << "mesolight bench ibl: relaxed cone map: " << error << "\n";
    return 1;
  }
  if (compareCount > 0)
  {
    vtkSmartPointer<vtkImageData> lights = setLights(compareCount);
    const auto start = std::chrono::steady_clock::now();
    // One per texture: each method is shaded with its own texture's normals (the cone packing
    // reconstructs z from the filtered x, y), which is the asset, not the method's error.
    const std::vector<EnvironmentIrradianceSample> lightsReference[2] = {
      ComputeLightSetReference(hits, scene.ReliefTexture, lights, o.DepthScale, 3000),
      ComputeLightSetReference(hits, coneRelief, lights, o.DepthScale, 3000)
    };
    lightsReferenceSeconds = SecondsSince(start);
    if (lightsReference[0].empty() || lightsReference[1].empty())
    {
      std::cerr << "mesolight bench ibl: no pixel for the light-set reference (empty light set or "
                   "relief texture, or nothing covered)\n";
      return 1;
    }
    for (int method : { int(vtkReliefProperty::Relief), int(vtkReliefProperty::RelaxedConeBinary) })
    {
      scene.Mapper->SetReliefTextureData(
        method == vtkReliefProperty::Relief ? scene.ReliefTexture.Get() : coneRelief.Get());
      scene.Mapper->GetReliefProperty()->SetMethod(method);
      for (int steps : { 4, 6, 8, 10, 12, 16, 24, 32, 48, 64 })
      {
        scene.Mapper->GetReliefProperty()->SetLinearSteps(steps);
        scene.Mapper->GetReliefProperty()->SetRefinementSteps(8);
        MethodRow row{ method, steps, MedianFrameMs(window, frames), 0.0, 0.0, 0.0 };
        const Frame frame = CaptureFrame(window);
        row.ErrorLights = EnvironmentError(
          frame, lightsReference[method == vtkReliefProperty::Relief ? 0 : 1], exposure);
        row.ErrorMc = EnvironmentError(frame, reference, exposure);
        scene.Mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::SampleCountOutput);
        row.Samples = MeanSampleCount(CaptureFrame(window));
        scene.Mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::ShadedOutput);
        methodRows.push_back(row);
      }
    }
    scene.Mapper->SetReliefTextureData(scene.ReliefTexture);
    scene.Mapper->GetReliefProperty()->SetMethod(vtkReliefProperty::Relief);
    scene.Mapper->GetReliefProperty()->SetLinearSteps(o.LinearSteps);
    scene.Mapper->GetReliefProperty()->SetRefinementSteps(o.RefinementSteps);
  }

  std::cout << "Relief lit by median-cut lights of " << o.Environment << " (relief 16+8, "
            << o.Width << "x" << o.Height << ", " << frames << " timed frames, median)\n"
            << "Error: mean relative error of the rendered radiance against a Monte Carlo "
               "reference\n(exact first hits and exact height-field visibility, "
            << samples << " samples per pixel, " << reference.size() << " pixels, " << std::fixed
            << std::setprecision(1) << referenceSeconds << " s).\n\n";
  std::cout << std::left << std::setw(46) << "configuration" << std::right << std::setw(7)
            << "lights" << std::setw(11) << "ms/frame" << std::setw(11) << "error %"
            << std::setw(13) << "vs full lvl"
            << "\n";
  for (const Row& r : rows)
  {
    std::cout << std::left << std::setw(46) << r.Config << std::right << std::setw(7) << r.Lights
              << std::fixed << std::setprecision(1) << std::setw(11) << r.Ms << std::setprecision(2)
              << std::setw(11) << r.ErrorMc << std::setw(13);
    if (r.DiffFull >= 0.0)
    {
      std::cout << r.DiffFull;
    }
    else
    {
      std::cout << "-";
    }
    std::cout << "\n";
  }
  for (const char* series :
    { "every light marches its shadow", "shadows for the 32 strongest facing lights" })
  {
    const Row* first = nullptr;
    const Row* last = nullptr;
    for (const Row& r : rows)
    {
      if (r.Config == series)
      {
        first = first ? first : &r;
        last = &r;
      }
    }
    if (first && last && first != last)
    {
      std::cout << "\n"
                << series << ": " << last->Lights << " lights take " << std::setprecision(1)
                << last->Ms / first->Ms << "x the time of " << first->Lights
                << " (the relief thesis: 29x from 32 to 1024).";
    }
  }
  std::cout << "\n";

  if (!methodRows.empty())
  {
    std::cout << "\nRelief vs relaxed cone stepping, " << compareCount
              << " lights, every light marches its shadow with the method's search (steps + 8 "
                 "binary).\nError: against the exact render of the same lights (exact hits and "
                 "visibility, "
              << std::setprecision(1) << lightsReferenceSeconds
              << " s), and against the Monte Carlo reference above.\n"
              << std::left << std::setw(16) << "method" << std::right << std::setw(7) << "steps"
              << std::setw(11) << "ms/frame" << std::setw(11) << "samples" << std::setw(11)
              << "error %" << std::setw(11) << "vs MC %"
              << "\n";
    for (const MethodRow& r : methodRows)
    {
      std::cout << std::left << std::setw(16)
                << (r.Method == vtkReliefProperty::Relief ? "relief" : "relaxed-cone") << std::right
                << std::setw(7) << r.Steps << std::fixed << std::setprecision(1) << std::setw(11)
                << r.Ms << std::setw(11) << r.Samples << std::setprecision(2) << std::setw(11)
                << r.ErrorLights << std::setw(11) << r.ErrorMc << "\n";
    }
    // Equal error (the method's own, against the same lights): each relief setting's error E
    // (plus 0.05 points: 8-bit quantization) is a target; each method's cheapest setting reaching
    // it, in ms and in samples.
    std::vector<double> msRatios, sampleRatios;
    for (const MethodRow& target : methodRows)
    {
      if (target.Method != vtkReliefProperty::Relief)
      {
        continue;
      }
      const MethodRow* fastest[2] = { nullptr, nullptr };
      const MethodRow* leanest[2] = { nullptr, nullptr };
      for (const MethodRow& r : methodRows)
      {
        const int k = r.Method == vtkReliefProperty::Relief ? 0 : 1;
        if (r.ErrorLights > target.ErrorLights + 0.05)
        {
          continue;
        }
        fastest[k] = !fastest[k] || r.Ms < fastest[k]->Ms ? &r : fastest[k];
        leanest[k] = !leanest[k] || r.Samples < leanest[k]->Samples ? &r : leanest[k];
      }
      if (fastest[0] && fastest[1] && fastest[1]->Ms > 0.0 && leanest[1]->Samples > 0.0)
      {
        msRatios.push_back(fastest[0]->Ms / fastest[1]->Ms);
        sampleRatios.push_back(leanest[0]->Samples / leanest[1]->Samples);
      }
    }
    if (!msRatios.empty())
    {
      std::sort(msRatios.begin(), msRatios.end());
      std::sort(sampleRatios.begin(), sampleRatios.end());
      std::cout << "At equal error (each relief setting's error a target, " << msRatios.size()
                << " targets): relief / relaxed cone = " << std::setprecision(2)
                << msRatios[msRatios.size() / 2] << "x in ms/frame (range " << msRatios.front()
                << " - " << msRatios.back() << "), " << sampleRatios[sampleRatios.size() / 2]
                << "x in samples per pixel (range " << sampleRatios.front() << " - "
                << sampleRatios.back()
                << ").\nThe relief thesis, 10 steps each at 32-1024 lights: 1.8-1.9x in frame "
                   "rate.\n";
    }
  }
  const std::string csvFile = cl.Get("--csv");
  if (!csvFile.empty())
  {
    std::ofstream csv(csvFile);
    csv << "configuration,lights,ms_per_frame,error_pct_vs_monte_carlo,mean_diff_vs_full\n";
    for (const Row& r : rows)
    {
      csv << '"' << r.Config << "\"," << r.Lights << ',' << r.Ms << ',' << r.ErrorMc << ','
          << (r.DiffFull >= 0.0 ? std::to_string(r.DiffFull) : std::string()) << "\n";
    }
    std::cout << "wrote " << csvFile << "\n";
  }
  return 0;
}

} // namespace mesolight
