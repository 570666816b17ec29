// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MedianCut.h
 * @brief Median cut light-probe sampling (Debevec 2005) with solid-angle weighting and
 *        optional variance-minimizing cuts (Viriyothai & Debevec 2009). Plain C++17.
 *
 * Map conventions: core/EnvironmentMaps.h (lat-long, VTK row order with row 0 = bottom,
 * v = 0 at the top row, +Z up, theta = pi v, phi = 2 pi u from +X toward +Y).
 *
 * Algorithm:
 *  1. Energy per pixel e = Y(max(0, RGB)) dOmega, Y = 0.2126 R + 0.7152 G + 0.0722 B and
 *     dOmega the exact pixel solid angle. Summed-area tables are DOUBLE precision (float
 *     SATs over HDR maps lose the small regions' energy).
 *  2. Start with the whole map as one region; repeatedly take the region with the most
 *     energy (plain) or the largest energy-weighted angular variance (VarianceMinimization)
 *     from a priority queue and cut it in two, until there are NumberOfLights regions (any
 *     count >= 1, not only powers of two). Regions of one pixel (cell) are never cut.
 *  3. Plain cuts: along the region's longer side measured in angle (the width is scaled by
 *     sin(theta) = cos(latitude) at the region's centre), at the column/row that splits the
 *     energy most evenly (binary search on the SAT).
 *     Variance-minimizing cuts: among all columns and rows of the region, the cut that
 *     minimizes the sum of the two halves' energy-weighted angular variances
 *     sum e |p - p_mean|^2, p = (phi sin(theta_centre), theta) (SATs of e, e x, e x^2, e y,
 *     e y^2). They cut on a grid of cells of k x k pixels, k the largest that keeps at least
 *     1024 x 512 cells and 16 cells per light (k = 1 up to 2047 pixels wide, 4 at 4096 x
 *     2048): the five tables at full resolution cost 4.5x the plain cut's time there, and
 *     the lights (step 4) are still integrated over the pixels.
 *  4. One light per region, at the region's energy centroid on the sphere: the direction of
 *     sum Y m_pixel (m the exact pixel moment, core/EnvironmentMaps.h PixelMoment); its
 *     colour is sum L dOmega over the region (RGB): the irradiance it delivers at normal
 *     incidence. The lights' colours sum to the map's total sum L dOmega.
 */
#ifndef mesolight_MedianCut_h
#define mesolight_MedianCut_h

#include "MesolightLightingModule.h" // for the export macro only

#include "Progress.h"

#include <functional>
#include <stdexcept>
#include <string>
#include <vector>

namespace mesolight
{

struct MedianCutOptions
{
  int NumberOfLights = 64;
  /// Variance-minimizing cuts and variance-ordered splitting (Viriyothai & Debevec 2009); the
  /// default, as it keeps the irradiance error of real maps under 1% at 64 lights (plain
  /// cuts: up to 2.1%). False: even-energy cuts of the most energetic region (Debevec 2005).
  bool VarianceMinimization = true;
  /**
   * Test/benchmark switch: false reproduces the thesis' unweighted variant, where every
   * pixel counts as the same solid angle 4 pi / (W H) (energies, colours and centroids).
   * It is wrong (lights crowd toward the poles) and exists to show that it is.
   */
  bool SolidAngleWeighting = true;
  /// Called with the fraction done in [0,1]; return false to abort (Progress.h).
  ProgressCallback Progress;
};

struct MedianCutLight
{
  double U = 0.0; ///< map coordinates of the light direction (v = 0 top row)
  double V = 0.0;
  double Direction[3] = { 0.0, 0.0, 1.0 }; ///< unit direction toward the light
  double Rgb[3] = { 0.0, 0.0, 0.0 };       ///< sum of L dOmega over the region
  double Energy = 0.0;                     ///< sum of Y dOmega over the region
  double SolidAngle = 0.0;                 ///< of the region, sr
  /// Region in pixels: columns [Column0, Column1), rows [Row0, Row1) counted from the TOP.
  int Column0 = 0;
  int Column1 = 0;
  int Row0 = 0;
  int Row1 = 0;
  /// Region in map coordinates: u in [U0, U1], v in [V0, V1] (v = 0 top).
  double U0 = 0.0;
  double U1 = 0.0;
  double V0 = 0.0;
  double V1 = 0.0;
};

/** Bad input for the median cut; what() is one sentence for the user. */
class MESOLIGHTLIGHTING_EXPORT MedianCutError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/** Thrown when MedianCutOptions::Progress returned false: not an error, the caller stops. */
class MESOLIGHTLIGHTING_EXPORT MedianCutAbortedError : public std::runtime_error
{
public:
  MedianCutAbortedError()
    : std::runtime_error("median cut aborted")
  {
  }
};

/**
 * Median cut of a lat-long map.
 *
 * @param pixels     width * height pixels of `components` (>= 3) floats, RGB first, VTK row
 *                   order (row 0 = bottom). Negative values count as 0; NaN/Inf are errors.
 * @return NumberOfLights lights, sorted by decreasing Energy.
 * @throws MedianCutAbortedError when Progress returned false; MedianCutError with a message for
 *         bad input (bad sizes, count 0 or above the pixel count, non-finite pixels, a map
 *         without light).
 */
MESOLIGHTLIGHTING_EXPORT std::vector<MedianCutLight> ComputeMedianCut(
  const float* pixels, int components, int width, int height, const MedianCutOptions& options);

/// Irradiance of a light set at normal n: sum Rgb max(0, n.Direction).
MESOLIGHTLIGHTING_EXPORT void IrradianceFromLights(
  const std::vector<MedianCutLight>& lights, const double n[3], double e[3]);

} // namespace mesolight

#endif
