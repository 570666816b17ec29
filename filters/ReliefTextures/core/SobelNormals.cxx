// SPDX-License-Identifier: BSD-3-Clause
#include "SobelNormals.h"

#include <cmath>
#include <cstddef>

namespace mesolight
{

namespace
{
/// Neighbour indices (minus, plus) of index i in [0, n) and the distance between them.
struct Neighbours
{
  int Minus;
  int Plus;
  int Distance; // 0 when the dimension has a single sample: derivative is 0
};

Neighbours GetNeighbours(int i, int n, BorderMode mode)
{
  if (n <= 1)
  {
    return { 0, 0, 0 };
  }
  if (mode == BorderMode::Wrap)
  {
    // Periodic: the stencil always spans two texels, even across the seam.
    return { (i + n - 1) % n, (i + 1) % n, 2 };
  }
  const int m = i > 0 ? i - 1 : 0;
  const int p = i < n - 1 ? i + 1 : n - 1;
  // Real index distance: 2 inside, 1 at a border (one-sided difference).
  return { m, p, p - m };
}

inline float At(const float* depth, int w, int i, int j)
{
  return depth[static_cast<std::size_t>(j) * static_cast<std::size_t>(w) +
    static_cast<std::size_t>(i)];
}

/// Sobel gradient at one texel (Méndez Fernández's thesis §3.2, eq. 2).
inline void SobelAt(const float* depth, int w, const Neighbours& ni, const Neighbours& nj, int i,
  int j, float& gi, float& gj)
{
  if (ni.Distance > 0)
  {
    const float plus = At(depth, w, ni.Plus, nj.Minus) + 2.f * At(depth, w, ni.Plus, j) +
      At(depth, w, ni.Plus, nj.Plus);
    const float minus = At(depth, w, ni.Minus, nj.Minus) + 2.f * At(depth, w, ni.Minus, j) +
      At(depth, w, ni.Minus, nj.Plus);
    gi = (plus - minus) / (4.f * static_cast<float>(ni.Distance));
  }
  else
  {
    gi = 0.f;
  }
  if (nj.Distance > 0)
  {
    const float plus = At(depth, w, ni.Minus, nj.Plus) + 2.f * At(depth, w, i, nj.Plus) +
      At(depth, w, ni.Plus, nj.Plus);
    const float minus = At(depth, w, ni.Minus, nj.Minus) + 2.f * At(depth, w, i, nj.Minus) +
      At(depth, w, ni.Plus, nj.Minus);
    gj = (plus - minus) / (4.f * static_cast<float>(nj.Distance));
  }
  else
  {
    gj = 0.f;
  }
}
} // namespace

void ComputeSobelGradientRows(
  const float* depth, int w, int h, BorderMode mode, int rowBegin, int rowEnd, float* gradOut)
{
  if (!depth || !gradOut || w <= 0 || h <= 0)
  {
    return;
  }
  rowBegin = rowBegin < 0 ? 0 : rowBegin;
  rowEnd = rowEnd > h ? h : rowEnd;
  for (int j = rowBegin; j < rowEnd; ++j)
  {
    ComputeSobelGradientRow(depth, w, h, mode, j,
      gradOut + 2 * static_cast<std::size_t>(j) * static_cast<std::size_t>(w));
  }
}

void ComputeSobelGradientRow(
  const float* depth, int w, int h, BorderMode mode, int row, float* rowOut)
{
  if (!depth || !rowOut || w <= 0 || row < 0 || row >= h)
  {
    return;
  }
  const Neighbours nj = GetNeighbours(row, h, mode);
  for (int i = 0; i < w; ++i)
  {
    const Neighbours ni = GetNeighbours(i, w, mode);
    SobelAt(depth, w, ni, nj, i, row, rowOut[2 * i], rowOut[2 * i + 1]);
  }
}

void ComputeSobelGradient(const float* depth, int w, int h, BorderMode mode, float* gradOut)
{
  ComputeSobelGradientRows(depth, w, h, mode, 0, h, gradOut);
}

void NormalFromGradient(float gi, float gj, int w, float depthScale, float n[3])
{
  // Surface z = -k d(x, y): its normal is (k dd/dx, k dd/dy, 1) with dd/dx = w dd/di.
  const float scale = depthScale * static_cast<float>(w);
  const float nx = scale * gi;
  const float ny = scale * gj;
  const float invLen = 1.f / std::sqrt(nx * nx + ny * ny + 1.f);
  n[0] = nx * invLen;
  n[1] = ny * invLen;
  n[2] = invLen;
}

void ComputeReliefTextureRows(const float* depth, int w, int h, float depthScale, BorderMode mode,
  int rowBegin, int rowEnd, float* rgbaOut)
{
  if (!depth || !rgbaOut || w <= 0 || h <= 0)
  {
    return;
  }
  rowBegin = rowBegin < 0 ? 0 : rowBegin;
  rowEnd = rowEnd > h ? h : rowEnd;
  for (int j = rowBegin; j < rowEnd; ++j)
  {
    const Neighbours nj = GetNeighbours(j, h, mode);
    const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(w);
    for (int i = 0; i < w; ++i)
    {
      const Neighbours ni = GetNeighbours(i, w, mode);
      float gi;
      float gj;
      SobelAt(depth, w, ni, nj, i, j, gi, gj);
      float n[3];
      NormalFromGradient(gi, gj, w, depthScale, n);
      float* texel = rgbaOut + 4 * (row + static_cast<std::size_t>(i));
      // Pack the normal to [0,1] as in the thesis; alpha keeps the depth itself.
      texel[0] = 0.5f * (n[0] + 1.f);
      texel[1] = 0.5f * (n[1] + 1.f);
      texel[2] = 0.5f * (n[2] + 1.f);
      texel[3] = depth[row + static_cast<std::size_t>(i)];
    }
  }
}

void ComputeReliefTexture(
  const float* depth, int w, int h, float depthScale, BorderMode mode, float* rgbaOut)
{
  ComputeReliefTextureRows(depth, w, h, depthScale, mode, 0, h, rgbaOut);
}

} // namespace mesolight
