// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench cones` (see ConeBenchmark.h).
#include "ConeBenchmark.h"

#include "CommandLine.h"
#include "ConeMaps.h"
#include "HeightFieldTracer.h"
#include "OutputFile.h"
#include "ProceduralHeightFields.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <ctime>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <thread>

namespace mesolight
{
namespace
{
using Clock = std::chrono::steady_clock;

double Seconds(Clock::time_point a, Clock::time_point b)
{
  return std::chrono::duration<double>(b - a).count();
}

bool PatternByName(const std::string& name, ReliefPattern& pattern)
{
  const std::pair<const char*, ReliefPattern> names[] = { { "Bricks", ReliefPattern::Bricks },
    { "Stone", ReliefPattern::Stone }, { "HemisphereTorus", ReliefPattern::HemisphereTorus },
    { "SineWave", ReliefPattern::SineWave } };
  for (const auto& n : names)
  {
    if (name == n.first)
    {
      pattern = n.second;
      return true;
    }
  }
  return false;
}

std::vector<float> MakeMap(ReliefPattern pattern, int n)
{
  HeightFieldParameters params;
  params.Pattern = pattern;
  params.SineFrequency[0] = 3;
  params.SineFrequency[1] = 2;
  std::vector<float> depth(static_cast<size_t>(n) * n);
  GenerateHeightField(params, n, n, depth.data(), nullptr);
  return depth;
}

double Quantile(std::vector<double> v, double q)
{
  if (v.empty())
  {
    return 0.0;
  }
  std::sort(v.begin(), v.end());
  return v[std::min(v.size() - 1, static_cast<size_t>(q * static_cast<double>(v.size())))];
}

// The shader's searches on the CPU (vtkReliefMarchFS.glsl: mlLinearSearch, mlConeSearch,
// mlBinaryRefine), for a view ray entering at origin (depth 0) with span (rate * dir, 1).
struct Bracket
{
  double Above = 0.0;
  double Below = 1.0;
  int ConeBeatFloor = 0; // cone steps longer than the even share of the rest
  int Steps = 0;
};

Bracket LinearSearch(const HeightField& hf, const glm::dvec3& o, const glm::dvec3& span, int steps)
{
  Bracket b;
  const double dt = 1.0 / steps;
  for (int i = 1; i <= steps; ++i)
  {
    const double t = i * dt;
    const glm::dvec3 p = o + t * span;
    if (p.z - hf.DepthAt(p.x, p.y) >= 0.0)
    {
      b.Below = t;
      return b;
    }
    b.Above = t;
  }
  return b;
}

Bracket ConeSearch(const HeightField& hf, const HeightField& cones, const glm::dvec3& o,
  const glm::dvec3& span, double rate, int steps, bool floor)
{
  Bracket b;
  double t = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    const glm::dvec3 p = o + t * span;
    const double depth = hf.DepthAt(p.x, p.y);
    if (p.z >= depth)
    {
      b.Below = t;
      return b;
    }
    const double c = cones.DepthAt(p.x, p.y);
    const double coneStep = c * (depth - p.z) / (rate + c);
    const double share = (1.0 - t) / (steps - i);
    b.ConeBeatFloor += coneStep > share ? 1 : 0;
    ++b.Steps;
    b.Above = t;
    t = std::min(t + (floor ? std::max(coneStep, share) : coneStep), 1.0);
  }
  b.Below = t;
  return b;
}

double BinaryRefine(
  const HeightField& hf, const glm::dvec3& o, const glm::dvec3& span, Bracket b, int steps)
{
  for (int i = 0; i < steps; ++i)
  {
    const double tm = 0.5 * (b.Above + b.Below);
    const glm::dvec3 p = o + tm * span;
    (p.z - hf.DepthAt(p.x, p.y) >= 0.0 ? b.Below : b.Above) = tm;
  }
  return 0.5 * (b.Above + b.Below);
}

// Hit error in texels of the shader's relief (linear + binary) and relaxed cone (+ binary)
// searches against the exact first hit, per search step count, on the CPU: what each step buys,
// without llvmpipe's timing noise or fixed per-frame cost.
void SteppingAnalysis(const std::vector<ReliefPattern>& patterns,
  const std::vector<std::string>& names, int n, double depthScale, int rays, int threads,
  std::ostream& out)
{
  const int stepCounts[] = { 2, 3, 4, 6, 8, 12, 16, 24, 32, 48, 64 };
  const int refine = 6;
  out << "\nSearch steps vs hit error on the CPU (" << n << "^2 maps, depth scale " << depthScale
      << ", " << rays << " random view rays per map and angle, " << refine
      << " binary steps after each search; error = horizontal distance to the exact first hit in "
         "texels).\nlin = relief's linear search; cone = relaxed cone search with the shader's "
         "even-share floor (bilinear-safe cones); cone/sample = the same with per-texel-sample "
         "cones (not bilinear-safe); beat = % of cone steps longer than the floor.\n";
  for (size_t mi = 0; mi < patterns.size(); ++mi)
  {
    const std::vector<float> depth = MakeMap(patterns[mi], n);
    ConeMapOptions safe;
    safe.Threads = threads;
    ConeMapOptions samples = safe;
    samples.BilinearSafe = false;
    const HeightField hf(n, n, depth);
    const HeightField cones(n, n, ComputeRelaxedConeMap(depth.data(), n, n, safe));
    const HeightField sampleCones(n, n, ComputeRelaxedConeMap(depth.data(), n, n, samples));
    for (double angle : { 45.0, 70.0, 80.0, 85.0 })
    {
      const double rate = depthScale * std::tan(angle * M_PI / 180.0); // widths per unit depth
      std::mt19937 rng(17);
      std::uniform_real_distribution<double> uni(0.0, 1.0);
      const size_t k = sizeof(stepCounts) / sizeof(stepCounts[0]);
      std::vector<double> lin(k, 0.0), cone(k, 0.0), sample(k, 0.0), beat(k, 0.0), tried(k, 0.0);
      int counted = 0;
      for (int r = 0; r < rays; ++r)
      {
        const double phi = 2.0 * M_PI * uni(rng);
        const glm::dvec3 o(0.1 + 0.8 * uni(rng), 0.1 + 0.8 * uni(rng), 0.0);
        const glm::dvec3 span(rate * std::cos(phi), rate * std::sin(phi), 1.0);
        const auto hit = IntersectFirst(hf, o, span, 1.0);
        if (!hit)
        {
          continue;
        }
        ++counted;
        const double toTexels = rate * n;
        for (size_t s = 0; s < k; ++s)
        {
          const int steps = stepCounts[s];
          lin[s] +=
            std::abs(BinaryRefine(hf, o, span, LinearSearch(hf, o, span, steps), refine) - hit->t) *
            toTexels;
          const Bracket b = ConeSearch(hf, cones, o, span, rate, steps, true);
          cone[s] += std::abs(BinaryRefine(hf, o, span, b, refine) - hit->t) * toTexels;
          beat[s] += b.ConeBeatFloor;
          tried[s] += b.Steps;
          sample[s] += std::abs(BinaryRefine(hf, o, span,
                                  ConeSearch(hf, sampleCones, o, span, rate, steps, true), refine) -
                         hit->t) *
            toTexels;
        }
      }
      out << "\n"
          << names[mi] << ", " << angle << " deg: mean hit error (texels) per search steps\n"
          << std::setw(8) << "steps" << std::setw(10) << "lin" << std::setw(10) << "cone"
          << std::setw(13) << "cone/sample" << std::setw(8) << "beat"
          << "\n";
      for (size_t s = 0; s < k; ++s)
      {
        out << std::setw(8) << stepCounts[s] << std::setprecision(3) << std::setw(10)
            << lin[s] / counted << std::setw(10) << cone[s] / counted << std::setw(13)
            << sample[s] / counted << std::setw(7) << std::setprecision(1)
            << (tried[s] > 0 ? 100.0 * beat[s] / tried[s] : 0.0) << "%\n";
      }
      // Equal error: for each linear step count, the fewest cone steps with no larger error.
      out << "  fewest cone steps reaching the linear search's error:";
      for (size_t s = 0; s < k; ++s)
      {
        size_t c = 0;
        while (c < k && cone[c] > lin[s])
        {
          ++c;
        }
        out << " " << stepCounts[s] << "->" << (c < k ? std::to_string(stepCounts[c]) : "-");
      }
      out << "\n" << std::flush;
    }
  }
}
} // namespace

int RunConeBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench cones",
    "mesolight bench cones [options]\n\nTimes the bilinear-safe cone-map generators "
    "(relaxed and conservative) per map and size,\nthe brute-force oracle on a small "
    "map (extrapolated by its O(cells^2) cost), and compares\nthe cone widths with "
    "per-texel-sample cones.\n");
  cl.AddValue("--maps", "A,B,..", "procedural maps: Bricks, Stone, HemisphereTorus, SineWave",
    "Bricks,Stone,HemisphereTorus");
  cl.AddValue("--sizes", "N,N,..", "map sizes (N x N texels) timed with the fast generators",
    "256,1024,4096");
  cl.AddValue("--threads", "N", "threads of the fast generators", "2");
  cl.AddValue("--oracle-size", "N", "map size the brute-force oracle is timed on (1 thread)", "48");
  cl.AddValue("--compare-size", "N",
    "map size for the width comparison with per-texel-sample cones (0: skip)", "128");
  cl.AddValue("--tolerance", "T", "relative tolerance of the fast search (ConeMapOptions)",
    std::to_string(ConeMapOptions().Tolerance));
  cl.AddValue("--stepping-size", "N",
    "map size of the CPU search-steps vs hit-error analysis (0: skip)", "256");
  cl.AddValue("--stepping-rays", "N", "rays per map and angle of that analysis", "20000");
  cl.AddValue("--depth-scale", "K", "depth scale of that analysis (as in bench relief)", "0.04");
  cl.AddValue("--csv", "FILE", "write one CSV row per map, size and cone type");
  std::string error;
  int threads = 2;
  int oracleSize = 48;
  int compareSize = 128;
  double tolerance = ConeMapOptions().Tolerance;
  int steppingSize = 256;
  int steppingRays = 20000;
  double depthScale = 0.04;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv" }, {}); !problem.empty())
  {
    return cl.UsageError(problem);
  }
  if (!cl.GetInt("--threads", 1, 256, threads, error) ||
    !cl.GetInt("--oracle-size", 2, 512, oracleSize, error) ||
    !cl.GetInt("--compare-size", 0, 2048, compareSize, error) ||
    !cl.GetDouble("--tolerance", 0.0, 10.0, tolerance, error) ||
    !cl.GetInt("--stepping-size", 0, 4096, steppingSize, error) ||
    !cl.GetInt("--stepping-rays", 1, 10000000, steppingRays, error) ||
    !cl.GetDouble("--depth-scale", 1e-4, 10.0, depthScale, error))
  {
    return cl.UsageError(error);
  }
  std::vector<ReliefPattern> patterns;
  const std::vector<std::string> mapNames = cl.GetStringList("--maps");
  for (const std::string& name : mapNames)
  {
    ReliefPattern p;
    if (!PatternByName(name, p))
    {
      std::cerr << "mesolight bench cones: unknown map '" << name << "'\n";
      return 2;
    }
    patterns.push_back(p);
  }
  std::vector<int> sizes;
  if (!cl.GetIntList("--sizes", 2, 8192, sizes, error))
  {
    return cl.UsageError(error);
  }
  std::ofstream csv;
  if (cl.Has("--csv"))
  {
    csv.open(cl.Get("--csv"));
    if (!csv)
    {
      std::cerr << "mesolight bench cones: cannot write " << cl.Get("--csv") << "\n";
      return 1;
    }
    csv << std::fixed;
    csv << "map,size,type,threads,seconds,cpu_seconds,oracle_seconds_extrapolated,speedup,median_"
           "ratio,"
           "clamped_fraction\n";
  }
  std::cout << std::fixed;
  std::cout << "cone maps: fast bilinear-safe search (" << threads << " threads, tolerance "
            << tolerance << ") vs brute-force oracle (1 thread, timed at " << oracleSize
            << "^2, extrapolated as (cells)^2)\n"
            << "hardware threads: " << std::thread::hardware_concurrency() << "\n\n";
  std::cout << std::left << std::setw(17) << "map" << std::setw(7) << "size" << std::setw(14)
            << "type" << std::right << std::setw(10) << "seconds" << std::setw(10) << "cpu s"
            << std::setw(14) << "oracle s*" << std::setw(11) << "speed-up" << std::setw(13)
            << "median c" << std::setw(10) << "clamped"
            << "\n";
  for (size_t mi = 0; mi < patterns.size(); ++mi)
  {
    for (bool relaxed : { true, false })
    {
      const ConeType type = relaxed ? ConeType::Relaxed : ConeType::Conservative;
      // Oracle on a small map; cost ~ ((n + 1)^2)^2 cell pairs.
      const std::vector<float> small = MakeMap(patterns[mi], oracleSize);
      const auto o0 = Clock::now();
      const std::vector<float> oracle = relaxed
        ? ComputeRelaxedConeMapBruteForce(small.data(), oracleSize, oracleSize)
        : ComputeConservativeConeMapBruteForce(small.data(), oracleSize, oracleSize);
      const double oracleSeconds = Seconds(o0, Clock::now());
      const double oracleCells = std::pow(oracleSize + 1.0, 2.0);
      for (int n : sizes)
      {
        const std::vector<float> depth = MakeMap(patterns[mi], n);
        ConeMapOptions options;
        options.Threads = threads;
        options.Tolerance = static_cast<float>(tolerance);
        const auto t0 = Clock::now();
        const std::clock_t c0 = std::clock();
        const std::vector<float> cones = ComputeConeMap(type, depth.data(), n, n, options);
        const double seconds = Seconds(t0, Clock::now());
        // Process CPU time of all threads: / threads estimates the wall time on idle cores
        // (this machine's cores are shared with other jobs).
        const double cpuSeconds = static_cast<double>(std::clock() - c0) / CLOCKS_PER_SEC;
        if (cones.empty())
        {
          std::cerr << "mesolight bench cones: generation failed\n";
          return 1;
        }
        const double extrapolated =
          oracleSeconds * std::pow(std::pow(n + 1.0, 2.0) / oracleCells, 2.0);
        std::vector<double> values(cones.begin(), cones.end());
        const double clamped = static_cast<double>(std::count(
                                 cones.begin(), cones.end(), static_cast<float>(kConeMaxRatio))) /
          static_cast<double>(cones.size());
        const double median = Quantile(values, 0.5);
        std::cout << std::left << std::setw(17) << mapNames[mi] << std::setw(7) << n
                  << std::setw(14) << (relaxed ? "relaxed" : "conservative") << std::right
                  << std::setprecision(2) << std::setw(10) << seconds << std::setw(10) << cpuSeconds
                  << std::setw(14) << std::setprecision(0) << extrapolated << std::setw(10)
                  << std::setprecision(0) << extrapolated / seconds << "x" << std::setprecision(3)
                  << std::setw(13) << median << std::setw(9) << std::setprecision(1)
                  << 100.0 * clamped << "%\n"
                  << std::flush;
        if (csv)
        {
          csv << mapNames[mi] << "," << n << "," << (relaxed ? "relaxed" : "conservative") << ","
              << threads << "," << std::setprecision(3) << seconds << "," << cpuSeconds << ","
              << std::setprecision(1) << extrapolated << "," << std::setprecision(1)
              << extrapolated / seconds << "," << std::setprecision(5) << median << ","
              << std::setprecision(5) << clamped << "\n";
        }
      }
      std::cout << std::left << std::setw(17) << mapNames[mi] << std::setw(7) << oracleSize
                << std::setw(14) << (relaxed ? "relaxed" : "conservative") << std::right
                << "  oracle measured: " << std::setprecision(3) << oracleSeconds << " s ("
                << oracle.size() << " texels)\n";
    }
  }
  if (compareSize > 0)
  {
    std::cout << "\nWidth of the bilinear-safe cones at " << compareSize << "^2 against cones "
              << "over the texel samples only\n(BilinearSafe off: not valid under bilinear "
              << "filtering), per texel whose sample cone is below the clamp;\nand relaxed "
              << "over conservative (both bilinear-safe), all texels:\n";
    std::cout << std::left << std::setw(17) << "map" << std::setw(14) << "type" << std::right
              << std::setw(12) << "p10" << std::setw(10) << "median" << std::setw(10) << "p90"
              << "\n";
    for (size_t mi = 0; mi < patterns.size(); ++mi)
    {
      const std::vector<float> depth = MakeMap(patterns[mi], compareSize);
      ConeMapOptions safe;
      safe.Threads = threads;
      safe.Tolerance = static_cast<float>(tolerance);
      ConeMapOptions samples = safe;
      samples.BilinearSafe = false;
      std::vector<float> safeMaps[2];
      for (int t = 0; t < 2; ++t)
      {
        const ConeType type = t == 0 ? ConeType::Relaxed : ConeType::Conservative;
        safeMaps[t] = ComputeConeMap(type, depth.data(), compareSize, compareSize, safe);
        const std::vector<float> sample =
          ComputeConeMap(type, depth.data(), compareSize, compareSize, samples);
        std::vector<double> ratios;
        for (size_t k = 0; k < sample.size(); ++k)
        {
          if (sample[k] < kConeMaxRatio && sample[k] > 0.0f)
          {
            ratios.push_back(safeMaps[t][k] / sample[k]);
          }
        }
        std::cout << std::left << std::setw(17) << mapNames[mi] << std::setw(14)
                  << (t == 0 ? "safe/sample R" : "safe/sample C") << std::right
                  << std::setprecision(3) << std::setw(12) << Quantile(ratios, 0.1) << std::setw(10)
                  << Quantile(ratios, 0.5) << std::setw(10) << Quantile(ratios, 0.9) << "\n";
      }
      std::vector<double> rc;
      for (size_t k = 0; k < safeMaps[0].size(); ++k)
      {
        if (safeMaps[1][k] > 0.0f)
        {
          rc.push_back(std::min(safeMaps[0][k], kConeMaxRatio) / safeMaps[1][k]);
        }
      }
      std::cout << std::left << std::setw(17) << mapNames[mi] << std::setw(14) << "relaxed/cons"
                << std::right << std::setprecision(3) << std::setw(12) << Quantile(rc, 0.1)
                << std::setw(10) << Quantile(rc, 0.5) << std::setw(10) << Quantile(rc, 0.9) << "\n"
                << std::flush;
    }
  }
  if (steppingSize > 0)
  {
    SteppingAnalysis(
      patterns, mapNames, steppingSize, depthScale, steppingRays, threads, std::cout);
  }
  return 0;
}

} // namespace mesolight
