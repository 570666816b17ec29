// SPDX-License-Identifier: BSD-3-Clause
// AutomaticSettings: the light field's resolution chosen from the scene instead of a fixed
// 513 directions x 32 x 32 lines.
//
// A face narrower than the line spacing h is crossed by a line of a given direction only by
// chance, so what it receives is a lottery over the directions (Wither 2005 §3.6: the field's
// error falls with the number of lines through a patch), and few directions leave bands and
// round splats around small lights. Measured per pixel against the path tracer on the five
// scenes of `mesolight bench vlf-accuracy` (docs/measurements/vlf/accuracy/), 2049 directions x
// 64 x 64 lines gave 0.4-0.7 times the mean error of 513 x 32 x 32 on every scene, at 4-15 times
// the time and memory; so that is the least the automatic choice takes when the budget allows.
//
// Beyond it the scene's small features ask for more: the width of a triangle (its smallest
// altitude, 2 area / longest edge), area-weighted, at the 10th percentile (a few slivers do not
// decide); two lines across it per direction: N = diameter * 2 / width, a multiple of 8 (tiles
// of 8 x 8 cells). Time and memory grow with the lines K N^2 (the maps hold one cell per line
// and surface crossed), so N is limited by MaxLines (2049 x 96^2) and by the memory budget
// (EstimateMemory within BudgetShare of it): from the most lines down, each N with its own
// directions (AutomaticDirections), and with 513 where the memory budget refused those.
//
// The texels are the cell side, or half of it where the features ask for more lines per side
// than the caps allowed (at least twice as many without the final gather): the resolution the lines
// cannot give then comes from the textures alone, each texel still gathering about a quarter of
// 2049 directions' lines. Measured on `bench vlf-accuracy` at 2049 x 96 x 96
// (docs/measurements/vlf/accuracy/): the boxes (their 9 cm features ask for 256 lines) went
// from 33.3% to 24.9% mean error per pixel (the floor between them from 60% to 37%), while the
// corridor (136 asked) went from 7.0% to 7.9% (noisier walls, the same edges), and at 513
// directions half texels gave the boxes nothing.
//
// With the final gather the texels of the surfaces other surfaces stand on (ContactSurfaces: a
// floor under boxes, a wall behind ribs) are halved once more: their contact shadows are strips
// about as wide as the features are high, which the gather computes exactly at each texel centre
// but bilinear reads between centres smear. Measured on the boxes (docs/vlf.md, "Finer texels
// where surfaces meet"): 5.7% / 14.4% -> 2.8% / 7.9% mean / p95 per pixel, the floor beside the
// boxes 24.2% -> 8.0%, at 167 MiB instead of 162.
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
  double BudgetShare = 0.5;                            // of the budget the estimate may use
  // K N^2, time's proxy: 2049 x 96 x 96. The corridor of the benchmark, whose 25 cm rib faces
  // ask for 136 lines per side, went from 9.0% to 7.0% mean error per pixel (p95 31.6% to 23.8%)
  // between 64 and 96 lines per side, at 354 and 597 MiB.
  std::uint64_t MaxLines = std::uint64_t(2049) * 96 * 96;
  // Lines per side for any scene when the budget allows (with 2049 directions): on the five
  // scenes of `mesolight bench vlf-accuracy` 2049 x 64 x 64 cut the error of 513 x 32 x 32 by
  // 30-60% where the small features alone asked for no more. Below it only for memory, to
  // MinRaysPerSide.
  int PreferredRaysPerSide = 64;
  int MinRaysPerSide = 32;
  int MaxRaysPerSide = 256;
  double LinesPerFeature = 2.0; // lines across the small-feature width, per direction
  // Texels half the cell side when the features ask for this many times the lines chosen (with
  // at least 2049 directions); 0 never. With the final gather (FinalGather.h, the default) a
  // texel no longer depends on the lines crossing it, so any ask beyond the lines taken gets
  // them (1): the corridor, 136 asked for 96 taken, went from 5.7% / 19.5% to 4.2% / 12.2% mean /
  // p95 per pixel gathered (`bench vlf-accuracy --scenes corridor --settings 2049x96t0.5`).
  // Without the gather (GatherlessFineTexelRatio) half texels made the corridor worse (7.0% ->
  // 7.9%), so there only at twice.
  double FineTexelRatio = 1.0;
  // Texels a quarter of the cell side where the features ask for twice FineTexelRatio times the
  // lines (2; 1 without the gather): the boxes (256 asked for 96) went from 12.1% / 39.3% at half
  // texels to 7.4% / 22.1% gathered (`--settings 2049x96t0.25`), the gather then 1.7 times the
  // propagation's time there.
  int MaxTexelHalvings = 2;
  // With the final gather and at least 2049 directions, texels halved this many more times on
  // surfaces other surfaces stand on (LightFieldSettings::ContactTexelHalvings) while the
  // estimate fits the budget share; 0 never. The boxes' floor beside the boxes was the one place
  // the gathered field stayed far off (23.6% per pixel, bias +17%: contact shadows narrower
  // than the 3.8 cm texels); measured in docs/vlf.md ("Finer texels where surfaces meet").
  int ContactTexelHalvings = 1;
};

constexpr double GatherlessFineTexelRatio = 2.0;

struct AutomaticChoice
{
  LightFieldSettings Settings;
  float SceneDiameter = 0.0f;   // world units: the bounding box's diagonal
  float FeatureWidth = 0.0f;    // world units: area-weighted 10th percentile of triangle widths
  int WantedRaysPerSide = 0;    // what the features ask for, before the caps
  std::string Limit;            // "features", "line cap", "memory budget" or "minimum"
  std::string Describe() const; // "2049 directions x 64 x 64 lines (features 0.1 m ask 296; ...)"
};

// Area-weighted 10th percentile of the triangles' smallest altitudes (2 area / longest edge),
// in the scene's units; 0 for a scene without triangles of nonzero area.
float SmallFeatureWidth(const TriangleScene& scene);

// The settings for `scene` (world units) within `limits` (see above). TilesPerSide is
// RaysPerSide / 8, TexelSize 0 (the cell side) or half the cell side (FineTexelRatio),
// ContactTexelHalvings limits.ContactTexelHalvings where it fits, MemoryBudget
// limits.MemoryBudget. Throws
// std::invalid_argument for a scene without triangles.
AutomaticChoice ChooseAutomaticSettings(
  const TriangleScene& scene, const AutomaticLimits& limits = {});

// The directions the automatic choice pairs with N lines per side.
std::size_t AutomaticDirections(int raysPerSide);

// Fills in what `requested` leaves automatic: RaysPerSide 0 is chosen from the scene
// (ChooseAutomaticSettings within its MemoryBudget), Directions 0 follows the lines
// (AutomaticDirections), TilesPerSide 0 is RaysPerSide / 8, TexelSize 0 with automatic lines is
// the choice's (and its ContactTexelHalvings, when those are 0); given values are kept. Returns
// the choice (Describe() for a log line; Limit "given" when nothing was automatic).
// finalGather false: the field's textures are used as propagated (FineTexelRatio
// GatherlessFineTexelRatio, no contact halvings: a propagated texel finer than the lines is a
// lottery of the few lines crossing it). contactTexelHalvings 0 to MaxContactTexelHalvings is
// kept whatever the rest (`vlf propagate --contact-texels H`,
// vtkVirtualLightField::ContactTexelHalvings); AutomaticContactTexelHalvings leaves it to the
// rules above (`--contact-texels auto`, the property's -1); other values reach the settings,
// whose Validate refuses them.
constexpr int AutomaticContactTexelHalvings = -1;
AutomaticChoice ResolveAutomaticSettings(const TriangleScene& scene,
  const LightFieldSettings& requested, bool finalGather = true,
  int contactTexelHalvings = AutomaticContactTexelHalvings);

} // namespace vlf
} // namespace mesolight

#endif
