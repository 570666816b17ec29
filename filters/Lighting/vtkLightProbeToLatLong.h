// SPDX-License-Identifier: BSD-3-Clause
/**
 * @class   vtkLightProbeToLatLong
 * @brief   Light probe picture (angular map or mirror ball) -> latitude-longitude environment.
 *
 * Input: a square RGB(A) picture of a light probe, any scalar type (float for HDR). Output: a
 * float RGB lat-long map in Mesolight's convention (docs/environment-maps.md: +Z up, v = 0 at
 * the top row), bilinearly resampled with Samples x Samples supersamples per output pixel.
 * Angular maps are Debevec's light-probe format; a mirror ball is a mirrored sphere filling the
 * picture, photographed along Forward. Forward and Up give the probe camera's frame in the
 * environment's coordinates (default: looking along +X, up +Z). Regions a probe cannot see (a
 * mirror ball's blind spot behind the ball) come out as the nearest seen radiance.
 * The two-view merge of the relief thesis (A C + B (1 - C)) is mesolight::MergeWithMask in
 * filters/Lighting/core/EnvironmentMaps.h and `mesolight probe --merge`.
 */
#ifndef vtkLightProbeToLatLong_h
#define vtkLightProbeToLatLong_h

#include "MesolightLightingModule.h" // for export macro
#include "vtkImageAlgorithm.h"

class MESOLIGHTLIGHTING_EXPORT vtkLightProbeToLatLong : public vtkImageAlgorithm
{
public:
  static vtkLightProbeToLatLong* New();
  vtkTypeMacro(vtkLightProbeToLatLong, vtkImageAlgorithm);
  void PrintSelf(ostream& os, vtkIndent indent) override;

  enum ProbeTypes
  {
    ANGULAR_MAP = 0,
    MIRROR_BALL = 1
  };
  vtkSetClampMacro(ProbeType, int, ANGULAR_MAP, MIRROR_BALL);
  vtkGetMacro(ProbeType, int);
  void SetProbeTypeToAngularMap() { this->SetProbeType(ANGULAR_MAP); }
  void SetProbeTypeToMirrorBall() { this->SetProbeType(MIRROR_BALL); }

  /** Output width; the height is half of it. 0 (default): twice the probe's size. */
  vtkSetClampMacro(OutputWidth, int, 0, 32768);
  vtkGetMacro(OutputWidth, int);

  /** Supersamples per output pixel and axis (default 2). */
  vtkSetClampMacro(Samples, int, 1, 8);
  vtkGetMacro(Samples, int);

  vtkSetVector3Macro(Forward, double);
  vtkGetVector3Macro(Forward, double);
  vtkSetVector3Macro(Up, double);
  vtkGetVector3Macro(Up, double);

  ///@{
  /**
   * Memory budget in bytes: the probe, the map and its copy are estimated before allocating, and
   * the filter fails with the size needed when that is more. 0 (default): the memory the process
   * can get (its cgroup limit, else the physical memory).
   */
  vtkSetClampMacro(MemoryBudget, vtkTypeInt64, 0, VTK_TYPE_INT64_MAX);
  vtkGetMacro(MemoryBudget, vtkTypeInt64);
  ///@}

protected:
  vtkLightProbeToLatLong() = default;
  ~vtkLightProbeToLatLong() override = default;

  int RequestInformation(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestUpdateExtent(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;
  int RequestData(vtkInformation*, vtkInformationVector**, vtkInformationVector*) override;

  int ProbeType = ANGULAR_MAP;
  int OutputWidth = 0;
  int Samples = 2;
  vtkTypeInt64 MemoryBudget = 0;
  double Forward[3] = { 1.0, 0.0, 0.0 };
  double Up[3] = { 0.0, 0.0, 1.0 };

private:
  vtkLightProbeToLatLong(const vtkLightProbeToLatLong&) = delete;
  void operator=(const vtkLightProbeToLatLong&) = delete;
};

#endif
