// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file DepthHallucination.h
 * @brief Depth hallucination (plain C++17, no VTK types): a diffuse-lit and a flash-lit
 *        photograph of a surface -> albedo and a plausible depth map.
 *
 * After Glencross, Ward, Melendez, Jay, Liu, Hubbard, "A perceptually validated model for
 * surface depth hallucination" (SIGGRAPH 2008), used as the depth source of Méndez Fernández's
 * thesis (ch. 3). What is implemented, step by step:
 *
 *  1. Albedo. The flash photograph is taken under the same overcast light plus a flash at the
 *     camera, so I_f - I_d is the flash alone; a flash at the camera sees no shadows and lights
 *     every point about equally, so it is albedo times the flash's fall-off, which a photograph
 *     of a white card under the flash (I_c) measures: albedo = (I_f - I_d) / I_c, per channel.
 *     Without a card I_c = 1 (a uniform flash; the albedo is then known up to a scale).
 *  2. Shading. S = lum(I_d) / lum(albedo): the overcast irradiance, normalised so that its
 *     99.5th percentile (the most open, upward-facing points) is 1.
 *  3. Depth from shading, scale by scale. Layers L_0 = S, L_k = Gaussian(S, sigma_k) with
 *     sigma_k = BaseSigma * 2^(k-1), k = 1..Layers. In layer k the ratio r = L_{k-1} / L_k
 *     compares a point with its surround at that scale:
 *       - r < 1 (darker than its surround): a valley ("dark is deep" under diffuse light:
 *         Langer & Zucker, "Shape-from-shading on a cloudy day"). A point at the bottom
 *         of a pit whose opening subtends the half-angle a sees the sky fraction sin^2 a
 *         (the visible aperture), so a = asin(sqrt(r)) and a pit of radius sigma_k is
 *         sigma_k * cot(a) = sigma_k * sqrt((1 - r) / r) deep.
 *       - r > 1 (brighter than its surround): a hill. Its surround is darker because it faces
 *         away from the zenith: a plane tilted by t sees (1 + cos t) / 2 of the sky, so
 *         cos t = 2 / r - 1 and the hill rises sigma_k * tan(t) over the distance sigma_k.
 *     Then a residual layer: the widest layer L_K against the open sky (shading 1) by the
 *     valley law, with sigma ResidualWeight * sigma_K: the broad darkening the band-pass layers
 *     leave out (the floor of a wide recessed panel is as bright as its surround in every layer).
 *     depth = DepthScale * (sum_k (ValleyWeight * valley_k - HillWeight * hill_k)
 *     + ValleyWeight * residual), in texels. The widest layer must match the features, and
 *     the best layer count differs from surface to surface (1 to 8 on real height maps); by
 *     default the depths of every count K = 1, 2, ... the photograph holds are averaged
 *     (a scale average: Lindeberg's scale space without a selection of one scale), each
 *     weighted by c_K^2 / its spread, c_K the correlation of its depth with the darkness of
 *     the image the layers read, which keeps it in texels (HallucinationModel::Shading: by
 *     1 / its spread, an equal say per count); when a count wider than the finest agrees
 *     best, the image's darkness itself joins with an equal say (deep perforations and pits,
 *     where the ratio is as good a depth as the layers make of it);
 *  4. What the layers read (HallucinationModel): by default not the shading S but the
 *     diffuse/flash ratio lum(I_d) / (lum(I_d) + lum(albedo)) = S / (S + 1) in units of the
 *     flash, the scale-free "dark is deep" cue of a flash pair, which compresses the bright
 *     open surfaces where the flash-pair albedo is least sure;
 *  5. Which counts (the default, Layers -2): the ratio image's own feature size, its
 *     autocorrelation length L (MeasureHallucinationFeatureScale). Fine features (L under 3
 *     texels) take the scale average; broad ones (the ratio smooth at the texel scale: wide
 *     tiles, stones, panels), whose depth the agreement weights would drop with the wide counts,
 *     take one count, the widest sigma about 32 L;
 *     the output is that depth stretched to [0, 1] (0 = highest point, 1 = deepest, the
 *     project's convention) and its range in texels (DepthRangeTexels).
 *
 * Where this departs from the paper: it follows the paper's structure (albedo from the flash
 * pair, shading, scale layers treated as hills or valleys, summed, a user depth scale), written
 * from its description, not from its code; the paper's own layer weights and filters are not
 * reproduced. Here the layers are Gaussian (wider than 16 texels: blurred on a reduced copy,
 * GaussianBlurPyramid, so that a layer costs about the same at every sigma), every layer has
 * weight 1 (the sigma_k factor is what
 * makes coarse layers count more), and the hill and valley laws are the two closed forms above.
 * The flash-pair albedo also carries what the flash measures besides albedo: the cosine of the
 * surface to the flash and light bounced between walls; dividing by it brightens slopes, which
 * the hill law reads (with the true albedo instead the model does worse: docs/hallucination.md).
 * It is an approximation by design: shading cannot tell absolute depth nor very low
 * frequencies, the widest useful layer must match the features (Layers; the scale average, the
 * feature size, the automatic choice and the residual layer are this project's), and where the
 * albedo is not removed dark paint reads as deep. docs/hallucination.md measures how far it gets.
 */
#ifndef mesolight_DepthHallucination_h
#define mesolight_DepthHallucination_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

#include "Luminance.h"
#include "Progress.h"
#include "RgbImage.h"

#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{

/// Which image the scale layers read, and how the scale average weighs its layer counts.
enum class HallucinationModel
{
  /// The default: the layers read the diffuse/flash ratio lum(I_d) / (lum(I_d) + lum(albedo))
  /// (I_d / I_f with the flash's fall-off divided out), and the scale average weighs each
  /// layer count by its squared correlation with that ratio image (dark is deep).
  Ratio,
  /// The previous model: the layers read the shading lum(I_d) / lum(albedo), and the scale
  /// average gives every layer count an equal say (weights 1 / spread).
  Shading
};

struct HallucinationSettings
{
  HallucinationModel Model = HallucinationModel::Ratio;
  /// Scale layers (1..12); -2 (the default, HallucinationFeatureLayers): from the feature size
  /// of the image the layers read (MeasureHallucinationFeatureScale): the scale average where
  /// its features are fine, one wide count where they are broad (under
  /// HallucinationModel::Shading: the scale average); 0: the scale average, the model with 1, 2,
  /// ..., K layers (K: every octave the photograph holds, HallucinationAverageLayers) averaged
  /// with weights inversely proportional to each one's spread; -1: one count chosen from the
  /// shading's octave energies (ChooseHallucinationLayers). The widest layer's sigma is
  /// BaseSigma * 2^(Layers - 1).
  int Layers = -2;
  float BaseSigma = 1.0f;    ///< sigma of the first layer, texels; doubles per layer
  float DepthScale = 1.0f;   ///< the user's depth scale: multiplies the model's depth
  float ValleyWeight = 1.0f; ///< weight of the aperture (valley) law
  float HillWeight = 1.0f;   ///< weight of the orientation (hill) law
  /// The residual layer's sigma in units of the widest layer's (0: no residual layer): the
  /// widest layer compared with the open sky by the valley law.
  float ResidualWeight = 8.0f;
  /// A pixel whose flash luminance is below its diffuse luminance by more than this fraction
  /// of the mean flash-only luminance counts as "flash darker" (photographs are noisy).
  float DarkerTolerance = 0.05f;
  /// More than this fraction of "flash darker" pixels is an error (images swapped, flash off).
  float MaximumDarkerFraction = 0.1f;
  int Threads = 0; ///< 1: the calling thread only; otherwise ParallelFor's threads
};

/// Why HallucinateDepth refused its input (HallucinationError::GetReason).
enum class HallucinationStatus
{
  EmptyImage,
  SizeMismatch,
  NonFinite,
  FlashDarker,
  BadSettings,
  TooSmall,      ///< fewer than MinimumSide pixels across: no surround to compare with
  NegativeLight, ///< a photograph negative in many pixels (not linear light)
  DarkCard,      ///< a calibration card dark in part of the view (albedo would blow up)
  GreyAndColour  ///< one photograph grey (R = G = B), the other in colour: a wrong albedo
};

/// The smallest photograph side HallucinateDepth accepts: the first layer compares a pixel with
/// a surround of sigma 1 texel, which needs a few pixels on either side.
constexpr int HallucinationMinimumSide = 4;

/// Input HallucinateDepth refuses; what() is one sentence for the user.
class MESOLIGHTRELIEFTEXTURES_EXPORT HallucinationError : public std::runtime_error
{
public:
  HallucinationError(HallucinationStatus reason, const std::string& message)
    : std::runtime_error(message)
    , Reason(reason)
  {
  }
  HallucinationStatus GetReason() const { return this->Reason; }

private:
  HallucinationStatus Reason;
};

/// Thrown when the progress callback returned false: not an error, the caller stops.
class MESOLIGHTRELIEFTEXTURES_EXPORT HallucinationAbortedError : public std::runtime_error
{
public:
  HallucinationAbortedError()
    : std::runtime_error("Aborted.")
  {
  }
};

struct HallucinationResult
{
  RgbImage Albedo;            ///< (I_f - I_d) / I_c, linear, per channel
  std::vector<float> Shading; ///< S, normalised (1 = open, upward-facing)
  /// lum(I_d) / (lum(I_d) + lum(albedo)), 1 at its maximum: what the layers read under
  /// HallucinationModel::Ratio.
  std::vector<float> Ratio;
  std::vector<float> Depth;      ///< w x h, 0 = highest point, 1 = deepest
  float DepthRangeTexels = 0.0f; ///< the model's depth of Depth = 1, in texel widths
  /// The layers used (settings.Layers, the automatic choice, or the widest count averaged)
  int Layers = 0;
  float FeatureSizeTexels = 0.0f; ///< the automatic choice's feature size (0: layers given)
  /// Layers -2: the image's autocorrelation length, texels (MeasureHallucinationFeatureScale)
  float CorrelationLengthTexels = 0.0f;
  bool Averaged = false; ///< the depth is the scale average (Layers 0, or -2 on fine features)
};

/// The automatic scale: the layer count the shading's own feature size calls for.
struct HallucinationScale
{
  int Layers = 1;
  /// The widest octave holding a fair share of the shading's band energy: the widest layer's
  /// sigma, in texels (0 for a uniform shading).
  float FeatureSizeTexels = 0.0f;
};

/**
 * Chooses the layer count from the shading alone (no true depth): the shading's band energy per
 * octave (difference of Gaussians of sigma 2^(k-2) and 2^(k-1) base sigmas, away from the
 * border); the widest octave holding at least a fifth of the strongest one's energy is the
 * widest layer. Deterministic.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT HallucinationScale ChooseHallucinationLayers(
  const std::vector<float>& shading, int w, int h, float baseSigma = 1.0f, int threads = 0);

/// HallucinationSettings::Layers: the count from the feature size (the default).
constexpr int HallucinationFeatureLayers = -2;

/// The feature size of the image the layers read, and the layers it calls for.
struct HallucinationFeatureScale
{
  /// The autocorrelation length: the shift (texels, interpolated) at which the image's
  /// autocorrelation, averaged over horizontal and vertical shifts, falls to one half; 0 for a
  /// uniform image.
  float CorrelationLengthTexels = 0.0f;
  /// 0: fine features, the scale average (Layers 0); otherwise the one count whose widest sigma
  /// is HallucinationBroadSigmaPerLength times the correlation length (at most half the
  /// photograph's shorter side).
  int Layers = 0;
};

/// Correlation lengths from this many texels on are broad features (one wide count).
constexpr float HallucinationBroadCorrelationLength = 3.0f;
/// Broad features: the widest layer's sigma in correlation lengths.
constexpr float HallucinationBroadSigmaPerLength = 32.0f;

/**
 * The scales from the image's own feature size (no true depth): its autocorrelation length
 * (Taylor's integral scales of a random field, here the half-correlation shift). An image that
 * decorrelates within a few texels (fine relief, texture, noise) leaves the choice among the
 * counts to the scale average; one that stays correlated over HallucinationBroadCorrelationLength
 * texels or more (smooth at the texel scale: broad tiles, stones, panels) gets one count, the
 * widest sigma HallucinationBroadSigmaPerLength correlation lengths (the two constants
 * measured on the real height maps the default was chosen on: docs/hallucination.md).
 * Deterministic; shifts are searched no further than the broadest count needs.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT HallucinationFeatureScale MeasureHallucinationFeatureScale(
  const std::vector<float>& image, int w, int h, float baseSigma = 1.0f, int threads = 0);

/// The layer count of the scale average (Layers 0): every octave whose sigma leaves an interior
/// 2 sigma from the border of a w x h photograph, 1..12.
MESOLIGHTRELIEFTEXTURES_EXPORT int HallucinationAverageLayers(int w, int h, float baseSigma = 1.0f);

/**
 * The whole filter: albedo, shading and depth. `calibration` may be null (a uniform flash).
 * Throws HallucinationError (its reason and a message) for an empty image, images of different
 * sizes, photographs smaller than HallucinationMinimumSide, a NaN or infinite pixel, a
 * photograph negative in more than MaximumDarkerFraction of its pixels, a flash image darker
 * than the diffuse one, a card darker than 2% of its brightest in more than 1% of the view,
 * settings out of range (both weights 0 included: the depth would be flat);
 * HallucinationAbortedError when `progress` returns false.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT HallucinationResult HallucinateDepth(const RgbImage& diffuse,
  const RgbImage& flash, const RgbImage* calibration, const HallucinationSettings& settings = {},
  const ProgressCallback& progress = {});

/**
 * Step 3 alone: the model depth in texels (not normalised; larger = deeper) of a shading image
 * (w x h, 1 = open sky): HallucinateDepth passes HallucinationResult::Ratio under
 * HallucinationModel::Ratio, HallucinationResult::Shading under HallucinationModel::Shading.
 * With Layers 0 and HallucinationModel::Ratio each layer count's depth is weighted by its
 * squared correlation with the input image's darkness (-image) over its spread (a weighted mean
 * of the counts' depths, still in texels). Empty when progress aborts. Exposed for tests and the
 * benchmark.
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> DepthFromShading(
  const std::vector<float>& shading, int w, int h, const HallucinationSettings& settings = {},
  const ProgressCallback& progress = {});

/// Gaussian blur (separable, clamped border) of a w x h image; sigma <= 0 copies.
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> GaussianBlurClamped(
  const std::vector<float>& image, int w, int h, float sigma, int threads = 0);

/// How many times the layer of this sigma is reduced before blurring (1: blurred directly,
/// exactly; sigma above 16 texels: a power of two leaving a coarse sigma of 8..16 texels).
MESOLIGHTRELIEFTEXTURES_EXPORT int HallucinationBlurFactor(float sigma);

/// The blur DepthFromShading uses: GaussianBlurClamped for sigma up to 16 texels; wider, the
/// same blur on a copy reduced HallucinationBlurFactor(sigma) times and interpolated back
/// (within about 1% of the image's range of the exact blur; cost independent of sigma).
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<float> GaussianBlurPyramid(
  const std::vector<float>& image, int w, int h, float sigma, int threads = 0);

/// The model of DepthFromShading's cost: multiply-adds for a w x h shading and `layers` layers
/// (the tool turns it into an estimate of seconds before starting).
MESOLIGHTRELIEFTEXTURES_EXPORT double HallucinationWork(
  int w, int h, int layers, float baseSigma = 1.0f);

} // namespace mesolight

#endif
