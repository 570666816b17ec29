// SPDX-License-Identifier: BSD-3-Clause
// The light set as data, written once for every source of lights (vtkMedianCutLights from an
// environment, vtkLightSetReader from a lights CSV): output port 0, one vertex per light at its
// unit direction with point arrays "Irradiance" (RGB), "MapCoordinates" (u, v) and "SolidAngle";
// output port 1, the N x 2 float RGBA light texture (row 0: direction; row 1: irradiance and
// solid angle) that vtkReliefMapper::SetLightSetConnection reads.
#ifndef mesolight_LightSetData_h
#define mesolight_LightSetData_h

#include "MedianCut.h"

#include <vector>

class vtkImageData;
class vtkInformation;
class vtkPolyData;

namespace mesolight
{

void FillLightSetData(
  const std::vector<MedianCutLight>& lights, vtkPolyData* output, vtkImageData* texture);

/** RequestInformation of output port 1: the whole extent and scalars of an N x 2 light texture. */
void SetLightTextureInformation(vtkInformation* textureInfo, int lights);

} // namespace mesolight

#endif
