// SPDX-License-Identifier: BSD-3-Clause
// The geometry image core against analytic cases: exact planes, vertices on the cylinder at their
// pixels, the cylinder's chord error (the sagitta), texel-for-texel texture coordinates (a
// half-texel shift must fail), holes, crack-free adaptive meshes within their tolerance.
#include "GeometryImageMesh.h"
#include "MathConstants.h"
#include "ProceduralGeometryImages.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <map>
#include <utility>

namespace
{
using namespace mesolight;

// Bilinear lookup at (u, v) as GL_LINEAR does: texel (i, j) has its centre at ((i+.5)/W, (j+.5)/H).
double Bilinear(const std::vector<double>& texels, int w, int h, double u, double v)
{
  const double x = u * w - 0.5, y = v * h - 0.5;
  const int i0 = std::clamp(static_cast<int>(std::floor(x)), 0, w - 1);
  const int j0 = std::clamp(static_cast<int>(std::floor(y)), 0, h - 1);
  const int i1 = std::min(i0 + 1, w - 1), j1 = std::min(j0 + 1, h - 1);
  const double fx = std::clamp(x - i0, 0.0, 1.0), fy = std::clamp(y - j0, 0.0, 1.0);
  const auto t = [&](int i, int j) { return texels[static_cast<size_t>(j) * w + i]; };
  return (1 - fy) * ((1 - fx) * t(i0, j0) + fx * t(i1, j0)) +
    fy * ((1 - fx) * t(i0, j1) + fx * t(i1, j1));
}

// Largest difference between a colour image looked up at the mesh's texture coordinates and the
// texel of each vertex's pixel: 0 when the coordinates map texel for texel.
double TexelForTexelError(
  const GeometryImageMesh& mesh, int w, int h, const std::vector<glm::dvec2>& tcoords)
{
  std::vector<double> colour(static_cast<size_t>(w) * h);
  for (size_t k = 0; k < colour.size(); ++k)
  {
    colour[k] = static_cast<double>((k * 7919) % 251); // no two neighbours alike
  }
  double worst = 0.0;
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    const glm::ivec2 px = mesh.Pixels[p];
    const double expected = colour[static_cast<size_t>(px.y) * w + px.x];
    worst =
      std::max(worst, std::abs(Bilinear(colour, w, h, tcoords[p].x, tcoords[p].y) - expected));
  }
  return worst;
}

// Edge -> number of triangles using it.
std::map<std::pair<int, int>, int> EdgeUse(const GeometryImageMesh& mesh)
{
  std::map<std::pair<int, int>, int> edges;
  for (const glm::ivec3& t : mesh.Triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const int a = t[k], b = t[(k + 1) % 3];
      ++edges[{ std::min(a, b), std::max(a, b) }];
    }
  }
  return edges;
}

// Signed area of a triangle in pixel space (positive: counter-clockwise).
double PixelArea(const GeometryImageMesh& mesh, const glm::ivec3& t)
{
  const glm::dvec2 a(mesh.Pixels[t[0]]), b(mesh.Pixels[t[1]]), c(mesh.Pixels[t[2]]);
  return 0.5 * ((b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y));
}

// No cracks: every triangle counter-clockwise and non-degenerate in pixel space, their areas tile
// the image, every edge inside the image shared by exactly two triangles and every edge on its
// border by one (a T-junction leaves an edge used once inside the image).
void ExpectWatertight(const GeometryImageMesh& mesh, int w, int h)
{
  double area = 0.0;
  for (const glm::ivec3& t : mesh.Triangles)
  {
    const double a = PixelArea(mesh, t);
    EXPECT_GT(a, 0.0);
    area += a;
  }
  EXPECT_NEAR(area, static_cast<double>(w - 1) * (h - 1), 1e-9);
  int interior = 0, border = 0;
  for (const auto& [edge, count] : EdgeUse(mesh))
  {
    const glm::ivec2 a = mesh.Pixels[edge.first], b = mesh.Pixels[edge.second];
    const bool onBorder =
      (a.x == b.x && (a.x == 0 || a.x == w - 1)) || (a.y == b.y && (a.y == 0 || a.y == h - 1));
    EXPECT_EQ(count, onBorder ? 1 : 2)
      << "edge (" << a.x << "," << a.y << ")-(" << b.x << "," << b.y << ")";
    (onBorder ? border : interior) += 1;
  }
  EXPECT_GT(interior, 0);
  EXPECT_GT(border, 0);
}
/// The message of the GeometryImageMeshError `call` throws, or "" when it throws none.
template <typename Call>
std::string Refusal(const Call& call)
{
  try
  {
    call();
  }
  catch (const GeometryImageMeshError& e)
  {
    return e.what();
  }
  return std::string();
}
} // namespace

TEST(GeometryImageMesh, PlaneIsExactAtEveryStride)
{
  const GeometryImage plane = MakeGeometryImage(GeometrySurface::Plane, 65, 49);
  for (int stride : { 1, 4, 16, 64 })
  {
    GeometryImageMesh mesh;
    ASSERT_NO_THROW(mesh = SampleRegular(plane, stride));
    const HausdorffDistance d = MeasureHausdorff(plane, mesh);
    EXPECT_LT(d.Hausdorff, 1e-12) << "stride " << stride;
    for (size_t p = 0; p < mesh.Points.size(); ++p)
    {
      EXPECT_DOUBLE_EQ(mesh.Points[p].x, mesh.TCoords[p].x);
      EXPECT_DOUBLE_EQ(mesh.Points[p].y, mesh.TCoords[p].y);
      EXPECT_NEAR(mesh.Normals[p].z, 1.0, 1e-12);
    }
  }
}

TEST(GeometryImageMesh, CylinderVerticesAreTheSurfaceAtTheirPixels)
{
  const int w = 96, h = 40;
  const GeometryImage cylinder = MakeGeometryImage(GeometrySurface::Cylinder, w, h);
  GeometryImageMesh mesh;
  ASSERT_NO_THROW(mesh = SampleRegular(cylinder, 7));
  const double r = 1.5 / Pi<double>; // arc length 1 over 120 degrees
  for (size_t p = 0; p < mesh.Points.size(); ++p)
  {
    glm::dvec3 n;
    const glm::dvec3 s =
      SurfacePoint(GeometrySurface::Cylinder, mesh.TCoords[p].x, mesh.TCoords[p].y, &n);
    EXPECT_LT(glm::distance(mesh.Points[p], s), 1e-12);
    EXPECT_LT(glm::distance(mesh.Normals[p], n), 1e-12);
    // On the cylinder of radius r about the axis x = 0.5, z = -r.
    EXPECT_NEAR(std::hypot(mesh.Points[p].x - 0.5, mesh.Points[p].z + r), r, 1e-12);
  }
}

// The chord error of a cylinder sampled every k pixels is the sagitta r (1 - cos(k dphi / 2)):
// the pixel halfway between two samples lies that far from the chord.
TEST(GeometryImageMesh, CylinderChordErrorIsTheSagitta)
{
  const int w = 129, h = 17;
  const GeometryImage cylinder = MakeGeometryImage(GeometrySurface::Cylinder, w, h);
  const double r = 1.5 / Pi<double>;
  const double dphi = 2.0 * Pi<double> / 3.0 / w;
  for (int stride : { 4, 8, 16 })
  {
    GeometryImageMesh mesh;
    ASSERT_NO_THROW(mesh = SampleRegular(cylinder, stride));
    const HausdorffDistance d = MeasureHausdorff(cylinder, mesh);
    const double sagitta = r * (1.0 - std::cos(0.5 * stride * dphi));
    EXPECT_NEAR(d.ImageToMesh, sagitta, 1e-3 * sagitta) << "stride " << stride;
    EXPECT_LE(d.MeshToImage, d.ImageToMesh * 1.01);
  }
}

TEST(GeometryImageMesh, StrideCoversTheWholeImage)
{
  const int w = 50, h = 37, stride = 8;
  const GeometryImage wave = MakeGeometryImage(GeometrySurface::Wave, w, h);
  GeometryImageMesh mesh;
  ASSERT_NO_THROW(mesh = SampleRegular(wave, stride));
  const int quadsX = (w - 2) / stride + 1, quadsY = (h - 2) / stride + 1; // ceil((n-1)/k)
  EXPECT_EQ(mesh.Triangles.size(), static_cast<size_t>(2 * quadsX * quadsY));
  EXPECT_EQ(mesh.Points.size(), static_cast<size_t>((quadsX + 1) * (quadsY + 1)));
  ExpectWatertight(mesh, w, h);
}

TEST(GeometryImageMesh, TextureCoordinatesMapTexelForTexel)
{
  const int w = 37, h = 23;
  const GeometryImage sphere = MakeGeometryImage(GeometrySurface::SpherePatch, w, h);
  GeometryImageMesh mesh;
  ASSERT_NO_THROW(mesh = SampleRegular(sphere, 3));
  EXPECT_LT(TexelForTexelError(mesh, w, h, mesh.TCoords), 1e-9);
  // Negative: the pixel-corner convention i / W and the end-to-end one i / (W - 1) blend
  // neighbouring texels and must fail the same check.
  std::vector<glm::dvec2> corner, endToEnd;
  for (const glm::ivec2& px : mesh.Pixels)
  {
    corner.emplace_back(static_cast<double>(px.x) / w, static_cast<double>(px.y) / h);
    endToEnd.emplace_back(static_cast<double>(px.x) / (w - 1), static_cast<double>(px.y) / (h - 1));
  }
  EXPECT_GT(TexelForTexelError(mesh, w, h, corner), 10.0);
  EXPECT_GT(TexelForTexelError(mesh, w, h, endToEnd), 10.0);
}

TEST(GeometryImageMesh, NaNHolesDropTheirQuads)
{
  const int w = 33, h = 33;
  GeometryImage plane = MakeGeometryImage(GeometrySurface::Plane, w, h);
  const double nan = std::numeric_limits<double>::quiet_NaN();
  plane.Positions[plane.Index(10, 12)] = glm::dvec3(nan);
  GeometryImageMesh full, coarse;
  ASSERT_NO_THROW(full = SampleRegular(plane, 1));
  EXPECT_EQ(full.Triangles.size(), static_cast<size_t>(2 * (32 * 32 - 4)));
  EXPECT_EQ(full.SkippedQuads, 4u);
  // At stride 8 the empty pixel is inside a quad (not a corner): that quad is dropped too.
  ASSERT_NO_THROW(coarse = SampleRegular(plane, 8));
  EXPECT_EQ(coarse.Triangles.size(), static_cast<size_t>(2 * (16 - 1)));
  for (const GeometryImageMesh* m : { &full, &coarse })
  {
    for (const glm::dvec3& p : m->Points)
    {
      EXPECT_TRUE(std::isfinite(p.x) && std::isfinite(p.y) && std::isfinite(p.z));
    }
  }
  GeometryImageMesh adaptive;
  ASSERT_NO_THROW(adaptive = SampleAdaptive(plane, 1e-3));
  EXPECT_EQ(adaptive.SkippedQuads, 4u); // refined down to the four pixel quads around the hole
  for (const auto& [edge, count] : EdgeUse(adaptive))
  {
    EXPECT_LE(count, 2);
  }
}

TEST(GeometryImageMesh, BadInputIsRefusedWithAMessage)
{
  const GeometryImage plane = MakeGeometryImage(GeometrySurface::Plane, 20, 10);
  std::string error = Refusal([&] { SampleRegular(plane, 0); });
  EXPECT_NE(error.find("stride 0"), std::string::npos) << error;
  error = Refusal([&] { SampleRegular(plane, 20); });
  EXPECT_NE(error.find("1..19"), std::string::npos) << error;
  GeometryImageMesh mesh;
  ASSERT_NO_THROW(mesh = SampleRegular(plane, 19));
  EXPECT_EQ(mesh.Triangles.size(), 2u);
  error = Refusal([&] { SampleAdaptive(plane, 0.0); });
  EXPECT_NE(error.find("tolerance"), std::string::npos) << error;
  GeometryImage empty = plane;
  for (glm::dvec3& p : empty.Positions)
  {
    p = glm::dvec3(std::numeric_limits<double>::quiet_NaN());
  }
  error = Refusal([&] { SampleRegular(empty, 4); });
  EXPECT_NE(error.find("empty"), std::string::npos) << error;
  EXPECT_FALSE(Refusal([&] { SampleAdaptive(empty, 0.01); }).empty());
  const GeometryImage line = MakeGeometryImage(GeometrySurface::Plane, 20, 1);
  error = Refusal([&] { SampleRegular(line, 1); });
  EXPECT_NE(error.find("2 x 2"), std::string::npos) << error;
}

TEST(GeometryImageMesh, AdaptiveMeshesHaveNoCracks)
{
  for (GeometrySurface s :
    { GeometrySurface::Bump, GeometrySurface::SpherePatch, GeometrySurface::Wave })
  {
    for (int w : { 65, 90 })
    {
      const GeometryImage image = MakeGeometryImage(s, w, 71);
      for (double tolerance : { 0.01, 0.002 })
      {
        GeometryImageMesh mesh;
        ASSERT_NO_THROW(mesh = SampleAdaptive(image, tolerance));
        SCOPED_TRACE(std::string(GeometrySurfaceName(s)) + " " + std::to_string(w) + " tol " +
          std::to_string(tolerance));
        ExpectWatertight(mesh, w, 71);
      }
    }
  }
}

TEST(GeometryImageMesh, AdaptiveHausdorffStaysWithinTheToleranceAndFallsWithIt)
{
  const GeometryImage bump = MakeGeometryImage(GeometrySurface::Bump, 129, 129);
  double previous = std::numeric_limits<double>::infinity();
  size_t previousTriangles = 0;
  for (double tolerance : { 0.02, 0.01, 0.005, 0.0025, 0.00125 })
  {
    GeometryImageMesh mesh;
    ASSERT_NO_THROW(mesh = SampleAdaptive(bump, tolerance));
    const HausdorffDistance d = MeasureHausdorff(bump, mesh);
    std::cout << "tolerance " << tolerance << ": " << mesh.Triangles.size() << " triangles, "
              << "Hausdorff " << d.Hausdorff << " (image to mesh " << d.ImageToMesh
              << ", mesh to image " << d.MeshToImage << ")" << std::endl;
    EXPECT_LE(d.ImageToMesh, tolerance + 1e-12);
    EXPECT_LE(d.Hausdorff, tolerance + 1e-12);
    EXPECT_LT(d.Hausdorff, previous);
    EXPECT_GT(mesh.Triangles.size(), previousTriangles);
    previous = d.Hausdorff;
    previousTriangles = mesh.Triangles.size();
  }
}

// Where the surface is flat and bent only in the middle, adaptive sampling needs fewer triangles
// than the regular stride for the same geometric error.
TEST(GeometryImageMesh, AdaptiveBeatsTheRegularStrideOnABump)
{
  const GeometryImage bump = MakeGeometryImage(GeometrySurface::Bump, 129, 129);
  GeometryImageMesh regular;
  ASSERT_NO_THROW(regular = SampleRegular(bump, 8));
  const HausdorffDistance r = MeasureHausdorff(bump, regular);
  GeometryImageMesh adaptive;
  ASSERT_NO_THROW(adaptive = SampleAdaptive(bump, r.Hausdorff));
  const HausdorffDistance a = MeasureHausdorff(bump, adaptive);
  std::cout << "regular stride 8: " << regular.Triangles.size() << " triangles, Hausdorff "
            << r.Hausdorff << "; adaptive: " << adaptive.Triangles.size() << " triangles, "
            << a.Hausdorff << std::endl;
  EXPECT_LE(a.Hausdorff, r.Hausdorff + 1e-12);
  EXPECT_LT(adaptive.Triangles.size(), regular.Triangles.size() / 2);
}

TEST(GeometryImageMesh, DisplacementMovesAlongTheNormalByDepthTimesScale)
{
  const int w = 64, h = 32;
  const GeometryImage cylinder = MakeGeometryImage(GeometrySurface::Cylinder, w, h);
  std::vector<float> depth(static_cast<size_t>(w) * h, 0.5f);
  const GeometryImage displaced = DisplaceGeometryImage(cylinder, depth, 0.04);
  const double r = 1.5 / Pi<double>;
  // |dP/du| is 1 (arc length 1); the central difference of the chord is sin(x)/x short of it.
  const double x = 2.0 * Pi<double> / 3.0 / w;
  const double expected = r - 0.5 * 0.04 * std::sin(x) / x;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 1; i + 1 < w; ++i)
    {
      const glm::dvec3 p = displaced.At(i, j);
      EXPECT_NEAR(std::hypot(p.x - 0.5, p.z + r), expected, 1e-12);
    }
  }
  const std::string error =
    Refusal([&] { DisplaceGeometryImage(cylinder, std::vector<float>(10), 0.04); });
  EXPECT_NE(error.find("one per pixel"), std::string::npos) << error;
}

// The grid-accelerated Hausdorff distance against brute force (every pixel to every triangle, every
// sample to every full-resolution triangle).
TEST(GeometryImageMesh, HausdorffMatchesBruteForce)
{
  for (GeometrySurface s : { GeometrySurface::SpherePatch, GeometrySurface::Bump })
  {
    const GeometryImage image = MakeGeometryImage(s, 41, 29);
    GeometryImageMesh coarse, full;
    ASSERT_NO_THROW(coarse = SampleAdaptive(image, 0.01));
    ASSERT_NO_THROW(full = SampleRegular(image, 1));
    const auto nearest = [](const GeometryImageMesh& m, const glm::dvec3& p)
    {
      double best = std::numeric_limits<double>::infinity();
      for (const glm::ivec3& t : m.Triangles)
      {
        best =
          std::min(best, PointTriangleDistance(p, m.Points[t[0]], m.Points[t[1]], m.Points[t[2]]));
      }
      return best;
    };
    double imageToMesh = 0.0, meshToImage = 0.0;
    for (const glm::dvec3& p : image.Positions)
    {
      imageToMesh = std::max(imageToMesh, nearest(coarse, p));
    }
    const int n = 4;
    for (const glm::ivec3& t : coarse.Triangles)
    {
      for (int a = 0; a <= n; ++a)
      {
        for (int b = 0; a + b <= n; ++b)
        {
          const double wa = static_cast<double>(a) / n, wb = static_cast<double>(b) / n;
          const glm::dvec3 p = wa * coarse.Points[t[0]] + wb * coarse.Points[t[1]] +
            (1.0 - wa - wb) * coarse.Points[t[2]];
          meshToImage = std::max(meshToImage, nearest(full, p));
        }
      }
    }
    const HausdorffDistance d = MeasureHausdorff(image, coarse, n);
    EXPECT_NEAR(d.ImageToMesh, imageToMesh, 1e-12) << GeometrySurfaceName(s);
    EXPECT_NEAR(d.MeshToImage, meshToImage, 1e-12) << GeometrySurfaceName(s);
    EXPECT_GT(imageToMesh, 0.0);
  }
}
