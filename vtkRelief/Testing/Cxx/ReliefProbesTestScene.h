// SPDX-License-Identifier: BSD-3-Clause
// The scene of the ReliefIrradianceProbes tests (TestReliefIrradianceProbes.cxx and
// TestReliefIrradianceProbesWalls.cxx): vtkReliefMapper drawing a depth function on the unit
// square in one 160 x 160 window, the same depth as the exact height field for the CPU evaluation
// along the rendered pixels' rays (ShadeReliefRay, reliefcore/core/ReliefShading), and the probe
// image with its visible-share map as vtkReliefMapper::SetIrradianceProbesData reads them.
#ifndef mesolight_ReliefProbesTestScene_h
#define mesolight_ReliefProbesTestScene_h

#include "EnvironmentMaps.h" // SH9
#include "ImageCompare.h"    // Frame
#include "ReliefShading.h"   // HeightField, ReliefFrame, ReliefLighting, ReliefNormal
#include "vtkReliefMapper.h"

#include <vtkActor.h>
#include <vtkNew.h>
#include <vtkRenderer.h>
#include <vtkSmartPointer.h>
#include <vtkType.h>

#include <glm/vec3.hpp>

#include <functional>
#include <vector>

class vtkImageData;

namespace mesolight
{
namespace test
{
namespace probes
{

constexpr double DepthScale = 0.1;
constexpr int DepthSize = 128;
constexpr int Pixels = 160;

// Smooth bumps: slopes up to about 35 degrees at this depth scale, valleys that shadow a low
// light, and no creases (the baked normals and the exact bilinear surface's agree closely).
double Bumps(double u, double v);

// The SH9 projection of a radiance function over the sphere (midpoint rule, uniform in z and
// phi, i.e. in solid angle).
SH9 Project(const std::function<glm::dvec3(const glm::dvec3&)>& radiance);

// The SH9 of a constant radiance l.
SH9 ConstantRadiance(const glm::dvec3& l);

// The probe image of vtkReliefMapper::SetIrradianceProbesData: (9 Nu) x Nv RGB floats.
vtkSmartPointer<vtkImageData> ProbeImage(int nu, int nv, const std::vector<SH9>& probes);

// Adds to a probe image the relief's visible-share map as vtkIrradianceProbesTexture reads it:
// "ReliefVisibleShare", `tuples` values of `components` components, value(tuple, component)
// each, over a w x h grid ("ReliefVisibleShareSize").
void AttachVisibleShare(vtkImageData* probes, int w, int h, vtkIdType tuples, int components,
  const std::function<double(vtkIdType, int)>& value);

struct Scene
{
  vtkNew<vtkReliefMapper> Mapper;
  vtkSmartPointer<vtkActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  HeightField Height{ 1, 1, { 0.0f } };
  ReliefFrame Plane;
};

// The unit square carrying `depth`, white Lambertian, linear shading (no tone mapping), no
// VTK light unless added; seen obliquely with a perspective camera, or straight down.
void BuildScene(Scene& scene, const std::function<double(double, double)>& depth, bool oblique);

// The scene drawn in the program's one window (see Render in the .cxx).
Frame Render(Scene& scene);

// The ray through the centre of pixel (x, y) with the renderer's camera of the last render.
void PixelRay(vtkRenderer* renderer, int x, int y, glm::dvec3& origin, glm::dvec3& direction);

// The CPU evaluation along each pixel's ray (PixelRay): albedo / pi x (probe irradiance +
// emitter irradiance), as 8-bit levels; -1 where the ray misses the relief.
std::vector<double> CpuImage(
  Scene& scene, const ReliefLighting& lighting, ReliefNormal normal, const glm::dvec3& albedo);

// Mean |GPU - CPU| in 8-bit levels over the pixels both cover, and how many that is.
double MeanError(const Frame& gpu, const std::vector<double>& cpu, long long* count = nullptr);

} // namespace probes
} // namespace test
} // namespace mesolight

#endif
