// SPDX-License-Identifier: BSD-3-Clause
// The GPU relief render against an independent reference of the same scene: the height field
// as a dense displaced mesh (one vertex per texel, vtkHeightFieldMeshFilter) drawn by VTK's stock
// mapper with the same camera, lights, normals and albedo. Self-shadowing is off on both sides
// (the stock mapper has none); shadows are tested against exact visibility in TestReliefShadows.
#include "DenseMeshTestScene.h"
#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"

#include <gtest/gtest.h>

#include <iostream>
#include <sstream>

namespace
{
using namespace mesolight;

// Renders the relief variant and the dense reference of the same options and compares them.
FrameDifference CompareWithDenseMesh(const ReliefSceneOptions& options, const std::string& tag)
{
  std::string error;
  ReliefScene dense, relief, coarse;
  EXPECT_TRUE(BuildDenseReferenceScene(options, dense, error)) << error;
  EXPECT_TRUE(BuildReliefScene(options, relief, error)) << error;
  EXPECT_TRUE(BuildTexturedPlaneScene(options, coarse, error)) << error;
  auto coarseWindow = MakeOffscreenWindow(options, coarse.Renderer);
  const Frame footprint = CaptureFrame(coarseWindow);
  auto denseWindow = MakeOffscreenWindow(options, dense.Renderer);
  const Frame reference = CaptureFrame(denseWindow);
  auto reliefWindow = MakeOffscreenWindow(options, relief.Renderer);
  const Frame frame = CaptureFrame(reliefWindow);
  WritePng(reference, test::OutputPath(tag + "-dense.png").c_str());
  WritePng(frame, test::OutputPath(tag + "-relief.png").c_str());
  // Depth tolerance: 5% of the relief's world depth.
  const FrameDifference d = CompareFrames(frame, reference, 0.05 * options.DepthScale, &footprint);
  std::cout << "[" << tag << "] mean colour error " << d.MeanColorError << " levels, PSNR "
            << d.Psnr << " dB, silhouette mismatch " << d.SilhouetteMismatch << "%, depth mismatch "
            << d.DepthMismatch << "%, mean depth error " << d.MeanDepthError << std::endl;
  EXPECT_GT(d.CoveredBoth, options.Width * options.Height / 4) << "the wall should fill the view";
  return d;
}

// Thresholds met by a correct first-hit march; plain texture mapping misses them by far.
constexpr double MaxMeanColorError = 3.0;     // 8-bit levels
constexpr double MaxSilhouetteMismatch = 1.0; // percent of pixels in the mesh footprint
constexpr double MaxDepthMismatch = 5.0;      // percent of common pixels off by > 5% of the depth

bool WithinTolerance(const FrameDifference& d)
{
  return d.MeanColorError <= MaxMeanColorError && d.SilhouetteMismatch <= MaxSilhouetteMismatch &&
    d.DepthMismatch <= MaxDepthMismatch;
}
} // namespace

// With no depth there is nothing to march: the relief shader must light exactly like the stock
// mapper (same Phong model, lights and texture modulation).
TEST(ReliefVsDenseMesh, FlatMapShadesLikeTheStockMapper)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Pattern = "Flat";
  const FrameDifference d = CompareWithDenseMesh(o, "flat");
  EXPECT_LT(d.MeanColorError, 1.0);
  EXPECT_LT(d.SilhouetteMismatch, 0.5);
  EXPECT_LT(d.DepthMismatch, 0.5);
}

struct MethodCase
{
  const char* Method;
  int Linear;
  int Refine;
  double ViewAngle;
  const char* Pattern;
  double DepthScale;
};

void PrintTo(const MethodCase& c, std::ostream* os)
{
  *os << c.Method << " " << c.Linear << "+" << c.Refine << " at " << c.ViewAngle << " deg on "
      << c.Pattern << " (depth scale " << c.DepthScale << ")";
}

class ReliefMethodVsDenseMesh : public ::testing::TestWithParam<MethodCase>
{
};

TEST_P(ReliefMethodVsDenseMesh, WithinTolerance)
{
  const MethodCase c = GetParam();
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Method = c.Method;
  o.LinearSteps = c.Linear;
  o.RefinementSteps = c.Refine;
  o.ViewAngle = c.ViewAngle;
  o.Pattern = c.Pattern;
  o.DepthScale = c.DepthScale;
  std::ostringstream tag;
  tag << c.Pattern << "-" << c.Method << c.Linear << "-" << c.Refine << "-view" << c.ViewAngle;
  const FrameDifference d = CompareWithDenseMesh(o, tag.str());
  EXPECT_LE(d.MeanColorError, MaxMeanColorError);
  EXPECT_LE(d.SilhouetteMismatch, MaxSilhouetteMismatch);
  EXPECT_LE(d.DepthMismatch, MaxDepthMismatch);
}

INSTANTIATE_TEST_SUITE_P(Methods, ReliefMethodVsDenseMesh,
  ::testing::Values(MethodCase{ "relief", 10, 8, 30.0, "Bricks", 0.04 },
    MethodCase{ "relief", 10, 8, 55.0, "Bricks", 0.04 },
    MethodCase{ "relief", 10, 8, 70.0, "Bricks", 0.04 },
    MethodCase{ "relief", 10, 8, 55.0, "HemisphereTorus", 0.15 },
    MethodCase{ "pom", 32, 0, 30.0, "Bricks", 0.04 },
    MethodCase{ "pom", 32, 0, 55.0, "HemisphereTorus", 0.15 }));

// Negative test: plain texture (and normal) mapping, no march, must fail the same comparison.
TEST(ReliefVsDenseMesh, PlainTextureMappingFailsTheComparison)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Method = "texture";
  o.ViewAngle = 55.0;
  const FrameDifference d = CompareWithDenseMesh(o, "bricks-texture-view55");
  EXPECT_FALSE(WithinTolerance(d));
  EXPECT_GT(d.DepthMismatch, 3.0 * MaxDepthMismatch);
}

// Negative test: without gl_FragDepth the relief keeps the mesh's depth, which the depth check
// must catch even though the colours match.
TEST(ReliefVsDenseMesh, WithoutDepthWriteTheDepthCheckFails)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.WriteDepth = false;
  o.ViewAngle = 55.0;
  const FrameDifference d = CompareWithDenseMesh(o, "bricks-relief-nodepth-view55");
  EXPECT_LE(d.MeanColorError, MaxMeanColorError);
  EXPECT_GT(d.DepthMismatch, MaxDepthMismatch);
}
