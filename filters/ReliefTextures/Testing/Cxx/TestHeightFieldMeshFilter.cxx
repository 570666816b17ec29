// SPDX-License-Identifier: BSD-3-Clause
// vtkHeightFieldMeshFilter: the dense displaced reference mesh.
#include "SobelNormals.h"
#include "vtkHeightFieldMeshFilter.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefTextureFilter.h"

#include "MesolightTestUtilities.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"

#include <gtest/gtest.h>

#include <cmath>

using mesolight_test::MessageCapture;

namespace
{
struct Pipeline
{
  vtkNew<vtkProceduralReliefSource> Source;
  vtkNew<vtkReliefTextureFilter> Relief;
  vtkNew<vtkHeightFieldMeshFilter> Mesh;

  Pipeline(int pattern, int w, int h, double depthScale)
  {
    this->Source->SetPattern(pattern);
    this->Source->SetResolution(w, h);
    this->Source->SetFlatDepth(0.3);
    this->Relief->SetInputConnection(this->Source->GetOutputPort(0));
    this->Relief->SetDepthScale(depthScale);
    this->Mesh->SetInputConnection(this->Relief->GetOutputPort());
  }
  vtkPolyData* Update()
  {
    this->Mesh->Update();
    return this->Mesh->GetOutput();
  }
  vtkDataArray* ReliefTexels() { return this->Relief->GetOutput()->GetPointData()->GetScalars(); }
};
}

TEST(vtkHeightFieldMeshFilter, OneVertexPerTexelDisplacedByDepth)
{
  const int w = 24;
  const int h = 16;
  const double scale = 0.1;
  Pipeline p(vtkProceduralReliefSource::SINE_WAVE, w, h, scale);
  vtkPolyData* mesh = p.Update();
  ASSERT_EQ(mesh->GetNumberOfPoints(), w * h);
  EXPECT_EQ(mesh->GetNumberOfPolys(), 2 * (w - 1) * (h - 1));

  vtkDataArray* texels = p.ReliefTexels();
  vtkDataArray* tcoords = mesh->GetPointData()->GetTCoords();
  ASSERT_NE(tcoords, nullptr);
  EXPECT_STREQ(tcoords->GetName(), "TCoords");
  EXPECT_EQ(tcoords->GetNumberOfComponents(), 2);
  ASSERT_NE(mesh->GetPointData()->GetNormals(), nullptr);
  EXPECT_EQ(mesh->GetPointData()->GetScalars(), nullptr) << "Depth must not be active scalars";
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const vtkIdType k = j * w + i;
      double x[3];
      mesh->GetPoint(k, x);
      const double u = (i + 0.5) / w;
      const double v = (j + 0.5) / h;
      EXPECT_NEAR(x[0], u, 1e-6);
      EXPECT_NEAR(x[1], v * h / w, 1e-6); // square texels: Point2 = (0, H/W, 0)
      // z = -depth * DepthScale * width (width 1).
      EXPECT_NEAR(x[2], -texels->GetComponent(k, 3) * scale * 1.0, 1e-6);
      EXPECT_NEAR(tcoords->GetComponent(k, 0), u, 1e-6);
      EXPECT_NEAR(tcoords->GetComponent(k, 1), v, 1e-6);
    }
  }
}

TEST(vtkHeightFieldMeshFilter, FlatMapHasUpNormals)
{
  Pipeline p(vtkProceduralReliefSource::FLAT, 8, 8, 0.5);
  vtkPolyData* mesh = p.Update();
  vtkDataArray* normals = mesh->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  for (vtkIdType k = 0; k < mesh->GetNumberOfPoints(); ++k)
  {
    EXPECT_NEAR(normals->GetComponent(k, 0), 0.0, 1e-6);
    EXPECT_NEAR(normals->GetComponent(k, 1), 0.0, 1e-6);
    EXPECT_NEAR(normals->GetComponent(k, 2), 1.0, 1e-6);
    EXPECT_NEAR(mesh->GetPoint(k)[2], -0.3 * 0.5, 1e-6);
  }
}

TEST(vtkHeightFieldMeshFilter, CustomPlaneFrame)
{
  Pipeline p(vtkProceduralReliefSource::FLAT, 4, 4, 0.5);
  // Plane x = 1 facing -x: T = +z (width 2), B = +y.
  p.Mesh->SetOrigin(1, 2, 3);
  p.Mesh->SetPoint1(1, 2, 5);
  p.Mesh->SetPoint2(1, 7, 3); // direction only: square texels make it 2 long
  vtkPolyData* mesh = p.Update();
  double x[3];
  mesh->GetPoint(0, x);                         // u = v = 1/8
  EXPECT_NEAR(x[0], 1 + 0.3 * 0.5 * 2.0, 1e-6); // displaced along -N = +x by d*k*width
  EXPECT_NEAR(x[1], 2 + 2.0 / 8, 1e-6);
  EXPECT_NEAR(x[2], 3 + 2.0 / 8, 1e-6);
  double n[3];
  mesh->GetPointData()->GetNormals()->GetTuple(0, n);
  EXPECT_NEAR(n[0], -1.0, 1e-6);

  p.Mesh->SquareTexelsOff();
  mesh = p.Update();
  mesh->GetPoint(0, x);
  EXPECT_NEAR(x[1], 2 + 5.0 / 8, 1e-6);
}

TEST(vtkHeightFieldMeshFilter, NormalsFollowTheDepthScale)
{
  const int w = 32;
  Pipeline p(vtkProceduralReliefSource::SINE_WAVE, w, w, 0.05);
  vtkPolyData* mesh = p.Update();
  vtkDataArray* texels = p.ReliefTexels();
  const vtkIdType k = 5 * w + 3;
  // Baked scale: the world normal is the texture's normal (default frame).
  double n[3];
  mesh->GetPointData()->GetNormals()->GetTuple(k, n);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(n[c], 2 * texels->GetComponent(k, c) - 1, 1e-5);
  }
  // Another scale: same as baking the normals with it.
  p.Mesh->UseInputDepthScaleOff();
  p.Mesh->SetDepthScale(0.2);
  mesh = p.Update();
  mesh->GetPointData()->GetNormals()->GetTuple(k, n);
  auto* depth = static_cast<float*>(
    p.Source->GetDepthOutput()->GetPointData()->GetScalars()->GetVoidPointer(0));
  std::vector<float> grad(2 * w * w);
  mesolight::ComputeSobelGradient(depth, w, w, mesolight::BorderMode::Clamp, grad.data());
  float expected[3];
  mesolight::NormalFromGradient(grad[2 * k], grad[2 * k + 1], w, 0.2f, expected);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(n[c], expected[c], 1e-4);
  }
  EXPECT_NEAR(mesh->GetPoint(k)[2], -texels->GetComponent(k, 3) * 0.2, 1e-6);
}

TEST(vtkHeightFieldMeshFilter, BadInput)
{
  vtkNew<vtkHeightFieldMeshFilter> mesh;
  vtkNew<MessageCapture> capture;
  capture->Watch(mesh);
  mesh->Update();
  EXPECT_TRUE(capture->HasError("No input")) << capture->AllErrors();

  capture->Errors.clear();
  vtkNew<vtkImageData> empty;
  mesh->SetInputData(empty);
  mesh->Update();
  EXPECT_TRUE(capture->HasError("empty")) << capture->AllErrors();

  capture->Errors.clear();
  vtkNew<vtkImageData> rgb;
  rgb->SetDimensions(4, 4, 1);
  rgb->AllocateScalars(VTK_FLOAT, 3);
  mesh->SetInputData(rgb);
  mesh->Update();
  EXPECT_TRUE(capture->HasError("4 components")) << capture->AllErrors();
  EXPECT_EQ(mesh->GetOutput()->GetNumberOfPoints(), 0);
}
