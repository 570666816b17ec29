// SPDX-License-Identifier: BSD-3-Clause
#include "AdaptiveTexels.h"

#include "FinalGather.h"
#include "Propagation.h"
#include "TextureComparison.h"

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdio>
#include <stdexcept>

namespace mesolight
{
namespace vlf
{
namespace
{
double Sum(const glm::vec3& v)
{
  return static_cast<double>(v.x) + static_cast<double>(v.y) + static_cast<double>(v.z);
}
} // namespace

AdaptiveTexelOptions FirstRuleAdaptiveTexelOptions()
{
  AdaptiveTexelOptions options;
  options.Coarsen = 0.004;
  options.CoarsenMaxNoise = 1e30;
  options.OnContactTexels = false;
  options.BorderRows = false;
  return options;
}

std::vector<SurfaceVariation> MeasureLightVariation(const LightField& field,
  const std::vector<glm::vec3>& totals, const std::vector<glm::vec3>& second, bool borderRows)
{
  if (totals.size() != field.TexelCount() || (!second.empty() && second.size() != totals.size()))
  {
    throw std::invalid_argument("the textures do not match the light field's texels");
  }
  // Texels whose centre lies on one of the surface's triangles (emitters left out).
  std::vector<std::uint8_t> on(field.TexelCount(), 0);
  for (const TexelPoint& p : SurfaceTexels(field))
  {
    on[p.Texel] = 1;
  }
  const auto value = [&](std::size_t t)
  { return second.empty() ? Sum(totals[t]) : 0.5 * (Sum(totals[t]) + Sum(second[t])); };
  const auto noise = [&](std::size_t t)
  { return second.empty() ? 0.0 : 0.5 * std::abs(Sum(totals[t]) - Sum(second[t])); };
  std::vector<SurfaceVariation> result(field.Surfaces().size());
  for (std::size_t s = 0; s < field.Surfaces().size(); ++s)
  {
    const Surface& surface = field.Surfaces()[s];
    SurfaceVariation& v = result[s];
    double sum = 0.0, noiseSum = 0.0;
    std::size_t count = 0;
    for (std::size_t t = surface.TexelOffset; t < surface.TexelOffset + surface.TexelCount(); ++t)
    {
      if (on[t] != 0)
      {
        sum += value(t);
        noiseSum += noise(t);
        ++count;
      }
    }
    if (count == 0 || !(sum > 0.0))
    {
      continue;
    }
    v.Mean = sum / static_cast<double>(count);
    const int w = surface.TextureWidth, h = surface.TextureHeight;
    const auto at = [&](int a, int b)
    { return surface.TexelOffset + static_cast<std::size_t>(b) * static_cast<std::size_t>(w) + a; };
    double defect = 0.0;
    for (int b = 0; b < h; ++b)
    {
      for (int a = 0; a < w; ++a)
      {
        const std::size_t c = at(a, b);
        if (on[c] == 0)
        {
          continue;
        }
        // Along each axis where both neighbours are on the surface.
        const std::size_t pairs[2][2] = { { a > 0 ? at(a - 1, b) : c,
                                            a + 1 < w ? at(a + 1, b) : c },
          { b > 0 ? at(a, b - 1) : c, b + 1 < h ? at(a, b + 1) : c } };
        for (const auto& p : pairs)
        {
          const bool low = p[0] != c && on[p[0]] != 0, high = p[1] != c && on[p[1]] != 0;
          if (low && high)
          {
            defect += std::abs(value(c) - 0.5 * (value(p[0]) + value(p[1])));
            ++v.Samples;
          }
          else if (borderRows && (low || high))
          {
            // A border texel: read clamped beyond its centre, it misses half the step to its
            // inner neighbour at the border (twice that with twice the texels).
            defect += 0.5 * std::abs(value(c) - value(low ? p[0] : p[1]));
            ++v.Samples;
          }
        }
      }
    }
    if (v.Samples == 0)
    {
      continue;
    }
    // The noise of the mean's texels (|g1 - g2| / 2) read as a defect: a defect of independent
    // noise sigma per texel has a standard deviation of sqrt(1.5) sigma, its mean absolute value
    // sqrt(2 / pi) sqrt(1.5) sigma ~ sigma, and E|g1 - g2| / 2 estimates sqrt(2 / pi) sigma:
    // subtract sqrt(1.5) times the mean noise.
    v.Noise = std::sqrt(1.5) * noiseSum / static_cast<double>(count) / v.Mean;
    v.Defect = std::max(0.0, defect / static_cast<double>(v.Samples) / v.Mean - v.Noise);
  }
  return result;
}

std::vector<std::int8_t> ChooseTexelLevels(const LightField& field,
  const std::vector<SurfaceVariation>& variation, const AdaptiveTexelOptions& options,
  const std::vector<std::int8_t>& floor)
{
  if (variation.size() != field.Surfaces().size() ||
    (!floor.empty() && floor.size() != variation.size()))
  {
    throw std::invalid_argument("the variation does not match the light field's surfaces");
  }
  std::vector<std::int8_t> levels(variation.size(), 0);
  for (std::size_t s = 0; s < variation.size(); ++s)
  {
    const SurfaceVariation& v = variation[s];
    const Surface& surface = field.Surfaces()[s];
    // A contact surface's halvings as a level (negative), else 0: no cap.
    const std::int8_t cap = floor.empty() ? std::int8_t(0) : floor[s];
    if (v.Samples == 0)
    {
      levels[s] = std::min<std::int8_t>(cap, 0); // an emitter, or too small to measure
      continue;
    }
    if (v.Defect > options.RefineTwice)
    {
      levels[s] = -2;
    }
    else if (v.Defect > options.Refine)
    {
      levels[s] = -1;
    }
    else if (v.Defect < options.Coarsen && v.Noise <= options.CoarsenMaxNoise && cap == 0 &&
      std::min(surface.TextureWidth, surface.TextureHeight) >= 2 * options.MinCoarseSide)
    {
      levels[s] = 1;
    }
    if (cap < 0)
    {
      levels[s] = std::min(levels[s], cap); // a contact surface: at least its halvings
    }
  }
  return levels;
}

std::vector<std::int8_t> LimitRefinement(const std::vector<std::size_t>& baseTexels,
  const std::vector<SurfaceVariation>& variation, const std::vector<std::int8_t>& levels,
  const std::vector<std::int8_t>& floor, double budget)
{
  const std::size_t n = levels.size();
  if (baseTexels.size() != n || variation.size() != n || (!floor.empty() && floor.size() != n))
  {
    throw std::invalid_argument("the texel levels, counts and variation name different surfaces");
  }
  if (budget < 0.0)
  {
    return levels;
  }
  const auto texelsAt = [&](std::size_t s, int level)
  { return std::ldexp(static_cast<double>(baseTexels[s]), -2 * level); };
  struct Step
  {
    double Gain; // per added texel
    double Cost; // added texels
    std::size_t Surface;
    int From; // the level it refines
  };
  std::vector<Step> steps;
  std::vector<std::int8_t> result = levels;
  double allowance = 0.0;
  for (std::size_t s = 0; s < n; ++s)
  {
    const int start = std::min<int>(floor.empty() ? 0 : floor[s], 0);
    allowance += budget * texelsAt(s, start);
    if (levels[s] > start)
    {
      allowance += texelsAt(s, start) - texelsAt(s, levels[s]); // coarsening pays for refining
    }
    for (int from = start; from > levels[s]; --from)
    {
      steps.push_back(
        { variation[s].Defect * std::ldexp(1.0, 3 * from), 3.0 * texelsAt(s, from), s, from });
    }
    if (levels[s] < start)
    {
      result[s] = static_cast<std::int8_t>(start);
    }
  }
  // Best gain per texel first; ties by surface, so the choice does not depend on the sort.
  std::sort(steps.begin(), steps.end(),
    [](const Step& a, const Step& b)
    {
      return a.Gain != b.Gain    ? a.Gain > b.Gain
        : a.Surface != b.Surface ? a.Surface < b.Surface
                                 : a.From > b.From;
    });
  double spent = 0.0;
  for (const Step& step : steps)
  {
    if (result[step.Surface] == step.From && spent + step.Cost <= allowance)
    {
      spent += step.Cost;
      result[step.Surface] = static_cast<std::int8_t>(step.From - 1);
    }
  }
  return result;
}

std::string AdaptiveTexelReport::Describe() const
{
  char text[400];
  std::snprintf(text, sizeof(text),
    "texels finer on %zu, coarser on %zu of %zu surfaces: %zu -> %zu texels; %zu contact "
    "surfaces, %zu finer than the contact texels alone, %zu left coarser by the gather budget "
    "(gathered texels %.3g, %.2f x the contact texels'; first pass %.1f s: field %.1f, "
    "gathers %.1f)",
    this->Finer, this->Coarser, this->Variation.size(), this->BaseTexels, this->Texels,
    this->Contact, this->BeyondContact, this->Limited, this->Gathered,
    this->GatheredDefault > 0.0 ? this->Gathered / this->GatheredDefault : 1.0, this->Seconds,
    this->FieldSeconds, this->GatherSeconds);
  return text;
}

LightFieldSettings ChooseAdaptiveTexels(const TriangleScene& scene,
  const LightFieldSettings& settings, const AdaptiveTexelOptions& options,
  AdaptiveTexelReport* report)
{
  const auto start = std::chrono::steady_clock::now();
  // The first pass: the base texels everywhere, fewer directions (the gather reads the field
  // only at its indirect rays' hits, the direct light -- the shadows -- it computes exactly).
  LightFieldSettings first = settings;
  first.TexelSize = settings.TexelSize > 0.0f ? settings.TexelSize : settings.CellSize();
  first.ContactTexelHalvings = 0;
  first.SurfaceTexelLevels.clear();
  first.Directions = std::min(settings.Directions, options.FirstPassDirections);
  std::unique_ptr<LightField> field =
    LightField::Build(scene, first, SubProgress(options.Progress, 0.0, 0.2));
  PropagationOptions propagation;
  propagation.Progress = SubProgress(options.Progress, 0.2, 0.5);
  PropagateToTolerance(*field, DefaultTolerance, DefaultMaxIterations, propagation);
  const auto fieldDone = std::chrono::steady_clock::now();
  FinalGatherOptions gather;
  gather.IndirectRays = options.FirstPassIndirectRays;
  gather.DirectSamples = options.FirstPassDirectSamples;
  gather.Prepass = false;
  gather.Progress = SubProgress(options.Progress, 0.5, 0.75);
  FinalGather(*field, gather);
  const std::vector<glm::vec3> one = field->TotalDiffuse;
  RestorePropagatedDiffuse(*field);
  gather.Sequence = 2;
  gather.Progress = SubProgress(options.Progress, 0.75, 1.0);
  FinalGather(*field, gather);
  const auto gatherDone = std::chrono::steady_clock::now();
  const std::vector<SurfaceVariation> variation =
    MeasureLightVariation(*field, one, field->TotalDiffuse, options.BorderRows);

  // The contact halvings as levels: the floor of the chosen ones.
  std::vector<std::int8_t> contact(field->Surfaces().size(), 0);
  if (options.OnContactTexels && settings.ContactTexelHalvings > 0)
  {
    std::vector<std::uint32_t> triangleSurface(field->Scene().TriangleCount());
    for (std::size_t t = 0; t < triangleSurface.size(); ++t)
    {
      triangleSurface[t] = field->SurfaceOfTriangle(t);
    }
    // Probed as LightField::Build probes them (GroupSurfaces).
    const std::vector<std::uint8_t> on =
      ContactSurfaces(field->Scene(), field->Surfaces(), triangleSurface, 0.25f * first.TexelSize);
    for (std::size_t s = 0; s < on.size(); ++s)
    {
      contact[s] = on[s] != 0 ? static_cast<std::int8_t>(-settings.ContactTexelHalvings) : 0;
    }
  }
  LightFieldSettings chosen = settings;
  chosen.TexelSize = first.TexelSize;
  const std::vector<std::int8_t> measured = ChooseTexelLevels(*field, variation, options, contact);
  // Within the gather budget: the texels on the surfaces (what the final gather gathers).
  std::vector<std::size_t> onSurface(field->Surfaces().size(), 0);
  for (const TexelPoint& p : SurfaceTexels(*field))
  {
    ++onSurface[p.Surface];
  }
  chosen.SurfaceTexelLevels =
    LimitRefinement(onSurface, variation, measured, contact, options.GatherBudget);
  // Within the budget: while the finer texels do not fit, the finest surfaces beyond their
  // contact halvings get one level less.
  for (std::size_t estimate = EstimateMemory(scene, chosen).TotalBytes;
       estimate > settings.MemoryBudget; estimate = EstimateMemory(scene, chosen).TotalBytes)
  {
    std::int8_t finest = 0;
    for (std::size_t s = 0; s < contact.size(); ++s)
    {
      if (chosen.SurfaceTexelLevels[s] < contact[s])
      {
        finest = std::min(finest, chosen.SurfaceTexelLevels[s]);
      }
    }
    if (finest >= 0)
    {
      break; // the default's texels: Build refuses the field as it would without the choice
    }
    for (std::size_t s = 0; s < contact.size(); ++s)
    {
      std::int8_t& level = chosen.SurfaceTexelLevels[s];
      level = level == finest && level < contact[s] ? static_cast<std::int8_t>(level + 1) : level;
    }
  }
  if (report != nullptr)
  {
    report->Variation = variation;
    report->Finer = static_cast<std::size_t>(std::count_if(chosen.SurfaceTexelLevels.begin(),
      chosen.SurfaceTexelLevels.end(), [](std::int8_t l) { return l < 0; }));
    report->Coarser = static_cast<std::size_t>(std::count_if(chosen.SurfaceTexelLevels.begin(),
      chosen.SurfaceTexelLevels.end(), [](std::int8_t l) { return l > 0; }));
    for (std::size_t s = 0; s < contact.size(); ++s)
    {
      report->Contact += contact[s] < 0 && chosen.SurfaceTexelLevels[s] <= contact[s] ? 1 : 0;
      report->BeyondContact += chosen.SurfaceTexelLevels[s] < contact[s] ? 1 : 0;
    }
    for (std::size_t s = 0; s < contact.size(); ++s)
    {
      report->Limited += chosen.SurfaceTexelLevels[s] > measured[s] ? 1 : 0;
      const double texels = static_cast<double>(onSurface[s]);
      report->GatheredDefault += std::ldexp(texels, -2 * std::min<int>(contact[s], 0));
      report->Gathered += std::ldexp(texels, -2 * chosen.SurfaceTexelLevels[s]);
    }
    report->BaseTexels = field->TexelCount();
    report->FirstPassBytes = field->AllocatedBytes();
    report->Texels = EstimateMemory(scene, chosen).Texels;
    report->Seconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    report->FieldSeconds = std::chrono::duration<double>(fieldDone - start).count();
    report->GatherSeconds = std::chrono::duration<double>(gatherDone - fieldDone).count();
  }
  return chosen;
}

} // namespace vlf
} // namespace mesolight
