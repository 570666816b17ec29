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
std::vector<float> DepthFromShading(const std::vector<float>& shading, int w, int h,
  const HallucinationSettings& settings, const ProgressCallback& progress)
{
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<float> depth(n, 0.0f);
  if (n == 0 || shading.size() != n)
  {
    return {};
  }
  std::vector<float> floored(n);
  std::transform(
    shading.begin(), shading.end(), floored.begin(), [](float s) { return std::max(Floor, s); });
  std::vector<float> previous = floored;
  for (int k = 1; k <= settings.Layers; ++k)
  {
    if (!ReportProgress(progress, static_cast<double>(k - 1) / settings.Layers))
    {
      return {};
    }
    const float sigma = settings.BaseSigma * std::ldexp(1.0f, k - 1);
    // Each layer blurs the shading itself (not the previous layer), so sigma_k is exact.
    std::vector<float> layer = GaussianBlurClamped(floored, w, h, sigma, settings.Threads);
    ParallelFor(
      0, n, 4096,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t p = begin; p < end; ++p)
        {
          const float r = previous[p] / std::max(Floor, layer[p]);
          float contribution = 0.0f;
          if (r < 1.0f)
          {
            // Valley: visible aperture sin^2 a = r; depth sigma cot a.
            contribution = settings.ValleyWeight * sigma * std::sqrt((1.0f - r) / r);
          }
          else if (r > 1.0f)
          {
            // Hill: surround tilted by t, (1 + cos t) / 2 = 1 / r; height sigma tan t. Slopes
            // beyond 80 degrees are not resolved from shading alone.
            const float cosT = std::max(std::cos(1.3962634f), 2.0f / r - 1.0f);
            const float tanT = std::sqrt(std::max(0.0f, 1.0f - cosT * cosT)) / cosT;
            contribution = -settings.HillWeight * sigma * tanT;
          }
          depth[p] += settings.DepthScale * contribution;
        }
      },
      settings.Threads);
    previous.swap(layer);
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
  if (settings.Layers < 1 || settings.Layers > 12 || !(settings.BaseSigma > 0.0f) ||
    !(settings.DepthScale > 0.0f) || !(settings.ValleyWeight >= 0.0f) ||
    !(settings.HillWeight >= 0.0f) || !std::isfinite(settings.DepthScale))
  {
    Fail(HallucinationStatus::BadSettings,
      "Settings out of range (layers 1..12, base sigma > 0, depth scale > 0, weights >= 0).");
  }
  const int w = diffuse.Width, h = diffuse.Height;
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);

  // The flash must add light: on average (else it did not fire, or the images are swapped), and
  // nearly everywhere (pixels darker in the flash image beyond noise are counted).
  double flashOnly = 0.0, diffuseMean = 0.0;
  for (std::size_t p = 0; p < n; ++p)
  {
    flashOnly += RgbLuminance(&flash.Rgb[3 * p]) - RgbLuminance(&diffuse.Rgb[3 * p]);
    diffuseMean += RgbLuminance(&diffuse.Rgb[3 * p]);
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
    const double difference = RgbLuminance(&flash.Rgb[3 * p]) - RgbLuminance(&diffuse.Rgb[3 * p]);
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
  // 1. Albedo = (I_f - I_d) / I_c; a calibration pixel at or below 0 would divide by nothing, so
  // the card is floored at 1e-4 of its brightest value.
  float calibrationMax = 1.0f;
  if (calibration)
  {
    calibrationMax = *std::max_element(calibration->Rgb.begin(), calibration->Rgb.end());
    if (!(calibrationMax > 0.0f))
    {
      Fail(HallucinationStatus::EmptyImage,
        "The calibration image is black (the flash did not fire).");
    }
  }
  result.Albedo = RgbImage(w, h);
  for (std::size_t i = 0; i < 3 * n; ++i)
  {
    const float card = calibration ? std::max(1e-4f * calibrationMax, calibration->Rgb[i]) : 1.0f;
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
    albedoLuminance[p] = RgbLuminance(&result.Albedo.Rgb[3 * p]);
  }
  const float albedoFloor = 1e-3f * Percentile(albedoLuminance, 0.995);
  result.Shading.assign(n, -1.0f);
  std::vector<float> valid;
  valid.reserve(n);
  for (std::size_t p = 0; p < n; ++p)
  {
    if (albedoLuminance[p] > albedoFloor)
    {
      result.Shading[p] = std::max(0.0f, RgbLuminance(&diffuse.Rgb[3 * p])) / albedoLuminance[p];
      valid.push_back(result.Shading[p]);
    }
  }
  const float open = valid.empty() ? 0.0f : Percentile(valid, 0.995);
  for (float& s : result.Shading)
  {
    s = (s < 0.0f || !(open > 0.0f)) ? 1.0f : std::min(1.0f, s / open);
  }

  // 3. Depth from the shading layers.
  std::vector<float> depth =
    DepthFromShading(result.Shading, w, h, settings, SubProgress(progress, 0.1, 1.0));
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
