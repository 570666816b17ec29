// `mesolight bench ibl`: a relief surface lit by median-cut light sets of an environment.
// Frame time against the number of lights (one run for all counts, like the relief thesis'
// table 1), the effect of each skip on time and error, the error of each light set against a
// Monte Carlo reference with exact height-field visibility, and relief vs relaxed cone stepping at
// equal error against the exact render of the same light set.
#ifndef mesolight_LightSetBenchmark_h
#define mesolight_LightSetBenchmark_h

#include "ReliefScene.h"

#include <string>
#include <vector>

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
 * not a 4-component relief texture or there is no environment.
 */
std::vector<EnvironmentIrradianceSample> ComputeEnvironmentReference(const ReliefReference& hits,
  vtkImageData* relief, vtkImageData* environment, double depthScale, int maxPixels,
  int samplesPerPixel, bool shadows);

/**
 * Exact reference for a light set (vtkMedianCutLights' light texture): for the same pixels as
 * ComputeEnvironmentReference, the irradiance at the exact hit from exactly these lights, each
 * shadowed by the exact bilinear height field. Against it, a render's error is the relief
 * method's own (hits and visibility), without the light set's sampling error, which is the same
 * for every method. Empty if `lights` is not an N x 2 light texture of at least 3 components or
 * `relief` is not a 4-component relief texture.
 */
std::vector<EnvironmentIrradianceSample> ComputeLightSetReference(const ReliefReference& hits,
  vtkImageData* relief, vtkImageData* lights, double depthScale, int maxPixels);

/**
 * Mean relative error of a render against the reference: the render's colour at each sampled
 * pixel against 255 x exposure x albedo / pi x irradiance (white albedo, no other light).
 */
double EnvironmentError(const Frame& frame, const std::vector<EnvironmentIrradianceSample>& ref,
  double exposure);

/** `mesolight bench ibl [--counts 32,...,1024] [--frames N] [--csv FILE] ...` */
int RunLightSetBenchmark(const std::vector<std::string>& args);

} // namespace mesolight

#endif
