// SPDX-License-Identifier: BSD-3-Clause
// vtkReliefPlaneFilter: the plane takes the map's proportions, the texels' and, for a
// georeferenced map, its pixels' on the ground; vtkReliefTextureFilter passes the pixel size on
// so the relief texture gives the same plane as its depth map. A square plane (ParaView's Plane)
// is the negative case; an empty image is refused.
#include "vtkReliefPlaneFilter.h"

#include "MesolightTestUtilities.h"
#include "vtkReliefTextureFilter.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>
#include <limits>

namespace
{
// A w x h depth map with a slope along x, optionally carrying a pixel size (metres along rows,
// along columns) as vtkOIIOImageReader gives a georeferenced file's.
vtkSmartPointer<vtkImageData> DepthMap(
  int w, int h, double alongRow = 0.0, double alongColumn = 0.0)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> depth;
  depth->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  for (vtkIdType k = 0; k < depth->GetNumberOfTuples(); ++k)
  {
    depth->SetValue(k, static_cast<float>(k % w) / static_cast<float>(w));
  }
  image->GetPointData()->SetScalars(depth);
  if (alongRow != 0.0 || alongColumn != 0.0)
  {
    vtkNew<vtkDoubleArray> size;
    size->SetName("MesolightPixelSize");
    size->SetNumberOfComponents(2);
    size->InsertNextTuple2(alongRow, alongColumn);
    image->GetFieldData()->AddArray(size);
  }
  return image;
}

// The plane's width and height.
void PlaneSize(vtkImageData* image, double width, double size[2])
{
  vtkNew<vtkReliefPlaneFilter> plane;
  plane->SetInputData(image);
  plane->SetWidth(width);
  plane->Update();
  double bounds[6];
  plane->GetOutput()->GetBounds(bounds);
  size[0] = bounds[1] - bounds[0];
  size[1] = bounds[3] - bounds[2];
  EXPECT_EQ(bounds[4], 0.0);
  EXPECT_EQ(bounds[5], 0.0);
}
} // namespace

TEST(ReliefPlaneFilter, TakesTheTexelsProportions)
{
  vtkNew<vtkReliefPlaneFilter> plane;
  plane->SetInputData(DepthMap(40, 20));
  plane->Update();
  vtkPolyData* quad = plane->GetOutput();
  ASSERT_EQ(quad->GetNumberOfPoints(), 4);
  ASSERT_EQ(quad->GetNumberOfPolys(), 1);
  // Centred, 1 wide, 0.5 high; (u, v) = (0, 0) at the lower left corner, +z normals.
  const double expected[4][4] = { { -0.5, -0.25, 0, 0 }, { 0.5, -0.25, 1, 0 }, { 0.5, 0.25, 1, 1 },
    { -0.5, 0.25, 0, 1 } };
  vtkDataArray* tcoords = quad->GetPointData()->GetTCoords();
  vtkDataArray* normals = quad->GetPointData()->GetNormals();
  ASSERT_NE(tcoords, nullptr);
  ASSERT_NE(normals, nullptr);
  for (vtkIdType p = 0; p < 4; ++p)
  {
    double x[3];
    quad->GetPoint(p, x);
    EXPECT_DOUBLE_EQ(x[0], expected[p][0]);
    EXPECT_DOUBLE_EQ(x[1], expected[p][1]);
    EXPECT_EQ(tcoords->GetComponent(p, 0), expected[p][2]);
    EXPECT_EQ(tcoords->GetComponent(p, 1), expected[p][3]);
    EXPECT_EQ(normals->GetComponent(p, 2), 1.0);
  }
  double size[2];
  PlaneSize(DepthMap(40, 20), 3.0, size);
  EXPECT_DOUBLE_EQ(size[0], 3.0);
  EXPECT_DOUBLE_EQ(size[1], 1.5);
}

TEST(ReliefPlaneFilter, AGeoreferencedMapTakesItsGroundProportions)
{
  // elev.tif's pixels: 597.89 m along a row, 926.63 m along a column (95 x 90 of them).
  // (The points are floats.)
  double size[2];
  PlaneSize(DepthMap(95, 90, 597.89, 926.63), 1.0, size);
  EXPECT_NEAR(size[1], 90.0 * 926.63 / (95.0 * 597.89), 1e-6);
  EXPECT_NEAR(
    vtkReliefPlaneFilter::GetGroundProportions(DepthMap(95, 90, 597.89, 926.63)), 1.468, 1e-3);
  // Negative: the texels' proportions alone (a square plane is further off still).
  EXPECT_GT(std::abs(size[1] - 90.0 / 95.0), 0.5);

  // The relief texture carries the pixel size on: the same plane from it as from its depth map.
  vtkNew<vtkReliefTextureFilter> bake;
  bake->SetInputData(DepthMap(95, 90, 597.89, 926.63));
  bake->Update();
  ASSERT_NE(bake->GetOutput()->GetFieldData()->GetArray("MesolightPixelSize"), nullptr);
  EXPECT_EQ(vtkReliefPlaneFilter::GetGroundProportions(bake->GetOutput()),
    vtkReliefPlaneFilter::GetGroundProportions(DepthMap(95, 90, 597.89, 926.63)));
}

TEST(ReliefPlaneFilter, WithoutAPixelSizeTheImagesSpacingGivesThePixelShape)
{
  // VTK's own pixel shape: 40 x 20 texels of 2 x 3 units (ParaView's GDAL Raster Reader gives a
  // projected raster's pixel size in metres there).
  auto spaced = DepthMap(40, 20);
  spaced->SetSpacing(2.0, 3.0, 1.0);
  EXPECT_DOUBLE_EQ(vtkReliefPlaneFilter::GetGroundProportions(spaced), 0.75);
  // The pixel size on the ground, where the image carries one, comes first.
  auto both = DepthMap(40, 20, 10.0, 10.0);
  both->SetSpacing(2.0, 3.0, 1.0);
  EXPECT_DOUBLE_EQ(vtkReliefPlaneFilter::GetGroundProportions(both), 0.5);
  // Spacings that are no pixel shape (negative: a flipped axis; a ratio that overflows).
  spaced->SetSpacing(-2.0, 3.0, 1.0);
  EXPECT_DOUBLE_EQ(vtkReliefPlaneFilter::GetGroundProportions(spaced), 0.5);
  spaced->SetSpacing(1e-300, 1e300, 1.0);
  EXPECT_DOUBLE_EQ(vtkReliefPlaneFilter::GetGroundProportions(spaced), 0.5);
}

TEST(ReliefPlaneFilter, AnUnusablePixelSizeLeavesTheTexelsProportions)
{
  const double nan = std::numeric_limits<double>::quiet_NaN();
  const double inf = std::numeric_limits<double>::infinity();
  for (const double bad : { 0.0, -3.0, nan, inf })
  {
    EXPECT_EQ(vtkReliefPlaneFilter::GetGroundProportions(DepthMap(40, 20, bad, 10.0)), 0.5);
    EXPECT_EQ(vtkReliefPlaneFilter::GetGroundProportions(DepthMap(40, 20, 10.0, bad)), 0.5);
  }
  // Sizes whose ratio overflows or vanishes.
  EXPECT_EQ(vtkReliefPlaneFilter::GetGroundProportions(DepthMap(40, 20, 1e-300, 1e300)), 0.5);
  EXPECT_EQ(vtkReliefPlaneFilter::GetGroundProportions(DepthMap(40, 20, 1e300, 1e-300)), 0.5);
  // The relief texture passes no unusable size on.
  vtkNew<vtkReliefTextureFilter> bake;
  bake->SetInputData(DepthMap(40, 20, 10.0, nan));
  bake->Update();
  EXPECT_EQ(bake->GetOutput()->GetFieldData()->GetArray("MesolightPixelSize"), nullptr);
  EXPECT_EQ(vtkReliefPlaneFilter::GetGroundProportions(nullptr), 1.0);
}

TEST(ReliefPlaneFilter, AnEmptyImageIsRefused)
{
  vtkNew<vtkImageData> empty;
  vtkNew<vtkReliefPlaneFilter> plane;
  plane->SetInputData(empty);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(plane);
  plane->Update();
  EXPECT_TRUE(messages->HasError("empty")) << messages->AllErrors();
  EXPECT_EQ(plane->GetOutput()->GetNumberOfPoints(), 0);
}
