// SPDX-License-Identifier: BSD-3-Clause
// TextureComparison: the light field's total diffuse textures texel by texel against a reference
// (the path tracer's DiffuseRadianceLeaving at each texel centre), and an edge-preserving filter
// of those textures.
//
// Per-patch means (PatchComparison) hide mottling: blotches of +-10% average out over a wall. Here
// every texel centre that lies on one of its surface's triangles is compared: the relative error
// of the texel (channels summed) and the error of its local contrast -- the texel's difference
// from the mean of its 4 neighbours, relative to that mean -- which is what the eye sees as
// blotches on a flat wall.
//
// The filter is a bilateral filter (Tomasi and Manduchi 1998) of each surface's texture on its own
// texel grid (never across surfaces): a (2r+1)^2 window whose weights are 1 where the neighbour's
// value is within a relative range of the centre's (Gaussian in the relative difference), so
// the low-contrast noise of the finite line count is averaged while a shadow edge (a large
// relative step) is kept. RangeSigma 0 gives a plain box blur (the negative test's case).
#ifndef mesolight_vlf_TextureComparison_h
#define mesolight_vlf_TextureComparison_h

#include "LightField.h"
#include "PatchComparison.h"

#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{

struct TexelPoint
{
  std::uint32_t Surface = 0;
  int A = 0, B = 0;           // texel column, row
  std::size_t Texel = 0;      // global index (Surface::TexelOffset + B * width + A)
  std::uint32_t Triangle = 0; // the scene triangle holding the centre
  glm::vec3 Unit{ 0.0f };     // the centre in the field's unit-sphere coordinates
};

// The texel centres of non-emitting surfaces that lie on one of the surface's triangles.
std::vector<TexelPoint> SurfaceTexels(const LightField& field);

// The reference at every texel centre (world coordinates), in parallel (mesolight::ParallelFor;
// the reference must be safe to call concurrently).
std::vector<glm::vec3> ReferenceAtTexels(const LightField& field,
  const std::vector<TexelPoint>& texels, const ReferenceRadiance& reference);

// The field's total diffuse value at every texel.
std::vector<glm::vec3> FieldAtTexels(
  const LightField& field, const std::vector<TexelPoint>& texels);

struct TexelError
{
  std::size_t Texels = 0;
  double Mean = 0.0;         // mean over texels of |sum(v) - sum(r)| / sum(r)
  double P95 = 0.0;          // 95th percentile of the same
  double ContrastMean = 0.0; // mean of |c(v) - c(r)|, c = (x - mean of 4 neighbours) / ref mean
  double ContrastP95 = 0.0;
  std::string Describe() const; // "mean 1.2%, p95 3.4%, contrast mean 0.8%, p95 2.1%"
};

// values and reference: one per texel of `texels` (same order). Texels whose reference is
// below 5% of their surface's mean (hidden, e.g. floor under a block) are skipped; neighbours are
// those of the same surface that are in `texels`. Throws std::invalid_argument when the sizes
// differ.
TexelError CompareTexels(const LightField& field, const std::vector<TexelPoint>& texels,
  const std::vector<glm::vec3>& values, const std::vector<glm::vec3>& reference);

struct TextureFilterSettings
{
  int Radius = 2;           // window (2r+1)^2 texels; 0 = no filtering
  float RangeSigma = 0.25f; // relative difference with weight exp(-1/2); 0 = box blur
};

// Filters field.TotalDiffuse in place, surface by surface (see above).
void FilterTotalDiffuse(LightField& field, const TextureFilterSettings& settings);

} // namespace vlf
} // namespace mesolight

#endif
