// SPDX-License-Identifier: BSD-3-Clause
#include "EnvironmentMaps.h"

#include "MathConstants.h"
#include "ParallelFor.h"

#include <algorithm>
#include <cmath>

namespace mesolight
{

namespace
{

double Dot(const double a[3], const double b[3])
{
  return a[0] * b[0] + a[1] * b[1] + a[2] * b[2];
}

void Normalize(double v[3])
{
  const double len = std::sqrt(Dot(v, v));
  if (len > 0.0)
  {
    v[0] /= len;
    v[1] /= len;
    v[2] /= len;
  }
}

/// Orthonormal frame (Forward, Right, Up) of a probe view.
struct Frame
{
  double F[3];
  double R[3];
  double U[3];
};

Frame MakeFrame(const ProbeView& view)
{
  Frame f;
  for (int k = 0; k < 3; ++k)
  {
    f.F[k] = view.Forward[k];
    f.U[k] = view.Up[k];
  }
  Normalize(f.F);
  const double along = Dot(f.U, f.F);
  for (int k = 0; k < 3; ++k)
  {
    f.U[k] -= along * f.F[k];
  }
  Normalize(f.U);
  // Right = Forward x Up.
  f.R[0] = f.F[1] * f.U[2] - f.F[2] * f.U[1];
  f.R[1] = f.F[2] * f.U[0] - f.F[0] * f.U[2];
  f.R[2] = f.F[0] * f.U[1] - f.F[1] * f.U[0];
  return f;
}

/// Polar range [theta0, theta1] of row j (VTK row order: row H-1 is the top).
void RowThetaRange(int j, int height, double& theta0, double& theta1)
{
  const int fromTop = height - 1 - j;
  theta0 = Pi<double> * fromTop / height;
  theta1 = Pi<double> * (fromTop + 1) / height;
}

/// Fills a W x H image, each pixel the average of samples x samples sub-pixel evaluations of
/// sample(fx, fy, rgb), with fx, fy the sub-pixel position in [0,1] over the image (VTK row order).
template <typename Sample>
RgbImage Supersample(int width, int height, int samples, Sample sample)
{
  RgbImage out(std::max(0, width), std::max(0, height));
  samples = std::max(1, samples);
  const double inv = 1.0 / (samples * samples);
  // Rows are independent (each pixel written once): the same image however they are split.
  ParallelFor(0, static_cast<std::size_t>(std::max(0, height)), 1,
    [&](std::size_t rowBegin, std::size_t rowEnd)
    {
      for (int j = static_cast<int>(rowBegin); j < static_cast<int>(rowEnd); ++j)
      {
        for (int i = 0; i < width; ++i)
        {
          double sum[3] = { 0.0, 0.0, 0.0 };
          for (int sj = 0; sj < samples; ++sj)
          {
            for (int si = 0; si < samples; ++si)
            {
              float c[3];
              sample((i + (si + 0.5) / samples) / width, (j + (sj + 0.5) / samples) / height, c);
              for (int k = 0; k < 3; ++k)
              {
                sum[k] += c[k];
              }
            }
          }
          float* p = out.Pixel(i, j);
          for (int k = 0; k < 3; ++k)
          {
            p[k] = static_cast<float>(sum[k] * inv);
          }
        }
      }
    });
  return out;
}

/// Resample a square probe picture into a lat-long map with the given inverse mapping.
template <typename PointFromDirection>
RgbImage ProbeToLatLong(
  const RgbImage& probe, int width, int height, int samples, PointFromDirection pointFromDirection)
{
  if (probe.Width < 1 || probe.Height < 1 || width < 1 || height < 1)
  {
    return RgbImage(std::max(0, width), std::max(0, height));
  }
  return Supersample(width, height, samples,
    [&](double fx, double fy, float c[3])
    {
      double d[3];
      DirectionFromMapUV(fx, 1.0 - fy, d); // v = 0 at the top row
      double a = 0.0;
      double b = 0.0;
      pointFromDirection(d, a, b);
      SampleBilinear(
        probe, (a + 1.0) * 0.5 * probe.Width, (b + 1.0) * 0.5 * probe.Height, false, c);
    });
}

/// Lat-long -> square probe picture with the given forward mapping (nearest-free: bilinear).
template <typename DirectionFromPoint>
RgbImage LatLongToProbe(const RgbImage& map, int size, DirectionFromPoint directionFromPoint)
{
  RgbImage out(size, size);
  if (map.Width < 1 || map.Height < 1 || size < 1)
  {
    return out;
  }
  for (int j = 0; j < size; ++j)
  {
    for (int i = 0; i < size; ++i)
    {
      const double a = 2.0 * (i + 0.5) / size - 1.0;
      const double b = 2.0 * (j + 0.5) / size - 1.0;
      double d[3];
      if (!directionFromPoint(a, b, d))
      {
        continue;
      }
      double u = 0.0;
      double v = 0.0;
      MapUVFromDirection(d, u, v);
      SampleBilinear(map, u * map.Width, (1.0 - v) * map.Height, true, out.Pixel(i, j));
    }
  }
  return out;
}
} // namespace

//------------------------------------------------------------------------------
void DirectionFromMapUV(double u, double v, double d[3])
{
  const double theta = Pi<double> * v;
  const double phi = 2.0 * Pi<double> * u;
  const double s = std::sin(theta);
  d[0] = s * std::cos(phi);
  d[1] = s * std::sin(phi);
  d[2] = std::cos(theta);
}

//------------------------------------------------------------------------------
void MapUVFromDirection(const double d[3], double& u, double& v)
{
  const double len = std::sqrt(Dot(d, d));
  if (!(len > 0.0))
  {
    u = 0.0;
    v = 0.0;
    return;
  }
  const double z = std::max(-1.0, std::min(1.0, d[2] / len));
  v = std::acos(z) / Pi<double>;
  double phi = std::atan2(d[1], d[0]);
  if (phi < 0.0)
  {
    phi += 2.0 * Pi<double>;
  }
  u = phi / (2.0 * Pi<double>);
  if (u >= 1.0)
  {
    u = 0.0;
  }
}

//------------------------------------------------------------------------------
double PixelSolidAngle(int j, int width, int height)
{
  double theta0 = 0.0;
  double theta1 = 0.0;
  RowThetaRange(j, height, theta0, theta1);
  return (2.0 * Pi<double> / width) * (std::cos(theta0) - std::cos(theta1));
}

//------------------------------------------------------------------------------
void PixelMoment(int i, int j, int width, int height, double m[3])
{
  double theta0 = 0.0;
  double theta1 = 0.0;
  RowThetaRange(j, height, theta0, theta1);
  const double phi0 = 2.0 * Pi<double> * i / width;
  const double phi1 = 2.0 * Pi<double> * (i + 1) / width;
  // integral of sin^2 theta d theta, and of cos theta sin theta d theta.
  const double sin2 =
    0.5 * (theta1 - theta0) - 0.25 * (std::sin(2.0 * theta1) - std::sin(2.0 * theta0));
  const double s0 = std::sin(theta0);
  const double s1 = std::sin(theta1);
  const double sincos = 0.5 * (s1 * s1 - s0 * s0);
  m[0] = sin2 * (std::sin(phi1) - std::sin(phi0));
  m[1] = sin2 * (std::cos(phi0) - std::cos(phi1));
  m[2] = sincos * (phi1 - phi0);
}

//------------------------------------------------------------------------------
ExactIrradiance::ExactIrradiance(const RgbImage& map)
  : Width(map.Width)
  , Height(map.Height)
{
  this->Radiance.assign(map.Rgb.begin(), map.Rgb.end());
  this->RowZ.resize(static_cast<size_t>(std::max(0, this->Height)));
  this->RowS.resize(static_cast<size_t>(std::max(0, this->Height)));
  this->ColC.resize(static_cast<size_t>(std::max(0, this->Width)));
  this->ColS.resize(static_cast<size_t>(std::max(0, this->Width)));
  if (this->Width < 1 || this->Height < 1)
  {
    return;
  }
  this->DeltaPhi = 2.0 * Pi<double> / this->Width;
  for (int j = 0; j < this->Height; ++j)
  {
    double m[3];
    PixelMoment(0, j, this->Width, this->Height, m);
    this->RowZ[j] = m[2];
    double theta0 = 0.0;
    double theta1 = 0.0;
    RowThetaRange(j, this->Height, theta0, theta1);
    this->RowS[j] =
      0.5 * (theta1 - theta0) - 0.25 * (std::sin(2.0 * theta1) - std::sin(2.0 * theta0));
  }
  for (int i = 0; i < this->Width; ++i)
  {
    const double phi0 = this->DeltaPhi * i;
    const double phi1 = this->DeltaPhi * (i + 1);
    this->ColC[i] = std::sin(phi1) - std::sin(phi0);
    this->ColS[i] = std::cos(phi0) - std::cos(phi1);
  }
}

//------------------------------------------------------------------------------
void ExactIrradiance::Evaluate(const double n[3], double e[3]) const
{
  e[0] = e[1] = e[2] = 0.0;
  const int w = this->Width;
  std::vector<double> a(static_cast<size_t>(std::max(0, w)));
  for (int i = 0; i < w; ++i)
  {
    a[i] = n[0] * this->ColC[i] + n[1] * this->ColS[i];
  }
  for (int j = 0; j < this->Height; ++j)
  {
    const double z = n[2] * this->RowZ[j];
    const double s = this->RowS[j];
    const double* l = this->Radiance.data() + 3 * static_cast<size_t>(j) * w;
    double r = 0.0;
    double g = 0.0;
    double b = 0.0;
    for (int i = 0; i < w; ++i)
    {
      const double c = z + s * a[i];
      if (c > 0.0)
      {
        r += c * l[3 * i];
        g += c * l[3 * i + 1];
        b += c * l[3 * i + 2];
      }
    }
    e[0] += r;
    e[1] += g;
    e[2] += b;
  }
}

//------------------------------------------------------------------------------
void EvaluateSHBasis(const double d[3], double y[9])
{
  const double x = d[0];
  const double yy = d[1];
  const double z = d[2];
  y[0] = 0.282095;
  y[1] = 0.488603 * yy;
  y[2] = 0.488603 * z;
  y[3] = 0.488603 * x;
  y[4] = 1.092548 * x * yy;
  y[5] = 1.092548 * yy * z;
  y[6] = 0.315392 * (3.0 * z * z - 1.0);
  y[7] = 1.092548 * x * z;
  y[8] = 0.546274 * (x * x - yy * yy);
}

SH9 ProjectSH9(const RgbImage& map)
{
  SH9 sh;
  for (int j = 0; j < map.Height; ++j)
  {
    const double dOmega = PixelSolidAngle(j, map.Width, map.Height);
    const double v = PixelCenterV(j, map.Height);
    for (int i = 0; i < map.Width; ++i)
    {
      double d[3];
      DirectionFromMapUV(PixelCenterU(i, map.Width), v, d);
      double y[9];
      EvaluateSHBasis(d, y);
      const float* l = map.Pixel(i, j);
      for (int k = 0; k < 9; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          sh.L[k][c] += l[c] * y[k] * dOmega;
        }
      }
    }
  }
  return sh;
}

void IrradianceSH9(const SH9& sh, const double n[3], double e[3])
{
  static const double A[9] = { Pi<double>, 2.0 * Pi<double> / 3.0, 2.0 * Pi<double> / 3.0,
    2.0 * Pi<double> / 3.0, Pi<double> / 4.0, Pi<double> / 4.0, Pi<double> / 4.0, Pi<double> / 4.0,
    Pi<double> / 4.0 };
  double y[9];
  EvaluateSHBasis(n, y);
  e[0] = e[1] = e[2] = 0.0;
  for (int k = 0; k < 9; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      e[c] += A[k] * sh.L[k][c] * y[k];
    }
  }
}

//------------------------------------------------------------------------------
void SampleBilinear(const RgbImage& image, double x, double y, bool wrapX, float out[3])
{
  out[0] = out[1] = out[2] = 0.0f;
  const int w = image.Width;
  const int h = image.Height;
  if (w < 1 || h < 1 || !std::isfinite(x) || !std::isfinite(y))
  {
    return;
  }
  const double fx = x - 0.5;
  const double fy = y - 0.5;
  const double x0f = std::floor(fx);
  const double y0f = std::floor(fy);
  const double tx = fx - x0f;
  const double ty = fy - y0f;
  auto column = [&](long long i) -> int
  {
    if (wrapX)
    {
      long long m = i % w;
      return static_cast<int>(m < 0 ? m + w : m);
    }
    return static_cast<int>(std::max(0LL, std::min<long long>(w - 1, i)));
  };
  auto row = [&](long long j) -> int
  { return static_cast<int>(std::max(0LL, std::min<long long>(h - 1, j))); };
  const long long xi = static_cast<long long>(x0f);
  const long long yi = static_cast<long long>(y0f);
  const int i0 = column(xi);
  const int i1 = column(xi + 1);
  const int j0 = row(yi);
  const int j1 = row(yi + 1);
  const float* p00 = image.Pixel(i0, j0);
  const float* p10 = image.Pixel(i1, j0);
  const float* p01 = image.Pixel(i0, j1);
  const float* p11 = image.Pixel(i1, j1);
  for (int c = 0; c < 3; ++c)
  {
    const double bottom = p00[c] + tx * (p10[c] - p00[c]);
    const double top = p01[c] + tx * (p11[c] - p01[c]);
    out[c] = static_cast<float>(bottom + ty * (top - bottom));
  }
}

//------------------------------------------------------------------------------
RgbImage ResampleLatLong(const RgbImage& map, int width, int height, int samples)
{
  if (map.Width < 1 || map.Height < 1 || width < 1 || height < 1)
  {
    return RgbImage(std::max(0, width), std::max(0, height));
  }
  return Supersample(width, height, samples,
    [&](double fx, double fy, float c[3])
    { SampleBilinear(map, fx * map.Width, fy * map.Height, true, c); });
}

//------------------------------------------------------------------------------
void AngularMapPointFromDirection(const ProbeView& view, const double d[3], double& a, double& b)
{
  const Frame f = MakeFrame(view);
  double n[3] = { d[0], d[1], d[2] };
  Normalize(n);
  const double cf = std::max(-1.0, std::min(1.0, Dot(n, f.F)));
  const double r = std::acos(cf) / Pi<double>;
  const double x = Dot(n, f.R);
  const double y = Dot(n, f.U);
  const double s = std::sqrt(x * x + y * y);
  if (s <= 0.0)
  {
    a = cf < 0.0 ? r : 0.0; // straight back: any point of the rim; pick (1, 0)
    b = 0.0;
    return;
  }
  a = r * x / s;
  b = r * y / s;
}

bool DirectionFromAngularMapPoint(const ProbeView& view, double a, double b, double d[3])
{
  const double r = std::sqrt(a * a + b * b);
  if (r > 1.0)
  {
    return false;
  }
  const Frame f = MakeFrame(view);
  const double angle = Pi<double> * r;
  const double c = std::cos(angle);
  const double s = r > 0.0 ? std::sin(angle) / r : 0.0;
  for (int k = 0; k < 3; ++k)
  {
    d[k] = c * f.F[k] + s * (a * f.R[k] + b * f.U[k]);
  }
  Normalize(d);
  return true;
}

void MirrorBallPointFromDirection(const ProbeView& view, const double d[3], double& a, double& b)
{
  const Frame f = MakeFrame(view);
  double n[3] = { d[0], d[1], d[2] };
  Normalize(n);
  double h[3] = { n[0] - f.F[0], n[1] - f.F[1], n[2] - f.F[2] };
  const double len = std::sqrt(Dot(h, h));
  if (len <= 1e-12)
  {
    a = 1.0; // d == Forward: the whole rim; pick (1, 0)
    b = 0.0;
    return;
  }
  for (double& c : h)
  {
    c /= len;
  }
  a = Dot(h, f.R);
  b = Dot(h, f.U);
}

bool DirectionFromMirrorBallPoint(const ProbeView& view, double a, double b, double d[3])
{
  const double rr = a * a + b * b;
  if (rr > 1.0)
  {
    return false;
  }
  const Frame f = MakeFrame(view);
  const double nz = std::sqrt(std::max(0.0, 1.0 - rr));
  double n[3];
  for (int k = 0; k < 3; ++k)
  {
    n[k] = a * f.R[k] + b * f.U[k] - nz * f.F[k];
  }
  const double ni = Dot(n, f.F);
  for (int k = 0; k < 3; ++k)
  {
    d[k] = f.F[k] - 2.0 * ni * n[k];
  }
  Normalize(d);
  return true;
}

//------------------------------------------------------------------------------
RgbImage AngularMapToLatLong(
  const RgbImage& probe, const ProbeView& view, int width, int height, int samples)
{
  return ProbeToLatLong(probe, width, height, samples,
    [&](const double d[3], double& a, double& b) { AngularMapPointFromDirection(view, d, a, b); });
}

RgbImage MirrorBallToLatLong(
  const RgbImage& ball, const ProbeView& view, int width, int height, int samples)
{
  return ProbeToLatLong(ball, width, height, samples,
    [&](const double d[3], double& a, double& b) { MirrorBallPointFromDirection(view, d, a, b); });
}

RgbImage LatLongToAngularMap(const RgbImage& map, const ProbeView& view, int size)
{
  return LatLongToProbe(map, size,
    [&](double a, double b, double d[3]) { return DirectionFromAngularMapPoint(view, a, b, d); });
}

RgbImage LatLongToMirrorBall(const RgbImage& map, const ProbeView& view, int size)
{
  return LatLongToProbe(map, size,
    [&](double a, double b, double d[3]) { return DirectionFromMirrorBallPoint(view, a, b, d); });
}

//------------------------------------------------------------------------------
RgbImage MergeWithMask(const RgbImage& a, const RgbImage& b, const std::vector<float>& mask)
{
  const size_t n = static_cast<size_t>(a.Width) * static_cast<size_t>(a.Height);
  if (a.Width != b.Width || a.Height != b.Height || mask.size() != n || a.Rgb.size() != 3 * n ||
    b.Rgb.size() != 3 * n)
  {
    return RgbImage();
  }
  RgbImage out(a.Width, a.Height);
  for (size_t k = 0; k < n; ++k)
  {
    const float c = std::max(0.0f, std::min(1.0f, mask[k]));
    for (int ch = 0; ch < 3; ++ch)
    {
      out.Rgb[3 * k + ch] = a.Rgb[3 * k + ch] * c + b.Rgb[3 * k + ch] * (1.0f - c);
    }
  }
  return out;
}

} // namespace mesolight
