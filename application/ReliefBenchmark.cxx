// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefBenchmark.h"

#include "ImageCompare.h"
#include "vtkReliefMapper.h"

#include <vtkActor.h>
#include <vtkMapper.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <algorithm>
#include <chrono>
#include <cstdio>
#include <fstream>
#include <iomanip>

namespace mesolight
{
namespace
{
struct Row
{
  std::string Config;
  int Resolution = 0;
  double FirstFrameMs = 0.0;
  double MedianMs = 0.0;
  bool HasError = false;
  FrameDifference Error;
  double MegaBytes = 0.0;
};

// Median frame time; the first frame (shader compilation, uploads) is reported apart.
void TimeFrames(vtkRenderWindow* window, int frames, Row& row)
{
  using Clock = std::chrono::steady_clock;
  auto ms = [](Clock::duration d) { return std::chrono::duration<double, std::milli>(d).count(); };
  auto t0 = Clock::now();
  window->Render();
  window->WaitForCompletion();
  row.FirstFrameMs = ms(Clock::now() - t0);
  std::vector<double> times;
  for (int i = 0; i < frames; ++i)
  {
    auto t = Clock::now();
    window->Render();
    window->WaitForCompletion();
    times.push_back(ms(Clock::now() - t));
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  row.MedianMs = times[times.size() / 2];
}

double DenseMeshMegaBytes(vtkActor* actor)
{
  // What the stock mapper uploads: position, normal (3 floats), tcoord (2 floats) per vertex
  // and three 32-bit indices per triangle.
  auto* poly = vtkPolyData::SafeDownCast(actor->GetMapper()->GetInputAsDataSet());
  if (!poly)
  {
    return 0.0;
  }
  return (poly->GetNumberOfPoints() * 32.0 + poly->GetNumberOfPolys() * 12.0) / 1048576.0;
}

} // namespace

bool RunReliefBenchmark(const BenchmarkSettings& settings, std::ostream& out)
{
  std::vector<Row> rows;
  const double depthTolerance = 0.05; // fraction of the relief depth
  for (int resolution : settings.Resolutions)
  {
    ReliefSceneOptions base = settings.Scene;
    base.Resolution = resolution;
    base.SelfShadowing = false; // the dense reference has no self-shadows; compare like with like
    std::string error;

    ReliefScene dense;
    if (!BuildDenseReferenceScene(base, dense, error))
    {
      out << "bench: " << error << "\n";
      return false;
    }
    ReliefScene coarse;
    if (!BuildTexturedPlaneScene(base, coarse, error))
    {
      out << "bench: " << error << "\n";
      return false;
    }
    auto coarseWindow = MakeOffscreenWindow(base, coarse.Renderer);
    const Frame footprint = CaptureFrame(coarseWindow);
    coarseWindow = nullptr;
    auto denseWindow = MakeOffscreenWindow(base, dense.Renderer);
    Row denseRow;
    denseRow.Config = "dense mesh (stock mapper)";
    denseRow.Resolution = resolution;
    TimeFrames(denseWindow, settings.Frames, denseRow);
    const Frame reference = CaptureFrame(denseWindow);
    denseRow.MegaBytes = DenseMeshMegaBytes(dense.Actor);
    denseRow.HasError = false; // it is the reference
    rows.push_back(denseRow);
    denseWindow = nullptr;

    struct Variant
    {
      std::string Label;
      std::string Method; // empty: plain textured plane
      int Linear;
      int Refine;
      bool Shadows;
      bool NoLevelOfDetail = false; // the other rows as the scene options say (default on)
    };
    const std::vector<Variant> variants = {
      { "textured plane (stock mapper)", "", 0, 0, false },
      { "relief 10+8", "relief", 10, 8, false },
      { "relief 10+8 + shadows", "relief", 10, 8, true },
      // What level of detail (the normal's moments from mip level 2 up) adds.
      { "relief 10+8, no level of detail", "relief", 10, 8, false, true },
      { "POM 10", "pom", 10, 0, false },
      { "POM 32", "pom", 32, 0, false },
      { "steep parallax 32", "steep", 32, 0, false },
    };
    for (const Variant& v : variants)
    {
      ReliefSceneOptions o = base;
      o.Method = v.Method.empty() ? "relief" : v.Method;
      o.LinearSteps = v.Linear > 0 ? v.Linear : o.LinearSteps;
      o.RefinementSteps = v.Refine;
      o.SelfShadowing = v.Shadows;
      o.LevelOfDetail = o.LevelOfDetail && !v.NoLevelOfDetail;
      ReliefScene scene;
      const bool built = v.Method.empty() ? BuildTexturedPlaneScene(o, scene, error)
                                          : BuildReliefScene(o, scene, error);
      if (!built)
      {
        out << "bench: " << error << "\n";
        return false;
      }
      auto window = MakeOffscreenWindow(o, scene.Renderer);
      Row row;
      row.Config = v.Label;
      row.Resolution = resolution;
      TimeFrames(window, settings.Frames, row); // first: the first frame compiles shaders
      if (!v.Method.empty() && scene.Mapper->GetShaderFailed())
      {
        out << "bench: the shader of " << v.Label
            << " did not compile (the GLSL compiler's message is above); stopping\n";
        return false;
      }
      const Frame frame = CaptureFrame(window);
      if (!v.Shadows)
      {
        row.HasError = true;
        row.Error = CompareFrames(frame, reference, depthTolerance * o.DepthScale, &footprint);
      }
      // What the mapper uploaded for this method, as OpenGL reports its textures' formats.
      row.MegaBytes =
        v.Method.empty() ? 0.0 : double(scene.Mapper->GetReliefTextureBytes()) / 1048576.0;
      rows.push_back(row);
    }
  }

  const ReliefSceneOptions& s = settings.Scene;
  out << "Relief benchmark: pattern " << s.Pattern << ", depth scale " << s.DepthScale << ", "
      << s.Width << "x" << s.Height << " pixels, view " << s.ViewAngle << " deg, "
      << settings.Frames << " timed frames (median)\n"
      << "Errors against the dense displaced mesh of the same map (self-shadowing off):\n"
      << "colour in 8-bit levels, silhouette = % of the mesh footprint covered by only one,\n"
      << "depth = % of common pixels whose depth differs by more than 5% of the relief depth.\n\n";
  out << std::left << std::setw(32) << "configuration" << std::right << std::setw(6) << "map"
      << std::setw(10) << "ms/frame" << std::setw(10) << "first ms" << std::setw(10) << "mean err"
      << std::setw(8) << "PSNR" << std::setw(10) << "silh. %" << std::setw(10) << "depth %"
      << std::setw(10) << "GPU MB"
      << "\n";
  for (const Row& r : rows)
  {
    out << std::left << std::setw(32) << r.Config << std::right << std::setw(6) << r.Resolution
        << std::fixed << std::setprecision(1) << std::setw(10) << r.MedianMs << std::setw(10)
        << r.FirstFrameMs;
    if (r.HasError)
    {
      out << std::setprecision(2) << std::setw(10) << r.Error.MeanColorError << std::setprecision(1)
          << std::setw(8) << r.Error.Psnr << std::setprecision(2) << std::setw(10)
          << r.Error.SilhouetteMismatch << std::setw(10) << r.Error.DepthMismatch;
    }
    else
    {
      out << std::setw(10) << "-" << std::setw(8) << "-" << std::setw(10) << "-" << std::setw(10)
          << "-";
    }
    out << std::setprecision(1) << std::setw(10) << r.MegaBytes << "\n";
    out.unsetf(std::ios::fixed);
  }
  // GPU memory: the dense mesh against each relief method of the same map.
  for (const Row& dense : rows)
  {
    if (dense.Config.rfind("dense mesh", 0) != 0)
    {
      continue;
    }
    out << "GPU memory at " << dense.Resolution << "^2, dense mesh MB / relief MB:";
    for (const Row& r : rows)
    {
      if (r.Resolution == dense.Resolution && r.MegaBytes > 0.0 && &r != &dense)
      {
        out << " " << r.Config << " " << std::fixed << std::setprecision(1)
            << dense.MegaBytes / r.MegaBytes << "x;";
        out.unsetf(std::ios::fixed);
      }
    }
    out << "\n";
  }
  if (!settings.CsvFile.empty())
  {
    std::ofstream csv(settings.CsvFile);
    csv << "configuration,map,ms_per_frame,first_frame_ms,mean_color_error,rms_color_error,psnr_db,"
           "silhouette_mismatch_pct,depth_mismatch_pct,gpu_megabytes\n";
    for (const Row& r : rows)
    {
      csv << '"' << r.Config << "\"," << r.Resolution << ',' << r.MedianMs << ',' << r.FirstFrameMs
          << ',';
      if (r.HasError)
      {
        csv << r.Error.MeanColorError << ',' << r.Error.RmsColorError << ',' << r.Error.Psnr << ','
            << r.Error.SilhouetteMismatch << ',' << r.Error.DepthMismatch;
      }
      else
      {
        csv << ",,,,";
      }
      csv << ',' << r.MegaBytes << "\n";
    }
    if (!csv)
    {
      out << "bench: could not write " << settings.CsvFile << "\n";
      return false;
    }
    out << "\nwrote " << settings.CsvFile << "\n";
  }
  return true;
}

} // namespace mesolight
