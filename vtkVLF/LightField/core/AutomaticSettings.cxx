// SPDX-License-Identifier: BSD-3-Clause
#include "AutomaticSettings.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <stdexcept>
#include <utility>
#include <vector>

namespace mesolight
{
namespace vlf
{

namespace
{
LightFieldSettings SettingsFor(int rays, std::uint64_t budget)
{
  LightFieldSettings s;
  s.Directions = AutomaticDirections(rays);
  s.RaysPerSide = rays;
  s.TilesPerSide = std::max(1, rays / 8);
  s.TexelSize = 0.0f;
  s.MemoryBudget = budget;
  return s;
}
} // namespace

// The angular sampling refined with the spatial one.
std::size_t AutomaticDirections(int raysPerSide)
{
  if (raysPerSide >= 128)
  {
    return 8193;
  }
  return raysPerSide >= 48 ? 2049 : 513;
}

float SmallFeatureWidth(const TriangleScene& scene)
{
  std::vector<std::pair<float, double>> widths; // (width, area)
  double total = 0.0;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const glm::vec3 a = scene.Vertex(t, 0), b = scene.Vertex(t, 1), c = scene.Vertex(t, 2);
    const double area = 0.5 * static_cast<double>(glm::length(glm::cross(b - a, c - a)));
    const float longest = std::max({ glm::length(b - a), glm::length(c - b), glm::length(a - c) });
    if (!(area > 0.0) || !(longest > 0.0f))
    {
      continue;
    }
    widths.emplace_back(static_cast<float>(2.0 * area / longest), area);
    total += area;
  }
  if (widths.empty())
  {
    return 0.0f;
  }
  std::sort(widths.begin(), widths.end());
  double below = 0.0;
  for (const auto& w : widths)
  {
    below += w.second;
    if (below >= 0.1 * total)
    {
      return w.first;
    }
  }
  return widths.back().first;
}

AutomaticChoice ChooseAutomaticSettings(const TriangleScene& scene, const AutomaticLimits& limits)
{
  glm::vec3 lower, upper;
  if (scene.TriangleCount() == 0 || !SceneBounds(scene, lower, upper))
  {
    throw std::invalid_argument("the scene has no triangles to choose light field settings for");
  }
  AutomaticChoice choice;
  choice.SceneDiameter = glm::length(upper - lower);
  choice.FeatureWidth = SmallFeatureWidth(scene);
  const int lo = std::max(8, limits.MinRaysPerSide / 8 * 8);
  const int hi = std::max(lo, limits.MaxRaysPerSide / 8 * 8);
  // In the unit sphere the diameter is 2 and the lines' square is 2 wide: N = 2 / h with
  // h = (feature / diameter * 2) / LinesPerFeature, i.e. N = diameter * lines / feature.
  int wanted = hi;
  if (choice.FeatureWidth > 0.0f && choice.SceneDiameter > 0.0f)
  {
    const double n = static_cast<double>(choice.SceneDiameter) * limits.LinesPerFeature /
      static_cast<double>(choice.FeatureWidth);
    wanted = static_cast<int>(std::min<double>(hi, std::ceil(n / 8.0) * 8.0));
  }
  choice.WantedRaysPerSide = wanted;
  const int preferred = std::min(hi, std::max(lo, limits.PreferredRaysPerSide / 8 * 8));
  int rays = std::max(preferred, wanted);
  choice.Limit = wanted <= preferred ? "the preferred minimum" : "features";
  // From the most lines down: at each N first its own directions, then, where memory refused
  // them, 513 (on the boxes of the benchmark 513 x 64 beat 2049 x 32 when memory allowed
  // neither 2049 x 64 nor more).
  LightFieldSettings chosen = SettingsFor(lo, limits.MemoryBudget);
  bool found = false;
  MemoryEstimate first; // the first exact estimate, scaled to screen the others
  int firstRays = 0;
  double firstLines = 0.0;
  for (; rays >= lo && !found; rays -= 8)
  {
    LightFieldSettings s = SettingsFor(rays, limits.MemoryBudget);
    for (const std::size_t directions : { s.Directions, std::size_t(513) })
    {
      s.Directions = directions;
      if (static_cast<std::uint64_t>(directions) * rays * rays > limits.MaxLines)
      {
        choice.Limit = "line cap";
        break; // fewer lines per side, not fewer directions (513 only where memory asks)
      }
      // An estimate costs directions x triangles (long for a large scene), so candidates are
      // screened by scaling the first one -- maps grow as K N^2, textures as N^2 -- and only
      // those predicted to fit are estimated exactly.
      const double share = limits.BudgetShare * static_cast<double>(limits.MemoryBudget);
      if (first.TotalBytes > 0)
      {
        const double lines = static_cast<double>(directions) * rays * rays;
        const double side = static_cast<double>(rays) / firstRays;
        const double predicted = static_cast<double>(first.MapBytes) * lines / firstLines +
          static_cast<double>(first.TextureBytes) * side * side;
        if (predicted > 1.25 * share)
        {
          choice.Limit = "memory budget";
          continue;
        }
      }
      const MemoryEstimate e = EstimateMemory(scene, s);
      if (first.TotalBytes == 0)
      {
        first = e;
        firstRays = rays;
        firstLines = static_cast<double>(directions) * rays * rays;
      }
      if (static_cast<double>(e.TotalBytes) > share)
      {
        choice.Limit = "memory budget";
        continue;
      }
      chosen = s;
      found = true;
      break;
    }
  }
  // Halve the texels while the features ask for FineTexelRatio times the lines per side the
  // texels give, at most MaxTexelHalvings times, and while the estimate fits the budget share.
  for (int halvings = 1; limits.FineTexelRatio > 0.0 && chosen.Directions >= 2049 &&
       halvings <= limits.MaxTexelHalvings &&
       static_cast<double>(wanted) >=
         limits.FineTexelRatio * chosen.RaysPerSide * static_cast<double>(1 << (halvings - 1));
       ++halvings)
  {
    const float before = chosen.TexelSize;
    chosen.TexelSize = chosen.CellSize() / static_cast<float>(1 << halvings);
    // The textures grow fourfold: still within the budget share?
    if (static_cast<double>(EstimateMemory(scene, chosen).TotalBytes) >
      limits.BudgetShare * static_cast<double>(limits.MemoryBudget))
    {
      chosen.TexelSize = before;
      break;
    }
  }
  // Finer texels on the surfaces others stand on, within the budget share.
  if (limits.ContactTexelHalvings > 0 && limits.FineTexelRatio > 0.0 && chosen.Directions >= 2049)
  {
    chosen.ContactTexelHalvings = std::min(limits.ContactTexelHalvings, MaxContactTexelHalvings);
    if (static_cast<double>(EstimateMemory(scene, chosen).TotalBytes) >
      limits.BudgetShare * static_cast<double>(limits.MemoryBudget))
    {
      chosen.ContactTexelHalvings = 0;
    }
  }
  choice.Settings = chosen;
  return choice;
}

AutomaticChoice ResolveAutomaticSettings(const TriangleScene& scene,
  const LightFieldSettings& requested, bool finalGather, int contactTexelHalvings)
{
  AutomaticChoice choice;
  if (requested.RaysPerSide == 0)
  {
    AutomaticLimits limits;
    limits.MemoryBudget = requested.MemoryBudget;
    if (!finalGather)
    {
      limits.FineTexelRatio = GatherlessFineTexelRatio;
      limits.MaxTexelHalvings = 1;
      limits.ContactTexelHalvings = 0;
    }
    choice = ChooseAutomaticSettings(scene, limits);
  }
  else
  {
    choice.Limit = "given";
  }
  LightFieldSettings s = requested;
  if (s.RaysPerSide == 0)
  {
    s.RaysPerSide = choice.Settings.RaysPerSide;
  }
  if (s.Directions == 0)
  {
    // Both automatic: the choice's (513 where memory asked); lines given: theirs.
    s.Directions =
      requested.RaysPerSide == 0 ? choice.Settings.Directions : AutomaticDirections(s.RaysPerSide);
  }
  if (s.TilesPerSide == 0)
  {
    s.TilesPerSide = std::max(1, s.RaysPerSide / 8);
  }
  if (requested.RaysPerSide == 0 && requested.TexelSize == 0.0f &&
    s.RaysPerSide == choice.Settings.RaysPerSide && s.Directions == choice.Settings.Directions)
  {
    s.TexelSize = choice.Settings.TexelSize; // half the cell where the features ask for it
    if (s.ContactTexelHalvings == 0)
    {
      s.ContactTexelHalvings = choice.Settings.ContactTexelHalvings;
    }
  }
  if (contactTexelHalvings != AutomaticContactTexelHalvings)
  {
    s.ContactTexelHalvings = contactTexelHalvings; // given: kept
  }
  choice.Settings = s;
  return choice;
}

std::string AutomaticChoice::Describe() const
{
  char text[320];
  std::snprintf(text, sizeof(text),
    "%zu directions x %d x %d lines%s%s (scene %.3g across, small features %.3g wide ask for %d "
    "lines per side; limited by %s)",
    this->Settings.Directions, this->Settings.RaysPerSide, this->Settings.RaysPerSide,
    this->Settings.TexelSize <= 0.0f ? ""
      : this->Settings.TexelSize > 0.3f * this->Settings.CellSize()
      ? ", texels half the line spacing"
      : ", texels a quarter of the line spacing",
    this->Settings.ContactTexelHalvings <= 0     ? ""
      : this->Settings.ContactTexelHalvings == 1 ? "; texels halved on surfaces others stand on"
                                                 : "; finer texels on surfaces others stand on",
    static_cast<double>(this->SceneDiameter), static_cast<double>(this->FeatureWidth),
    this->WantedRaysPerSide, this->Limit.c_str());
  return text;
}

} // namespace vlf
} // namespace mesolight
