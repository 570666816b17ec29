// SPDX-License-Identifier: BSD-3-Clause
#include "ProceduralHeightFields.h"

#include "MathConstants.h"

#include <algorithm>
#include <cmath>
#include <cstddef>

namespace mesolight
{

namespace
{

float Clamp01(float x)
{
  return std::min(1.f, std::max(0.f, x)); // NaN maps to 0: never out of range
}

float SmoothStep(float e0, float e1, float x)
{
  const float t = Clamp01((x - e0) / (e1 - e0));
  return t * t * (3.f - 2.f * t);
}

float UnitFromHash(std::uint32_t h)
{
  return static_cast<float>(h >> 8) * (1.f / 16777216.f); // [0,1)
}

std::uint32_t Hash3(std::int32_t x, std::int32_t y, std::uint32_t seed)
{
  return HashInt(static_cast<std::uint32_t>(x) * 0x8da6b343u ^
    HashInt(static_cast<std::uint32_t>(y) * 0xd8163841u ^ HashInt(seed + 0x9e3779b9u)));
}

int PositiveMod(int a, int n)
{
  const int r = a % n;
  return r < 0 ? r + n : r;
}

std::uint8_t ToByte(float x)
{
  return static_cast<std::uint8_t>(std::lround(255.f * Clamp01(x)));
}

void SetRGB(std::uint8_t* albedo, float r, float g, float b)
{
  if (albedo)
  {
    albedo[0] = ToByte(r);
    albedo[1] = ToByte(g);
    albedo[2] = ToByte(b);
  }
}

/// Subtle 8x8 checker (+-4%) so that texture displacement is visible on light patterns.
float Checker(float u, float v)
{
  const int cu = static_cast<int>(std::floor(u * 8.f));
  const int cv = static_cast<int>(std::floor(v * 8.f));
  return ((cu + cv) & 1) ? 1.04f : 0.96f;
}

float SampleBricks(const HeightFieldParameters& p, float u, float v, std::uint8_t* albedo)
{
  const int rows = std::max(1, p.BrickRows);
  const int cols = std::max(1, p.BrickColumns);
  const float mortar = std::min(0.9f, std::max(0.f, p.MortarWidth));

  // Running bond: every other course is shifted by half a brick.
  const float by = v * static_cast<float>(rows);
  const int row = static_cast<int>(std::floor(by));
  const float bx = u * static_cast<float>(cols) + ((row & 1) ? 0.5f : 0.f);
  const int colUnwrapped = static_cast<int>(std::floor(bx));
  const int col = PositiveMod(colUnwrapped, cols); // tileable along u
  const float fx = bx - static_cast<float>(colUnwrapped);
  const float fy = by - static_cast<float>(row);

  // Distance to the brick outline in uv units (u and v joints have the same uv width).
  const float du = std::min(fx, 1.f - fx) / static_cast<float>(cols);
  const float dv = std::min(fy, 1.f - fy) / static_cast<float>(rows);
  const float edge = std::min(du, dv);
  const float halfJoint = 0.5f * mortar / static_cast<float>(rows);
  const float bevel = std::max(halfJoint, 0.02f / static_cast<float>(rows));

  // Fine surface noise, defined in uv so it is resolution independent.
  const float grain = FractalNoise(u, v, 32, 3, p.Seed ^ 0x51ed270bu);

  if (edge < halfJoint)
  {
    // Mortar: deep, grey, slightly rough.
    const float d = 0.85f + 0.08f * (grain - 0.5f);
    const float shade = 0.62f + 0.16f * grain;
    SetRGB(albedo, shade, shade * 0.98f, shade * 0.94f);
    return Clamp01(d);
  }

  // Brick: near the top with a rounded bevel towards the joints.
  const float s = SmoothStep(0.f, 1.f, (edge - halfJoint) / bevel);
  const float d = 0.45f * (1.f - s) + 0.06f * s + 0.08f * (grain - 0.5f);

  // One colour per brick (hash of its row/column), modulated by the grain.
  const std::uint32_t id = Hash3(col, PositiveMod(row, rows), p.Seed);
  const float h1 = UnitFromHash(id);
  const float h2 = UnitFromHash(HashInt(id));
  const float tone = 0.85f + 0.3f * (grain - 0.5f);
  SetRGB(
    albedo, (0.52f + 0.22f * h1) * tone, (0.22f + 0.10f * h2) * tone, (0.15f + 0.06f * h2) * tone);
  return Clamp01(d);
}

float SampleStone(const HeightFieldParameters& p, float u, float v, std::uint8_t* albedo)
{
  const int octaves = std::max(1, std::min(12, p.StoneOctaves));
  // fBm bulk (contrast stretched: fBm of value noise concentrates around 0.5)...
  const float bulk = Clamp01(0.5f + 2.2f * (FractalNoise(u, v, 4, octaves, p.Seed) - 0.5f));
  // ... plus cracks along the zero set of a second noise (ridged noise).
  const float n2 = FractalNoise(u, v, 3, 4, p.Seed ^ 0x68e31da4u);
  const float ridge = 1.f - std::fabs(2.f * n2 - 1.f);
  const float crack = SmoothStep(0.93f, 0.99f, ridge);
  const float d = Clamp01(0.08f + 0.62f * bulk + 0.3f * crack);

  if (albedo)
  {
    const float tint = FractalNoise(u, v, 8, 4, p.Seed ^ 0xb5297a4du);
    const float shade = (0.7f + 0.6f * tint) * (1.f - 0.35f * d);
    SetRGB(albedo, 0.50f * shade, 0.45f * shade, 0.39f * shade); // greyish brown
  }
  return d;
}

float SampleHemisphereTorus(float u, float v, std::uint8_t* albedo)
{
  // Hemisphere (radius Rh) and torus (ring radius Rt, tube radius rt) rising from a flat
  // base at depth 0.9. Depth units per uv unit are the same for both shapes, so with
  // DepthScale = Rh / 0.9 both profiles are true circles (hemisphere height = radius).
  constexpr float base = HemisphereTorusBaseDepth;
  constexpr float rh = 0.18f;
  constexpr float ringRadius = 0.15f;
  constexpr float tube = 0.07f;
  constexpr float depthPerUV = base / rh;

  float d = base;
  {
    const float dx = u - 0.28f;
    const float dy = v - 0.5f;
    const float rho2 = dx * dx + dy * dy;
    if (rho2 < rh * rh)
    {
      d = std::min(d, base - depthPerUV * std::sqrt(rh * rh - rho2));
    }
  }
  {
    const float dx = u - 0.72f;
    const float dy = v - 0.5f;
    const float t = std::sqrt(dx * dx + dy * dy) - ringRadius;
    if (t * t < tube * tube)
    {
      d = std::min(d, base - depthPerUV * std::sqrt(tube * tube - t * t));
    }
  }
  const float c = Checker(u, v);
  SetRGB(albedo, 0.88f * c, 0.86f * c, 0.82f * c);
  return Clamp01(d);
}
} // namespace

std::uint32_t HashInt(std::uint32_t x)
{
  // "lowbias32" integer hash (C. Wellons): good avalanche, fully deterministic.
  x ^= x >> 16;
  x *= 0x7feb352du;
  x ^= x >> 15;
  x *= 0x846ca68bu;
  x ^= x >> 16;
  return x;
}

float ValueNoise(float u, float v, int period, std::uint32_t seed)
{
  period = std::max(1, period);
  const float x = u * static_cast<float>(period);
  const float y = v * static_cast<float>(period);
  const float xf = std::floor(x);
  const float yf = std::floor(y);
  const int x0 = static_cast<int>(xf);
  const int y0 = static_cast<int>(yf);
  float tx = x - xf;
  float ty = y - yf;
  // Quintic fade: C2-continuous, so the Sobel normals of the noise are smooth.
  tx = tx * tx * tx * (tx * (tx * 6.f - 15.f) + 10.f);
  ty = ty * ty * ty * (ty * (ty * 6.f - 15.f) + 10.f);
  // Lattice indices modulo the period make the noise tile on the unit square.
  const int xa = PositiveMod(x0, period);
  const int xb = PositiveMod(x0 + 1, period);
  const int ya = PositiveMod(y0, period);
  const int yb = PositiveMod(y0 + 1, period);
  const float v00 = UnitFromHash(Hash3(xa, ya, seed));
  const float v10 = UnitFromHash(Hash3(xb, ya, seed));
  const float v01 = UnitFromHash(Hash3(xa, yb, seed));
  const float v11 = UnitFromHash(Hash3(xb, yb, seed));
  const float a = v00 + (v10 - v00) * tx;
  const float b = v01 + (v11 - v01) * tx;
  return a + (b - a) * ty;
}

float FractalNoise(float u, float v, int baseFrequency, int octaves, std::uint32_t seed)
{
  float sum = 0.f;
  float norm = 0.f;
  float amplitude = 1.f;
  int frequency = std::max(1, baseFrequency);
  for (int o = 0; o < octaves; ++o)
  {
    sum += amplitude * ValueNoise(u, v, frequency, HashInt(seed + static_cast<std::uint32_t>(o)));
    norm += amplitude;
    amplitude *= 0.5f;
    frequency *= 2;
  }
  return norm > 0.f ? sum / norm : 0.f;
}

float SampleHeightField(const HeightFieldParameters& params, float u, float v, std::uint8_t* albedo)
{
  switch (params.Pattern)
  {
    case ReliefPattern::Bricks:
      return SampleBricks(params, u, v, albedo);
    case ReliefPattern::Stone:
      return SampleStone(params, u, v, albedo);
    case ReliefPattern::HemisphereTorus:
      return SampleHemisphereTorus(u, v, albedo);
    case ReliefPattern::Flat:
    {
      const float c = Checker(u, v);
      SetRGB(albedo, 0.8f * c, 0.8f * c, 0.8f * c);
      return Clamp01(params.FlatDepth);
    }
    case ReliefPattern::SineWave:
    default:
    {
      const float fx = static_cast<float>(params.SineFrequency[0]);
      const float fy = static_cast<float>(params.SineFrequency[1]);
      const float c = Checker(u, v);
      SetRGB(albedo, 0.8f * c, 0.8f * c, 0.8f * c);
      return Clamp01(
        0.5f + 0.5f * std::sin(2.f * Pi<float> * fx * u) * std::cos(2.f * Pi<float> * fy * v));
    }
  }
}

void GenerateHeightFieldRows(const HeightFieldParameters& params, int w, int h, int rowBegin,
  int rowEnd, float* depth, std::uint8_t* albedo)
{
  if (w <= 0 || h <= 0 || (!depth && !albedo))
  {
    return;
  }
  rowBegin = std::max(0, rowBegin);
  rowEnd = std::min(h, rowEnd);
  for (int j = rowBegin; j < rowEnd; ++j)
  {
    const float v = (static_cast<float>(j) + 0.5f) / static_cast<float>(h);
    const std::size_t row = static_cast<std::size_t>(j) * static_cast<std::size_t>(w);
    for (int i = 0; i < w; ++i)
    {
      const float u = (static_cast<float>(i) + 0.5f) / static_cast<float>(w);
      const std::size_t k = row + static_cast<std::size_t>(i);
      const float d = SampleHeightField(params, u, v, albedo ? albedo + 3 * k : nullptr);
      if (depth)
      {
        depth[k] = d;
      }
    }
  }
}

void GenerateHeightField(
  const HeightFieldParameters& params, int w, int h, float* depth, std::uint8_t* albedo)
{
  GenerateHeightFieldRows(params, w, h, 0, h, depth, albedo);
}

} // namespace mesolight
