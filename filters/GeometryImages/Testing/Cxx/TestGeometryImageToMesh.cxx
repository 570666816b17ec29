// SPDX-License-Identifier: BSD-3-Clause
// vtkGeometryImageSource -> vtkGeometryImageToMesh: arrays, counts, the normal image port, holes,
// adaptive sampling and bad input with clear messages.
#include "MesolightTestUtilities.h"
#include "vtkGeometryImageSource.h"
#include "vtkGeometryImageToMesh.h"

#include <vtkCellArray.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <string>

using mesolight_test::MessageCapture;

TEST(GeometryImageToMesh, CylinderAtStrideTwentyHasTexelCentreCoordinatesAndNormals)
{
  vtkNew<vtkGeometryImageSource> source;
  source->SetSurfaceToCylinder();
  source->SetResolution(101, 61);
  vtkNew<vtkGeometryImageToMesh> mesh;
  mesh->SetInputConnection(source->GetOutputPort());
  mesh->Update();
  vtkPolyData* out = mesh->GetOutput();
  // Columns 0, 20, ..., 100 and rows 0, 20, 40, 60: 5 x 3 quads.
  EXPECT_EQ(out->GetNumberOfPolys(), 2 * 5 * 3);
  EXPECT_EQ(out->GetNumberOfPoints(), 6 * 4);
  vtkDataArray* tc = out->GetPointData()->GetTCoords();
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  ASSERT_NE(tc, nullptr);
  ASSERT_NE(normals, nullptr);
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    // u = (i + 0.5) / W with i a multiple of 20 or the last column.
    const double i = tc->GetComponent(p, 0) * 101 - 0.5;
    EXPECT_NEAR(i, std::round(i), 1e-4);
    EXPECT_TRUE(static_cast<int>(std::round(i)) % 20 == 0);
    double x[3], n[3];
    out->GetPoint(p, x);
    normals->GetTuple(p, n);
    // The cylinder's normal points away from its axis (x = 0.5, z = -r).
    const double r = 1.5 / 3.141592653589793;
    EXPECT_NEAR(n[0] * (x[0] - 0.5) + n[2] * (x[2] + r), r, 1e-5);
  }
}

TEST(GeometryImageToMesh, NormalImagePortOverridesTheImagesNormals)
{
  vtkNew<vtkGeometryImageSource> source;
  source->SetSurfaceToPlane();
  source->SetResolution(9, 9);
  vtkNew<vtkImageData> tilted;
  tilted->SetDimensions(9, 9, 1);
  tilted->AllocateScalars(VTK_FLOAT, 3);
  for (vtkIdType k = 0; k < 81; ++k)
  {
    tilted->GetPointData()->GetScalars()->SetTuple3(k, 0.0, 3.0, 4.0);
  }
  vtkNew<vtkGeometryImageToMesh> mesh;
  mesh->SetInputConnection(source->GetOutputPort());
  mesh->SetNormalImageConnection(nullptr);
  mesh->SetInputData(1, tilted);
  mesh->SetStride(4);
  mesh->Update();
  double n[3];
  mesh->GetOutput()->GetPointData()->GetNormals()->GetTuple(0, n);
  EXPECT_NEAR(n[1], 0.6, 1e-6);
  EXPECT_NEAR(n[2], 0.8, 1e-6);
}

TEST(GeometryImageToMesh, HolesAndAdaptiveSampling)
{
  vtkNew<vtkGeometryImageSource> source;
  source->SetSurfaceToBump();
  source->SetResolution(129, 129);
  source->HolesOn();
  vtkNew<vtkGeometryImageToMesh> mesh;
  mesh->SetInputConnection(source->GetOutputPort());
  mesh->SetStride(8);
  mesh->Update();
  const vtkIdType withHoles = mesh->GetOutput()->GetNumberOfPolys();
  EXPECT_LT(withHoles, 2 * 16 * 16);
  EXPECT_GT(withHoles, 2 * 16 * 16 * 3 / 4);
  for (vtkIdType p = 0; p < mesh->GetOutput()->GetNumberOfPoints(); ++p)
  {
    double x[3];
    mesh->GetOutput()->GetPoint(p, x);
    EXPECT_TRUE(std::isfinite(x[0]) && std::isfinite(x[1]) && std::isfinite(x[2]));
  }
  source->HolesOff();
  mesh->SetTolerance(0.005);
  mesh->Update();
  EXPECT_GT(mesh->GetOutput()->GetNumberOfPolys(), 8);
  EXPECT_LT(mesh->GetOutput()->GetNumberOfPolys(), 2 * 16 * 16);
}

TEST(GeometryImageToMesh, BadInputGivesAClearError)
{
  vtkNew<MessageCapture> messages;
  vtkNew<vtkGeometryImageToMesh> mesh;
  messages->Watch(mesh);
  mesh->Update();
  EXPECT_TRUE(messages->HasError("no geometry image")) << messages->AllErrors();

  vtkNew<vtkImageData> grey;
  grey->SetDimensions(16, 16, 1);
  grey->AllocateScalars(VTK_FLOAT, 1);
  mesh->SetInputData(grey);
  mesh->Update();
  EXPECT_TRUE(messages->HasError("3 components")) << messages->AllErrors();

  vtkNew<vtkGeometryImageSource> source;
  source->SetResolution(16, 16);
  mesh->SetInputConnection(source->GetOutputPort());
  mesh->SetStride(40);
  mesh->Update();
  EXPECT_TRUE(messages->HasError("stride 40 is outside 1..15")) << messages->AllErrors();
  EXPECT_EQ(mesh->GetOutput()->GetNumberOfPolys(), 0);

  vtkNew<vtkImageData> holes;
  holes->SetDimensions(8, 8, 1);
  holes->AllocateScalars(VTK_FLOAT, 3);
  holes->GetPointData()->GetScalars()->Fill(std::numeric_limits<double>::quiet_NaN());
  mesh->SetInputData(holes);
  mesh->SetStride(2);
  mesh->Update();
  EXPECT_TRUE(messages->HasError("every pixel of the geometry image is empty"))
    << messages->AllErrors();

  vtkNew<vtkImageData> wrongNormals;
  wrongNormals->SetDimensions(4, 4, 1);
  wrongNormals->AllocateScalars(VTK_FLOAT, 3);
  mesh->SetInputConnection(source->GetOutputPort());
  mesh->SetInputData(1, wrongNormals);
  mesh->Update();
  EXPECT_TRUE(messages->HasError("normal image must have")) << messages->AllErrors();
}

namespace
{
// A 16 x 16 geometry image whose pixel (i, j) is at f(i, j).
template <class F>
vtkSmartPointer<vtkImageData> GeometryImageOf(F&& f)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(16, 16, 1);
  image->AllocateScalars(VTK_FLOAT, 3);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  for (int j = 0; j < 16; ++j)
  {
    for (int i = 0; i < 16; ++i)
    {
      double p[3];
      f(i, j, p);
      scalars->SetTuple(j * 16 + i, p);
    }
  }
  return image;
}

// Meshes `image` at stride 3 and adaptively; true when both fail with `needle` and no triangles.
::testing::AssertionResult RefusedWith(vtkImageData* image, const std::string& needle)
{
  for (const double tolerance : { 0.0, 1e-3 })
  {
    vtkNew<MessageCapture> messages;
    vtkNew<vtkGeometryImageToMesh> mesh;
    messages->Watch(mesh);
    mesh->SetInputData(image);
    mesh->SetStride(3);
    mesh->SetTolerance(tolerance);
    mesh->Update();
    if (!messages->HasError(needle) || mesh->GetOutput()->GetNumberOfPolys() != 0)
    {
      return ::testing::AssertionFailure()
        << "tolerance " << tolerance << ": " << mesh->GetOutput()->GetNumberOfPolys()
        << " triangles, errors: " << messages->AllErrors();
    }
  }
  return ::testing::AssertionSuccess();
}
} // namespace

// Geometry images whose triangles all have zero (or overflowing) area in single precision gave
// "N triangles" and a background-only render with exit 0: now a clear error.
// An 8-bit RGB image (a colour picture given as a geometry image) is meshed, with a warning that
// its colours are read as positions; the float geometry image of the source gets none.
TEST(GeometryImageToMesh, EightBitImagesAreWarnedAbout)
{
  vtkNew<vtkImageData> picture;
  picture->SetDimensions(8, 8, 1);
  picture->AllocateScalars(VTK_UNSIGNED_CHAR, 3);
  vtkDataArray* rgb = picture->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < 64; ++p)
  {
    rgb->SetTuple3(p, 10 + 20 * (p % 8), 10 + 20 * (p / 8), 100);
  }
  vtkNew<MessageCapture> messages;
  vtkNew<vtkGeometryImageToMesh> mesh;
  messages->Watch(mesh);
  mesh->SetInputData(picture);
  mesh->SetStride(1);
  mesh->Update();
  EXPECT_TRUE(messages->HasWarning("The geometry image is 8-bit")) << messages->AllWarnings();
  EXPECT_GT(mesh->GetOutput()->GetNumberOfPolys(), 0);
  messages->Warnings.clear();
  vtkNew<vtkGeometryImageSource> source;
  source->SetResolution(16, 16);
  mesh->SetInputConnection(source->GetOutputPort());
  mesh->Update();
  EXPECT_FALSE(messages->HasWarning("8-bit")) << messages->AllWarnings();
}

TEST(GeometryImageToMesh, DegenerateGeometryImagesAreRefused)
{
  EXPECT_TRUE(RefusedWith(GeometryImageOf([](int, int, double* p) { p[0] = p[1] = p[2] = 0.5; }),
    "all its positions are the same point"));
  EXPECT_TRUE(RefusedWith(
    GeometryImageOf([](int i, int, double* p) { p[0] = p[1] = p[2] = i; }), "collinear"));
  for (const double scale : { 1e-30, 1e30, 2e37 })
  {
    EXPECT_TRUE(RefusedWith(GeometryImageOf(
                              [scale](int i, int j, double* p)
                              {
                                p[0] = scale * i;
                                p[1] = scale * j;
                                p[2] = 0.0;
                              }),
      scale < 1.0 ? "too small" : "too large"))
      << scale;
  }
  // The same plane at ordinary and at large but representable scales still meshes.
  for (const double scale : { 1e-12, 1.0, 1e12 })
  {
    vtkNew<vtkGeometryImageToMesh> mesh;
    mesh->SetInputData(GeometryImageOf(
      [scale](int i, int j, double* p)
      {
        p[0] = scale * i;
        p[1] = scale * j;
        p[2] = 0.0;
      }));
    mesh->SetStride(3);
    mesh->Update();
    EXPECT_EQ(mesh->GetOutput()->GetNumberOfPolys(), 2 * 5 * 5) << scale;
  }
}
