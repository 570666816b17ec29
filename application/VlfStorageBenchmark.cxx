// SPDX-License-Identifier: BSD-3-Clause
// `mesolight bench vlf-storage`: the light field's storage, measured. Per scene and setting the
// field is built and propagated to the default tolerance with float radiance, then:
//   - the maps' cells: all (what version 1 stored), crossings (what is stored now), the share of
//     crossings whose radiance is zero;
//   - memory: the dense float layout (computed: what the maps and textures took before the
//     sparse storage), while propagating (sparse, float), and after (sparse, shared exponent:
//     LightField::AllocatedBytes);
//   - file size: a version 1 snapshot (dense float, WriteSnapshotVersion) against version 2;
//   - the error the shared exponent adds, float field vs the same field compacted: an image of
//     the radiance leaving every visible surface toward the eye (Lookup::RadianceLeaving, the
//     walkthrough's field lookup and its mirror lookup), the diffuse-texture image (`vlf
//     render`), and the gathered irradiance (Lookup::Irradiance) at points in the scene: mean
//     relative per-pixel (per-point) difference, over pixels whose float value is not black.
#include "VlfStorageBenchmark.h"

#include "CommandLine.h"
#include "LightFieldCamera.h"
#include "OutputFile.h"
#include "Timing.h"

#include "EmbreeScene.h"
#include "LightField.h"
#include "Lookup.h"
#include "MathConstants.h"
#include "ObjScene.h"
#include "ParallelFor.h"
#include "PatchComparison.h" // ToUnit
#include "Propagation.h"
#include "Snapshot.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>
#include <sys/stat.h>
#include <unistd.h>

namespace mesolight
{
namespace
{
struct Row
{
  std::string Scene;
  std::size_t Directions = 0;
  int Rays = 0;
  int Iterations = 0;
  std::uint64_t Cells = 0, Crossings = 0, ZeroCrossings = 0, Maps = 0;
  std::uint64_t DenseBytes = 0, PropagatingBytes = 0, CompactBytes = 0;
  std::uint64_t DenseFile = 0, CompactFile = 0;
  double ImageError = 0.0, ImageWorst = 0.0, DiffuseError = 0.0, GatherError = 0.0;
};

std::uint64_t FileBytes(const std::string& path)
{
  struct stat info;
  return ::stat(path.c_str(), &info) == 0 ? static_cast<std::uint64_t>(info.st_size) : 0;
}

// Mean and worst relative difference of b against a over the entries where a is not black
// (luminance-like sum of channels above floor).
void Compare(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b, double& mean,
  double* worst = nullptr)
{
  double sum = 0.0, most = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < a.size(); ++i)
  {
    const double ref = static_cast<double>(a[i].x) + a[i].y + a[i].z;
    if (!(ref > 1e-6))
    {
      continue;
    }
    const glm::vec3 d = glm::abs(b[i] - a[i]);
    const double e = (static_cast<double>(d.x) + d.y + d.z) / ref;
    sum += e;
    most = std::max(most, e);
    ++n;
  }
  mean = n > 0 ? sum / static_cast<double>(n) : 0.0;
  if (worst)
  {
    *worst = most;
  }
}

// The radiance leaving the visible surface of each pixel toward the eye: RadianceLeaving
// (maps) and DiffuseRadiance (textures).
void RenderField(const vlf::LightField& field, const glm::vec3& eyeUnit, const glm::vec3& focalUnit,
  const glm::vec3& upWorld, double viewAngle, int size, std::vector<glm::vec3>& maps,
  std::vector<glm::vec3>& diffuse)
{
  const EmbreeScene embree(field.Scene());
  const vlf::Lookup lookup(field);
  const glm::vec3 forward = glm::normalize(focalUnit - eyeUnit);
  const glm::vec3 right = glm::normalize(glm::cross(forward, upWorld));
  const glm::vec3 up = glm::cross(right, forward);
  const float tanHalf = static_cast<float>(std::tan(0.5 * viewAngle * Pi<double> / 180.0));
  maps.assign(static_cast<std::size_t>(size) * size, glm::vec3(0.0f));
  diffuse = maps;
  ParallelFor(0, static_cast<std::size_t>(size), 1,
    [&](std::size_t r0, std::size_t r1)
    {
      for (std::size_t row = r0; row < r1; ++row)
      {
        for (int column = 0; column < size; ++column)
        {
          const float sx = (2.0f * (column + 0.5f) / size - 1.0f) * tanHalf;
          const float sy = (2.0f * (static_cast<float>(row) + 0.5f) / size - 1.0f) * tanHalf;
          SceneRay ray;
          ray.Origin = eyeUnit;
          ray.Direction = glm::normalize(forward + sx * right + sy * up);
          const SceneHit hit = embree.Intersect(ray);
          if (!hit.Hit())
          {
            continue;
          }
          const std::uint32_t s = field.SurfaceOfTriangle(hit.Triangle);
          if (s == vlf::NoSurface || glm::dot(field.Surfaces()[s].Normal, ray.Direction) >= 0.0f)
          {
            continue;
          }
          const glm::vec3 p = ray.Origin + hit.T * ray.Direction;
          const std::size_t i = row * static_cast<std::size_t>(size) + column;
          maps[i] = lookup.RadianceLeaving(s, p, -ray.Direction);
          diffuse[i] = lookup.DiffuseRadiance(s, p);
        }
      }
    });
}

// Gathered irradiance at points inside the scene's bounds (random, fixed), random normals.
std::vector<glm::vec3> Gather(const vlf::LightField& field, int points)
{
  glm::vec3 lo(1e30f), hi(-1e30f);
  for (const glm::vec3& p : field.Scene().Positions)
  {
    lo = glm::min(lo, p);
    hi = glm::max(hi, p);
  }
  std::mt19937 rng(12345);
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  std::vector<std::pair<glm::vec3, glm::vec3>> at(static_cast<std::size_t>(points));
  for (auto& q : at)
  {
    q.first =
      lo + (hi - lo) * glm::vec3(0.1f + 0.8f * u(rng), 0.1f + 0.8f * u(rng), 0.1f + 0.8f * u(rng));
    glm::vec3 n(u(rng) - 0.5f, u(rng) - 0.5f, u(rng) - 0.5f);
    q.second = glm::length(n) > 1e-3f ? glm::normalize(n) : glm::vec3(0.0f, 1.0f, 0.0f);
  }
  std::vector<glm::vec3> result(at.size());
  const vlf::Lookup lookup(field);
  ParallelFor(0, at.size(), 1,
    [&](std::size_t i0, std::size_t i1)
    {
      for (std::size_t i = i0; i < i1; ++i)
      {
        result[i] = lookup.Irradiance(at[i].first, at[i].second);
      }
    });
  return result;
}

std::string Mib(std::uint64_t bytes)
{
  std::ostringstream s;
  s << std::fixed << std::setprecision(2) << static_cast<double>(bytes) / (1024.0 * 1024.0);
  return s.str();
}
} // namespace

int RunVlfStorageBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench vlf-storage",
    "mesolight bench vlf-storage [SCENE.obj ...] [options]\n\nThe light field's storage: "
    "memory and file size of the dense float layout\n(snapshot version 1) against the sparse, "
    "shared-exponent one, and the error the\nshared exponent adds to lookups (images of the "
    "field and of its diffuse textures,\ngathered irradiance), per scene (the built-in Cornell "
    "box, then each SCENE.obj)\nand setting.\n");
  cl.AddValue("--settings", "DxR,DxR,..", "directions x rays per side", "513x32,2049x64");
  cl.AddValue("--size", "N", "image side (pixels) of the compared renders", "128");
  cl.AddValue("--points", "N", "gathered irradiance points", "256");
  cl.AddValue("--scratch", "DIR", "where the two snapshots are written (removed after)", "/tmp");
  cl.AddFlag("--no-cornell", "leave the built-in Cornell box out");
  cl.AddValue("--csv", "FILE", "write the rows as CSV");
  AddLightFieldCameraOptions(cl);
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  std::string error;
  int size = 0, points = 0;
  if (!cl.GetInt("--size", 8, 4096, size, error) ||
    !cl.GetInt("--points", 1, 1 << 20, points, error))
  {
    return cl.UsageError(error);
  }
  std::vector<std::pair<std::size_t, int>> settingsList;
  {
    std::stringstream list(cl.Get("--settings"));
    std::string item;
    while (std::getline(list, item, ','))
    {
      const std::size_t x = item.find('x');
      if (x == std::string::npos)
      {
        return cl.UsageError("--settings: '" + item + "' is not DIRECTIONSxRAYS");
      }
      try
      {
        settingsList.emplace_back(std::stoul(item.substr(0, x)), std::stoi(item.substr(x + 1)));
      }
      catch (const std::exception&)
      {
        return cl.UsageError("--settings: '" + item + "' is not DIRECTIONSxRAYS");
      }
    }
  }
  std::vector<std::pair<std::string, std::string>> scenes; // name, path ("" = built in)
  if (!cl.Has("--no-cornell"))
  {
    scenes.emplace_back("cornell", "");
  }
  for (const std::string& path : cl.Positional())
  {
    scenes.emplace_back(path.substr(path.find_last_of('/') + 1), path);
  }
  double viewAngle = 0.0;
  if (!ReadViewAngle(cl, viewAngle, error))
  {
    return cl.UsageError(error);
  }

  std::vector<Row> rows;
  const std::string scratch =
    cl.Get("--scratch") + "/vlf-storage-" + std::to_string(static_cast<long>(::getpid()));
  try
  {
    for (const auto& scene : scenes)
    {
      const TriangleScene triangles =
        scene.second.empty() ? MakeCornellBox() : ReadObjScene(scene.second).Scene;
      for (const auto& setting : settingsList)
      {
        Row row;
        row.Scene = scene.first;
        row.Directions = setting.first;
        row.Rays = setting.second;
        vlf::LightFieldSettings settings;
        settings.Directions = setting.first;
        settings.RaysPerSide = setting.second;
        settings.TilesPerSide = std::max(1, setting.second / 8); // `vlf propagate`'s default
        std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(triangles, settings);
        // PropagateToTolerance without its final compaction: the float field is the reference.
        while (vlf::UnshotFraction(*field) > vlf::DefaultTolerance &&
          field->IterationsDone < vlf::DefaultMaxIterations)
        {
          vlf::PropagateIteration(*field);
        }
        row.Iterations = field->IterationsDone;
        row.PropagatingBytes = field->AllocatedBytes();
        const std::size_t cellsPerMap =
          static_cast<std::size_t>(settings.TileSide()) * settings.TileSide();
        const std::size_t tiles =
          static_cast<std::size_t>(settings.TilesPerSide) * settings.TilesPerSide;
        const std::uint64_t perCell =
          sizeof(float) + sizeof(glm::vec3) + (field->HasSpecular() ? sizeof(glm::vec3) : 0);
        for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
        {
          const vlf::Subfield& f = field->GetSubfield(k);
          row.Maps += f.Entries.size();
          row.Cells += f.Entries.size() * cellsPerMap;
          row.Crossings += f.Cells.Slots();
          for (std::size_t q = 0; q < f.Radiance.size(); ++q)
          {
            const glm::vec3 r = f.Radiance[q];
            row.ZeroCrossings += (r.x <= 0.0f && r.y <= 0.0f && r.z <= 0.0f) ? 1 : 0;
          }
          // What version 1 held for this subfield (vectors sized exactly).
          row.DenseBytes += f.Entries.size() * cellsPerMap * perCell +
            f.Entries.size() * sizeof(vlf::TileEntry) + (tiles + 1) * sizeof(std::uint32_t);
        }
        row.DenseBytes +=
          (field->TotalDiffuse.size() + field->UnshotDiffuse.size()) * sizeof(glm::vec3) +
          field->Capacity.size() * sizeof(float);

        glm::vec3 eye, focal;
        double up[3] = { 0.0, 1.0, 0.0 };
        if (!ReadLightFieldCamera(cl, *field, eye, focal, up, error))
        {
          return cl.UsageError(error);
        }
        const glm::vec3 upWorld(
          static_cast<float>(up[0]), static_cast<float>(up[1]), static_cast<float>(up[2]));
        std::vector<glm::vec3> mapsFloat, diffuseFloat, mapsCompact, diffuseCompact;
        RenderField(*field, vlf::ToUnit(*field, eye), vlf::ToUnit(*field, focal), upWorld,
          viewAngle, size, mapsFloat, diffuseFloat);
        const std::vector<glm::vec3> gatherFloat = Gather(*field, points);

        vlf::WriteSnapshotVersion(*field, scratch + "-dense.vlf", vlf::DenseSnapshotVersion);
        row.DenseFile = FileBytes(scratch + "-dense.vlf");
        std::remove((scratch + "-dense.vlf").c_str());

        field->CompactRadiance();
        row.CompactBytes = field->AllocatedBytes();
        vlf::WriteSnapshot(*field, scratch + "-compact.vlf");
        row.CompactFile = FileBytes(scratch + "-compact.vlf");
        // The field as a user loads it: read back compact, lookups on the loaded field.
        field = vlf::ReadSnapshot(scratch + "-compact.vlf");
        std::remove((scratch + "-compact.vlf").c_str());
        RenderField(*field, vlf::ToUnit(*field, eye), vlf::ToUnit(*field, focal), upWorld,
          viewAngle, size, mapsCompact, diffuseCompact);
        const std::vector<glm::vec3> gatherCompact = Gather(*field, points);
        Compare(mapsFloat, mapsCompact, row.ImageError, &row.ImageWorst);
        Compare(diffuseFloat, diffuseCompact, row.DiffuseError);
        Compare(gatherFloat, gatherCompact, row.GatherError);
        rows.push_back(row);
        std::cout << "measured " << row.Scene << " " << row.Directions << "x" << row.Rays
                  << std::endl;
      }
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "mesolight bench vlf-storage: " << e.what() << "\n";
    return 1;
  }

  std::cout << "\nscene             dirs rays it  crossings/cells zero  memory MiB dense -> "
               "propagating -> compact (ratio)  file MiB dense -> compact (ratio)  error: "
               "field image mean/worst, diffuse image, gather\n";
  for (const Row& r : rows)
  {
    const double occupancy =
      r.Cells > 0 ? static_cast<double>(r.Crossings) / static_cast<double>(r.Cells) : 0.0;
    const double zero = r.Crossings > 0
      ? static_cast<double>(r.ZeroCrossings) / static_cast<double>(r.Crossings)
      : 0.0;
    std::cout << std::left << std::setw(18) << r.Scene << std::right << std::setw(5) << r.Directions
              << std::setw(5) << r.Rays << std::setw(4) << r.Iterations << std::fixed
              << std::setprecision(1) << std::setw(9) << 100.0 * occupancy << "%" << std::setw(9)
              << 100.0 * zero << "%   " << Mib(r.DenseBytes) << " -> " << Mib(r.PropagatingBytes)
              << " -> " << Mib(r.CompactBytes) << " (" << std::setprecision(1)
              << 100.0 * static_cast<double>(r.CompactBytes) / static_cast<double>(r.DenseBytes)
              << "%)   " << Mib(r.DenseFile) << " -> " << Mib(r.CompactFile) << " ("
              << 100.0 * static_cast<double>(r.CompactFile) / static_cast<double>(r.DenseFile)
              << "%)   " << std::setprecision(3) << 100.0 * r.ImageError << "% / "
              << 100.0 * r.ImageWorst << "%, " << 100.0 * r.DiffuseError << "%, "
              << 100.0 * r.GatherError << "%\n";
  }
  if (cl.Has("--csv"))
  {
    std::ofstream csv(cl.Get("--csv"));
    csv << "scene,directions,rays,iterations,maps,cells,crossings,zero_crossings,dense_bytes,"
           "propagating_bytes,compact_bytes,memory_ratio,dense_file_bytes,compact_file_bytes,"
           "file_ratio,field_image_mean_rel_error,field_image_worst_rel_error,"
           "diffuse_image_mean_rel_error,gather_mean_rel_error\n";
    for (const Row& r : rows)
    {
      csv << r.Scene << ',' << r.Directions << ',' << r.Rays << ',' << r.Iterations << ',' << r.Maps
          << ',' << r.Cells << ',' << r.Crossings << ',' << r.ZeroCrossings << ',' << r.DenseBytes
          << ',' << r.PropagatingBytes << ',' << r.CompactBytes << ','
          << static_cast<double>(r.CompactBytes) / static_cast<double>(r.DenseBytes) << ','
          << r.DenseFile << ',' << r.CompactFile << ','
          << static_cast<double>(r.CompactFile) / static_cast<double>(r.DenseFile) << ','
          << r.ImageError << ',' << r.ImageWorst << ',' << r.DiffuseError << ',' << r.GatherError
          << '\n';
    }
    if (!csv)
    {
      std::cerr << "mesolight bench vlf-storage: could not write " << cl.Get("--csv") << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--csv") << "\n";
  }
  return 0;
}

} // namespace mesolight
