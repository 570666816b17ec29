// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefSweep.h"
#include "ReliefSweepReport.h"

#include "CommandLine.h"
#include "ImageCompare.h"
#include "OutputFile.h"
#include "ReliefReference.h"
#include "ReliefScene.h"
#include "vtkOIIOImageWriter.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefMapper.h"
#include "vtkReliefPlaneFilter.h"
#include "vtkReliefProperty.h"

#if __has_include("vtkConeMapFilter.h")
#include "vtkConeMapFilter.h"
#define MESOLIGHT_HAVE_CONE_MAP_FILTER 1
#else
#define MESOLIGHT_HAVE_CONE_MAP_FILTER 0
#endif

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>
#include <stdexcept>

namespace mesolight
{

//------------------------------------------------------------------------------
// The step table. LinearSteps / RefinementSteps are the mapper's two knobs; what they count
// depends on the method (vtkReliefMapper.h): linear-search samples and binary / interval
// refinement steps for the safe searches; iterations for iterative parallax and max-mipmap;
// cone-stepping steps for cone methods. Non-iterative methods have one setting.
std::vector<ReliefSweepStep> ReliefSweepStepsFor(int method)
{
  auto label = [](int l, int r) { return std::to_string(l) + "+" + std::to_string(r); };
  std::vector<ReliefSweepStep> steps;
  switch (method)
  {
    case vtkReliefProperty::TextureMapping:
    case vtkReliefProperty::Bump:
    case vtkReliefProperty::Parallax:
    case vtkReliefProperty::ParallaxOffsetLimiting:
    case vtkReliefProperty::ParallaxSlope:
      // One setting; the mapper's defaults, so a method that still falls back to the default
      // march (not yet implemented in the shaders) shows that march, not a degenerate one.
      steps.push_back({ 10, 8, "-" });
      break;
    case vtkReliefProperty::IterativeParallax:
      for (int l : { 2, 4, 8 })
      {
        steps.push_back({ l, 0, "iter " + std::to_string(l) });
      }
      break;
    case vtkReliefProperty::BinarySearch:
    case vtkReliefProperty::Secant:
      // Unsafe searches over the whole ray: iterations as refinement steps, no linear search.
      for (int r : { 4, 8, 16 })
      {
        steps.push_back({ 1, r, "iter " + std::to_string(r) });
      }
      break;
    // Search steps up to 128: at grazing angles the sub-texel accurate settings, where the
    // searches differ most, need 64 or more.
    case vtkReliefProperty::LinearSearch:
    case vtkReliefProperty::ParallaxOcclusion:
      for (int l : { 8, 16, 32, 64, 128 })
      {
        steps.push_back({ l, 0, label(l, 0) });
      }
      break;
    case vtkReliefProperty::Relief:
    case vtkReliefProperty::Interval:
      for (int l : { 8, 16, 32, 64, 128 })
      {
        for (int r : { 0, 4, 8 })
        {
          steps.push_back({ l, r, label(l, r) });
        }
      }
      break;
    case vtkReliefProperty::RelaxedConeBinary:
    case vtkReliefProperty::RelaxedConeInterval:
      for (int l : { 8, 16, 32, 64, 128 })
      {
        for (int r : { 4, 8 })
        {
          steps.push_back({ l, r, label(l, r) });
        }
      }
      break;
    case vtkReliefProperty::ConservativeCone:
      for (int l : { 8, 16, 32, 64, 128 })
      {
        steps.push_back({ l, 4, label(l, 4) }); // cone steps, then binary search of the bracket
      }
      break;
    case vtkReliefProperty::MaximumMipmap:
      for (int l : { 32, 64, 128 })
      {
        steps.push_back({ l, 0, "iter " + std::to_string(l) });
      }
      break;
    default:
      steps.push_back({ 10, 8, label(10, 8) });
      break;
  }
  return steps;
}

namespace
{
using Clock = std::chrono::steady_clock;

double Milliseconds(Clock::duration d)
{
  return std::chrono::duration<double, std::milli>(d).count();
}

// Methods whose LinearSteps / RefinementSteps are a linear or cone search and its refinement.
bool UsesSearchSteps(int m)
{
  return m == vtkReliefProperty::LinearSearch || m == vtkReliefProperty::ParallaxOcclusion ||
    m == vtkReliefProperty::Relief || m == vtkReliefProperty::Interval ||
    m == vtkReliefProperty::RelaxedConeBinary || m == vtkReliefProperty::RelaxedConeInterval ||
    m == vtkReliefProperty::ConservativeCone;
}

// "L+R" -> LinearSteps L (1..1024), RefinementSteps R (0..64).
bool ParseStepLabel(const std::string& label, ReliefSweepStep& step)
{
  const size_t plus = label.find('+');
  if (plus == std::string::npos)
  {
    return false;
  }
  char* end1 = nullptr;
  char* end2 = nullptr;
  const long l = std::strtol(label.c_str(), &end1, 10);
  const long r = std::strtol(label.c_str() + plus + 1, &end2, 10);
  if (end1 != label.c_str() + plus || *end2 != '\0' || l < 1 || l > 1024 || r < 0 || r > 64)
  {
    return false;
  }
  step.LinearSteps = static_cast<int>(l);
  step.RefinementSteps = static_cast<int>(r);
  step.Label = label;
  return true;
}

// The cone map a cone method needs, built from the relief texture; null when it cannot be built
// (no vtkConeMapFilter in this build, or the filter failed).
vtkSmartPointer<vtkImageData> BuildConeMap(
  vtkImageData* relief, int kind, double depthScale, std::string& why)
{
#if MESOLIGHT_HAVE_CONE_MAP_FILTER
  vtkNew<vtkConeMapFilter> cones;
  cones->SetInputData(relief);
  if (kind == vtkReliefProperty::RelaxedConeMap)
  {
    cones->SetConeTypeToRelaxed();
  }
  else
  {
    cones->SetConeTypeToConservative();
  }
  cones->SetDepthScale(depthScale);
  cones->Update();
  vtkImageData* output = cones->GetOutput();
  if (!output || output->GetNumberOfPoints() == 0)
  {
    why = "vtkConeMapFilter produced no output";
    return nullptr;
  }
  auto copy = vtkSmartPointer<vtkImageData>::New();
  copy->DeepCopy(output);
  return copy;
#else
  (void)relief;
  (void)kind;
  (void)depthScale;
  why = "vtkConeMapFilter is not part of this build";
  return nullptr;
#endif
}

double TimeFrames(vtkRenderWindow* window, int frames, double& firstMs)
{
  auto t0 = Clock::now();
  window->Render();
  window->WaitForCompletion();
  firstMs = Milliseconds(Clock::now() - t0);
  std::vector<double> times;
  for (int i = 0; i < std::max(1, frames); ++i)
  {
    auto t = Clock::now();
    window->Render();
    window->WaitForCompletion();
    times.push_back(Milliseconds(Clock::now() - t));
  }
  std::sort(times.begin(), times.end());
  const size_t n = times.size();
  return n % 2 ? times[n / 2] : 0.5 * (times[n / 2 - 1] + times[n / 2]);
}

// Mean and lock-step mean of a per-pixel count of the reference (-1: not covered).
ExactTraversalCounts CountsOf(const ReliefReference& reference, const std::vector<int>& counts)
{
  return { MeanCount(counts), MeanLockStepCount(counts, reference.Width, reference.Height, 8, 4) };
}

// Colour RMSE (8-bit levels over RGB) against the dense mesh, pixels of the reference footprint
// covered in both frames.
double ColorRmse(const ReliefReference& reference, const Frame& shaded, const Frame& dense)
{
  double sum = 0.0;
  long long n = 0;
  const size_t pixels = reference.State.size();
  if (shaded.Depth.size() != pixels || dense.Depth.size() != pixels)
  {
    return 255.0;
  }
  for (size_t p = 0; p < pixels; ++p)
  {
    if (!reference.InFootprint(p) || !shaded.Covered(p) || !dense.Covered(p))
    {
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double d = double(shaded.Rgb[3 * p + c]) - double(dense.Rgb[3 * p + c]);
      sum += d * d;
    }
    n += 3;
  }
  return n > 0 ? std::sqrt(sum / double(n)) : 255.0;
}

struct MapSource
{
  std::string Label;   // as shown in the table
  std::string Pattern; // procedural pattern, or empty
  std::string DepthFile;
  std::string Note; // printed under the table
};

// The "file" maps: one per depth file, or the Stone pattern written as a 16-bit PNG.
bool PrepareFileMaps(const ReliefSweepSettings& settings, const std::string& directory,
  std::vector<MapSource>& maps, std::ostream& out)
{
  if (!settings.DepthFiles.empty())
  {
    for (const std::string& depthFile : settings.DepthFiles)
    {
      MapSource map;
      map.Label = std::filesystem::path(depthFile).stem().string();
      map.DepthFile = depthFile;
      maps.push_back(map);
    }
    return true;
  }
  MapSource map;
  const std::string file = (std::filesystem::path(directory) / "sweep-stone-16bit.png").string();
  vtkNew<vtkProceduralReliefSource> stone;
  stone->SetPatternToStone();
  stone->SetResolution(512, 512);
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputConnection(stone->GetOutputPort(0));
  writer->SetFileName(file.c_str());
  writer->SetBitDepth(16);
  if (!writer->Write())
  {
    out << "bench relief: could not write " << file << "\n";
    return false;
  }
  map.Label = "file(stone16)";
  map.DepthFile = file;
  map.Note = "the Stone pattern written to " + file +
    " as a 16-bit PNG and read back through vtkOIIOImageReader (tests the file path, not real "
    "data)";
  out << "map 'file': no --depth-file given, so the Stone pattern was written to " << file
      << " as a 16-bit PNG and is read back through vtkOIIOImageReader: this row set tests the "
         "file path, not real data.\n";
  maps.push_back(map);
  return true;
}

// What VTK's stock mapper uploads for the dense displaced mesh of a w x h map (one vertex per
// texel, vtkHeightFieldMeshFilter): position, normal (3 floats each) and texture coordinate (2)
// per vertex, three 32-bit indices per triangle; as ReliefBenchmark.cxx counts it.
double DenseMeshMegaBytes(int w, int h)
{
  return (double(w) * h * 32.0 + 2.0 * (w - 1) * (h - 1) * 12.0) / 1048576.0;
}

// The method "default" in the method list.
constexpr int DefaultSettings = -1;
} // namespace

//------------------------------------------------------------------------------
bool RunReliefSweep(
  const ReliefSweepSettings& settings, std::ostream& out, std::vector<ReliefSweepRow>* rowsOut)
{
  // Methods, in the mapper's order.
  std::vector<int> methods;
  if (settings.Methods.empty())
  {
    for (int m = 0; m < vtkReliefProperty::NumberOfMethods; ++m)
    {
      methods.push_back(m);
    }
  }
  for (const std::string& name : settings.Methods)
  {
    const int m =
      name == "default" ? DefaultSettings : vtkReliefProperty::GetMethodFromName(name.c_str());
    if (m < 0 && m != DefaultSettings)
    {
      out << "bench relief: unknown method '" << name << "'\n";
      return false;
    }
    methods.push_back(m);
  }

  // Where generated files go: the plot directory, else the CSV's directory, else here.
  std::string directory = ".";
  if (!settings.PlotDirectory.empty())
  {
    directory = settings.PlotDirectory;
  }
  else if (!settings.CsvFile.empty() &&
    !std::filesystem::path(settings.CsvFile).parent_path().empty())
  {
    directory = std::filesystem::path(settings.CsvFile).parent_path().string();
  }
  std::error_code ec;
  std::filesystem::create_directories(directory, ec);
  if (ec)
  {
    out << "bench relief: cannot create " << directory << ": " << ec.message() << "\n";
    return false;
  }

  std::vector<MapSource> maps;
  for (const std::string& name : settings.Maps)
  {
    if (name == "file")
    {
      if (!PrepareFileMaps(settings, directory, maps, out))
      {
        return false;
      }
      continue;
    }
    MapSource map;
    map.Label = name;
    map.Pattern = name;
    maps.push_back(map);
  }

  out << "Relief sweep: " << settings.Width << "x" << settings.Height << " pixels, depth scale "
      << settings.DepthScale << ", procedural maps " << settings.Resolution << "^2 texels, "
      << settings.Frames << " timed frames (median, after a warm-up frame), "
      << (settings.FillViewport ? "each view stretched so the wall fills the window"
                                : "whole-wall square framing")
      << ".\n"
      << "hit = |uv_gpu - uv_cpu| in texels vs the exact CPU reference (pixels covered in both); "
         "silh = % of the footprint covered by exactly one;\n"
      << "RMSE/PSNR = shaded colour (no self-shadowing) vs the dense displaced mesh; shadow = % of "
         "pixels covered in both where first-light visibility differs.\n"
      << "samples = relief-texture samples per covered pixel (what texture units fetch); warp smp "
         "= the same charged at the largest count of each 8 x 4 pixel group (a 32-lane warp's "
         "loop runs until its slowest pixel ends).\n"
      << std::flush;

  std::vector<ReliefSweepRow> rows;
  std::vector<std::string> skipped;
  for (const MapSource& map : maps)
  {
    ReliefSceneOptions o;
    o.Pattern = map.Pattern.empty() ? "Bricks" : map.Pattern;
    o.DepthFile = map.DepthFile;
    o.DepthFileIsHeight = settings.DepthFilesAreHeight && !settings.DepthFiles.empty();
    o.NormalizeDepthFile = settings.NormalizeDepthFiles && !settings.DepthFiles.empty();
    o.UseNoDataValue = settings.UseNoDataValue && !settings.DepthFiles.empty();
    o.NoDataValue = settings.NoDataValue;
    o.UseFileNoDataValue = settings.UseFileNoDataValue;
    o.Resolution = settings.Resolution;
    o.DepthScale = settings.DepthScale;
    o.Width = settings.Width;
    o.Height = settings.Height;
    o.FillViewport = settings.FillViewport;
    o.SelfShadowing = false;
    o.LevelOfDetail = settings.LevelOfDetail;
    o.FarViewRays = settings.FarViewRays;
    std::string error;
    ReliefScene relief, dense;
    if (!BuildReliefScene(o, relief, error) ||
      (settings.DenseMesh && !BuildDenseReferenceScene(o, dense, error)))
    {
      out << "bench relief: map " << map.Label << ": " << error << "\n";
      return false;
    }
    // Cone maps, once per map, for the cone methods requested.
    std::map<int, vtkSmartPointer<vtkImageData>> coneMaps;
    vtkNew<vtkReliefProperty> defaults; // an untouched property: the "default" row's settings
    for (int m : methods)
    {
      const int kind =
        vtkReliefProperty::GetRequiredConeMap(m == DefaultSettings ? defaults->GetMethod() : m);
      if (kind == vtkReliefProperty::NoConeMap || coneMaps.count(kind))
      {
        continue;
      }
      std::string why;
      coneMaps[kind] = BuildConeMap(relief.ReliefTexture, kind, o.DepthScale, why);
      if (!coneMaps[kind])
      {
        skipped.push_back(
          std::string(kind == vtkReliefProperty::RelaxedConeMap ? "relaxed" : "conservative") +
          " cone map for " + map.Label + ": " + why);
      }
    }
    auto reliefWindow = MakeOffscreenWindow(o, relief.Renderer);
    auto denseWindow = settings.DenseMesh ? MakeOffscreenWindow(o, dense.Renderer)
                                          : vtkSmartPointer<vtkRenderWindow>();
    vtkReliefMapper* mapper = relief.Mapper;
    int texels[3];
    relief.ReliefTexture->GetDimensions(texels);
    const double denseMegaBytes = DenseMeshMegaBytes(texels[0], texels[1]);

    for (double angle : settings.Angles)
    {
      o.ViewAngle = angle;
      SetupCameraAndLights(
        o, relief.Renderer, vtkReliefPlaneFilter::GetGroundProportions(relief.ReliefTexture));
      Frame denseFrame;
      if (settings.DenseMesh)
      {
        SetupCameraAndLights(
          o, dense.Renderer, vtkReliefPlaneFilter::GetGroundProportions(relief.ReliefTexture));
        denseFrame = CaptureFrame(denseWindow);
      }
      ReliefReference reference;
      ReliefReferenceInput referenceInput = MakeReliefReferenceInput(relief, o);
      referenceInput.CountTraversalFetches = true;
      if (!ComputeReliefReference(referenceInput, reference, error))
      {
        out << "bench relief: " << error << "\n";
        return false;
      }
      const ExactTraversalCounts floor = CountsOf(reference, reference.BoundReachingCells);
      const ExactTraversalCounts oracleStored =
        CountsOf(reference, reference.OracleFetchesStoredLevels);
      const ExactTraversalCounts oracleAll = CountsOf(reference, reference.OracleFetchesAllLevels);
      out << "[" << map.Label << ", " << angle
          << " deg] CPU reference: " << reference.CountCovered() << " covered of "
          << reference.CountFootprint() << " footprint pixels in "
          << report::Fixed(reference.Seconds, 3)
          << " s; exact bound traversals fetch (samples / warp samples per pixel) at least "
          << report::Fixed(floor.Mean, 1) << " / " << report::Fixed(floor.LockStep, 1)
          << ", told every level " << report::Fixed(oracleStored.Mean, 1) << " / "
          << report::Fixed(oracleStored.LockStep, 1) << " over the stored pyramid, "
          << report::Fixed(oracleAll.Mean, 1) << " / " << report::Fixed(oracleAll.LockStep, 1)
          << " over a full one\n"
          << std::flush;

      for (int listed : methods)
      {
        const bool isDefault = listed == DefaultSettings;
        const int m = isDefault ? defaults->GetMethod() : listed;
        const int kind = vtkReliefProperty::GetRequiredConeMap(m);
        if (kind != vtkReliefProperty::NoConeMap && !coneMaps[kind])
        {
          continue;
        }
        mapper->SetReliefTextureData(
          kind == vtkReliefProperty::NoConeMap ? relief.ReliefTexture.Get() : coneMaps[kind].Get());
        mapper->GetReliefProperty()->SetMethod(m);
        std::vector<ReliefSweepStep> steps = ReliefSweepStepsFor(m);
        if (isDefault)
        {
          // Labelled as the method's own rows are (max-mipmap: "iter N").
          const std::string count = m == vtkReliefProperty::MaximumMipmap
            ? "iter " + std::to_string(defaults->GetLinearSteps())
            : std::to_string(defaults->GetLinearSteps()) + "+" +
              std::to_string(defaults->GetRefinementSteps());
          steps = { { defaults->GetLinearSteps(), defaults->GetRefinementSteps(),
            std::string(vtkReliefProperty::GetMethodName(m)) + " " + count } };
        }
        else if (!settings.Steps.empty() && UsesSearchSteps(m))
        {
          steps.clear();
          for (const std::string& label : settings.Steps)
          {
            ReliefSweepStep step;
            ParseStepLabel(label, step);
            steps.push_back(step);
          }
        }
        else if (!settings.Iterations.empty() && m == vtkReliefProperty::MaximumMipmap)
        {
          steps.clear();
          for (int n : settings.Iterations)
          {
            steps.push_back({ n, 0, "iter " + std::to_string(n) });
          }
        }
        for (size_t k = 0; k < steps.size() * settings.TextureStorages.size(); ++k)
        {
          // Each storage in turn with every step setting (one upload per storage and method).
          const ReliefSweepStep& step = steps[k % steps.size()];
          const std::string& storage = settings.TextureStorages[k / steps.size()];
          ReliefSweepRow row;
          row.Map = map.Label;
          row.Angle = angle;
          row.Method = m;
          row.FloatTextures = storage == "float";
          row.MethodName =
            std::string(isDefault ? "default" : vtkReliefProperty::GetMethodName(m)) +
            (storage == "compact" ? "" : " (" + storage + ")");
          row.IsDefault = isDefault;
          row.Step = step;
          row.DenseMegaBytes = denseMegaBytes;
          row.Floor = floor;
          row.OracleStoredLevels = oracleStored;
          row.OracleAllLevels = oracleAll;
          mapper->GetReliefProperty()->SetFloatTextures(row.FloatTextures);
          mapper->GetReliefProperty()->SetLinearSteps(step.LinearSteps);
          mapper->GetReliefProperty()->SetRefinementSteps(step.RefinementSteps);

          // Shaded, no self-shadowing: timing and colour against the dense mesh.
          mapper->GetReliefProperty()->SetSelfShadowing(false);
          mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::ShadedOutput);
          row.MedianMs = TimeFrames(reliefWindow, settings.Frames, row.FirstMs);
          if (mapper->GetShaderFailed())
          {
            out << "bench relief: the shader of " << row.MethodName << " " << step.Label
                << " did not compile (the GLSL compiler's message is above); stopping\n";
            return false;
          }
          row.GpuMegaBytes = double(mapper->GetReliefTextureBytes()) / 1048576.0;
          const Frame shaded = CaptureFrame(reliefWindow);
          row.ColorRmse = settings.DenseMesh ? ColorRmse(reference, shaded, denseFrame) : -1.0;
          row.Psnr = row.ColorRmse > 0.0 ? 20.0 * std::log10(255.0 / row.ColorRmse)
            : row.ColorRmse == 0.0       ? 99.0
                                         : -1.0;

          // What the march sampled, per covered pixel of the same (shadowless) frame.
          mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::SampleCountOutput);
          const Frame counts = CaptureFrame(reliefWindow);
          row.SamplesPerPixel = MeanSampleCount(counts);
          row.LockStepSamplesPerPixel = MeanLockStepSampleCount(counts, 8, 4);

          // Hit coordinates against the CPU reference.
          mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::HitUOutput);
          const Frame hitU = CaptureFrame(reliefWindow);
          mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::HitVOutput);
          const Frame hitV = CaptureFrame(reliefWindow);
          const HitComparison hits = CompareHits(reference, hitU, hitV);
          row.HitMeanTexels = hits.MeanTexels;
          row.HitP99Texels = hits.P99Texels;
          row.SilhouetteMismatch = hits.SilhouetteMismatch;
          row.CoveredBoth = hits.CoveredBoth;
          row.Footprint = hits.Footprint;

          // First-light visibility with self-shadowing on.
          mapper->GetReliefProperty()->SetSelfShadowing(true);
          mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::LightVisibilityOutput);
          const Frame visibility = CaptureFrame(reliefWindow);
          row.ShadowMismatch = CompareLightVisibility(reference, visibility);
          mapper->GetReliefProperty()->SetSelfShadowing(false);
          mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::ShadedOutput);

          rows.push_back(row);
        }
      }
      out << "[" << map.Label << ", " << angle << " deg] done, " << rows.size()
          << " configurations so far\n"
          << std::flush;
    }
    mapper->SetReliefTextureData(relief.ReliefTexture);
    mapper->GetReliefProperty()->SetFloatTextures(false);
  }

  out << "\n";
  report::PrintHeader(out);
  for (const ReliefSweepRow& r : rows)
  {
    report::PrintRow(out, r);
  }
  for (const MapSource& map : maps)
  {
    if (!map.Note.empty())
    {
      out << map.Label << ": " << map.Note << "\n";
    }
  }
  for (const std::string& s : skipped)
  {
    out << "skipped cone methods: " << s << "\n";
  }
  bool ok = true;
  if (!settings.CsvFile.empty())
  {
    if (report::WriteCsv(settings.CsvFile, rows, settings))
    {
      out << "wrote " << settings.CsvFile << "\n";
    }
    else
    {
      out << "bench relief: could not write " << settings.CsvFile << "\n";
      ok = false;
    }
  }
  if (!settings.PlotDirectory.empty())
  {
    std::vector<std::string> labels;
    for (const MapSource& map : maps)
    {
      labels.push_back(map.Label);
    }
    ok = report::WritePlots(settings, rows, labels, out) && ok;
  }
  report::PrintSummary(settings, rows, out);
  if (rowsOut)
  {
    *rowsOut = rows;
  }
  return ok;
}

//------------------------------------------------------------------------------
int RunReliefSweep(const std::vector<std::string>& args)
{
  ReliefSweepSettings settings;
  CommandLine cl("mesolight bench relief",
    "Usage: mesolight bench relief [options]\n"
    "Accuracy and speed of every relief method per map, view angle and step setting,\n"
    "against the exact CPU reference and the dense displaced mesh.\n");
  cl.AddValue("--maps", "LIST",
    "comma-separated maps: procedural patterns (Bricks, Stone, HemisphereTorus, ...) and 'file'",
    "Bricks,Stone,HemisphereTorus,file");
  cl.AddValue("--depth-file", "IMAGE[,IMAGE..]",
    "depth images of the 'file' maps, one map each (default: the Stone pattern written as "
    "16-bit PNG)");
  cl.AddFlag("--height", "the depth images store height (white = high) rather than depth");
  cl.AddFlag("--normalize",
    "stretch each depth image's value range to [0, 1] (elevations in metres, as in DEMs)");
  cl.AddValue("--no-data", "VALUE", CommandLine::NoDataHelp);
  for (const char* option : { "--height", "--normalize", "--no-data" })
  {
    cl.AppliesOnlyWith(option, { "--depth-file" });
  }
  cl.AddValue("--angles", "LIST", "view angles from the wall normal, degrees", "0,45,70,80,85");
  cl.AddValue("--size", "WxH", "window size in pixels", "512x512");
  cl.AddValue("--frames", "N", "timed frames per configuration, after a warm-up frame", "5");
  cl.AddValue("--methods", "all|LIST",
    "vtkReliefMapper method names, and 'default' (an untouched vtkReliefProperty's settings)",
    "all");
  cl.AddValue("--resolution", "N", "texels per side of the procedural maps", "512");
  cl.AddValue("--depth-scale", "K", "world depth of depth 1 / wall width", "0.04");
  cl.AddValue("--steps", "L+R,..",
    "step settings for the linear/cone-search methods instead of the built-in table");
  cl.AddValue("--iterations", "N,..",
    "iteration budgets for max-mipmap instead of the built-in table (32,64,128)");
  cl.AddValue("--csv", "FILE", "write one CSV row per configuration");
  cl.AddValue("--plots", "DIR", "write one PNG chart per view angle into DIR");
  cl.AddValue("--texture-storage", "LIST",
    "how the relief is uploaded, each measured: compact (the default storage), float (float "
    "RGBA, vtkReliefProperty::FloatTextures)",
    "compact");
  cl.AddFlag("--no-dense",
    "do not draw the dense displaced mesh (maps too large to mesh): no colour columns; its size "
    "is still computed");
  cl.AddFlag("--level-of-detail",
    "draw with level of detail (vtkReliefProperty's default; off in the sweep), to measure what "
    "it uploads");
  cl.AddValue("--far-view-rays", "N",
    "with --level-of-detail, the most view rays per far pixel, 1-8 (vtkReliefProperty::"
    "FarViewRays; the property's default otherwise)");
  cl.AddFlag("--no-fill",
    "keep the square, whole-wall framing (the wall is then a thin strip at grazing angles) "
    "instead of stretching the view so the wall fills the window");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  settings.DepthFiles = cl.GetStringList("--depth-file");
  if (const std::string problem = CheckOutputOptions(cl, { "--csv" }, settings.DepthFiles);
      !problem.empty())
  {
    return cl.UsageError(problem);
  }
  if (!cl.Positional().empty())
  {
    std::cerr << "mesolight bench relief: unexpected argument '" << cl.Positional()[0] << "'\n";
    return 2;
  }
  settings.Maps = cl.GetStringList("--maps");
  settings.FillViewport = !cl.Has("--no-fill");
  settings.DepthFilesAreHeight = cl.Has("--height");
  settings.NormalizeDepthFiles = cl.Has("--normalize");
  CommandLine::NoDataOption noData;
  const bool noDataRead = cl.GetNoData("--no-data", noData, error);
  settings.UseNoDataValue = noData.Use;
  settings.NoDataValue = noData.Value;
  settings.UseFileNoDataValue = noData.UseFileValue;
  if (!noDataRead)
  {
    return cl.UsageError(error);
  }
  if (!cl.GetDoubleList("--angles", 0.0, 90.0, settings.Angles, error))
  {
    return cl.UsageError(error);
  }
  for (double angle : settings.Angles)
  {
    if (angle == 90.0)
    {
      return cl.UsageError("--angles: '90' is not an angle in [0, 90)");
    }
  }
  if (!cl.GetSize("--size", 16, 8192, settings.Width, settings.Height, error))
  {
    return cl.UsageError(error);
  }
  if (!cl.GetInt("--frames", 1, 1000, settings.Frames, error) ||
    !cl.GetInt("--resolution", 2, 8192, settings.Resolution, error) ||
    !cl.GetDouble("--depth-scale", 1e-4, 10.0, settings.DepthScale, error))
  {
    return cl.UsageError(error);
  }
  const std::string methods = cl.Get("--methods");
  if (methods != "all")
  {
    settings.Methods = cl.GetStringList("--methods");
    for (const std::string& name : settings.Methods)
    {
      if (name != "default" && vtkReliefProperty::GetMethodFromName(name.c_str()) < 0)
      {
        std::cerr << "mesolight bench relief: unknown method '" << name << "' (names:";
        for (int m = 0; m < vtkReliefProperty::NumberOfMethods; ++m)
        {
          std::cerr << " " << vtkReliefProperty::GetMethodName(m);
        }
        std::cerr << ")\n";
        return 2;
      }
    }
  }
  if (settings.Maps.empty() || settings.Angles.empty())
  {
    return cl.UsageError("--maps and --angles need at least one entry");
  }
  settings.Steps = cl.GetStringList("--steps");
  for (const std::string& label : settings.Steps)
  {
    ReliefSweepStep step;
    if (!ParseStepLabel(label, step))
    {
      std::cerr << "mesolight bench relief: --steps: '" << label << "' is not L+R\n";
      return 2;
    }
  }
  for (const std::string& n : cl.GetStringList("--iterations"))
  {
    int iterations = 0;
    try
    {
      iterations = std::stoi(n);
    }
    catch (const std::exception&)
    {
      iterations = 0;
    }
    if (iterations < 1 || iterations > 1024)
    {
      return cl.UsageError("--iterations: '" + n + "' is not a count in [1, 1024]");
    }
    settings.Iterations.push_back(iterations);
  }
  settings.TextureStorages = cl.GetStringList("--texture-storage");
  for (const std::string& storage : settings.TextureStorages)
  {
    if (storage != "compact" && storage != "float")
    {
      return cl.UsageError("--texture-storage: '" + storage + "' is not compact or float");
    }
  }
  if (settings.TextureStorages.empty())
  {
    return cl.UsageError("--texture-storage needs compact or float");
  }
  settings.DenseMesh = !cl.Has("--no-dense");
  settings.LevelOfDetail = cl.Has("--level-of-detail");
  if (cl.Has("--far-view-rays") && !cl.GetInt("--far-view-rays", 1, 8, settings.FarViewRays, error))
  {
    return cl.UsageError(error);
  }
  settings.CsvFile = cl.Get("--csv");
  settings.PlotDirectory = cl.Get("--plots");
  return RunReliefSweep(settings, std::cout) ? 0 : 1;
}

} // namespace mesolight
