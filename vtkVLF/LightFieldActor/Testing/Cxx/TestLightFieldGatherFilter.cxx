// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldGatherFilter (Wither 2005 §3.6): a sphere inside the Cornell box's field gets the
// irradiance vtkVirtualLightField's own ComputeIrradiance gives at each point (an independent
// path: Lookup::Irradiance point by point), with computed normals when it has none; bad input
// is reported, never a crash.
#include "vtkLightFieldGatherFilter.h"

#include "vtkCallbackCommand.h"
#include "vtkCellData.h"
#include "vtkClipPolyData.h"
#include "vtkCommand.h"
#include "vtkCompositeLightFieldMapper.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIdList.h"
#include "vtkLightFieldCasterShadows.h"
#include "vtkNew.h"
#include "vtkPlane.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkVirtualLightField.h"

#include "MessageCapture.h"
#include "ObjectShadows.h"
#include "WalkthroughImage.h"

#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

namespace
{
struct Pipeline
{
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkVirtualLightField> field;
  vtkNew<vtkSphereSource> sphere;
  vtkNew<vtkLightFieldGatherFilter> gather;
  vtkNew<mesolight_test::MessageCapture> messages;
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
    messages->Watch(gather);
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

// What ParaView's Light Field representation needs to draw the gathered surface's shadow and
// to expose it like the scene: the field's emitters, its normalisation and log-average luminance
// on the gather's output; each scene vertex's unit-sphere point, normal and Kd on the field's.
TEST(LightFieldGatherFilter, CarriesWhatTheShadowCasterNeeds)
{
  namespace vlf = mesolight::vlf;
  Pipeline p;
  p.gather->Update();
  vtkFieldData* fields = p.gather->GetOutput()->GetFieldData();
  auto* packed = vtkFloatArray::SafeDownCast(
    fields->GetAbstractArray(vtkLightFieldGatherFilter::GetEmittersName()));
  ASSERT_NE(packed, nullptr);
  std::vector<vlf::ShadowEmitter> emitters;
  ASSERT_TRUE(vlf::UnpackEmitters(
    packed->GetPointer(0), static_cast<std::size_t>(packed->GetNumberOfValues()), emitters));
  ASSERT_EQ(emitters.size(), 1u); // the Cornell box's one light, Le = (17, 12, 4)
  EXPECT_NEAR(emitters[0].Light.Radiance.x, 17.0f, 1e-4f);
  EXPECT_NEAR(emitters[0].Light.Radiance.z, 4.0f, 1e-4f);
  EXPECT_EQ(emitters[0].Samples.size(), 9u);

  // The normalisation maps the scene's vertices onto the field's own unit-sphere points.
  vtkDataArray* toUnit = vtkArrayDownCast<vtkDataArray>(
    fields->GetAbstractArray(vtkLightFieldGatherFilter::GetToUnitSphereName()));
  ASSERT_NE(toUnit, nullptr);
  ASSERT_EQ(toUnit->GetNumberOfValues(), 4);
  vtkPolyData* scene = p.field->GetOutput();
  vtkDataArray* unit =
    scene->GetPointData()->GetArray(vtkVirtualLightField::GetReceiverPointName());
  vtkDataArray* normal =
    scene->GetPointData()->GetArray(vtkVirtualLightField::GetReceiverNormalName());
  vtkDataArray* kd =
    scene->GetPointData()->GetArray(vtkVirtualLightField::GetReceiverDiffuseName());
  ASSERT_TRUE(unit && normal && kd);
  double worst = 0.0;
  for (vtkIdType i = 0; i < scene->GetNumberOfPoints(); ++i)
  {
    const double* x = scene->GetPoint(i);
    for (int c = 0; c < 3; ++c)
    {
      const double mapped = (x[c] - toUnit->GetComponent(c, 0)) * toUnit->GetComponent(3, 0);
      worst = std::max(worst, std::abs(mapped - unit->GetComponent(i, c)));
    }
    const double n[3] = { normal->GetComponent(i, 0), normal->GetComponent(i, 1),
      normal->GetComponent(i, 2) };
    EXPECT_NEAR(n[0] * n[0] + n[1] * n[1] + n[2] * n[2], 1.0, 1e-4);
  }
  EXPECT_LT(worst, 1e-5);
  // Each vertex's Kd is its triangle's Diffuse (vertices are per surface).
  vtkDataArray* diffuse = scene->GetCellData()->GetArray("Diffuse");
  ASSERT_NE(diffuse, nullptr);
  vtkNew<vtkIdList> ids;
  scene->GetCellPoints(0, ids);
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_NEAR(kd->GetComponent(ids->GetId(0), c), diffuse->GetComponent(0, c), 1e-6);
  }

  // The log-average is the one the scene's automatic exposure uses.
  vtkDataArray* average = vtkArrayDownCast<vtkDataArray>(
    fields->GetAbstractArray(vtkLightFieldGatherFilter::GetLogAverageName()));
  int size[2];
  vtkFloatArray* atlas = vtkVirtualLightField::GetAttachedAtlas(scene, size);
  ASSERT_TRUE(average && atlas);
  EXPECT_GT(average->GetComponent(0, 0), 0.0);
  EXPECT_NEAR(average->GetComponent(0, 0),
    vlf::LogAverageLuminance(
      atlas->GetPointer(0), static_cast<std::size_t>(atlas->GetNumberOfTuples())),
    1e-9);

  // One field, made once: a new reflectance gathers again without propagating again.
  EXPECT_EQ(p.gather->GetFieldPropagations(), 1);
  p.gather->SetReflectance(0.5, 0.5, 0.5);
  p.gather->Update();
  EXPECT_EQ(p.field->GetPropagationCount(), 1);
  EXPECT_EQ(p.gather->GetFieldPropagations(), 1);
  EXPECT_EQ(p.gather->GetFieldBroadcasts(), 0); // one process
}

// What ParaView draws a Shadow Caster with (on the scene and on a relief): the gather output's
// emitters and normalisation make the maps, rebuilt only when the caster or a setting changes;
// a caster that is no gather output is said once, through the object the user watches.
TEST(LightFieldCasterShadows, MapsFromTheGatherOutputRebuiltOnlyOnChange)
{
  Pipeline p;
  p.gather->Update();
  vtkNew<vtkLightFieldCasterShadows> shadows;
  vtkNew<vtkObject> reporter;
  vtkNew<mesolight_test::MessageCapture> said;
  said->Watch(reporter);
  shadows->Update(reporter);
  EXPECT_FALSE(shadows->HasShadows()); // no caster
  const unsigned long none = shadows->GetVersion();

  shadows->SetCaster(p.gather->GetOutput());
  shadows->Update(reporter);
  ASSERT_TRUE(shadows->HasShadows()) << shadows->GetProblem();
  EXPECT_STREQ(shadows->GetProblem(), "");
  EXPECT_GT(shadows->GetGpu().EmitterCount, 0);
  const unsigned long built = shadows->GetVersion();
  EXPECT_NE(built, none);
  shadows->Update(reporter);
  EXPECT_EQ(shadows->GetVersion(), built); // nothing changed: not rebuilt
  p.gather->GetOutput()->Modified();
  shadows->Update(reporter);
  EXPECT_NE(shadows->GetVersion(), built); // the caster changed

  // World to the field's unit sphere: the gather's normalisation.
  float m[16];
  shadows->GetWorldToUnitSphere(m);
  vtkDataArray* toUnit =
    vtkArrayDownCast<vtkDataArray>(p.gather->GetOutput()->GetFieldData()->GetAbstractArray(
      vtkLightFieldGatherFilter::GetToUnitSphereName()));
  ASSERT_NE(toUnit, nullptr);
  const double x[3] = { 100.0, 200.0, 300.0 };
  for (int c = 0; c < 3; ++c)
  {
    const double mapped = m[c * 5] * x[c] + m[12 + c];
    EXPECT_NEAR(mapped, (x[c] - toUnit->GetComponent(c, 0)) * toUnit->GetComponent(3, 0), 1e-4);
  }

  shadows->SetMode(0); // None
  shadows->Update(reporter);
  EXPECT_FALSE(shadows->HasShadows());
  shadows->SetMode(3);

  // The sphere itself (no emitters): no shadow, one warning naming what to connect.
  shadows->SetCaster(p.sphere->GetOutput());
  p.sphere->Update();
  shadows->Update(reporter);
  EXPECT_FALSE(shadows->HasShadows());
  EXPECT_NE(std::string(shadows->GetProblem()).find("Light Field Gather"), std::string::npos);
  EXPECT_TRUE(said->HasWarning("casts no shadow")) << said->AllWarnings();
  said->Clear();
  p.sphere->GetOutput()->Modified();
  shadows->Update(reporter);
  EXPECT_EQ(said->AllWarnings(), ""); // the same cause is not said again
}

// A caster gathered from another field (here the same box scaled by 1.5: another unit sphere,
// its lamp elsewhere) would draw that field's shadow in this one: it casts none, says why once,
// and the caster of the field itself still casts (the check does not refuse everything).
TEST(LightFieldCasterShadows, ACasterOfAnotherFieldCastsNone)
{
  Pipeline p;
  p.gather->Update();
  double centre[3], scale = 0.0;
  ASSERT_TRUE(vtkVirtualLightField::GetAttachedUnitSphere(p.field->GetOutput(), centre, &scale));
  double casterCentre[3], casterScale = 0.0;
  ASSERT_TRUE(
    vtkVirtualLightField::GetAttachedUnitSphere(p.gather->GetOutput(), casterCentre, &casterScale));
  EXPECT_EQ(scale, casterScale); // the field's output and its gather's carry the same sphere
  for (int c = 0; c < 3; ++c)
  {
    EXPECT_EQ(centre[c], casterCentre[c]);
  }

  vtkNew<vtkTransform> larger;
  larger->Scale(1.5, 1.5, 1.5);
  vtkNew<vtkTransformPolyDataFilter> otherBox;
  otherBox->SetInputConnection(p.box->GetOutputPort());
  otherBox->SetTransform(larger);
  vtkNew<vtkVirtualLightField> otherField;
  otherField->SetInputConnection(otherBox->GetOutputPort());
  otherField->SetDirections(33);
  otherField->SetRaysPerSide(8);
  otherField->SetIterations(1);
  otherField->Update();
  double otherCentre[3], otherScale = 0.0;
  ASSERT_TRUE(
    vtkVirtualLightField::GetAttachedUnitSphere(otherField->GetOutput(), otherCentre, &otherScale));
  EXPECT_NEAR(otherScale, scale / 1.5, 1e-3 * scale);

  vtkNew<vtkLightFieldCasterShadows> shadows;
  vtkNew<vtkObject> reporter;
  vtkNew<mesolight_test::MessageCapture> said;
  said->Watch(reporter);
  shadows->SetCaster(p.gather->GetOutput());
  shadows->SetFieldUnitSphere(centre, scale);
  shadows->Update(reporter);
  EXPECT_TRUE(shadows->HasShadows()) << shadows->GetProblem(); // its own field
  EXPECT_EQ(said->AllWarnings(), "");

  shadows->SetFieldUnitSphere(otherCentre, otherScale);
  shadows->Update(reporter);
  EXPECT_FALSE(shadows->HasShadows());
  EXPECT_NE(std::string(shadows->GetProblem()).find("another light field"), std::string::npos)
    << shadows->GetProblem();
  EXPECT_TRUE(said->HasWarning("gathered from another light field")) << said->AllWarnings();
  said->Clear();
  shadows->Update(reporter);
  p.gather->GetOutput()->Modified();
  shadows->Update(reporter);
  EXPECT_EQ(said->AllWarnings(), ""); // the same cause is not said again

  // A caster gathered in the other field, drawn in the first.
  vtkNew<vtkLightFieldGatherFilter> otherGather;
  otherGather->SetInputConnection(p.sphere->GetOutputPort());
  otherGather->SetLightFieldConnection(otherField->GetOutputPort());
  otherGather->Update();
  shadows->SetCaster(otherGather->GetOutput());
  shadows->SetFieldUnitSphere(centre, scale);
  shadows->Update(reporter);
  EXPECT_FALSE(shadows->HasShadows());
  shadows->SetFieldUnitSphere(otherCentre, otherScale);
  shadows->Update(reporter);
  EXPECT_TRUE(shadows->HasShadows()) << shadows->GetProblem(); // in its own field it casts

  // Not known (no field given): not checked, as before.
  shadows->SetFieldUnitSphere(centre, scale);
  shadows->Update(reporter);
  EXPECT_FALSE(shadows->HasShadows());
  shadows->ClearFieldUnitSphere();
  shadows->Update(reporter);
  EXPECT_TRUE(shadows->HasShadows()) << shadows->GetProblem();
}

// Each point's place when gathered goes with it: a Transform after the gather (which also turns
// Radiance as a vector) shows as a move, a clip (cut points interpolated) does not.
TEST(LightFieldGatherFilter, KeepsWhereEachPointWasGathered)
{
  Pipeline p;
  p.gather->Update();
  EXPECT_EQ(vtkCompositeLightFieldMapper::MovedSinceGathered(p.gather->GetOutput()), 0.0);

  vtkNew<vtkTransform> turn;
  turn->RotateY(90.0);
  vtkNew<vtkTransformFilter> turned;
  turned->SetInputConnection(p.gather->GetOutputPort());
  turned->SetTransform(turn);
  turned->TransformAllInputVectorsOn();
  turned->Update();
  EXPECT_GT(vtkCompositeLightFieldMapper::MovedSinceGathered(
              vtkPolyData::SafeDownCast(turned->GetOutput())),
    100.0); // the sphere's centre (300, 250, 200) turns to (200, 250, -300)

  vtkNew<vtkPlane> plane;
  plane->SetOrigin(300.0, 250.0, 200.0);
  plane->SetNormal(1.0, 0.3, 0.0);
  vtkNew<vtkClipPolyData> clipped;
  clipped->SetInputConnection(p.gather->GetOutputPort());
  clipped->SetClipFunction(plane);
  clipped->Update();
  ASSERT_GT(clipped->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(vtkCompositeLightFieldMapper::MovedSinceGathered(clipped->GetOutput()), 0.0);
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
