// SPDX-License-Identifier: BSD-3-Clause
// FinalGather: the total diffuse textures recomputed per texel from exact rays after the
// propagation (Reichert 1992, "A Two-Pass Radiosity Method Driven by Lights and Viewer
// Position", Cornell MSc thesis; Christensen 1999, "Faster Photon Map Global Illumination": the
// final gather).
//
// A propagated texel holds what the few parallel lines crossing it brought: small faces draw a
// lottery of lines, and visibility (a contact shadow, the corner beside a rib) is resolved only
// at the line spacing. The gather replaces each texel's value by
//   Ke + Kd (E_direct / pi + mean L_indirect)
// with, from jittered points stratified over a footprint around the texel centre (only points on
// the surface's triangles):
// - E_direct: next-event estimation, emitter triangles sampled by area x luminance of Ke, each
//   sample an exact shadow ray (Embree);
// - L_indirect: cosine-distributed rays (stratified over the hemisphere) cast with Embree; at
//   the hit the field's converged radiance leaving toward the texel, less the hit surface's own
//   emission (the direct term has it): its total diffuse texture, or RadianceLeaving on a mirror.
// Visibility then resolves per ray, not per line; the field's own error enters only through the
// second bounce, averaged over many rays.
//
// By default the gather runs twice (FinalGatherOptions::Prepass): the second pass reads the
// first pass's totals at its rays' hits, so the second bounce is gathered too.
//
// A ray that meets a back face first starts inside a solid (the floor under a box) or sees the
// unlit side of a one-sided surface: it is left out of the texel's mean, as the propagation
// leaves such lines out of a texel's capacity (LightField::Receiver). Texels none of whose
// points lie on a triangle in the open (beyond a polygon's edge, under a box) take a value from
// their gathered neighbours: the mean of the linear extrapolations 2 g1 - g2 along the lines of
// two gathered texels through them (at least g1 / 2), else (and in later rings) the mean of their
// gathered 8-neighbours, so bilinear reads along an edge follow the gathered values' slope
// toward a contact instead of flattening it.
//
// The propagated totals are kept in LightField::PropagatedDiffuse: the sent radiance of the
// lines (SentRadiance: total less unshot) then follows the gathered value, and a resumed
// propagation (Propagation.h) restores the propagated totals first.
//
// Distributed over MPI ranks (Distribution.h). The gather reads only what every rank holds
// alike after a distributed propagation: the scene and the total diffuse textures (mirrors are
// followed by exact reflection, never through the directional maps a rank holds a share of). So
// the texels are split, not the directions: each rank gathers every ranks-th block of
// GatherBlockTexels texels with triangles (texels cost alike -- the same ray counts -- and
// interleaved blocks spread the costlier regions, such as texels facing a mirror, over every
// rank), and one sum over the ranks (16 bytes a texel with triangles: the value and whether it
// was gathered, zeros from the other ranks) gives every rank every gathered value; each rank
// then fills the texels in the shade of triangles alike. A texel's random numbers follow from its
// index (SampleSeed), and a float plus zeros is that float: the textures are the serial gather's
// bit for bit, on any number of ranks.
#ifndef mesolight_vlf_FinalGather_h
#define mesolight_vlf_FinalGather_h

#include "LightField.h" // and class Reducer (Distribution.h)

#include <cstdint>

namespace mesolight
{
namespace vlf
{

struct FinalGatherOptions
{
  // Cosine-distributed rays per texel for the indirect light.
  int IndirectRays = 1024;
  // Emitter samples (shadow rays) per texel for the direct light.
  int DirectSamples = 64;
  // Gather twice: a first pass with a quarter of the rays and emitter samples, whose totals the
  // second pass's indirect rays then read at their hits instead of the propagated ones. The
  // second bounce is then the gathered one, not the lines' (which are too bright beside small
  // boxes: their contact shadows are finer than the lines); the first pass's noise averages
  // out over the second pass's rays. Off: one pass reading the propagated totals.
  bool Prepass = true;
  // Side of the square around the texel centre the points are spread over, in texels: the
  // textures are read bilinearly between texel centres, so a texel should hold the value at its
  // centre, not the mean over its area (which blurs a contact shadow by a texel); a little
  // spread still averages what varies within the texel.
  float Footprint = 0.5f;
  // Which random numbers (the same value gives the same textures on any thread split).
  std::uint64_t Sequence = 1;
  // Progress in [0, 1]; false aborts (AbortedError, the textures unchanged).
  ProgressCallback Progress;
  // Distributed field: this rank gathers its share of the texels and the shares are summed over
  // the ranks (see above); failures are agreed (Agree). Collective. nullptr = one process.
  Reducer* Reduce = nullptr;
};

// Texels with triangles per block of the split between ranks (every rank gathers every
// ranks-th block).
constexpr std::size_t GatherBlockTexels = 64;

struct FinalGatherReport
{
  std::size_t Texels = 0; // texels gathered (with a point on a triangle in the open)
  std::size_t Filled = 0; // texels filled from gathered neighbours
  std::uint64_t Rays = 0; // rays cast (indirect and shadow), by every rank
  double Seconds = 0.0;
  // This rank's share (all of them in one process): texels with triangles it gathered (in each
  // pass), the rays it cast and the seconds it spent gathering them (before the combinations),
  // over both passes.
  std::size_t OwnTexels = 0;
  std::uint64_t OwnRays = 0;
  double OwnSeconds = 0.0;
  std::uint64_t CombinedBytes = 0; // this rank's contribution to the combining sum (0: one rank)
};

// Gathers every texel of every surface (see above) and replaces field.TotalDiffuse with the
// result, the propagated totals moved to field.PropagatedDiffuse (a second gather starts from
// those again). Throws std::invalid_argument for non-positive ray counts, AbortedError when the
// progress callback returns false (the field unchanged). With options.Reduce of several ranks:
// collective, every rank ends with the same textures; a failure on one rank throws
// DistributedError on the others (the field unchanged on every rank).
FinalGatherReport FinalGather(LightField& field, const FinalGatherOptions& options = {});

// Undoes FinalGather: the propagated totals back into TotalDiffuse (nothing when not gathered).
void RestorePropagatedDiffuse(LightField& field);

} // namespace vlf
} // namespace mesolight

#endif
