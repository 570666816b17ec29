// SPDX-License-Identifier: BSD-3-Clause
#include "CurvedReliefBenchmark.h"

#include "CommandLine.h"
#include "GeometryImageScene.h"
#include "ImageCompare.h"
#include "OutputFile.h"
#include "Timing.h"

#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

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
// The outline's rows only (CompareCoverage's margin): the other sides are the texture's edges.
constexpr int OutlineMargin = 10;

struct Row
{
  std::string Surface;
  CoverageDifference Curved, Flat;               // the top of the outline
  CoverageDifference CurvedWhole, FlatWhole;     // the whole frame
  bool SameImage = false;                        // curved and flat march drew the same pixels
  double CurvedMs = 0.0, FlatMs = 0.0;           // median frame times, interleaved
  double CurvedSamples = 0.0, FlatSamples = 0.0; // mean relief-texture samples per pixel
};

// Mean relief-texture samples per covered pixel (SampleCountOutput): the march's cost without
// the noise of a shared machine's clock.
double MeanSamples(ReliefScene& scene, vtkRenderWindow* window)
{
  vtkReliefProperty* property = scene.Mapper->GetReliefProperty();
  const int output = property->GetOutput();
  property->SetOutput(vtkReliefProperty::SampleCountOutput);
  const double samples = MeanSampleCount(CaptureFrame(window));
  property->SetOutput(output);
  return samples;
}

double Median(std::vector<double> v)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  const size_t n = v.size();
  return n % 2 ? v[n / 2] : 0.5 * (v[n / 2 - 1] + v[n / 2]);
}

double FrameMs(vtkRenderWindow* window)
{
  const auto start = std::chrono::steady_clock::now();
  window->Render();
  window->WaitForCompletion();
  return 1000.0 * SecondsSince(start);
}

bool Measure(
  const std::string& surface, int width, int height, int frames, Row& row, std::string& error)
{
  GeometryImageSceneOptions o = CurvedOutlineScene(surface);
  o.Relief.Width = width;
  o.Relief.Height = height;
  ReliefScene dense, curved, flat;
  if (!BuildGeometryImageDenseScene(o, dense, error) ||
    !BuildGeometryImageReliefScene(o, curved, error))
  {
    return false;
  }
  o.Relief.SurfaceCurvature = false;
  if (!BuildGeometryImageReliefScene(o, flat, error))
  {
    return false;
  }
  auto denseWindow = MakeOffscreenWindow(o.Relief, dense.Renderer);
  auto curvedWindow = MakeOffscreenWindow(o.Relief, curved.Renderer);
  auto flatWindow = MakeOffscreenWindow(o.Relief, flat.Renderer);
  const Frame reference = CaptureFrame(denseWindow);
  const Frame withCurvature = CaptureFrame(curvedWindow);
  const Frame withoutCurvature = CaptureFrame(flatWindow);
  row.Surface = surface;
  row.Curved = CompareCoverage(withCurvature, reference, OutlineMargin);
  row.Flat = CompareCoverage(withoutCurvature, reference, OutlineMargin);
  row.CurvedWhole = CompareCoverage(withCurvature, reference);
  row.FlatWhole = CompareCoverage(withoutCurvature, reference);
  row.SameImage =
    withCurvature.Rgb == withoutCurvature.Rgb && withCurvature.Depth == withoutCurvature.Depth;
  row.CurvedSamples = MeanSamples(curved, curvedWindow);
  row.FlatSamples = MeanSamples(flat, flatWindow);
  // Interleaved, so both see the same load on a shared machine; the ratio is what to read.
  std::vector<double> curvedMs, flatMs;
  for (int f = 0; f < frames; ++f)
  {
    curvedMs.push_back(FrameMs(curvedWindow));
    flatMs.push_back(FrameMs(flatWindow));
  }
  row.CurvedMs = Median(curvedMs);
  row.FlatMs = Median(flatMs);
  return true;
}
} // namespace

//------------------------------------------------------------------------------
int RunCurvedReliefBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench curved-relief",
    "mesolight bench curved-relief [options]\n\nRelief mapping on curved meshes (per-vertex "
    "quadrics, Oliveira & Policarpo 2005)\nagainst the flat-plane march on the same coarse mesh "
    "(stride 8 of a 256^2 geometry\nimage, HemisphereTorus at depth scale 0.06, seen from 55 deg "
    "about the cylinder's axis):\nthe outline's coverage mismatch against the dense displaced "
    "mesh (% of the pixels\neither covers, top of the outline and whole frame), the median "
    "frame time of\nboth (frames interleaved in the same run) and their mean relief-texture "
    "samples per\npixel (SampleCountOutput).\n");
  cl.AddValue("--surfaces", "A,B,..", "procedural surfaces (cylinder, sphere, plane, ...)",
    "cylinder,sphere,plane");
  cl.AddValue("--size", "WxH", "rendered image size", "300x300");
  cl.AddValue("--frames", "N", "timed frames per march", "30");
  cl.AddValue("--csv", "FILE", "write one CSV row per surface");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv" }, {}); !problem.empty())
  {
    return cl.UsageError(problem);
  }
  std::string error;
  int width = 300, height = 300, frames = 30;
  if (!cl.GetSize("--size", 16, 4096, width, height, error) ||
    !cl.GetInt("--frames", 1, 100000, frames, error))
  {
    return cl.UsageError(error);
  }
  std::ostream& out = std::cout;
  out << "Coverage mismatch against the dense displaced mesh (pixels covered by exactly one "
         "frame, % of\nthose either covers): 'outline' = the top of the frame, where the surface "
         "turns away;\n'whole' = every pixel. Frame times: median of "
      << frames << " interleaved frames, " << width << "x" << height << ".\n\n";
  out << std::left << std::setw(10) << "surface" << std::right << std::setw(12) << "curved px"
      << std::setw(9) << "curved%" << std::setw(10) << "flat px" << std::setw(8) << "flat%"
      << std::setw(11) << "whole c%" << std::setw(11) << "whole f%" << std::setw(11) << "curved ms"
      << std::setw(9) << "flat ms" << std::setw(8) << "ratio" << std::setw(11) << "samples c"
      << std::setw(11) << "samples f" << std::setw(10) << "same img"
      << "\n";
  std::vector<Row> rows;
  for (const std::string& surface : cl.GetStringList("--surfaces"))
  {
    Row row;
    if (!Measure(surface, width, height, frames, row, error))
    {
      std::cerr << "mesolight bench curved-relief: " << error << "\n";
      return 1;
    }
    out << std::left << std::setw(10) << row.Surface << std::right << std::fixed
        << std::setprecision(2) << std::setw(12) << row.Curved.Mismatched << std::setw(9)
        << row.Curved.Percent() << std::setw(10) << row.Flat.Mismatched << std::setw(8)
        << row.Flat.Percent() << std::setw(11) << row.CurvedWhole.Percent() << std::setw(11)
        << row.FlatWhole.Percent() << std::setw(11) << row.CurvedMs << std::setw(9) << row.FlatMs
        << std::setprecision(3) << std::setw(8) << row.CurvedMs / std::max(row.FlatMs, 1e-9)
        << std::setprecision(2) << std::setw(11) << row.CurvedSamples << std::setw(11)
        << row.FlatSamples << std::setw(10) << (row.SameImage ? "yes" : "no") << "\n";
    out.unsetf(std::ios::fixed);
    rows.push_back(row);
  }
  if (cl.Has("--csv"))
  {
    std::ofstream csv(cl.Get("--csv"));
    csv << "surface,outline_curved_px,outline_curved_pct,outline_flat_px,outline_flat_pct,"
           "whole_curved_pct,whole_flat_pct,curved_ms,flat_ms,cost_ratio,curved_samples,"
           "flat_samples,same_image\n";
    for (const Row& r : rows)
    {
      csv << r.Surface << ',' << r.Curved.Mismatched << ',' << r.Curved.Percent() << ','
          << r.Flat.Mismatched << ',' << r.Flat.Percent() << ',' << r.CurvedWhole.Percent() << ','
          << r.FlatWhole.Percent() << ',' << r.CurvedMs << ',' << r.FlatMs << ','
          << r.CurvedMs / std::max(r.FlatMs, 1e-9) << ',' << r.CurvedSamples << ',' << r.FlatSamples
          << ',' << (r.SameImage ? 1 : 0) << "\n";
    }
    if (!csv)
    {
      std::cerr << "mesolight bench curved-relief: could not write " << cl.Get("--csv") << "\n";
      return 1;
    }
    out << "\nwrote " << cl.Get("--csv") << "\n";
  }
  return 0;
}

} // namespace mesolight
