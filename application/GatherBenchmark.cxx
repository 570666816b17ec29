// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench gather`: the cost of shading a movable object by gathering the light field's
// irradiance at its vertices (ObjectGatherer, Wither 2005 §3.6): microseconds per
// vertex on one thread (its CPU time, so other load on a shared machine does not count, and wall
// time) and on all threads, per direction count, subdivision level and direction set; the
// per-vertex cache's hit rate along a short path; with --error, the mean relative error of the
// outgoing radiance against the path tracer with the object in place (ObjectReference.h).
#include "GatherBenchmark.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "OutputFile.h"
#include "Timing.h"

#include "IrradianceVolume.h"
#include "LightField.h"
#include "ObjectGatherer.h"
#include "ObjectReference.h"
#include "Propagation.h"
#include "Snapshot.h"
#include "TriangleScene.h"

#include <glm/gtc/matrix_transform.hpp>

#include <algorithm>
#include <cstdio>
#include <cstdlib>
#include <ctime>
#include <fstream>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace mesolight
{

namespace
{
double ThreadCpuSeconds()
{
  timespec t{};
  clock_gettime(CLOCK_THREAD_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

const char* SamplingName(vlf::DirectionSampling s)
{
  switch (s)
  {
    case vlf::DirectionSampling::Half:
      return "half";
    case vlf::DirectionSampling::Importance:
      return "importance";
    default:
      return "all";
  }
}

// The object of the benchmark: in the built-in Cornell box the test sphere (radius 40 mm,
// 130 mm below the ceiling in front of the tall block); in another field a sphere of radius
// 0.08 (unit-sphere units) at its centre.
glm::mat4 Placement(const vlf::LightField& field, bool cornell, float& radius, bool bracket)
{
  if (cornell && bracket)
  {
    // The concave bracket of the self-occlusion test, in the free front-right part of the box.
    radius = 60.0f;
    return vlf::WorldToUnitSphere(field) *
      glm::translate(glm::mat4(1.0f), glm::vec3(420.0f, 300.0f, 130.0f));
  }
  if (cornell)
  {
    radius = 40.0f;
    return vlf::WorldToUnitSphere(field) *
      glm::translate(glm::mat4(1.0f), glm::vec3(400.0f, 420.0f, 150.0f));
  }
  radius = 0.08f / field.NormalizationScale();
  return vlf::WorldToUnitSphere(field) *
    glm::translate(glm::mat4(1.0f), field.NormalizationCentre());
}
} // namespace

int RunGatherBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench gather",
    "mesolight bench gather [FIELD] [options]\n\nGathering a movable object's irradiance "
    "from a light field (ObjectGatherer): microseconds\nper vertex on one thread and on all, "
    "per direction count, subdivision level and\ndirection set (all, half, importance); the "
    "per-vertex cache's hit rate along a\nshort path; with --error the mean relative error "
    "against the path tracer with the\nobject in place. Without FIELD the built-in Cornell box "
    "is propagated per direction\ncount (--rays, --iterations).\n");
  cl.AddValue("--directions", "N,N,..", "direction counts (2n^2+1) without FIELD", "513,2049,8193");
  cl.AddValue("--rays", "N", "lines per subfield side without FIELD", "32");
  cl.AddValue("--iterations", "K", "shooting iterations without FIELD", "10");
  cl.AddValue("--subdivisions", "L,L,..", "subdivision levels (0-3)", "0,1,2,3");
  cl.AddValue("--rings", "N", "the sphere's rings (2N segments)", "8");
  cl.AddValue("--sets", "S,S,..", "direction sets: all, half, importance", "all,half,importance");
  cl.AddValue("--volumes", "R,R,..",
    "irradiance volumes of R points along the longest side, each a row (set volumeR); 0: none",
    "0");
  cl.AddValue("--repeats", "R", "fastest of R runs per timing", "3");
  cl.AddValue("--path", "N", "steps of the cache path (0: none)", "10");
  cl.AddFlag("--error", "also the error against the path tracer (slow)");
  cl.AddValue("--samples", "N", "--error: paths per vertex", "8192");
  cl.AddValue("--points", "N", "--error: vertices compared", "64");
  cl.AddValue("--object", "sphere|bracket",
    "the sphere, or a concave bracket (120 x 100 mm, bars 20 mm; 'radius' = half its width)",
    "sphere");
  cl.AddValue("--self-occlusion", "on,off", "the object's own occlusion (GatherSettings)", "on");
  cl.AddValue("--csv", "FILE", "write the rows as CSV");
  cl.AddValue(
    "--plot", "FILE.png", "plot us per vertex vs directions (FILE-error.png too with --error)");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  const std::string fieldPath = cl.Positional().empty() ? std::string() : cl.Positional()[0];
  if (cl.Positional().size() > 1)
  {
    return cl.UsageError("one FIELD at most");
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, { fieldPath });
      !problem.empty())
  {
    return cl.UsageError(problem);
  }
  if (cl.Has("--plot") && !std::getenv("DISPLAY"))
  {
    return cl.UsageError("--plot: VTK charts need a display (run under scripts/xvfb.sh)");
  }
  std::string error;
  std::vector<int> directionList, levels;
  int rays = 0, iterations = 0, rings = 0, repeats = 0, pathSteps = 0, samples = 0, points = 0;
  if (!cl.GetIntList("--directions", 3, 1 << 20, directionList, error) ||
    !cl.GetInt("--rays", 8, 4096, rays, error) ||
    !cl.GetInt("--iterations", 1, 1000, iterations, error) ||
    !cl.GetIntList("--subdivisions", 0, 3, levels, error) ||
    !cl.GetInt("--rings", 2, 1000, rings, error) ||
    !cl.GetInt("--repeats", 1, 100, repeats, error) ||
    !cl.GetInt("--path", 0, 10000, pathSteps, error) ||
    !cl.GetInt("--samples", 1, 1 << 24, samples, error) ||
    !cl.GetInt("--points", 1, 1 << 20, points, error))
  {
    return cl.UsageError(error);
  }
  std::vector<int> volumeResolutions;
  if (!cl.GetIntList("--volumes", 0, 128, volumeResolutions, error))
  {
    return cl.UsageError(error);
  }
  volumeResolutions.erase(
    std::remove(volumeResolutions.begin(), volumeResolutions.end(), 0), volumeResolutions.end());
  if (std::count(volumeResolutions.begin(), volumeResolutions.end(), 1) > 0)
  {
    return cl.UsageError("--volumes: 1 is not a grid (use 2-128)");
  }
  std::vector<vlf::DirectionSampling> sets;
  for (const std::string& name : cl.GetStringList("--sets"))
  {
    if (name == "all")
    {
      sets.push_back(vlf::DirectionSampling::All);
    }
    else if (name == "half")
    {
      sets.push_back(vlf::DirectionSampling::Half);
    }
    else if (name == "importance")
    {
      sets.push_back(vlf::DirectionSampling::Importance);
    }
    else
    {
      return cl.UsageError("--sets: '" + name + "' is not all, half or importance");
    }
  }
  const bool withError = cl.Has("--error");
  const std::string objectName = cl.Get("--object");
  if (objectName != "sphere" && objectName != "bracket")
  {
    return cl.UsageError("--object: '" + objectName + "' is not sphere or bracket");
  }
  const bool bracket = objectName == "bracket";
  std::vector<bool> selfOcclusion;
  for (const std::string& name : cl.GetStringList("--self-occlusion"))
  {
    if (name != "on" && name != "off")
    {
      return cl.UsageError("--self-occlusion: '" + name + "' is not on or off");
    }
    selfOcclusion.push_back(name == "on");
  }

  std::ostringstream csv;
  csv << "directions,subdivision,vertices,set,directions_used,us_per_vertex_1thread_cpu,"
         "us_per_vertex_1thread_wall,us_per_vertex_all_threads,mean_relative_error,cache_hit_rate,"
         "object,self_occlusion,self_facing_vertices\n";
  std::map<std::string, ChartSeries> timeSeries, errorSeries;
  std::printf("%10s %5s %8s %10s %6s %14s %14s %14s %10s\n", "directions", "level", "vertices",
    "set", "used", "us/v 1 thr cpu", "us/v 1 thr wall", "us/v all thr", "error");
  try
  {
    std::vector<int> counts = directionList;
    if (!fieldPath.empty())
    {
      counts = { 0 };
    }
    for (const int directions : counts)
    {
      std::unique_ptr<vlf::LightField> field;
      if (!fieldPath.empty())
      {
        field = vlf::ReadSnapshot(fieldPath);
      }
      else
      {
        vlf::LightFieldSettings settings;
        settings.Directions = static_cast<std::size_t>(directions);
        settings.RaysPerSide = rays;
        settings.TilesPerSide = rays % 4 == 0 ? 4 : 1;
        field = vlf::LightField::Build(MakeCornellBox(), settings);
        vlf::Propagate(*field, iterations);
      }
      const auto count = static_cast<int>(field->SubfieldCount());
      float radius = 0.0f;
      const glm::mat4 placement = Placement(*field, fieldPath.empty(), radius, bracket);
      vlf::ObjectMesh sphere = bracket
        ? vlf::MakeBracket(2.0f * radius, 5.0f / 3.0f * radius, radius / 3.0f, 2.0f * radius)
        : vlf::MakeSphere(radius, rings, 2 * rings);
      std::map<int, vlf::ObjectReference> references;
      std::map<int, std::unique_ptr<vlf::IrradianceVolume>> volumes;
      for (const int resolution : volumeResolutions)
      {
        vlf::IrradianceVolumeSettings volumeSettings;
        volumeSettings.Resolution = resolution;
        auto& volume = volumes[resolution];
        volume = std::make_unique<vlf::IrradianceVolume>(*field, volumeSettings);
        std::printf("irradiance volume %d (%d x %d x %d points, %zu valid, %zu normals): built in "
                    "%.2f s on all threads\n",
          resolution, volume->Dimensions()[0], volume->Dimensions()[1], volume->Dimensions()[2],
          volume->ValidPointCount(), volume->NormalCount(), volume->BuildSeconds());
      }
      // One row per direction set, then one per irradiance volume (set "volumeR").
      std::vector<std::pair<vlf::DirectionSampling, int>> rows;
      for (const vlf::DirectionSampling set : sets)
      {
        rows.emplace_back(set, 0);
      }
      for (const int resolution : volumeResolutions)
      {
        rows.emplace_back(vlf::DirectionSampling::All, resolution);
      }
      for (const int level : levels)
      {
        for (const bool self : selfOcclusion)
        {
          for (const auto& [set, volumeRow] : rows)
          {
            const std::string setName =
              volumeRow > 0 ? "volume" + std::to_string(volumeRow) : std::string(SamplingName(set));
            vlf::GatherSettings settings;
            settings.ObjectOcclusion = self;
            settings.Subdivision = level;
            settings.Directions = set;
            settings.Volume = volumeRow > 0 ? volumes[volumeRow].get() : nullptr;
            settings.UseCache = false;
            vlf::ObjectGatherer gatherer(*field);
            settings.Threads = 1;
            double cpu = 1e30;
            const double wall = FastestSeconds(repeats,
              [&]
              {
                const double start = ThreadCpuSeconds();
                gatherer.Gather(sphere, placement, settings);
                cpu = std::min(cpu, ThreadCpuSeconds() - start);
              });
            settings.Threads = 0;
            const double all =
              FastestSeconds(repeats, [&] { gatherer.Gather(sphere, placement, settings); });
            const vlf::ShadedObject& shaded = gatherer.Result();
            const double n = static_cast<double>(shaded.GatheredPoints);
            std::string errorText = "";
            if (withError)
            {
              auto found = references.find(level);
              if (found == references.end())
              {
                vlf::ObjectReferenceSettings reference;
                reference.Samples = samples;
                reference.MaxPoints = static_cast<std::size_t>(points);
                found = references
                          .emplace(level, vlf::TraceObjectReference(*field, shaded.Mesh, reference))
                          .first;
              }
              const double e = vlf::MeanRelativeError(shaded.Radiance, found->second);
              errorText = std::to_string(e);
              const std::string name = setName + ", subdivision " + std::to_string(level) +
                (self ? "" : ", no self-occlusion");
              ChartSeries& series = errorSeries[name];
              series.Name = name;
              series.X.push_back(count);
              series.Y.push_back(100.0 * e);
            }
            std::printf("%10d %5d %8zu %10s %6zu %14.1f %14.1f %14.1f %10s\n", count, level,
              shaded.GatheredPoints, setName.c_str(), shaded.DirectionsUsed, 1e6 * cpu / n,
              1e6 * wall / n, 1e6 * all / n, errorText.c_str());
            std::fflush(stdout);
            csv << count << "," << level << "," << shaded.GatheredPoints << "," << setName << ","
                << shaded.DirectionsUsed << "," << 1e6 * cpu / n << "," << 1e6 * wall / n << ","
                << 1e6 * all / n << "," << errorText << ",," << objectName << ","
                << (self ? "on" : "off") << "," << shaded.SelfFacingPoints << "\n";
            if (self && selfOcclusion.size() > 1)
            {
              std::printf(
                "%10s %5s %8s %10s self-occlusion: %zu vertices face the object, %zu rays "
                "blocked\n",
                "", "", "", "", shaded.SelfFacingPoints, shaded.SelfBlockedRays);
            }
            if (set == vlf::DirectionSampling::All && volumeRow == 0 &&
              self == selfOcclusion.front())
            {
              ChartSeries& series = timeSeries["subdivision " + std::to_string(level)];
              series.Name = "subdivision " + std::to_string(level) + " (" +
                std::to_string(shaded.GatheredPoints) + " vertices)";
              series.X.push_back(count);
              series.Y.push_back(1e6 * cpu / n);
            }
          }
        }
      }
      // The cache along a short path: each step moves the sphere by 0.15 field cells and turns it
      // by 0.02 rad about its axis; the points that moved less than the tolerances keep their
      // values.
      if (pathSteps > 0)
      {
        vlf::ObjectGatherer gatherer(*field);
        vlf::GatherSettings settings;
        settings.Subdivision = levels.empty() ? 1 : levels.back();
        const float cellWorld = field->Settings().CellSize() / field->NormalizationScale();
        std::size_t gathered = 0, cached = 0;
        const auto start = std::chrono::steady_clock::now();
        for (int step = 0; step <= pathSteps; ++step)
        {
          const glm::mat4 moved = placement *
            glm::translate(glm::mat4(1.0f), glm::vec3(0.15f * cellWorld * step, 0.0f, 0.0f)) *
            glm::rotate(glm::mat4(1.0f), 0.02f * step, glm::vec3(0.0f, 0.0f, 1.0f));
          const vlf::ShadedObject& s = gatherer.Gather(sphere, moved, settings);
          if (step > 0)
          {
            gathered += s.GatheredPoints;
            cached += s.CachedPoints;
          }
        }
        const double seconds = SecondsSince(start);
        const double rate = static_cast<double>(cached) /
          static_cast<double>(std::max<std::size_t>(1, cached + gathered));
        std::printf("cache path (%d directions, subdivision %d, %d steps of 0.15 cell and 0.02 "
                    "rad): hit rate %.1f%% (%zu kept, %zu gathered), %.1f ms per step\n",
          count, settings.Subdivision, pathSteps, 100.0 * rate, cached, gathered,
          1e3 * seconds / (pathSteps + 1));
        // The path's row: its points, set "path", the time per step in the all-threads column.
        csv << count << "," << settings.Subdivision << ","
            << gatherer.Result().Mesh.Positions.size() << ",path,"
            << gatherer.Result().DirectionsUsed << ",,,"
            << 1e6 * seconds / (pathSteps + 1) /
            static_cast<double>(gatherer.Result().Mesh.Positions.size())
            << ",," << rate << "," << objectName << ",on,\n";
      }
    }
  }
  catch (const std::exception& ex)
  {
    std::cerr << "mesolight bench gather: " << ex.what() << "\n";
    return 1;
  }
  if (cl.Has("--csv"))
  {
    std::ofstream file(cl.Get("--csv"));
    file << csv.str();
    if (!file)
    {
      std::cerr << "mesolight bench gather: could not write " << cl.Get("--csv") << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--csv") << "\n";
  }
  if (cl.Has("--plot"))
  {
    const std::string plot = cl.Get("--plot");
    ScatterChart chart;
    chart.Title = "Gathering a sphere's irradiance: one thread, CPU time per vertex";
    chart.XLabel = "directions";
    chart.YLabel = "microseconds per vertex";
    for (auto& s : timeSeries)
    {
      chart.Points.push_back(s.second);
    }
    if (!WriteScatterChartPng(chart, plot, error))
    {
      std::cerr << "mesolight bench gather: " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << plot << "\n";
    if (withError)
    {
      ScatterChart errors;
      errors.Title = "Gathered outgoing radiance vs the path tracer (object in place)";
      errors.XLabel = "directions";
      errors.YLabel = "mean relative error (%)";
      for (auto& s : errorSeries)
      {
        errors.Points.push_back(s.second);
      }
      const std::string errorPlot = plot.size() > 4 && plot.substr(plot.size() - 4) == ".png"
        ? plot.substr(0, plot.size() - 4) + "-error.png"
        : plot + "-error.png";
      if (!WriteScatterChartPng(errors, errorPlot, error))
      {
        std::cerr << "mesolight bench gather: " << error << "\n";
        return 1;
      }
      std::cout << "wrote " << errorPlot << "\n";
    }
  }
  return 0;
}

} // namespace mesolight
