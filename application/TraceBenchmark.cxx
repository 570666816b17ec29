// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench trace`: Embree ray throughput on a dense sphere seen from inside (every ray
// hits), coherent primary rays (single and 16-ray packets) against incoherent diffuse bounces
// (single and packets), and path-tracer samples per second on the Cornell box.
#include "TraceCommand.h"

#include "CommandLine.h"
#include "MathConstants.h"
#include "OutputFile.h"
#include "Timing.h"

#include "EmbreeScene.h"
#include "ParallelTiles.h"
#include "PathTracer.h"
#include "PinholeCamera.h"
#include "RandomSequence.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <vector>

namespace mesolight
{

namespace
{

// A latitude-longitude sphere of radius 1 with about `triangles` triangles, faces pointing in.
TriangleScene MakeDenseSphere(int triangles)
{
  const int rings = std::max(4, static_cast<int>(std::sqrt(triangles / 4.0)));
  const int segments = 2 * rings;
  TriangleScene scene;
  SceneMaterial grey;
  scene.AddMaterial(grey);
  for (int r = 0; r <= rings; ++r)
  {
    const float theta =
      Pi<float> * (0.02f + 0.96f * static_cast<float>(r) / rings); // open at the poles
    for (int s = 0; s < segments; ++s)
    {
      const float phi = 2.0f * Pi<float> * static_cast<float>(s) / segments;
      scene.Positions.emplace_back(
        std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
    }
  }
  for (int r = 0; r < rings; ++r)
  {
    for (int s = 0; s < segments; ++s)
    {
      const auto a = static_cast<std::uint32_t>(r * segments + s);
      const auto b = static_cast<std::uint32_t>(r * segments + (s + 1) % segments);
      const auto c = a + static_cast<std::uint32_t>(segments);
      const auto d = b + static_cast<std::uint32_t>(segments);
      scene.Triangles.emplace_back(a, b, c);
      scene.Triangles.emplace_back(b, d, c);
      scene.MaterialIds.insert(scene.MaterialIds.end(), { 0u, 0u });
    }
  }
  return scene;
}

struct Row
{
  std::string Case;
  int Threads;
  double Count;
  double Seconds;
  std::string Unit;
};

glm::vec3 CosineAround(const glm::vec3& n, RandomSequence& rng)
{
  const float u1 = rng.NextFloat();
  const float u2 = rng.NextFloat();
  const float r = std::sqrt(u1);
  const float phi = 2.0f * Pi<float> * u2;
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  const glm::vec3 t(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  const glm::vec3 bt(b, sign + n.y * n.y * a, -n.y);
  return r * std::cos(phi) * t + r * std::sin(phi) * bt + std::sqrt(std::max(0.0f, 1.0f - u1)) * n;
}
} // namespace

int RunTraceBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench trace",
    "mesolight bench trace [options]\n\nEmbree rays per second on a dense sphere seen from "
    "inside (coherent primary rays\nsingle and in 16-ray packets, incoherent diffuse bounces "
    "single and in packets),\nand path-tracer paths per second on the Cornell box.\n");
  cl.AddValue("--triangles", "N", "triangles of the dense sphere", "1000000");
  cl.AddValue("--size", "N", "rays per side of the primary ray grid", "1024");
  cl.AddValue("--threads", "N", "worker threads", "2");
  cl.AddValue("--cornell-size", "N", "Cornell box image side for the path tracer", "128");
  cl.AddValue("--cornell-samples", "N", "paths per pixel for the path tracer", "16");
  cl.AddValue("--repeats", "N", "timed repetitions (the fastest is reported)", "3");
  cl.AddValue("--csv", "FILE", "also write the table as CSV");
  std::string error;
  int triangles = 0, size = 0, threads = 0, cornellSize = 0, cornellSamples = 0, repeats = 0;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv" }, {}); !problem.empty())
  {
    return cl.UsageError(problem);
  }
  if (!cl.GetInt("--triangles", 8, 50000000, triangles, error) ||
    !cl.GetInt("--size", 16, 8192, size, error) ||
    !cl.GetInt("--threads", 1, 1024, threads, error) ||
    !cl.GetInt("--cornell-size", 8, 4096, cornellSize, error) ||
    !cl.GetInt("--cornell-samples", 1, 65536, cornellSamples, error) ||
    !cl.GetInt("--repeats", 1, 100, repeats, error))
  {
    return cl.UsageError(error);
  }

  std::vector<Row> rows;
  const auto buildStart = std::chrono::steady_clock::now();
  const TriangleScene sphere = MakeDenseSphere(triangles);
  const EmbreeScene embree(sphere);
  const double buildSeconds = SecondsSince(buildStart);
  std::cout << "dense sphere: " << sphere.TriangleCount() << " triangles, built in " << std::fixed
            << std::setprecision(2) << buildSeconds << " s\n";

  // A camera at the centre looking along +x, 90 degrees: every primary ray hits the inside.
  PinholeCamera camera;
  camera.Position = glm::vec3(0.0f);
  camera.FocalPoint = glm::vec3(1.0f, 0.0f, 0.0f);
  camera.ViewUp = glm::vec3(0.0f, 0.0f, 1.0f);
  camera.ViewAngleDegrees = 90.0f;
  const double primaryCount = static_cast<double>(size) * size;
  std::atomic<std::uint64_t> hits{ 0 };

  const double single = FastestSeconds(repeats,
    [&]
    {
      ForEachTile(size, size, 16, threads,
        [&](const TileRange& tile)
        {
          std::uint64_t local = 0;
          for (int j = tile.Y0; j < tile.Y1; ++j)
          {
            for (int i = tile.X0; i < tile.X1; ++i)
            {
              local += embree.Intersect(camera.Ray(i + 0.5f, j + 0.5f, size, size)).Hit();
            }
          }
          hits += local;
        });
    });
  rows.push_back({ "primary coherent, single rays", threads, primaryCount, single, "rays" });

  // Traces the rays of 4 x 4 pixel blocks as 16-ray packets; rayAt(i, j) gives pixel (i, j)'s ray.
  auto tracePackets = [&](const std::function<SceneRay(int, int)>& rayAt)
  {
    ForEachTile(size, size, 16, threads,
      [&](const TileRange& tile)
      {
        SceneRay rays[16];
        SceneHit result[16];
        for (int j = tile.Y0; j < tile.Y1; j += 4)
        {
          for (int i = tile.X0; i < tile.X1; i += 4)
          {
            int n = 0;
            for (int b = 0; b < 4 && j + b < tile.Y1; ++b)
            {
              for (int a = 0; a < 4 && i + a < tile.X1; ++a)
              {
                rays[n++] = rayAt(i + a, j + b);
              }
            }
            embree.Intersect16(rays, result, n);
          }
        }
      });
  };
  const double packets = FastestSeconds(repeats,
    [&]
    { tracePackets([&](int i, int j) { return camera.Ray(i + 0.5f, j + 0.5f, size, size); }); });
  rows.push_back(
    { "primary coherent, 16-ray packets (4x4 pixels)", threads, primaryCount, packets, "rays" });

  // Diffuse bounces from the primary hits: origins on the wall, cosine-distributed directions.
  std::vector<SceneRay> bounces(static_cast<std::size_t>(size) * size);
  ForEachTile(size, size, 16, threads,
    [&](const TileRange& tile)
    {
      for (int j = tile.Y0; j < tile.Y1; ++j)
      {
        for (int i = tile.X0; i < tile.X1; ++i)
        {
          const SceneRay ray = camera.Ray(i + 0.5f, j + 0.5f, size, size);
          const SceneHit hit = embree.Intersect(ray);
          RandomSequence rng(SampleSeed(7, static_cast<std::uint64_t>(j) * size + i, 0));
          const glm::vec3 p = ray.Origin + (hit.Hit() ? hit.T : 1.0f) * ray.Direction;
          const glm::vec3 n = -glm::normalize(p);
          SceneRay bounce;
          bounce.Origin = p + 1e-4f * n;
          bounce.Direction = CosineAround(n, rng);
          bounces[static_cast<std::size_t>(j) * size + i] = bounce;
        }
      }
    });
  const double incoherent = FastestSeconds(repeats,
    [&]
    {
      ForEachTile(size, size, 16, threads,
        [&](const TileRange& tile)
        {
          for (int j = tile.Y0; j < tile.Y1; ++j)
          {
            for (int i = tile.X0; i < tile.X1; ++i)
            {
              embree.Intersect(bounces[static_cast<std::size_t>(j) * size + i]);
            }
          }
        });
    });
  rows.push_back(
    { "diffuse bounces incoherent, single rays", threads, primaryCount, incoherent, "rays" });
  const double incoherentPackets = FastestSeconds(repeats,
    [&] {
      tracePackets([&](int i, int j) { return bounces[static_cast<std::size_t>(j) * size + i]; });
    });
  rows.push_back({ "diffuse bounces incoherent, 16-ray packets", threads, primaryCount,
    incoherentPackets, "rays" });

  // Path tracer on the Cornell box.
  const TriangleScene box = MakeCornellBox();
  const EmbreeScene cornell(box);
  for (int t : { 1, threads })
  {
    PathTracerSettings settings;
    settings.Threads = t;
    const PathTracer tracer(cornell, settings);
    const double seconds = FastestSeconds(repeats,
      [&]
      {
        tracer.RenderImage(
          PinholeCamera(CornellCamera{}), cornellSize, cornellSize, cornellSamples, 1);
      });
    rows.push_back({ "path tracer, Cornell box " + std::to_string(cornellSize) + "^2 x " +
        std::to_string(cornellSamples) + " spp",
      t, static_cast<double>(cornellSize) * cornellSize * cornellSamples, seconds, "paths" });
    if (t == threads)
    {
      break;
    }
  }

  std::cout << "\n"
            << std::left << std::setw(52) << "case" << std::right << std::setw(8) << "threads"
            << std::setw(12) << "count" << std::setw(10) << "seconds" << std::setw(14)
            << "M per second"
            << "\n";
  for (const Row& row : rows)
  {
    std::cout << std::left << std::setw(52) << row.Case << std::right << std::setw(8) << row.Threads
              << std::setw(12) << std::setprecision(0) << row.Count << std::setw(10)
              << std::setprecision(3) << row.Seconds << std::setw(14) << std::setprecision(2)
              << row.Count / row.Seconds / 1e6 << " " << row.Unit << "/s\n";
  }
  if (cl.Has("--csv"))
  {
    std::ofstream csv(cl.Get("--csv"));
    if (!csv)
    {
      std::cerr << "mesolight bench trace: cannot write " << cl.Get("--csv") << "\n";
      return 1;
    }
    csv << "case,threads,count,seconds,millions_per_second,unit,triangles\n";
    for (const Row& row : rows)
    {
      csv << '"' << row.Case << "\"," << row.Threads << "," << std::setprecision(0) << row.Count
          << "," << std::setprecision(4) << row.Seconds << "," << row.Count / row.Seconds / 1e6
          << "," << row.Unit << "," << sphere.TriangleCount() << "\n";
    }
    std::cout << "wrote " << cl.Get("--csv") << "\n";
  }
  return hits.load() > 0 ? 0 : 1;
}

} // namespace mesolight
