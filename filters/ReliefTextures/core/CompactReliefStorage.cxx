// SPDX-License-Identifier: BSD-3-Clause
#include "CompactReliefStorage.h"

#include "MinDepthPyramid.h"
#include "ParallelFor.h"
#include "SobelNormals.h"

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

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

std::vector<std::vector<std::uint8_t>> CompactChildMinima8(
  const std::uint16_t* depth16, int w, int h, int firstLevel, std::vector<int>& levelSizes)
{
  levelSizes.clear();
  std::vector<std::vector<std::uint8_t>> out;
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
  const std::vector<std::vector<float>> levels =
    ChildMinimaFromLevel(depth.data(), w, h, firstLevel, levelSizes);
  for (const std::vector<float>& level : levels)
  {
    std::vector<std::uint8_t> bytes(level.size());
    for (std::size_t i = 0; i < level.size(); ++i)
    {
      // A minimum of m / 65535 values is exact; m / 257 rounded down reads back no deeper.
      bytes[i] = static_cast<std::uint8_t>(QuantizeDepth16(level[i]) / 257);
    }
    out.push_back(std::move(bytes));
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
  // Row by row (a row's gradient at a time): the check runs on every upload, maps of 8192^2
  // included, and a whole gradient image would double the upload's memory.
  const double k = depthScale;
  std::vector<float> rowMax(static_cast<std::size_t>(h), 0.f);
  ParallelFor(1, static_cast<std::size_t>(h - 1), 16,
    [&](std::size_t b, std::size_t e)
    {
      std::vector<float> gradient(2 * static_cast<std::size_t>(w));
      for (std::size_t row = b; row < e; ++row)
      {
        ComputeSobelGradientRow(
          depth, w, h, BorderMode::Clamp, static_cast<int>(row), gradient.data());
        float worst = 0.f;
        for (std::size_t c = 1; c + 1 < std::size_t(w); ++c)
        {
          const std::size_t i = row * std::size_t(w) + c;
          float derived[3];
          NormalFromGradient(
            gradient[2 * c], gradient[2 * c + 1], w, static_cast<float>(k), derived);
          worst = std::max(worst,
            std::max(std::fabs(derived[0] - normalXY[2 * i]),
              std::fabs(derived[1] - normalXY[2 * i + 1])));
        }
        rowMax[row] = worst;
      }
    });
  return *std::max_element(rowMax.begin(), rowMax.end());
}

bool NormalsAreTheDepths(const float* depth, const float* normalXY, int w, int h, double depthScale)
{
  return SobelNormalMismatch(depth, normalXY, w, h, depthScale) <= SobelNormalTolerance;
}

void EncodeOctahedral8(float x, float y, float z, std::int8_t& e0, std::int8_t& e1)
{
  // Signed normalised: 8 bits err alike in every direction, where x, y with z rebuilt lose the
  // steep normals of walls (z = sqrt(1 - x^2 - y^2) is ill-conditioned there), and a flat
  // normal's 0 is exact.
  z = std::max(z, 0.f);
  const float l1 = std::fabs(x) + std::fabs(y) + z;
  const float px = l1 > 0.f ? x / l1 : 0.f, py = l1 > 0.f ? y / l1 : 0.f;
  e0 = static_cast<std::int8_t>(std::lround(std::min(std::max(px + py, -1.f), 1.f) * 127.f));
  e1 = static_cast<std::int8_t>(std::lround(std::min(std::max(px - py, -1.f), 1.f) * 127.f));
}

void DecodeOctahedral8(std::int8_t e0, std::int8_t e1, float n[3])
{
  // GL_RG8_SNORM: max(k / 127, -1); then vtkReliefHeightFieldFS.glsl's mlOctahedralNormal.
  const float a = std::max(static_cast<float>(e0) / 127.f, -1.f);
  const float b = std::max(static_cast<float>(e1) / 127.f, -1.f);
  const float px = 0.5f * (a + b), py = 0.5f * (a - b);
  const float pz = 1.f - std::fabs(px) - std::fabs(py);
  const float length = std::sqrt(px * px + py * py + pz * pz);
  n[0] = px / length;
  n[1] = py / length;
  n[2] = pz / length;
}

void NormalMoments(float x, float y, float z, float m[8])
{
  z = std::max(z, 0.f);
  const float length = std::sqrt(x * x + y * y + z * z);
  if (length > 0.f)
  {
    x /= length;
    y /= length;
    z /= length;
  }
  else
  {
    x = y = 0.f;
    z = 1.f;
  }
  // Walls steeper than nz = 1/16 are weighted as at 1/16, which keeps half floats finite and
  // exact enough.
  const float w = 1.f / std::max(z, 1.f / 16.f);
  m[0] = w * x * x;
  m[1] = w * y * y;
  m[2] = w * x * y;
  m[3] = w * z * z;
  m[4] = w * x * z;
  m[5] = w * y * z;
  m[6] = w * x;
  m[7] = w * y;
}

int MipLevelSize(int size, int level)
{
  return std::max(1, size >> level);
}

namespace
{
// The level-0 indices (with repeats) that level `level`'s index i averages along one axis of
// `size` texels: children 2i and 2i + 1 clamped to each finer level in turn.
void AxisTexels(int i, int level, int size, std::vector<int>& out)
{
  if (level == 0)
  {
    out.push_back(i);
    return;
  }
  const int finer = MipLevelSize(size, level - 1);
  for (int d = 0; d < 2; ++d)
  {
    AxisTexels(std::min(2 * i + d, finer - 1), level - 1, size, out);
  }
}
} // namespace

namespace
{
// Level `level` of the moments of a w x h map whose level-0 texel t has the moments
// texelMoments(t, m) (NormalMomentCount floats): each texel the mean of the level-0 texels
// AxisTexels gives it.
template <typename TexelMoments>
std::vector<float> MomentLevel(int w, int h, int level, const TexelMoments& texelMoments)
{
  constexpr int k = NormalMomentCount;
  const int lw = MipLevelSize(w, level), lh = MipLevelSize(h, level);
  std::vector<float> out(static_cast<size_t>(lw) * static_cast<size_t>(lh) * k, 0.f);
  std::vector<std::vector<int>> columns(static_cast<size_t>(lw));
  for (int i = 0; i < lw; ++i)
  {
    AxisTexels(i, level, w, columns[static_cast<size_t>(i)]);
  }
  const float share = 1.f / static_cast<float>((1 << level) * (1 << level));
  ParallelFor(0, static_cast<std::size_t>(lh), 16,
    [&](std::size_t rowBegin, std::size_t rowEnd)
    {
      std::vector<int> rows;
      float m[k];
      for (int j = static_cast<int>(rowBegin); j < static_cast<int>(rowEnd); ++j)
      {
        rows.clear();
        AxisTexels(j, level, h, rows);
        for (int i = 0; i < lw; ++i)
        {
          float* o = &out[(static_cast<size_t>(j) * lw + i) * k];
          for (int cj : rows)
          {
            for (int ci : columns[static_cast<size_t>(i)])
            {
              texelMoments(static_cast<size_t>(cj) * w + ci, m);
              for (int c = 0; c < k; ++c)
              {
                o[c] += share * m[c];
              }
            }
          }
        }
      }
    });
  return out;
}
} // namespace

std::vector<float> NormalMomentLevel(
  const float* normalXY, const float* normalZ, int w, int h, int level)
{
  return MomentLevel(w, h, level,
    [&](size_t t, float m[NormalMomentCount])
    {
      const float x = normalXY[2 * t], y = normalXY[2 * t + 1];
      const float z = normalZ ? normalZ[t] : std::sqrt(std::max(0.f, 1.f - x * x - y * y));
      NormalMoments(x, y, z, m);
    });
}

std::vector<float> SurfaceNormalMomentLevel(
  const float* depth, int w, int h, double depthScale, int level)
{
  auto at = [&](int i, int j)
  {
    i = std::min(std::max(i, 0), w - 1);
    j = std::min(std::max(j, 0), h - 1);
    return depth[static_cast<size_t>(j) * w + i];
  };
  const float k = static_cast<float>(depthScale);
  return MomentLevel(w, h, level,
    [&](size_t t, float m[NormalMomentCount])
    {
      const int ti = static_cast<int>(t % static_cast<size_t>(w));
      const int tj = static_cast<int>(t / static_cast<size_t>(w));
      std::fill(m, m + NormalMomentCount, 0.f);
      // One sample at the centre of each quarter of the texel: each quarter lies in one cell of
      // the bilinear surface (between four texel centres), whose gradient is linear across it.
      for (int q = 0; q < 4; ++q)
      {
        const int di = q % 2, dj = q / 2;
        const int i0 = ti - 1 + di, j0 = tj - 1 + dj;                 // the cell's lower-left texel
        const float fx = di ? 0.25f : 0.75f, fy = dj ? 0.25f : 0.75f; // within the cell
        const float d00 = at(i0, j0), d10 = at(i0 + 1, j0), d01 = at(i0, j0 + 1),
                    d11 = at(i0 + 1, j0 + 1);
        const float gi = (1.f - fy) * (d10 - d00) + fy * (d11 - d01);
        const float gj = (1.f - fx) * (d01 - d00) + fx * (d11 - d10);
        float n[3], qm[NormalMomentCount];
        NormalFromGradient(gi, gj, w, k, n);
        NormalMoments(n[0], n[1], n[2], qm);
        for (int c = 0; c < NormalMomentCount; ++c)
        {
          m[c] += 0.25f * qm[c];
        }
      }
    });
}

} // namespace mesolight
