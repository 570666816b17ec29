// SPDX-License-Identifier: BSD-3-Clause
// Relief mapping on curved meshes (Oliveira & Policarpo 2005, "An efficient representation for
// surface details"; Policarpo, Oliveira & Comba 2005, "Real-time relief mapping on arbitrary
// polygonal surfaces"): the outline of a relief-mapped cylinder and sphere patch, seen so that
// they turn away from the viewer inside the texture, against the dense displaced mesh of the same
// surface (DisplaceGeometryImage, drawn by VTK's stock mapper). The check is the coverage mask:
// pixels covered by exactly one of the two frames. Negative case: the flat-plane march (surface
// curvature off) covers the whole coarse mesh and must fail the same check. A flat mesh must
// draw the same image whether the curvature setting is on or off.
#include "GeometryImageScene.h"
#include "ImageCompare.h"
#include "TestReliefTestUtilities.h"

#include <vtkPolyData.h>

#include "vtkReliefGeometryCache.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <gtest/gtest.h>

#include <iostream>

namespace
{
using namespace mesolight;

// CurvedOutlineScene: the cylinder's axis is v (y); the camera turns 90 degrees about it and
// looks from 55 degrees, so the surface turns away about 35 degrees from its middle, well inside
// the 120-degree patch. The hemispheres-and-tori pattern has a base 0.9 deep: where the surface
// turns away the dense mesh's outline lies most of the relief depth inside the coarse mesh's.
GeometryImageSceneOptions Scene(const char* surface)
{
  return CurvedOutlineScene(surface);
}

// Only the top of the outline counts (CompareCoverage's margin): the left, right and bottom of
// the frame are the patch's texture edges (the ends of the cylinder, its u = 0 edge), the
// texture-border rule's business, drawn by both marches alike.
constexpr int OutlineMargin = 10;
using Coverage = CoverageDifference;

Frame Render(const GeometryImageSceneOptions& o, bool dense, const std::string& tag)
{
  std::string error;
  ReliefScene scene;
  const bool built = dense ? BuildGeometryImageDenseScene(o, scene, error)
                           : BuildGeometryImageReliefScene(o, scene, error);
  EXPECT_TRUE(built) << error;
  if (!built)
  {
    return Frame{};
  }
  auto window = MakeOffscreenWindow(o.Relief, scene.Renderer);
  Frame frame = CaptureFrame(window);
  WritePng(frame, test::OutputPath("curved-relief-" + tag + ".png").c_str());
  return frame;
}

// Coverage mismatch of the relief with curvature on and off against the dense mesh.
void Measure(const char* surface, Coverage& curved, Coverage& flat)
{
  GeometryImageSceneOptions o = Scene(surface);
  const Frame reference = Render(o, true, std::string(surface) + "-dense");
  const Frame withCurvature = Render(o, false, std::string(surface) + "-curved");
  o.Relief.SurfaceCurvature = false;
  const Frame withoutCurvature = Render(o, false, std::string(surface) + "-flat-march");
  ASSERT_FALSE(reference.Depth.empty());
  ASSERT_EQ(reference.Depth.size(), withCurvature.Depth.size());
  ASSERT_EQ(reference.Depth.size(), withoutCurvature.Depth.size());
  curved = CompareCoverage(withCurvature, reference, OutlineMargin);
  flat = CompareCoverage(withoutCurvature, reference, OutlineMargin);
  const Coverage curvedWhole = CompareCoverage(withCurvature, reference);
  const Coverage flatWhole = CompareCoverage(withoutCurvature, reference);
  std::cout << "[" << surface << "] coverage mismatch against the dense mesh where the surface "
            << "turns away: curved march " << curved.Mismatched << " px (" << curved.Percent()
            << "%), flat march " << flat.Mismatched << " px (" << flat.Percent() << "%) of "
            << flat.Either << " px covered; whole frame: curved " << curvedWhole.Mismatched
            << " px (" << curvedWhole.Percent() << "%), flat " << flatWhole.Mismatched << " px ("
            << flatWhole.Percent() << "%)" << std::endl;
  EXPECT_GT(flat.Either, o.Relief.Width * o.Relief.Height / 8) << "the surface fills the view";
}

// The threshold, between what the curved march leaves (pixels along the outline where the
// coarse mesh's chords and the bilinear quadric differ from the exact surface) and what the flat
// march shows (the whole band between the coarse and the dense outline).
constexpr double MaxCoverageMismatch = 1.5; // % of the pixels covered by either frame
} // namespace

TEST(CurvedReliefSilhouette, CylinderOutlineMatchesTheDenseMesh)
{
  Coverage curved, flat;
  Measure("cylinder", curved, flat);
  EXPECT_LE(curved.Percent(), MaxCoverageMismatch);
  // Negative: the flat-plane march keeps the coarse mesh's outline.
  EXPECT_GT(flat.Percent(), MaxCoverageMismatch);
  EXPECT_GT(flat.Mismatched, 3 * curved.Mismatched);
}

TEST(CurvedReliefSilhouette, SphereOutlineMatchesTheDenseMesh)
{
  Coverage curved, flat;
  Measure("sphere", curved, flat);
  EXPECT_LE(curved.Percent(), MaxCoverageMismatch);
  EXPECT_GT(flat.Percent(), MaxCoverageMismatch);
  EXPECT_GT(flat.Mismatched, 3 * curved.Mismatched);
}

// On a flat mesh every quadric is 0: the mesh carries none, the shader has no curvature code, and
// the image (colour and depth) is the same bit for bit with the setting on or off.
TEST(CurvedReliefSilhouette, FlatMeshDrawsTheSameImage)
{
  GeometryImageSceneOptions o = Scene("plane");
  o.Relief.ViewAzimuth = 20.0;
  o.Relief.ViewAngle = 60.0;
  std::string error;
  vtkSmartPointer<vtkPolyData> mesh;
  ReliefScene on;
  ASSERT_TRUE(BuildGeometryImageReliefScene(o, on, error, &mesh)) << error;
  vtkNew<vtkReliefGeometryCache> cache;
  EXPECT_FALSE(vtkReliefGeometryCache::IsCurved(cache->Prepare(mesh)));
  auto onWindow = MakeOffscreenWindow(o.Relief, on.Renderer);
  const Frame a = CaptureFrame(onWindow);
  o.Relief.SurfaceCurvature = false;
  ReliefScene off;
  ASSERT_TRUE(BuildGeometryImageReliefScene(o, off, error)) << error;
  auto offWindow = MakeOffscreenWindow(o.Relief, off.Renderer);
  const Frame b = CaptureFrame(offWindow);
  ASSERT_EQ(a.Rgb.size(), b.Rgb.size());
  EXPECT_TRUE(a.Rgb == b.Rgb);
  EXPECT_TRUE(a.Depth == b.Depth);
  // The curved cylinder's mesh does carry quadrics (the positive side of the same check).
  ReliefScene cylinder;
  vtkSmartPointer<vtkPolyData> curvedMesh;
  ASSERT_TRUE(BuildGeometryImageReliefScene(Scene("cylinder"), cylinder, error, &curvedMesh))
    << error;
  EXPECT_TRUE(vtkReliefGeometryCache::IsCurved(cache->Prepare(curvedMesh)));
}
