// SPDX-License-Identifier: BSD-3-Clause
// The CPU relief reference (ReliefReference: exact per-pixel ray / bilinear height field hits)
// is checked twice: against the independent dense displaced mesh drawn by VTK's stock mapper
// (depth buffer and coverage), and as the yardstick of the GPU march (decoded hit coordinates of
// vtkReliefMapper's HitUOutput / HitVOutput). Each check has a negative counterpart that must fail.
#include "DenseMeshTestScene.h"
#include "ImageCompare.h"
#include "ReliefReference.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkRenderWindow.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace
{
using namespace mesolight;

struct DenseAgreement
{
  double DepthAgreement = 0.0;   // % of pixels covered by both within the tolerance
  double CoverageMismatch = 0.0; // % of footprint pixels covered by exactly one
  long long CoveredBoth = 0;
  long long Footprint = 0;
};

// The reference against a dense-mesh frame of the same camera: eye depth of every pixel covered
// by both within 5% of the relief's world depth, and coverage inside the wall's footprint.
DenseAgreement CompareWithDense(
  const ReliefReference& reference, const Frame& dense, double depthScale)
{
  DenseAgreement a;
  const double tolerance = 0.05 * depthScale;
  long long close = 0, onlyOne = 0;
  for (size_t p = 0; p < reference.State.size(); ++p)
  {
    if (!reference.InFootprint(p))
    {
      continue;
    }
    ++a.Footprint;
    const bool cpu = reference.IsCovered(p), gpu = dense.Covered(p);
    onlyOne += cpu != gpu;
    if (cpu && gpu)
    {
      ++a.CoveredBoth;
      close += std::abs(reference.EyeDepth[p] - dense.EyeDepth(p)) <= tolerance;
    }
  }
  a.DepthAgreement = a.CoveredBoth > 0 ? 100.0 * double(close) / double(a.CoveredBoth) : 0.0;
  a.CoverageMismatch = a.Footprint > 0 ? 100.0 * double(onlyOne) / double(a.Footprint) : 100.0;
  return a;
}

Frame RenderDense(const ReliefSceneOptions& options)
{
  std::string error;
  ReliefScene dense;
  EXPECT_TRUE(BuildDenseReferenceScene(options, dense, error)) << error;
  auto window = MakeOffscreenWindow(options, dense.Renderer);
  return CaptureFrame(window);
}

ReliefReference ComputeReference(
  const ReliefSceneOptions& options, ReliefScene& scene, double depthScale = 0.0)
{
  std::string error;
  EXPECT_TRUE(BuildReliefScene(options, scene, error)) << error;
  ReliefReference reference;
  EXPECT_TRUE(
    ComputeReliefReference(MakeReliefReferenceInput(scene, options, depthScale), reference, error))
    << error;
  return reference;
}

struct ReferenceCase
{
  const char* Pattern;
  double DepthScale;
  double ViewAngle;
};

void PrintTo(const ReferenceCase& c, std::ostream* os)
{
  *os << c.Pattern << " depth scale " << c.DepthScale << " at " << c.ViewAngle << " deg";
}

class ReliefReferenceVsDenseMesh : public ::testing::TestWithParam<ReferenceCase>
{
};
} // namespace

TEST_P(ReliefReferenceVsDenseMesh, DepthAndCoverageAgree)
{
  const ReferenceCase c = GetParam();
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Pattern = c.Pattern;
  o.DepthScale = c.DepthScale;
  o.ViewAngle = c.ViewAngle;
  ReliefScene scene;
  const ReliefReference reference = ComputeReference(o, scene);
  const Frame dense = RenderDense(o);
  const DenseAgreement a = CompareWithDense(reference, dense, o.DepthScale);
  std::cout << "[reference " << c.Pattern << " " << c.ViewAngle << " deg] " << reference.Seconds
            << " s; covered " << reference.CountCovered() << " of footprint " << a.Footprint
            << "; depth within 5% of the relief depth: " << a.DepthAgreement
            << "%; coverage mismatch " << a.CoverageMismatch << "%" << std::endl;
  EXPECT_GT(a.CoveredBoth, o.Width * o.Height / 20) << "at 85 deg the wall is a thin band";
  EXPECT_GE(a.DepthAgreement, 99.0);
  EXPECT_LE(a.CoverageMismatch, 1.0);
  // The time is printed above, not asserted: speed belongs to the benchmarks, and a loaded
  // machine must not fail a correctness test.
}

INSTANTIATE_TEST_SUITE_P(Scenes, ReliefReferenceVsDenseMesh,
  ::testing::Values(ReferenceCase{ "Bricks", 0.04, 55.0 }, ReferenceCase{ "Bricks", 0.04, 80.0 },
    ReferenceCase{ "Bricks", 0.04, 85.0 }, ReferenceCase{ "HemisphereTorus", 0.15, 55.0 },
    ReferenceCase{ "Stone", 0.08, 0.0 }));

// Negative test: a reference traced with the wrong depth scale must fail the same comparison.
TEST(ReliefReference, WrongDepthScaleDisagreesWithTheDenseMesh)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Pattern = "HemisphereTorus";
  o.DepthScale = 0.15;
  ReliefScene scene;
  const ReliefReference wrong = ComputeReference(o, scene, 0.5 * o.DepthScale);
  const Frame dense = RenderDense(o);
  const DenseAgreement a = CompareWithDense(wrong, dense, o.DepthScale);
  std::cout << "[reference with half the depth scale] depth within tolerance " << a.DepthAgreement
            << "%, coverage mismatch " << a.CoverageMismatch << "%" << std::endl;
  EXPECT_LT(a.DepthAgreement, 90.0);
}

namespace
{
// The relief scene's hit coordinates, decoded from the mapper's measurement outputs.
HitComparison GpuHitError(const ReliefSceneOptions& options, const std::string& tag)
{
  ReliefScene scene;
  const ReliefReference reference = ComputeReference(options, scene);
  auto window = MakeOffscreenWindow(options, scene.Renderer);
  scene.Mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::HitUOutput);
  const Frame u = CaptureFrame(window);
  scene.Mapper->GetReliefProperty()->SetOutput(vtkReliefProperty::HitVOutput);
  const Frame v = CaptureFrame(window);
  const HitComparison c = CompareHits(reference, u, v);
  std::cout << "[" << tag << "] hit error mean " << c.MeanTexels << " texels, p99 " << c.P99Texels
            << ", max " << c.MaxTexels << "; silhouette mismatch " << c.SilhouetteMismatch
            << "% of " << c.Footprint << " footprint pixels" << std::endl;
  EXPECT_GT(c.CoveredBoth, options.Width * options.Height / 8);
  return c;
}
} // namespace

TEST(ReliefReference, GpuReliefHitsMatchTheReference)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Method = "relief";
  o.LinearSteps = 10;
  o.RefinementSteps = 8;
  const HitComparison c = GpuHitError(o, "relief 10+8, 55 deg");
  EXPECT_LT(c.MeanTexels, 0.5);
  EXPECT_LT(c.SilhouetteMismatch, 1.0);
}

// Negative test: plain texture mapping (no march) hits the mesh surface, far from the exact hit.
TEST(ReliefReference, PlainTextureMappingHitsAreFarOff)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Method = "texture";
  const HitComparison c = GpuHitError(o, "texture, 55 deg");
  EXPECT_GT(c.MeanTexels, 1.0) << "twice the 0.5 texel bound the relief march must meet";
}
