// SPDX-License-Identifier: BSD-3-Clause
#include "DepthHallucination.h"

#include "ParallelFor.h"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <sstream>

namespace mesolight
{
namespace
{
// Ratios are taken of shading floored away from 0 (a black pixel is a very deep pit, not an
// infinitely deep one).
constexpr float Floor = 1e-3f;

[[noreturn]] void Fail(HallucinationStatus reason, const std::string& message)
{
  throw HallucinationError(reason, message);
}

bool AllFinite(const RgbImage& image)
{
  return std::all_of(image.Rgb.begin(), image.Rgb.end(), [](float x) { return std::isfinite(x); });
}

std::string SizeOf(const RgbImage& image)
{
  return std::to_string(image.Width) + "x" + std::to_string(image.Height);
}

// The value below which a fraction q of the values lie (nearest rank).
float Percentile(std::vector<float> values, double q)
{
  if (values.empty())
  {
    return 0.0f;
  }
  const std::size_t k = std::min(
    values.size() - 1, static_cast<std::size_t>(q * static_cast<double>(values.size() - 1) + 0.5));
  std::nth_element(values.begin(), values.begin() + static_cast<std::ptrdiff_t>(k), values.end());
  return values[k];
}

} // namespace

//------------------------------------------------------------------------------
std::vector<float> GaussianBlurClamped(
  const std::vector<float>& image, int w, int h, float sigma, int threads)
{
  if (!(sigma > 0.0f) || w <= 0 || h <= 0)
  {
    return image;
  }
  const int radius = std::max(1, static_cast<int>(std::ceil(3.0f * sigma)));
  std::vector<float> kernel(static_cast<std::size_t>(2 * radius + 1));
  float sum = 0.0f;
  for (int i = -radius; i <= radius; ++i)
  {
    kernel[static_cast<std::size_t>(i + radius)] =
      std::exp(-0.5f * static_cast<float>(i * i) / (sigma * sigma));
    sum += kernel[static_cast<std::size_t>(i + radius)];
  }
  for (float& k : kernel)
  {
    k /= sum;
  }
  std::vector<float> rows(image.size()), out(image.size());
  // Horizontal then vertical pass; the border is clamped (the photograph ends there, it does
  // not repeat).
  ParallelFor(
    0, static_cast<std::size_t>(h), 8,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t j = begin; j < end; ++j)
      {
        const float* src = image.data() + j * static_cast<std::size_t>(w);
        float* dst = rows.data() + j * static_cast<std::size_t>(w);
        for (int i = 0; i < w; ++i)
        {
          float acc = 0.0f;
          for (int t = -radius; t <= radius; ++t)
          {
            acc += kernel[static_cast<std::size_t>(t + radius)] * src[std::clamp(i + t, 0, w - 1)];
          }
          dst[i] = acc;
        }
      }
    },
    threads);
  ParallelFor(
    0, static_cast<std::size_t>(h), 8,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t j = begin; j < end; ++j)
      {
        float* dst = out.data() + j * static_cast<std::size_t>(w);
        for (int i = 0; i < w; ++i)
        {
          float acc = 0.0f;
          for (int t = -radius; t <= radius; ++t)
          {
            const int jj = std::clamp(static_cast<int>(j) + t, 0, h - 1);
            acc += kernel[static_cast<std::size_t>(t + radius)] *
              rows[static_cast<std::size_t>(jj) * static_cast<std::size_t>(w) +
                static_cast<std::size_t>(i)];
          }
          dst[i] = acc;
        }
      }
    },
    threads);
  return out;
}

//------------------------------------------------------------------------------
int HallucinationBlurFactor(float sigma)
{
  // Coarse sigma at least 8 texels: bilinear interpolation of a Gaussian that wide errs by a few
  // 1e-3 of its amplitude; sigma up to 16 (five layers) stays exact.
  int factor = 1;
  while (sigma > 16.0f && sigma / static_cast<float>(2 * factor) >= 8.0f)
  {
    factor *= 2;
  }
  return factor;
}

//------------------------------------------------------------------------------
std::vector<float> GaussianBlurPyramid(
  const std::vector<float>& image, int w, int h, float sigma, int threads)
{
  const int f = HallucinationBlurFactor(sigma);
  if (f == 1 || w <= 0 || h <= 0)
  {
    return GaussianBlurClamped(image, w, h, sigma, threads);
  }
  // Burt & Adelson, "The Laplacian pyramid as a compact image code": a wide blur is computed on
  // a copy reduced f times (f x f block means), then interpolated back bilinearly. The block
  // means add a variance of about f^2 / 12 and the interpolation f^2 / 6 (texels^2), which the
  // coarse sigma leaves out. The reduced copy extends `pad` blocks beyond the photograph, made of
  // the clamped photograph (as the fine blur extends it), so the border is blurred as the exact
  // blur does it, not as the border of the reduced copy.
  const float ratio = sigma / static_cast<float>(f);
  const float coarseSigma = std::sqrt(ratio * ratio - 0.25f);
  const int pad = static_cast<int>(std::ceil(3.0f * coarseSigma)) + 1;
  const int cw = (w + f - 1) / f + 2 * pad, ch = (h + f - 1) / f + 2 * pad;
  const std::size_t W = static_cast<std::size_t>(w), CW = static_cast<std::size_t>(cw);
  // Rows first: each fine row reduced to cw block means.
  std::vector<float> rows(static_cast<std::size_t>(h) * CW);
  ParallelFor(
    0, static_cast<std::size_t>(h), 8,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t j = begin; j < end; ++j)
      {
        const float* src = image.data() + j * W;
        for (int ci = 0; ci < cw; ++ci)
        {
          const int first = (ci - pad) * f;
          double sum = 0.0;
          if (first + f <= 0 || first >= w)
          {
            sum = static_cast<double>(src[first < 0 ? 0 : w - 1]) * f;
          }
          else
          {
            for (int di = 0; di < f; ++di)
            {
              sum += src[std::clamp(first + di, 0, w - 1)];
            }
          }
          rows[j * CW + static_cast<std::size_t>(ci)] = static_cast<float>(sum / f);
        }
      }
    },
    threads);
  std::vector<float> coarse(static_cast<std::size_t>(ch) * CW);
  for (int cj = 0; cj < ch; ++cj)
  {
    for (int ci = 0; ci < cw; ++ci)
    {
      double sum = 0.0;
      for (int dj = 0; dj < f; ++dj)
      {
        const int j = std::clamp((cj - pad) * f + dj, 0, h - 1);
        sum += rows[static_cast<std::size_t>(j) * CW + static_cast<std::size_t>(ci)];
      }
      coarse[static_cast<std::size_t>(cj) * CW + static_cast<std::size_t>(ci)] =
        static_cast<float>(sum / f);
    }
  }
  const std::vector<float> blurred = GaussianBlurClamped(coarse, cw, ch, coarseSigma, threads);
  std::vector<float> out(image.size());
  // Fine texel i lies at coarse coordinate (i - (f - 1) / 2) / f + pad (block centres at
  // integers); the padding keeps it inside the reduced copy.
  const auto locate = [f, pad](int i, int n, int& i0, int& i1, float& t)
  {
    const float x = std::clamp(
      (static_cast<float>(i) - 0.5f * static_cast<float>(f - 1)) / static_cast<float>(f) +
        static_cast<float>(pad),
      0.0f, static_cast<float>(n - 1));
    i0 = std::min(static_cast<int>(x), n - 1);
    i1 = std::min(i0 + 1, n - 1);
    t = x - static_cast<float>(i0);
  };
  ParallelFor(
    0, static_cast<std::size_t>(h), 8,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t j = begin; j < end; ++j)
      {
        int j0 = 0, j1 = 0, i0 = 0, i1 = 0;
        float tj = 0.0f, ti = 0.0f;
        locate(static_cast<int>(j), ch, j0, j1, tj);
        const float* r0 = blurred.data() + static_cast<std::size_t>(j0) * CW;
        const float* r1 = blurred.data() + static_cast<std::size_t>(j1) * CW;
        for (int i = 0; i < w; ++i)
        {
          locate(i, cw, i0, i1, ti);
          const float top = r0[i0] + ti * (r0[i1] - r0[i0]);
          const float bottom = r1[i0] + ti * (r1[i1] - r1[i0]);
          out[j * W + static_cast<std::size_t>(i)] = top + tj * (bottom - top);
        }
      }
    },
    threads);
  return out;
}

//------------------------------------------------------------------------------
double HallucinationWork(int w, int h, int layers, float baseSigma)
{
  // Multiply-adds of the blurs (two passes of 2 radius + 1 taps over the blurred image) plus the
  // per-pixel work of each layer (block means, interpolation, the hill and valley laws).
  const double n = static_cast<double>(w) * static_cast<double>(h);
  double work = 0.0;
  for (int k = 1; k <= layers; ++k)
  {
    const float sigma = baseSigma * std::ldexp(1.0f, k - 1);
    const int f = HallucinationBlurFactor(sigma);
    const double radius = std::max(1.0, std::ceil(3.0 * sigma / f));
    work += 2.0 * (2.0 * radius + 1.0) * n / (static_cast<double>(f) * f) + 8.0 * n;
  }
  return work;
}

namespace
{
// Layers -2: the count the feature size calls for (0: the scale average). The feature size is
// measured on the ratio image; the shading model keeps its scale average.
int FeatureLayers(
  const std::vector<float>& image, int w, int h, const HallucinationSettings& settings)
{
  return settings.Model == HallucinationModel::Ratio
    ? MeasureHallucinationFeatureScale(image, w, h, settings.BaseSigma, settings.Threads).Layers
    : 0;
}

// Layer k's depth (texels) from the ratio r = L_{k-1} / L_k by the valley and hill laws.
float LayerDepth(float r, float sigma, const HallucinationSettings& settings)
{
  if (r < 1.0f)
  {
    // Valley: visible aperture sin^2 a = r; depth sigma cot a.
    return settings.ValleyWeight * sigma * std::sqrt((1.0f - r) / r);
  }
  if (r > 1.0f)
  {
    // Hill: surround tilted by t, (1 + cos t) / 2 = 1 / r; height sigma tan t. Slopes beyond 80
    // degrees are not resolved from shading alone.
    const float cosT = std::max(std::cos(1.3962634f), 2.0f / r - 1.0f);
    const float tanT = std::sqrt(std::max(0.0f, 1.0f - cosT * cosT)) / cosT;
    return -settings.HillWeight * sigma * tanT;
  }
  return 0.0f;
}

// Whether the ratio image itself joins the scale average: when a count wider than the finest
// agrees with it best, the image's darkness is a picture of features resolved over several
// texels (perforations, pits), not of texel-scale texture and noise, and the darkness is then as
// good a depth as the layers make of it (measured on real height maps: docs/hallucination.md).
bool RatioJoinsTheAverage(const std::vector<double>& agreements)
{
  return agreements.size() >= 2 &&
    std::max_element(agreements.begin(), agreements.end()) != agreements.begin();
}

// The residual layer's depth (texels): the widest layer's value against the open sky (1).
float ResidualDepth(float widest, float sigma, const HallucinationSettings& settings)
{
  const float r = std::min(1.0f, std::max(Floor, widest));
  return settings.ValleyWeight * sigma * std::sqrt((1.0f - r) / r);
}
} // namespace

//------------------------------------------------------------------------------
std::vector<float> DepthFromShading(const std::vector<float>& shading, int w, int h,
  const HallucinationSettings& settings, const ProgressCallback& progress)
{
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<float> depth(n, 0.0f);
  if (n == 0 || shading.size() != n)
  {
    return {};
  }
  const int requested = settings.Layers == HallucinationFeatureLayers
    ? FeatureLayers(shading, w, h, settings)
    : settings.Layers;
  const bool average = requested == 0;
  const int layers = requested > 0 ? requested
    : average
    ? HallucinationAverageLayers(w, h, settings.BaseSigma)
    : ChooseHallucinationLayers(shading, w, h, settings.BaseSigma, settings.Threads).Layers;
  std::vector<float> floored(n);
  std::transform(
    shading.begin(), shading.end(), floored.begin(), [](float s) { return std::max(Floor, s); });
  std::vector<float> previous = floored;
  // The scale average: the model with 1, 2, ..., `layers` layers (each with its residual layer)
  // is a hypothesis of the feature size; nothing in the shading alone says which is right (the
  // best count measured 1 to 8 on real maps, and a threshold on the octave energies chose it
  // wrongly on a third of them), so all are averaged with equal say: weights inversely
  // proportional to each hypothesis' spread (the widest layer's sigma would otherwise decide),
  // which keeps the result in texels.
  // Under HallucinationModel::Ratio the counts do not get an equal say: each is weighted by its
  // squared correlation with the input's own darkness (the ratio image, the paper's "dark is
  // deep" cue, which does not depend on a scale): the counts whose structure the image shows
  // count, those that invent broad shape the image does not hold fade out (measured on real
  // height maps: docs/hallucination.md). Equal weights are kept alongside, for an input no
  // count agrees with.
  const bool agreement = average && settings.Model == HallucinationModel::Ratio;
  double darkMean = 0.0, darkSpread = 0.0;
  if (agreement)
  {
    double square = 0.0;
    for (const float s : floored)
    {
      darkMean -= s;
      square += static_cast<double>(s) * s;
    }
    darkMean /= static_cast<double>(n);
    darkSpread = std::sqrt(std::max(0.0, square / static_cast<double>(n) - darkMean * darkMean));
  }
  std::vector<float> hypothesis(average ? n : 0), sum(average ? n : 0, 0.0f),
    agreed(agreement ? n : 0, 0.0f);
  double weightSum = 0.0, agreedSum = 0.0;
  // The agreement c_K of each count with the image's darkness, finest first.
  std::vector<double> agreements;
  for (int k = 1; k <= layers; ++k)
  {
    if (!ReportProgress(progress, static_cast<double>(k - 1) / layers))
    {
      return {};
    }
    const float sigma = settings.BaseSigma * std::ldexp(1.0f, k - 1);
    // Each layer blurs the shading itself (not the previous layer), so sigma_k does not drift;
    // layers wider than 16 texels are blurred on a reduced copy (the cost of each layer is then
    // about the same instead of doubling).
    std::vector<float> layer = GaussianBlurPyramid(floored, w, h, sigma, settings.Threads);
    ParallelFor(
      0, n, 4096,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t p = begin; p < end; ++p)
        {
          depth[p] += settings.DepthScale *
            LayerDepth(previous[p] / std::max(Floor, layer[p]), sigma, settings);
        }
      },
      settings.Threads);
    previous.swap(layer);
    if (average)
    {
      const float residualSigma = settings.ResidualWeight * sigma;
      double mean = 0.0, square = 0.0;
      for (std::size_t p = 0; p < n; ++p)
      {
        hypothesis[p] = depth[p] +
          (settings.ResidualWeight > 0.0f
              ? settings.DepthScale * ResidualDepth(previous[p], residualSigma, settings)
              : 0.0f);
        mean += hypothesis[p];
        square += static_cast<double>(hypothesis[p]) * hypothesis[p];
      }
      mean /= static_cast<double>(n);
      const double spread = std::sqrt(std::max(0.0, square / static_cast<double>(n) - mean * mean));
      if (spread > 1e-12)
      {
        const double weight = 1.0 / spread;
        weightSum += weight;
        for (std::size_t p = 0; p < n; ++p)
        {
          sum[p] += static_cast<float>(weight * hypothesis[p]);
        }
        if (agreement && darkSpread > 1e-12)
        {
          // Pearson correlation of this count's depth with -image.
          double covariance = 0.0;
          for (std::size_t p = 0; p < n; ++p)
          {
            covariance += (hypothesis[p] - mean) * (-floored[p] - darkMean);
          }
          const double c =
            std::max(0.0, covariance / (static_cast<double>(n) * spread * darkSpread));
          agreements.push_back(c);
          const double agreedWeight = c * c / spread;
          agreedSum += agreedWeight;
          for (std::size_t p = 0; p < n; ++p)
          {
            agreed[p] += static_cast<float>(agreedWeight * (hypothesis[p] - mean));
          }
        }
      }
    }
  }
  if (average)
  {
    // A uniform shading gives flat hypotheses (no weight): the depth stays flat.
    if (agreedSum > 0.0)
    {
      const float inverse = static_cast<float>(1.0 / agreedSum);
      for (std::size_t p = 0; p < n; ++p)
      {
        depth[p] = agreed[p] * inverse;
      }
      if (RatioJoinsTheAverage(agreements) && darkSpread > 1e-12)
      {
        // The ratio's darkness itself joins with an equal say (both at the average's spread).
        double mean = 0.0, square = 0.0;
        for (const float d : depth)
        {
          mean += d;
          square += static_cast<double>(d) * d;
        }
        mean /= static_cast<double>(n);
        const double spread =
          std::sqrt(std::max(0.0, square / static_cast<double>(n) - mean * mean));
        const float scale = static_cast<float>(spread / darkSpread);
        for (std::size_t p = 0; p < n; ++p)
        {
          depth[p] += scale * (-floored[p] - static_cast<float>(darkMean));
        }
      }
    }
    else
    {
      const float inverse = weightSum > 0.0 ? static_cast<float>(1.0 / weightSum) : 0.0f;
      for (std::size_t p = 0; p < n; ++p)
      {
        depth[p] = sum[p] * inverse;
      }
    }
  }
  else if (settings.ResidualWeight > 0.0f)
  {
    // The residual layer: what the layers leave out, the widest layer itself, compared with
    // the open sky (shading 1) by the valley law, sigma ResidualWeight times the widest layer's.
    // Broad dark regions (a wide recessed panel, a long groove's floor) come out deep instead
    // of as flat as the open surface.
    const float sigma = settings.ResidualWeight * settings.BaseSigma * std::ldexp(1.0f, layers - 1);
    for (std::size_t p = 0; p < n; ++p)
    {
      depth[p] += settings.DepthScale * ResidualDepth(previous[p], sigma, settings);
    }
  }
  if (!ReportProgress(progress, 1.0))
  {
    return {};
  }
  return depth;
}

//------------------------------------------------------------------------------
HallucinationResult HallucinateDepth(const RgbImage& diffuse, const RgbImage& flash,
  const RgbImage* calibration, const HallucinationSettings& settings,
  const ProgressCallback& progress)
{
  const auto empty = [](const RgbImage& image)
  {
    return image.Width <= 0 || image.Height <= 0 ||
      image.Rgb.size() != 3 * static_cast<std::size_t>(image.Width) * image.Height;
  };
  if (empty(diffuse) || empty(flash) || (calibration && empty(*calibration)))
  {
    Fail(HallucinationStatus::EmptyImage,
      std::string("The ") +
        (empty(diffuse) ? "diffuse" : (empty(flash) ? "flash" : "calibration")) +
        " image is empty.");
  }
  if (flash.Width != diffuse.Width || flash.Height != diffuse.Height ||
    (calibration && (calibration->Width != diffuse.Width || calibration->Height != diffuse.Height)))
  {
    const bool flashDiffers = flash.Width != diffuse.Width || flash.Height != diffuse.Height;
    Fail(HallucinationStatus::SizeMismatch,
      "The photographs differ in size: diffuse " + SizeOf(diffuse) + ", " +
        (flashDiffers ? "flash " + SizeOf(flash) : "calibration " + SizeOf(*calibration)) +
        " (they must show the same view, pixel for pixel).");
  }
  if (!AllFinite(diffuse) || !AllFinite(flash) || (calibration && !AllFinite(*calibration)))
  {
    Fail(HallucinationStatus::NonFinite,
      std::string("The ") +
        (!AllFinite(diffuse) ? "diffuse" : (!AllFinite(flash) ? "flash" : "calibration")) +
        " image has NaN or infinite pixels.");
  }
  if (settings.Layers < HallucinationFeatureLayers || settings.Layers > 12 ||
    !(settings.BaseSigma > 0.0f) || !(settings.DepthScale > 0.0f) ||
    !(settings.ValleyWeight >= 0.0f) || !(settings.HillWeight >= 0.0f) ||
    !(settings.ResidualWeight >= 0.0f) || !std::isfinite(settings.DepthScale) ||
    !std::isfinite(settings.ResidualWeight))
  {
    Fail(HallucinationStatus::BadSettings,
      "Settings out of range (layers -2 = from the feature size, 0 = scale average, -1 = "
      "automatic count or 1..12, base "
      "sigma > 0, depth scale > 0, "
      "weights >= 0).");
  }
  if (!(settings.ValleyWeight > 0.0f) && !(settings.HillWeight > 0.0f))
  {
    Fail(HallucinationStatus::BadSettings,
      "The hill and valley weights are both 0: the depth would be flat.");
  }
  const int w = diffuse.Width, h = diffuse.Height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  if (std::min(w, h) < HallucinationMinimumSide)
  {
    Fail(HallucinationStatus::TooSmall,
      "The photographs are " + SizeOf(diffuse) + ": depth from shading compares each pixel with " +
        "its surround, which needs at least " + std::to_string(HallucinationMinimumSide) + "x" +
        std::to_string(HallucinationMinimumSide) + " pixels.");
  }
  // Linear photographs are not negative beyond noise (a black level subtracted twice, or a
  // difference image, is): the shading of a negative pixel would be taken as black.
  const auto negativeFraction = [n](const RgbImage& image)
  {
    std::size_t negative = 0;
    for (std::size_t p = 0; p < n; ++p)
    {
      negative += Luminance(&image.Rgb[3 * p]) < 0.0f ? 1 : 0;
    }
    return static_cast<double>(negative) / static_cast<double>(n);
  };
  const struct
  {
    const RgbImage* Image;
    const char* Role;
  } photographs[] = { { &diffuse, "diffuse" }, { &flash, "flash" },
    { calibration, "calibration" } };
  for (const auto& photograph : photographs)
  {
    const double fraction = photograph.Image ? negativeFraction(*photograph.Image) : 0.0;
    if (fraction > static_cast<double>(settings.MaximumDarkerFraction))
    {
      std::ostringstream message;
      message << "The " << photograph.Role << " photograph is negative in "
              << std::max(1L, std::lround(100.0 * fraction))
              << "% of the pixels: photographs must be linear light, >= 0 (was a black level "
                 "subtracted twice?).";
      Fail(HallucinationStatus::NegativeLight, message.str());
    }
  }

  // The albedo (I_f - I_d) / I_c is per channel: a grey photograph (R = G = B everywhere, e.g. one
  // channel read as grey) beside a colour one gives wrong colours, or the darker-flash check
  // below blames swapped photographs. (An all-black frame is left to that check.)
  const auto grey = [n](const RgbImage& image)
  {
    bool lit = false;
    for (std::size_t p = 0; p < n; ++p)
    {
      const float* rgb = &image.Rgb[3 * p];
      if (rgb[0] != rgb[1] || rgb[1] != rgb[2])
      {
        return false;
      }
      lit = lit || rgb[0] != 0.0f;
    }
    return lit;
  };
  const bool diffuseGrey = grey(diffuse);
  if (diffuseGrey != grey(flash))
  {
    Fail(HallucinationStatus::GreyAndColour,
      std::string("The ") + (diffuseGrey ? "diffuse" : "flash") + " photograph is grey and the " +
        (diffuseGrey ? "flash" : "diffuse") +
        " one is in colour: the albedo, flash minus diffuse per channel, would have wrong "
        "colours. Give both in colour (or both grey), from the same camera settings.");
  }

  // The flash must add light: on average (else it did not fire, or the images are swapped), and
  // nearly everywhere (pixels darker in the flash image beyond noise are counted).
  double flashOnly = 0.0, diffuseMean = 0.0;
  for (std::size_t p = 0; p < n; ++p)
  {
    flashOnly += Luminance(&flash.Rgb[3 * p]) - Luminance(&diffuse.Rgb[3 * p]);
    diffuseMean += Luminance(&diffuse.Rgb[3 * p]);
  }
  flashOnly /= static_cast<double>(n);
  diffuseMean /= static_cast<double>(n);
  if (flashOnly < 0.0)
  {
    Fail(HallucinationStatus::FlashDarker,
      "The flash image is darker than the diffuse one: were the two swapped?");
  }
  if (!(flashOnly > 1e-3 * diffuseMean))
  {
    Fail(HallucinationStatus::FlashDarker,
      "The flash image is not brighter than the diffuse one: did the flash fire?");
  }
  std::size_t darker = 0;
  for (std::size_t p = 0; p < n; ++p)
  {
    const double difference = Luminance(&flash.Rgb[3 * p]) - Luminance(&diffuse.Rgb[3 * p]);
    if (difference < -settings.DarkerTolerance * flashOnly)
    {
      ++darker;
    }
  }
  if (static_cast<double>(darker) > settings.MaximumDarkerFraction * static_cast<double>(n))
  {
    std::ostringstream message;
    message << "The flash image is darker than the diffuse one in "
            << static_cast<int>(std::lround(100.0 * static_cast<double>(darker) / n))
            << "% of the pixels: were the two swapped, or did the light change between them?";
    Fail(HallucinationStatus::FlashDarker, message.str());
  }

  HallucinationResult result;
  // 1. Albedo = (I_f - I_d) / I_c. The card measures the flash's fall-off, which is smooth: a
  // card dark in part of the view (it did not fill the frame, or was shadowed) would divide the
  // flash light there by almost nothing (albedos in the thousands), so it is refused beyond 1% of
  // the pixels, and the card is floored at 2% of its bright level (the 99.5th percentile).
  float cardFloor = 1.0f;
  if (calibration)
  {
    const float calibrationMax =
      *std::max_element(calibration->Rgb.begin(), calibration->Rgb.end());
    if (!(calibrationMax > 0.0f))
    {
      Fail(HallucinationStatus::EmptyImage,
        "The calibration image is black (the flash did not fire).");
    }
    std::vector<float> cardLuminance(n);
    for (std::size_t p = 0; p < n; ++p)
    {
      cardLuminance[p] = Luminance(&calibration->Rgb[3 * p]);
    }
    const float bright = Percentile(cardLuminance, 0.995);
    cardFloor = 0.02f * (bright > 0.0f ? bright : calibrationMax);
    const auto dark = static_cast<std::size_t>(std::count_if(
      cardLuminance.begin(), cardLuminance.end(), [cardFloor](float l) { return l < cardFloor; }));
    if (static_cast<double>(dark) > 0.01 * static_cast<double>(n))
    {
      std::ostringstream message;
      message << "The calibration card is darker than 2% of its bright level in "
              << std::max(1L, std::lround(100.0 * static_cast<double>(dark) / n))
              << "% of the pixels: it must fill the view and be lit by the flash (else the "
                 "albedo there is divided by almost nothing).";
      Fail(HallucinationStatus::DarkCard, message.str());
    }
  }
  result.Albedo = RgbImage(w, h);
  for (std::size_t i = 0; i < 3 * n; ++i)
  {
    const float card = calibration ? std::max(cardFloor, calibration->Rgb[i]) : 1.0f;
    result.Albedo.Rgb[i] = std::max(0.0f, flash.Rgb[i] - diffuse.Rgb[i]) / card;
  }
  if (!ReportProgress(progress, 0.05))
  {
    throw HallucinationAbortedError();
  }

  // 2. Shading = lum(I_d) / lum(albedo), 1 at the 99.5th percentile. A black albedo carries no
  // shading: such pixels take the shading of the open surface (1).
  std::vector<float> albedoLuminance(n);
  for (std::size_t p = 0; p < n; ++p)
  {
    albedoLuminance[p] = Luminance(&result.Albedo.Rgb[3 * p]);
  }
  const float albedoFloor = 1e-3f * Percentile(albedoLuminance, 0.995);
  result.Shading.assign(n, -1.0f);
  std::vector<float> valid;
  valid.reserve(n);
  for (std::size_t p = 0; p < n; ++p)
  {
    if (albedoLuminance[p] > albedoFloor)
    {
      result.Shading[p] = std::max(0.0f, Luminance(&diffuse.Rgb[3 * p])) / albedoLuminance[p];
      valid.push_back(result.Shading[p]);
    }
  }
  const float open = valid.empty() ? 0.0f : Percentile(valid, 0.995);
  for (float& s : result.Shading)
  {
    s = (s < 0.0f || !(open > 0.0f)) ? 1.0f : std::min(1.0f, s / open);
  }

  // The diffuse/flash ratio with the flash's fall-off divided out: lum(I_d) / (lum(I_d) +
  // lum(albedo)), which is I_d / I_f without a card. It is a monotonic function of the sky's
  // share of the light, S / (S + 1) in units of the flash: the shading compressed where it is
  // bright, where the flash-pair albedo is least sure (its cosine to the flash, bounced light)
  // and open surfaces differ least in depth. 1 at its maximum.
  result.Ratio.assign(n, 1.0f);
  float ratioMax = 0.0f;
  for (std::size_t p = 0; p < n; ++p)
  {
    const float d = std::max(0.0f, Luminance(&diffuse.Rgb[3 * p]));
    const float total = d + albedoLuminance[p];
    result.Ratio[p] = total > 0.0f ? d / total : 1.0f;
    ratioMax = std::max(ratioMax, result.Ratio[p]);
  }
  for (float& r : result.Ratio)
  {
    r = ratioMax > 0.0f ? r / ratioMax : 1.0f;
  }
  const std::vector<float>& layerInput =
    settings.Model == HallucinationModel::Ratio ? result.Ratio : result.Shading;

  // 3. Depth from the layers: by default the counts the ratio image's feature size calls for
  // (the average over every count the photograph holds on fine features, one wide count on broad
  // ones); 0: that average (DepthFromShading); -1: the count the octave energies choose; or
  // fixed.
  HallucinationSettings used = settings;
  if (used.Layers == HallucinationFeatureLayers)
  {
    // The feature size of what the layers read: fine, the scale average; broad, one wide count.
    if (settings.Model == HallucinationModel::Ratio)
    {
      const HallucinationFeatureScale scale =
        MeasureHallucinationFeatureScale(layerInput, w, h, settings.BaseSigma, settings.Threads);
      used.Layers = scale.Layers;
      result.CorrelationLengthTexels = scale.CorrelationLengthTexels;
    }
    else
    {
      used.Layers = 0;
    }
  }
  if (used.Layers == -1)
  {
    const HallucinationScale scale =
      ChooseHallucinationLayers(layerInput, w, h, settings.BaseSigma, settings.Threads);
    used.Layers = scale.Layers;
    result.FeatureSizeTexels = scale.FeatureSizeTexels;
  }
  result.Averaged = used.Layers == 0;
  result.Layers =
    used.Layers == 0 ? HallucinationAverageLayers(w, h, settings.BaseSigma) : used.Layers;
  if (!ReportProgress(progress, 0.1))
  {
    throw HallucinationAbortedError();
  }
  std::vector<float> depth =
    DepthFromShading(layerInput, w, h, used, SubProgress(progress, 0.1, 1.0));
  if (depth.empty())
  {
    throw HallucinationAbortedError();
  }
  const auto range = std::minmax_element(depth.begin(), depth.end());
  const float lowest = *range.first;
  result.DepthRangeTexels = *range.second - lowest;
  const float inverse = result.DepthRangeTexels > 0.0f ? 1.0f / result.DepthRangeTexels : 0.0f;
  for (float& d : depth)
  {
    d = (d - lowest) * inverse;
  }
  result.Depth = std::move(depth);
  return result;
}

} // namespace mesolight
