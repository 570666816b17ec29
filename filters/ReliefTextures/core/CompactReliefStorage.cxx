// SPDX-License-Identifier: BSD-3-Clause
#include "CompactReliefStorage.h"

#include "MinDepthPyramid.h"
#include "ParallelFor.h"
#include "SobelNormals.h"

#include <algorithm>
#include <cmath>
#include <limits>

namespace mesolight
{

std::uint16_t QuantizeDepth16(float depth)
{
  const float d = std::min(std::max(depth, 0.f), 1.f);
  return static_cast<std::uint16_t>(std::lround(d * 65535.f));
}

std::vector<std::vector<std::uint16_t>> CompactMinDepthPyramid(
  const std::uint16_t* depth16, int w, int h, std::vector<int>& levelSizes)
{
  levelSizes.clear();
  std::vector<std::vector<std::uint16_t>> out;
  if (!depth16 || w < 1 || h < 1)
  {
    return out;
  }
  // The pyramid of the depths as the GPU reads them (m / 65535, exact in float and back).
  std::vector<float> depth(static_cast<std::size_t>(w) * static_cast<std::size_t>(h));
  for (std::size_t i = 0; i < depth.size(); ++i)
  {
    depth[i] = static_cast<float>(depth16[i]) / 65535.f;
  }
  const std::vector<std::vector<float>> levels = ComputeMinDepthPyramid(depth.data(), w, h);
  for (std::size_t l = 1; l < levels.size(); ++l)
  {
    int lw = 0, lh = 0;
    MinDepthPyramidLevelSize(w, h, static_cast<int>(l), lw, lh);
    levelSizes.push_back(lw);
    levelSizes.push_back(lh);
    std::vector<std::uint16_t> level(levels[l].size());
    for (std::size_t i = 0; i < level.size(); ++i)
    {
      level[i] = QuantizeDepth16(levels[l][i]); // a minimum of m / 65535 values: exact
    }
    out.push_back(std::move(level));
  }
  return out;
}

float SobelNormalMismatch(
  const float* depth, const float* normalXY, int w, int h, double depthScale)
{
  if (!depth || !normalXY || w < 3 || h < 3 || !(depthScale > 0.0))
  {
    return std::numeric_limits<float>::max();
  }
  const std::size_t n = static_cast<std::size_t>(w) * static_cast<std::size_t>(h);
  std::vector<float> gradient(2 * n);
  ParallelFor(0, static_cast<std::size_t>(h), 16,
    [&](std::size_t b, std::size_t e)
    {
      ComputeSobelGradientRows(
        depth, w, h, BorderMode::Clamp, static_cast<int>(b), static_cast<int>(e), gradient.data());
    });
  const double k = depthScale;
  std::vector<float> rowMax(static_cast<std::size_t>(h), 0.f);
  ParallelFor(1, static_cast<std::size_t>(h - 1), 16,
    [&](std::size_t b, std::size_t e)
    {
      for (std::size_t row = b; row < e; ++row)
      {
        float worst = 0.f;
        for (std::size_t i = row * std::size_t(w) + 1; i + 1 < (row + 1) * std::size_t(w); ++i)
        {
          float derived[3];
          NormalFromGradient(
            gradient[2 * i], gradient[2 * i + 1], w, static_cast<float>(k), derived);
          worst = std::max(worst,
            std::max(std::fabs(derived[0] - normalXY[2 * i]),
              std::fabs(derived[1] - normalXY[2 * i + 1])));
        }
        rowMax[row] = worst;
      }
    });
  return *std::max_element(rowMax.begin(), rowMax.end());
}

} // namespace mesolight
