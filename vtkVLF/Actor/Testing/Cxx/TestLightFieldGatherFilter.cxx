// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldGatherFilter (issue 14, 6): a sphere inside the Cornell box's field gets the
// irradiance vtkVirtualLightField's own ComputeIrradiance gives at each point (an independent
// path: Lookup::Irradiance point by point), with computed normals when it has none; bad input
// is reported, never a crash.
#include "vtkLightFieldGatherFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCommand.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkVirtualLightField.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
class Messages : public vtkCommand
{
public:
  static Messages* New() { return new Messages; }
  void Execute(vtkObject*, unsigned long event, void* data) override
  {
    (event == vtkCommand::ErrorEvent ? this->Errors : this->Warnings)
      .emplace_back(data ? static_cast<const char*>(data) : "");
  }
  std::vector<std::string> Errors, Warnings;
};

struct Pipeline
{
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkVirtualLightField> field;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkLightFieldGatherFilter> gather;
  vtkNew<Messages> messages;
  Pipeline()
  {
    field->SetInputConnection(box->GetOutputPort());
    field->SetDirections(513);
    field->SetRaysPerSide(16);
    field->SetIterations(3);
    sphere->SetCenter(300.0, 250.0, 200.0); // inside the box (millimetres)
    sphere->SetRadius(50.0);
    sphere->SetThetaResolution(12);
    sphere->SetPhiResolution(8);
    gather->SetInputConnection(sphere->GetOutputPort());
    gather->SetLightFieldConnection(field->GetOutputPort());
    gather->AddObserver(vtkCommand::ErrorEvent, messages);
    gather->AddObserver(vtkCommand::WarningEvent, messages);
  }
};

// Max relative difference of "Irradiance" against the producer's lookup at each point.
double WorstAgainstLookup(vtkPolyData* out, vtkVirtualLightField* field)
{
  vtkDataArray* e = out->GetPointData()->GetArray("Irradiance");
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  EXPECT_NE(e, nullptr);
  if (!e)
  {
    return 1e30;
  }
  double worst = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    double p[3], n[3] = { 0.0, 0.0, 1.0 }, expected[3];
    out->GetPoint(i, p);
    if (normals)
    {
      normals->GetTuple(i, n);
    }
    EXPECT_TRUE(field->ComputeIrradiance(p, n, expected));
    double got[3];
    e->GetTuple(i, got);
    for (int c = 0; c < 3; ++c)
    {
      worst = std::max(worst, std::abs(got[c] - expected[c]) / (std::abs(expected[c]) + 1e-3));
    }
  }
  return worst;
}
} // namespace

TEST(LightFieldGatherFilter, MatchesTheFieldsOwnLookup)
{
  Pipeline p;
  p.gather->Update();
  vtkPolyData* out = p.gather->GetOutput();
  ASSERT_EQ(out->GetNumberOfPoints(), p.sphere->GetOutput()->GetNumberOfPoints());
  EXPECT_TRUE(p.messages->Errors.empty());
  EXPECT_LT(WorstAgainstLookup(out, p.field), 1e-3);
  // Radiance = Reflectance / pi x Irradiance, and the light from above: the top is brighter.
  vtkDataArray* l = out->GetPointData()->GetArray("Radiance");
  vtkDataArray* e = out->GetPointData()->GetArray("Irradiance");
  ASSERT_NE(l, nullptr);
  EXPECT_NEAR(l->GetComponent(3, 1), 0.7 / M_PI * e->GetComponent(3, 1), 1e-5);
  double top = 0.0, bottom = 0.0;
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    (out->GetPoint(i)[1] > 250.0 ? top : bottom) += l->GetComponent(i, 1);
  }
  EXPECT_GT(top, 2.0 * bottom);
  // Another reflectance scales the radiance only.
  const double before = l->GetComponent(3, 1);
  p.gather->SetReflectance(0.35, 0.35, 0.35);
  p.gather->Update();
  EXPECT_NEAR(p.gather->GetOutput()->GetPointData()->GetArray("Radiance")->GetComponent(3, 1),
    0.5 * before, 1e-5);
}

TEST(LightFieldGatherFilter, ComputesMissingNormals)
{
  Pipeline p;
  p.sphere->GenerateNormalsOff();
  p.gather->Update();
  vtkPolyData* out = p.gather->GetOutput();
  EXPECT_TRUE(p.messages->Errors.empty());
  ASSERT_NE(out->GetPointData()->GetArray("Irradiance"), nullptr);
  // The computed normals come with the output, point outward like the sphere's own, and are
  // what the irradiance was gathered with.
  vtkDataArray* normals = out->GetPointData()->GetNormals();
  ASSERT_NE(normals, nullptr);
  for (vtkIdType i = 0; i < out->GetNumberOfPoints(); ++i)
  {
    const double* x = out->GetPoint(i);
    const double radial[3] = { (x[0] - 300.0) / 50.0, (x[1] - 250.0) / 50.0,
      (x[2] - 200.0) / 50.0 };
    double n[3];
    normals->GetTuple(i, n);
    EXPECT_GT(n[0] * radial[0] + n[1] * radial[1] + n[2] * radial[2], 0.9);
  }
  EXPECT_LT(WorstAgainstLookup(out, p.field), 1e-3);
}

TEST(LightFieldGatherFilter, BadInputIsReportedNotACrash)
{
  {
    // The light field input is not a light field.
    Pipeline p;
    vtkNew<vtkSphereSource> notAField;
    p.gather->SetLightFieldConnection(notAField->GetOutputPort());
    p.gather->Update();
    ASSERT_FALSE(p.messages->Errors.empty());
    EXPECT_NE(p.messages->Errors[0].find("Virtual Light Field"), std::string::npos);
  }
  {
    // Outside the field's bounding sphere: gathered on the boundary, with a warning.
    Pipeline p;
    p.sphere->SetCenter(5000.0, 250.0, 200.0);
    p.gather->Update();
    EXPECT_TRUE(p.messages->Errors.empty());
    EXPECT_GT(p.gather->GetOutsidePoints(), 0);
    ASSERT_FALSE(p.messages->Warnings.empty());
    EXPECT_NE(p.messages->Warnings[0].find("outside the light field"), std::string::npos);
  }
  {
    // Points without polygons.
    Pipeline p;
    vtkNew<vtkPolyData> points;
    p.sphere->Update();
    points->SetPoints(p.sphere->GetOutput()->GetPoints());
    p.gather->SetInputData(points);
    p.gather->Update();
    ASSERT_FALSE(p.messages->Errors.empty());
    EXPECT_NE(p.messages->Errors[0].find("polygons"), std::string::npos);
  }
  {
    // Abort: an empty output, no error.
    Pipeline p;
    p.field->Update();
    vtkNew<vtkCallbackCommand> abort;
    abort->SetCallback([](vtkObject* caller, unsigned long, void*, void*)
      { static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1); });
    p.gather->AddObserver(vtkCommand::ProgressEvent, abort);
    p.gather->Update();
    EXPECT_EQ(p.gather->GetOutput()->GetNumberOfPoints(), 0);
  }
}
