// SPDX-License-Identifier: BSD-3-Clause
// AutomaticSettings: the light field's resolution chosen from the scene instead of a fixed
// 513 directions x 32 x 32 lines.
//
// A face narrower than the line spacing h is crossed by a line of a given direction only by
// chance, so what it receives is a lottery over the directions (Wither 2005 §3.6: the field's
// error falls with the number of lines through a patch). The line count per face and
// direction grows as (width / h)^2, so h follows the scene's small features: the width of a
// triangle (its smallest altitude, 2 area / longest edge), area-weighted, at the 10th percentile
// (a few slivers do not decide). h is the feature width over LinesPerFeature, and the line count
// per side N = 2 / h in the field's unit sphere, rounded up to a multiple of 8 (tiles of 8 x 8).
//
// Time and memory grow with the number of lines K N^2 (the maps hold one cell per line and
// surface crossed), so N is then limited by MaxLines and by the memory budget (EstimateMemory
// within BudgetShare of it). The directions follow N: a line spacing refined without more
// directions leaves the angular sampling as coarse as before (bands and round splats around
// small lights, whose light then reaches a receiver along few directions), so K grows with N
// (513 up to 32 lines per side, 2049 from 48, 8193 from 128, when the line cap allows).
// The texels stay the cell side: a texel receives about K/2 lines per cell area, and a smaller
// texel is crossed by fewer of them (noisier, measured by `mesolight bench vlf-accuracy`).
#ifndef mesolight_vlf_AutomaticSettings_h
#define mesolight_vlf_AutomaticSettings_h

#include "LightField.h"

#include <cstdint>
#include <string>

namespace mesolight
{
namespace vlf
{

struct AutomaticLimits
{
  std::uint64_t MemoryBudget = std::uint64_t(4) << 30; // bytes; the settings' budget
  double BudgetShare = 0.5;                             // of the budget the estimate may use
  std::uint64_t MaxLines = std::uint64_t(2049) * 64 * 64; // K N^2, time's proxy
  int MinRaysPerSide = 32;
  int MaxRaysPerSide = 256;
  double LinesPerFeature = 2.0; // lines across the small-feature width, per direction
};

struct AutomaticChoice
{
  LightFieldSettings Settings;
  float SceneDiameter = 0.0f; // world units: the bounding box's diagonal
  float FeatureWidth = 0.0f;  // world units: area-weighted 10th percentile of triangle widths
  int WantedRaysPerSide = 0;  // what the features ask for, before the caps
  std::string Limit;          // "features", "line cap", "memory budget" or "minimum"
  std::string Describe() const; // "2049 directions x 64 x 64 lines (features 0.1 m ask 296; ...)"
};

// Area-weighted 10th percentile of the triangles' smallest altitudes (2 area / longest edge),
// in the scene's units; 0 for a scene without triangles of nonzero area.
float SmallFeatureWidth(const TriangleScene& scene);

// The settings for `scene` (world units) within `limits` (see above). TilesPerSide is
// RaysPerSide / 8, TexelSize 0 (the cell side), MemoryBudget limits.MemoryBudget. Throws
// std::invalid_argument for a scene without triangles.
AutomaticChoice ChooseAutomaticSettings(
  const TriangleScene& scene, const AutomaticLimits& limits = {});

// The directions the automatic choice pairs with N lines per side.
std::size_t AutomaticDirections(int raysPerSide);

// Fills in what `requested` leaves automatic: RaysPerSide 0 is chosen from the scene
// (ChooseAutomaticSettings within its MemoryBudget), Directions 0 follows the lines
// (AutomaticDirections), TilesPerSide 0 is RaysPerSide / 8; given values are kept. Returns the
// choice (Describe() for a log line; Limit "given" when nothing was automatic).
AutomaticChoice ResolveAutomaticSettings(
  const TriangleScene& scene, const LightFieldSettings& requested);

} // namespace vlf
} // namespace mesolight

#endif
