// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldReliefSurface: a named surface of a field's scene made ready for vtkReliefMapper.
// The probe image is checked against the exact integrals of the field's incident radiance
// (IncidentIrradiance over its 2K line samples, not the SH projection) at the points its own
// texture coordinates give, for several normals; the emitter lights against the emitting
// surface's world area and radiance; bad input against its messages.
#include "vtkLightFieldReliefSurface.h"

#include "vtkCornellBoxSource.h"
#include "vtkIrradianceProbesTexture.h" // the visible share's array names
#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldReliefSurfaceCore.h"
#include "vtkReliefMapper.h"
#include "vtkVirtualLightField.h"
#include "vtkVirtualLightFieldCore.h"

#include "EmitterTestFields.h"
#include "FieldIrradiance.h"
#include "LightField.h"
#include "MessageCapture.h"
#include "PatchComparison.h" // ToUnit, ToWorld
#include "ReliefSurface.h"
#include "TriangleScene.h"
#include "WalkthroughTestFields.h"

#include <vtkCallbackCommand.h>
#include <vtkCellArray.h>
#include <vtkCellData.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkLightCollection.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSmartPointer.h>

#include <glm/geometric.hpp>
#include <gtest/gtest.h>

#include <cmath>
#include <iostream>
#include <memory>
#include <vector>

namespace
{
using namespace mesolight;
namespace vlf = mesolight::vlf;

// The world point of the output polydata at texture (u, v): barycentric in its triangles' uv.
bool PointAtTexture(vtkPolyData* poly, double u, double v, glm::dvec3& point)
{
  vtkDataArray* tc = poly->GetPointData()->GetTCoords();
  const vtkIdType* ids = nullptr;
  vtkIdType count = 0;
  vtkCellArray* polys = poly->GetPolys();
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    double t[3][2];
    glm::dvec3 p[3];
    for (int k = 0; k < 3; ++k)
    {
      tc->GetTuple(ids[k], t[k]);
      double x[3];
      poly->GetPoint(ids[k], x);
      p[k] = glm::dvec3(x[0], x[1], x[2]);
    }
    const double d =
      (t[1][0] - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (t[1][1] - t[0][1]);
    const double b1 =
      ((u - t[0][0]) * (t[2][1] - t[0][1]) - (t[2][0] - t[0][0]) * (v - t[0][1])) / d;
    const double b2 =
      ((t[1][0] - t[0][0]) * (v - t[0][1]) - (u - t[0][0]) * (t[1][1] - t[0][1])) / d;
    if (b1 >= -1e-9 && b2 >= -1e-9 && b1 + b2 <= 1.0 + 1e-9)
    {
      point = p[0] + b1 * (p[1] - p[0]) + b2 * (p[2] - p[0]);
      return true;
    }
  }
  return false;
}

glm::dvec3 ProbeIrradiance(vtkImageData* probes, int i, int j, const glm::dvec3& n)
{
  SH9 sh;
  for (int k = 0; k < 9; ++k)
  {
    for (int c = 0; c < 3; ++c)
    {
      sh.L[k][c] = probes->GetScalarComponentAsDouble(9 * i + k, j, 0, c);
    }
  }
  const double normal[3] = { n.x, n.y, n.z };
  double e[3];
  IrradianceSH9(sh, normal, e);
  return glm::dvec3(e[0], e[1], e[2]);
}

// The Cornell box's field as a pipeline, coarse enough for a unit test (33 directions, 8 x 8
// rays, one iteration).
vtkSmartPointer<vtkVirtualLightField> SmallCornellField()
{
  vtkNew<vtkCornellBoxSource> box;
  auto field = vtkSmartPointer<vtkVirtualLightField>::New();
  field->SetInputConnection(box->GetOutputPort());
  field->SetDirections(33);
  field->SetRaysPerSide(8);
  field->SetIterations(1);
  return field;
}

// A 380 x 380 patch parallel to the back wall (z = 559.2) at depth z.
vtkSmartPointer<vtkPolyData> BackWallPatch(double z)
{
  vtkNew<vtkPlaneSource> patch;
  patch->SetOrigin(90.0, 90.0, z);
  patch->SetPoint1(90.0, 470.0, z);
  patch->SetPoint2(470.0, 90.0, z);
  patch->Update();
  return patch->GetOutput();
}

struct ReliefSurfaceFixture
{
  vtkNew<vtkLightFieldActor> Actor;
  vtkNew<vtkLightFieldReliefSurface> Surface;
  vtkNew<mesolight_test::MessageCapture> Messages;
  const vlf::LightField& Field = walkthroughtest::PlainCornellField(129);
  ReliefSurfaceFixture(const char* name, int probes = 4)
  {
    vtkLightFieldActorCore::SetLightField(this->Actor, &this->Field);
    this->Messages->Watch(this->Surface);
    this->Surface->SetLightFieldActor(this->Actor);
    this->Surface->SetSurfaceName(name);
    this->Surface->SetProbesPerSide(probes);
    this->Surface->Update();
  }
};

// The largest relative difference, over probes and normals, between the probe image's SH
// irradiance and the exact sum over the field's samples at the point its texture gives; with
// `transposed` the image's probe (j, i) stands for (i, j) (the negative case).
double WorstProbeError(ReliefSurfaceFixture& f, bool transposed, bool emission)
{
  vtkPolyData* poly = f.Surface->GetOutput();
  vtkImageData* probes = f.Surface->GetProbesOutput();
  const int n = f.Surface->GetProbesPerSide();
  double* nw = poly->GetPointData()->GetNormals()->GetTuple3(0);
  const glm::dvec3 normal = glm::normalize(glm::dvec3(nw[0], nw[1], nw[2]));
  const glm::dvec3 side = glm::normalize(glm::cross(normal, glm::dvec3(0.0, 1.0, 0.0)));
  const glm::dvec3 up = glm::cross(side, normal);
  const glm::dvec3 normals[5] = { normal, glm::normalize(normal + side),
    glm::normalize(normal - side), glm::normalize(normal + up), glm::normalize(normal - up) };
  vlf::IncidentOptions options;
  options.Ignore = vlf::FindReliefSurface(f.Field, f.Surface->GetSurfaceName()).FieldSurface;
  options.Emission = emission;
  double worst = 0.0;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      glm::dvec3 world;
      EXPECT_TRUE(PointAtTexture(poly, (i + 0.5) / n, (j + 0.5) / n, world));
      const glm::vec3 unit = vlf::ToUnit(f.Field, glm::vec3(world)) + 1e-3f * glm::vec3(normal);
      const auto samples = vlf::IncidentRadianceSamples(f.Field, unit, options);
      for (const glm::dvec3& m : normals)
      {
        const glm::dvec3 exact(vlf::IncidentIrradiance(samples, glm::vec3(m)));
        const glm::dvec3 image =
          transposed ? ProbeIrradiance(probes, j, i, m) : ProbeIrradiance(probes, i, j, m);
        const double scale = std::max(exact.x, std::max(exact.y, exact.z));
        for (int c = 0; c < 3; ++c)
        {
          worst = std::max(worst, std::abs(image[c] - exact[c]) / scale);
        }
      }
    }
  }
  return worst;
}
} // namespace

TEST(LightFieldReliefSurface, ProbesAreTheFieldsIndirectIrradianceAtTheirTexturePoints)
{
  ReliefSurfaceFixture f("back");
  ASSERT_TRUE(f.Messages->Errors.empty()) << f.Messages->AllErrors();
  vtkImageData* probes = f.Surface->GetProbesOutput();
  int dims[3];
  probes->GetDimensions(dims);
  EXPECT_EQ(dims[0], 36);
  EXPECT_EQ(dims[1], 4);
  EXPECT_EQ(probes->GetNumberOfScalarComponents(), 3);
  // SH9 irradiance is within a few percent of the exact one for smooth light (Ramamoorthi and
  // Hanrahan: at most 9% for any light); the indirect light on the back wall is smooth.
  const double error = WorstProbeError(f, false, false);
  EXPECT_LT(error, 0.06);
  // Negative: the probes read transposed (the red and green walls swap sides), or compared with
  // the emitters' light included, are far off.
  const double transposed = WorstProbeError(f, true, false);
  const double withEmitters = WorstProbeError(f, false, true);
  std::cout << "worst relative irradiance error: probes " << error << ", read transposed "
            << transposed << ", against the light with the emitters " << withEmitters << "\n";
  EXPECT_GT(transposed, 2.0 * error);
  EXPECT_GT(withEmitters, 0.5);
}

// The walkthrough's mirrors shade the relief with these probes instead of computing them again
// (application/LightFieldReliefs.cxx): they must be the core's, bit for bit, and port 1's floats.
TEST(LightFieldReliefSurface, ProbesAsComputedAreLentForTheSurfaceItWasGiven)
{
  ReliefSurfaceFixture f("back", 3);
  const std::vector<SH9>* lent = vtkLightFieldReliefSurfaceCore::GetProbes(f.Surface);
  ASSERT_NE(lent, nullptr);
  const std::vector<SH9> own =
    vlf::ReliefSurfaceProbes(f.Field, vlf::FindReliefSurface(f.Field, "back"), 3, 3);
  ASSERT_EQ(lent->size(), own.size());
  vtkDataArray* image = f.Surface->GetProbesOutput()->GetPointData()->GetScalars();
  for (std::size_t p = 0; p < own.size(); ++p)
  {
    for (int k = 0; k < 9; ++k)
    {
      for (int c = 0; c < 3; ++c)
      {
        EXPECT_EQ((*lent)[p].L[k][c], own[p].L[k][c]);
        const vtkIdType pixel = static_cast<vtkIdType>((p / 3) * 27 + 9 * (p % 3) + k);
        EXPECT_EQ(image->GetComponent(pixel, c), static_cast<float>(own[p].L[k][c]));
      }
    }
  }
  // Negative: another wall's probes differ.
  const std::vector<SH9> floor =
    vlf::ReliefSurfaceProbes(f.Field, vlf::FindReliefSurface(f.Field, "floor"), 3, 3);
  EXPECT_NE(floor[0].L[0][0], (*lent)[0].L[0][0]);
  // None after a failed update, nor for a surface of input port 1 (its probes travel as floats).
  f.Surface->SetSurfaceName("wall");
  f.Surface->Update();
  EXPECT_EQ(vtkLightFieldReliefSurfaceCore::GetProbes(f.Surface), nullptr);
  EXPECT_EQ(vtkLightFieldReliefSurfaceCore::GetProbes(nullptr), nullptr);
}

TEST(LightFieldReliefSurface, PolygonsCarryThePlanesTextureCoordinatesInWorldCoordinates)
{
  ReliefSurfaceFixture f("back");
  vtkPolyData* poly = f.Surface->GetOutput();
  const std::vector<std::size_t> triangles = SurfaceTriangles(f.Field.Scene(), "back");
  ASSERT_EQ(poly->GetNumberOfPolys(), static_cast<vtkIdType>(triangles.size()));
  double range[2][2];
  poly->GetPointData()->GetTCoords()->GetRange(range[0], 0);
  poly->GetPointData()->GetTCoords()->GetRange(range[1], 1);
  for (int a = 0; a < 2; ++a)
  {
    EXPECT_NEAR(range[a][0], 0.0, 1e-5);
    EXPECT_NEAR(range[a][1], 1.0, 1e-5);
  }
  // Its points are the scene's, in world coordinates; the normal faces into the room.
  double bounds[6];
  poly->GetBounds(bounds);
  for (const std::size_t t : triangles)
  {
    for (int c = 0; c < 3; ++c)
    {
      const glm::vec3 world = vlf::ToWorld(f.Field, f.Field.Scene().Vertex(t, c));
      for (int a = 0; a < 3; ++a)
      {
        EXPECT_GE(world[a], bounds[2 * a] - 1e-3);
        EXPECT_LE(world[a], bounds[2 * a + 1] + 1e-3);
      }
    }
  }
  const glm::vec3 centre = vlf::ToWorld(f.Field, glm::vec3(0.0f));
  double x[3], nrm[3];
  poly->GetPoint(0, x);
  poly->GetPointData()->GetNormals()->GetTuple(0, nrm);
  EXPECT_GT(
    glm::dot(glm::dvec3(centre) - glm::dvec3(x[0], x[1], x[2]), glm::dvec3(nrm[0], nrm[1], nrm[2])),
    0.0);
}

TEST(LightFieldReliefSurface, EmitterLightsCarryRadiantIntensityInWorldUnits)
{
  ReliefSurfaceFixture f("back", 1);
  vtkLightCollection* lights = f.Surface->GetEmitterLights();
  ASSERT_EQ(lights->GetNumberOfItems(), 1);
  lights->InitTraversal();
  vtkLight* light = lights->GetNextItem();
  // The Cornell box's light: Le times its area, both from the scene, the area in world units.
  const TriangleScene& scene = f.Field.Scene();
  double area = 0.0;
  glm::dvec3 centroid(0.0);
  glm::vec3 le(0.0f);
  for (const std::size_t t : SurfaceTriangles(scene, "light"))
  {
    const glm::dvec3 a(vlf::ToWorld(f.Field, scene.Vertex(t, 0)));
    const glm::dvec3 b(vlf::ToWorld(f.Field, scene.Vertex(t, 1)));
    const glm::dvec3 c(vlf::ToWorld(f.Field, scene.Vertex(t, 2)));
    const double at = 0.5 * glm::length(glm::cross(b - a, c - a));
    area += at;
    centroid += at * (a + b + c) / 3.0;
    le = scene.MaterialOf(t).Emission;
  }
  centroid /= area;
  double* colour = light->GetDiffuseColor();
  for (int c = 0; c < 3; ++c)
  {
    // VTK shades Kd x intensity x cos: the Lambertian 1 / pi is in the light's intensity.
    const double expected = le[c] * area / 3.14159265358979323846;
    EXPECT_NEAR(light->GetIntensity() * colour[c], expected, 1e-3 * expected);
    EXPECT_NEAR(light->GetPosition()[c], centroid[c], 1e-3);
  }
  EXPECT_TRUE(light->GetPositional());
  EXPECT_DOUBLE_EQ(light->GetConeAngle(), 90.0);
  EXPECT_DOUBLE_EQ(light->GetExponent(), 1.0);
  EXPECT_DOUBLE_EQ(light->GetAttenuationValues()[2], 1.0);
  // Facing down into the box.
  EXPECT_LT(light->GetFocalPoint()[1], light->GetPosition()[1]);
}

TEST(LightFieldReliefSurface, MoreLampsThanTheReliefShadesAreMergedNotDropped)
{
  // Twelve lamps, and the relief mapper shades 8 lights: the relief's emitter lights are merged
  // to 8 that carry all twelve lamps' light. (The mapper would shade the first 8 of twelve and
  // drop the rest with a warning.)
  const std::vector<emittertest::Lamp> lamps = emittertest::TwelveLamps();
  const std::unique_ptr<vlf::LightField> field = emittertest::BoxWithLamps(lamps);
  vtkNew<vtkLightFieldActor> actor;
  vtkLightFieldActorCore::SetLightField(actor, field.get());
  vtkNew<vtkLightCollection> lights;
  ASSERT_TRUE(vtkLightFieldReliefSurface::GetEmitterLights(actor, lights));
  ASSERT_EQ(lights->GetNumberOfItems(), vtkReliefMapper::GetMaximumNumberOfLights());
  double total = 0.0;
  lights->InitTraversal();
  while (vtkLight* light = lights->GetNextItem())
  {
    total += light->GetIntensity() * light->GetDiffuseColor()[0];
    EXPECT_LT(light->GetFocalPoint()[1], light->GetPosition()[1]) << "facing down";
  }
  // Le x area over pi (VTK's lights carry the Lambertian 1 / pi), the area in world units.
  double expected = 0.0;
  for (const emittertest::Lamp& lamp : lamps)
  {
    expected +=
      lamp.Emission.x * (lamp.X1 - lamp.X0) * (lamp.Z1 - lamp.Z0) / 3.14159265358979323846;
  }
  EXPECT_NEAR(total, expected, 1e-4 * expected);
}

TEST(LightFieldReliefSurface, BadInputIsReported)
{
  {
    ReliefSurfaceFixture f("wall", 1);
    EXPECT_TRUE(f.Messages->HasError(
      "its surfaces are: floor, ceiling, back, left, right, light, short, tall"))
      << f.Messages->AllErrors();
    EXPECT_EQ(f.Surface->GetOutput()->GetNumberOfPoints(), 0);
  }
  {
    ReliefSurfaceFixture f("tall", 1);
    EXPECT_TRUE(f.Messages->HasError("is not planar")) << f.Messages->AllErrors();
  }
  {
    vtkNew<vtkLightFieldReliefSurface> surface;
    vtkNew<mesolight_test::MessageCapture> messages;
    messages->Watch(surface);
    surface->SetSurfaceName("back");
    surface->Update();
    EXPECT_TRUE(messages->HasError("needs a light field")) << messages->AllErrors();
  }
}

TEST(LightFieldReliefSurface, AbortStopsWithoutError)
{
  vtkNew<vtkLightFieldActor> actor;
  vtkLightFieldActorCore::SetLightField(actor, &walkthroughtest::PlainCornellField(129));
  vtkNew<vtkLightFieldReliefSurface> surface;
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(surface);
  surface->SetLightFieldActor(actor);
  surface->SetSurfaceName("back");
  int reports = 0;
  vtkNew<vtkCallbackCommand> abort;
  abort->SetClientData(&reports);
  abort->SetCallback(
    [](vtkObject* caller, unsigned long, void* data, void*)
    {
      ++*static_cast<int*>(data);
      static_cast<vtkLightFieldReliefSurface*>(caller)->SetAbortExecute(1);
    });
  surface->AddObserver(vtkCommand::ProgressEvent, abort);
  surface->Update();
  EXPECT_GE(reports, 1);
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  EXPECT_EQ(surface->GetOutput()->GetNumberOfPoints(), 0);
}

TEST(LightFieldReliefSurface, ProbesAreRecomputedForANewFieldOnly)
{
  ReliefSurfaceFixture f("back", 2);
  int runs = 0;
  vtkNew<vtkCallbackCommand> count;
  count->SetClientData(&runs);
  count->SetCallback(
    [](vtkObject*, unsigned long, void* data, void*) { ++*static_cast<int*>(data); });
  f.Surface->AddObserver(vtkCommand::StartEvent, count);
  // The walkthrough's settings change the actor, not its field.
  f.Actor->SetExposure(2.0);
  f.Actor->AddHiddenSurface("back");
  f.Surface->Update();
  EXPECT_EQ(runs, 0);
  // Another field (the mirror box, which has a back wall too): new outputs.
  vtkLightFieldActorCore::SetLightField(f.Actor, &walkthroughtest::MirrorCornellField(129));
  f.Surface->Update();
  EXPECT_EQ(runs, 1);
}

// The filter route: the scene comes as polydata (vtkTriangleSceneConverter), which now carries
// the surfaces' names (cell array SurfaceId): a relief on the Cornell box's "floor" of a
// vtkVirtualLightField is found (it was refused, "no surface named 'floor'", so a Python user
// could not put a relief on a field propagated in Python). Polydata without the names still
// gets the message that says why and what to do.
TEST(LightFieldReliefSurface, AVirtualLightFieldFiltersSceneKeepsItsNames)
{
  vtkSmartPointer<vtkVirtualLightField> field = SmallCornellField();
  vtkNew<vtkLightFieldReliefSurface> surface;
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(surface);
  surface->SetLightFieldConnection(field->GetOutputPort());
  surface->SetSurfaceName("floor");
  surface->SetProbesPerSide(2);
  surface->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(field), nullptr);
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  EXPECT_EQ(surface->GetOutput()->GetNumberOfCells(), 2); // the floor's two triangles

  vtkNew<vtkCornellBoxSource> box;
  box->Update();
  vtkNew<vtkPolyData> unnamed;
  unnamed->DeepCopy(box->GetOutput());
  unnamed->GetCellData()->RemoveArray("SurfaceId");
  field->SetInputData(unnamed);
  surface->Update();
  EXPECT_TRUE(messages->HasError("a field propagated from polydata has no surface names"))
    << messages->AllErrors();
}

// A patch mounted 1.2 mm in front of the back wall (z = 559.2, facing -z) gets the depth limit
// plane halfway between the two; a patch far from any wall and a named surface (the wall itself)
// get none.
TEST(LightFieldReliefSurface, AMountedPatchLimitsItsDepthHalfwayToTheWall)
{
  vtkSmartPointer<vtkVirtualLightField> field = SmallCornellField();
  field->FinalGatherOff();
  const auto limitOf = [&](double z, double origin[3], double normal[3])
  {
    vtkSmartPointer<vtkPolyData> patch = BackWallPatch(z);
    vtkNew<vtkLightFieldReliefSurface> surface;
    vtkNew<mesolight_test::MessageCapture> messages;
    messages->Watch(surface);
    surface->SetLightFieldConnection(field->GetOutputPort());
    surface->SetSurfaceData(patch);
    surface->SetProbesPerSide(2);
    surface->Update();
    EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
    // The field's unit sphere, what a movable object's shadow on the patch must come from.
    double centre[3], scale = 0.0, fieldCentre[3], fieldScale = 0.0;
    EXPECT_TRUE(surface->GetFieldUnitSphere(centre, &scale));
    EXPECT_TRUE(
      vtkVirtualLightField::GetAttachedUnitSphere(field->GetOutput(), fieldCentre, &fieldScale));
    EXPECT_EQ(scale, fieldScale);
    EXPECT_EQ(centre[2], fieldCentre[2]);
    return surface->GetDepthLimitPlane(origin, normal);
  };
  double origin[3], normal[3];
  ASSERT_TRUE(limitOf(558.0, origin, normal));
  EXPECT_NEAR(origin[2], 0.5 * (558.0 + 559.2), 0.01);
  EXPECT_NEAR(normal[0], 0.0, 1e-6);
  EXPECT_NEAR(normal[1], 0.0, 1e-6);
  EXPECT_NEAR(normal[2], -1.0, 1e-6);
  EXPECT_FALSE(limitOf(300.0, origin, normal)) << "in the middle of the room: mounted on none";

  ReliefSurfaceFixture named("back");
  EXPECT_FALSE(named.Surface->GetDepthLimitPlane(origin, normal))
    << "a named surface is the wall itself";
  double centre[3], scale = 0.0;
  EXPECT_TRUE(named.Surface->GetFieldUnitSphere(centre, &scale));
  EXPECT_GT(scale, 0.0);
}

namespace
{
// A relief texture (RGBA floats, depth in A) of n x n texels: square cells of `cell` texels,
// plateaus at depth 0.1 parted by grooves one texel wide at depth 1 (bricks and mortar).
vtkSmartPointer<vtkImageData> GroovedTexture(int n, int cell)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(n, n, 1);
  image->AllocateScalars(VTK_FLOAT, 4);
  float* p = static_cast<float*>(image->GetScalarPointer());
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      float* t = p + 4 * (static_cast<std::size_t>(j) * n + i);
      t[0] = t[1] = 0.5f;
      t[2] = 1.0f;
      t[3] = (i % cell == 0 || j % cell == 0) ? 1.0f : 0.1f;
    }
  }
  return image;
}
} // namespace

// The relief's visible-share map and the emitter lights' factors (what the walkthrough's relief
// adds to its probes, vtkIrradianceProbesTexture): the map is low in the grooves and 1 on the
// plateaus' middles (the exact intersector: a plateau 0.9 above its grooves sees the whole
// hemisphere there) and holds light 0's area shadow; the one lamp's factors stay near or below
// 1 (its area and its point differ by a few per cent this far away); a new depth scale
// computes the map again but keeps the probes; a new surface gathers them again; a texture
// without depth is an error that keeps the probes.
TEST(LightFieldReliefSurface, ReliefOcclusionAddsTheVisibleShareMapAndLightFactors)
{
  vtkSmartPointer<vtkVirtualLightField> field = SmallCornellField();
  field->FinalGatherOff();
  vtkSmartPointer<vtkPolyData> patch = BackWallPatch(558.0);
  vtkNew<vtkLightFieldReliefSurface> surface;
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(surface);
  surface->SetLightFieldConnection(field->GetOutputPort());
  surface->SetSurfaceData(patch);
  surface->SetProbesPerSide(2);
  surface->Update();
  vtkImageData* probes = surface->GetProbesOutput();
  ASSERT_EQ(probes->GetPointData()->GetScalars()->GetNumberOfComponents(), 3)
    << "without SceneOcclusion the probes are as before";
  EXPECT_EQ(
    probes->GetFieldData()->GetArray(vtkIrradianceProbesTexture::GetVisibleShareName()), nullptr);

  const int n = 32, cell = 8;
  surface->SetReliefTextureData(GroovedTexture(n, cell));
  surface->SetReliefDepthScale(0.2);
  surface->SceneOcclusionOn();
  surface->Update();
  ASSERT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  probes = surface->GetProbesOutput();
  vtkDataArray* scalars = probes->GetPointData()->GetScalars();
  ASSERT_EQ(scalars->GetNumberOfComponents(), 4);
  const int lights = surface->GetEmitterLights()->GetNumberOfItems();
  ASSERT_GE(lights, 1);
  for (vtkIdType p = 0; p < scalars->GetNumberOfTuples(); ++p)
  {
    // The light's factor (EmitterLightFactors): the scene's shadow times the lamp's irradiance
    // over its point light's, which differ by a few per cent at most this far from the small
    // Cornell lamp.
    const double factor = scalars->GetComponent(p, 3);
    EXPECT_GE(factor, 0.0);
    EXPECT_LE(factor, 1.05);
    if (p % 9 >= lights)
    {
      EXPECT_EQ(factor, 1.0) << "no light k there";
    }
  }
  vtkDataArray* share =
    probes->GetFieldData()->GetArray(vtkIrradianceProbesTexture::GetVisibleShareName());
  vtkDataArray* size =
    probes->GetFieldData()->GetArray(vtkIrradianceProbesTexture::GetVisibleShareSizeName());
  ASSERT_NE(share, nullptr);
  ASSERT_NE(size, nullptr);
  ASSERT_EQ(size->GetComponent(0, 0), n);
  ASSERT_EQ(size->GetComponent(1, 0), n);
  ASSERT_EQ(share->GetNumberOfTuples(), n * n);
  // A fourth value: the relief's shadow of light 0's area (ReliefEmitterShadowMap over the
  // emitter samples it stands for), as a named surface's map has it; the Cornell lamp above and
  // in front of the back wall reaches into part of the grooves only.
  ASSERT_EQ(share->GetNumberOfComponents(), 4);
  double lowestLight = 1.0;
  for (vtkIdType t = 0; t < share->GetNumberOfTuples(); ++t)
  {
    EXPECT_GE(share->GetComponent(t, 3), 0.0);
    EXPECT_LE(share->GetComponent(t, 3), 1.0);
    lowestLight = std::min(lowestLight, share->GetComponent(t, 3));
  }
  std::cout << "light 0's share past the relief's shadow: lowest " << lowestLight << "\n";
  EXPECT_LT(lowestLight, 0.9);
  double groove = 0.0, middle = 0.0;
  int grooves = 0, middles = 0;
  for (int j = 1; j < n - 1; ++j)
  {
    for (int i = 1; i < n - 1; ++i)
    {
      const double v = share->GetComponent(static_cast<vtkIdType>(j) * n + i, 0);
      if (i % cell == 0 && j % cell != 0)
      {
        groove += v;
        ++grooves;
      }
      else if (i % cell == cell / 2 && j % cell == cell / 2 && i > cell && j > cell &&
        i < n - cell && j < n - cell) // away from the walled border
      {
        middle += v;
        ++middles;
      }
    }
  }
  groove /= grooves;
  middle /= middles;
  std::cout << "visible share: grooves " << groove << ", plateau middles " << middle << "\n";
  EXPECT_LT(groove, 0.6) << "a groove one texel wide and 0.9 deep hides most of the room";
  EXPECT_GT(middle, 0.99);
  EXPECT_EQ(surface->GetProbeComputations(), 2) << "SceneOcclusion gathers again";
  EXPECT_EQ(surface->GetVisibleShareComputations(), 1);

  // A new depth scale: the map again, the probes kept; deeper, the grooves darker.
  surface->SetReliefDepthScale(0.4);
  surface->Update();
  EXPECT_EQ(surface->GetProbeComputations(), 2);
  EXPECT_EQ(surface->GetVisibleShareComputations(), 2);
  share = surface->GetProbesOutput()->GetFieldData()->GetArray(
    vtkIrradianceProbesTexture::GetVisibleShareName());
  ASSERT_NE(share, nullptr);
  EXPECT_LT(share->GetComponent(static_cast<vtkIdType>(4) * n + cell, 0), groove + 1e-9);
  // A new surface: the probes again, the map kept (same frame, texture and depth scale).
  vtkNew<vtkPolyData> copy;
  copy->DeepCopy(patch);
  surface->SetSurfaceData(copy);
  surface->Update();
  EXPECT_EQ(surface->GetProbeComputations(), 3);
  EXPECT_EQ(surface->GetVisibleShareComputations(), 2);

  // A texture without depth: an error, the probes still made (without the map).
  vtkNew<vtkImageData> bad;
  bad->SetDimensions(4, 4, 1);
  bad->AllocateScalars(VTK_FLOAT, 1);
  surface->SetReliefTextureData(bad);
  surface->Update();
  EXPECT_TRUE(messages->HasError("RGBA")) << messages->AllErrors();
  EXPECT_GT(surface->GetProbesOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(surface->GetProbesOutput()->GetFieldData()->GetArray(
              vtkIrradianceProbesTexture::GetVisibleShareName()),
    nullptr);
}

// The map reports its progress after the probes' (non-decreasing, the second half) and stops on
// AbortExecute: empty outputs, no error; the next update makes it.
TEST(LightFieldReliefSurface, AbortStopsTheVisibleShareMapWithoutError)
{
  ReliefSurfaceFixture f("back", 2);
  f.Surface->SetReliefTextureData(GroovedTexture(64, 8));
  f.Surface->SetReliefDepthScale(0.2);
  struct Watch
  {
    std::vector<double> Fractions;
    bool Abort = true;
  } watch;
  vtkNew<vtkCallbackCommand> abort;
  abort->SetClientData(&watch);
  abort->SetCallback(
    [](vtkObject* caller, unsigned long, void* data, void* fraction)
    {
      auto* w = static_cast<Watch*>(data);
      w->Fractions.push_back(*static_cast<double*>(fraction));
      if (w->Abort && w->Fractions.back() > 0.5)
      {
        static_cast<vtkLightFieldReliefSurface*>(caller)->SetAbortExecute(1);
      }
    });
  f.Surface->AddObserver(vtkCommand::ProgressEvent, abort);
  f.Surface->Update();
  EXPECT_TRUE(f.Messages->Errors.empty()) << f.Messages->AllErrors();
  EXPECT_EQ(f.Surface->GetOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(f.Surface->GetProbesOutput()->GetNumberOfPoints(), 0);
  EXPECT_EQ(f.Surface->GetVisibleShareComputations(), 0);
  ASSERT_FALSE(watch.Fractions.empty());
  for (std::size_t k = 1; k < watch.Fractions.size(); ++k)
  {
    EXPECT_GE(watch.Fractions[k], watch.Fractions[k - 1]) << "progress went back at " << k;
  }

  watch.Abort = false;
  f.Surface->SetAbortExecute(0);
  f.Surface->Modified();
  f.Surface->Update();
  EXPECT_EQ(f.Surface->GetVisibleShareComputations(), 1);
  EXPECT_NE(f.Surface->GetProbesOutput()->GetFieldData()->GetArray(
              vtkIrradianceProbesTexture::GetVisibleShareName()),
    nullptr);
}
