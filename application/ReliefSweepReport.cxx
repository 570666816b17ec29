// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefSweepReport.h"

#include "ChartPlot.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <algorithm>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <map>
#include <sstream>

namespace mesolight
{
namespace report
{
std::string Fixed(double value, int precision)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(precision) << value;
  return s.str();
}

void PrintHeader(std::ostream& out)
{
  out << std::left << std::setw(16) << "map" << std::right << std::setw(6) << "angle"
      << "  " << std::left << std::setw(22) << "method" << std::setw(9) << "steps" << std::right
      << std::setw(9) << "ms/frame" << std::setw(9) << "samples" << std::setw(10) << "hit mean"
      << std::setw(9) << "hit p99" << std::setw(8) << "silh %" << std::setw(8) << "RMSE"
      << std::setw(7) << "PSNR" << std::setw(9) << "shadow %" << std::setw(9) << "GPU MB"
      << std::setw(10) << "warp smp"
      << "\n";
}

void PrintRow(std::ostream& out, const ReliefSweepRow& r)
{
  out << std::left << std::setw(16) << r.Map << std::right << std::setw(6) << Fixed(r.Angle, 0)
      << "  " << std::left << std::setw(22) << r.MethodName << std::setw(9) << r.Step.Label
      << std::right << std::setw(9) << Fixed(r.MedianMs, 1) << std::setw(9)
      << Fixed(r.SamplesPerPixel, 1) << std::setw(10) << Fixed(r.HitMeanTexels, 3) << std::setw(9)
      << Fixed(r.HitP99Texels, 2) << std::setw(8) << Fixed(r.SilhouetteMismatch, 2) << std::setw(8)
      << (r.ColorRmse < 0.0 ? std::string("-") : Fixed(r.ColorRmse, 2)) << std::setw(7)
      << (r.ColorRmse < 0.0 ? std::string("-") : Fixed(r.Psnr, 1)) << std::setw(9)
      << Fixed(r.ShadowMismatch, 2) << std::setw(9) << Fixed(r.GpuMegaBytes, 2) << std::setw(10)
      << Fixed(r.LockStepSamplesPerPixel, 1) << "\n";
}

bool WriteCsv(const std::string& file, const std::vector<ReliefSweepRow>& rows,
  const ReliefSweepSettings& settings)
{
  std::ofstream csv(file);
  csv << "map,view_angle_deg,method,linear_steps,refinement_steps,steps,width,height,depth_scale,"
         "ms_per_frame,first_frame_ms,samples_per_pixel,hit_error_mean_texels,hit_error_p99_texels,"
         "silhouette_mismatch_pct,color_rmse,psnr_db,shadow_mismatch_pct,covered_both,"
         "footprint,texture_storage,gpu_megabytes,dense_mesh_megabytes,lockstep_samples_per_pixel,"
         "exact_floor_samples_per_pixel,exact_floor_lockstep_samples_per_pixel,"
         "oracle_stored_levels_samples_per_pixel,oracle_stored_levels_lockstep_samples_per_pixel,"
         "oracle_all_levels_samples_per_pixel,oracle_all_levels_lockstep_samples_per_pixel\n";
  csv << std::setprecision(8);
  for (const ReliefSweepRow& r : rows)
  {
    csv << '"' << r.Map << "\"," << r.Angle << ',' << r.MethodName << ',' << r.Step.LinearSteps
        << ',' << r.Step.RefinementSteps << ",\"" << r.Step.Label << "\"," << settings.Width << ','
        << settings.Height << ',' << settings.DepthScale << ',' << r.MedianMs << ',' << r.FirstMs
        << ',' << r.SamplesPerPixel << ',' << r.HitMeanTexels << ',' << r.HitP99Texels << ','
        << r.SilhouetteMismatch << ',' << r.ColorRmse << ',' << r.Psnr << ',' << r.ShadowMismatch
        << ',' << r.CoveredBoth << ',' << r.Footprint << ','
        << (r.FloatTextures ? "float" : "compact") << ',' << r.GpuMegaBytes << ','
        << r.DenseMegaBytes << ',' << r.LockStepSamplesPerPixel << ',' << r.Floor.Mean << ','
        << r.Floor.LockStep << ',' << r.OracleStoredLevels.Mean << ','
        << r.OracleStoredLevels.LockStep << ',' << r.OracleAllLevels.Mean << ','
        << r.OracleAllLevels.LockStep << "\n";
  }
  return static_cast<bool>(csv);
}

namespace
{
// Rows of a storage other than the default (compact): compared apart, in PrintStorage.
bool OtherStorage(const ReliefSweepRow& r)
{
  return r.FloatTextures;
}

std::string AngleTag(double angle)
{
  std::ostringstream s;
  s << angle;
  std::string t = s.str();
  std::replace(t.begin(), t.end(), '.', 'p');
  return t;
}
} // namespace

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
        chart.Points.push_back({ vtkReliefProperty::GetMethodName(method), {}, {} });
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
    const std::string file = (std::filesystem::path(settings.PlotDirectory) /
      ("relief-sweep-view" + AngleTag(angle) + ".png"))
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

namespace
{
// Relaxed cones vs relief at equal mean hit error (the goal: >= 2x faster). Each relief
// configuration's mean hit error E is a target; for each method take its fastest configuration
// (same map and angle) with mean hit error <= E: both Pareto fronts read at E, the minimum over
// noisy timings taken on both sides alike. Cost is measured twice: llvmpipe ms/frame, and
// relief-texture samples per pixel (what the march costs on any GPU, without llvmpipe's noise and
// fixed per-frame cost). Targets of at most 0.1 texel (sub-texel accurate settings) are also
// reported apart: that is where a renderer that must look right at grazing angles operates.
void PrintConeVersusRelief(
  const ReliefSweepSettings& settings, const std::vector<ReliefSweepRow>& rows, std::ostream& out)
{
  const double accurate = 0.1; // texels
  auto median = [](std::vector<double> v)
  {
    std::sort(v.begin(), v.end());
    return v.empty() ? 0.0 : v[v.size() / 2];
  };
  auto cell = [&median](const std::vector<double>& v)
  {
    return v.empty() ? std::string("-")
                     : Fixed(median(v), 2) + " (" + std::to_string(v.size()) + ")";
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
        if (target.IsDefault || OtherStorage(target) ||
          target.Method != vtkReliefProperty::Relief || target.Angle != angle || target.Map != map)
        {
          continue;
        }
        const ReliefSweepRow* fastest[2] = { nullptr, nullptr }; // relief, relaxed cone
        const ReliefSweepRow* leanest[2] = { nullptr, nullptr };
        for (const ReliefSweepRow& r : rows)
        {
          const int k = r.Method == vtkReliefProperty::Relief  ? 0
            : r.Method == vtkReliefProperty::RelaxedConeBinary ? 1
                                                               : -1;
          if (k < 0 || r.IsDefault || OtherStorage(r) || r.Map != map || r.Angle != angle ||
            r.HitMeanTexels > target.HitMeanTexels)
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
      << std::setw(16) << "accurate samp."
      << "\n"
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

// The untouched defaults per map and angle: the accuracy goal (mean <= 0.25 texel, p99 <= 1
// texel against the exact reference), the cost against relief 32+8 of the same run, and the
// default's place on the time-vs-error front of every other row of that map and angle.
void PrintDefaultPlace(const std::vector<ReliefSweepRow>& rows, std::ostream& out)
{
  const double goalMean = 0.25, goalP99 = 1.0;
  bool any = false;
  std::ostringstream table;
  int met = 0, cheap = 0, cheapLockStep = 0, front = 0, cells = 0;
  int floorAbove = 0, oracleStoredAbove = 0, oracleAllAbove = 0;
  for (const ReliefSweepRow& d : rows)
  {
    if (!d.IsDefault || OtherStorage(d))
    {
      continue;
    }
    any = true;
    ++cells;
    const ReliefSweepRow* relief = nullptr;
    int dominating = 0, dominatingSamples = 0;
    const ReliefSweepRow* best = nullptr; // the fastest row at least as accurate
    for (const ReliefSweepRow& r : rows)
    {
      if (r.IsDefault || OtherStorage(r) || r.Map != d.Map || r.Angle != d.Angle)
      {
        continue;
      }
      if (r.Method == vtkReliefProperty::Relief && r.Step.LinearSteps == 32 &&
        r.Step.RefinementSteps == 8)
      {
        relief = &r;
      }
      const bool noWorse = r.HitMeanTexels <= d.HitMeanTexels;
      const bool better = r.HitMeanTexels < d.HitMeanTexels;
      if (noWorse && r.MedianMs <= d.MedianMs && (better || r.MedianMs < d.MedianMs))
      {
        ++dominating;
      }
      if (noWorse && r.SamplesPerPixel <= d.SamplesPerPixel &&
        (better || r.SamplesPerPixel < d.SamplesPerPixel))
      {
        ++dominatingSamples;
      }
      if (noWorse && (!best || r.MedianMs < best->MedianMs))
      {
        best = &r;
      }
    }
    const bool accurate = d.HitMeanTexels <= goalMean && d.HitP99Texels <= goalP99;
    const bool costs =
      relief && d.MedianMs <= relief->MedianMs && d.SamplesPerPixel <= relief->SamplesPerPixel;
    met += accurate ? 1 : 0;
    cheap += costs ? 1 : 0;
    cheapLockStep += relief && d.LockStepSamplesPerPixel <= relief->LockStepSamplesPerPixel ? 1 : 0;
    // Lock-step counts of exact bound traversals above relief 32+8's: no such traversal (of that
    // data) can meet its cost in lock step.
    const auto above = [relief](const ExactTraversalCounts& c)
    { return relief && c.LockStep > relief->LockStepSamplesPerPixel ? 1 : 0; };
    floorAbove += above(d.Floor);
    oracleStoredAbove += above(d.OracleStoredLevels);
    oracleAllAbove += above(d.OracleAllLevels);
    const auto ratio = [relief](double lockStep)
    {
      return relief && relief->LockStepSamplesPerPixel > 0.0
        ? Fixed(lockStep / relief->LockStepSamplesPerPixel, 2)
        : std::string("-");
    };
    front += dominating == 0 ? 1 : 0;
    table << "    " << std::left << std::setw(22) << d.Map << std::right << std::setw(5)
          << Fixed(d.Angle, 0) << std::setw(9) << Fixed(d.HitMeanTexels, 3) << std::setw(8)
          << Fixed(d.HitP99Texels, 2) << std::setw(6) << (accurate ? "yes" : "no") << std::setw(9)
          << (relief ? Fixed(d.MedianMs / relief->MedianMs, 2) : std::string("-")) << std::setw(9)
          << (relief && relief->SamplesPerPixel > 0.0
                 ? Fixed(d.SamplesPerPixel / relief->SamplesPerPixel, 2)
                 : std::string("-"))
          << std::setw(9)
          << (relief && relief->LockStepSamplesPerPixel > 0.0
                 ? Fixed(d.LockStepSamplesPerPixel / relief->LockStepSamplesPerPixel, 2)
                 : std::string("-"))
          << std::setw(11) << ratio(d.Floor.LockStep) << std::setw(11)
          << ratio(d.OracleStoredLevels.LockStep) << std::setw(11)
          << ratio(d.OracleAllLevels.LockStep) << "   "
          << (dominating == 0 ? std::string("on the front")
                              : "behind " + std::to_string(dominating) + " rows")
          << (dominatingSamples == 0
                 ? ", on the samples front"
                 : ", behind " + std::to_string(dominatingSamples) + " in samples")
          << (best && dominating > 0 ? " (fastest as accurate: " + best->MethodName + " " +
                   best->Step.Label + ", " + Fixed(best->MedianMs, 1) + " ms)"
                                     : std::string())
          << "\n";
  }
  if (!any)
  {
    return;
  }
  const ReliefSweepRow* first = nullptr;
  for (const ReliefSweepRow& r : rows)
  {
    if (r.IsDefault && !OtherStorage(r))
    {
      first = &r;
      break;
    }
  }
  out << "- the default (" << first->Step.Label << ") per map and angle: goal mean <= " << goalMean
      << " and p99 <= " << goalP99
      << " texel; cost as a ratio to relief 32+8 of the same run (ms/frame, samples per pixel); "
         "place on the time-vs-mean-error front of the other rows ('behind N': N rows are at "
         "least as accurate and at least as fast)\n"
      << "    " << std::left << std::setw(22) << "map" << std::right << std::setw(5) << "angle"
      << std::setw(9) << "mean" << std::setw(8) << "p99" << std::setw(6) << "goal" << std::setw(9)
      << "ms/rel" << std::setw(9) << "smp/rel" << std::setw(9) << "warp/rel" << std::setw(11)
      << "floor/rel" << std::setw(11) << "oracle/rel" << std::setw(11) << "full/rel"
      << "   front\n"
      << table.str() << "    accuracy goal met in " << met << " of " << cells
      << ", at most relief 32+8's ms and samples in " << cheap << " of " << cells
      << ", at most its warp samples in " << cheapLockStep << " of " << cells
      << ", on the time front in " << front << " of " << cells << "\n"
      << "    warp samples of exact traversals of per-cell depth bounds over relief 32+8's: "
         "floor/rel, the cells whose bound the exact ray reaches (above 1 in "
      << floorAbove << " of " << cells
      << "); oracle/rel, a traversal told the right level at every step over the stored "
         "pyramid (above 1 in "
      << oracleStoredAbove << " of " << cells
      << "); full/rel, the same over every level (above 1 in " << oracleAllAbove << " of " << cells
      << ")\n";
}
} // namespace

namespace
{
// GPU memory per method and map: the relief's textures against the dense displaced mesh, and,
// with float rows in the run, compact against float storage in memory and in hit error (the
// same map, angle and steps, so the difference is the storage's alone).
void PrintStorage(const std::vector<ReliefSweepRow>& rows, std::ostream& out)
{
  struct Entry
  {
    std::string Map, Method;
    double Dense = 0.0, Compact = 0.0, Float = 0.0;
    double CompactMean = 0.0, FloatMean = 0.0, CompactP99 = 0.0, FloatP99 = 0.0;
    double CompactRmse = 0.0, FloatRmse = 0.0;
    int Pairs = 0;
  };
  std::vector<Entry> entries;
  auto entryOf = [&entries](const ReliefSweepRow& r) -> Entry&
  {
    const std::string method = r.IsDefault ? "default" : vtkReliefProperty::GetMethodName(r.Method);
    for (Entry& e : entries)
    {
      if (e.Map == r.Map && e.Method == method)
      {
        return e;
      }
    }
    entries.push_back({ r.Map, method });
    return entries.back();
  };
  for (const ReliefSweepRow& r : rows)
  {
    Entry& e = entryOf(r);
    e.Dense = r.DenseMegaBytes;
    double& mb = r.FloatTextures ? e.Float : e.Compact;
    mb = std::max(mb, r.GpuMegaBytes);
    if (OtherStorage(r))
    {
      continue;
    }
    for (const ReliefSweepRow& f : rows)
    {
      const bool paired = f.Map == r.Map && f.Angle == r.Angle && f.Method == r.Method &&
        f.IsDefault == r.IsDefault && f.Step.Label == r.Step.Label;
      if (paired && f.FloatTextures)
      {
        e.CompactMean += r.HitMeanTexels;
        e.FloatMean += f.HitMeanTexels;
        e.CompactP99 += r.HitP99Texels;
        e.FloatP99 += f.HitP99Texels;
        e.CompactRmse += r.ColorRmse;
        e.FloatRmse += f.ColorRmse;
        ++e.Pairs;
      }
    }
  }
  if (entries.empty())
  {
    return;
  }
  out << "- GPU memory: the relief's textures (largest over the method's rows) against the dense "
         "displaced mesh (32 B/vertex + 12 B/triangle); with float rows, compact vs float "
         "storage at equal settings: hit error mean and p99 (texels) and colour RMSE, averaged "
         "over the paired rows\n"
      << "    " << std::left << std::setw(18) << "map" << std::setw(14) << "method" << std::right
      << std::setw(9) << "dense MB" << std::setw(11) << "compact MB" << std::setw(10) << "dense/cmp"
      << std::setw(10) << "float MB" << std::setw(10) << "float/cmp" << std::setw(16)
      << "mean cmp/float" << std::setw(16) << "p99 cmp/float" << std::setw(16) << "RMSE cmp/float"
      << "\n";
  for (const Entry& e : entries)
  {
    auto ratio = [](double a, double b)
    { return a > 0.0 && b > 0.0 ? Fixed(a / b, 1) + "x" : std::string("-"); };
    auto pair = [&e](double a, double b, int precision)
    {
      return e.Pairs > 0 ? Fixed(a / e.Pairs, precision) + "/" + Fixed(b / e.Pairs, precision)
                         : std::string("-");
    };
    out << "    " << std::left << std::setw(18) << e.Map << std::setw(14) << e.Method << std::right
        << std::setw(9) << Fixed(e.Dense, 1) << std::setw(11)
        << (e.Compact > 0.0 ? Fixed(e.Compact, 2) : std::string("-")) << std::setw(10)
        << ratio(e.Dense, e.Compact) << std::setw(10)
        << (e.Float > 0.0 ? Fixed(e.Float, 2) : std::string("-")) << std::setw(10)
        << ratio(e.Float, e.Compact) << std::setw(16) << pair(e.CompactMean, e.FloatMean, 3)
        << std::setw(16) << pair(e.CompactP99, e.FloatP99, 2) << std::setw(16)
        << (e.CompactRmse >= 0.0 ? pair(e.CompactRmse, e.FloatRmse, 2) : std::string("-")) << "\n";
  }
}
} // namespace

void PrintSummary(
  const ReliefSweepSettings& settings, const std::vector<ReliefSweepRow>& rows, std::ostream& out)
{
  out << "\nSummary\n";
  PrintStorage(rows, out);
  PrintDefaultPlace(rows, out);
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
    const bool exactRelief = r.Method == vtkReliefProperty::Relief && r.Step.LinearSteps == 32 &&
      r.Step.RefinementSteps == 8;
    if (r.Angle != grazing || OtherStorage(r) ||
      !(r.IsDefault || exactRelief || r.Method == vtkReliefProperty::MaximumMipmap))
    {
      continue;
    }
    any = true;
    out << "    " << std::left << std::setw(22) << r.Map << " " << std::setw(12) << r.MethodName
        << std::setw(9) << r.Step.Label << std::right << " mean " << Fixed(r.HitMeanTexels, 3)
        << " texels, p99 " << Fixed(r.HitP99Texels, 2) << ", " << Fixed(r.MedianMs, 1)
        << " ms/frame\n";
  }
  if (!any)
  {
    out << "    (neither max-mipmap nor relief 32+8 was swept)\n";
  }
}

} // namespace report
} // namespace mesolight
