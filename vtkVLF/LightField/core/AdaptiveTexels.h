// SPDX-License-Identifier: BSD-3-Clause
// AdaptiveTexels: texel density from the field's own light (LightFieldSettings::
// SurfaceTexelLevels): finer texels on the surfaces whose light varies between texels, coarser
// ones where it is flat, chosen from a cheap first pass.
//
// The textures are read bilinearly between texel centres, so what a texel size costs is the
// interpolation error between them. Per surface the first pass measures it directly: at every
// texel with both neighbours along a texture axis on the surface, the interpolation defect
//   |L_a - (L_{a-1} + L_{a+1}) / 2| / mean L of the surface    (channels summed)
// -- the error the texel would show if the texels were twice as large and the value at a were
// read between a-1 and a+1 -- averaged over the surface. A linear gradient has none (bilinear
// reads hold it at any size); a shadow edge or a contact shadow has a large one. This is the
// a-posteriori refinement of adaptive radiosity meshing (Cohen, Greenberg, Immel and Brock,
// "An Efficient Radiosity Approach for Realistic Image Synthesis", 1986: subdivide the patches
// whose radiosity differs from their neighbours'), per surface since every surface has its own
// texel frame.
//
// The first pass is the field at its base texels (no contact halvings) with at most 129
// directions (FirstPassDirections), propagated to the tolerance and gathered twice in one pass with
// an eighth of the final gather's indirect rays each (other random numbers): the mean of the two is
// measured, and the mean defect their difference alone produces (the gather's noise, which would
// otherwise read as variation: |g1 - g2| / 2 is the noise of the mean's texel, and its defect
// averages about that) is subtracted. The border rows count too: a texel whose neighbour along an
// axis is off the surface is read clamped over the half texel beyond its centre, so there the
// defect is half the step to its inner neighbour, |L_a - L_{a-1}| / 2 (a wall's light falls off
// fastest within a texel of a corner). Then per surface:
//   defect > RefineTwice          -> texels a quarter
//   defect > Refine               -> texels a half
//   defect < Coarsen (off by default), the first pass's noise below CoarsenMaxNoise, no contact
//   surface, and the texture at least 2 MinCoarseSide texels on its shorter side
//                                 -> texels doubled
// and on top of the contact halvings (LightFieldSettings::ContactTexelHalvings): a contact
// surface keeps at least its halvings, since a contact shadow narrower than a base texel does
// not show in the first pass. The refinements beyond the contact texels are then taken within a
// budget of gathered texels (GatherBudget: the final gather's rays grow with them), best gain
// per texel first (LimitRefinement). The field is then built again with those levels.
//
// Measured per pixel against the path tracer (docs/vlf.md, "Texels from the light"): the first
// rule (interior rows only, instead of the contact halvings, coarsening below 0.4%) gained on
// the boxes but lost 0.1-1.0 points of mean error on the other four scenes (coarsened walls
// lost their borders, the contact shadows were missed). Refining only, on top of the contact
// halvings, every surface has at least the default's texels. Within the gather budget the
// boxes keep 2.8% -> 2.6% of their 2.8% -> 2.1% for 1.6 instead of 3.6 times the time (their
// gain is the floor's quartering), and the other four scenes gain nothing measurable for the
// first pass: asked for (vlf propagate --adaptive-texels), not the default.
#ifndef mesolight_vlf_AdaptiveTexels_h
#define mesolight_vlf_AdaptiveTexels_h

#include "LightField.h"

#include <cstdint>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{

struct AdaptiveTexelOptions
{
  // Mean relative interpolation defect (above) beyond which a surface's texels are halved, and
  // beyond which they are quartered.
  double Refine = 0.02;
  double RefineTwice = 0.08;
  // Below it the surface's texels are doubled; negative: never (the default: coarsening saved
  // little memory, the maps hold most of it, and cost accuracy at the borders).
  double Coarsen = -1.0;
  // A surface whose first-pass noise share (SurfaceVariation::Noise) exceeds this is never
  // coarsened: what is left of its defect after subtracting the noise is not resolved.
  double CoarsenMaxNoise = 0.02;
  // The contact surfaces keep at least their LightFieldSettings::ContactTexelHalvings (false:
  // the levels replace them, the first rule).
  bool OnContactTexels = true;
  // The border rows count in the defect (above; false: interior texels only, the first rule).
  bool BorderRows = true;
  // A surface is coarsened only when its texture keeps at least this many texels on its shorter
  // side.
  int MinCoarseSide = 8;
  // The refinements beyond the contact texels may add at most this fraction of the contact
  // texels' gathered texels (plus what coarsening saves); negative: unbounded. Unbounded, the
  // boxes of docs/vlf.md gathered 3.3 times the texels (3.8 times the time) for their gain.
  double GatherBudget = 0.5;
  // The first pass's directions (at most the field's). 129 directions and 128 rays chose as well
  // as 513 and 256 on the five scenes of docs/vlf.md (the same per-pixel error) at about half
  // the first pass's work: the gather computes the shadows exactly and reads the field only at
  // its indirect rays' hits.
  std::size_t FirstPassDirections = 129;
  // The first pass's gather: indirect rays and emitter samples of each of its two gathers.
  int FirstPassIndirectRays = 128;
  int FirstPassDirectSamples = 16;
  // Progress in [0, 1]; false aborts (AbortedError).
  ProgressCallback Progress;
};

struct SurfaceVariation
{
  double Mean = 0.0;       // mean radiance over the surface's texels (channels summed)
  double Defect = 0.0;     // mean relative interpolation defect, the noise's share subtracted
  double Noise = 0.0;      // the share subtracted
  std::size_t Samples = 0; // texels measured (0: too small to tell, or an emitter)
};

// The options of the first rule (measured in docs/vlf.md; for comparisons and the negative
// tests): interior rows only, coarsening below 0.4%, the levels instead of the contact halvings.
AdaptiveTexelOptions FirstRuleAdaptiveTexelOptions();

// The variation of every surface of the field's textures: totals and second are two estimates of
// the same textures with independent noise (second may be empty: no noise subtracted).
// borderRows: the border texels' clamp defect counts too (above).
std::vector<SurfaceVariation> MeasureLightVariation(const LightField& field,
  const std::vector<glm::vec3>& totals, const std::vector<glm::vec3>& second = {},
  bool borderRows = true);

// Per surface of field the texel level (LightFieldSettings::SurfaceTexelLevels) relative to the
// field's base texels, from its variation (above). floor (empty, or one level per surface: the
// contact halvings as levels) caps every level: a surface is never coarser than its floor.
std::vector<std::int8_t> ChooseTexelLevels(const LightField& field,
  const std::vector<SurfaceVariation>& variation, const AdaptiveTexelOptions& options = {},
  const std::vector<std::int8_t>& floor = {});

// The levels within a budget of gathered texels. baseTexels: per surface the texels whose
// centre is on the surface at the base texels (level 0; a level L has about baseTexels x 4^-L);
// levels: the measured choice (ChooseTexelLevels); floor: as there (empty: 0). Every surface keeps
// at least min(floor, 0) and its level if that is coarser; the refinements beyond it are taken
// one level at a time, best first, while the texels they add stay within budget x the texels at
// min(floor, 0) everywhere plus the texels the coarsened surfaces save. Best: the largest gain per
// added texel. A surface's mean defect at level L is about Defect x 2^L (a shadow edge's smeared
// band narrows with the texel), over its area (baseTexels); one more level costs 3 x 4^-L x
// baseTexels: gain per texel ~ Defect x 8^L, so a halving on a surface of large defect comes
// before a quartering (the area cancels: a large floor pays for its gain with its texels).
// Negative budget: levels unchanged.
std::vector<std::int8_t> LimitRefinement(const std::vector<std::size_t>& baseTexels,
  const std::vector<SurfaceVariation>& variation, const std::vector<std::int8_t>& levels,
  const std::vector<std::int8_t>& floor, double budget);

struct AdaptiveTexelReport
{
  std::vector<SurfaceVariation> Variation;
  std::size_t Finer = 0, Coarser = 0; // surfaces finer / coarser than the base texels
  std::size_t Contact = 0;            // surfaces at their contact halvings (or finer)
  std::size_t BeyondContact = 0;      // surfaces finer than their contact halvings alone
  std::size_t BaseTexels = 0;         // the first pass's (uniform) texels
  std::size_t Texels = 0;             // with the chosen levels
  std::size_t Limited = 0;            // surfaces left coarser than measured by the GatherBudget
  double GatheredDefault = 0.0;       // texels on the surfaces at the contact texels (estimate)
  double Gathered = 0.0;              // and at the chosen levels
  double Seconds = 0.0;               // the first pass and the choice
  double FieldSeconds = 0.0;          // of which the first pass's build and propagation
  double GatherSeconds = 0.0;         // and its two gathers
  std::uint64_t FirstPassBytes = 0;   // the first pass's field (AllocatedBytes)
  std::string Describe() const; // "texels finer on 3, coarser on 12 of 40 surfaces: 1.2e5 -> ..."
};

// The settings with SurfaceTexelLevels chosen from a first pass (above) over the scene: the
// texel size of settings without contact halvings is the base; with options.OnContactTexels the
// settings' ContactTexelHalvings are the floor of the contact surfaces' levels. Throws what
// LightField::Build, the propagation and the gather throw.
LightFieldSettings ChooseAdaptiveTexels(const TriangleScene& scene,
  const LightFieldSettings& settings, const AdaptiveTexelOptions& options = {},
  AdaptiveTexelReport* report = nullptr);

} // namespace vlf
} // namespace mesolight

#endif
