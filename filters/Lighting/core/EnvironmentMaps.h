// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file EnvironmentMaps.h
 * @brief Lat-long environment maps: directions, solid angles, exact irradiance, SH9,
 *        light-probe converters (plain C++17, no VTK types).
 *
 * Reference: Méndez Fernández's thesis §5 (light probes, median cut). The thesis maps
 * image rows to the polar angle with pi/2 and does not weight pixels by solid angle; both
 * are corrected here. docs/environment-maps.md has a picture of the conventions.
 *
 * CONVENTIONS
 *  - A lat-long (equirectangular) map is W x H RGB floats, W = 2H expected. Images are in
 *    VTK row order: row j = 0 is the BOTTOM of the picture (the nadir); in FILE order the
 *    top row is the zenith (vtkOIIOImageReader flips rows).
 *  - Map coordinates: u in [0,1] left to right along a row; v in [0,1] with v = 0 at the
 *    TOP row. Pixel (i, j) has its centre at u = (i + 0.5) / W, v = 1 - (j + 0.5) / H.
 *  - Directions: +Z is up. Polar angle theta = pi v (from +Z), azimuth phi = 2 pi u, phi = 0
 *    toward +X and increasing toward +Y: d = (sin theta cos phi, sin theta sin phi, cos theta).
 *  - Pixel solid angle: the exact band integral (2 pi / W) (cos theta0 - cos theta1) over the
 *    pixel's polar range [theta0, theta1]; the W H pixels sum to 4 pi.
 *  - Luminance Y = 0.2126 R + 0.7152 G + 0.0722 B (common/Luminance.h; the thesis' eq. 11 prints
 *    them rounded as 0.2125, 0.7154, 0.0721).
 *  - RGB values are radiance; an irradiance is sum L max(0, n.d) dOmega.
 */
#ifndef mesolight_EnvironmentMaps_h
#define mesolight_EnvironmentMaps_h

#include "MesolightLightingModule.h" // for the export macro only

#include "Luminance.h" // Y of the energy the cuts balance
#include "MathConstants.h"
#include "RgbImage.h"

#include <array>
#include <cstddef>
#include <vector>

namespace mesolight
{

/// Unit direction of map coordinates (u, v) (v = 0 top = zenith).
MESOLIGHTLIGHTING_EXPORT void DirectionFromMapUV(double u, double v, double d[3]);

/// Map coordinates of a direction (need not be unit); u in [0,1), v in [0,1].
MESOLIGHTLIGHTING_EXPORT void MapUVFromDirection(const double d[3], double& u, double& v);

/// Map coordinates of the centre of pixel (i, j) in VTK row order.
inline double PixelCenterU(int i, int width)
{
  return (i + 0.5) / width;
}
inline double PixelCenterV(int j, int height)
{
  return 1.0 - (j + 0.5) / height;
}

/// Exact solid angle of a pixel of row j (VTK row order) of a W x H lat-long map.
MESOLIGHTLIGHTING_EXPORT double PixelSolidAngle(int j, int width, int height);

/**
 * Exact integral of the direction d over pixel (i, j) (VTK row order): the pixel's
 * "moment" m = integral of d dOmega; |m| <= dOmega, and n.m is the pixel's exact cosine-
 * weighted solid angle for any n with n.d >= 0 over the whole pixel.
 */
MESOLIGHTLIGHTING_EXPORT void PixelMoment(int i, int j, int width, int height, double m[3]);

/**
 * Exact numerical irradiance of a lat-long map: E(n) = sum over pixels of
 * L max(0, n.m_pixel), m_pixel the pixel moment (PixelMoment), in double precision. Exact
 * for pixels entirely above the horizon of n; a pixel straddling it counts its clamped
 * centre-ish value. The tables are computed once; Evaluate() is thread-safe.
 */
class MESOLIGHTLIGHTING_EXPORT ExactIrradiance
{
public:
  explicit ExactIrradiance(const RgbImage& map);
  /// E(n) for a unit normal n, RGB.
  void Evaluate(const double n[3], double e[3]) const;

private:
  int Width;
  int Height;
  std::vector<double> Radiance;   // 3 W H, VTK row order
  std::vector<double> RowZ, RowS; // per row: z moment / Dphi, sin^2 integral
  std::vector<double> ColC, ColS; // per column: sin phi1 - sin phi0, cos phi0 - cos phi1
  double DeltaPhi = 0.0;
};

/**
 * Spherical harmonics irradiance (Ramamoorthi & Hanrahan 2001): the 9 real SH coefficients
 * L_lm (order: Y00, Y1-1, Y10, Y11, Y2-2, Y2-1, Y20, Y21, Y22; real SH with
 * Y1-1 = 0.488603 y, Y10 = 0.488603 z, Y11 = 0.488603 x, ...), RGB, projected with exact
 * pixel solid angles at the pixel centre directions.
 */
struct SH9
{
  std::array<std::array<double, 3>, 9> L{};
};
MESOLIGHTLIGHTING_EXPORT SH9 ProjectSH9(const RgbImage& map);
/// The 9 real SH basis functions at a unit direction d, in the order of SH9.
MESOLIGHTLIGHTING_EXPORT void EvaluateSHBasis(const double d[3], double y[9]);
/// E(n) = sum_lm A_l L_lm Y_lm(n), A0 = pi, A1 = 2 pi / 3, A2 = pi / 4.
MESOLIGHTLIGHTING_EXPORT void IrradianceSH9(const SH9& sh, const double n[3], double e[3]);

/**
 * Bilinear sample at continuous pixel coordinates (x, y), pixel (i, j) covering
 * [i, i+1) x [j, j+1) with its centre at (i + 0.5, j + 0.5). wrapX: periodic in x (lat-long
 * maps); otherwise clamped. y is always clamped.
 */
MESOLIGHTLIGHTING_EXPORT void SampleBilinear(
  const RgbImage& image, double x, double y, bool wrapX, float out[3]);

/// Lat-long -> lat-long of another size, bilinear (wrapping in u), with samples^2
/// supersamples per output pixel.
MESOLIGHTLIGHTING_EXPORT RgbImage ResampleLatLong(
  const RgbImage& map, int width, int height, int samples = 2);

/**
 * The camera frame of a light-probe picture (angular map or mirror ball). Forward is the
 * direction the camera looks in, Up the picture's up direction (made orthogonal to
 * Forward); the picture's right is Forward x Up. Defaults: looking toward +X, up +Z.
 * Picture coordinates a, b in [-1,1] run left->right and bottom->top over the square image
 * (a = 2 (i + 0.5) / S - 1, b = 2 (j + 0.5) / S - 1, VTK row order).
 */
struct ProbeView
{
  double Forward[3] = { 1.0, 0.0, 0.0 };
  double Up[3] = { 0.0, 0.0, 1.0 };
};

/**
 * Angular map (Debevec's "light probe" format): with z_view = -Forward, a picture point at
 * radius r = sqrt(a^2 + b^2) <= 1 shows the direction at angle pi r from Forward:
 * r = (1/pi) acos(-d.z_view) = (1/pi) acos(d.Forward), along the picture direction (a, b)/r.
 * The centre is Forward, the rim (r = 1) is -Forward.
 */
MESOLIGHTLIGHTING_EXPORT void AngularMapPointFromDirection(
  const ProbeView& view, const double d[3], double& a, double& b);
MESOLIGHTLIGHTING_EXPORT bool DirectionFromAngularMapPoint(
  const ProbeView& view, double a, double b, double d[3]);

/**
 * Mirror ball: a mirrored sphere filling the square picture, seen orthographically by a
 * camera looking along Forward (i.e. from -Forward). The sphere normal at picture point
 * (a, b) is n = a right + b up - sqrt(1 - a^2 - b^2) Forward and the point reflects the
 * direction d = I - 2 (n.I) n with I = Forward: the centre shows -Forward (behind the
 * camera, where the camera itself appears), the rim shows Forward. Inverse: n is the unit
 * half vector of d and -Forward.
 */
MESOLIGHTLIGHTING_EXPORT void MirrorBallPointFromDirection(
  const ProbeView& view, const double d[3], double& a, double& b);
MESOLIGHTLIGHTING_EXPORT bool DirectionFromMirrorBallPoint(
  const ProbeView& view, double a, double b, double d[3]);

/// Angular map (square) -> lat-long W x H, bilinear, samples^2 supersamples per pixel.
MESOLIGHTLIGHTING_EXPORT RgbImage AngularMapToLatLong(
  const RgbImage& probe, const ProbeView& view, int width, int height, int samples = 2);
/// Mirror ball (square) -> lat-long W x H, bilinear, samples^2 supersamples per pixel.
MESOLIGHTLIGHTING_EXPORT RgbImage MirrorBallToLatLong(
  const RgbImage& ball, const ProbeView& view, int width, int height, int samples = 2);
/// Lat-long -> angular map S x S (for tests and round trips); outside the disc is black.
MESOLIGHTLIGHTING_EXPORT RgbImage LatLongToAngularMap(
  const RgbImage& map, const ProbeView& view, int size);
/// Lat-long -> mirror ball S x S; outside the disc is black.
MESOLIGHTLIGHTING_EXPORT RgbImage LatLongToMirrorBall(
  const RgbImage& map, const ProbeView& view, int size);

/**
 * Two-view merge (thesis Sec. 5.2.1, HDRShop's "Calculate"): A C + B (1 - C) per pixel,
 * C the mask (one value per pixel, 0 = take B, 1 = take A, clamped to [0,1]). All three
 * must have the same size; returns an empty image otherwise.
 */
MESOLIGHTLIGHTING_EXPORT RgbImage MergeWithMask(
  const RgbImage& a, const RgbImage& b, const std::vector<float>& mask);

} // namespace mesolight

#endif
