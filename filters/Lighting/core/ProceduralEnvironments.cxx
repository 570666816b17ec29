// SPDX-License-Identifier: BSD-3-Clause
#include "ProceduralEnvironments.h"

#include "MathConstants.h"

#include <algorithm>
#include <cmath>

namespace mesolight
{

namespace
{
constexpr double Deg = Pi<double> / 180.0;

void SkyRadiance(const SkyParameters& p, double elevation, double out[3])
{
  const double s = std::sin(std::max(0.0, elevation));
  const double t = std::sqrt(s);
  double sky[3];
  double ground[3];
  const double g = 0.6 + 0.4 * std::cos(std::min(0.0, elevation));
  for (int c = 0; c < 3; ++c)
  {
    sky[c] = p.Horizon[c] + (p.Zenith[c] - p.Horizon[c]) * t;
    ground[c] = p.Ground[c] * g;
  }
  const double blend = std::max(1e-9, p.HorizonBlend * Deg);
  const double a = std::min(1.0, std::max(0.0, 0.5 + 0.5 * elevation / blend));
  for (int c = 0; c < 3; ++c)
  {
    out[c] = a * sky[c] + (1.0 - a) * ground[c];
  }
}

/// Length of the overlap of [a0, a1] and [b0, b1].
double Overlap(double a0, double a1, double b0, double b1)
{
  return std::max(0.0, std::min(a1, b1) - std::max(a0, b0));
}
} // namespace

RgbImage MakeSkyMap(int width, int height, const SkyParameters& p)
{
  RgbImage map(std::max(0, width), std::max(0, height));
  if (width < 1 || height < 1)
  {
    return map;
  }
  double sunDir[3];
  DirectionFromMapUV(p.SunAzimuth / 360.0, 0.5 - p.SunElevation / 180.0, sunDir);
  const double sunRadius = 0.5 * p.SunDiameter * Deg;
  const double cosSun = std::cos(sunRadius);
  // A pixel may touch the disc if its centre is within the radius + a pixel diagonal.
  const double pixelAngle = std::max(2.0 * Pi<double> / width, Pi<double> / height) * 1.5;
  const double cosNear = std::cos(std::min(Pi<double>, sunRadius + pixelAngle));
  // Window rectangle in map coordinates (u may wrap).
  const double wu0 = (p.WindowAzimuth - 0.5 * p.WindowWidth) / 360.0;
  const double wu1 = (p.WindowAzimuth + 0.5 * p.WindowWidth) / 360.0;
  const double wv0 = 0.5 - (p.WindowElevation + 0.5 * p.WindowHeight) / 180.0;
  const double wv1 = 0.5 - (p.WindowElevation - 0.5 * p.WindowHeight) / 180.0;
  constexpr int SunSamples = 8;
  for (int j = 0; j < height; ++j)
  {
    const double v = PixelCenterV(j, height);
    const double elevation = 0.5 * Pi<double> - Pi<double> * v;
    double sky[3];
    SkyRadiance(p, elevation, sky);
    const double pv0 = 1.0 - (j + 1.0) / height;
    const double pv1 = 1.0 - static_cast<double>(j) / height;
    for (int i = 0; i < width; ++i)
    {
      double l[3] = { sky[0], sky[1], sky[2] };
      if (p.Window)
      {
        const double pu0 = static_cast<double>(i) / width;
        const double pu1 = (i + 1.0) / width;
        double cu = 0.0;
        for (int shift = -1; shift <= 1; ++shift)
        {
          cu += Overlap(pu0, pu1, wu0 + shift, wu1 + shift);
        }
        const double coverage =
          std::min(1.0, cu * width) * std::min(1.0, Overlap(pv0, pv1, wv0, wv1) * height);
        for (int c = 0; c < 3; ++c)
        {
          l[c] += coverage * (p.WindowRadiance * p.WindowColor[c] - l[c]);
        }
      }
      if (p.Sun && sunRadius > 0.0)
      {
        double d[3];
        DirectionFromMapUV(PixelCenterU(i, width), v, d);
        const double cosCentre = d[0] * sunDir[0] + d[1] * sunDir[1] + d[2] * sunDir[2];
        if (cosCentre >= cosNear)
        {
          int inside = 0;
          for (int sj = 0; sj < SunSamples; ++sj)
          {
            for (int si = 0; si < SunSamples; ++si)
            {
              double s[3];
              DirectionFromMapUV((i + (si + 0.5) / SunSamples) / width,
                1.0 - (j + (sj + 0.5) / SunSamples) / height, s);
              if (s[0] * sunDir[0] + s[1] * sunDir[1] + s[2] * sunDir[2] >= cosSun)
              {
                ++inside;
              }
            }
          }
          const double coverage = static_cast<double>(inside) / (SunSamples * SunSamples);
          for (int c = 0; c < 3; ++c)
          {
            l[c] += coverage * p.SunIntensity * p.SunColor[c];
          }
        }
      }
      float* out = map.Pixel(i, j);
      for (int c = 0; c < 3; ++c)
      {
        out[c] = static_cast<float>(l[c]);
      }
    }
  }
  return map;
}

} // namespace mesolight
