// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkProceduralEnvironmentSource
 * @brief   deterministic procedural lat-long environment maps (float RGB radiance)
 *
 * vtkProceduralEnvironmentSource produces a lat-long (equirectangular) environment map,
 * W x H float RGB point scalars named "Radiance", extent [0, W-1, 0, H-1, 0, 0], origin 0,
 * spacing 1, for tests, benchmarks and demos of image-based lighting:
 *  - SMOOTH_SKY: a sky gradient (brighter toward the horizon) over a dim ground, blended
 *    over +-2 degrees around the horizon;
 *  - SUN_SKY: the smooth sky plus a small, intense sun disc (angular diameter SunDiameter,
 *    default 2 degrees, at SunElevation / SunAzimuth, radiance SunIntensity times a warm
 *    white), and, when Window is on, a bright rectangular "window" patch.
 * Formulas: core/ProceduralEnvironments.h.
 *
 * Map conventions (see core/EnvironmentMaps.h and docs/environment-maps.md): VTK row order,
 * row 0 = the bottom of the picture (the nadir), the top row is the zenith; map coordinates
 * u in [0,1] left to right, v in [0,1] with v = 0 at the top row; +Z up, polar angle
 * theta = pi v, azimuth phi = 2 pi u from +X toward +Y. Elevation (from the horizon) and
 * azimuth (from +X toward +Y) are in degrees.
 */
#ifndef vtkProceduralEnvironmentSource_h
#define vtkProceduralEnvironmentSource_h

#include "MesolightLightingModule.h" // For export macro
#include "vtkImageAlgorithm.h"

class MESOLIGHTLIGHTING_EXPORT vtkProceduralEnvironmentSource : public vtkImageAlgorithm
{
public:
  static vtkProceduralEnvironmentSource* New();
  vtkTypeMacro(vtkProceduralEnvironmentSource, vtkImageAlgorithm)
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum MapType
  {
    SMOOTH_SKY = 0,
    SUN_SKY = 1
  };

  ///@{
  /**
   * Which map to make. Default is SMOOTH_SKY.
   */
  vtkSetClampMacro(Map, int, SMOOTH_SKY, SUN_SKY);
  vtkGetMacro(Map, int);
  void SetMapToSmoothSky() { this->SetMap(SMOOTH_SKY); }
  void SetMapToSunSky() { this->SetMap(SUN_SKY); }
  ///@}

  ///@{
  /**
   * Width and height in pixels, each clamped to [2, 16384] (the width should be twice the
   * height). Default is 512 x 256.
   */
  void SetResolution(int w, int h);
  void SetResolution(const int res[2]) { this->SetResolution(res[0], res[1]); }
  vtkGetVector2Macro(Resolution, int);
  ///@}

  ///@{
  /**
   * The sun (SUN_SKY): elevation above the horizon in [-90, 90] degrees (default 40),
   * azimuth from +X toward +Y in degrees (default 30), angular diameter in (0, 90] degrees
   * (default 2) and disc radiance (default 10000, times the colour (1, 0.95, 0.85)).
   */
  vtkSetClampMacro(SunElevation, double, -90.0, 90.0);
  vtkGetMacro(SunElevation, double);
  vtkSetMacro(SunAzimuth, double);
  vtkGetMacro(SunAzimuth, double);
  vtkSetClampMacro(SunDiameter, double, 0.0, 90.0);
  vtkGetMacro(SunDiameter, double);
  vtkSetClampMacro(SunIntensity, double, 0.0, 1.0e9);
  vtkGetMacro(SunIntensity, double);
  ///@}

  ///@{
  /**
   * The window patch (SUN_SKY only): off by default. Centre elevation (default 15) and
   * azimuth (default 210), angular width (azimuth extent, default 40) and height (default
   * 25) in degrees, radiance (default 5).
   */
  vtkSetMacro(Window, bool);
  vtkGetMacro(Window, bool);
  vtkBooleanMacro(Window, bool);
  vtkSetClampMacro(WindowElevation, double, -90.0, 90.0);
  vtkGetMacro(WindowElevation, double);
  vtkSetMacro(WindowAzimuth, double);
  vtkGetMacro(WindowAzimuth, double);
  vtkSetClampMacro(WindowWidth, double, 0.0, 360.0);
  vtkGetMacro(WindowWidth, double);
  vtkSetClampMacro(WindowHeight, double, 0.0, 180.0);
  vtkGetMacro(WindowHeight, double);
  vtkSetClampMacro(WindowRadiance, double, 0.0, 1.0e9);
  vtkGetMacro(WindowRadiance, double);
  ///@}

protected:
  vtkProceduralEnvironmentSource();
  ~vtkProceduralEnvironmentSource() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int Map = SMOOTH_SKY;
  int Resolution[2] = { 512, 256 };
  // The sun and window defaults are the core's (mesolight::SkyParameters), set by the constructor.
  double SunElevation;
  double SunAzimuth;
  double SunDiameter;
  double SunIntensity;
  bool Window;
  double WindowElevation;
  double WindowAzimuth;
  double WindowWidth;
  double WindowHeight;
  double WindowRadiance;

private:
  vtkProceduralEnvironmentSource(const vtkProceduralEnvironmentSource&) = delete;
  void operator=(const vtkProceduralEnvironmentSource&) = delete;
};

#endif
