// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldReliefSurface's conversions between the light field's cores and VTK data: the
// field's emitters as VTK lights, the probe image of port 1, the emitter lights' factors, the
// relief texture as a height field, and what one rank computes for a surface of polydata. Defined
// in vtkLightFieldReliefSurfaceProbes.cxx (comments there); not installed.
#ifndef vtkLightFieldReliefSurfaceProbes_h
#define vtkLightFieldReliefSurfaceProbes_h

#include "EnvironmentMaps.h"   // SH9
#include "HeightFieldTracer.h" // HeightField
#include "Progress.h"          // ProgressCallback
#include "ReliefShading.h"     // ReliefEmitterSample

#include <cstddef>
#include <string>
#include <vector>

class vtkImageData;
class vtkLightCollection;
class vtkPolyData;

namespace mesolight
{
class EmbreeScene;
namespace vlf
{
class LightField;
struct EmitterLight;
struct ReliefSurface;

namespace reliefsurface
{
// The field's emitters as the relief shades them: one light per lamp, merged down to the count
// the relief shader shades (vtkReliefMapper::GetMaximumNumberOfLights), so that a room of more
// lamps loses none of their light and every light keeps its scene visibility. Given the surface
// they light, the lamps nearest it stay separate (the merges go to the far ones).
std::vector<EmitterLight> ReliefEmitterLights(
  const LightField& field, const ReliefSurface* surface = nullptr);

// Those lights (computed once by the caller: the merge is not free) packed 9 numbers a light
// (world position, normal, intensity), or added as VTK lights.
std::vector<double> PackEmitterLights(
  const LightField& field, const std::vector<EmitterLight>& emitters);
void AddPackedLights(const std::vector<double>& packed, vtkLightCollection* lights);
void AddEmitterLights(
  const LightField& field, const std::vector<EmitterLight>& emitters, vtkLightCollection* lights);

// Port 1's probe image: n x n SH9 probes as floats (pixel (9 i + k, j)), and the image itself
// with, when given, the factor of light k (EmitterLightFactors) as a fourth component.
std::vector<float> PackProbes(const std::vector<SH9>& probes, int n);
void FillProbesImage(vtkImageData* image, const std::vector<float>& values, int n,
  const std::vector<float>* factors = nullptr, std::size_t lights = 0);

// Those lights' factors at the surface's n x n probes (EmitterLightFactors: the scene's shadow
// and the point light's error; traced in `lent` when given).
std::vector<float> LightFactors(const LightField& field, const ReliefSurface& surface,
  const std::vector<EmitterLight>& emitters, int n, const EmbreeScene* lent = nullptr);

// The depth (A) of a relief texture; throws std::runtime_error saying why not.
HeightField ReliefHeightField(vtkImageData* texture, bool walled);

// What one rank computes for a surface of polydata and sends: the probes, the texture frame,
// the surface's Kd and Ke and the emitter lights.
struct SurfaceResult
{
  int ProbesPerSide = 0; // n (vlf::ReliefProbesPerSide)
  std::vector<float> Probes;
  double Frame[16] = {}; // origin, u axis, v axis, normal (unit sphere); centre, scale (world)
  double Diffuse[3] = {};
  double Emission[3] = {};
  // The depth limit (world): a point, the front normal, 1 when the surface is mounted on a wall.
  double Limit[7] = {};
  std::vector<double> Lights;
  // Per probe and light (SceneOcclusion, EmitterLightFactors), else empty.
  std::vector<float> Factors;
  // The emitter samples light 0 stands for (EmitterSamplesOfLight; SceneOcclusion, else empty),
  // unit sphere, packed 9 numbers a sample (position, normal, radiance x area): the relief's
  // shadow of that light's area goes into the visible-share map on every rank.
  std::vector<double> LightSamples;
  // Said once by the computing rank: the surface covers scene surfaces of several materials.
  std::string Warning;
};

// The emitter samples the first of those lights stands for (EmitterSamplesOfLight), whose shadow
// by the relief the visible-share map holds; empty without lights.
std::vector<ReliefEmitterSample> FirstLightSamples(
  const LightField& field, const std::vector<EmitterLight>& emitters);

// Emitter samples packed 9 numbers a sample (SurfaceResult::LightSamples) and back.
std::vector<double> PackEmitterSamples(const std::vector<ReliefEmitterSample>& samples);
std::vector<ReliefEmitterSample> UnpackEmitterSamples(const std::vector<double>& packed);

// `probesPerSide`: vtkLightFieldReliefSurface::ProbesPerSide (0: ReliefProbesPerSide's choice).
SurfaceResult ComputeSurface(const LightField& field, vtkPolyData* whole, int probesPerSide,
  bool sceneOcclusion, const ProgressCallback& progress);
} // namespace reliefsurface
} // namespace vlf
} // namespace mesolight

#endif
