// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefAliasingBenchmark.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "ImageCompare.h"
#include "OutputFile.h"
#include "ReliefScene.h"
#include "Timing.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>

#include <algorithm>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <sstream>

namespace mesolight
{
namespace
{
// What a frame is drawn with.
enum class Variant
{
  Reference, // maximum-mipmap tracing, 128 iterations, level of detail off: exact
  Before,    // an untouched property's method and steps, level of detail off
  Mean,      // the same with level of detail on, filtering the mean normal (Toksvig 2005)
  Default,   // the same with level of detail on and the property's default normal filter
  Surface    // texture mapping: the hit is the mesh's own texture coordinate (the footprint)
};

struct Settings
{
  std::vector<std::string> Maps; // procedural pattern names, or image files
  bool Height = false;           // image files store height
  int Resolution = 1024;         // texels per side of the procedural maps
  std::vector<double> Angles;    // degrees from the wall normal
  std::vector<double> Distances; // wall widths
  int Width = 200;
  int Height_ = 150;
  int Supersampling = 8;
  double DepthScale = 0.04;
  bool Shadows = true;
  std::string Method; // instead of the default's method (both rows), with Linear + Refine steps
  int Linear = 0;
  int Refine = 0;
  int CompareFilter = vtkReliefProperty::MeanNormalFilter; // the "mean" row's normal filter
  int CompareFarViewRays = 0; // the "mean" row's vtkReliefProperty::FarViewRays, 0: the default's
  int Frames = 5;             // timed frames of each row's shaded frame (median ms), 0: none
  int Lights = 2;             // VTK lights (ReliefSceneOptions::Lights)
  std::string Environment;    // image-based lighting (ReliefSceneOptions::Environment)
  int EnvironmentLights = 128;
  vtkSmartPointer<vtkImageData> EnvironmentLightSet; // its median cut, made once for every case
  double Exposure = 1.0;
  std::string CsvFile;
  std::string PlotFile;
};

struct ClassFigures
{
  long long Pixels = 0;
  double ErrorBefore = 0.0; // mean |frame - box-filtered reference|, 8-bit levels over RGB
  double ErrorDefault = 0.0;
  double ErrorMean = 0.0;     // the third row: level of detail with --compare-filter's filter
  double SamplesBefore = 0.0; // relief-texture samples per pixel
  double SamplesDefault = 0.0;
  double SamplesMean = 0.0;
};

// Median ms per frame of the rows' shaded frames (0 when not timed).
struct FrameTimes
{
  double Before = 0.0, Default = 0.0, Mean = 0.0;
};

struct CaseRow
{
  std::string Map;
  double Angle = 0.0;
  double Distance = 0.0;
  double MedianFootprint = 0.0;  // texels per pixel, longer axis
  ClassFigures All, Near, Far;   // near: footprint <= 1 texel; far: > 1
  double NearHitChangeMax = 0.0; // texels, before vs default, over near pixels
  double NearHitChangeMean = 0.0;
  // Far pixels' mean of frame - reference (8-bit levels): bias, where the error is noise or not.
  double FarSignedBefore = 0.0, FarSignedDefault = 0.0, FarSignedMean = 0.0;
  FrameTimes Ms;
};

bool IsFile(const std::string& map)
{
  return map.find('/') != std::string::npos || map.find('.') != std::string::npos;
}

std::string MapLabel(const std::string& map)
{
  const size_t slash = map.find_last_of('/');
  std::string name = slash == std::string::npos ? map : map.substr(slash + 1);
  const size_t dot = name.find_last_of('.');
  return dot == std::string::npos ? name : name.substr(0, dot);
}

// Draws one frame of the variant; with ms, also the median time of settings.Frames more frames of
// the same window (the first, captured, compiled the shaders).
bool RenderVariant(const Settings& settings, ReliefSceneOptions options, Variant variant,
  int output, int scale, Frame& frame, int& texels, std::string& error, double* ms = nullptr)
{
  vtkNew<vtkReliefProperty> defaults; // an untouched property: the default
  switch (variant)
  {
    case Variant::Reference:
      options.Method = "max-mipmap";
      options.LinearSteps = 128;
      options.RefinementSteps = 0;
      options.AdaptiveSteps = false;
      options.LevelOfDetail = false;
      break;
    case Variant::Before:
    case Variant::Mean:
    case Variant::Default:
      options.Method = vtkReliefProperty::GetMethodName(defaults->GetMethod());
      options.LinearSteps = defaults->GetLinearSteps();
      options.RefinementSteps = defaults->GetRefinementSteps();
      options.AdaptiveSteps = defaults->GetAdaptiveSteps();
      options.LevelOfDetail = variant != Variant::Before;
      if (!settings.Method.empty())
      {
        options.Method = settings.Method;
        options.LinearSteps = settings.Linear;
        options.RefinementSteps = settings.Refine;
      }
      break;
    case Variant::Surface:
      options.Method = "texture";
      options.LevelOfDetail = false;
      break;
  }
  options.Width *= scale;
  options.Height *= scale;
  ReliefScene scene;
  if (!BuildReliefScene(options, scene, error))
  {
    return false;
  }
  vtkReliefProperty* p = scene.Mapper->GetReliefProperty();
  if (variant == Variant::Before || variant == Variant::Mean || variant == Variant::Default)
  {
    p->SetMinimumSteps(defaults->GetMinimumSteps());
    p->SetNormalFilter(
      variant == Variant::Mean ? settings.CompareFilter : defaults->GetNormalFilter());
    if (variant == Variant::Mean && settings.CompareFarViewRays > 0)
    {
      p->SetFarViewRays(settings.CompareFarViewRays);
    }
  }
  p->SetOutput(output);
  int dims[3];
  scene.ReliefTexture->GetDimensions(dims);
  texels = std::max(dims[0], dims[1]);
  auto window = MakeOffscreenWindow(options, scene.Renderer);
  frame = CaptureFrame(window);
  if (frame.Width != options.Width || frame.Height != options.Height ||
    frame.Rgb.size() != size_t(3) * options.Width * options.Height)
  {
    error = "the frame was not rendered (a shader failed?)";
    return false;
  }
  if (ms)
  {
    *ms = MedianMilliseconds(settings.Frames,
      [&]
      {
        window->Render();
        window->WaitForCompletion();
      });
  }
  return true;
}

// Longer axis of each pixel's footprint in texels, from the mesh's texture coordinates at the
// pixel and its neighbours; negative where unknown (background or a neighbourless pixel).
std::vector<double> Footprints(const Frame& u, const Frame& v, int texels)
{
  const int w = u.Width;
  const int h = u.Height;
  std::vector<double> result(size_t(w) * h, -1.0);
  auto uv = [&](int x, int y, double& a, double& b)
  {
    if (x < 0 || y < 0 || x >= w || y >= h)
    {
      return false;
    }
    const size_t p = size_t(y) * w + x;
    return DecodeHitCoordinate(u, p, a) && DecodeHitCoordinate(v, p, b);
  };
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      double u0, v0, u1, v1;
      if (!uv(x, y, u0, v0))
      {
        continue;
      }
      double axis[2] = { -1.0, -1.0 };
      for (int k = 0; k < 2; ++k)
      {
        const int dx = k == 0 ? 1 : 0;
        const int dy = k == 0 ? 0 : 1;
        if (uv(x + dx, y + dy, u1, v1) || uv(x - dx, y - dy, u1, v1))
        {
          axis[k] = std::hypot(u1 - u0, v1 - v0) * texels;
        }
      }
      if (axis[0] >= 0.0 && axis[1] >= 0.0)
      {
        result[size_t(y) * w + x] = std::max(axis[0], axis[1]);
      }
    }
  }
  return result;
}

// Box-filtered reference colour of a pixel, false unless all its subsamples are covered.
bool BoxFiltered(const Frame& reference, int s, int x, int y, int width, double mean[3])
{
  mean[0] = mean[1] = mean[2] = 0.0;
  for (int j = 0; j < s; ++j)
  {
    for (int i = 0; i < s; ++i)
    {
      const size_t q = size_t(y * s + j) * (width * s) + (x * s + i);
      if (!reference.Covered(q))
      {
        return false;
      }
      for (int c = 0; c < 3; ++c)
      {
        mean[c] += reference.Rgb[3 * q + c];
      }
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    mean[c] /= s * s;
  }
  return true;
}

double Median(std::vector<double> values)
{
  if (values.empty())
  {
    return 0.0;
  }
  std::nth_element(values.begin(), values.begin() + values.size() / 2, values.end());
  return values[values.size() / 2];
}

bool MeasureCase(const Settings& settings, const std::string& map, double angle, double distance,
  CaseRow& row, std::string& error)
{
  ReliefSceneOptions options;
  if (IsFile(map))
  {
    options.DepthFile = map;
    options.DepthFileIsHeight = settings.Height;
  }
  else
  {
    options.Pattern = map;
    options.Resolution = settings.Resolution;
  }
  options.DepthScale = settings.DepthScale;
  options.SelfShadowing = settings.Shadows;
  options.Lights = settings.Lights;
  options.Environment = settings.Environment;
  options.EnvironmentLights = settings.EnvironmentLights;
  options.EnvironmentLightSet = settings.EnvironmentLightSet;
  options.Exposure = settings.Exposure;
  options.ToneMapping = true; // as `mesolight render` and the property have it
  options.ViewAngle = angle;
  options.ViewDistance = distance;
  options.Width = settings.Width;
  options.Height = settings.Height_;
  const int s = settings.Supersampling;
  int texels = 0;
  Frame reference, before, current, mean, surfaceU, surfaceV, samplesBefore, samplesDefault,
    samplesMean;
  Frame hitsBefore[2], hitsDefault[2];
  const int shaded = vtkReliefProperty::ShadedOutput;
  const int samples = vtkReliefProperty::SampleCountOutput;
  const bool timed = settings.Frames > 0;
  if (!RenderVariant(settings, options, Variant::Reference, shaded, s, reference, texels, error) ||
    !RenderVariant(settings, options, Variant::Before, shaded, 1, before, texels, error,
      timed ? &row.Ms.Before : nullptr) ||
    !RenderVariant(settings, options, Variant::Default, shaded, 1, current, texels, error,
      timed ? &row.Ms.Default : nullptr) ||
    !RenderVariant(settings, options, Variant::Mean, shaded, 1, mean, texels, error,
      timed ? &row.Ms.Mean : nullptr) ||
    !RenderVariant(settings, options, Variant::Mean, samples, 1, samplesMean, texels, error) ||
    !RenderVariant(settings, options, Variant::Before, samples, 1, samplesBefore, texels, error) ||
    !RenderVariant(
      settings, options, Variant::Default, samples, 1, samplesDefault, texels, error) ||
    !RenderVariant(settings, options, Variant::Surface, vtkReliefProperty::HitUOutput, 1, surfaceU,
      texels, error) ||
    !RenderVariant(settings, options, Variant::Surface, vtkReliefProperty::HitVOutput, 1, surfaceV,
      texels, error))
  {
    return false;
  }
  for (int k = 0; k < 2; ++k)
  {
    const int output = k == 0 ? vtkReliefProperty::HitUOutput : vtkReliefProperty::HitVOutput;
    if (!RenderVariant(
          settings, options, Variant::Before, output, 1, hitsBefore[k], texels, error) ||
      !RenderVariant(settings, options, Variant::Default, output, 1, hitsDefault[k], texels, error))
    {
      return false;
    }
  }
  const std::vector<double> footprint = Footprints(surfaceU, surfaceV, texels);
  row.Map = MapLabel(map);
  row.Angle = angle;
  row.Distance = distance;
  std::vector<double> covered;
  long long nearHits = 0;
  double signedBefore = 0.0, signedDefault = 0.0, signedMean = 0.0;
  for (int y = 0; y < settings.Height_; ++y)
  {
    for (int x = 0; x < settings.Width; ++x)
    {
      const size_t p = size_t(y) * settings.Width + x;
      double box[3];
      if (footprint[p] < 0.0 || !before.Covered(p) || !current.Covered(p) || !mean.Covered(p) ||
        !BoxFiltered(reference, s, x, y, settings.Width, box))
      {
        continue;
      }
      covered.push_back(footprint[p]);
      double eb = 0.0, ed = 0.0, em = 0.0;
      for (int c = 0; c < 3; ++c)
      {
        if (footprint[p] > 1.0)
        {
          signedBefore += (before.Rgb[3 * p + c] - box[c]) / 3.0;
          signedDefault += (current.Rgb[3 * p + c] - box[c]) / 3.0;
          signedMean += (mean.Rgb[3 * p + c] - box[c]) / 3.0;
        }
        eb += std::abs(box[c] - before.Rgb[3 * p + c]) / 3.0;
        ed += std::abs(box[c] - current.Rgb[3 * p + c]) / 3.0;
        em += std::abs(box[c] - mean.Rgb[3 * p + c]) / 3.0;
      }
      int nb = 0, nd = 0, nm = 0;
      DecodeSampleCount(samplesBefore, p, nb);
      DecodeSampleCount(samplesDefault, p, nd);
      DecodeSampleCount(samplesMean, p, nm);
      const bool isNear = footprint[p] <= 1.0;
      for (ClassFigures* f : { &row.All, isNear ? &row.Near : &row.Far })
      {
        ++f->Pixels;
        f->ErrorBefore += eb;
        f->ErrorDefault += ed;
        f->ErrorMean += em;
        f->SamplesBefore += nb;
        f->SamplesDefault += nd;
        f->SamplesMean += nm;
      }
      double ub, vb, ud, vd;
      if (isNear && DecodeHitCoordinate(hitsBefore[0], p, ub) &&
        DecodeHitCoordinate(hitsBefore[1], p, vb) && DecodeHitCoordinate(hitsDefault[0], p, ud) &&
        DecodeHitCoordinate(hitsDefault[1], p, vd))
      {
        const double change = std::hypot(ub - ud, vb - vd) * texels;
        row.NearHitChangeMax = std::max(row.NearHitChangeMax, change);
        row.NearHitChangeMean += change;
        ++nearHits;
      }
    }
  }
  for (ClassFigures* f : { &row.All, &row.Near, &row.Far })
  {
    const double n = std::max<long long>(f->Pixels, 1);
    f->ErrorBefore /= n;
    f->ErrorDefault /= n;
    f->ErrorMean /= n;
    f->SamplesBefore /= n;
    f->SamplesDefault /= n;
    f->SamplesMean /= n;
  }
  {
    const double n = std::max<long long>(row.Far.Pixels, 1);
    row.FarSignedBefore = signedBefore / n;
    row.FarSignedDefault = signedDefault / n;
    row.FarSignedMean = signedMean / n;
  }
  row.NearHitChangeMean /= std::max<long long>(nearHits, 1);
  row.MedianFootprint = Median(covered);
  return true;
}

std::string Ratio(double a, double b)
{
  std::ostringstream os;
  if (b > 0.0)
  {
    os << std::fixed << std::setprecision(2) << a / b;
  }
  else
  {
    os << "-";
  }
  return os.str();
}
} // namespace

int RunReliefAliasingBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench relief-aliasing",
    "Usage: mesolight bench relief-aliasing [options]\n"
    "The default relief (an untouched vtkReliefProperty: level of detail on, visible normals), "
    "the\n"
    "same with level of detail off, and a third row (by default the mean normal filter, Toksvig),\n"
    "against the exact relief (maximum-mipmap tracing, 128 iterations) rendered at S x S times\n"
    "the resolution and box-filtered: S^2 exact subsamples per pixel. Per map, view angle and\n"
    "distance: mean colour error over all, near (footprint <= 1 texel) and far pixels, the\n"
    "relief-texture samples per pixel, how far level of detail moves near hits, and each row's\n"
    "time per frame.\n");
  cl.AddValue("--maps", "LIST", "procedural patterns and depth image files", "Stone");
  cl.AddFlag("--height", "the image files store height (white = high) rather than depth");
  cl.AddValue("--resolution", "N", "texels per side of the procedural maps", "1024");
  cl.AddValue("--angles", "LIST", "view angles from the wall normal, degrees", "45,70,80");
  cl.AddValue(
    "--distances", "LIST", "camera distances to the wall's centre, wall widths", "0.5,1.3,3");
  cl.AddValue("--size", "WxH", "window size in pixels", "200x150");
  cl.AddValue("--supersampling", "S", "subsamples per pixel side of the reference", "8");
  cl.AddValue("--depth-scale", "K", "world depth of depth 1 / wall width", "0.04");
  cl.AddValue("--method", "NAME",
    "draw both rows with this vtkReliefMapper method instead of the default's (e.g. max-mipmap, "
    "to see the filtering alone)");
  cl.AddValue(
    "--steps", "L+R", "the --method's linear (or iteration) and refinement steps", "10+8");
  cl.AddFlag("--no-shadows", "self-shadowing off in every frame, the reference's too");
  cl.AddValue("--lights", "N", "VTK lights: 0 = none, 1 = key light, 2 = key + fill", "2");
  cl.AddValue("--environment", "SPEC",
    "light also by an environment (every frame, the reference's too): procedural:sky, "
    "procedural:sun or a lat-long HDR file");
  cl.AddValue("--env-lights", "N", "median-cut lights of the environment", "128");
  cl.AddValue("--exposure", "X", "scale of the environment lighting (Reinhard tone mapped)", "1");
  cl.AddValue("--compare-filter", "NAME",
    "the normal filter of the third row: mean (Toksvig), visible (the moments: facets turned "
    "away count negatively) or masked (facets turned away left out; the default's)",
    "mean");
  cl.AddValue("--compare-far-view-rays", "N",
    "the third row's most view rays per far pixel (vtkReliefProperty::FarViewRays; 1: one ray "
    "per pixel, the default before), default: the default's");
  cl.AddValue("--frames", "N",
    "timed frames of each row's shaded frame after the one measured (median ms; 0: not timed)",
    "5");
  cl.AddValue("--csv", "FILE", "write one CSV row per case");
  cl.AddValue("--plot", "FILE.png", "error against footprint: off, the third row and default");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  Settings settings;
  std::string error;
  settings.Maps = cl.GetStringList("--maps");
  settings.Height = cl.Has("--height");
  settings.Shadows = !cl.Has("--no-shadows");
  char plus = 0;
  std::istringstream steps(cl.Get("--steps"));
  if (!(steps >> settings.Linear >> plus >> settings.Refine) || plus != '+' ||
    settings.Linear < 1 || settings.Refine < 0 || !(steps >> std::ws).eof())
  {
    return cl.UsageError("--steps: '" + cl.Get("--steps") + "' is not L+R");
  }
  if (cl.Has("--method"))
  {
    settings.Method = cl.Get("--method");
    if (vtkReliefProperty::GetMethodFromName(settings.Method.c_str()) < 0)
    {
      return cl.UsageError("--method: unknown method '" + settings.Method + "'");
    }
  }
  const std::string compare = cl.Get("--compare-filter");
  settings.CompareFilter = vtkReliefProperty::GetNormalFilterFromName(compare.c_str());
  if (settings.CompareFilter < 0)
  {
    return cl.UsageError("--compare-filter: '" + compare + "' is not mean, visible or masked");
  }
  if (!cl.GetInt("--resolution", 2, 8192, settings.Resolution, error) ||
    !cl.GetDoubleList("--angles", 0.0, 89.0, settings.Angles, error) ||
    !cl.GetDoubleList("--distances", 0.05, 100.0, settings.Distances, error) ||
    !cl.GetSize("--size", 8, 4096, settings.Width, settings.Height_, error) ||
    !cl.GetInt("--supersampling", 1, 16, settings.Supersampling, error) ||
    !cl.GetDouble("--depth-scale", 1e-4, 10.0, settings.DepthScale, error) ||
    !cl.GetInt("--frames", 0, 1000, settings.Frames, error) ||
    !cl.GetInt("--lights", 0, 2, settings.Lights, error) ||
    !cl.GetInt("--env-lights", 1, 4096, settings.EnvironmentLights, error) ||
    !cl.GetDouble("--exposure", 0.0, 1e6, settings.Exposure, error) ||
    (cl.Has("--compare-far-view-rays") &&
      !cl.GetInt("--compare-far-view-rays", 1, 8, settings.CompareFarViewRays, error)))
  {
    return cl.UsageError(error);
  }
  if (settings.Maps.empty())
  {
    return cl.UsageError("--maps needs at least one map");
  }
  if (!cl.Positional().empty())
  {
    return cl.UsageError("unexpected argument '" + cl.Positional()[0] + "'");
  }
  settings.Environment = cl.Get("--environment");
  if (settings.Environment.empty() && (cl.Has("--env-lights") || cl.Has("--exposure")))
  {
    return cl.UsageError("--env-lights and --exposure need --environment");
  }
  if (settings.Environment.empty() && settings.Lights == 0)
  {
    return cl.UsageError("--lights 0 without --environment leaves the relief unlit");
  }
  settings.CsvFile = cl.Get("--csv");
  settings.PlotFile = cl.Get("--plot");
  if (const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, {});
      !problem.empty())
  {
    return cl.UsageError(problem);
  }

  if (!settings.Environment.empty())
  {
    ReliefSceneOptions lighting;
    lighting.Environment = settings.Environment;
    lighting.EnvironmentLights = settings.EnvironmentLights;
    settings.EnvironmentLightSet = MakeEnvironmentLights(lighting, error);
    if (!settings.EnvironmentLightSet)
    {
      std::cerr << "mesolight bench relief-aliasing: " << error << "\n";
      return 1;
    }
  }

  vtkNew<vtkReliefProperty> defaults;
  std::ostream& out = std::cout;
  const std::string compareRays = settings.CompareFarViewRays > 0
    ? ", FarViewRays " + std::to_string(settings.CompareFarViewRays)
    : std::string();
  // The third row, as the table, the summary and the chart name it.
  const std::string third =
    std::string(settings.CompareFilter == vtkReliefProperty::MeanNormalFilter
        ? "mean normal filter (Toksvig)"
        : settings.CompareFilter == vtkReliefProperty::VisibleNormalFilter
        ? "visible normal filter (the moments, facets turned away unmasked)"
        : "default's normal filter") +
    compareRays;
  out << "Relief aliasing: " << settings.Width << "x" << settings.Height_ << " pixels, depth scale "
      << settings.DepthScale << "; reference: max-mipmap 128 (exact) at " << settings.Supersampling
      << "x" << settings.Supersampling << " subsamples per pixel, box-filtered.\n"
      << "lights: " << settings.Lights << " VTK light(s)"
      << (settings.Environment.empty() ? std::string()
                                       : "; environment " + settings.Environment + ", " +
               std::to_string(settings.EnvironmentLights) + " median-cut lights, exposure " +
               Ratio(settings.Exposure, 1.0) + ", tone mapped")
      << ".\n"
      << "before: "
      << (settings.Method.empty() ? vtkReliefProperty::GetMethodName(defaults->GetMethod())
                                  : settings.Method.c_str())
      << " " << (settings.Method.empty() ? defaults->GetLinearSteps() : settings.Linear) << "+"
      << (settings.Method.empty() ? defaults->GetRefinementSteps() : settings.Refine)
      << ", level of detail off; default: the same with level of detail on and the default normal\n"
      << "filter (visible normals, second moments, facets turned away masked; several view rays\n"
      << "per far pixel); 3rd (third row): level of detail with the " << third
      << (settings.Method.empty() ? "" : " (the method above)") << ".\n"
      << "err: mean |colour - reference| in 8-bit levels; fp: median footprint, texels per pixel;\n"
      << "far: pixels whose footprint exceeds one texel; spp: relief-texture samples per pixel;\n"
      << "near hit: how far the default moves hits of near pixels from before's, texels (max);\n"
      << "ms: the whole frame's median milliseconds over " << settings.Frames
      << " frames (before, default, 3rd).\n\n";
  out << std::left << std::setw(18) << "map" << std::right << std::setw(5) << "deg" << std::setw(6)
      << "dist" << std::setw(6) << "fp" << std::setw(6) << "far%" << std::setw(8) << "err bef"
      << std::setw(8) << "err def" << std::setw(7) << "ratio" << std::setw(9) << "far bef"
      << std::setw(9) << "far def" << std::setw(7) << "ratio" << std::setw(9) << "far 3rd"
      << std::setw(7) << "ratio" << std::setw(9) << "near bef" << std::setw(9) << "near def"
      << std::setw(9) << "spp bef" << std::setw(9) << "spp def" << std::setw(9) << "far spp"
      << std::setw(9) << "near hit" << std::setw(8) << "ms bef" << std::setw(8) << "ms def"
      << std::setw(8) << "ms 3rd"
      << "\n";
  std::vector<CaseRow> rows;
  for (const std::string& map : settings.Maps)
  {
    for (double angle : settings.Angles)
    {
      for (double distance : settings.Distances)
      {
        CaseRow row;
        if (!MeasureCase(settings, map, angle, distance, row, error))
        {
          std::cerr << "mesolight bench relief-aliasing: " << error << "\n";
          return 1;
        }
        const double farShare = row.All.Pixels > 0 ? 100.0 * row.Far.Pixels / row.All.Pixels : 0;
        out << std::left << std::setw(18) << row.Map.substr(0, 17) << std::right << std::fixed
            << std::setprecision(0) << std::setw(5) << angle << std::setprecision(1) << std::setw(6)
            << distance << std::setw(6) << row.MedianFootprint << std::setw(6) << farShare
            << std::setprecision(2) << std::setw(8) << row.All.ErrorBefore << std::setw(8)
            << row.All.ErrorDefault << std::setw(7)
            << Ratio(row.All.ErrorDefault, row.All.ErrorBefore) << std::setw(9)
            << row.Far.ErrorBefore << std::setw(9) << row.Far.ErrorDefault << std::setw(7)
            << Ratio(row.Far.ErrorDefault, row.Far.ErrorBefore) << std::setw(9) << row.Far.ErrorMean
            << std::setw(7) << Ratio(row.Far.ErrorMean, row.Far.ErrorBefore) << std::setw(9)
            << row.Near.ErrorBefore << std::setw(9) << row.Near.ErrorDefault << std::setprecision(1)
            << std::setw(9) << row.Far.SamplesBefore << std::setw(9) << row.Far.SamplesDefault
            << std::setw(9) << Ratio(row.Far.SamplesDefault, row.Far.SamplesBefore)
            << std::setprecision(3) << std::setw(9) << row.NearHitChangeMax << std::setprecision(1)
            << std::setw(8) << row.Ms.Before << std::setw(8) << row.Ms.Default << std::setw(8)
            << row.Ms.Mean << "\n"
            << std::setprecision(3); // the summary's figures below
        out.unsetf(std::ios::fixed);
        out.flush();
        rows.push_back(row);
      }
    }
  }

  // Summary: the error ratio over all measured pixels of every case, and per case.
  double before = 0.0, current = 0.0, farBefore = 0.0, farCurrent = 0.0, sb = 0.0, sd = 0.0;
  double farMean = 0.0, sm = 0.0;
  FrameTimes ms; // summed over the cases
  long long pixels = 0, farPixels = 0, met = 0, withFar = 0, better = 0;
  double nearHitMax = 0.0;
  for (const CaseRow& r : rows)
  {
    before += r.All.ErrorBefore * r.All.Pixels;
    current += r.All.ErrorDefault * r.All.Pixels;
    pixels += r.All.Pixels;
    farBefore += r.Far.ErrorBefore * r.Far.Pixels;
    farCurrent += r.Far.ErrorDefault * r.Far.Pixels;
    farMean += r.Far.ErrorMean * r.Far.Pixels;
    sm += r.Far.SamplesMean * r.Far.Pixels;
    sb += r.Far.SamplesBefore * r.Far.Pixels;
    sd += r.Far.SamplesDefault * r.Far.Pixels;
    farPixels += r.Far.Pixels;
    nearHitMax = std::max(nearHitMax, r.NearHitChangeMax);
    ms.Before += r.Ms.Before;
    ms.Default += r.Ms.Default;
    ms.Mean += r.Ms.Mean;
    if (r.Far.Pixels > 0)
    {
      ++withFar;
      met += r.Far.ErrorDefault <= 0.5 * r.Far.ErrorBefore ? 1 : 0;
      better += r.Far.ErrorDefault < std::min(r.Far.ErrorBefore, r.Far.ErrorMean) ? 1 : 0;
    }
  }
  out << "\nall pixels of all cases: error " << before / std::max<long long>(pixels, 1) << " -> "
      << current / std::max<long long>(pixels, 1) << " levels (" << Ratio(current, before)
      << "x); far pixels: " << farBefore / std::max<long long>(farPixels, 1) << " -> "
      << farCurrent / std::max<long long>(farPixels, 1) << " (" << Ratio(farCurrent, farBefore)
      << "x), samples per far pixel " << sb / std::max<long long>(farPixels, 1) << " -> "
      << sd / std::max<long long>(farPixels, 1) << " (" << Ratio(sd, sb) << "x)\n"
      << "3rd, " << third << ": far error " << farMean / std::max<long long>(farPixels, 1) << " ("
      << Ratio(farMean, farBefore) << "x before), samples per far pixel "
      << sm / std::max<long long>(farPixels, 1) << " (" << Ratio(sm, sb) << "x)\n"
      << "cases with far error <= 0.5x before: " << met << " of " << withFar
      << "; default below both before and mean: " << better << " of " << withFar
      << "; largest move of a near hit: " << nearHitMax << " texels\n";
  if (settings.Frames > 0)
  {
    out << "ms per frame, summed over the cases: before " << ms.Before << ", default " << ms.Default
        << " (" << Ratio(ms.Default, ms.Before) << "x), 3rd " << ms.Mean << " ("
        << Ratio(ms.Mean, ms.Before) << "x)\n";
  }
  out << "signed far error (frame - reference, levels; before / default / third row):";
  for (const CaseRow& r : rows)
  {
    if (r.Far.Pixels > 0)
    {
      out << "\n  " << r.Map << " " << r.Angle << " deg " << r.Distance << ": " << std::fixed
          << std::setprecision(2) << r.FarSignedBefore << " / " << r.FarSignedDefault << " / "
          << r.FarSignedMean;
      out.unsetf(std::ios::fixed);
    }
  }
  out << "\n";

  if (!settings.CsvFile.empty())
  {
    std::ofstream csv(settings.CsvFile);
    csv << "map,view_deg,distance,median_footprint_texels,pixels,far_pixels,error_before,"
           "error_default,far_error_before,far_error_default,near_error_before,"
           "near_error_default,far_spp_before,far_spp_default,near_spp_before,near_spp_default,"
           "near_hit_change_max_texels,near_hit_change_mean_texels,error_third_row,"
           "far_error_third_row,near_error_third_row,far_spp_third_row,ms_before,ms_default,"
           "ms_third_row\n";
    for (const CaseRow& r : rows)
    {
      csv << r.Map << ',' << r.Angle << ',' << r.Distance << ',' << r.MedianFootprint << ','
          << r.All.Pixels << ',' << r.Far.Pixels << ',' << r.All.ErrorBefore << ','
          << r.All.ErrorDefault << ',' << r.Far.ErrorBefore << ',' << r.Far.ErrorDefault << ','
          << r.Near.ErrorBefore << ',' << r.Near.ErrorDefault << ',' << r.Far.SamplesBefore << ','
          << r.Far.SamplesDefault << ',' << r.Near.SamplesBefore << ',' << r.Near.SamplesDefault
          << ',' << r.NearHitChangeMax << ',' << r.NearHitChangeMean << ',' << r.All.ErrorMean
          << ',' << r.Far.ErrorMean << ',' << r.Near.ErrorMean << ',' << r.Far.SamplesMean << ','
          << r.Ms.Before << ',' << r.Ms.Default << ',' << r.Ms.Mean << "\n";
    }
    if (!csv)
    {
      std::cerr << "mesolight bench relief-aliasing: could not write " << settings.CsvFile << "\n";
      return 1;
    }
    out << "wrote " << settings.CsvFile << "\n";
  }
  if (!settings.PlotFile.empty())
  {
    ScatterChart chart;
    chart.Title = "Relief against the supersampled exact reference";
    chart.XLabel = "median footprint (texels per pixel)";
    chart.YLabel = "mean colour error (8-bit levels)";
    ChartSeries b{ "level of detail off (before)", {}, {} };
    ChartSeries d{ "default (visible normals)", {}, {} };
    ChartSeries m{ "3rd: " + third, {}, {} };
    for (const CaseRow& r : rows)
    {
      b.X.push_back(r.MedianFootprint);
      b.Y.push_back(r.All.ErrorBefore);
      d.X.push_back(r.MedianFootprint);
      d.Y.push_back(r.All.ErrorDefault);
      m.X.push_back(r.MedianFootprint);
      m.Y.push_back(r.All.ErrorMean);
    }
    chart.Points = { b, m, d };
    if (!WriteScatterChartPng(chart, settings.PlotFile, error))
    {
      std::cerr << "mesolight bench relief-aliasing: " << error << "\n";
      return 1;
    }
    out << "wrote " << settings.PlotFile << "\n";
  }
  return 0;
}

} // namespace mesolight
