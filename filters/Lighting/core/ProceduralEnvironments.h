// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ProceduralEnvironments.h
 * @brief Deterministic procedural lat-long environment maps (plain C++17, no VTK types):
 *        a smooth sky over a dim ground, optionally with a sun disc and a bright
 *        rectangular "window". Used by tests, `mesolight bench lights` and the demo.
 *
 * Conventions: core/EnvironmentMaps.h. Elevation is measured from the horizon (90 degrees =
 * zenith, +Z), azimuth from +X toward +Y, both in degrees. Values are RGB radiance.
 *
 *  - Sky (elevation > 0): L = Horizon + (Zenith - Horizon) * sqrt(sin(elevation)), brighter
 *    at the horizon than at the zenith; ground (elevation < 0):
 *    L = Ground * (0.6 + 0.4 cos(elevation)).
 *    Sky and ground blend linearly over +-HorizonBlend degrees around the horizon.
 *  - Sun: a disc of angular diameter SunDiameter at (SunElevation, SunAzimuth) with radiance
 *    SunIntensity * SunColor, added to the sky; edge pixels get their covered fraction
 *    (8 x 8 supersamples).
 *  - Window: the rectangle elevation in [WindowElevation -+ WindowHeight / 2], azimuth in
 *    [WindowAzimuth -+ WindowWidth / 2] replaced by radiance WindowRadiance * WindowColor;
 *    edge pixels get their exact covered fraction (the rectangle is a rectangle in (u, v)).
 */
#ifndef mesolight_ProceduralEnvironments_h
#define mesolight_ProceduralEnvironments_h

#include "EnvironmentMaps.h"

namespace mesolight
{

struct SkyParameters
{
  double Zenith[3] = { 0.35, 0.55, 1.0 };
  double Horizon[3] = { 1.0, 1.0, 1.05 };
  double Ground[3] = { 0.2, 0.17, 0.13 };
  double HorizonBlend = 2.0; ///< degrees

  bool Sun = false;
  double SunElevation = 40.0;
  double SunAzimuth = 30.0;
  double SunDiameter = 2.0;
  double SunIntensity = 10000.0;
  double SunColor[3] = { 1.0, 0.95, 0.85 };

  bool Window = false;
  double WindowElevation = 15.0;
  double WindowAzimuth = 210.0;
  double WindowWidth = 40.0;
  double WindowHeight = 25.0;
  double WindowRadiance = 5.0;
  double WindowColor[3] = { 1.0, 0.97, 0.9 };
};

/// A width x height lat-long map (VTK row order).
MESOLIGHTLIGHTING_EXPORT RgbImage MakeSkyMap(int width, int height, const SkyParameters& p);

} // namespace mesolight

#endif
