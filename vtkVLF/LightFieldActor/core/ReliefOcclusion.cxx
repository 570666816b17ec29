// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefOcclusion.h"

#include "Distribution.h" // Reducer, Agree
#include "EmbreeScene.h"
#include "EmitterLights.h" // EmitterLight
#include "LightField.h"
#include "Luminance.h"
#include "ReliefSurface.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <stdexcept>
#include <thread>

namespace mesolight
{
namespace vlf
{

std::vector<ReliefEmitterSample> EmitterSamples(const TriangleScene& scene, int n)
{
  std::vector<ReliefEmitterSample> samples;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const glm::vec3 ke = scene.MaterialOf(t).Emission;
    const double area = scene.Area(t);
    if (!(ke.x + ke.y + ke.z > 0.0f) || !(area > 0.0))
    {
      continue;
    }
    const glm::dvec3 a(scene.Vertex(t, 0)), b(scene.Vertex(t, 1)), c(scene.Vertex(t, 2));
    const glm::dvec3 normal = glm::normalize(glm::dvec3(scene.FaceNormal(t)));
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; j < n; ++j)
      {
        const double s = (i + 0.5) / n, r = std::sqrt((j + 0.5) / n);
        ReliefEmitterSample sample;
        sample.Position = (1.0 - r) * a + r * (1.0 - s) * b + r * s * c;
        sample.Normal = normal;
        sample.RadianceArea = glm::dvec3(ke) * (area / (n * n));
        samples.push_back(sample);
      }
    }
  }
  return samples;
}

namespace
{
// Per sample, the index of the nearest light.
std::vector<std::size_t> NearestLights(
  const std::vector<ReliefEmitterSample>& samples, const std::vector<glm::vec3>& lights)
{
  std::vector<std::size_t> nearest(samples.size(), 0);
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    double best = std::numeric_limits<double>::max();
    for (std::size_t k = 0; k < lights.size(); ++k)
    {
      const glm::dvec3 d = samples[s].Position - glm::dvec3(lights[k]);
      if (glm::dot(d, d) < best)
      {
        best = glm::dot(d, d);
        nearest[s] = k;
      }
    }
  }
  return nearest;
}
} // namespace

std::vector<ReliefEmitterSample> EmitterSamplesOfLight(
  const TriangleScene& scene, const std::vector<glm::vec3>& lights, std::size_t light, int n)
{
  const std::vector<ReliefEmitterSample> samples = EmitterSamples(scene, std::max(1, n));
  const std::vector<std::size_t> nearest = NearestLights(samples, lights);
  std::vector<ReliefEmitterSample> of;
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    if (light < lights.size() && nearest[s] == light)
    {
      of.push_back(samples[s]);
    }
  }
  return of;
}

std::vector<float> EmitterLightFactors(const LightField& field, const EmbreeScene& scene,
  const ReliefSurface& surface, const std::vector<EmitterLight>& lights, int probesU, int probesV,
  int samplesPerSide)
{
  const std::size_t count = lights.size();
  std::vector<float> factors(static_cast<std::size_t>(probesU) * probesV * count, 1.0f);
  if (count == 0)
  {
    return factors;
  }
  const auto luminance = [](const glm::dvec3& c) { return Luminance(c.x, c.y, c.z); };
  const std::vector<ReliefEmitterSample> samples =
    EmitterSamples(field.Scene(), std::max(1, samplesPerSide));
  const std::vector<std::size_t> nearest = NearestLights(samples, LightPositions(lights));
  for (int j = 0; j < probesV; ++j)
  {
    for (int i = 0; i < probesU; ++i)
    {
      const glm::dvec3 p(ReliefProbePoint(surface, i, j, probesU, probesV));
      std::vector<double> seen(count, 0.0);
      for (std::size_t s = 0; s < samples.size(); ++s)
      {
        const ReliefEmitterSample& e = samples[s];
        glm::dvec3 l;
        double r2 = 0.0;
        const double weight =
          EmitterSampleGeometry(e, p, surface.Normal, l, r2) * luminance(e.RadianceArea);
        if (!(weight > 0.0))
        {
          continue;
        }
        SceneRay ray;
        ray.Origin = glm::vec3(p);
        ray.Direction = glm::vec3(l);
        ray.TNear = 1e-4f;
        ray.TFar = static_cast<float>(std::sqrt(r2) * (1.0 - 1e-4));
        if (!scene.Occluded(ray))
        {
          seen[nearest[s]] += weight;
        }
      }
      for (std::size_t k = 0; k < count; ++k)
      {
        const EmitterLight& light = lights[k];
        const glm::dvec3 toLight = glm::dvec3(light.Position) - p;
        const double d2 = glm::dot(toLight, toLight);
        if (!(d2 > 0.0))
        {
          continue;
        }
        const glm::dvec3 l = toLight / std::sqrt(d2);
        const double point = std::max(0.0, glm::dot(surface.Normal, l)) *
          std::max(0.0, -glm::dot(glm::dvec3(light.Normal), l)) / d2 *
          luminance(glm::dvec3(light.Intensity()));
        if (point > 0.0)
        {
          factors[(static_cast<std::size_t>(j) * probesU + i) * count + k] =
            static_cast<float>(std::min(seen[k] / point, double{ MaxEmitterLightFactor }));
        }
      }
    }
  }
  return factors;
}

ReliefFrame ReliefFrameOf(const ReliefSurface& surface, double depthScale)
{
  ReliefFrame frame;
  frame.Origin = surface.Origin;
  frame.AxisU = surface.AxisU;
  frame.AxisV = surface.AxisV;
  frame.Normal = surface.Normal;
  frame.DepthScale = depthScale;
  return frame;
}

std::vector<float> ReliefVisibleShareGrid(const HeightField& field, const ReliefFrame& frame,
  int& gridWidth, int& gridHeight, const ProgressCallback& progress,
  const std::vector<ReliefEmitterSample>& lightSamples, Reducer* reducer, std::vector<float>* walls,
  const ReliefLighting* probes)
{
  gridWidth = std::min(field.Width(), MaxVisibleShareSide);
  gridHeight = std::min(field.Height(), MaxVisibleShareSide);
  const bool split = reducer && reducer->Size() > 1;
  const GridRows rows = split ? GridRows{ reducer->Rank(), reducer->Size() } : GridRows{};
  // ReliefVisibleShareMap reports from its worker threads: only the calling thread talks to the
  // caller's callback (a VTK filter's UpdateProgress is for the thread that runs the filter);
  // the workers see its answer through the flag.
  const std::thread::id caller = std::this_thread::get_id();
  std::atomic<bool> stopped{ false };
  const ProgressCallback watched = [&](double fraction)
  {
    if (std::this_thread::get_id() == caller && !ReportProgress(progress, fraction))
    {
      stopped = true;
    }
    return !stopped;
  };
  // This rank's rows of one pass; a stop becomes AbortedError (agreed as such between ranks).
  const auto pass = [&](const std::function<std::vector<float>()>& rowsOfPass)
  {
    std::vector<float> values;
    const auto step = [&]()
    {
      try
      {
        values = rowsOfPass();
      }
      catch (const std::runtime_error&)
      {
        if (stopped)
        {
          throw AbortedError();
        }
        throw;
      }
    };
    if (split)
    {
      Agree(*reducer, step); // a stop or failure on one rank stops every rank before the sum
      // A value plus the other ranks' zeros is that value exactly.
      reducer->SumInPlace(values.data(), values.size());
    }
    else
    {
      step();
    }
    return values;
  };
  // The visible share (with the side walls' on a walled relief), then the share of the relief
  // each cell's occluded directions meet (ReliefSeenShareMap, which reads the first, whole, and
  // the points the first pass noted), then the area light's self-shadow if asked for. The
  // progress follows their rough shares of the work: the first pass and the self-shadow march,
  // the walls are a small grid and the seen shares read what the first pass noted
  // (docs/relief-against-path-tracer.md, "The map's cost").
  const int count = ReliefLighting().OcclusionDirections;
  const bool light = !lightSamples.empty();
  const bool walled = field.EdgeRule() == HeightField::Edge::Walled;
  const double shareEnd = light ? 0.55 : 0.85; // the first pass
  const double wallsEnd = shareEnd + (walled ? 0.05 : 0.0);
  const double seenEnd = light ? 0.65 : 1.0;
  // What each direction of this rank's cells met: the seen shares read it instead of marching
  // again (the same rows on every pass, so never summed).
  ReliefDirectionHits hits;
  const std::vector<float> share = pass(
    [&]()
    {
      return ReliefVisibleShareMap(field, frame, gridWidth, gridHeight, count,
        SubProgress(watched, 0.0, shareEnd), rows, &hits);
    });
  // The directions that meet a side wall read its share from here (most of the seen shares'
  // work on a walled relief marched 32 directions at each such point); the wall map reuses it.
  std::vector<float> wallShare;
  if (walled)
  {
    wallShare = pass(
      [&]()
      {
        return ReliefWallVisibleShareMap(field, frame, gridWidth, WallShareLevels, count,
          SubProgress(watched, shareEnd, wallsEnd), rows);
      });
  }
  const ReliefWallShares wallShares{ walled ? &wallShare : nullptr, WallShareLevels };
  const std::vector<float> seen = pass(
    [&]()
    {
      return ReliefSeenShareMap(field, frame, share, gridWidth, gridHeight, count,
        SubProgress(watched, wallsEnd, seenEnd), rows, &hits, wallShares);
    });
  std::vector<float> shadow;
  if (light)
  {
    shadow = pass(
      [&]()
      {
        return ReliefEmitterShadowMap(field, frame, lightSamples,
          std::vector<int>(lightSamples.size(), 0), 1, gridWidth, gridHeight,
          SubProgress(watched, seenEnd, 1.0), rows);
      });
  }
  const std::size_t components = light ? 4 : 3;
  if (walls)
  {
    walls->clear();
    if (walled)
    {
      // A small pass (4 x WallShareLevels rows of the grid's width), after the others.
      const std::vector<float> wallCells = pass(
        [&]()
        {
          return ReliefWallShareMap(field, frame, share, gridWidth, gridHeight, WallShareLevels,
            count, lightSamples, SubProgress(watched, 1.0, 1.0), rows, probes, &wallShare);
        });
      walls->resize(components * (wallCells.size() / 4));
      for (std::size_t c = 0; c < wallCells.size() / 4; ++c)
      {
        std::copy(&wallCells[4 * c], &wallCells[4 * c] + components, &(*walls)[components * c]);
      }
    }
  }
  std::vector<float> cells(components * seen.size());
  for (std::size_t c = 0; c < seen.size(); ++c)
  {
    cells[components * c] = share[2 * c];
    cells[components * c + 1] = share[2 * c + 1];
    cells[components * c + 2] = seen[c];
    if (light)
    {
      cells[components * c + 3] = shadow[c];
    }
  }
  return cells;
}

} // namespace vlf
} // namespace mesolight
