// SPDX-License-Identifier: BSD-3-Clause
// Shared helpers of the integration tests.
#ifndef mesolight_TestReliefTestUtilities_h
#define mesolight_TestReliefTestUtilities_h

#include "ImageCompare.h"   // Frame
#include "MessageCapture.h" // mesolight_test::MessageCapture: errors and warnings of a test

#include <vtkSmartPointer.h>

#include <array>
#include <functional>
#include <string>
#include <vector>

class vtkActor;
class vtkImageData;
class vtkReliefMapper;
class vtkRenderer;

namespace mesolight
{
namespace test
{

/** A depth map sampled at texel centres from depth(u, v) in [0,1]. */
vtkSmartPointer<vtkImageData> MakeDepthMap(
  int width, int height, const std::function<double(double, double)>& depth);

/** The relief texture of a depth map (vtkReliefTextureFilter, clamp borders). */
vtkSmartPointer<vtkImageData> BakeRelief(vtkImageData* depth, double depthScale);

/**
 * The unit square [0,1]^2 at z = 0 (texture coordinates = position) drawn by mapper with the given
 * relief texture, as a white Lambertian actor (ambient 0, diffuse 1, specular 0).
 */
vtkSmartPointer<vtkActor> UnitSquareRelief(
  vtkReliefMapper* mapper, vtkImageData* relief, double depthScale);

/** A parallel camera looking straight down at the unit square, which fills the view. */
void LookStraightDown(vtkRenderer* renderer);

/**
 * The frame of `actors` seen straight down at the unit square (LookStraightDown) in a
 * pixels x pixels offscreen window, lit by one directional scene light shining from `toLight`
 * (a direction from the square's centre, straight overhead by default) and no other.
 */
Frame CaptureTopDown(const std::vector<vtkActor*>& actors, int pixels,
  const std::array<double, 3>& toLight = { 0.0, 0.0, 1.0 });

/** Where test output goes (a build-tree directory). */
std::string OutputPath(const std::string& name);

} // namespace test
} // namespace mesolight

#endif
