// SPDX-License-Identifier: BSD-3-Clause
#include "VlfReliefBenchmark.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "CornellRegions.h" // ReadLinearImage
#include "LightFieldCamera.h"
#include "OutputFile.h"
#include "Timing.h"
#include "VlfRelief.h"

#include "EmbreeScene.h"
#include "LightField.h"
#include "Lookup.h"
#include "Luminance.h"
#include "MathConstants.h"
#include "ParallelFor.h"
#include "PatchComparison.h" // ToUnit
#include "Snapshot.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>
#include <memory>
#include <stdexcept>

namespace mesolight
{
namespace
{
struct Row
{
  std::string Name;
  std::string File; // empty: rendered here
  MaskedError Error;
  double Seconds = -1.0; // shading time of the relief's pixels (here) or per frame (given)
  bool Negative = true;  // must be --margin times worse than the first row
  RgbImage Image;
};

// One primary ray through a relief pixel that hit the relief's macro surface from the front.
struct ReliefRay
{
  int Column = 0, Row = 0;
  glm::vec3 Origin{ 0.0f }, Direction{ 0.0f };
  glm::vec3 Point{ 0.0f }; // on the macro surface
  std::uint32_t Surface = 0;
  float Weight = 1.0f; // 1 / rays per pixel
};

// The three lightings of the same relief pixels, rendered here so their shading times are
// measured in the same run on the same rays:
//  - field: the method (vlf render --relief: SH9 probes of the field + its emitters, relief
//    self-shadowing, perturbed normal);
//  - flat-wall: the flat wall's field value at the point the ray meets the wall (what the field
//    shows without a relief: the relief's own light variation is missing);
//  - one-light: one light where the lamp is, of the lamp's power, with the relief's
//    self-shadowing and the scene's occlusion, no indirect light (a hand-placed VTK light with
//    shadows);
//  - field-unoccluded: the method without the relief's occlusion of its indirect light,
//    field-no-bounce / -one-bounce / -multi-bounce: the relief's inter-reflection models, and
//    flat-normal: the field's lighting at the wall's normal instead of the relief's (both shown,
//    not required to lose by the margin).
struct InProcess
{
  std::vector<Row> Rows;
  std::size_t Pixels = 0;
  std::size_t Rays = 0;
  double SetupSeconds = 0.0;
};

InProcess RenderInProcess(
  const CommandLine& cl, const RgbImage& mask, double coverage, int subpixels, int threads)
{
  InProcess result;
  const int width = mask.Width, height = mask.Height;
  const std::unique_ptr<vlf::LightField> field = vlf::ReadSnapshot(cl.Positional()[0]);
  const TriangleScene& unit = field->Scene();
  glm::vec3 eye, focal;
  double up[3] = { 0.0, 1.0, 0.0 };
  std::string error;
  double viewAngle = 0.0;
  if (!ReadLightFieldCamera(cl, *field, eye, focal, up, error) ||
    !ReadViewAngle(cl, viewAngle, error))
  {
    throw std::invalid_argument(error);
  }
  // The camera of `vlf render` (VlfCommand.cxx), in the field's unit-sphere coordinates.
  const glm::vec3 eyeUnit = vlf::ToUnit(*field, eye);
  const glm::vec3 forward = glm::normalize(vlf::ToUnit(*field, focal) - eyeUnit);
  const glm::vec3 right = glm::normalize(glm::cross(forward, glm::vec3(up[0], up[1], up[2])));
  const glm::vec3 trueUp = glm::cross(right, forward);
  const float tanHalf = static_cast<float>(std::tan(0.5 * viewAngle * Pi<double> / 180.0));
  const float aspect = static_cast<float>(width) / static_cast<float>(height);

  const EmbreeScene embree(unit);
  const vlf::Lookup lookup(*field);
  FieldReliefOptions options;
  if (!cl.GetDouble("--relief-depth-scale", 0.0, 10.0, options.DepthScale, error))
  {
    throw std::invalid_argument(error);
  }
  const auto setup = std::chrono::steady_clock::now();
  const std::vector<FieldRelief> reliefs =
    SetUpFieldReliefs(*field, embree, { cl.Get("--relief") }, options);
  result.SetupSeconds = SecondsSince(setup);
  const FieldRelief& relief = reliefs.front();
  std::vector<bool> onRelief(unit.TriangleCount(), false);
  for (std::size_t t : SurfaceTriangles(unit, relief.Name))
  {
    onRelief[t] = true;
  }

  // The one light: the emitters' area-weighted centre, their power, facing as they face.
  FieldRelief oneLight = relief;
  oneLight.Lighting.Probes.clear();          // no indirect light,
  oneLight.Lighting.OcclusionDirections = 0; // so nothing to occlude
  {
    ReliefEmitterSample lamp;
    glm::dvec3 centre(0.0), normal(0.0), power(0.0);
    double area = 0.0;
    for (std::size_t t = 0; t < unit.TriangleCount(); ++t)
    {
      const glm::vec3 emission = unit.MaterialOf(t).Emission;
      if (glm::length(emission) > 0.0f)
      {
        const double a = unit.Area(t);
        centre += a * glm::dvec3(unit.Vertex(t, 0) + unit.Vertex(t, 1) + unit.Vertex(t, 2)) / 3.0;
        normal += glm::dvec3(unit.FaceNormal(t));
        power += a * glm::dvec3(emission);
        area += a;
      }
    }
    if (area > 0.0)
    {
      lamp.Position = centre / area;
      lamp.Normal = glm::normalize(normal);
      lamp.RadianceArea = power;
      oneLight.Lighting.Emitters = { lamp };
    }
  }

  // The rays: subpixels x subpixels per relief pixel, stratified (the reference integrates
  // over the pixel too).
  std::vector<ReliefRay> rays;
  for (int row = 0; row < height; ++row)
  {
    for (int column = 0; column < width; ++column)
    {
      if (mask.Pixel(column, row)[0] < coverage - 1e-6)
      {
        continue;
      }
      ++result.Pixels;
      for (int b = 0; b < subpixels; ++b)
      {
        for (int a = 0; a < subpixels; ++a)
        {
          const float x = column + (a + 0.5f) / subpixels, y = row + (b + 0.5f) / subpixels;
          const float sx = (2.0f * x / width - 1.0f) * tanHalf * aspect;
          const float sy = (2.0f * y / height - 1.0f) * tanHalf;
          SceneRay ray;
          ray.Origin = eyeUnit;
          ray.Direction = glm::normalize(forward + sx * right + sy * trueUp);
          const SceneHit hit = embree.Intersect(ray);
          if (!hit.Hit() || hit.Triangle == SceneHit::None || !onRelief[hit.Triangle])
          {
            continue;
          }
          const std::uint32_t s = field->SurfaceOfTriangle(hit.Triangle);
          if (s == vlf::NoSurface || glm::dot(field->Surfaces()[s].Normal, ray.Direction) >= 0.0f)
          {
            continue;
          }
          ReliefRay r;
          r.Column = column;
          r.Row = row;
          r.Origin = ray.Origin;
          r.Direction = ray.Direction;
          r.Point = ray.Origin + hit.T * ray.Direction;
          r.Surface = s;
          r.Weight = 1.0f / static_cast<float>(subpixels * subpixels);
          rays.push_back(r);
        }
      }
    }
  }
  result.Rays = rays.size();

  const auto render = [&](const std::string& name, bool negative,
                        const std::function<glm::vec3(const ReliefRay&)>& shade)
  {
    Row row;
    row.Name = name;
    row.Negative = negative;
    std::vector<glm::vec3> values(rays.size());
    const auto start = std::chrono::steady_clock::now();
    ParallelFor(
      0, rays.size(), 64,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t k = begin; k < end; ++k)
        {
          values[k] = shade(rays[k]);
        }
      },
      threads);
    row.Seconds = SecondsSince(start);
    row.Image = RgbImage(width, height);
    for (std::size_t k = 0; k < rays.size(); ++k)
    {
      float* px = row.Image.Pixel(rays[k].Column, rays[k].Row);
      for (int c = 0; c < 3; ++c)
      {
        px[c] += rays[k].Weight * values[k][c];
      }
    }
    result.Rows.push_back(std::move(row));
  };
  const auto flatWall = [&](const ReliefRay& r)
  { return lookup.DiffuseRadiance(r.Surface, r.Point); };
  render("field", false,
    [&](const ReliefRay& r)
    {
      glm::vec3 radiance;
      return ReliefRadiance(relief, r.Origin, r.Direction, radiance) ? radiance : flatWall(r);
    });
  render("flat-wall", true, flatWall);
  render("one-light", true,
    [&](const ReliefRay& r)
    {
      glm::vec3 radiance;
      return ReliefRadiance(oneLight, r.Origin, r.Direction, radiance) ? radiance : glm::vec3(0.0f);
    });
  // The method without the relief's occlusion of its indirect light (shown).
  FieldRelief unoccluded = relief;
  unoccluded.Lighting.OcclusionDirections = 0;
  render("field-unoccluded", false,
    [&](const ReliefRay& r)
    {
      glm::vec3 radiance;
      return ReliefRadiance(unoccluded, r.Origin, r.Direction, radiance) ? radiance : flatWall(r);
    });
  // The relief's inter-reflection, each model (the field row is the default one): none (the
  // occluded directions black, as before it was modelled), one bounce and the multi-bounce series.
  const std::pair<const char*, ReliefInterReflection> models[] = { { "field-no-bounce",
                                                                     ReliefInterReflection::None },
    { "field-one-bounce", ReliefInterReflection::OneBounce },
    { "field-multi-bounce", ReliefInterReflection::MultiBounce } };
  for (const auto& [name, model] : models)
  {
    FieldRelief variant = relief;
    variant.Lighting.InterReflection = model;
    render(name, false,
      [&](const ReliefRay& r)
      {
        glm::vec3 radiance;
        return ReliefRadiance(variant, r.Origin, r.Direction, radiance) ? radiance : flatWall(r);
      });
  }
  render("flat-normal", false,
    [&](const ReliefRay& r)
    {
      const auto shade = ShadeReliefRay(relief.Height, relief.Frame, relief.Lighting,
        glm::dvec3(r.Origin), glm::dvec3(r.Direction), ReliefNormal::Flat);
      return shade ? relief.Emission +
          relief.Albedo * glm::vec3((shade->Indirect + shade->Direct) / Pi<double>)
                   : flatWall(r);
    });
  return result;
}

// NAME=VALUE
bool SplitNamed(const std::string& spec, std::string& name, std::string& value)
{
  const std::size_t equals = spec.find('=');
  if (equals == std::string::npos || equals == 0 || equals + 1 == spec.size())
  {
    return false;
  }
  name = spec.substr(0, equals);
  value = spec.substr(equals + 1);
  return true;
}

std::vector<std::string> SplitList(const std::string& text)
{
  std::vector<std::string> items;
  std::size_t start = 0;
  while (start <= text.size())
  {
    const std::size_t comma = text.find(',', start);
    const std::string item =
      text.substr(start, comma == std::string::npos ? std::string::npos : comma - start);
    if (!item.empty())
    {
      items.push_back(item);
    }
    if (comma == std::string::npos)
    {
      break;
    }
    start = comma + 1;
  }
  return items;
}
} // namespace

MaskedError MaskedRelativeError(const RgbImage& image, const RgbImage& reference,
  const RgbImage& mask, double coverage, double floor)
{
  if (image.Width != reference.Width || image.Height != reference.Height ||
    mask.Width != reference.Width || mask.Height != reference.Height)
  {
    throw std::invalid_argument("the image, the reference and the mask differ in size (" +
      std::to_string(image.Width) + "x" + std::to_string(image.Height) + ", " +
      std::to_string(reference.Width) + "x" + std::to_string(reference.Height) + ", " +
      std::to_string(mask.Width) + "x" + std::to_string(mask.Height) + ")");
  }
  MaskedError result;
  std::vector<double> errors;
  double sum = 0.0, sumReference = 0.0;
  for (int j = 0; j < reference.Height; ++j)
  {
    for (int i = 0; i < reference.Width; ++i)
    {
      if (mask.Pixel(i, j)[0] < coverage - 1e-6)
      {
        continue;
      }
      const float* ref = reference.Pixel(i, j);
      const float* rgb = image.Pixel(i, j);
      const double yRef = Luminance<double>(ref[0], ref[1], ref[2]);
      const double y = Luminance<double>(rgb[0], rgb[1], rgb[2]);
      if (!(yRef > floor) || !std::isfinite(y))
      {
        continue;
      }
      errors.push_back(std::abs(y - yRef) / yRef);
      sum += y;
      sumReference += yRef;
    }
  }
  result.Pixels = errors.size();
  if (errors.empty())
  {
    return result;
  }
  double total = 0.0;
  for (double e : errors)
  {
    total += e;
  }
  result.MeanRelativeError = total / static_cast<double>(errors.size());
  std::nth_element(errors.begin(), errors.begin() + errors.size() / 2, errors.end());
  result.MedianRelativeError = errors[errors.size() / 2];
  result.MeanRatio = sum / sumReference;
  return result;
}

int RunVlfReliefBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench vlf-relief",
    "mesolight bench vlf-relief [FIELD --relief SURFACE=DEPTH_IMAGE] --reference REF.exr "
    "--mask MASK.exr [options]\n\n"
    "A relief lit by the light field against the truth: the mean relative luminance error per\n"
    "pixel over the pixels wholly on the relief, against the path-traced dense displaced mesh of\n"
    "the same relief and camera (`mesolight trace --relief ... --exr REF.exr --relief-mask\n"
    "MASK.exr`). With FIELD, the relief's pixels are rendered here four ways on the same rays,\n"
    "each timed in this run: field (the method, `vlf render --relief`), flat-wall (the flat\n"
    "wall's field value) and one-light (one light of the lamp's power with shadows, no indirect\n"
    "light) -- the negative cases it must beat by --margin -- and flat-normal (shown). Without\n"
    "FIELD the first of --images is the method and the others its negative cases.\n"
    "scripts/bench-vlf-relief.sh renders the references and runs this.\n");
  cl.AddValue("--relief", "SURFACE=DEPTH_IMAGE", "FIELD: the relief, as given to vlf render");
  cl.AddValue("--relief-depth-scale", "K", "FIELD: as given to vlf render and trace", "0.05");
  AddLightFieldCameraOptions(cl);
  cl.AddValue("--subpixels", "N",
    "FIELD: N x N rays per pixel (the reference's paths cover the "
    "pixel too)",
    "2");
  cl.AddValue("--threads", "N", "FIELD: shading threads (0: all cores)", "0");
  cl.AddValue("--reference", "REF.exr", "the path-traced dense mesh (required)");
  cl.AddValue("--reference-2", "REF2.exr",
    "the same reference with other random paths: its error is the reference's own noise");
  cl.AddValue("--mask", "MASK.exr", "the relief's coverage per pixel (required)");
  cl.AddValue("--images", "NAME=FILE.exr,..", "more renderings of the same view to measure");
  cl.AddValue("--times", "NAME=SECONDS,..", "seconds per frame of the --images (shown)");
  cl.AddValue("--coverage", "X", "least share of a pixel on the relief to count it", "1");
  cl.AddValue("--goal", "X", "largest mean relative error of the method", "0.08");
  cl.AddValue("--margin", "X", "the negative cases' error must be X times the method's", "2");
  cl.AddValue("--cost-goal", "X", "largest field / one-light time per relief pixel", "1.5");
  cl.AddValue(
    "--label", "TEXT", "a name for the run in the CSV (scene, map, directions)", "cornell");
  cl.AddValue("--csv", "FILE", "append the rows as CSV (header written to a new file)");
  cl.AddValue("--plot", "FILE.png", "plot the errors");
  cl.AddValue("--write-images", "PREFIX", "FIELD: write PREFIX-NAME.exr of each rendering");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  double coverage = 1.0, goal = 0.08, margin = 2.0, costGoal = 1.5;
  int subpixels = 2, threads = 0;
  if (!cl.GetDouble("--coverage", 0.0, 1.0, coverage, error) ||
    !cl.GetDouble("--goal", 0.0, 100.0, goal, error) ||
    !cl.GetDouble("--margin", 0.0, 1000.0, margin, error) ||
    !cl.GetDouble("--cost-goal", 0.0, 1e6, costGoal, error) ||
    !cl.GetInt("--subpixels", 1, 16, subpixels, error) ||
    !cl.GetInt("--threads", 0, 1024, threads, error))
  {
    return cl.UsageError(error);
  }
  const bool inProcess = !cl.Positional().empty();
  if (cl.Positional().size() > 1)
  {
    return cl.UsageError("one light field at most");
  }
  if (inProcess != cl.Has("--relief"))
  {
    return cl.UsageError("FIELD and --relief SURFACE=DEPTH_IMAGE go together");
  }
  if (!cl.Has("--reference") || !cl.Has("--mask") || (!inProcess && !cl.Has("--images")))
  {
    return cl.UsageError("--reference, --mask and FIELD --relief or --images are required");
  }
  RgbImage reference, mask;
  if (!ReadLinearImage(cl.Get("--reference"), reference, error) ||
    !ReadLinearImage(cl.Get("--mask"), mask, error))
  {
    std::cerr << "mesolight bench vlf-relief: " << error << "\n";
    return 1;
  }
  std::vector<Row> rows;
  InProcess rendered;
  try
  {
    if (inProcess)
    {
      if (mask.Width != reference.Width || mask.Height != reference.Height)
      {
        throw std::invalid_argument("the mask and the reference differ in size");
      }
      rendered = RenderInProcess(cl, mask, coverage, subpixels, threads);
      rows = std::move(rendered.Rows);
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "mesolight bench vlf-relief: " << e.what() << "\n";
    return 1;
  }
  for (const std::string& spec : SplitList(cl.Get("--images")))
  {
    Row row;
    if (!SplitNamed(spec, row.Name, row.File))
    {
      return cl.UsageError("--images takes NAME=FILE.exr,.. not '" + spec + "'");
    }
    // Without FIELD the first image is the method; with it, the images are shown only.
    row.Negative = !inProcess && !rows.empty();
    rows.push_back(row);
  }
  if (cl.Has("--reference-2"))
  {
    Row noise;
    noise.Name = "reference-noise";
    noise.File = cl.Get("--reference-2");
    noise.Negative = false;
    rows.push_back(noise);
  }
  for (const std::string& spec : SplitList(cl.Get("--times")))
  {
    std::string name, value;
    if (!SplitNamed(spec, name, value))
    {
      return cl.UsageError("--times takes NAME=SECONDS,.. not '" + spec + "'");
    }
    for (Row& row : rows)
    {
      if (row.Name == name && !row.File.empty())
      {
        row.Seconds = std::atof(value.c_str());
      }
    }
  }
  try
  {
    for (Row& row : rows)
    {
      if (!row.File.empty() && !ReadLinearImage(row.File, row.Image, error))
      {
        std::cerr << "mesolight bench vlf-relief: " << error << "\n";
        return 1;
      }
      row.Error = MaskedRelativeError(row.Image, reference, mask, coverage);
    }
  }
  catch (const std::exception& e)
  {
    std::cerr << "mesolight bench vlf-relief: " << e.what() << "\n";
    return 1;
  }
  const std::string label = cl.Get("--label");
  std::cout << "relief pixels: " << rows[0].Error.Pixels << " (coverage >= " << coverage << ")";
  if (inProcess)
  {
    std::cout << "; " << rendered.Rays << " rays (" << subpixels << "x" << subpixels
              << " per pixel); field setup (probes, emitter samples) " << std::fixed
              << std::setprecision(3) << rendered.SetupSeconds << " s";
  }
  std::cout << "\n";
  std::cout << std::left << std::setw(18) << "image" << std::right << std::setw(11) << "mean rel."
            << std::setw(11) << "median" << std::setw(12) << "mean ratio" << std::setw(16)
            << (inProcess ? "us/relief px" : "s/frame") << "\n";
  for (const Row& row : rows)
  {
    std::cout << std::left << std::setw(18) << row.Name << std::right << std::fixed
              << std::setprecision(4) << std::setw(11) << row.Error.MeanRelativeError
              << std::setw(11) << row.Error.MedianRelativeError << std::setw(12)
              << row.Error.MeanRatio << std::setw(16);
    if (row.Seconds >= 0.0 && row.File.empty())
    {
      std::cout << std::setprecision(2)
                << 1e6 * row.Seconds / std::max<std::size_t>(1, rendered.Pixels);
    }
    else if (row.Seconds >= 0.0)
    {
      std::cout << std::setprecision(3) << row.Seconds;
    }
    else
    {
      std::cout << "-";
    }
    std::cout << "\n";
  }
  bool pass = rows[0].Error.Pixels > 0 && rows[0].Error.MeanRelativeError <= goal;
  for (std::size_t k = 1; k < rows.size(); ++k)
  {
    if (!rows[k].Negative)
    {
      continue;
    }
    const double factor =
      rows[k].Error.MeanRelativeError / std::max(rows[0].Error.MeanRelativeError, 1e-12);
    std::cout << rows[k].Name << " / " << rows[0].Name << ": " << std::setprecision(2) << factor
              << "x the error (goal >= " << margin << "x)\n";
    pass = pass && factor >= margin;
  }
  double costRatio = -1.0;
  if (inProcess)
  {
    for (const Row& row : rows)
    {
      if (row.Name == "one-light" && row.Seconds > 0.0)
      {
        costRatio = rows[0].Seconds / row.Seconds;
      }
    }
    std::cout << "cost: a relief pixel lit by the field / by one light with shadows = "
              << std::setprecision(2) << costRatio << " (same run, same rays; goal <= " << costGoal
              << ")\n";
  }
  std::cout << std::defaultfloat << std::setprecision(6) << (pass ? "PASS" : "FAIL") << ": "
            << rows[0].Name << " within " << goal
            << " mean relative error and every negative case at least " << margin << "x worse\n";
  if (inProcess && cl.Has("--write-images"))
  {
    for (const Row& row : rows)
    {
      if (row.File.empty())
      {
        const std::string file = cl.Get("--write-images") + "-" + row.Name + ".exr";
        if (!WriteLinearImage(row.Image, file, error))
        {
          std::cerr << "mesolight bench vlf-relief: " << error << "\n";
          return 1;
        }
        std::cout << "wrote " << file << "\n";
      }
    }
  }
  if (cl.Has("--csv"))
  {
    const std::string csv = cl.Get("--csv");
    const bool fresh = !std::ifstream(csv).good();
    std::ofstream out(csv, std::ios::app);
    if (fresh)
    {
      out << "label,image,pixels,mean_relative_error,median_relative_error,mean_ratio,"
             "seconds,microseconds_per_relief_pixel,cost_ratio_field_over_one_light\n";
    }
    for (const Row& row : rows)
    {
      const double perPixel = row.File.empty() && rendered.Pixels > 0
        ? 1e6 * row.Seconds / static_cast<double>(rendered.Pixels)
        : -1.0;
      out << label << "," << row.Name << "," << row.Error.Pixels << ","
          << row.Error.MeanRelativeError << "," << row.Error.MedianRelativeError << ","
          << row.Error.MeanRatio << "," << row.Seconds << "," << perPixel << "," << costRatio
          << "\n";
    }
    if (!out)
    {
      std::cerr << "mesolight bench vlf-relief: cannot write " << csv << "\n";
      return 1;
    }
    std::cout << "wrote " << csv << "\n";
  }
  if (cl.Has("--plot"))
  {
    ScatterChart chart;
    chart.Title = "relief vs the path-traced dense mesh (" + label + ")";
    chart.XLabel = "rendering (field, negative cases, others)";
    chart.YLabel = "mean relative error per relief pixel";
    for (std::size_t k = 0; k < rows.size(); ++k)
    {
      chart.Points.push_back(
        { rows[k].Name, { static_cast<double>(k + 1) }, { rows[k].Error.MeanRelativeError } });
    }
    chart.Line.Name = "goal";
    chart.Line.X = { 0.5, rows.size() + 0.5 };
    chart.Line.Y = { goal, goal };
    if (!WriteScatterChartPng(chart, cl.Get("--plot"), error))
    {
      std::cerr << "mesolight bench vlf-relief: " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--plot") << "\n";
  }
  return pass ? 0 : 1;
}

} // namespace mesolight
