#include "ReliefSweep.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "ImageCompare.h"
#include "ReliefReference.h"
#include "ReliefScene.h"
#include "vtkOIIOImageWriter.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefMapper.h"

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
    case vtkReliefMapper::TextureMapping:
    case vtkReliefMapper::Bump:
    case vtkReliefMapper::Parallax:
    case vtkReliefMapper::ParallaxOffsetLimiting:
    case vtkReliefMapper::ParallaxSlope:
      // One setting; the mapper's defaults, so a method that still falls back to the default
      // march (not yet implemented in the shaders) shows that march, not a degenerate one.
      steps.push_back({ 10, 8, "-" });
      break;
    case vtkReliefMapper::IterativeParallax:
      for (int l : { 2, 4, 8 })
      {
        steps.push_back({ l, 0, "iter " + std::to_string(l) });
      }
      break;
    case vtkReliefMapper::BinarySearch:
    case vtkReliefMapper::Secant:
      // Unsafe searches over the whole ray: iterations as refinement steps, no linear search.
      for (int r : { 4, 8, 16 })
      {
        steps.push_back({ 1, r, "iter " + std::to_string(r) });
      }
      break;
    // Search steps up to 128: at grazing angles the sub-texel accurate settings, where the
    // searches differ most, need 64 or more.
    case vtkReliefMapper::LinearSearch:
    case vtkReliefMapper::ParallaxOcclusion:
      for (int l : { 8, 16, 32, 64, 128 })
      {
        steps.push_back({ l, 0, label(l, 0) });
      }
      break;
    case vtkReliefMapper::Relief:
    case vtkReliefMapper::Interval:
      for (int l : { 8, 16, 32, 64, 128 })
      {
        for (int r : { 0, 4, 8 })
        {
          steps.push_back({ l, r, label(l, r) });
        }
      }
      break;
    case vtkReliefMapper::RelaxedConeBinary:
    case vtkReliefMapper::RelaxedConeInterval:
      for (int l : { 8, 16, 32, 64, 128 })
      {
        for (int r : { 4, 8 })
        {
          steps.push_back({ l, r, label(l, r) });
        }
      }
      break;
    case vtkReliefMapper::ConservativeCone:
      for (int l : { 8, 16, 32, 64, 128 })
      {
        steps.push_back({ l, 4, label(l, 4) }); // cone steps, then binary search of the bracket
      }
      break;
    case vtkReliefMapper::MaximumMipmap:
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

std::vector<std::string> SplitList(const std::string& text)
{
  std::vector<std::string> items;
  std::stringstream stream(text);
  std::string item;
  while (std::getline(stream, item, ','))
  {
    while (!item.empty() && item.front() == ' ')
    {
      item.erase(item.begin());
    }
    while (!item.empty() && item.back() == ' ')
    {
      item.pop_back();
    }
    if (!item.empty())
    {
      items.push_back(item);
    }
  }
  return items;
}

// Methods whose LinearSteps / RefinementSteps are a linear or cone search and its refinement.
bool UsesSearchSteps(int m)
{
  return m == vtkReliefMapper::LinearSearch || m == vtkReliefMapper::ParallaxOcclusion ||
    m == vtkReliefMapper::Relief || m == vtkReliefMapper::Interval ||
    m == vtkReliefMapper::RelaxedConeBinary || m == vtkReliefMapper::RelaxedConeInterval ||
    m == vtkReliefMapper::ConservativeCone;
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

int MethodFromName(const std::string& name)
{
  if (name == "steep")
  {
    return vtkReliefMapper::LinearSearch;
  }
  for (int m = 0; m < vtkReliefMapper::NumberOfMethods; ++m)
  {
    if (name == vtkReliefMapper::GetMethodName(m))
    {
      return m;
    }
  }
  return -1;
}

// The cone map a cone method needs, built from the relief texture; null when it cannot be built
// (no vtkConeMapFilter in this build, or the filter failed).
vtkSmartPointer<vtkImageData> BuildConeMap(
  vtkImageData* relief, int kind, double depthScale, std::string& why)
{
#if MESOLIGHT_HAVE_CONE_MAP_FILTER
  vtkNew<vtkConeMapFilter> cones;
  cones->SetInputData(relief);
  if (kind == vtkReliefMapper::RelaxedConeMap)
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
  std::string Label;    // as shown in the table
  std::string Pattern;  // procedural pattern, or empty
  std::string DepthFile;
  std::string Note; // printed under the table
};

// The "file" map: the user's depth file, or the Stone pattern written as a 16-bit PNG.
bool PrepareFileMap(const ReliefSweepSettings& settings, const std::string& directory,
  MapSource& map, std::ostream& out)
{
  if (!settings.DepthFile.empty())
  {
    map.Label = "file:" + std::filesystem::path(settings.DepthFile).filename().string();
    map.DepthFile = settings.DepthFile;
    return true;
  }
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
    " as a 16-bit PNG and read back through vtkOIIOImageReader (tests the file path, not real data)";
  out << "map 'file': no --depth-file given, so the Stone pattern was written to " << file
      << " as a 16-bit PNG and is read back through vtkOIIOImageReader: this row set tests the "
         "file path, not real data.\n";
  return true;
}

std::string Fixed(double value, int precision)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(precision) << value;
  return s.str();
}

void PrintHeader(std::ostream& out)
{
  out << std::left << std::setw(16) << "map" << std::right << std::setw(6) << "angle" << "  "
      << std::left << std::setw(22) << "method" << std::setw(9) << "steps" << std::right
      << std::setw(9) << "ms/frame" << std::setw(9) << "samples" << std::setw(10) << "hit mean" << std::setw(9) << "hit p99"
      << std::setw(8) << "silh %" << std::setw(8) << "RMSE" << std::setw(7) << "PSNR"
      << std::setw(9) << "shadow %" << "\n";
}

void PrintRow(std::ostream& out, const ReliefSweepRow& r)
{
  out << std::left << std::setw(16) << r.Map << std::right << std::setw(6) << Fixed(r.Angle, 0)
      << "  " << std::left << std::setw(22) << r.MethodName << std::setw(9) << r.Step.Label
      << std::right << std::setw(9) << Fixed(r.MedianMs, 1) << std::setw(9)
      << Fixed(r.SamplesPerPixel, 1) << std::setw(10) << Fixed(r.HitMeanTexels, 3) << std::setw(9) << Fixed(r.HitP99Texels, 2) << std::setw(8)
      << Fixed(r.SilhouetteMismatch, 2) << std::setw(8) << Fixed(r.ColorRmse, 2) << std::setw(7)
      << Fixed(r.Psnr, 1) << std::setw(9) << Fixed(r.ShadowMismatch, 2) << "\n";
}

bool WriteCsv(const std::string& file, const std::vector<ReliefSweepRow>& rows,
  const ReliefSweepSettings& settings)
{
  std::ofstream csv(file);
  csv << "map,view_angle_deg,method,linear_steps,refinement_steps,steps,width,height,depth_scale,"
         "ms_per_frame,first_frame_ms,samples_per_pixel,hit_error_mean_texels,hit_error_p99_texels,"
         "silhouette_mismatch_pct,color_rmse,psnr_db,shadow_mismatch_pct,covered_both,"
         "footprint\n";
  csv << std::setprecision(8);
  for (const ReliefSweepRow& r : rows)
  {
    csv << '"' << r.Map << "\"," << r.Angle << ',' << r.MethodName << ',' << r.Step.LinearSteps
        << ',' << r.Step.RefinementSteps << ",\"" << r.Step.Label << "\"," << settings.Width << ','
        << settings.Height << ',' << settings.DepthScale << ',' << r.MedianMs << ',' << r.FirstMs
        << ',' << r.SamplesPerPixel << ',' << r.HitMeanTexels << ',' << r.HitP99Texels << ',' << r.SilhouetteMismatch << ','
        << r.ColorRmse << ',' << r.Psnr << ',' << r.ShadowMismatch << ',' << r.CoveredBoth << ','
        << r.Footprint << "\n";
  }
  return static_cast<bool>(csv);
}

std::string AngleTag(double angle)
{
  std::ostringstream s;
  s << angle;
  std::string t = s.str();
  std::replace(t.begin(), t.end(), '.', 'p');
  return t;
}

// One chart per view angle: every configuration's ms/frame and mean hit error, averaged over the
// maps, one series per method, and the Pareto front.
bool WritePlots(const ReliefSweepSettings& settings, const std::vector<ReliefSweepRow>& rows,
  const std::vector<std::string>& mapLabels, std::ostream& out)
{
  for (double angle : settings.Angles)
  {
    struct Sum
    {
      double Ms = 0.0;
      double Error = 0.0;
      int N = 0;
    };
    std::map<std::pair<int, std::string>, Sum> sums; // (method, step label)
    for (const ReliefSweepRow& r : rows)
    {
      if (r.Angle != angle)
      {
        continue;
      }
      Sum& s = sums[{ r.Method, r.Step.Label }];
      s.Ms += r.MedianMs;
      s.Error += r.HitMeanTexels;
      ++s.N;
    }
    if (sums.empty())
    {
      continue;
    }
    ScatterChart chart;
    std::ostringstream title;
    title << "View " << angle << " deg: speed vs accuracy (" << settings.Width << "x"
          << settings.Height << " px, mean over";
    for (const std::string& m : mapLabels)
    {
      title << " " << m;
    }
    title << ")";
    chart.Title = title.str();
    chart.XLabel = "ms/frame (median)";
    chart.YLabel = "mean hit error (texels, log)";
    chart.LogY = true;
    chart.YFloor = 1e-3;
    std::map<int, size_t> seriesOf;
    std::vector<double> allX, allY;
    for (const auto& entry : sums)
    {
      const int method = entry.first.first;
      if (!seriesOf.count(method))
      {
        seriesOf[method] = chart.Points.size();
        chart.Points.push_back({ vtkReliefMapper::GetMethodName(method), {}, {} });
      }
      ChartSeries& series = chart.Points[seriesOf[method]];
      const double x = entry.second.Ms / entry.second.N;
      const double y = entry.second.Error / entry.second.N;
      series.X.push_back(x);
      series.Y.push_back(y);
      allX.push_back(x);
      allY.push_back(y);
    }
    chart.Line.Name = "Pareto front";
    for (size_t i : ParetoFront(allX, allY))
    {
      chart.Line.X.push_back(allX[i]);
      chart.Line.Y.push_back(allY[i]);
    }
    const std::string file =
      (std::filesystem::path(settings.PlotDirectory) / ("relief-sweep-view" + AngleTag(angle) + ".png"))
        .string();
    std::string error;
    if (!WriteScatterChartPng(chart, file, error))
    {
      out << "bench relief: " << error << "\n";
      return false;
    }
    out << "wrote " << file << "\n";
  }
  return true;
}

// Relaxed cones vs relief at equal mean hit error (issue target: >= 2x). Each relief
// configuration's mean hit error E is a target; for each method take its fastest configuration
// (same map and angle) with mean hit error <= E: both Pareto fronts read at E, the minimum over
// noisy timings taken on both sides alike. Cost is measured twice: llvmpipe ms/frame, and
// relief-texture samples per pixel (what the march costs on any GPU, without llvmpipe's noise and
// fixed per-frame cost). Targets of at most 0.1 texel (sub-texel accurate settings) are also
// reported apart: that is where a renderer that must look right at grazing angles operates.
void PrintConeVersusRelief(const ReliefSweepSettings& settings,
  const std::vector<ReliefSweepRow>& rows, std::ostream& out)
{
  const double accurate = 0.1; // texels
  auto median = [](std::vector<double> v) {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  auto cell = [&median](const std::vector<double>& v) {
    return v.empty() ? std::string("-") : Fixed(median(v), 2) + " (" + std::to_string(v.size()) + ")";
  };
  std::vector<std::string> maps;
  for (const ReliefSweepRow& r : rows)
  {
    if (std::find(maps.begin(), maps.end(), r.Map) == maps.end())
    {
      maps.push_back(r.Map);
    }
  }
  struct Ratios
  {
    std::vector<double> Ms, Samples, AccurateMs, AccurateSamples;
  };
  std::map<double, Ratios> perAngle;
  Ratios all;
  std::ostringstream table;
  bool any = false;
  for (const std::string& map : maps)
  {
    for (const double angle : settings.Angles)
    {
      Ratios here;
      for (const ReliefSweepRow& target : rows)
      {
        if (target.Method != vtkReliefMapper::Relief || target.Angle != angle || target.Map != map)
        {
          continue;
        }
        const ReliefSweepRow* fastest[2] = { nullptr, nullptr }; // relief, relaxed cone
        const ReliefSweepRow* leanest[2] = { nullptr, nullptr };
        for (const ReliefSweepRow& r : rows)
        {
          const int k = r.Method == vtkReliefMapper::Relief ? 0
            : r.Method == vtkReliefMapper::RelaxedConeBinary ? 1
                                                             : -1;
          if (k < 0 || r.Map != map || r.Angle != angle || r.HitMeanTexels > target.HitMeanTexels)
          {
            continue;
          }
          if (!fastest[k] || r.MedianMs < fastest[k]->MedianMs)
          {
            fastest[k] = &r;
          }
          if (!leanest[k] || r.SamplesPerPixel < leanest[k]->SamplesPerPixel)
          {
            leanest[k] = &r;
          }
        }
        if (!fastest[1] || fastest[1]->MedianMs <= 0.0 || leanest[1]->SamplesPerPixel <= 0.0)
        {
          continue;
        }
        const double ms = fastest[0]->MedianMs / fastest[1]->MedianMs;
        const double samples = leanest[0]->SamplesPerPixel / leanest[1]->SamplesPerPixel;
        for (Ratios* into : { &here, &perAngle[angle], &all })
        {
          into->Ms.push_back(ms);
          into->Samples.push_back(samples);
          if (target.HitMeanTexels <= accurate)
          {
            into->AccurateMs.push_back(ms);
            into->AccurateSamples.push_back(samples);
          }
        }
      }
      if (here.Ms.empty())
      {
        continue;
      }
      any = true;
      table << "    " << std::left << std::setw(18) << map << std::right << std::setw(5)
            << Fixed(angle, 0) << std::setw(16) << cell(here.Ms) << std::setw(16)
            << cell(here.Samples) << std::setw(16) << cell(here.AccurateMs) << std::setw(16)
            << cell(here.AccurateSamples) << "\n";
    }
  }
  if (!any)
  {
    out << "- relaxed cones vs relief: skipped (needs relief and relaxed-cone rows; cone maps "
           "unavailable or method not selected)\n";
    return;
  }
  out << "- relaxed cones vs relief at equal mean hit error: relief / relaxed cone, each method's "
         "cheapest setting reaching each relief setting's error; median (number of error "
         "targets), in ms/frame and in relief-texture samples per pixel; 'accurate' = targets <= "
      << accurate << " texel\n"
      << "    " << std::left << std::setw(18) << "map" << std::right << std::setw(5) << "angle"
      << std::setw(16) << "ms" << std::setw(16) << "samples" << std::setw(16) << "accurate ms"
      << std::setw(16) << "accurate samp." << "\n"
      << table.str();
  for (const auto& entry : perAngle)
  {
    out << "    " << std::left << std::setw(18) << "all maps" << std::right << std::setw(5)
        << Fixed(entry.first, 0) << std::setw(16) << cell(entry.second.Ms) << std::setw(16)
        << cell(entry.second.Samples) << std::setw(16) << cell(entry.second.AccurateMs)
        << std::setw(16) << cell(entry.second.AccurateSamples) << "\n";
  }
  out << "    " << std::left << std::setw(18) << "all" << std::right << std::setw(5) << "-"
      << std::setw(16) << cell(all.Ms) << std::setw(16) << cell(all.Samples) << std::setw(16)
      << cell(all.AccurateMs) << std::setw(16) << cell(all.AccurateSamples) << "\n";
}

void PrintSummary(const ReliefSweepSettings& settings, const std::vector<ReliefSweepRow>& rows,
  std::ostream& out)
{
  out << "\nSummary\n";
  PrintConeVersusRelief(settings, rows, out);

  // The exact methods at the most grazing angle.
  double grazing = -1.0;
  for (double a : settings.Angles)
  {
    grazing = std::max(grazing, a);
  }
  if (grazing < 0.0)
  {
    return;
  }
  out << "- mean hit error of the exact methods at " << grazing << " deg"
      << (grazing == 85.0 ? "" : " (85 deg not swept: the most grazing angle instead)") << ":\n";
  bool any = false;
  for (const ReliefSweepRow& r : rows)
  {
    const bool exactRelief = r.Method == vtkReliefMapper::Relief && r.Step.LinearSteps == 32 &&
      r.Step.RefinementSteps == 8;
    if (r.Angle != grazing || !(exactRelief || r.Method == vtkReliefMapper::MaximumMipmap))
    {
      continue;
    }
    any = true;
    out << "    " << std::left << std::setw(16) << r.Map << std::setw(12) << r.MethodName
        << std::setw(9) << r.Step.Label << std::right << " mean " << Fixed(r.HitMeanTexels, 3)
        << " texels, p99 " << Fixed(r.HitP99Texels, 2) << ", " << Fixed(r.MedianMs, 1)
        << " ms/frame\n";
  }
  if (!any)
  {
    out << "    (neither max-mipmap nor relief 32+8 was swept)\n";
  }
}
} // namespace

//------------------------------------------------------------------------------
bool RunReliefSweep(
  const ReliefSweepSettings& settings, std::ostream& out, std::vector<ReliefSweepRow>* rowsOut)
{
  // Methods, in the mapper's order.
  std::vector<int> methods;
  if (settings.Methods.empty())
  {
    for (int m = 0; m < vtkReliefMapper::NumberOfMethods; ++m)
    {
      methods.push_back(m);
    }
  }
  for (const std::string& name : settings.Methods)
  {
    const int m = MethodFromName(name);
    if (m < 0)
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
    MapSource map;
    if (name == "file")
    {
      if (!PrepareFileMap(settings, directory, map, out))
      {
        return false;
      }
    }
    else
    {
      map.Label = name;
      map.Pattern = name;
    }
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
      << std::flush;

  std::vector<ReliefSweepRow> rows;
  std::vector<std::string> skipped;
  for (const MapSource& map : maps)
  {
    ReliefSceneOptions o;
    o.Pattern = map.Pattern.empty() ? "Bricks" : map.Pattern;
    o.DepthFile = map.DepthFile;
    o.Resolution = settings.Resolution;
    o.DepthScale = settings.DepthScale;
    o.Width = settings.Width;
    o.Height = settings.Height;
    o.FillViewport = settings.FillViewport;
    o.SelfShadowing = false;
    std::string error;
    ReliefScene relief, dense;
    if (!BuildReliefScene(o, relief, error) || !BuildDenseReferenceScene(o, dense, error))
    {
      out << "bench relief: map " << map.Label << ": " << error << "\n";
      return false;
    }
    // Cone maps, once per map, for the cone methods requested.
    std::map<int, vtkSmartPointer<vtkImageData>> coneMaps;
    for (int m : methods)
    {
      const int kind = vtkReliefMapper::GetRequiredConeMap(m);
      if (kind == vtkReliefMapper::NoConeMap || coneMaps.count(kind))
      {
        continue;
      }
      std::string why;
      coneMaps[kind] = BuildConeMap(relief.ReliefTexture, kind, o.DepthScale, why);
      if (!coneMaps[kind])
      {
        skipped.push_back(std::string(kind == vtkReliefMapper::RelaxedConeMap ? "relaxed" : "conservative") +
          " cone map for " + map.Label + ": " + why);
      }
    }
    auto reliefWindow = MakeOffscreenWindow(o, relief.Renderer);
    auto denseWindow = MakeOffscreenWindow(o, dense.Renderer);
    vtkReliefMapper* mapper = relief.Mapper;

    for (double angle : settings.Angles)
    {
      o.ViewAngle = angle;
      SetupCameraAndLights(o, relief.Renderer);
      SetupCameraAndLights(o, dense.Renderer);
      const Frame denseFrame = CaptureFrame(denseWindow);
      ReliefReference reference;
      if (!ComputeReliefReference(MakeReliefReferenceInput(relief, o), reference, error))
      {
        out << "bench relief: " << error << "\n";
        return false;
      }
      out << "[" << map.Label << ", " << angle << " deg] CPU reference: "
          << reference.CountCovered() << " covered of " << reference.CountFootprint()
          << " footprint pixels in " << Fixed(reference.Seconds, 3) << " s\n"
          << std::flush;

      for (int m : methods)
      {
        const int kind = vtkReliefMapper::GetRequiredConeMap(m);
        if (kind != vtkReliefMapper::NoConeMap && !coneMaps[kind])
        {
          continue;
        }
        mapper->SetReliefTextureData(
          kind == vtkReliefMapper::NoConeMap ? relief.ReliefTexture.Get() : coneMaps[kind].Get());
        mapper->SetMethod(m);
        std::vector<ReliefSweepStep> steps = ReliefSweepStepsFor(m);
        if (!settings.Steps.empty() && UsesSearchSteps(m))
        {
          steps.clear();
          for (const std::string& label : settings.Steps)
          {
            ReliefSweepStep step;
            ParseStepLabel(label, step);
            steps.push_back(step);
          }
        }
        for (const ReliefSweepStep& step : steps)
        {
          ReliefSweepRow row;
          row.Map = map.Label;
          row.Angle = angle;
          row.Method = m;
          row.MethodName = vtkReliefMapper::GetMethodName(m);
          row.Step = step;
          mapper->SetLinearSteps(step.LinearSteps);
          mapper->SetRefinementSteps(step.RefinementSteps);

          // Shaded, no self-shadowing: timing and colour against the dense mesh.
          mapper->SetSelfShadowing(false);
          mapper->SetOutput(vtkReliefMapper::ShadedOutput);
          row.MedianMs = TimeFrames(reliefWindow, settings.Frames, row.FirstMs);
          const Frame shaded = CaptureFrame(reliefWindow);
          row.ColorRmse = ColorRmse(reference, shaded, denseFrame);
          row.Psnr = row.ColorRmse > 0.0 ? 20.0 * std::log10(255.0 / row.ColorRmse) : 99.0;

          // What the march sampled, per covered pixel of the same (shadowless) frame.
          mapper->SetOutput(vtkReliefMapper::SampleCountOutput);
          row.SamplesPerPixel = MeanSampleCount(CaptureFrame(reliefWindow));

          // Hit coordinates against the CPU reference.
          mapper->SetOutput(vtkReliefMapper::HitUOutput);
          const Frame hitU = CaptureFrame(reliefWindow);
          mapper->SetOutput(vtkReliefMapper::HitVOutput);
          const Frame hitV = CaptureFrame(reliefWindow);
          const HitComparison hits = CompareHits(reference, hitU, hitV);
          row.HitMeanTexels = hits.MeanTexels;
          row.HitP99Texels = hits.P99Texels;
          row.SilhouetteMismatch = hits.SilhouetteMismatch;
          row.CoveredBoth = hits.CoveredBoth;
          row.Footprint = hits.Footprint;

          // First-light visibility with self-shadowing on.
          mapper->SetSelfShadowing(true);
          mapper->SetOutput(vtkReliefMapper::LightVisibilityOutput);
          const Frame visibility = CaptureFrame(reliefWindow);
          row.ShadowMismatch = CompareLightVisibility(reference, visibility);
          mapper->SetSelfShadowing(false);
          mapper->SetOutput(vtkReliefMapper::ShadedOutput);

          rows.push_back(row);
        }
      }
      out << "[" << map.Label << ", " << angle << " deg] done, " << rows.size()
          << " configurations so far\n"
          << std::flush;
    }
    mapper->SetReliefTextureData(relief.ReliefTexture);
  }

  out << "\n";
  PrintHeader(out);
  for (const ReliefSweepRow& r : rows)
  {
    PrintRow(out, r);
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
    if (WriteCsv(settings.CsvFile, rows, settings))
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
    ok = WritePlots(settings, rows, labels, out) && ok;
  }
  PrintSummary(settings, rows, out);
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
  CommandLine cl;
  cl.AddValue("--maps", "LIST",
    "comma-separated maps: procedural patterns (Bricks, Stone, HemisphereTorus, ...) and 'file'",
    "Bricks,Stone,HemisphereTorus,file");
  cl.AddValue("--depth-file", "IMAGE",
    "depth image of the 'file' map (default: the Stone pattern written as 16-bit PNG)");
  cl.AddValue("--angles", "LIST", "view angles from the wall normal, degrees", "0,45,70,80,85");
  cl.AddValue("--size", "WxH", "window size in pixels", "512x512");
  cl.AddValue("--frames", "N", "timed frames per configuration, after a warm-up frame", "5");
  cl.AddValue("--methods", "all|LIST", "vtkReliefMapper method names", "all");
  cl.AddValue("--resolution", "N", "texels per side of the procedural maps", "512");
  cl.AddValue("--depth-scale", "K", "world depth of depth 1 / wall width", "0.04");
  cl.AddValue("--steps", "L+R,..",
    "step settings for the linear/cone-search methods instead of the built-in table");
  cl.AddValue("--csv", "FILE", "write one CSV row per configuration");
  cl.AddValue("--plots", "DIR", "write one PNG chart per view angle into DIR");
  cl.AddFlag("--no-fill",
    "keep the square, whole-wall framing (the wall is then a thin strip at grazing angles) "
    "instead of stretching the view so the wall fills the window");
  cl.AddFlag("--help", "show this help");
  std::string error;
  if (!cl.Parse(args, error))
  {
    std::cerr << "mesolight bench relief: " << error << "\n";
    return 2;
  }
  if (cl.Has("--help"))
  {
    std::cout << "Usage: mesolight bench relief [options]\n"
                 "Accuracy and speed of every relief method per map, view angle and step setting,\n"
                 "against the exact CPU reference and the dense displaced mesh.\n\nOptions:\n";
    cl.PrintOptions(std::cout);
    return 0;
  }
  if (!cl.Positional().empty())
  {
    std::cerr << "mesolight bench relief: unexpected argument '" << cl.Positional()[0] << "'\n";
    return 2;
  }
  settings.Maps = SplitList(cl.Get("--maps"));
  settings.FillViewport = !cl.Has("--no-fill");
  settings.DepthFile = cl.Get("--depth-file");
  settings.Angles.clear();
  for (const std::string& a : SplitList(cl.Get("--angles")))
  {
    char* end = nullptr;
    const double angle = std::strtod(a.c_str(), &end);
    if (end == a.c_str() || *end != '\0' || !(angle >= 0.0 && angle < 90.0))
    {
      std::cerr << "mesolight bench relief: --angles: '" << a << "' is not an angle in [0, 90)\n";
      return 2;
    }
    settings.Angles.push_back(angle);
  }
  const std::string size = cl.Get("--size");
  const size_t x = size.find('x');
  char* end1 = nullptr;
  char* end2 = nullptr;
  const long w = x == std::string::npos ? 0 : std::strtol(size.c_str(), &end1, 10);
  const long h = x == std::string::npos ? 0 : std::strtol(size.c_str() + x + 1, &end2, 10);
  if (x == std::string::npos || end1 != size.c_str() + x || *end2 != '\0' || w < 16 || h < 16 ||
    w > 8192 || h > 8192)
  {
    std::cerr << "mesolight bench relief: --size: '" << size << "' is not WxH (16 to 8192)\n";
    return 2;
  }
  settings.Width = int(w);
  settings.Height = int(h);
  if (!cl.GetInt("--frames", 1, 1000, settings.Frames, error) ||
    !cl.GetInt("--resolution", 2, 8192, settings.Resolution, error) ||
    !cl.GetDouble("--depth-scale", 1e-4, 10.0, settings.DepthScale, error))
  {
    std::cerr << "mesolight bench relief: " << error << "\n";
    return 2;
  }
  const std::string methods = cl.Get("--methods");
  if (methods != "all")
  {
    settings.Methods = SplitList(methods);
    for (const std::string& name : settings.Methods)
    {
      if (MethodFromName(name) < 0)
      {
        std::cerr << "mesolight bench relief: unknown method '" << name << "' (names:";
        for (int m = 0; m < vtkReliefMapper::NumberOfMethods; ++m)
        {
          std::cerr << " " << vtkReliefMapper::GetMethodName(m);
        }
        std::cerr << ")\n";
        return 2;
      }
    }
  }
  if (settings.Maps.empty() || settings.Angles.empty())
  {
    std::cerr << "mesolight bench relief: --maps and --angles need at least one entry\n";
    return 2;
  }
  settings.Steps = SplitList(cl.Get("--steps"));
  for (const std::string& label : settings.Steps)
  {
    ReliefSweepStep step;
    if (!ParseStepLabel(label, step))
    {
      std::cerr << "mesolight bench relief: --steps: '" << label << "' is not L+R\n";
      return 2;
    }
  }
  settings.CsvFile = cl.Get("--csv");
  settings.PlotDirectory = cl.Get("--plots");
  return RunReliefSweep(settings, std::cout) ? 0 : 1;
}

} // namespace mesolight
