// SPDX-License-Identifier: BSD-3-Clause
// Captures a rendered frame (colour and depth) and compares two frames of the same view:
// the error figures every relief test and benchmark reports.
#ifndef mesolight_ImageCompare_h
#define mesolight_ImageCompare_h

#include "MesolightEvaluationModule.h" // for the export macro

#include <cstddef>
#include <vector>

class vtkRenderWindow;

namespace mesolight
{

/** One rendered frame: RGB bytes and the depth buffer, bottom row first. */
struct MESOLIGHTEVALUATION_EXPORT Frame
{
  int Width = 0;
  int Height = 0;
  std::vector<unsigned char> Rgb;
  std::vector<float> Depth; // window depth in [0,1]; 1 = background
  double Near = 0.0;        // camera clipping range, to linearise Depth
  double Far = 1.0;
  bool Parallel = false;

  bool Covered(size_t pixel) const { return this->Depth[pixel] < 1.0f; }
  /** Distance from the eye plane of a covered pixel. */
  double EyeDepth(size_t pixel) const;
};

/** Renders the window and reads back its colour and depth. */
MESOLIGHTEVALUATION_EXPORT Frame CaptureFrame(vtkRenderWindow* window);

struct FrameDifference
{
  double MeanColorError =
    0.0;                      // mean |difference| over RGB, in 8-bit levels, pixels covered in both
  double RmsColorError = 0.0; // RMSE in 8-bit levels
  double Psnr = 0.0;          // dB, from RmsColorError
  double SilhouetteMismatch = 0.0; // % of pixels covered in exactly one frame, of those in either
  double MeanDepthError =
    0.0; // mean |eye depth difference| over pixels covered in both, world units
  double DepthMismatch = 0.0; // % of pixels covered in both whose eye depths differ by > tolerance
  long long CoveredBoth = 0;
};

/**
 * Compares two frames of the same camera. depthTolerance is in world units. When footprint is
 * given (the coarse mesh drawn alone), only pixels it covers count: a relief can only draw
 * inside its mesh's footprint, so the band of a displaced surface seen outside it is not an error
 * of the march.
 */
MESOLIGHTEVALUATION_EXPORT FrameDifference CompareFrames(
  const Frame& a, const Frame& b, double depthTolerance, const Frame* footprint = nullptr);

/** Pixels covered by exactly one of two frames (the outline's error), of those covered by either.
 */
struct CoverageDifference
{
  long long Mismatched = 0;
  long long Either = 0;
  /** Mismatched as % of Either (100 when nothing is covered). */
  double Percent() const
  {
    return this->Either > 0 ? 100.0 * this->Mismatched / this->Either : 100.0;
  }
};

/**
 * Compares the coverage masks of two frames of the same camera. A margin > 0 leaves out that many
 * pixels on the left, right and bottom of the bounding box of the pixels either frame covers, so
 * that only the top of a surface's outline counts (the curved-relief scenes turn away from the
 * viewer at the top of the frame; their other sides are the texture's own edges).
 */
MESOLIGHTEVALUATION_EXPORT CoverageDifference CompareCoverage(
  const Frame& a, const Frame& b, int margin = 0);

/**
 * Decodes vtkReliefMapper's HitUOutput / HitVOutput at a pixel: the hit coordinate as 24-bit
 * fixed point. False for background pixels.
 */
MESOLIGHTEVALUATION_EXPORT bool DecodeHitCoordinate(
  const Frame& frame, size_t pixel, double& coordinate);

/**
 * Decodes vtkReliefMapper's SampleCountOutput at a pixel: the relief-texture samples the fragment
 * took. False for background pixels.
 */
MESOLIGHTEVALUATION_EXPORT bool DecodeSampleCount(const Frame& frame, size_t pixel, int& count);

/** Mean of DecodeSampleCount over the covered pixels of a frame (0 if none is covered). */
MESOLIGHTEVALUATION_EXPORT double MeanSampleCount(const Frame& frame);

/**
 * The samples a lock-step machine issues per covered pixel: the frame cut into groups of
 * groupWidth x groupHeight pixels (a GPU's warp or wavefront: 8 x 4 is 32 lanes), every covered
 * pixel charged its group's largest count, since a loop runs until its slowest lane ends.
 * MeanSampleCount is what the texture units fetch (idle lanes fetch nothing); this is what the
 * loop's arithmetic costs. 0 if nothing is covered or a group size is below 1.
 */
MESOLIGHTEVALUATION_EXPORT double MeanLockStepSampleCount(
  const Frame& frame, int groupWidth, int groupHeight);

/** Mean of per-pixel counts given directly over the covered pixels (negative: not covered). */
MESOLIGHTEVALUATION_EXPORT double MeanCount(const std::vector<int>& counts);

/**
 * The same lock-step mean for per-pixel counts given directly: counts holds width x height
 * values (row-major, row 0 at the bottom like Frame), negative where no pixel is covered.
 */
MESOLIGHTEVALUATION_EXPORT double MeanLockStepCount(
  const std::vector<int>& counts, int width, int height, int groupWidth, int groupHeight);

/** Writes the frame's colour as PNG. */
MESOLIGHTEVALUATION_EXPORT bool WritePng(const Frame& frame, const char* fileName);

} // namespace mesolight

#endif
