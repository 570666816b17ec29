// SPDX-License-Identifier: BSD-3-Clause
// Exact references for a relief surface lit by an environment or by a light set of it: the
// irradiance at each reference pixel's exact hit (ReliefReference.h), shadowed by the exact
// bilinear height field (HeightFieldTracer.h), and a render's error against it. `mesolight bench
// ibl` and the light-set tests measure renders against these.
#ifndef mesolight_LightSetReference_h
#define mesolight_LightSetReference_h

#include "MesolightEvaluationModule.h" // for the export macro

#include <cstddef>
#include <vector>

class vtkImageData;

namespace mesolight
{
struct Frame;
struct ReliefReference;

/** Irradiance a relief pixel receives from the environment, computed on the CPU. */
struct EnvironmentIrradianceSample
{
  size_t Pixel = 0;
  double Irradiance[3] = { 0.0, 0.0, 0.0 }; // at the exact first hit, with exact visibility
};

/**
 * Monte Carlo reference (importance sampling of environment pixels by luminance x solid angle,
 * deterministic seed): for up to maxPixels covered pixels of the reference, the irradiance at the
 * exact hit, from every direction of the environment, shadowed by the exact bilinear height field.
 * world depth = d x depthScale, +Z up for both the wall and the environment. Empty if `relief` is
 * not a 4-component relief texture (float values in [0, 1], or 8-bit ones read as / 255, as the
 * relief mapper reads them) or there is no environment.
 */
MESOLIGHTEVALUATION_EXPORT std::vector<EnvironmentIrradianceSample> ComputeEnvironmentReference(
  const ReliefReference& hits, vtkImageData* relief, vtkImageData* environment, double depthScale,
  int maxPixels, int samplesPerPixel, bool shadows);

/**
 * Exact reference for a light set (vtkMedianCutLights' light texture): for the same pixels as
 * ComputeEnvironmentReference, the irradiance at the exact hit from exactly these lights, each
 * shadowed by the exact bilinear height field. Against it, a render's error is the relief
 * method's own (hits and visibility), without the light set's sampling error, which is the same
 * for every method. Empty if `lights` is not an N x 2 light texture of at least 3 components or
 * `relief` is not a 4-component relief texture.
 */
MESOLIGHTEVALUATION_EXPORT std::vector<EnvironmentIrradianceSample> ComputeLightSetReference(
  const ReliefReference& hits, vtkImageData* relief, vtkImageData* lights, double depthScale,
  int maxPixels);

/**
 * Mean relative error of a render against the reference: the render's colour at each sampled
 * pixel against 255 x exposure x albedo / pi x irradiance (white albedo, no other light).
 */
MESOLIGHTEVALUATION_EXPORT double EnvironmentError(
  const Frame& frame, const std::vector<EnvironmentIrradianceSample>& ref, double exposure);

} // namespace mesolight

#endif
