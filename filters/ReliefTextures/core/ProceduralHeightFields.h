// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ProceduralHeightFields.h
 * @brief Deterministic procedural depth maps + albedo (plain C++17, no VTK types).
 *
 * Every pattern is a pure function of the texture coordinates (u, v) in [0,1]^2, the
 * parameters and the thesis, so an image of any resolution is just that function sampled at
 * the texel centres u = (i + 0.5) / w, v = (j + 0.5) / h (row j = 0 is the bottom row, VTK
 * order). Shapes therefore do not depend on the resolution. Noise comes from an integer hash
 * (no std::rand, no global state), so results are identical on every platform and run.
 *
 * Depth follows the Mesolight convention: 0 = top surface, 1 = deepest.
 */
#ifndef mesolight_ProceduralHeightFields_h
#define mesolight_ProceduralHeightFields_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

#include <cstdint>

namespace mesolight
{

enum class ReliefPattern
{
  Bricks = 0,      ///< running-bond brick wall, deep mortar joints
  Stone,           ///< rough stone: fractal (fBm) value noise with cracks
  HemisphereTorus, ///< thesis test pattern (fig. 45): hemisphere + torus on a flat base
  Flat,            ///< constant depth (tests)
  SineWave         ///< d = 0.5 + 0.5 sin(2 pi fx u) cos(2 pi fy v) (analytic tests)
};

/// Depth of the flat base of the HemisphereTorus pattern; the bumps rise from it to depth 0.
constexpr float HemisphereTorusBaseDepth = 0.9f;

struct HeightFieldParameters
{
  ReliefPattern Pattern = ReliefPattern::HemisphereTorus;
  std::uint32_t Seed = 0;
  // Bricks
  int BrickRows = 8;         ///< bricks along v
  int BrickColumns = 4;      ///< bricks along u
  float MortarWidth = 0.15f; ///< joint width as a fraction of the brick height
  // Stone
  int StoneOctaves = 6;
  // Flat
  float FlatDepth = 0.5f;
  // SineWave (integer frequencies keep the pattern periodic on the unit square)
  int SineFrequency[2] = { 1, 1 };
};

/**
 * Evaluate the pattern at (u, v). Returns the depth in [0,1]; if albedo is not null it
 * receives the RGB8 colour.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT float SampleHeightField(
  const HeightFieldParameters& params, float u, float v, std::uint8_t* albedo);

/**
 * Fill rows [rowBegin, rowEnd) of a w x h depth map (w*h floats, may be null) and of its
 * albedo (3*w*h bytes RGB, may be null), sampling at texel centres. The pointers address
 * the whole images.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT void GenerateHeightFieldRows(const HeightFieldParameters& params,
  int w, int h, int rowBegin, int rowEnd, float* depth, std::uint8_t* albedo);

/// Whole-image version of GenerateHeightFieldRows().
MESOLIGHTRELIEFTEXTURES_EXPORT void GenerateHeightField(
  const HeightFieldParameters& params, int w, int h, float* depth, std::uint8_t* albedo);

/// Integer hash noise helpers (exposed for tests and other procedural code).
MESOLIGHTRELIEFTEXTURES_EXPORT std::uint32_t HashInt(std::uint32_t x);
/// Smooth, tileable value noise in [0,1]: lattice of `period` x `period` cells over the
/// unit square, evaluated at (u, v) in [0,1]^2.
MESOLIGHTRELIEFTEXTURES_EXPORT float ValueNoise(float u, float v, int period, std::uint32_t seed);
/// Fractal Brownian motion of ValueNoise(): octaves of doubling frequency and halving
/// amplitude starting at baseFrequency cells per unit; normalised to [0,1].
MESOLIGHTRELIEFTEXTURES_EXPORT float FractalNoise(
  float u, float v, int baseFrequency, int octaves, std::uint32_t seed);

} // namespace mesolight

#endif
