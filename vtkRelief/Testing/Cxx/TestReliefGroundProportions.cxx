// SPDX-License-Identifier: BSD-3-Clause
// A georeferenced map keeps its proportions on the ground. A geographic raster's pixels are
// narrower than tall away from the equator (an SRTM tile at 60 N: cos 60.5 = 0.49 as wide as
// tall), so a hill that is round on the ground is an ellipse twice as wide as tall in the
// raster. The relief wall takes the map's ground proportions (vtkReliefPlaneFilter::
// GetGroundProportions, from the pixel size vtkOIIOImageReader reads): the hill must draw round,
// and the relief on that stretched wall must match its dense displaced mesh. The same pixels
// without a georeference (a 16-bit PNG) draw the ellipse: the negative case.
#include "DenseMeshTestScene.h"
#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"

#include "vtkOIIOImageWriter.h"
#include "vtkReliefPlaneFilter.h"

#include <vtkImageData.h>
#include <vtkNew.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <fstream>
#include <iostream>
#include <string>
#include <vector>

namespace
{
using namespace mesolight;

constexpr int Side = 1201;              // an SRTM3 tile's side
constexpr double Peak = 500.0;          // metres
constexpr double RadiusRows = 250.0;    // the hill's radius on the ground, in rows
constexpr double MiddleLatitude = 60.5; // of tile N60E010
constexpr double Pi = 3.14159265358979323846;

// Elevation in metres at column i, row r: a hemisphere round on the ground, an ellipse in the
// raster (RadiusRows / cos(latitude) columns wide).
double Elevation(int i, int r)
{
  const double columns = RadiusRows / std::cos(MiddleLatitude * Pi / 180.0);
  const double x = (i - 0.5 * (Side - 1)) / columns;
  const double y = (r - 0.5 * (Side - 1)) / RadiusRows;
  return Peak * std::sqrt(std::max(0.0, 1.0 - x * x - y * y));
}

// SRTM layout: big-endian int16 metres, no header (the reader takes the latitude from the name).
std::string WriteTile()
{
  const std::string path = test::OutputPath("N60E010.hgt");
  std::ofstream out(path, std::ios::binary);
  for (int r = 0; r < Side; ++r)
  {
    for (int i = 0; i < Side; ++i)
    {
      const auto v =
        static_cast<std::uint16_t>(static_cast<std::int16_t>(std::lround(Elevation(i, r))));
      const char bytes[2] = { static_cast<char>(v >> 8), static_cast<char>(v & 0xff) };
      out.write(bytes, 2);
    }
  }
  return out ? path : std::string();
}

// The same elevations as a 16-bit PNG: no georeference.
std::string WritePngOfTheSamePixels()
{
  vtkNew<vtkImageData> image;
  image->SetDimensions(Side, Side, 1);
  image->AllocateScalars(VTK_UNSIGNED_SHORT, 1);
  auto* p = static_cast<unsigned short*>(image->GetScalarPointer());
  for (int r = 0; r < Side; ++r)
  {
    for (int i = 0; i < Side; ++i)
    {
      p[static_cast<size_t>(r) * Side + i] =
        static_cast<unsigned short>(std::lround(Elevation(i, r) / Peak * 65535.0));
    }
  }
  const std::string path = test::OutputPath("hill-without-georeference.png");
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(image);
  writer->SetFileName(path.c_str());
  writer->SetDataTypeToUnsignedShort();
  return writer->Write() ? path : std::string();
}

ReliefSceneOptions HillScene(const std::string& file)
{
  ReliefSceneOptions o;
  o.DepthFile = file;
  o.DepthFileIsHeight = true;
  o.NormalizeDepthFile = true;
  o.Method = "max-mipmap";
  o.LinearSteps = 64;
  o.RefinementSteps = 0;
  o.DepthScale = 0.1;
  o.SelfShadowing = false;
  o.Width = 400;
  o.Height = 400;
  return o;
}

// Width over height, in pixels, of the hill seen from straight above: the pixels nearer the eye
// than the plain around it (by a tenth of the relief's depth).
double HillAspectFromAbove(const std::string& file, double& wallHeight)
{
  ReliefSceneOptions o = HillScene(file);
  o.ViewAngle = 0.0;
  o.ViewAzimuth = 0.0;
  ReliefScene scene;
  std::string error;
  EXPECT_TRUE(BuildReliefScene(o, scene, error)) << error;
  if (!scene.Renderer)
  {
    return 0.0;
  }
  wallHeight = vtkReliefPlaneFilter::GetGroundProportions(scene.ReliefTexture);
  auto window = MakeOffscreenWindow(o, scene.Renderer);
  const Frame frame = CaptureFrame(window);
  double plain = 0.0; // the farthest covered eye depth: the plain around the hill
  for (size_t p = 0; p < frame.Depth.size(); ++p)
  {
    plain = frame.Covered(p) ? std::max(plain, frame.EyeDepth(p)) : plain;
  }
  int lo[2] = { frame.Width, frame.Height }, hi[2] = { -1, -1 };
  for (int y = 0; y < frame.Height; ++y)
  {
    for (int x = 0; x < frame.Width; ++x)
    {
      const size_t p = static_cast<size_t>(y) * frame.Width + x;
      if (frame.Covered(p) && frame.EyeDepth(p) < plain - 0.1 * o.DepthScale)
      {
        lo[0] = std::min(lo[0], x);
        lo[1] = std::min(lo[1], y);
        hi[0] = std::max(hi[0], x);
        hi[1] = std::max(hi[1], y);
      }
    }
  }
  if (hi[0] < lo[0] || hi[1] < lo[1])
  {
    ADD_FAILURE() << "no hill in the view of " << file;
    return 0.0;
  }
  const double aspect = double(hi[0] - lo[0] + 1) / double(hi[1] - lo[1] + 1);
  std::cout << "[" << file << "] wall height " << wallHeight << ", hill " << hi[0] - lo[0] + 1
            << " x " << hi[1] - lo[1] + 1 << " pixels from above (width / height " << aspect << ")"
            << std::endl;
  return aspect;
}
} // namespace

TEST(ReliefGroundProportions, AGeographicMapDrawsRoundWhatIsRoundOnTheGround)
{
  const std::string tile = WriteTile();
  ASSERT_FALSE(tile.empty());
  double wallHeight = 0.0;
  const double aspect = HillAspectFromAbove(tile, wallHeight);
  // The wall is as tall, for its width, as the tile on the ground: 1 / cos(60.5 degrees).
  EXPECT_NEAR(wallHeight, 1.0 / std::cos(MiddleLatitude * Pi / 180.0), 1e-3);
  EXPECT_NEAR(aspect, 1.0, 0.03) << "a hill round on the ground must draw round";

  // Negative: the same pixels without a georeference are square texels, and the hill an ellipse.
  const std::string png = WritePngOfTheSamePixels();
  ASSERT_FALSE(png.empty());
  double squareWall = 0.0;
  const double squareAspect = HillAspectFromAbove(png, squareWall);
  EXPECT_EQ(squareWall, 1.0);
  EXPECT_NEAR(squareAspect, 1.0 / std::cos(MiddleLatitude * Pi / 180.0), 0.1);
}

// The relief on the stretched wall against its dense displaced mesh on the same wall: shading
// normals, depth and silhouettes hold when a texel is not square in the world.
TEST(ReliefGroundProportions, TheReliefOnAStretchedWallMatchesItsDenseMesh)
{
  const std::string tile = WriteTile();
  ASSERT_FALSE(tile.empty());
  ReliefSceneOptions o = HillScene(tile);
  o.ViewAngle = 55.0;
  const FrameDifference d = test::CompareWithDenseMesh(o, "ground-proportions");
  EXPECT_GT(d.CoveredBoth, o.Width * o.Height / 8);
  EXPECT_LE(d.MeanColorError, 3.0);
  EXPECT_LE(d.SilhouetteMismatch, 1.0);
  EXPECT_LE(d.DepthMismatch, 5.0);
}
