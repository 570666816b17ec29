// SPDX-License-Identifier: BSD-3-Clause
// mesolight bench vlf-accuracy: the light field's per-pixel error against the path tracer on the
// scenes of VlfAccuracyScenes.h, over resolution settings, with time and memory.
//
// Per scene one camera image: each pixel's primary hit (Embree, world scene) is looked up in the
// field's total diffuse textures (what the walkthrough draws, Lookup::DiffuseRadiance) and
// compared with the path tracer's diffuse radiance leaving the same point (PathTracer::
// DiffuseRadianceLeaving, all bounces), so the comparison sees the field's error only, not a
// rasterisation difference. The reference is two independent halves: their difference gives the
// reference's own noise, printed beside the error it inflates. References are cached (--cache).
#include "VlfAccuracyBenchmark.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "CornellRegions.h" // WriteLinearImage, ReadLinearImage
#include "LightFieldCamera.h"
#include "OutputFile.h"
#include "Timing.h"
#include "TraceObjScene.h" // IsObjSceneName
#include "VlfAccuracyScenes.h"
#include "VlfPixelComparison.h"

#include "AdaptiveTexels.h"
#include "AutomaticSettings.h"
#include "EmbreeScene.h"
#include "FinalGather.h"
#include "LightField.h"
#include "MathConstants.h"
#include "MemoryBudget.h"
#include "ObjScene.h"
#include "Propagation.h"
#include "TextureComparison.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>
#include <sys/stat.h>

namespace mesolight
{
namespace
{
namespace vlf = mesolight::vlf;
using Clock = std::chrono::steady_clock;

// The adaptive texels' options a setting names (false: not one of them or a bad budget).
bool AdaptiveOptions(const std::string& text, vlf::AdaptiveTexelOptions& options)
{
  options = vlf::AdaptiveTexelOptions();
  if (text == "auto-adaptive-first" || text == "auto-refine")
  {
    options = vlf::FirstRuleAdaptiveTexelOptions();
    options.Coarsen = text == "auto-refine" ? -1.0 : options.Coarsen;
    return true;
  }
  if (text == "auto-adaptive-unbounded")
  {
    options.GatherBudget = -1.0;
    return true;
  }
  if (text == "auto-adaptive-513")
  {
    options.FirstPassDirections = 513; // the first pass before it was made cheaper
    options.FirstPassIndirectRays = 256;
    return true;
  }
  if (text == "auto-adaptive-coarsen")
  {
    options.Coarsen = vlf::FirstRuleAdaptiveTexelOptions().Coarsen; // with the guards of now
    return true;
  }
  double fraction = 0.0;
  char tail = 0;
  if (text.rfind("auto-adaptive-b", 0) == 0)
  {
    if (std::sscanf(text.c_str() + 15, "%lf%c", &fraction, &tail) != 1 || !(fraction >= 0.0))
    {
      return false;
    }
    options.GatherBudget = fraction;
    return true;
  }
  return text == "auto-adaptive" || text.rfind("auto-adaptive", 0) != 0;
}

// "auto", "auto-uniform" (the automatic choice without its finer texels on contact surfaces),
// "auto-adaptive" (auto's lines, base texels and contact halvings, texels per surface refined
// from a first pass on top of them: AdaptiveTexels.h; the caller chooses them),
// "auto-adaptive-first" (the first rule: auto-uniform's, the levels instead of the contact
// halvings, coarsening, interior rows only), "auto-refine" (the first rule never coarser),
// "auto-adaptive-unbounded" (the rule without its gather budget), "auto-adaptive-bF" (budget F),
// "auto-adaptive-coarsen" (the rule, flat low-noise surfaces doubled as the first rule did),
// "auto-adaptive-513" (the rule's first pass at 513 directions and 256 indirect rays, as before),
// "KxN" or "KxNtF" (texel = F x the cell side).
bool ParseSettings(const std::string& text, const TriangleScene& scene, std::uint64_t budget,
  vlf::LightFieldSettings& settings, std::string& note)
{
  if (text == "auto" || text == "auto-uniform" || text.rfind("auto-adaptive", 0) == 0 ||
    text == "auto-refine")
  {
    vlf::AdaptiveTexelOptions options;
    if (!AdaptiveOptions(text, options))
    {
      return false;
    }
    vlf::AutomaticLimits limits;
    limits.MemoryBudget = budget;
    if (text == "auto-uniform" || text == "auto-adaptive-first" || text == "auto-refine")
    {
      limits.ContactTexelHalvings = 0;
    }
    const vlf::AutomaticChoice c = vlf::ChooseAutomaticSettings(scene, limits);
    settings = c.Settings;
    note = c.Describe();
    return true;
  }
  unsigned long directions = 0;
  int rays = 0;
  float texel = 0.0f;
  char t = 0;
  const int n = std::sscanf(text.c_str(), "%lux%d%c%f", &directions, &rays, &t, &texel);
  if (n != 2 && !(n == 4 && t == 't' && texel > 0.0f))
  {
    return false;
  }
  settings = vlf::LightFieldSettings();
  settings.Directions = directions;
  settings.RaysPerSide = rays;
  settings.TilesPerSide = std::max(1, rays / 8);
  settings.TexelSize = n == 4 ? texel * settings.CellSize() : 0.0f;
  settings.MemoryBudget = budget;
  note.clear();
  return settings.Validate().empty();
}

// A digest of the scene's geometry, materials and camera: a cached reference of a changed scene
// is never reused (FNV-1a over the floats' bytes).
std::string SceneDigest(const AccuracyScene& s)
{
  std::uint64_t h = 1469598103934665603ull;
  const auto add = [&h](const void* data, std::size_t bytes)
  {
    const unsigned char* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < bytes; ++i)
    {
      h = (h ^ p[i]) * 1099511628211ull;
    }
  };
  add(s.Scene.Positions.data(), s.Scene.Positions.size() * sizeof(glm::vec3));
  add(s.Scene.Triangles.data(), s.Scene.Triangles.size() * sizeof(glm::uvec3));
  add(s.Scene.MaterialIds.data(), s.Scene.MaterialIds.size() * sizeof(std::uint32_t));
  for (const SceneMaterial& m : s.Scene.Materials)
  {
    add(&m.Diffuse, sizeof(glm::vec3));
    add(&m.Emission, sizeof(glm::vec3));
  }
  add(&s.Camera, sizeof(PinholeCamera));
  char text[20];
  std::snprintf(text, sizeof(text), "%08x", static_cast<unsigned>(h ^ (h >> 32)));
  return text;
}

bool FileExists(const std::string& path)
{
  struct stat st;
  return stat(path.c_str(), &st) == 0;
}

// --write-obj: each scene as DIR/NAME.obj + NAME.mtl (the project's OBJ writer), for the commands
// that read OBJ scenes (`vlf propagate`, `trace --scene`), with the benchmark's camera in a
// comment; prints what a reader must find again: triangles, area, emitted power (a Lambertian
// emitter of radiance Ke sends pi Ke per unit area).
int WriteSceneObjs(const std::vector<std::string>& names, const std::string& directory)
{
  mkdir(directory.c_str(), 0755);
  for (const std::string& name : names)
  {
    const AccuracyScene s = MakeAccuracyScene(name);
    const PinholeCamera& c = s.Camera;
    char camera[256];
    std::snprintf(camera, sizeof(camera), "--camera %g,%g,%g,%g,%g,%g,%g,%g,%g --fov %g",
      c.Position.x, c.Position.y, c.Position.z, c.FocalPoint.x, c.FocalPoint.y, c.FocalPoint.z,
      c.ViewUp.x, c.ViewUp.y, c.ViewUp.z, c.ViewAngleDegrees);
    const std::string path = directory + "/" + name + ".obj";
    WriteObjScene(s.Scene, path, false,
      "mesolight bench vlf-accuracy scene '" + name + "': " + s.Description +
        "\nthe benchmark's camera: " + camera);
    double area = 0.0;
    glm::dvec3 power(0.0);
    std::size_t emitting = 0;
    for (std::size_t t = 0; t < s.Scene.TriangleCount(); ++t)
    {
      const double a = s.Scene.Area(t);
      const glm::vec3 ke = s.Scene.MaterialOf(t).Emission;
      area += a;
      power += Pi<double> * a * glm::dvec3(ke);
      emitting += ke.x > 0.0f || ke.y > 0.0f || ke.z > 0.0f ? 1 : 0;
    }
    std::printf("wrote %s and %s.mtl: %zu triangles (%zu emitting), area %.9g, emitted power "
                "%.9g,%.9g,%.9g (scene units; camera %s)\n",
      path.c_str(), name.c_str(), s.Scene.TriangleCount(), emitting, area, power.x, power.y,
      power.z, camera);
  }
  return 0;
}
} // namespace

int RunVlfAccuracyBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench vlf-accuracy",
    "mesolight bench vlf-accuracy [options]\n\n"
    "The light field's per-pixel error against the path tracer on five scenes (900 small boxes, "
    "a room lit\nindirectly, a ribbed corridor, thin panels near walls, the Cornell box), per "
    "resolution setting:\npropagation time, memory, field size, mean / p95 relative error, "
    "black-where-lit pixels,\nwithout and with the final gather (FinalGather.h) and the bilateral "
    "texture filter.\n"
    "A sixth scene, props (an office of nine models made for a game, open meshes; they are read "
    "from\nDebian's redeclipse-data), runs when named, and so does any OBJ + MTL scene file, seen "
    "from --camera.\n");
  cl.AddValue("--scenes", "LIST", "boxes,room,corridor,thin,cornell; props; or FILE.obj",
    "boxes,room,corridor,thin,cornell");
  AddLightFieldCameraOptions(cl); // the view of a FILE.obj scene
  cl.AddValue("--settings", "LIST",
    "per scene: auto, auto-uniform (auto without its finer texels on surfaces others stand on), "
    "auto-adaptive (auto's, texels refined per surface from the light of a first pass on top of "
    "the contact texels), auto-adaptive-first (the first rule: auto-uniform's, texels per surface "
    "instead of the contact texels, coarser where flat), auto-refine (the first rule never "
    "coarser), auto-adaptive-unbounded (auto-adaptive without its gather budget), "
    "auto-adaptive-bF (gather budget F), auto-adaptive-coarsen (auto-adaptive, flat low-noise "
    "surfaces coarser), auto-adaptive-513 (its first pass at 513 directions, 256 rays, as before), "
    "KxN (K "
    "directions, N lines per side) "
    "or KxNtF (texel F x the cell side)",
    "513x32,auto");
  cl.AddFlag(
    "--full", "sweep more settings: 513x32,513x64,2049x32,2049x64,2049x64t0.5,auto,2049x96");
  cl.AddValue("--size", "WxH", "compared image size", "64x64");
  cl.AddValue("--samples", "N",
    "path-tracer paths per pixel of the reference (two halves; cached, so paid once; 4 x for the "
    "room, lit by many bounces)",
    "8192");
  cl.AddValue("--cache", "DIR", "where references are kept between runs", "vlf-accuracy-cache");
  cl.AddValue("--memory-budget", "GIB", "the fields' memory budget (auto uses half of it)", "4");
  cl.AddValue("--csv", "FILE", "write one row per scene, setting and filter");
  cl.AddValue("--plot", "FILE.png", "time vs mean error, one series per scene (needs a display)");
  cl.AddValue("--images", "DIR", "write each field image and the reference as EXR here");
  cl.AddValue("--variants", "LIST",
    "what is compared per setting: none (the propagated textures), single (the final gather in "
    "one pass, reading the propagated textures at its rays' hits), gather (the final gather: "
    "two passes, the default), bilateral (the texture filter), gather-bilateral (the filter on "
    "the gathered textures)",
    "none,gather,bilateral");
  cl.AddValue("--gather-rays", "LIST",
    "the final gather's indirect rays per texel (several: one gather row each)", "1024");
  cl.AddValue("--gather-direct", "N", "the final gather's emitter samples per texel", "64");
  cl.AddValue("--write-obj", "DIR",
    "instead of benchmarking: write each scene of --scenes as DIR/NAME.obj + NAME.mtl (read by "
    "vlf propagate and trace --scene; existing files are kept) and print its triangles, area and "
    "emitted power");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  int width = 0, height = 0, samples = 0;
  double budgetGib = 4.0;
  if (!cl.GetSize("--size", 8, 2048, width, height, error) ||
    !cl.GetInt("--samples", 2, 1 << 20, samples, error) ||
    !cl.GetDouble("--memory-budget", 1e-3, 1e6, budgetGib, error))
  {
    return cl.UsageError(error);
  }
  vlf::FinalGatherOptions gatherOptions;
  if (!cl.GetInt("--gather-direct", 0, 1 << 16, gatherOptions.DirectSamples, error))
  {
    return cl.UsageError(error);
  }
  std::vector<int> gatherRayCounts;
  for (const std::string& text : cl.GetStringList("--gather-rays"))
  {
    char* end = nullptr;
    const long value = std::strtol(text.c_str(), &end, 10);
    if (text.empty() || *end != '\0' || value < 1 || value > (1 << 16))
    {
      return cl.UsageError("--gather-rays: '" + text + "' is not a count from 1 to 65536");
    }
    gatherRayCounts.push_back(static_cast<int>(value));
  }
  const std::vector<std::string> variants = cl.GetStringList("--variants");
  for (const std::string& v : variants)
  {
    if (v != "none" && v != "single" && v != "gather" && v != "bilateral" &&
      v != "gather-bilateral")
    {
      return cl.UsageError(
        "--variants: '" + v + "' is not none, single, gather, bilateral or gather-bilateral");
    }
  }
  const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, {});
  if (!problem.empty())
  {
    return cl.UsageError(problem);
  }
  if (cl.Has("--write-obj"))
  {
    const std::vector<std::string> known = AccuracySceneNames();
    for (const std::string& name : cl.GetStringList("--scenes"))
    {
      if (std::find(known.begin(), known.end(), name) == known.end())
      {
        try
        {
          MakeAccuracyScene(name); // its message names the scenes
        }
        catch (const std::exception& e)
        {
          return cl.UsageError(e.what());
        }
      }
    }
    try
    {
      return WriteSceneObjs(cl.GetStringList("--scenes"), cl.Get("--write-obj"));
    }
    catch (const std::exception& e)
    {
      std::cerr << "mesolight bench vlf-accuracy: " << e.what() << "\n";
      return 1;
    }
  }
  const std::uint64_t budget = static_cast<std::uint64_t>(budgetGib * 1073741824.0);
  std::vector<std::string> settingsList = cl.GetStringList("--settings");
  if (cl.Has("--full"))
  {
    settingsList = { "513x32", "513x64", "2049x32", "2049x64", "2049x64t0.5", "auto", "2049x96" };
  }
  const std::string cache = cl.Get("--cache");
  mkdir(cache.c_str(), 0755);

  std::ostringstream csv;
  csv << "scene,settings,directions,rays,tiles,texel_m,lines,surfaces,texels,map_cells,"
         "iterations,build_s,propagate_s,total_s,allocated_bytes,estimate_bytes,filter,gather_s,"
         "gather_rays,"
         "pixels,mean_rel_error,p95_rel_error,black_where_lit,reference_noise,peak_bytes\n";
  std::map<std::string, ChartSeries> series;
  std::printf("%-9s %-12s %6s %4s %8s %9s %7s %7s %8s %9s %6s %7s %7s %6s %6s\n", "scene",
    "settings", "dirs", "rays", "texel m", "lines", "iter", "time s", "memory", "filter", "mean",
    "p95", "black", "refn", "pix");
  for (const std::string& requested : cl.GetStringList("--scenes"))
  {
    AccuracyScene s;
    if (IsObjSceneName(requested))
    {
      double up[3] = { 0.0, 1.0, 0.0 }, degrees = 0.0;
      try
      {
        s = MakeObjAccuracyScene(requested);
      }
      catch (const std::exception& e)
      {
        std::cerr << "mesolight bench vlf-accuracy: " << e.what() << "\n";
        return 1;
      }
      glm::vec3 lower, upper;
      SceneBounds(s.Scene, lower, upper);
      if (!ReadCameraOptions(cl, lower, upper, s.Camera.Position, s.Camera.FocalPoint, up, error) ||
        !ReadViewAngle(cl, degrees, error))
      {
        return cl.UsageError(error);
      }
      s.Camera.ViewUp = glm::vec3(up[0], up[1], up[2]);
      s.Camera.ViewAngleDegrees = static_cast<float>(degrees);
    }
    else
    {
      try
      {
        s = MakeAccuracyScene(requested);
      }
      catch (const std::exception& e)
      {
        return cl.UsageError(e.what());
      }
    }
    const std::string& name = s.Name;
    const EmbreeScene embree(s.Scene);
    const std::vector<PixelHit> hits = PrimaryHits(s, embree, width, height);
    std::printf(
      "# %s: %s, %zu triangles\n", name.c_str(), s.Description.c_str(), s.Scene.TriangleCount());
    std::fflush(stdout);
    RgbImage a, b;
    const int sceneSamples = samples * s.ReferenceSamplesScale;
    const std::string key = cache + "/" + name + "-" + SceneDigest(s) + "-" +
      std::to_string(width) + "x" + std::to_string(height) + "-" + std::to_string(sceneSamples);
    std::printf("# %s: reference %s-{a,b}.exr\n", name.c_str(), key.c_str());
    std::fflush(stdout);
    if (!(FileExists(key + "-a.exr") && ReadLinearImage(key + "-a.exr", a, error) &&
          ReadLinearImage(key + "-b.exr", b, error) && a.Width == width && b.Width == width))
    {
      const Clock::time_point start = Clock::now();
      a = ReferenceHalf(embree, hits, width, height, sceneSamples / 2, 1);
      b = ReferenceHalf(embree, hits, width, height, sceneSamples / 2, 2);
      std::printf("# %s: path-traced reference, %d paths per pixel, %.1f s (cached in %s-*.exr)\n",
        name.c_str(), sceneSamples, SecondsSince(start), key.c_str());
      if (!WriteLinearImage(a, key + "-a.exr", error) ||
        !WriteLinearImage(b, key + "-b.exr", error))
      {
        std::cerr << "mesolight bench vlf-accuracy: " << error << "\n";
      }
    }
    for (const std::string& text : settingsList)
    {
      vlf::LightFieldSettings settings;
      std::string note;
      if (!ParseSettings(text, s.Scene, budget, settings, note))
      {
        return cl.UsageError("--settings: '" + text +
          "' is not auto, KxN or KxNtF (or auto-uniform, auto-adaptive, auto-adaptive-first, "
          "auto-refine, auto-adaptive-unbounded, auto-adaptive-bF, auto-adaptive-coarsen, "
          "auto-adaptive-513)");
      }
      if (!note.empty())
      {
        std::printf("# %s auto: %s\n", name.c_str(), note.c_str());
        std::fflush(stdout);
      }
      try
      {
        const Clock::time_point start = Clock::now();
        if (text.rfind("auto-adaptive", 0) == 0 || text == "auto-refine")
        {
          // The first pass's time counts as the build's.
          vlf::AdaptiveTexelReport report;
          vlf::AdaptiveTexelOptions adaptive;
          AdaptiveOptions(text, adaptive);
          settings = vlf::ChooseAdaptiveTexels(s.Scene, settings, adaptive, &report);
          std::printf("# %s %s: %s, first pass %s\n", name.c_str(), text.c_str(),
            report.Describe().c_str(), FormatBytes(report.FirstPassBytes).c_str());
          std::ostringstream levels;
          for (std::size_t i = 0; i < report.Variation.size(); ++i)
          {
            const vlf::SurfaceVariation& v = report.Variation[i];
            if (v.Samples > 0)
            {
              levels << ' ' << i << ':' << static_cast<int>(settings.SurfaceTexelLevels[i]) << '('
                     << std::fixed << std::setprecision(1) << 100.0 * v.Defect << '/'
                     << 100.0 * v.Noise << "%)";
            }
          }
          std::printf("# %s %s: surface:level(defect/noise):%s\n", name.c_str(), text.c_str(),
            levels.str().c_str());
          std::fflush(stdout);
        }
        const vlf::MemoryEstimate estimate = vlf::EstimateMemory(s.Scene, settings);
        std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(s.Scene, settings);
        const double build = SecondsSince(start);
        const Clock::time_point propagateStart = Clock::now();
        vlf::PropagateToTolerance(*field, vlf::DefaultTolerance, vlf::DefaultMaxIterations);
        const double propagate = SecondsSince(propagateStart);
        const std::uint64_t allocated = field->AllocatedBytes();
        // The estimate (what the automatic settings budget with) against what the field
        // holds while it propagates: its structure plus one texture of flux per worker block.
        const std::uint64_t peak = allocated +
          vlf::DefaultBlockCount(field->SubfieldCount()) * field->TexelCount() * sizeof(glm::vec3);
        std::printf("# %s %s: memory estimate %s, propagation peak %s (estimate / peak %.2f)\n",
          name.c_str(), text.c_str(), FormatBytes(estimate.TotalBytes).c_str(),
          FormatBytes(peak).c_str(),
          static_cast<double>(estimate.TotalBytes) / static_cast<double>(peak));
        const double texelWorld =
          (settings.TexelSize > 0.0f ? settings.TexelSize : settings.CellSize()) /
          field->NormalizationScale();
        if (settings.ContactTexelHalvings > 0)
        {
          // The surfaces that got finer texels (LightFieldSettings::ContactTexelHalvings).
          std::size_t finer = 0, finerTexels = 0;
          for (const vlf::Surface& surface : field->Surfaces())
          {
            if (surface.TexelU / field->NormalizationScale() < 0.75 * texelWorld)
            {
              ++finer;
              finerTexels += surface.TexelCount();
            }
          }
          std::printf("# %s %s: texels halved %d time(s) on %zu of %zu surfaces (others stand on "
                      "them): %zu of %zu texels\n",
            name.c_str(), text.c_str(), settings.ContactTexelHalvings, finer,
            field->Surfaces().size(), finerTexels, field->TexelCount());
        }
        const std::uint64_t lines = static_cast<std::uint64_t>(settings.Directions) *
          settings.RaysPerSide * settings.RaysPerSide;
        // The filter changes the totals for good: it runs last.
        std::vector<std::string> order;
        for (const char* v : { "none", "single", "gather", "gather-bilateral", "bilateral" })
        {
          if (std::find(variants.begin(), variants.end(), v) != variants.end())
          {
            if (std::string(v) == "gather" && gatherRayCounts.size() > 1)
            {
              for (const int rays : gatherRayCounts)
              {
                order.push_back("gather" + std::to_string(rays));
              }
            }
            else
            {
              order.push_back(v);
            }
          }
        }
        for (const std::string& variant : order)
        {
          const bool filtered = variant == "bilateral";
          const bool single = variant == "single";
          // The filter on top of the gathered textures (the gather at the first ray count).
          const bool gatherFiltered = variant == "gather-bilateral";
          gatherOptions.Prepass = !single;
          gatherOptions.IndirectRays =
            variant.size() > 6 && variant.compare(0, 6, "gather") == 0 && !gatherFiltered
            ? std::atoi(variant.c_str() + 6)
            : gatherRayCounts.front();
          double gatherSeconds = 0.0;
          std::uint64_t gatherRays = 0;
          vlf::RestorePropagatedDiffuse(*field);
          if (filtered)
          {
            vlf::FilterTotalDiffuse(*field, vlf::TextureFilterSettings());
          }
          if (single || variant.compare(0, 6, "gather") == 0)
          {
            const vlf::FinalGatherReport g = vlf::FinalGather(*field, gatherOptions);
            if (gatherFiltered)
            {
              vlf::FilterTotalDiffuse(*field, vlf::TextureFilterSettings());
            }
            gatherSeconds = g.Seconds;
            gatherRays = g.Rays;
            std::printf("# %s %s gather: %zu texels gathered, %zu filled from neighbours, "
                        "%.3g rays, %.1f s (%.2f x build + propagation), +%s for the "
                        "propagated totals\n",
              name.c_str(), text.c_str(), g.Texels, g.Filled, static_cast<double>(g.Rays),
              g.Seconds, g.Seconds / (build + propagate),
              FormatBytes(field->PropagatedDiffuse.size() * sizeof(glm::vec3)).c_str());
          }
          const RgbImage image = FieldImage(*field, hits, width, height);
          const PixelError e = ComparePixels(hits, image, a, b);
          std::printf("# %s %s %s: %s\n", name.c_str(), text.c_str(), variant.c_str(),
            ErrorBreakdown(*field, hits, width, height, image, a, b).c_str());
          std::printf("# %s %s %s: by class: %s\n", name.c_str(), text.c_str(), variant.c_str(),
            ClassBreakdown(*field, s, embree, hits, static_cast<float>(texelWorld), image, a, b)
              .c_str());
          if (!cl.Get("--images").empty())
          {
            const std::string base = cl.Get("--images") + "/" + name + "-" + text +
              (variant == "none" ? "" : "-" + variant);
            WriteLinearImage(image, base + ".exr", error);
          }
          std::printf("%-9s %-12s %6zu %4d %8.3f %9.3g %7d %7.1f %8s %9s %5.1f%% %6.1f%% %5.2f%% "
                      "%5.1f%% %6zu\n",
            name.c_str(), text.c_str(), settings.Directions, settings.RaysPerSide, texelWorld,
            static_cast<double>(lines), field->IterationsDone, build + propagate + gatherSeconds,
            FormatBytes(allocated).c_str(), variant.c_str(), 100.0 * e.Mean, 100.0 * e.P95,
            100.0 * e.Black, 100.0 * e.ReferenceNoise, e.Pixels);
          std::fflush(stdout);
          csv << name << ',' << text << ',' << settings.Directions << ',' << settings.RaysPerSide
              << ',' << settings.TilesPerSide << ',' << texelWorld << ',' << lines << ','
              << field->Surfaces().size() << ',' << field->TexelCount() << ',' << estimate.MapCells
              << ',' << field->IterationsDone << ',' << build << ',' << propagate << ','
              << build + propagate << ',' << allocated << ',' << estimate.TotalBytes << ','
              << variant << ',' << gatherSeconds << ',' << gatherRays << ',' << e.Pixels << ','
              << e.Mean << ',' << e.P95 << ',' << e.Black << ',' << e.ReferenceNoise << ',' << peak
              << '\n';
          if (variant != "bilateral" && variant != "gather-bilateral")
          {
            const std::string label = name + (variant == "none" ? "" : " " + variant);
            ChartSeries& cs = series[label];
            cs.Name = label;
            cs.X.push_back(build + propagate + gatherSeconds);
            cs.Y.push_back(100.0 * e.Mean);
          }
        }
      }
      catch (const std::exception& ex)
      {
        std::printf("%-9s %-12s skipped: %s\n", name.c_str(), text.c_str(), ex.what());
      }
    }
    if (!cl.Get("--images").empty())
    {
      RgbImage mean(width, height);
      for (std::size_t i = 0; i < mean.Rgb.size(); ++i)
      {
        mean.Rgb[i] = 0.5f * (a.Rgb[i] + b.Rgb[i]);
      }
      WriteLinearImage(mean, cl.Get("--images") + "/" + name + "-reference.exr", error);
    }
  }
  if (!cl.Get("--csv").empty())
  {
    std::ofstream file(cl.Get("--csv"));
    file << csv.str();
    if (!file)
    {
      std::cerr << "mesolight bench vlf-accuracy: could not write " << cl.Get("--csv") << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--csv") << "\n";
  }
  if (!cl.Get("--plot").empty())
  {
    ScatterChart chart;
    chart.Title = "Light field vs path tracer: mean per-pixel relative error vs build + "
                  "propagation (+ gather) time";
    chart.XLabel = "build + propagation (+ final gather) seconds";
    chart.YLabel = "mean relative error per pixel (%)";
    chart.LogY = true;
    chart.YFloor = 0.5;
    for (auto& entry : series)
    {
      chart.Points.push_back(entry.second);
    }
    if (!WriteScatterChartPng(chart, cl.Get("--plot"), error))
    {
      std::cerr << "mesolight bench vlf-accuracy: " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--plot") << "\n";
  }
  return 0;
}

} // namespace mesolight
