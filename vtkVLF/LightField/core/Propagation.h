// SPDX-License-Identifier: BSD-3-Clause
// Propagation: iterative shooting of diffuse and perfect-specular radiance along the parallel
// subfields of a LightField (Wither 2005 §2.4.1.2), progressive-radiosity style.
//
// One iteration, for every subfield k and every line: each crossing whose front faces along the
// line sends its unshot radiance (the unshot diffuse texture sampled bilinearly at the crossing,
// plus the line's unshot specular radiance) to the next crossing in that direction, and adds it
// to its radiance map (the radiance sent along the line so far). A line is a beam of cross
// section h^2 (cell area) and solid angle w_k (the direction's solid angle, §3.6.2), so it
// carries the flux  Phi = L h^2 w_k.  At the receiving crossing:
//   - Kd Phi is splatted (bilinear weights) into the receiver's texels as reflected diffuse flux;
//   - Ks times the radiance goes to the nearest direction k' of the mirrored direction, into the
//     lines of subfield k' around the crossing (bilinear over the cells that cross the same
//     surface), scaled by w_k / w_k' so the flux is kept;
//   - the rest, (1 - Kd - Ks) Phi, is absorbed; flux whose line leaves the scene escapes.
// A crossing whose line runs into a solid (the next crossing is a back side, or a coincident
// face: LightField::Receiver) sends nothing and is no part of the texel's capacity: the part of
// a floor under a box is not seen, and its lines would otherwise dilute the visible part's
// radiance and lose the flux shot into the box.
// After all subfields each texel turns its reflected flux into unshot diffuse radiance by
// dividing by its shooting capacity C_t = sum over the lines leaving the texel into the scene of
// (bilinear weight) h^2 w_k, the flux a unit radiance there sends in the next iteration. C_t is
// the discrete counterpart of pi * (texel area) -- Wither's "total projected unit cell area"
// normalisation (§3.6.3): the cell's projected area on the surface is the cosine term, the
// solid angle weights the directions (§3.6.2). With it the flux sent next iteration equals the
// reflected flux exactly, so every iteration conserves energy (IterationEnergy records it).
// The continuous normalisation pi * texel area (DiffuseNormalization::ContinuousArea) is only
// there for the negative tests: it ignores how the lines actually sample each texel.
#ifndef mesolight_vlf_Propagation_h
#define mesolight_vlf_Propagation_h

#include "Distribution.h"
#include "LightField.h"

#include <functional>

namespace mesolight
{
namespace vlf
{

enum class DiffuseNormalization
{
  DiscreteCapacity, // flux / C_t (default, energy conserving)
  ContinuousArea    // flux / (pi * texel area): negative tests only
};

struct PropagationOptions
{
  DiffuseNormalization Normalization = DiffuseNormalization::DiscreteCapacity;
  // Progress in [0, 1] over the whole call; false aborts (AbortedError).
  ProgressCallback Progress;
  // Distributed field (Distribution.h): shoots only the subfields this rank owns, hands the
  // mirrored radiance meant for other ranks' directions to their owners, then sums the
  // reflected flux over the ranks once per iteration. nullptr = one process.
  Reducer* Reduce = nullptr;
};

// One shooting iteration. Appends its energy record to field.EnergyLog and returns it.
// Throws AbortedError when aborted (the field is then inconsistent: reload the last snapshot).
LightField::IterationEnergy PropagateIteration(
  LightField& field, const PropagationOptions& options = {});

// Iterates until field.IterationsDone == iterations (nothing when already there), calling
// afterIteration (e.g. writing a snapshot) after each.
void Propagate(LightField& field, int iterations, const PropagationOptions& options = {},
  const std::function<void(const LightField&)>& afterIteration = {});

// Total flux of the unshot radiance (diffuse and specular): what the next iteration sends.
std::array<double, 3> UnshotFlux(const LightField& field);

// The unshot flux over the emitted flux (what the first iteration shoots), channels summed: the
// share of the light not yet propagated (before the reflections it will still make).
double UnshotFraction(const LightField& field);

// The default stop rule: iterate until at most 1% of the emitted flux is left unshot (a fixed
// count of 4 left 9% on the Cornell box and 27% in rooms lit indirectly), at most 100 iterations.
constexpr double DefaultTolerance = 0.01;
constexpr int DefaultMaxIterations = 100;

// Iterates until UnshotFraction(field) <= tolerance (tolerance > 0), at most maxIterations in
// total (a cap: mirrors facing each other keep light long), calling afterIteration after each.
// Progress after each iteration is how far the unshot fraction has come toward the tolerance
// on a log scale (or the share of the cap, if larger). Returns whether the tolerance was
// reached. Throws std::invalid_argument for tolerance <= 0.
bool PropagateToTolerance(LightField& field, double tolerance, int maxIterations,
  const PropagationOptions& options = {},
  const std::function<void(const LightField&)>& afterIteration = {});

} // namespace vlf
} // namespace mesolight

#endif
