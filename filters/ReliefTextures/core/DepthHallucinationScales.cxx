// SPDX-License-Identifier: BSD-3-Clause
// The scale layers of depth hallucination (Glencross et al., "A perceptually validated model for
// surface depth hallucination"): how many octaves a photograph's features call for, chosen from
// the layers' energies, the image size, or the ratio image's autocorrelation length. Declared
// in DepthHallucination.h.
#include "DepthHallucination.h"

#include "ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <vector>

namespace mesolight
{

//------------------------------------------------------------------------------
HallucinationScale ChooseHallucinationLayers(
  const std::vector<float>& shading, int w, int h, float baseSigma, int threads)
{
  HallucinationScale scale;
  const std::size_t n =
    static_cast<std::size_t>(std::max(0, w)) * static_cast<std::size_t>(std::max(0, h));
  if (n == 0 || shading.size() != n || !(baseSigma > 0.0f))
  {
    return scale;
  }
  // The shading's energy per octave, a scale-space band-pass (Burt & Adelson's Laplacian pyramid;
  // Lindeberg, "Feature detection with automatic scale selection"): E_k = mean of
  // (L_{k-1} - L_k)^2, starting from the shading blurred by the first layer's sigma (the
  // photograph's noise is in the finest band), over the pixels at least 2 sigma_k from the border
  // (the clamped border is no feature). Features of a size put energy in the octaves up to about
  // their size, little beyond: the widest layer is the widest octave holding at least a fifth of
  // the strongest octave's energy (the threshold measured on bench hallucinate's maps, with the
  // generator's panels and holes: docs/hallucination.md).
  std::vector<float> previous = GaussianBlurPyramid(shading, w, h, baseSigma, threads);
  std::vector<double> energies;
  std::vector<int> layerOf;
  for (int k = 2; k <= 12; ++k)
  {
    const float sigma = baseSigma * std::ldexp(1.0f, k - 1);
    const int border = static_cast<int>(std::ceil(2.0f * sigma));
    if (2 * border >= std::min(w, h) - 2)
    {
      break;
    }
    std::vector<float> layer = GaussianBlurPyramid(shading, w, h, sigma, threads);
    double energy = 0.0, count = 0.0;
    for (int j = border; j < h - border; ++j)
    {
      for (int i = border; i < w - border; ++i)
      {
        const std::size_t p =
          static_cast<std::size_t>(j) * static_cast<std::size_t>(w) + static_cast<std::size_t>(i);
        const double d = static_cast<double>(previous[p]) - layer[p];
        energy += d * d;
        count += 1.0;
      }
    }
    energies.push_back(count > 0.0 ? energy / count : 0.0);
    layerOf.push_back(k);
    previous.swap(layer);
  }
  scale.Layers = std::min(2, std::max(1, std::min(w, h) / 4));
  if (energies.empty())
  {
    return scale;
  }
  const double strongest = *std::max_element(energies.begin(), energies.end());
  double meanSquare = 0.0;
  for (const float v : shading)
  {
    meanSquare += static_cast<double>(v) * v / static_cast<double>(n);
  }
  if (!(strongest > 1e-10 * meanSquare))
  {
    return scale; // uniform shading (to the blur's rounding): no feature to size
  }
  for (std::size_t k = 0; k < energies.size(); ++k)
  {
    if (energies[k] >= 0.2 * strongest)
    {
      scale.Layers = layerOf[k];
    }
  }
  scale.FeatureSizeTexels = baseSigma * std::ldexp(1.0f, scale.Layers - 1);
  return scale;
}

//------------------------------------------------------------------------------
int HallucinationAverageLayers(int w, int h, float baseSigma)
{
  // Every octave whose layer leaves an interior 2 sigma from the border (the energies of
  // ChooseHallucinationLayers use the same interior), at most 12.
  int layers = 1;
  while (layers < 12)
  {
    const float sigma = baseSigma * std::ldexp(1.0f, layers);
    if (2 * static_cast<int>(std::ceil(2.0f * sigma)) >= std::min(w, h) - 2)
    {
      break;
    }
    ++layers;
  }
  return layers;
}

//------------------------------------------------------------------------------
HallucinationFeatureScale MeasureHallucinationFeatureScale(
  const std::vector<float>& image, int w, int h, float baseSigma, int threads)
{
  HallucinationFeatureScale scale;
  const std::size_t n =
    static_cast<std::size_t>(std::max(0, w)) * static_cast<std::size_t>(std::max(0, h));
  if (n == 0 || image.size() != n || !(baseSigma > 0.0f) || std::min(w, h) < 2)
  {
    return scale;
  }
  double mean = 0.0;
  for (const float v : image)
  {
    mean += v;
  }
  mean /= static_cast<double>(n);
  double variance = 0.0;
  for (const float v : image)
  {
    variance += (v - mean) * (v - mean);
  }
  variance /= static_cast<double>(n);
  if (!(variance > 1e-12 * std::max(1.0, mean * mean)))
  {
    return scale; // uniform: no feature to size, the scale average (which stays flat)
  }
  // The widest count allowed: its sigma at most half the shorter side. Shifts beyond the length
  // that already calls for it change nothing, so the search stops there (the cost stays a few
  // passes over the image even on large photographs).
  const int side = std::min(w, h);
  int widest = 1;
  while (widest < 12 && baseSigma * std::ldexp(1.0f, widest) <= 0.5f * static_cast<float>(side))
  {
    ++widest;
  }
  const float widestSigma = baseSigma * std::ldexp(1.0f, widest - 1);
  const int longestShift =
    std::max(static_cast<int>(std::ceil(std::max(HallucinationBroadCorrelationLength,
               2.0f * widestSigma / HallucinationBroadSigmaPerLength))) +
        1,
      2);
  const int maxShift = std::min(longestShift, side / 2);
  // Autocovariance at shift s, horizontal and vertical pairs pooled; per-row sums over a fixed
  // partition, added in order (the same result however the rows are split).
  const std::size_t W = static_cast<std::size_t>(w);
  double previous = 1.0;
  for (int s = 1; s <= maxShift; ++s)
  {
    std::vector<double> rowSums(static_cast<std::size_t>(h), 0.0);
    ParallelFor(
      0, static_cast<std::size_t>(h), 16,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t j = begin; j < end; ++j)
        {
          const float* row = image.data() + j * W;
          double sum = 0.0;
          for (int i = 0; i + s < w; ++i)
          {
            sum += (row[i] - mean) * (row[i + s] - mean);
          }
          if (j + static_cast<std::size_t>(s) < static_cast<std::size_t>(h))
          {
            const float* below = row + static_cast<std::size_t>(s) * W;
            for (int i = 0; i < w; ++i)
            {
              sum += (row[i] - mean) * (below[i] - mean);
            }
          }
          rowSums[j] = sum;
        }
      },
      threads);
    double sum = 0.0;
    for (const double r : rowSums)
    {
      sum += r;
    }
    const double pairs = static_cast<double>(h) * (w - s) + static_cast<double>(h - s) * w;
    const double correlation = sum / pairs / variance;
    if (correlation < 0.5)
    {
      scale.CorrelationLengthTexels =
        static_cast<float>(s - 1 + (previous - 0.5) / (previous - correlation));
      break;
    }
    previous = correlation;
    scale.CorrelationLengthTexels = static_cast<float>(s); // still correlated at the last shift
  }
  if (scale.CorrelationLengthTexels >= HallucinationBroadCorrelationLength)
  {
    // The octave nearest to HallucinationBroadSigmaPerLength correlation lengths.
    const float sigma = HallucinationBroadSigmaPerLength * scale.CorrelationLengthTexels;
    const int layers = 1 + static_cast<int>(std::lround(std::log2(sigma / baseSigma)));
    scale.Layers = std::clamp(layers, 1, widest);
  }
  return scale;
}

} // namespace mesolight
