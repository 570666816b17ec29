// SPDX-License-Identifier: BSD-3-Clause
#include "GeometryImageBenchmark.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "GeometryImageMesh.h"
#include "GeometryImageScene.h"
#include "ImageCompare.h"
#include "OutputFile.h"
#include "ProceduralGeometryImages.h"
#include "Timing.h"

#include <vtkPolyData.h>
#include <vtkRenderWindow.h>

#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <map>

namespace mesolight
{
namespace
{
struct Row
{
  std::string Surface;
  std::string Sampling; // "regular" or "adaptive"
  int Stride = 0;
  double Tolerance = 0.0;
  size_t Triangles = 0;
  HausdorffDistance Distance;
  double MeshMs = 0.0;
  bool Rendered = false;
  FrameDifference Image;
};

// Triangles of a regular sampling with this stride (no holes): two per quad.
size_t RegularTriangles(int width, int height, int stride)
{
  const size_t qx = (width - 2) / stride + 1, qy = (height - 2) / stride + 1;
  return 2 * qx * qy;
}

// The stride whose triangle count is nearest to `triangles`.
int MatchingStride(int width, int height, size_t triangles)
{
  int best = 1;
  for (int k = 1; k < std::max(width, height); ++k)
  {
    const auto gap = [&](int s)
    { return std::abs(static_cast<double>(RegularTriangles(width, height, s)) - triangles); };
    if (gap(k) < gap(best))
    {
      best = k;
    }
  }
  return best;
}

class Bench
{
public:
  GeometryImageSceneOptions Scene;
  bool Render = true;
  std::string SurfaceName;
  GeometryImage Image;
  Frame Reference;
  std::map<std::pair<int, double>, Row> Done;

  bool Start(std::string& error)
  {
    GeometrySurface surface;
    try
    {
      surface = GeometrySurfaceFromName(this->SurfaceName);
    }
    catch (const std::invalid_argument& e)
    {
      error = e.what();
      return false;
    }
    this->Scene.GeometryImage = "procedural:" + this->SurfaceName;
    this->Image =
      MakeGeometryImage(surface, this->Scene.Relief.Resolution, this->Scene.Relief.Resolution);
    this->Done.clear();
    if (this->Render)
    {
      ReliefScene dense;
      if (!BuildGeometryImageDenseScene(this->Scene, dense, error))
      {
        return false;
      }
      auto window = MakeOffscreenWindow(this->Scene.Relief, dense.Renderer);
      this->Reference = CaptureFrame(window);
    }
    return true;
  }

  // One configuration (stride > 0: regular; else adaptive at tolerance), measured once.
  const Row* Measure(int stride, double tolerance, std::string& error)
  {
    const auto key = std::make_pair(stride, tolerance);
    if (auto it = this->Done.find(key); it != this->Done.end())
    {
      return &it->second;
    }
    Row row;
    row.Surface = this->SurfaceName;
    row.Sampling = stride > 0 ? "regular" : "adaptive";
    row.Stride = stride;
    row.Tolerance = tolerance;
    GeometryImageMesh mesh;
    try
    {
      row.MeshMs = 1000.0 *
        FastestSeconds(3,
          [&]
          {
            mesh = stride > 0 ? SampleRegular(this->Image, stride)
                              : SampleAdaptive(this->Image, tolerance);
          });
    }
    catch (const GeometryImageMeshError& e)
    {
      error = e.what();
      return nullptr;
    }
    row.Triangles = mesh.Triangles.size();
    row.Distance = MeasureHausdorff(this->Image, mesh);
    if (this->Render)
    {
      GeometryImageSceneOptions o = this->Scene;
      o.Stride = std::max(1, stride);
      o.Tolerance = stride > 0 ? 0.0 : tolerance;
      ReliefScene relief, coarse;
      if (!BuildGeometryImageReliefScene(o, relief, error) ||
        !BuildGeometryImageTexturedScene(o, coarse, error))
      {
        return nullptr;
      }
      auto coarseWindow = MakeOffscreenWindow(o.Relief, coarse.Renderer);
      const Frame footprint = CaptureFrame(coarseWindow);
      auto window = MakeOffscreenWindow(o.Relief, relief.Renderer);
      const Frame frame = CaptureFrame(window);
      row.Image = CompareFrames(frame, this->Reference, 0.05 * o.Relief.DepthScale, &footprint);
      row.Rendered = true;
    }
    return &(this->Done[key] = row);
  }
};

void PrintRow(std::ostream& out, const Row& r)
{
  out << std::left << std::setw(10) << r.Surface << std::setw(10) << r.Sampling << std::right;
  if (r.Stride > 0)
  {
    out << std::setw(10) << r.Stride;
  }
  else
  {
    out << std::setw(10) << std::setprecision(4) << r.Tolerance;
  }
  out << std::setw(9) << r.Triangles << std::scientific << std::setprecision(2) << std::setw(11)
      << r.Distance.Hausdorff << std::setw(11) << r.Distance.MeanImageToMesh << std::fixed
      << std::setprecision(2);
  if (r.Rendered)
  {
    out << std::setw(9) << r.Image.MeanColorError << std::setw(9) << r.Image.DepthMismatch
        << std::setw(9) << r.Image.SilhouetteMismatch;
  }
  else
  {
    out << std::setw(9) << "-" << std::setw(9) << "-" << std::setw(9) << "-";
  }
  out << std::setw(10) << r.MeshMs << "\n";
  out.unsetf(std::ios::fixed | std::ios::scientific);
}
} // namespace

int RunGeometryImageBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench geometry-image",
    "mesolight bench geometry-image [options]\n\nSamples analytic surfaces written as geometry "
    "images regularly (every k-th pixel) and\nadaptively (to a world tolerance) and measures "
    "triangles, the Hausdorff distance to\nthe full-resolution geometry image, the time to "
    "mesh, and the image error of the\nrelief drawn on the coarse mesh against the dense "
    "displaced mesh (self-shadowing off).\nEvery tolerance is paired with the stride of about "
    "the same triangle count.\n");
  cl.AddValue("--surfaces", "A,B,..", std::string("surfaces: ") + GeometrySurfaceNames(),
    "cylinder,sphere,bump");
  cl.AddValue("--resolution", "N", "geometry image and depth map size (N x N)", "256");
  cl.AddValue("--strides", "K,K,..", "regular strides", "4,8,16,32,64");
  cl.AddValue("--tolerances", "T,T,..",
    "adaptive tolerances (world units; the surfaces are 1 wide)",
    "0.0005,0.001,0.002,0.004,0.008,0.016");
  cl.AddValue("--pattern", "NAME", "procedural depth map", "Bricks");
  cl.AddValue("--depth-scale", "K", "relief depth / surface width", "0.04");
  cl.AddValue("--size", "WxH", "rendered image size", "300x300");
  cl.AddFlag("--no-render", "geometric error only (no GL)");
  cl.AddValue("--csv", "FILE", "write one CSV row per surface and sampling");
  cl.AddValue("--plot", "FILE.png", "Hausdorff distance against triangles, regular vs adaptive");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode;
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, {});
      !problem.empty())
  {
    return cl.UsageError(problem);
  }
  Bench bench;
  GeometryImageSceneOptions& scene = bench.Scene;
  scene.Relief.SelfShadowing = false; // the dense reference has no self-shadows
  scene.Relief.ViewAngle = 45.0;
  scene.Relief.ViewDistance = 2.4;
  scene.Relief.LinearSteps = 32;
  scene.Relief.RefinementSteps = 8;
  scene.Relief.Pattern = cl.Get("--pattern");
  std::string error;
  std::vector<int> strides;
  std::vector<double> tolerances;
  if (!cl.GetInt("--resolution", 8, 4096, scene.Relief.Resolution, error) ||
    !cl.GetIntList("--strides", 1, 4095, strides, error) ||
    !cl.GetDoubleList("--tolerances", 1e-9, 1e3, tolerances, error) ||
    !cl.GetDouble("--depth-scale", 0.0, 1.0, scene.Relief.DepthScale, error) ||
    !cl.GetSize("--size", 16, 4096, scene.Relief.Width, scene.Relief.Height, error))
  {
    return cl.UsageError(error);
  }
  bench.Render = !cl.Has("--no-render");

  std::ostream& out = std::cout;
  out << "Geometry images: " << scene.Relief.Resolution << "^2 pixels, depth map "
      << scene.Relief.Pattern << " (depth scale " << scene.Relief.DepthScale << "), "
      << scene.Relief.Width << "x" << scene.Relief.Height << " renders at "
      << scene.Relief.ViewAngle << " deg\n"
      << "Hausdorff: max over full-resolution pixels and mesh samples (world units; the "
         "surfaces are 1 wide);\nmean: mean pixel-to-mesh distance. Image error vs the dense "
         "displaced mesh: colour (8-bit\nlevels), depth (% of common pixels off by > 5% of the "
         "relief depth), silhouette (%).\n\n";
  out << std::left << std::setw(10) << "surface" << std::setw(10) << "sampling" << std::right
      << std::setw(10) << "k / tol" << std::setw(9) << "tris" << std::setw(11) << "Hausdorff"
      << std::setw(11) << "mean" << std::setw(9) << "colour" << std::setw(9) << "depth%"
      << std::setw(9) << "silh%" << std::setw(10) << "mesh ms"
      << "\n";
  std::vector<Row> rows;
  std::vector<std::pair<Row, Row>> pairs;
  ScatterChart chart;
  chart.Title = "Geometric error against triangles: regular stride vs adaptive";
  chart.XLabel = "triangles";
  chart.YLabel = "Hausdorff distance (world units, surface 1 wide)";
  chart.LogY = true;
  chart.YFloor = 1e-5;
  for (const std::string& name : cl.GetStringList("--surfaces"))
  {
    bench.SurfaceName = name;
    if (!bench.Start(error))
    {
      std::cerr << "mesolight bench geometry-image: " << error << "\n";
      return 1;
    }
    ChartSeries regular{ name + " regular", {}, {} }, adaptive{ name + " adaptive", {}, {} };
    const auto add = [&](const Row* r)
    {
      rows.push_back(*r);
      PrintRow(out, *r);
      ChartSeries& series = r->Stride > 0 ? regular : adaptive;
      series.X.push_back(static_cast<double>(r->Triangles));
      series.Y.push_back(r->Distance.Hausdorff);
    };
    for (int k : strides)
    {
      const Row* r = bench.Measure(k, 0.0, error);
      if (!r)
      {
        std::cerr << "mesolight bench geometry-image: " << error << "\n";
        return 1;
      }
      add(r);
    }
    for (double t : tolerances)
    {
      const Row* a = bench.Measure(0, t, error);
      if (!a)
      {
        std::cerr << "mesolight bench geometry-image: " << error << "\n";
        return 1;
      }
      add(a);
      const Row a0 = *a;
      const int k = MatchingStride(bench.Image.Width, bench.Image.Height, a0.Triangles);
      const bool fresh = bench.Done.count({ k, 0.0 }) == 0;
      const Row* r = bench.Measure(k, 0.0, error);
      if (!r)
      {
        std::cerr << "mesolight bench geometry-image: " << error << "\n";
        return 1;
      }
      if (fresh)
      {
        add(r);
      }
      pairs.emplace_back(a0, *r);
    }
    chart.Points.push_back(regular);
    chart.Points.push_back(adaptive);
  }

  out << "\nAt about equal triangle counts (each tolerance and the stride nearest its count):\n"
      << std::left << std::setw(10) << "surface" << std::right << std::setw(10) << "tolerance"
      << std::setw(8) << "tris" << std::setw(11) << "Hausdorff" << std::setw(8) << "colour"
      << std::setw(8) << "depth%"
      << "  |" << std::setw(7) << "stride" << std::setw(8) << "tris" << std::setw(11) << "Hausdorff"
      << std::setw(8) << "colour" << std::setw(8) << "depth%"
      << "\n";
  for (const auto& [a, r] : pairs)
  {
    out << std::left << std::setw(10) << a.Surface << std::right << std::setw(10) << a.Tolerance
        << std::setw(8) << a.Triangles << std::scientific << std::setprecision(2) << std::setw(11)
        << a.Distance.Hausdorff << std::fixed << std::setprecision(2) << std::setw(8)
        << a.Image.MeanColorError << std::setw(8) << a.Image.DepthMismatch << "  |" << std::setw(7)
        << r.Stride << std::setw(8) << r.Triangles << std::scientific << std::setw(11)
        << r.Distance.Hausdorff << std::fixed << std::setw(8) << r.Image.MeanColorError
        << std::setw(8) << r.Image.DepthMismatch << "\n";
    out.unsetf(std::ios::fixed | std::ios::scientific);
  }

  if (cl.Has("--csv"))
  {
    std::ofstream csv(cl.Get("--csv"));
    csv << "surface,sampling,stride,tolerance,triangles,hausdorff,image_to_mesh,mesh_to_image,"
           "mean_image_to_mesh,mesh_ms,mean_color_error,depth_mismatch_pct,"
           "silhouette_mismatch_pct\n";
    for (const Row& r : rows)
    {
      csv << r.Surface << ',' << r.Sampling << ',' << r.Stride << ',' << r.Tolerance << ','
          << r.Triangles << ',' << r.Distance.Hausdorff << ',' << r.Distance.ImageToMesh << ','
          << r.Distance.MeshToImage << ',' << r.Distance.MeanImageToMesh << ',' << r.MeshMs << ',';
      if (r.Rendered)
      {
        csv << r.Image.MeanColorError << ',' << r.Image.DepthMismatch << ','
            << r.Image.SilhouetteMismatch;
      }
      else
      {
        csv << ",,";
      }
      csv << "\n";
    }
    if (!csv)
    {
      std::cerr << "mesolight bench geometry-image: could not write " << cl.Get("--csv") << "\n";
      return 1;
    }
    out << "\nwrote " << cl.Get("--csv") << "\n";
  }
  if (cl.Has("--plot"))
  {
    if (!WriteScatterChartPng(chart, cl.Get("--plot"), error))
    {
      std::cerr << "mesolight bench geometry-image: " << error << "\n";
      return 1;
    }
    out << "wrote " << cl.Get("--plot") << "\n";
  }
  return 0;
}

} // namespace mesolight
