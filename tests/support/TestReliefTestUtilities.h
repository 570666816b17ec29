// SPDX-License-Identifier: BSD-3-Clause
// Shared helpers of the integration tests.
#ifndef mesolight_TestReliefTestUtilities_h
#define mesolight_TestReliefTestUtilities_h

#include "MessageCapture.h" // mesolight_test::MessageCapture: errors and warnings of a test

#include <vtkSmartPointer.h>

#include <functional>
#include <string>

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

/** Where test output goes (a build-tree directory). */
std::string OutputPath(const std::string& name);

} // namespace test
} // namespace mesolight

#endif
