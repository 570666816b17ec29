// SPDX-License-Identifier: BSD-3-Clause
#include "WalkthroughImage.h"

#include "Luminance.h"

#include <glm/common.hpp>

#include <algorithm>
#include <cmath>

namespace mesolight
{
namespace vlf
{

glm::vec3 ToneMap(const glm::vec3& radiance, float exposure, ToneMapOperator op)
{
  const DisplayTransform transform{ exposure, op, true };
  glm::vec3 out;
  for (int c = 0; c < 3; ++c)
  {
    out[c] = ApplyDisplayTransform(transform, radiance[c]);
  }
  return out;
}

glm::vec3 InverseToneMap(const glm::vec3& display, float exposure, ToneMapOperator op)
{
  const DisplayTransform transform{ exposure, op, true };
  glm::vec3 out;
  for (int c = 0; c < 3; ++c)
  {
    out[c] = InvertDisplayTransform(transform, display[c]);
  }
  return out;
}

ErrorStatistics RelativeError(const std::vector<glm::vec3>& image,
  const std::vector<glm::vec3>& reference, const std::vector<std::uint8_t>& mask,
  std::uint8_t which, float floor)
{
  std::vector<double> errors;
  const std::size_t n = std::min(image.size(), std::min(reference.size(), mask.size()));
  for (std::size_t i = 0; i < n; ++i)
  {
    if (mask[i] != which)
    {
      continue;
    }
    const glm::vec3 d = glm::abs(image[i] - reference[i]);
    const float r = reference[i].x + reference[i].y + reference[i].z;
    errors.push_back(
      static_cast<double>(d.x + d.y + d.z) / static_cast<double>(std::max(r, floor)));
  }
  ErrorStatistics stats;
  stats.Pixels = errors.size();
  if (errors.empty())
  {
    return stats;
  }
  double sum = 0.0;
  for (double e : errors)
  {
    sum += e;
  }
  stats.Mean = sum / static_cast<double>(errors.size());
  const std::size_t k = std::min(
    errors.size() - 1, static_cast<std::size_t>(0.95 * static_cast<double>(errors.size())));
  std::nth_element(errors.begin(), errors.begin() + static_cast<std::ptrdiff_t>(k), errors.end());
  stats.Percentile95 = errors[k];
  return stats;
}

double LogAverageLuminance(const float* rgba, std::size_t texels)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < texels; ++i)
  {
    const float* p = rgba + 4 * i;
    const double y = Luminance<double>(p[0], p[1], p[2]);
    if (y > 0.0 && std::isfinite(y))
    {
      sum += std::log(y);
      ++count;
    }
  }
  return count > 0 ? std::exp(sum / static_cast<double>(count)) : 0.0;
}

} // namespace vlf
} // namespace mesolight
