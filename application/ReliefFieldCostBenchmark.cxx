// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefFieldCostBenchmark.h"

#include "CommandLine.h"
#include "EnvironmentMaps.h" // SH9, EvaluateSHBasis
#include "ImageCompare.h"
#include "MathConstants.h"
#include "ReliefScene.h"
#include "ReliefShading.h" // ReliefVisibleShareMap, ReliefSeenShareMap, ReliefEmitterShadowMap
#include "Timing.h"
#include "vtkIrradianceProbesTexture.h"
#include "vtkReliefMapper.h"

#include <vtkActor.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkMath.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <functional>
#include <iomanip>
#include <iostream>

namespace mesolight
{
namespace
{
// The SH9 projection of a radiance function (midpoint rule, uniform in z and phi).
SH9 Project(const std::function<double(const double d[3])>& radiance, const double colour[3])
{
  SH9 sh;
  const int nz = 64, nphi = 128;
  const double dOmega = (2.0 / nz) * (2.0 * Pi<double> / nphi);
  for (int a = 0; a < nz; ++a)
  {
    const double z = -1.0 + (a + 0.5) * 2.0 / nz;
    const double r = std::sqrt(std::max(0.0, 1.0 - z * z));
    for (int b = 0; b < nphi; ++b)
    {
      const double phi = (b + 0.5) * 2.0 * Pi<double> / nphi;
      const double d[3] = { r * std::cos(phi), r * std::sin(phi), z };
      const double l = radiance(d);
      double y[9];
      EvaluateSHBasis(d, y);
      for (int k = 0; k < 9; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          sh.L[k][c] += colour[c] * l * y[k] * dOmega;
        }
      }
    }
  }
  return sh;
}

// n x n probes of a smooth room-like light (a sky-and-ground gradient plus a lobe that turns
// across the wall), in vtkReliefMapper::SetIrradianceProbesData's layout.
vtkSmartPointer<vtkImageData> MakeProbes(int n)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(9 * n, n, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(3);
  values->SetNumberOfTuples(static_cast<vtkIdType>(9 * n) * n);
  const double colour[3] = { 0.35, 0.3, 0.25 };
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const double a = (i + 0.5) / n - 0.5, b = (j + 0.5) / n - 0.5;
      const double norm = std::sqrt(a * a + b * b + 1.0);
      const SH9 sh = Project(
        [&](const double d[3])
        {
          const double lobe = std::max(0.0, (a * d[0] + b * d[1] + d[2]) / norm);
          return 0.3 * (1.0 + 0.5 * d[2]) + lobe * lobe;
        },
        colour);
      for (int k = 0; k < 9; ++k)
      {
        values->SetTuple3(
          static_cast<vtkIdType>(j) * 9 * n + 9 * i + k, sh.L[k][0], sh.L[k][1], sh.L[k][2]);
      }
    }
  }
  image->GetPointData()->SetScalars(values);
  return image;
}

// Emitter k above the wall (ceiling-like rows of 4 small emitters facing down and in; k 4-7 a
// second row farther out, as the lights the relief shades at most).
vtkSmartPointer<vtkLight> MakeEmitterLight(int k)
{
  const int row = k / 4;
  const double x = 0.2 + 0.2 * (k % 4) + 0.1 * row;
  const double position[3] = { x, -0.3 - 0.2 * row, 0.6 + 0.2 * row };
  const double normal[3] = { 0.0, 0.6, -0.8 };
  const double intensity[3] = { 1.2, 1.1, 0.9 };
  auto light = vtkSmartPointer<vtkLight>::New();
  vtkReliefMapper::ConfigureEmitterLight(light, position, normal, intensity);
  return light;
}

vtkSmartPointer<vtkLight> MakeKeyLight()
{
  auto light = vtkSmartPointer<vtkLight>::New();
  light->SetLightTypeToSceneLight();
  light->PositionalOff();
  light->SetFocalPoint(0.5, 0.5, 0.0);
  light->SetPosition(0.5 - 0.65, 0.5 + 0.5, 0.57); // about 35 degrees above the wall
  return light;
}

// What the visible-share map's passes cost (median ms of `repeats` runs each): the first pass
// (which notes what each direction met), the side walls' shares, and the second pass reading
// both, against the second pass marching the walls' directions (what it did before it read the
// walls' shares) and marching every direction again (before it read the first pass's hits); the
// share of the cells' directions that leave, how far reading the hits moves the map (where a ray
// only touches the surface the two marches differ; float coordinates) and how far reading the
// walls' shares moves it.
struct ShareMapTimes
{
  int Width = 0, Height = 0, Directions = 0, WallLevels = 0;
  double FirstPassMs = 0.0, WallPassMs = 0.0, SecondPassMs = 0.0;
  double SecondPassMarchingWallsMs = 0.0, SecondPassMarchingMs = 0.0;
  double EmitterShadowMs = 0.0; // the area light's shadow by the relief (ReliefEmitterShadowMap)
  int EmitterSamples = 0;
  double LeavingShare = 0.0;
  double HitsLargestChange = 0.0; // the hits read against every direction marched again
  int HitsCellsOver = 0;          // cells whose seen share moved by more than 1e-4
  double WallsMeanChange = 0.0, WallsLargestChange = 0.0;
};

// The probes with the relief's precomputed occlusion, as the walkthrough gives them to the
// relief mapper (application/LightFieldReliefs.cxx): the visible-share map of this height field
// (depth: the relief texture's fourth component), the relief's shadow of emitter 0's area (4 x 4
// samples of a 0.1 x 0.1 square facing its normal) and a light visibility per probe.
vtkSmartPointer<vtkImageData> OccludedProbes(
  vtkImageData* probes, vtkImageData* relief, double depthScale, int repeats, ShareMapTimes& times)
{
  int dims[3];
  relief->GetDimensions(dims);
  vtkDataArray* texels = relief->GetPointData()->GetScalars();
  std::vector<float> depth(static_cast<std::size_t>(dims[0]) * dims[1]);
  for (std::size_t t = 0; t < depth.size(); ++t)
  {
    depth[t] = static_cast<float>(texels->GetComponent(static_cast<vtkIdType>(t), 3));
  }
  // Walled, as the walkthrough's reliefs on the scene's surfaces are (ReadDepthImage).
  const HeightField height(dims[0], dims[1], std::move(depth), HeightField::Edge::Walled);
  ReliefFrame frame; // the unit square of BuildReliefScene's wall
  frame.DepthScale = depthScale;
  const int w = std::min(dims[0], 256), h = std::min(dims[1], 256);
  const int count = ReliefLighting().OcclusionDirections;
  ReliefDirectionHits hits;
  std::vector<float> share, wallShare, seen, seenMarchingWalls, seenMarching;
  constexpr int WallLevels = 8; // vlf::WallShareLevels, as the walkthrough's reliefs have
  times.Width = w;
  times.Height = h;
  times.Directions = count;
  times.WallLevels = WallLevels;
  times.FirstPassMs = MedianMilliseconds(
    repeats, [&]() { share = ReliefVisibleShareMap(height, frame, w, h, count, {}, {}, &hits); });
  times.WallPassMs = MedianMilliseconds(
    repeats, [&]() { wallShare = ReliefWallVisibleShareMap(height, frame, w, WallLevels, count); });
  const ReliefWallShares walls{ &wallShare, WallLevels };
  times.SecondPassMs = MedianMilliseconds(repeats,
    [&]() { seen = ReliefSeenShareMap(height, frame, share, w, h, count, {}, {}, &hits, walls); });
  times.SecondPassMarchingWallsMs = MedianMilliseconds(repeats,
    [&]()
    { seenMarchingWalls = ReliefSeenShareMap(height, frame, share, w, h, count, {}, {}, &hits); });
  times.SecondPassMarchingMs = MedianMilliseconds(repeats,
    [&]()
    { seenMarching = ReliefSeenShareMap(height, frame, share, w, h, count, {}, {}, nullptr); });
  for (std::size_t c = 0; c < seen.size(); ++c)
  {
    const double change = std::abs(static_cast<double>(seenMarchingWalls[c]) - seenMarching[c]);
    times.HitsLargestChange = std::max(times.HitsLargestChange, change);
    times.HitsCellsOver += change > 1e-4 ? 1 : 0;
  }
  for (std::size_t c = 0; c < seen.size(); ++c)
  {
    const double change = std::abs(static_cast<double>(seen[c]) - seenMarchingWalls[c]);
    times.WallsMeanChange += change / static_cast<double>(seen.size());
    times.WallsLargestChange = std::max(times.WallsLargestChange, change);
  }
  times.LeavingShare = hits.Kinds.empty()
    ? 0.0
    : static_cast<double>(std::count(
        hits.Kinds.begin(), hits.Kinds.end(), std::uint8_t(ReliefDirectionHits::Leaves))) /
      static_cast<double>(hits.Kinds.size());
  std::vector<ReliefEmitterSample> samples;
  const glm::dvec3 position(0.2, -0.3, 0.6), normal(0.0, 0.6, -0.8), side(1.0, 0.0, 0.0);
  const glm::dvec3 up = glm::cross(normal, side);
  for (int a = 0; a < 4; ++a)
  {
    for (int b = 0; b < 4; ++b)
    {
      ReliefEmitterSample e;
      e.Position =
        position + 0.1 * ((a + 0.5) / 4.0 - 0.5) * side + 0.1 * ((b + 0.5) / 4.0 - 0.5) * up;
      e.Normal = normal;
      e.RadianceArea = glm::dvec3(0.01 / 16.0);
      samples.push_back(e);
    }
  }
  std::vector<float> shadow;
  times.EmitterSamples = static_cast<int>(samples.size());
  times.EmitterShadowMs = MedianMilliseconds(repeats,
    [&]()
    {
      shadow = ReliefEmitterShadowMap(
        height, frame, samples, std::vector<int>(samples.size(), 0), 1, w, h);
    });
  auto result = vtkSmartPointer<vtkImageData>::New();
  result->DeepCopy(probes);
  vtkDataArray* in = probes->GetPointData()->GetScalars();
  vtkNew<vtkFloatArray> out;
  out->SetNumberOfComponents(4);
  out->SetNumberOfTuples(in->GetNumberOfTuples());
  for (vtkIdType t = 0; t < in->GetNumberOfTuples(); ++t)
  {
    out->SetTuple4(t, in->GetComponent(t, 0), in->GetComponent(t, 1), in->GetComponent(t, 2), 1.0);
  }
  result->GetPointData()->SetScalars(out);
  vtkNew<vtkFloatArray> shareArray;
  shareArray->SetNumberOfComponents(4);
  shareArray->SetNumberOfTuples(static_cast<vtkIdType>(seen.size()));
  for (std::size_t c = 0; c < seen.size(); ++c)
  {
    const float tuple[4] = { share[2 * c], share[2 * c + 1], seen[c], shadow[c] };
    shareArray->SetTypedTuple(static_cast<vtkIdType>(c), tuple);
  }
  vtkIrradianceProbesTexture::AttachVisibleShare(result, shareArray, w, h);
  return result;
}

struct Config
{
  std::string Label;
  int Emitters = 0;       // field emitters as VTK lights
  bool KeyLight = false;  // one directional VTK light
  bool Probes = false;    // SH9 probes
  bool Hidden = false;    // the relief not drawn: the frame's fixed cost
  std::vector<double> Ms; // every timed frame
  double MedianMs = 0.0;
  bool Unoccluded = false; // the probes without the precomputed occlusion
};
} // namespace

//------------------------------------------------------------------------------
int RunReliefFieldCostBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench relief-field-cost",
    "mesolight bench relief-field-cost [options]\n\nFrame time of one relief (vtkReliefMapper, "
    "relief 16+8, self-shadowed) filling the\nwindow, lit (a) by one VTK light, (b) by SH9 "
    "irradiance probes plus one light-field\nemitter as a VTK light, (c) by the probes plus four "
    "emitters, (d) plus eight (the most\nthe relief shades: more lamps are merged to eight); "
    "also the probes alone, one\nemitter alone and no light, to split the cost. The "
    "configurations alternate over\n--rounds rounds (the median of all their frames is "
    "reported), so a loaded machine\nslows them alike. The goal: (b) <= 1.5 x (a). The probes "
    "carry the relief's\nprecomputed occlusion (visible share, light visibility) as the "
    "walkthrough's do.\n");
  cl.AddValue(
    "--map", "PATTERN", "procedural height map (Bricks, Stone, HemisphereTorus, ...)", "Bricks");
  cl.AddValue("--resolution", "N", "height map resolution", "512");
  cl.AddValue("--depth", "FILE", "a depth image (0 top, 1 deepest) instead of --map");
  cl.AddFlag("--height", "the --depth image stores height (white = high), as game textures do");
  cl.AddValue("--size", "WxH", "window size", "800x800");
  cl.AddValue("--probes", "N", "N x N SH9 probes over the wall", "8");
  cl.AddValue("--frames", "N", "timed frames per configuration and round", "10");
  cl.AddValue("--rounds", "N", "rounds over the configurations", "3");
  cl.AddValue("--csv", "FILE", "also write the rows as CSV");
  int exitCode = 0;
  if (!cl.ParseArguments(args, { "--csv" }, {}, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  std::string error;
  int frames = 0, rounds = 0, probes = 0;
  ReliefSceneOptions o;
  if (!cl.GetInts({ { "--frames", 1, 10000, &frames }, { "--rounds", 1, 100, &rounds },
                    { "--probes", 1, 256, &probes }, { "--resolution", 8, 8192, &o.Resolution } },
        error) ||
    !cl.GetSize("--size", 16, 8192, o.Width, o.Height, error))
  {
    return cl.UsageError(error);
  }
  o.Pattern = cl.Get("--map");
  if (cl.Has("--height") && !cl.Has("--depth"))
  {
    return cl.UsageError("--height describes a --depth image; give one");
  }
  if (cl.Has("--depth"))
  {
    o.DepthFile = cl.Get("--depth");
    o.DepthFileIsHeight = cl.Has("--height");
    o.Pattern = o.DepthFile;
  }
  o.DepthScale = 0.08;
  o.ViewAngle = 30.0;
  o.LinearSteps = 16;
  o.RefinementSteps = 8;
  o.SelfShadowing = true;
  o.FillViewport = true;
  o.Lights = 0;
  ReliefScene scene;
  if (!BuildReliefScene(o, scene, error))
  {
    std::cerr << "mesolight bench relief-field-cost: " << error << "\n";
    return 1;
  }
  scene.Actor->GetProperty()->SetAmbient(0.0);
  scene.Actor->GetProperty()->SetDiffuse(1.0);
  scene.Actor->GetProperty()->SetSpecular(0.0);
  vtkReliefProperty* settings = scene.Mapper->GetReliefProperty();
  settings->SetExposure(1.0);
  const vtkSmartPointer<vtkImageData> plainProbes = MakeProbes(probes);
  ShareMapTimes mapTimes;
  const vtkSmartPointer<vtkImageData> probeImage =
    OccludedProbes(plainProbes, scene.ReliefTexture, o.DepthScale, rounds, mapTimes);
  auto window = MakeOffscreenWindow(o, scene.Renderer);

  std::vector<Config> configs = {
    { "background only (relief hidden)", 0, false, false, true, {}, 0.0 },
    { "no light (march only)", 0, false, false, false, {}, 0.0 },
    { "(a) one VTK light + shadows", 0, true, false, false, {}, 0.0 },
    { "(b) SH9 probes + 1 emitter light + shadows", 1, false, true, false, {}, 0.0 },
    { "(c) SH9 probes + 4 emitter lights + shadows", 4, false, true, false, {}, 0.0 },
    { "(d) SH9 probes + 8 emitter lights + shadows", vtkReliefMapper::GetMaximumNumberOfLights(),
      false, true, false, {}, 0.0 },
    { "SH9 probes only", 0, false, true, false, {}, 0.0 },
    { "1 emitter light + shadows, no probes", 1, false, false, false, {}, 0.0 },
    { "(b) without the precomputed occlusion", 1, false, true, false, {}, 0.0, true },
  };
  auto apply = [&](const Config& c)
  {
    scene.Renderer->RemoveAllLights();
    if (c.KeyLight)
    {
      scene.Renderer->AddLight(MakeKeyLight());
    }
    for (int k = 0; k < c.Emitters; ++k)
    {
      scene.Renderer->AddLight(MakeEmitterLight(k));
    }
    scene.Mapper->SetIrradianceProbesData(
      c.Probes ? (c.Unoccluded ? plainProbes.Get() : probeImage.Get()) : nullptr);
    scene.Actor->SetVisibility(!c.Hidden);
  };
  double coverage = 0.0;
  for (int round = 0; round < rounds; ++round)
  {
    for (Config& c : configs)
    {
      apply(c);
      window->Render(); // warm-up: shader variant, uploads
      window->WaitForCompletion();
      for (int f = 0; f < frames; ++f)
      {
        c.Ms.push_back(MedianMilliseconds(1,
          [&]()
          {
            window->Render();
            window->WaitForCompletion();
          }));
      }
      if (round == 0 && c.KeyLight)
      {
        const Frame frame = CaptureFrame(window);
        long long covered = 0;
        for (size_t p = 0; p < frame.Depth.size(); ++p)
        {
          covered += frame.Covered(p) ? 1 : 0;
        }
        coverage = frame.Depth.empty() ? 0.0 : double(covered) / frame.Depth.size();
      }
    }
  }
  for (Config& c : configs)
  {
    std::nth_element(c.Ms.begin(), c.Ms.begin() + c.Ms.size() / 2, c.Ms.end());
    c.MedianMs = c.Ms[c.Ms.size() / 2];
  }
  const double background = configs[0].MedianMs;
  const double single = configs[2].MedianMs;
  const double singleRelief = single - background;
  std::cout << "Relief lit by a light field vs one VTK light: map " << o.Pattern << " "
            << o.Resolution << ", relief 16+8 with self-shadowing, " << o.Width << "x" << o.Height
            << " window, " << std::fixed << std::setprecision(1) << 100.0 * coverage
            << "% covered, " << probes << "x" << probes << " SH9 probes; " << rounds << " rounds x "
            << frames << " frames (median)\n";
  std::cout << "ratio: ms/frame over (a)'s; relief ratio: the same less the background frame\n\n";
  std::cout << std::left << std::setw(46) << "configuration" << std::right << std::setw(10)
            << "ms/frame" << std::setw(8) << "ratio" << std::setw(14) << "relief ratio"
            << "\n";
  for (const Config& c : configs)
  {
    std::cout << std::left << std::setw(46) << c.Label << std::right << std::fixed
              << std::setprecision(2) << std::setw(10) << c.MedianMs << std::setw(8)
              << c.MedianMs / single << std::setw(14)
              << (c.Hidden ? 0.0 : (c.MedianMs - background) / singleRelief) << "\n";
  }
  const double ratioB = (configs[3].MedianMs - background) / singleRelief;
  std::cout << "\n(b) / (a) per relief pixel: " << std::setprecision(2) << ratioB
            << (ratioB <= 1.5 ? " (goal <= 1.5: met)" : " (goal <= 1.5: NOT met)") << "\n";
  const ShareMapTimes& m = mapTimes;
  const double mapMs = m.FirstPassMs + m.WallPassMs + m.SecondPassMs;
  const double marchingWallsMs = m.FirstPassMs + m.SecondPassMarchingWallsMs;
  const double marchingMs = m.FirstPassMs + m.SecondPassMarchingMs;
  std::cout << "\nThe probes' visible-share map (the seen shares' part), " << m.Width << " x "
            << m.Height << " cells, " << m.Directions << " directions, walls of " << m.WallLevels
            << " levels (median of " << rounds << " runs, ParallelFor's threads):\n"
            << std::setprecision(1) << "  first pass " << m.FirstPassMs << " ms ("
            << 100.0 * m.LeavingShare << "% of the directions leave the relief), the side walls' "
            << "shares " << m.WallPassMs << " ms\n  second pass reading both " << m.SecondPassMs
            << " ms; marching the walls' directions " << m.SecondPassMarchingWallsMs
            << " ms; marching every direction again " << m.SecondPassMarchingMs << " ms (the "
            << "first pass's hits against marching again: largest change " << std::setprecision(7)
            << m.HitsLargestChange << ", cells moved by more than 1e-4: " << m.HitsCellsOver
            << ", within 1e-4: " << (m.HitsLargestChange <= 1e-4 ? "yes" : "NO") << ")\n"
            << std::setprecision(1) << "  the map " << mapMs << " ms, against " << marchingWallsMs
            << " ms (" << std::setprecision(2) << mapMs / std::max(1e-9, marchingWallsMs)
            << "x) and " << std::setprecision(1) << marchingMs << " ms (" << std::setprecision(2)
            << mapMs / std::max(1e-9, marchingMs) << "x); reading the walls' shares moves the "
            << "seen shares by " << std::setprecision(4) << m.WallsMeanChange << " on average, "
            << m.WallsLargestChange << " at most\n"
            << std::setprecision(1) << "  the area light's shadow by the relief ("
            << m.EmitterSamples << " samples of emitter 0, a march to each from every cell) "
            << m.EmitterShadowMs << " ms\n";
  std::cout.unsetf(std::ios::fixed);
  if (cl.Has("--csv"))
  {
    const std::string file = cl.Get("--csv");
    std::ofstream csv(file);
    csv << "configuration,vtk_lights,emitter_lights,sh9_probes,ms_per_frame,ratio_to_a,"
           "relief_ratio_to_a,window,coverage,map,rounds,frames\n";
    for (const Config& c : configs)
    {
      csv << '"' << c.Label << "\"," << (c.KeyLight ? 1 : 0) << ',' << c.Emitters << ','
          << (c.Probes ? probes * probes : 0) << ',' << c.MedianMs << ',' << c.MedianMs / single
          << ',' << (c.Hidden ? 0.0 : (c.MedianMs - background) / singleRelief) << ',' << o.Width
          << 'x' << o.Height << ',' << coverage << ',' << o.Pattern << ',' << rounds << ','
          << frames << "\n";
    }
    if (!csv)
    {
      std::cerr << "mesolight bench relief-field-cost: could not write " << file << "\n";
      return 1;
    }
    std::cout << "wrote " << file << "\n";
  }
  return 0;
}

} // namespace mesolight
