// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldObjectReliefProbes: the charts and probe images of a vtkLightFieldActor's movable
// object in vtkReliefMapper's probe layout (coefficient k of probe (i, j) at pixel (9 i + k, j)),
// equal to the core's probes at the actor's placement; regathered when the object moves; an
// object without texture coordinates reported with a message saying how to get them.
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldObjectReliefProbes.h"

#include "vtkActor.h"
#include "vtkImageData.h"
#include "vtkMatrix4x4.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkPolyDataMapper.h"
#include "vtkTriangleSceneConverter.h"

#include "LightField.h"
#include "MessageCapture.h"
#include "ObjectMesh.h"
#include "ObjectReliefProbes.h"
#include "WalkthroughTestFields.h"

#include <glm/gtc/matrix_transform.hpp>

#include <gtest/gtest.h>

#include <cmath>

using namespace mesolight;

namespace
{
} // namespace

TEST(LightFieldObjectReliefProbes, ImagesHoldTheCoreProbesInTheMappersLayout)
{
  const vlf::LightField& field = walkthroughtest::PlainCornellField(129);
  vtkNew<vtkLightFieldActor> scene;
  vtkLightFieldActorCore::SetLightField(scene, &field);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(vtkTriangleSceneConverter::MeshToPolyData(vlf::MakeCube(1.0f)));
  vtkNew<vtkActor> object;
  object->SetMapper(mapper);
  object->SetPosition(300.0, 400.0, 250.0);
  object->SetOrientation(0.0, 30.0, 0.0);
  object->SetScale(120.0);
  scene->SetMovableObject(object);
  vtkNew<vtkLightFieldObjectReliefProbes> probes;
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(probes);
  probes->SetLightFieldActor(scene);
  probes->SetProbesPerSide(4);
  ASSERT_TRUE(probes->Update()) << messages->AllErrors();
  ASSERT_EQ(probes->GetNumberOfCharts(), 6);
  EXPECT_EQ(probes->GetNumberOfProbes(), 96);
  EXPECT_EQ(probes->GetLastGatheredProbes(), 96);

  // The core's probes at the actor's placement, independently.
  vlf::ObjectReliefProbes reference(field);
  reference.SetMesh(vlf::MakeCube(1.0f), 4);
  reference.Gather(vtkLightFieldActorCore::UnitSpherePlacement(field, object->GetMatrix()));
  double largest = 0.0, worst = 0.0;
  for (int c = 0; c < 6; ++c)
  {
    vtkImageData* image = probes->GetProbes(c);
    ASSERT_NE(image, nullptr);
    int dims[3];
    image->GetDimensions(dims);
    EXPECT_EQ(dims[0], 36);
    EXPECT_EQ(dims[1], 4);
    EXPECT_EQ(image->GetNumberOfScalarComponents(), 3);
    EXPECT_EQ(image->GetScalarType(), VTK_FLOAT);
    vtkPolyData* chart = probes->GetChart(c);
    ASSERT_NE(chart, nullptr);
    EXPECT_EQ(chart->GetNumberOfCells(), 2);
    EXPECT_NE(chart->GetPointData()->GetTCoords(), nullptr);
    EXPECT_NE(chart->GetPointData()->GetNormals(), nullptr);
    for (int j = 0; j < 4; ++j)
    {
      for (int i = 0; i < 4; ++i)
      {
        const SH9& sh =
          reference.Probes()[static_cast<std::size_t>(c)][static_cast<std::size_t>(j * 4 + i)];
        for (int k = 0; k < 9; ++k)
        {
          for (int channel = 0; channel < 3; ++channel)
          {
            const double value = image->GetScalarComponentAsDouble(9 * i + k, j, 0, channel);
            largest = std::max(largest, std::abs(sh.L[k][channel]));
            worst = std::max(worst, std::abs(value - sh.L[k][channel]));
          }
        }
      }
    }
  }
  EXPECT_GT(largest, 0.0);
  EXPECT_LT(worst, 1e-5 * largest);

  // Nothing moved: nothing gathered; moved: every probe again.
  const unsigned long charts = probes->GetChartsVersion();
  ASSERT_TRUE(probes->Update());
  object->SetPosition(250.0, 380.0, 200.0);
  ASSERT_TRUE(probes->Update());
  EXPECT_EQ(probes->GetLastGatheredProbes(), 96);
  EXPECT_EQ(probes->GetChartsVersion(), charts) << "a move keeps the charts";
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
}

TEST(LightFieldObjectReliefProbes, ObjectWithoutTextureCoordinatesIsReported)
{
  const vlf::LightField& field = walkthroughtest::PlainCornellField(129);
  vtkNew<vtkLightFieldActor> scene;
  vtkLightFieldActorCore::SetLightField(scene, &field);
  vtkNew<vtkLightFieldObjectReliefProbes> probes;
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(probes);
  probes->SetLightFieldActor(scene);
  EXPECT_FALSE(probes->Update());
  EXPECT_TRUE(messages->HasError("no movable object")) << messages->AllErrors();
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputData(vtkTriangleSceneConverter::MeshToPolyData(vlf::MakeSphere(0.5f, 8, 16)));
  vtkNew<vtkActor> object;
  object->SetMapper(mapper);
  object->SetPosition(300.0, 400.0, 250.0);
  object->SetScale(100.0);
  scene->SetMovableObject(object);
  messages->Clear();
  EXPECT_FALSE(probes->Update());
  EXPECT_TRUE(messages->HasError("no texture coordinates")) << messages->AllErrors();
  EXPECT_TRUE(messages->HasError("'vt'")) << "how to get them";
  EXPECT_EQ(probes->GetNumberOfCharts(), 0);
  EXPECT_EQ(probes->GetProbes(0), nullptr);
}
