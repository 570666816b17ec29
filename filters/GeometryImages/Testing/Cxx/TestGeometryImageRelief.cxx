// SPDX-License-Identifier: BSD-3-Clause
// A relief on the coarse mesh of a geometry image against the dense displaced mesh of the same
// surface (Méndez Fernández, "Visualizing 3D models with fine-grain surface depth", §6): a
// cylinder and a sphere patch written as 256 x 256 geometry images, the Bricks depth map texel for
// texel, the coarse mesh every 8 pixels (regular) or to a tolerance (adaptive), drawn by
// vtkReliefMapper; the reference displaces every pixel along the surface normal and is drawn by
// VTK's stock mapper with the same camera, lights and albedo. Negative tests: the coarse mesh
// plainly texture-mapped, and a stride so coarse that its chords cut deeper than the relief.
#include "GeometryImageScene.h"
#include "ImageCompare.h"
#include "TestReliefTestUtilities.h"

#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPolyData.h>

#include "vtkOIIOImageWriter.h"

#include <gtest/gtest.h>

#include <cstdio>
#include <iostream>

namespace
{
using namespace mesolight;

GeometryImageSceneOptions Scene(const char* surface)
{
  GeometryImageSceneOptions o;
  o.GeometryImage = std::string("procedural:") + surface;
  o.Relief.Pattern = "Bricks";
  o.Relief.Resolution = 256;
  o.Relief.Width = 300;
  o.Relief.Height = 300;
  o.Relief.DepthScale = 0.04;
  o.Relief.SelfShadowing = false; // the stock mapper has no shadows
  o.Relief.ViewAngle = 45.0;
  o.Relief.ViewDistance = 2.4;
  o.Relief.LinearSteps = 32;
  o.Relief.RefinementSteps = 8;
  o.Stride = 8;
  return o;
}

enum class Variant
{
  Relief,
  Textured
};

FrameDifference Compare(const GeometryImageSceneOptions& o, Variant variant, const std::string& tag,
  vtkIdType* triangles = nullptr)
{
  std::string error;
  ReliefScene dense, drawn, coarse;
  vtkSmartPointer<vtkPolyData> mesh;
  EXPECT_TRUE(BuildGeometryImageDenseScene(o, dense, error)) << error;
  EXPECT_TRUE(BuildGeometryImageTexturedScene(o, coarse, error)) << error;
  if (variant == Variant::Relief)
  {
    EXPECT_TRUE(BuildGeometryImageReliefScene(o, drawn, error, &mesh)) << error;
  }
  else
  {
    EXPECT_TRUE(BuildGeometryImageTexturedScene(o, drawn, error)) << error;
  }
  if (!dense.Renderer || !drawn.Renderer || !coarse.Renderer)
  {
    return FrameDifference{ 1e9, 1e9, 0, 100, 1e9, 100, 0 };
  }
  // Only pixels inside the coarse mesh's footprint count: the relief cannot draw outside it.
  auto coarseWindow = MakeOffscreenWindow(o.Relief, coarse.Renderer);
  const Frame footprint = CaptureFrame(coarseWindow);
  auto denseWindow = MakeOffscreenWindow(o.Relief, dense.Renderer);
  const Frame reference = CaptureFrame(denseWindow);
  auto window = MakeOffscreenWindow(o.Relief, drawn.Renderer);
  const Frame frame = CaptureFrame(window);
  WritePng(reference, test::OutputPath("geometry-image-" + tag + "-dense.png").c_str());
  WritePng(frame, test::OutputPath("geometry-image-" + tag + ".png").c_str());
  const FrameDifference d = CompareFrames(frame, reference, 0.05 * o.Relief.DepthScale, &footprint);
  std::cout << "[" << tag << "] " << (mesh ? mesh->GetNumberOfPolys() : 0)
            << " triangles: mean colour error " << d.MeanColorError << " levels, silhouette "
            << d.SilhouetteMismatch << "%, depth mismatch " << d.DepthMismatch
            << "%, mean depth error " << d.MeanDepthError << std::endl;
  if (triangles)
  {
    *triangles = mesh ? mesh->GetNumberOfPolys() : 0;
  }
  EXPECT_GT(d.CoveredBoth, o.Relief.Width * o.Relief.Height / 5) << "the surface fills the view";
  return d;
}

// The wall's thresholds (TestReliefAgainstDenseMesh): met by the relief on a coarse mesh whose
// chords stay well inside the depth tolerance (5% of the relief depth, 0.002: stride 8 leaves
// 2.6e-4 on the cylinder, 3.8e-4 on the sphere); missed by far by plain texture mapping.
constexpr double MaxMeanColorError = 3.0;
constexpr double MaxSilhouetteMismatch = 1.0;
constexpr double MaxDepthMismatch = 5.0;

bool WithinTolerance(const FrameDifference& d)
{
  return d.MeanColorError <= MaxMeanColorError && d.SilhouetteMismatch <= MaxSilhouetteMismatch &&
    d.DepthMismatch <= MaxDepthMismatch;
}
} // namespace

TEST(GeometryImageRelief, CylinderAtStrideEightMatchesTheDenseMesh)
{
  vtkIdType triangles = 0;
  const FrameDifference d = Compare(Scene("cylinder"), Variant::Relief, "cylinder8", &triangles);
  EXPECT_EQ(triangles, 2 * 32 * 32);
  EXPECT_LE(d.MeanColorError, MaxMeanColorError);
  EXPECT_LE(d.SilhouetteMismatch, MaxSilhouetteMismatch);
  EXPECT_LE(d.DepthMismatch, MaxDepthMismatch);
}

TEST(GeometryImageRelief, SpherePatchAtStrideEightMatchesTheDenseMesh)
{
  const FrameDifference d = Compare(Scene("sphere"), Variant::Relief, "sphere8");
  EXPECT_LE(d.MeanColorError, MaxMeanColorError);
  EXPECT_LE(d.SilhouetteMismatch, MaxSilhouetteMismatch);
  EXPECT_LE(d.DepthMismatch, MaxDepthMismatch);
}

TEST(GeometryImageRelief, AdaptiveBumpMatchesTheDenseMesh)
{
  GeometryImageSceneOptions o = Scene("bump");
  o.Tolerance = 0.001; // half the depth tolerance
  vtkIdType triangles = 0;
  const FrameDifference d = Compare(o, Variant::Relief, "bump-adaptive", &triangles);
  EXPECT_LT(triangles, 2 * 32 * 32); // fewer than stride 8, whose chords miss by 3.2e-3
  EXPECT_LE(d.MeanColorError, MaxMeanColorError);
  EXPECT_LE(d.SilhouetteMismatch, MaxSilhouetteMismatch);
  EXPECT_LE(d.DepthMismatch, MaxDepthMismatch);
}

// Negative: the same coarse mesh without the march (plain texture mapping) must fail.
TEST(GeometryImageRelief, PlainTextureMappingOnTheCoarseMeshFails)
{
  const FrameDifference d = Compare(Scene("cylinder"), Variant::Textured, "cylinder8-texture");
  EXPECT_FALSE(WithinTolerance(d));
  EXPECT_GT(d.DepthMismatch, 3.0 * MaxDepthMismatch);
}

// Negative: at stride 32 the chords of the cylinder lie 4.1e-3 inside it, twice the depth
// tolerance: the relief, marched from the chords, cannot carry that, and the comparison must see
// it.
TEST(GeometryImageRelief, AStrideTooCoarseForTheCurvatureFails)
{
  GeometryImageSceneOptions o = Scene("cylinder");
  o.Stride = 32;
  const FrameDifference d = Compare(o, Variant::Relief, "cylinder32");
  EXPECT_FALSE(WithinTolerance(d));
  EXPECT_GT(d.DepthMismatch, 3.0 * MaxDepthMismatch);
}

// A float colour image (an EXR albedo, as depth hallucination writes) shows as its colours: a
// constant (0.1, 0.15, 0.9) albedo makes the lit model blue. vtkTexture maps float scalars
// through a lookup table unless told to use them directly: before, this model came out red.
TEST(GeometryImageRelief, FloatColourImageShowsItsColours)
{
  vtkNew<vtkImageData> albedo;
  albedo->SetDimensions(4, 4, 1);
  albedo->AllocateScalars(VTK_FLOAT, 3);
  auto* values = static_cast<float*>(albedo->GetScalarPointer());
  for (int p = 0; p < 16; ++p)
  {
    values[3 * p] = 0.1f;
    values[3 * p + 1] = 0.15f;
    values[3 * p + 2] = 0.9f;
  }
  const std::string file = test::OutputPath("geometry-image-float-albedo.exr");
  std::remove(file.c_str());
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(albedo);
  writer->SetFileName(file.c_str());
  writer->Write();
  GeometryImageSceneOptions o = Scene("cylinder");
  o.ColorFile = file;
  std::string error;
  ReliefScene scene;
  ASSERT_TRUE(BuildGeometryImageReliefScene(o, scene, error)) << error;
  auto window = MakeOffscreenWindow(o.Relief, scene.Renderer);
  const Frame frame = CaptureFrame(window);
  double sum[3] = { 0.0, 0.0, 0.0 };
  long long covered = 0;
  for (size_t p = 0; p < frame.Depth.size(); ++p)
  {
    if (frame.Covered(p))
    {
      ++covered;
      for (int c = 0; c < 3; ++c)
      {
        sum[c] += frame.Rgb[3 * p + c];
      }
    }
  }
  ASSERT_GT(covered, 1000);
  std::cout << "mean colour " << sum[0] / covered << ", " << sum[1] / covered << ", "
            << sum[2] / covered << std::endl;
  EXPECT_GT(sum[2], 3.0 * sum[0]);
  EXPECT_GT(sum[2], 3.0 * sum[1]);
}
