// SPDX-License-Identifier: BSD-3-Clause
#include "VlfCommand.h"

#include "AnalyticCases.h"
#include "ChartPlot.h"
#include "CommandLine.h"
#include "CornellRegions.h"
#include "DisplayTransform.h"
#include "LightFieldCamera.h"
#include "LightFieldViewCommand.h"
#include "OutputFile.h"
#include "Timing.h"
#include "VlfRelief.h"

#include "Distribution.h"
#include "EmbreeScene.h"
#include "LightField.h"
#include "Lookup.h"
#include "MathConstants.h"
#include "ObjScene.h"
#include "ParallelFor.h"
#include "PatchComparison.h"
#include "PathTracer.h"
#include "Propagation.h"
#include "Snapshot.h"
#include "TextureComparison.h"
#include "TriangleScene.h"
#include "vtkLightFieldReducer.h"

#include <vtkImageData.h>
#include <vtkMultiProcessController.h>
#include <vtkNew.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkUnsignedCharArray.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <cstdlib>
#include <fstream>
#include <functional>
#include <iostream>
#include <map>
#include <memory>
#include <sstream>

namespace mesolight
{
namespace
{
// The field of one sweep configuration: `directions` x `rays`^2 lines in (rays / 8)^2 tiles.
vlf::LightFieldSettings SweepSettings(int directions, int rays)
{
  vlf::LightFieldSettings settings;
  settings.Directions = static_cast<std::size_t>(directions);
  settings.RaysPerSide = rays;
  settings.TilesPerSide = std::max(1, rays / 8);
  return settings;
}

namespace vlf = mesolight::vlf;
using Clock = std::chrono::steady_clock;

// Peak resident memory since the last reset (Linux: VmHWM; writing 5 to clear_refs resets it).
std::uint64_t PeakResidentBytes()
{
  std::ifstream status("/proc/self/status");
  std::string line;
  while (std::getline(status, line))
  {
    if (line.compare(0, 6, "VmHWM:") == 0)
    {
      return std::strtoull(line.c_str() + 6, nullptr, 10) * 1024;
    }
  }
  return 0;
}
void ResetPeakResident()
{
  std::ofstream clear("/proc/self/clear_refs");
  clear << "5";
}

int Render(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight vlf render",
    "mesolight vlf render FIELD --out IMAGE.png [options]\n\n"
    "Renders a light field's diffuse totals (Wither's progressive mode: per-surface "
    "total diffuse\ntextures, bilinear) by casting a ray per pixel; mirror surfaces "
    "show the field's radiance\ntoward the eye (three-direction spherical "
    "interpolation).\n"
    "Under mpiexec -n N the ranks split the image's rows and the field's directions: a "
    "mirror pixel\nasks the owners of the directions around its view (vlf::RadianceLeaving); "
    "rank 0 writes.\n");
  cl.AddValue("--out", "IMAGE.png", "where to write the image (required)");
  cl.AddValue("--size", "WxH", "image size in pixels", "512x512");
  AddLightFieldCameraOptions(cl);
  cl.AddValue("--exposure", "X", "radiance scale before the sRGB curve", "1");
  cl.AddValue("--exr", "FILE.exr", "also write the linear radiance");
  cl.AddValue("--compare-exr", "FILE.exr",
    "built-in Cornell box field: compare per region with another renderer's linear image of the "
    "Cornell camera (e.g. Blender Cycles)");
  cl.AddValue("--tolerance", "X", "relative tolerance of --compare-exr", "0.1");
  cl.AddFlag("--force", "replace an existing IMAGE.png");
  cl.AddValue("--relief", "SURFACE=DEPTH_IMAGE",
    "repeatable: draw the named surface of the field's scene as a relief (depth image, 0 = top, "
    "1 = deepest) lit per pixel by the field: indirect light as SH9 at the relief's perturbed "
    "normal, direct light from the field's emitters with the relief's self-shadowing");
  cl.AddValue("--relief-depth-scale", "K",
    "world depth of depth 1 over the world width of the relief's texture", "0.05");
  cl.AddFlag("--relief-height", "the relief images store height (white = high), not depth");
  cl.AddFlag("--relief-normalize", CommandLine::ReliefNormalizeHelp);
  cl.AddValue("--relief-probes", "N", ReliefProbesHelp(), "0");
  cl.AppliesOnlyWith("--relief-normalize", { "--relief" });
  cl.AppliesOnlyWith("--relief-depth-scale", { "--relief" });
  cl.AppliesOnlyWith("--relief-height", { "--relief" });
  cl.AppliesOnlyWith("--relief-probes", { "--relief" });
  // --help lists the --mode renderer's options too (--tone-map, --object, ...): say they need it.
  cl.SetUnknownOptionHint(
    "see --help: the options listed under 'With --mode' need --mode MODE, the GPU renderer");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (cl.Positional().size() != 1 || cl.Get("--out").empty())
  {
    return cl.UsageError("give one FIELD and --out IMAGE.png");
  }
  const std::string out = cl.Get("--out");
  // Each output checked against the inputs and the other output, the message naming its option.
  std::vector<std::string> inputs{ cl.Positional()[0], cl.Get("--compare-exr") };
  for (const std::string& item : cl.GetAll("--relief"))
  {
    const std::size_t equals = item.find('=');
    if (equals != std::string::npos)
    {
      inputs.push_back(item.substr(equals + 1));
    }
  }
  std::string problem = CheckOutputOptions(cl, { "--out", "--exr" }, inputs);
  if (problem.empty())
  {
    problem = CheckImageOutputNames(cl);
  }
  if (!problem.empty())
  {
    return cl.UsageError(problem);
  }
  if (vlf::FileExists(out) && !cl.Has("--force"))
  {
    std::cerr << "mesolight vlf render: '" << out << "' exists; add --force to replace it\n";
    return 1;
  }
  int width = 0, height = 0;
  if (!cl.GetSize("--size", 1, 16384, width, height, error))
  {
    return cl.UsageError(error);
  }
  double viewAngle = 0.0, exposure = 0.0, tolerance = 0.1;
  FieldReliefOptions reliefOptions;
  reliefOptions.DepthIsHeight = cl.Has("--relief-height");
  reliefOptions.NormalizeDepth = cl.Has("--relief-normalize");
  if (!ReadViewAngle(cl, viewAngle, error) ||
    !cl.GetDouble("--exposure", 0.0, 1e9, exposure, error) ||
    !cl.GetDouble("--tolerance", 0.0, 10.0, tolerance, error) ||
    !cl.GetDouble("--relief-depth-scale", 0.0, 10.0, reliefOptions.DepthScale, error) ||
    !cl.GetInt("--relief-probes", 0, 256, reliefOptions.Probes, error))
  {
    return cl.UsageError(error);
  }
  // Under mpiexec every rank reads the field and keeps its own directions (Distribution.h).
  vlf::ControllerReducer reducer;
  const bool distributed = reducer.Size() > 1;
  const bool root = reducer.Rank() == 0;
  if (distributed && !cl.GetAll("--relief").empty())
  {
    // A relief pixel integrates the incident radiance over every direction at its point; on a
    // distributed field each rank holds only its own directions.
    if (root)
    {
      std::cerr << "mesolight vlf render: --relief needs the whole field on one process: run it "
                   "without mpiexec (the field file is the same)\n";
    }
    return 2;
  }
  try
  {
    std::unique_ptr<vlf::LightField> field;
    vlf::Agree(reducer,
      [&]()
      {
        field = vlf::ReadSnapshot(cl.Positional()[0]);
        vlf::KeepOwnedSubfields(*field, reducer);
      });
    const TriangleScene& unit = field->Scene();
    glm::vec3 eye, focal;
    double up[3] = { 0.0, 1.0, 0.0 };
    if (!ReadLightFieldCamera(cl, *field, eye, focal, up, error))
    {
      return cl.UsageError(error);
    }
    // Camera frame in the field's unit-sphere coordinates.
    const glm::vec3 eyeUnit = vlf::ToUnit(*field, eye);
    const glm::vec3 forward = glm::normalize(vlf::ToUnit(*field, focal) - eyeUnit);
    glm::vec3 right = glm::cross(forward, glm::vec3(up[0], up[1], up[2]));
    if (!(glm::length(right) > 1e-6f))
    {
      return cl.UsageError("the view-up direction is parallel to the view direction");
    }
    right = glm::normalize(right);
    const glm::vec3 trueUp = glm::cross(right, forward);
    const float tanHalf = static_cast<float>(std::tan(0.5 * viewAngle * Pi<double> / 180.0));
    const float aspect = static_cast<float>(width) / static_cast<float>(height);

    const EmbreeScene embree(unit);
    const vlf::Lookup lookup(*field);
    std::vector<FieldRelief> reliefs;
    try
    {
      reliefs = SetUpFieldReliefs(*field, embree, cl.GetAll("--relief"), reliefOptions);
    }
    catch (const ReliefSetupError& e)
    {
      std::cerr << "mesolight vlf render: " << e.what() << "\n";
      return 2;
    }
    const std::vector<int> reliefOf = ReliefOfTriangle(*field, reliefs);
    std::vector<unsigned char> pixels(static_cast<std::size_t>(width) * height * 3);
    RgbImage linear(width, height);
    // Exposure, clamp and sRGB: the light field actor's default display (vtkLightFieldActor).
    const DisplayTransform display{ exposure, ToneMapOperator::Clamp, true };
    const Clock::time_point start = Clock::now();
    const std::uint64_t bytesBefore = reducer.BytesContributed();
    // This rank's rows; mirror pixels are looked up afterwards, all together (their directions
    // may be held by other ranks).
    const std::size_t firstRow = static_cast<std::size_t>(height) *
      static_cast<std::size_t>(reducer.Rank()) / static_cast<std::size_t>(reducer.Size());
    const std::size_t lastRow = static_cast<std::size_t>(height) *
      static_cast<std::size_t>(reducer.Rank() + 1) / static_cast<std::size_t>(reducer.Size());
    std::vector<std::uint32_t> mirrorPixel(static_cast<std::size_t>(width) * height, 0xffffffffu);
    std::vector<std::vector<std::pair<std::size_t, vlf::RadianceQuery>>> mirrorsOfRow(
      static_cast<std::size_t>(height));
    ParallelFor(firstRow, lastRow, 1,
      [&](std::size_t r0, std::size_t r1)
      {
        for (std::size_t row = r0; row < r1; ++row)
        {
          for (int column = 0; column < width; ++column)
          {
            const float sx = (2.0f * (column + 0.5f) / width - 1.0f) * tanHalf * aspect;
            const float sy = (2.0f * (row + 0.5f) / height - 1.0f) * tanHalf;
            SceneRay ray;
            ray.Origin = eyeUnit;
            ray.Direction = glm::normalize(forward + sx * right + sy * trueUp);
            const SceneHit hit = embree.Intersect(ray);
            glm::vec3 radiance(0.0f);
            if (hit.Hit())
            {
              const std::uint32_t s = field->SurfaceOfTriangle(hit.Triangle);
              const glm::vec3 p = ray.Origin + hit.T * ray.Direction;
              const SceneMaterial& m = unit.MaterialOf(hit.Triangle);
              const bool front =
                s != vlf::NoSurface && glm::dot(field->Surfaces()[s].Normal, ray.Direction) < 0.0f;
              const int relief = reliefOf[hit.Triangle];
              if (front && relief >= 0 &&
                ReliefRadiance(
                  reliefs[static_cast<std::size_t>(relief)], ray.Origin, ray.Direction, radiance))
              {
                // drawn by the relief
              }
              else if (front && glm::length(m.Specular) > 0.0f)
              {
                vlf::RadianceQuery query;
                query.Surface = s;
                query.Point = p;
                query.Toward = -ray.Direction;
                mirrorsOfRow[row].emplace_back(
                  row * static_cast<std::size_t>(width) + static_cast<std::size_t>(column), query);
              }
              else if (front)
              {
                radiance = lookup.DiffuseRadiance(s, p);
              }
            }
            // Row 0 of a VTK image is the bottom row.
            float* value = linear.Pixel(column, static_cast<int>(row));
            for (int c = 0; c < 3; ++c)
            {
              value[c] = radiance[c];
            }
          }
        }
      });
    // The mirrors: every rank's pixels answered by the owners of their directions.
    std::vector<vlf::RadianceQuery> queries;
    std::vector<std::size_t> queryPixel;
    for (const auto& rowQueries : mirrorsOfRow)
    {
      for (const auto& q : rowQueries)
      {
        queryPixel.push_back(q.first);
        queries.push_back(q.second);
      }
    }
    const Clock::time_point lookupStart = Clock::now();
    const std::uint64_t lookupBytesBefore = reducer.BytesContributed();
    const std::vector<glm::vec3> mirrored = vlf::RadianceLeaving(*field, queries, reducer);
    const double lookupSeconds = SecondsSince(lookupStart);
    std::uint64_t lookupBytes = reducer.BytesContributed() - lookupBytesBefore;
    for (std::size_t q = 0; q < queries.size(); ++q)
    {
      float* value = linear.Pixel(static_cast<int>(queryPixel[q] % static_cast<std::size_t>(width)),
        static_cast<int>(queryPixel[q] / static_cast<std::size_t>(width)));
      for (int c = 0; c < 3; ++c)
      {
        value[c] = mirrored[q][c];
      }
    }
    // Every rank's rows onto every rank (the others' rows are zero here): one sum.
    if (distributed)
    {
      reducer.SumInPlace(linear.Rgb.data(), linear.Rgb.size());
    }
    const double frameSeconds = SecondsSince(start);
    std::uint64_t frameBytes = reducer.BytesContributed() - bytesBefore;
    double mirrorPixels = static_cast<double>(queries.size());
    if (distributed)
    {
      double totals[3] = { static_cast<double>(frameBytes), mirrorPixels,
        static_cast<double>(lookupBytes) };
      reducer.SumInPlace(totals, 3);
      frameBytes = static_cast<std::uint64_t>(totals[0]);
      mirrorPixels = totals[1];
      lookupBytes = static_cast<std::uint64_t>(totals[2]);
    }
    for (std::size_t i = 0; i < pixels.size() / 3; ++i)
    {
      const float* value = linear.Pixel(static_cast<int>(i % static_cast<std::size_t>(width)),
        static_cast<int>(i / static_cast<std::size_t>(width)));
      for (int c = 0; c < 3; ++c)
      {
        pixels[3 * i + c] = static_cast<unsigned char>(
          std::lround(255.0 * ApplyDisplayTransform<double>(display, value[c])));
      }
    }
    if (!root)
    {
      return 0; // rank 0 writes
    }
    if (vtkMultiProcessController::GetGlobalController()) // under mpiexec, even one rank
    {
      std::cout << "MPI: " << reducer.Size() << " ranks, frame " << frameSeconds
                << " s (mirror lookups " << lookupSeconds << " s on rank 0), "
                << static_cast<std::uint64_t>(mirrorPixels)
                << " mirror pixels; sent by all ranks: " << lookupBytes
                << " bytes for the lookups, " << frameBytes - lookupBytes
                << " bytes for the image sum\n";
    }
    vtkNew<vtkImageData> image;
    image->SetDimensions(width, height, 1);
    vtkNew<vtkUnsignedCharArray> colours;
    colours->SetNumberOfComponents(3);
    colours->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
    std::copy(pixels.begin(), pixels.end(), colours->GetPointer(0));
    image->GetPointData()->SetScalars(colours);
    vtkNew<vtkPNGWriter> writer;
    writer->SetInputData(image);
    writer->SetFileName(out.c_str());
    writer->Write();
    if (writer->GetErrorCode() != 0)
    {
      std::cerr << "mesolight vlf render: could not write '" << out << "'\n";
      return 1;
    }
    std::cout << "wrote " << out << " (" << width << "x" << height << ", " << SecondsSince(start)
              << " s, light field after " << field->IterationsDone << " iterations)\n";
    WarnIfAllBlack("mesolight vlf render", linear.Rgb, cl);
    if (cl.Has("--exr"))
    {
      if (!WriteLinearImage(linear, cl.Get("--exr"), error))
      {
        std::cerr << "mesolight vlf render: " << error << "\n";
        return 1;
      }
      std::cout << "wrote " << cl.Get("--exr") << " (linear radiance)\n";
    }
    if (cl.Has("--compare-exr"))
    {
      const TriangleScene box = MakeCornellBox();
      RgbImage theirs;
      if (field->Scene().TriangleCount() != box.TriangleCount())
      {
        std::cerr << "mesolight vlf render: --compare-exr compares the built-in Cornell box only\n";
        return 2;
      }
      if (!ReadLinearImage(cl.Get("--compare-exr"), theirs, error))
      {
        std::cerr << "mesolight vlf render: " << error << "\n";
        return 1;
      }
      if (!CompareCornellRegions(box, linear, theirs, tolerance))
      {
        return 1;
      }
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "mesolight vlf render: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

} // namespace

int RunVlfRender(const std::vector<std::string>& args)
{
  // With --mode the image goes through vtkLightFieldActor (reliefs by vtkReliefMapper, lit by
  // the field: LightFieldReliefs.h); without, this CPU reference renders it.
  const auto mode = std::find(args.begin(), args.end(), "--mode");
  if (mode != args.end())
  {
    return RunLightFieldRender(args);
  }
  // The help shows both renderers: the walkthrough's options (--mode, --object, ...) are found
  // from here, not only once --mode is given.
  if (std::find(args.begin(), args.end(), "--help") != args.end())
  {
    const int status = Render(args);
    if (status == 0)
    {
      std::cout << "\nWith --mode:\n\n";
      std::cout.flush();
      return RunLightFieldRender({ "--help" });
    }
    return status;
  }
  return Render(args);
}

namespace
{
// The Cornell box reference: the path tracer's diffuse radiance leaving each point (all bounces,
// next-event estimation; vtkRayTracing/core/PathTracer.h), 256 paths per point.
vlf::ReferenceRadiance CornellReference(const TriangleScene& world)
{
  auto scene = std::make_shared<TriangleScene>(world);
  auto embree = std::make_shared<EmbreeScene>(*scene);
  auto tracer = std::make_shared<PathTracer>(*embree);
  return [scene, embree, tracer](std::uint32_t triangle, const glm::vec3& point)
  {
    const std::uint64_t seed = (static_cast<std::uint64_t>(triangle) << 32) ^
      std::hash<float>{}(point.x) ^ (std::hash<float>{}(point.y) << 1) ^
      (std::hash<float>{}(point.z) << 2);
    return tracer->DiffuseRadianceLeaving(triangle, point, 256, seed);
  };
}

// Path-traced reference at every texel centre of the Cornell box field, `samples` paths each; the
// seed depends on the texel and `seed`, so two seeds give two independent references.
std::vector<glm::vec3> CornellTexelReference(const TriangleScene& world,
  const vlf::LightField& field, const std::vector<vlf::TexelPoint>& texels, int samples,
  std::uint64_t seed)
{
  EmbreeScene embree(world);
  PathTracer tracer(embree);
  std::vector<glm::vec3> out(texels.size());
  ParallelFor(0, texels.size(), 16,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t i = begin; i < end; ++i)
      {
        out[i] = tracer.DiffuseRadianceLeaving(texels[i].Triangle,
          vlf::ToWorld(field, texels[i].Unit), samples, seed * 0x9e3779b97f4a7c15ull + i);
      }
    });
  return out;
}

// bench vlf --texels: per-texel error of the Cornell box's total diffuse textures against the
// path tracer, filter off and on, with propagation time.
int TexelSweep(const std::vector<int>& directionList, const std::vector<int>& rayList,
  int iterations, int samples, const vlf::TextureFilterSettings& filter, const std::string& csvPath)
{
  std::ostringstream csv;
  csv
    << "directions,rays,filter,texels,propagate_s,filter_s,mean_error,p95_error,"
       "contrast_mean_error,contrast_p95_error,reference_noise_p95,reference_noise_contrast_p95\n";
  std::printf("%10s %5s %6s %7s %11s %8s %8s %8s %9s %9s %10s %10s\n", "directions", "rays",
    "filter", "texels", "propagate s", "filter s", "mean", "p95", "contr mean", "contr p95",
    "ref p95", "ref contr");
  const TriangleScene cornell = MakeCornellBox();
  for (const int directions : directionList)
  {
    for (const int rays : rayList)
    {
      vlf::LightFieldSettings settings = SweepSettings(directions, rays);
      std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(cornell, settings);
      double propagate = 0.0;
      for (int it = 0; it < iterations; ++it)
      {
        propagate += vlf::PropagateIteration(*field).Seconds;
      }
      const std::vector<vlf::TexelPoint> texels = vlf::SurfaceTexels(*field);
      const std::vector<glm::vec3> reference =
        CornellTexelReference(cornell, *field, texels, samples, 1);
      // The reference's own noise: a second, independent reference against the first (the
      // difference of two estimates, so sqrt(2) times one estimate's noise).
      const std::vector<glm::vec3> second =
        CornellTexelReference(cornell, *field, texels, samples, 2);
      const vlf::TexelError noise = vlf::CompareTexels(*field, texels, second, reference);
      for (int on = 0; on < 2; ++on)
      {
        double filterSeconds = 0.0;
        if (on)
        {
          const Clock::time_point start = Clock::now();
          vlf::FilterTotalDiffuse(*field, filter);
          filterSeconds = SecondsSince(start);
        }
        const vlf::TexelError e =
          vlf::CompareTexels(*field, texels, vlf::FieldAtTexels(*field, texels), reference);
        std::printf(
          "%10d %5d %6s %7zu %11.2f %8.3f %7.2f%% %7.2f%% %8.2f%% %8.2f%% %9.2f%% %9.2f%%\n",
          directions, rays, on ? "on" : "off", e.Texels, propagate, filterSeconds, 100.0 * e.Mean,
          100.0 * e.P95, 100.0 * e.ContrastMean, 100.0 * e.ContrastP95, 100.0 * noise.P95,
          100.0 * noise.ContrastP95);
        std::fflush(stdout);
        csv << directions << ',' << rays << ',' << (on ? "on" : "off") << ',' << e.Texels << ','
            << propagate << ',' << filterSeconds << ',' << e.Mean << ',' << e.P95 << ','
            << e.ContrastMean << ',' << e.ContrastP95 << ',' << noise.P95 << ','
            << noise.ContrastP95 << '\n';
      }
    }
  }
  if (!csvPath.empty())
  {
    if (vlf::FileExists(csvPath))
    {
      std::cerr << "mesolight bench vlf: '" << csvPath << "' exists; it is left alone\n";
      return 1;
    }
    std::ofstream file(csvPath);
    file << csv.str();
    if (!file)
    {
      std::cerr << "mesolight bench vlf: could not write " << csvPath << "\n";
      return 1;
    }
    std::cout << "wrote " << csvPath << "\n";
  }
  return 0;
}

} // namespace

int RunVlfBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench vlf",
    "mesolight bench vlf [options]\n\nPropagation time and peak memory of the Cornell "
    "box light field per direction count,\nrays per side and iteration; accuracy of "
    "the same settings on analytic cases (floor under\na square emitter vs the form "
    "factor; furnace vs Le/(1-rho)).\n");
  cl.AddValue("--directions", "N,N,..", "direction counts (2n^2+1)", "513,2049");
  cl.AddValue("--rays", "N,N,..", "lines per subfield side", "32,64,128");
  cl.AddValue("--iterations", "K", "shooting iterations (each one timed)", "4");
  cl.AddValue("--memory-budget", "GIB", "skip configurations needing more", "6");
  cl.AddValue("--csv", "FILE", "write the rows as CSV");
  cl.AddValue("--plot", "FILE.png", "plot time vs rays (and FILE-error.png: error vs rays)");
  cl.AddFlag("--texels",
    "instead: per-texel error of the Cornell box's diffuse textures vs the "
    "path tracer, texture filter off and on");
  cl.AddValue("--samples", "N", "--texels: path-traced samples per texel", "1024");
  cl.AddValue("--filter-radius", "R", "--texels: filter window (2R+1)^2 texels", "2");
  cl.AddValue("--filter-range", "S", "--texels: filter range sigma (relative difference)", "0.25");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, {});
      !problem.empty())
  {
    return cl.UsageError(problem);
  }
  std::vector<int> directionList, rayList;
  int iterations = 0;
  double budget = 0.0;
  if (!cl.GetIntList("--directions", 3, 1 << 26, directionList, error) ||
    !cl.GetIntList("--rays", 8, 4096, rayList, error) ||
    !cl.GetInt("--iterations", 1, 1000, iterations, error) ||
    !cl.GetDouble("--memory-budget", 1e-3, 1e6, budget, error))
  {
    return cl.UsageError(error);
  }
  if (cl.Has("--texels"))
  {
    int samples = 0;
    vlf::TextureFilterSettings filter;
    double range = 0.0;
    if (!cl.GetInt("--samples", 1, 1 << 20, samples, error) ||
      !cl.GetInt("--filter-radius", 1, 64, filter.Radius, error) ||
      !cl.GetDouble("--filter-range", 0.0, 1e6, range, error))
    {
      return cl.UsageError(error);
    }
    filter.RangeSigma = static_cast<float>(range);
    try
    {
      return TexelSweep(directionList, rayList, iterations, samples, filter, cl.Get("--csv"));
    }
    catch (const std::exception& ex)
    {
      std::cerr << "mesolight bench vlf: " << ex.what() << "\n";
      return 1;
    }
  }
  ResetPeakResident();
  std::printf("process resident memory before any light field: %s (VTK, Embree, TBB loaded)\n",
    FormatBytes(PeakResidentBytes()).c_str());
  std::ostringstream csv;
  csv
    << "directions,rays,tiles,iteration,build_s,propagate_s,total_s,estimate_bytes,allocated_bytes,"
       "peak_rss_bytes,energy_error,floor_mean_error,floor_rms_error,furnace_error,cornell_error\n";
  std::map<int, ChartSeries> timeSeries, errorSeries;
  std::printf("%10s %5s %5s %4s %9s %11s %9s %11s %11s %10s %9s %9s %9s\n", "directions", "rays",
    "tiles", "iter", "build s", "propagate s", "total s", "estimate", "peak RSS", "energy err",
    "floor err", "floor rms", "furnace");
  for (const int directions : directionList)
  {
    for (const int rays : rayList)
    {
      vlf::LightFieldSettings settings = SweepSettings(directions, rays);
      settings.MemoryBudget = static_cast<std::uint64_t>(budget * 1073741824.0);
      try
      {
        struct Row
        {
          int Iteration;
          double Energy, Propagate;
          std::uint64_t Peak, Allocated;
          std::string Cornell;
        };
        std::vector<Row> rows;
        const TriangleScene cornell = MakeCornellBox();
        const vlf::MemoryEstimate estimate = vlf::EstimateMemory(cornell, settings);
        ResetPeakResident();
        const Clock::time_point start = Clock::now();
        std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(cornell, settings);
        const double build = SecondsSince(start);
        double propagate = 0.0;
        for (int it = 1; it <= iterations; ++it)
        {
          const vlf::LightField::IterationEnergy e = vlf::PropagateIteration(*field);
          propagate += e.Seconds;
          std::string cornellError = "n/a";
          const vlf::ReferenceRadiance reference = CornellReference(cornell);
          if (reference && it == iterations)
          {
            const vlf::PatchComparisonResult r = vlf::ComparePatches(*field, reference, 64);
            cornellError = std::to_string(r.AreaWeightedMeanError);
            std::cout << r.Table();
          }
          const std::uint64_t peak = PeakResidentBytes();
          rows.push_back(
            { it, e.ConservationError(), propagate, peak, field->AllocatedBytes(), cornellError });
        }
        field.reset();
        // Accuracy at these settings on the analytic cases (small scenes, quick).
        double floorMean = 0.0, floorRms = 0.0, furnace = 0.0;
        {
          const float albedo = 0.5f, le = 2.0f;
          std::unique_ptr<vlf::LightField> f = vlf::LightField::Build(
            vlf::MakeEmitterOverFloor(1.0f, 1.0f, 2.0f, albedo, le), settings);
          vlf::Propagate(*f, 1);
          const TriangleScene& unit = f->Scene();
          const vlf::PatchComparisonResult r = vlf::ComparePatches(
            *f,
            [&](std::uint32_t t, const glm::vec3& w)
            {
              return unit.MaterialOf(t).Emission.x > 0.0f
                ? glm::vec3(le)
                : glm::vec3(
                    static_cast<float>(albedo * le * vlf::SquareFormFactor(1.0, 1.0, w.x, w.y)));
            },
            1000);
          floorMean = r.Patches[0].MeanError;
          floorRms = r.Patches[0].PointError;
        }
        {
          TriangleScene cube;
          SceneMaterial m;
          m.Diffuse = glm::vec3(0.5f);
          m.Emission = glm::vec3(1.0f);
          const std::uint32_t id = cube.AddMaterial(m);
          for (int axis = 0; axis < 3; ++axis)
          {
            for (int side = -1; side <= 1; side += 2)
            {
              std::vector<glm::vec3> q(4);
              const int u = (axis + 1) % 3, v = (axis + 2) % 3;
              for (int c = 0; c < 4; ++c)
              {
                q[c][axis] = static_cast<float>(side);
                q[c][u] = (c == 1 || c == 2) ? 1.0f : -1.0f;
                q[c][v] = c >= 2 ? 1.0f : -1.0f;
              }
              if (side > 0) // fronts toward the centre
              {
                std::swap(q[1], q[3]);
              }
              cube.AddPolygon(q, id);
            }
          }
          std::unique_ptr<vlf::LightField> f = vlf::LightField::Build(cube, settings);
          vlf::Propagate(*f, iterations);
          for (const glm::vec3& t : f->TotalDiffuse)
          {
            furnace = std::max(furnace, std::abs(t.x - 2.0) / 2.0);
          }
        }

        for (const Row& row : rows)
        {
          std::printf(
            "%10d %5d %5d %4d %9.2f %11.2f %9.2f %11s %11s %10.1e %8.2f%% %8.2f%% %8.2f%%\n",
            directions, rays, settings.TilesPerSide, row.Iteration, build, row.Propagate,
            build + row.Propagate, FormatBytes(estimate.TotalBytes).c_str(),
            FormatBytes(row.Peak).c_str(), row.Energy, 100.0 * floorMean, 100.0 * floorRms,
            100.0 * furnace);
          csv << directions << ',' << rays << ',' << settings.TilesPerSide << ',' << row.Iteration
              << ',' << build << ',' << row.Propagate << ',' << build + row.Propagate << ','
              << estimate.TotalBytes << ',' << row.Allocated << ',' << row.Peak << ',' << row.Energy
              << ',' << floorMean << ',' << floorRms << ',' << furnace << ',' << row.Cornell
              << '\n';
        }
        std::fflush(stdout);
        ChartSeries& t = timeSeries[directions];
        t.Name =
          std::to_string(directions) + " directions, " + std::to_string(iterations) + " iterations";
        t.X.push_back(rays);
        t.Y.push_back(build + propagate);
        ChartSeries& er = errorSeries[directions];
        er.Name = std::to_string(directions) + " directions";
        er.X.push_back(rays);
        er.Y.push_back(100.0 * floorRms);
      }
      catch (const std::exception& ex)
      {
        std::printf("%10d %5d: skipped: %s\n", directions, rays, ex.what());
      }
    }
  }
  if (!cl.Get("--csv").empty())
  {
    std::ofstream file(cl.Get("--csv"));
    file << csv.str();
    if (!file)
    {
      std::cerr << "mesolight bench vlf: could not write " << cl.Get("--csv") << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--csv") << "\n";
  }
  const std::string plot = cl.Get("--plot");
  if (!plot.empty() && !std::getenv("DISPLAY"))
  {
    std::cerr << "mesolight bench vlf: no plot: VTK charts need a display (run under xvfb-run)\n";
    return 1;
  }
  if (!plot.empty())
  {
    ScatterChart chart;
    chart.Title = "Cornell box light field: build + propagation time (2 cores)";
    chart.XLabel = "rays per subfield side";
    chart.YLabel = "seconds";
    for (auto& s : timeSeries)
    {
      chart.Points.push_back(s.second);
    }
    ScatterChart errors;
    errors.Title =
      "Floor under a square emitter: RMS error of the diffuse radiance vs the form factor";
    errors.XLabel = "rays per subfield side";
    errors.YLabel = "RMS relative error (%)";
    for (auto& s : errorSeries)
    {
      errors.Points.push_back(s.second);
    }
    const std::string errorPlot = plot.size() > 4 && plot.substr(plot.size() - 4) == ".png"
      ? plot.substr(0, plot.size() - 4) + "-error.png"
      : plot + "-error.png";
    if (!WriteScatterChartPng(chart, plot, error) ||
      !WriteScatterChartPng(errors, errorPlot, error))
    {
      std::cerr << "mesolight bench vlf: " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << plot << " and " << errorPlot << "\n";
  }
  return 0;
}

} // namespace mesolight
