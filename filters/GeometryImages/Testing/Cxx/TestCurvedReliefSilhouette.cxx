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

#include <algorithm>
#include <iostream>

namespace
{
using namespace mesolight;

// The cylinder's axis is v (y): ViewAzimuth 90 turns the camera about it, so at ViewAngle 55 the
// surface turns away from the viewer about 35 degrees from its middle, well inside the 120-degree
// patch. The hemispheres-and-tori pattern has a base 0.9 deep: where the surface turns away the
// dense mesh's outline lies most of the relief depth inside the coarse mesh's.
GeometryImageSceneOptions Scene(const char* surface)
{
  GeometryImageSceneOptions o;
  o.GeometryImage = std::string("procedural:") + surface;
  o.Relief.Pattern = "HemisphereTorus";
  o.Relief.Resolution = 256;
  o.Relief.Width = 300;
  o.Relief.Height = 300;
  o.Relief.DepthScale = 0.06;
  o.Relief.SelfShadowing = false; // the stock mapper has no shadows
  o.Relief.ViewAngle = 55.0;
  o.Relief.ViewAzimuth = 90.0;
  o.Relief.ViewDistance = 2.4;
  o.Relief.LinearSteps = 32;
  o.Relief.RefinementSteps = 8;
  o.Stride = 8;
  return o;
}

struct Coverage
{
  long long Mismatched = 0; // pixels covered by exactly one frame
  long long Either = 0;     // pixels covered by either
  double Percent() const { return Either > 0 ? 100.0 * Mismatched / Either : 100.0; }
};

// Pixels covered by exactly one frame. With outlineOnly, only those of the part of the frame
// where the surface turns away: the covered bounding box without a margin on its left, right and
// bottom, where the patch ends at the texture's own edges (the ends of the cylinder and its
// u = 0 edge, the texture-border rule's business, drawn by both marches alike).
Coverage CompareCoverage(const Frame& a, const Frame& b, bool outlineOnly)
{
  int x0 = a.Width, x1 = -1, y0 = a.Height;
  for (int y = 0; y < a.Height; ++y)
  {
    for (int x = 0; x < a.Width; ++x)
    {
      const size_t p = static_cast<size_t>(y) * a.Width + x;
      if (a.Covered(p) || b.Covered(p))
      {
        x0 = std::min(x0, x);
        x1 = std::max(x1, x);
        y0 = std::min(y0, y);
      }
    }
  }
  const int margin = outlineOnly ? 10 : 0;
  Coverage c;
  for (int y = y0 + margin; y < a.Height; ++y)
  {
    for (int x = x0 + margin; x <= x1 - margin; ++x)
    {
      const size_t p = static_cast<size_t>(y) * a.Width + x;
      const bool ca = a.Covered(p), cb = b.Covered(p);
      c.Mismatched += ca != cb ? 1 : 0;
      c.Either += ca || cb ? 1 : 0;
    }
  }
  return c;
}

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
  curved = CompareCoverage(withCurvature, reference, true);
  flat = CompareCoverage(withoutCurvature, reference, true);
  const Coverage curvedWhole = CompareCoverage(withCurvature, reference, false);
  const Coverage flatWhole = CompareCoverage(withoutCurvature, reference, false);
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
