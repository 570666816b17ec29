// SPDX-License-Identifier: BSD-3-Clause
#include "LightsCommand.h"

#include "CommandLine.h"
#include "MathConstants.h"
#include "OutputFile.h"
#include "Timing.h"

#include "EnvironmentMaps.h"
#include "MedianCut.h"
#include "ProceduralEnvironments.h"
#include "vtkMedianCutLights.h"
#include "vtkOIIOImageReader.h"
#include "vtkProceduralEnvironmentSource.h"

#include <vtkAlgorithm.h>
#include <vtkDataArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>
#include <vtkSmartPointer.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <sstream>

namespace mesolight
{

namespace
{

/// The built-in maps: "sky" (smooth sky over a dim ground) and "sun" (the same sky, a
/// 2-degree sun and a bright window, as in the reference experiment).
SkyParameters ProceduralParameters(const std::string& name)
{
  SkyParameters p;
  if (name == "sun")
  {
    p.Sun = true;
    p.Window = true;
  }
  return p;
}

/// An algorithm producing the lat-long map named by `source`, or null with a message.
vtkSmartPointer<vtkAlgorithm> MapSource(const std::string& source, int height, std::string& error)
{
  const std::string prefix = "procedural:";
  if (source.compare(0, prefix.size(), prefix) == 0)
  {
    const std::string name = source.substr(prefix.size());
    if (name != "sky" && name != "sun")
    {
      error = "unknown procedural map '" + name + "' (expected procedural:sky or procedural:sun)";
      return nullptr;
    }
    auto sky = vtkSmartPointer<vtkProceduralEnvironmentSource>::New();
    sky->SetResolution(2 * height, height);
    if (name == "sun")
    {
      sky->SetMapToSunSky();
      sky->WindowOn();
    }
    return sky;
  }
  auto reader = vtkSmartPointer<vtkOIIOImageReader>::New();
  reader->SetFileName(source.c_str());
  return reader;
}

/// RGB floats of an image's point scalars (3+ components).
bool ToRgbImage(vtkImageData* image, RgbImage& out, std::string& error)
{
  vtkDataArray* scalars = image ? image->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (image)
  {
    image->GetDimensions(dims);
  }
  if (!scalars || scalars->GetNumberOfComponents() < 3 || dims[2] != 1)
  {
    error = "not a 2D RGB image";
    return false;
  }
  out = RgbImage(dims[0], dims[1]);
  const vtkIdType n = static_cast<vtkIdType>(dims[0]) * dims[1];
  for (vtkIdType k = 0; k < n; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      out.Rgb[3 * k + c] = static_cast<float>(scalars->GetComponent(k, c));
    }
  }
  return true;
}

std::vector<std::array<double, 3>> FibonacciNormals(int n)
{
  std::vector<std::array<double, 3>> out;
  out.reserve(static_cast<size_t>(n));
  const double golden = Pi<double> * (3.0 - std::sqrt(5.0));
  for (int k = 0; k < n; ++k)
  {
    const double z = 1.0 - (k + 0.5) * 2.0 / n;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    out.push_back({ r * std::cos(golden * k), r * std::sin(golden * k), z });
  }
  return out;
}

struct ErrorStats
{
  double Mean = 0.0;
  double Max = 0.0;
};

/// Relative luminance error of approx(n) against exact, over normals whose exact
/// irradiance is above 1e-4 of the largest.
template <typename Approx>
ErrorStats Compare(const std::vector<std::array<double, 3>>& normals,
  const std::vector<double>& exactY, Approx approx)
{
  const double largest = *std::max_element(exactY.begin(), exactY.end());
  ErrorStats s;
  int used = 0;
  for (size_t k = 0; k < normals.size(); ++k)
  {
    if (!(exactY[k] > 1e-4 * largest))
    {
      continue;
    }
    double e[3];
    approx(normals[k].data(), e);
    const double err = std::abs(Luminance(e[0], e[1], e[2]) - exactY[k]) / exactY[k];
    s.Mean += err;
    s.Max = std::max(s.Max, err);
    ++used;
  }
  s.Mean /= std::max(1, used);
  return s;
}
} // namespace

//------------------------------------------------------------------------------
int RunLightsCommand(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight lights",
    "mesolight lights ENV_IMAGE --out lights.csv [options]\n\nApproximates a "
    "lat-long environment map (or procedural:sky / procedural:sun)\nby N directional "
    "lights with solid-angle-weighted median cut. CSV columns:\nu,v = light centroid "
    "in map coordinates (v = 0 top row); x,y,z = unit direction\n(+Z up, u = 0 toward "
    "+X, u = 0.25 toward +Y); r,g,b = irradiance at normal incidence.\n");
  cl.AddValue("--out", "FILE.csv", "where to write the lights (header u,v,x,y,z,r,g,b)");
  cl.AddValue("--count", "N", "number of lights (any N >= 1)", "64");
  cl.AddFlag("--variance",
    "variance-minimizing cuts (Viriyothai & Debevec 2009), the default: kept for scripts");
  cl.AddFlag("--plain", "even-energy cuts of the most energetic region (Debevec 2005) instead");
  cl.AddValue("--resolution", "H", "height of procedural maps (width 2H)", "512");
  cl.AddValue("--memory-budget", "GIB", "refuse maps needing more memory (0: all there is)", "0");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (cl.Positional().size() != 1 || !cl.Has("--out"))
  {
    std::cerr << "mesolight lights: usage: mesolight lights ENV_IMAGE --out lights.csv "
                 "[--count N] [--plain]\n";
    return 2;
  }
  if (cl.Has("--plain") && cl.Has("--variance"))
  {
    return cl.UsageError("--plain and --variance exclude each other");
  }
  int count = 64;
  int height = 512;
  double budget = 0.0;
  if (!cl.GetInt("--count", 1, 1 << 26, count, error) ||
    !cl.GetInt("--resolution", 2, 8192, height, error) ||
    !cl.GetDouble("--memory-budget", 0.0, 1e6, budget, error))
  {
    return cl.UsageError(error);
  }
  const std::string in = cl.Positional()[0];
  const std::string file = cl.Get("--out");
  const std::string problem = CheckOutputFile(file, { in });
  if (!problem.empty())
  {
    return cl.UsageError("--out: " + problem);
  }
  vtkSmartPointer<vtkAlgorithm> source = MapSource(in, height, error);
  if (!source)
  {
    return cl.UsageError(error);
  }
  vtkNew<vtkMedianCutLights> lights;
  lights->SetInputConnection(source->GetOutputPort());
  lights->SetNumberOfLights(count);
  lights->SetVarianceMinimization(!cl.Has("--plain"));
  lights->SetMemoryBudget(static_cast<vtkTypeInt64>(budget * 1073741824.0));
  // Errors from any stage are reported by VTK on stderr; the exit code tells the caller.
  lights->Update();
  vtkPolyData* out = lights->GetOutput();
  if (out->GetNumberOfPoints() != count)
  {
    std::cerr << "mesolight lights: could not compute " << count << " lights from " << in << "\n";
    return 1;
  }
  if (!vtkMedianCutLights::WriteCsv(out, file, error))
  {
    std::cerr << "mesolight lights: " << error << "\n";
    return 1;
  }
  double total[3] = { 0.0, 0.0, 0.0 };
  vtkDataArray* irradiance = out->GetPointData()->GetArray("Irradiance");
  for (vtkIdType k = 0; k < out->GetNumberOfPoints(); ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      total[c] += irradiance->GetComponent(k, c);
    }
  }
  std::cout << "wrote " << file << " (" << count << " lights"
            << (cl.Has("--plain") ? ", even-energy cuts" : ", variance-minimizing")
            << "; total sum L dOmega = " << total[0] << ", " << total[1] << ", " << total[2]
            << ")\n";
  return 0;
}

//------------------------------------------------------------------------------
int RunLightsBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench lights",
    "mesolight bench lights [options]\n\nMean and max relative error of unoccluded "
    "diffuse irradiance (luminance) from\nmedian cut light sets (plain and "
    "variance-minimizing) and from 9 spherical\nharmonics (Ramamoorthi & Hanrahan "
    "2001), against exact numerical integration\nover the map, for the procedural "
    "SmoothSky and SunSky (2-degree sun + window)\nmaps and Blender's CC0 studio-light "
    "HDRIs when installed (package blender-data);\nthe same maps at 4096x2048 at the "
    "default count, the worst real map per cut,\nthen the median cut times for 4096x2048.\n");
  cl.AddValue("--counts", "N,N,..", "light counts", "16,32,64,128,256,512,1024");
  cl.AddValue("--normals", "N", "Fibonacci-sphere normals for the irradiance error", "2000");
  cl.AddValue("--resolution", "H", "height of the procedural maps (width 2H)", "512");
  cl.AddValue("--csv", "FILE", "also write the table as CSV");
  cl.AddValue("--blender-dir", "DIR", "directory of lat-long EXR studio lights",
    "/usr/share/blender/datafiles/studiolights/world");
  cl.AddValue("--timing-repeats", "N", "median cut runs on 4096x2048 (best is reported)", "5");
  cl.AddValue("--timing-counts", "N,N,..", "light counts timed on 4096x2048", "64,1024");
  cl.AddValue("--large-normals", "N",
    "normals for the maps at 4096x2048 at the default count (0: skip them)", "200");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv" }, {}); !problem.empty())
  {
    return cl.UsageError(problem);
  }
  std::vector<int> counts;
  int normalCount = 2000;
  int height = 512;
  int repeats = 5;
  std::vector<int> timingCounts;
  int largeNormalCount = 200;
  if (!cl.GetIntList("--counts", 1, 1000000, counts, error) ||
    !cl.GetInt("--normals", 10, 1000000, normalCount, error) ||
    !cl.GetInt("--resolution", 8, 8192, height, error) ||
    !cl.GetInt("--timing-repeats", 0, 1000, repeats, error) ||
    !cl.GetIntList("--timing-counts", 1, 1000000, timingCounts, error) ||
    !cl.GetInt("--large-normals", 0, 1000000, largeNormalCount, error))
  {
    return cl.UsageError(error);
  }

  // Maps.
  std::vector<std::pair<std::string, RgbImage>> maps;
  maps.emplace_back("SmoothSky", MakeSkyMap(2 * height, height, ProceduralParameters("sky")));
  maps.emplace_back("SunSky", MakeSkyMap(2 * height, height, ProceduralParameters("sun")));
  const std::filesystem::path blender = cl.Get("--blender-dir");
  std::error_code ec;
  if (std::filesystem::is_directory(blender, ec))
  {
    std::vector<std::filesystem::path> files;
    for (const auto& entry : std::filesystem::directory_iterator(blender, ec))
    {
      if (entry.path().extension() == ".exr")
      {
        files.push_back(entry.path());
      }
    }
    std::sort(files.begin(), files.end());
    for (const auto& file : files)
    {
      vtkNew<vtkOIIOImageReader> reader;
      reader->SetFileName(file.string().c_str());
      reader->Update();
      RgbImage map;
      if (reader->GetErrorCode() != 0 || !ToRgbImage(reader->GetOutput(), map, error))
      {
        std::cerr << "mesolight bench lights: skipping " << file << ": " << error << "\n";
        continue;
      }
      maps.emplace_back("blender/" + file.stem().string(), std::move(map));
    }
  }
  else
  {
    std::cout << "(no " << blender.string()
              << ": install blender-data for the 8 CC0 HDRIs; measuring procedural maps only)\n";
  }

  std::ofstream csv;
  if (cl.Has("--csv"))
  {
    csv.open(cl.Get("--csv"));
    if (!csv)
    {
      std::cerr << "mesolight bench lights: cannot write " << cl.Get("--csv") << "\n";
      return 1;
    }
    csv << "map,width,height,method,lights,mean_rel_error,max_rel_error\n";
  }
  auto header = [](int normals)
  {
    std::cout << "Unoccluded diffuse irradiance (luminance), relative error vs exact integration "
                 "over "
              << normals << " normals\n";
    std::cout << std::left << std::setw(22) << "map" << std::setw(18) << "method" << std::right
              << std::setw(7) << "lights" << std::setw(11) << "mean %" << std::setw(11) << "max %"
              << "\n";
  };
  // The worst mean error of each method at the default light count, over the real maps.
  const MedianCutOptions defaults;
  std::map<std::string, std::pair<std::string, double>> worst;
  auto report = [&](const std::string& map, const RgbImage& image, const std::string& method,
                  int lightCount, const ErrorStats& s)
  {
    std::cout << std::left << std::setw(22) << map << std::setw(18) << method << std::right
              << std::setw(7) << lightCount << std::fixed << std::setprecision(3) << std::setw(11)
              << 100.0 * s.Mean << std::setw(11) << 100.0 * s.Max << "\n"
              << std::defaultfloat;
    if (csv)
    {
      csv << map << ',' << image.Width << ',' << image.Height << ',' << method << ',' << lightCount
          << ',' << std::setprecision(6) << s.Mean << ',' << s.Max << '\n';
    }
    if (lightCount == defaults.NumberOfLights && map.compare(0, 8, "blender/") == 0)
    {
      auto& w = worst[method];
      if (s.Mean > w.second)
      {
        w = { map + " " + std::to_string(image.Width) + "x" + std::to_string(image.Height),
          s.Mean };
      }
    }
  };
  auto exactLuminance = [](const RgbImage& map, const std::vector<std::array<double, 3>>& normals)
  {
    const ExactIrradiance exact(map);
    std::vector<double> exactY(normals.size());
    vtkSMPTools::For(0, static_cast<vtkIdType>(normals.size()),
      [&](vtkIdType b, vtkIdType e)
      {
        for (vtkIdType k = b; k < e; ++k)
        {
          double irr[3];
          exact.Evaluate(normals[k].data(), irr);
          exactY[k] = Luminance(irr[0], irr[1], irr[2]);
        }
      });
    return exactY;
  };
  // Both cuts of `map` at each count; false after a median cut error.
  auto measure = [&](const std::string& name, const RgbImage& map,
                   const std::vector<std::array<double, 3>>& normals,
                   const std::vector<double>& exactY, const std::vector<int>& lightCounts)
  {
    for (bool variance : { false, true })
    {
      for (int n : lightCounts)
      {
        if (static_cast<long long>(n) > static_cast<long long>(map.Width) * map.Height)
        {
          continue;
        }
        MedianCutOptions options;
        options.NumberOfLights = n;
        options.VarianceMinimization = variance;
        std::vector<MedianCutLight> lights;
        try
        {
          lights = ComputeMedianCut(map.Rgb.data(), 3, map.Width, map.Height, options);
        }
        catch (const MedianCutError& e)
        {
          std::cerr << "mesolight bench lights: " << name << ": " << e.what() << "\n";
          return false;
        }
        report(name, map, variance ? "median-cut-var" : "median-cut", n,
          Compare(normals, exactY,
            [&](const double* m, double e[3]) { IrradianceFromLights(lights, m, e); }));
      }
    }
    return true;
  };

  const auto normals = FibonacciNormals(normalCount);
  header(normalCount);
  for (const auto& [name, map] : maps)
  {
    const std::vector<double> exactY = exactLuminance(map, normals);
    const SH9 sh = ProjectSH9(map);
    report(name, map, "SH9", 9,
      Compare(normals, exactY, [&](const double* n, double e[3]) { IrradianceSH9(sh, n, e); }));
    if (!measure(name, map, normals, exactY, counts))
    {
      return 1;
    }
  }

  // The same maps at 4096 x 2048 (the real ones resampled bilinearly), at the default count:
  // the size the timing below uses, where the variance cut's moment tables are coarser than
  // the map (MedianCut.h).
  if (largeNormalCount > 0)
  {
    const auto largeNormals = FibonacciNormals(largeNormalCount);
    std::cout << "\n4096x2048 maps, " << defaults.NumberOfLights << " lights (the default count)\n";
    header(largeNormalCount);
    for (const auto& [name, map] : maps)
    {
      const RgbImage large = name.compare(0, 8, "blender/") == 0
        ? ResampleLatLong(map, 4096, 2048, 1)
        : MakeSkyMap(4096, 2048, ProceduralParameters(name == "SunSky" ? "sun" : "sky"));
      if (!measure(name, large, largeNormals, exactLuminance(large, largeNormals),
            { defaults.NumberOfLights }))
      {
        return 1;
      }
    }
  }

  const std::string defaultMethod = defaults.VarianceMinimization ? "median-cut-var" : "median-cut";
  std::cout << "\nWorst real map at " << defaults.NumberOfLights
            << " lights (mean error; the default cut is " << defaultMethod << "):\n";
  for (const auto& [method, w] : worst)
  {
    std::cout << "  " << std::left << std::setw(16) << method << std::right << w.first << ": "
              << std::fixed << std::setprecision(3) << 100.0 * w.second << " %"
              << (method == defaultMethod ? "  (default)" : "") << "\n"
              << std::defaultfloat;
  }

  // Timing: 4096 x 2048 (the SunSky map) -> each timing count, both cuts and the default.
  if (repeats > 0)
  {
    const RgbImage big = MakeSkyMap(4096, 2048, ProceduralParameters("sun"));
    for (int n : timingCounts)
    {
      double plainMs = 0.0;
      for (bool variance : { false, true })
      {
        MedianCutOptions options;
        options.NumberOfLights = n;
        options.VarianceMinimization = variance;
        const double best = 1000.0 *
          FastestSeconds(repeats,
            [&]
            {
              const std::vector<MedianCutLight> lights =
                ComputeMedianCut(big.Rgb.data(), 3, big.Width, big.Height, options);
            });
        plainMs = variance ? plainMs : best;
        std::cout << "median cut" << (variance ? " (variance)" : "") << " 4096x2048 -> " << n
                  << " lights: " << std::fixed << std::setprecision(1) << best << " ms (best of "
                  << repeats << ")";
        if (variance)
        {
          std::cout << ", " << std::setprecision(2) << best / plainMs << "x the plain cut's";
        }
        std::cout << "\n" << std::defaultfloat;
        if (csv)
        {
          csv << "timing-4096x2048," << big.Width << ',' << big.Height << ','
              << (variance ? "median-cut-var-ms" : "median-cut-ms") << "," << n << "," << best
              << ",\n";
        }
      }
    }
  }
  return 0;
}

} // namespace mesolight
