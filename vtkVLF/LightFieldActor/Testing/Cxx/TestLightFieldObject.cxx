// SPDX-License-Identifier: BSD-3-Clause
// A movable object in vtkLightFieldActor's field (Wither 2005, "Interactive dynamic objects in a
// virtual light field"), offscreen under Xvfb: in every mode the object hides what is behind it
// (depth buffer; no screen value over the mirror) and appears in the mirror, as an independent
// ray cast of one merged triangle scene says, pixel by pixel; with the object kept out of the
// tracer (a testing flag) the masks fail. The actor's matrix moves it in the image and
// invalidates the traced reflections; vtkLightFieldObjectMapper's three shadings; weak
// references; bad objects reported, never a crash.
#include "MessageCapture.h"
#include "ObjectTestReference.h"
#include "WalkthroughTestViewer.h"

#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldObjectMapper.h"
#include "vtkTriangleSceneConverter.h"

#include "EmitterLights.h"
#include "ObjectGatherer.h"
#include "ObjectMesh.h"

#include <vtkCellArray.h>
#include <vtkMatrix4x4.h>
#include <vtkPointData.h>
#include <vtkPoints.h>

#include <glm/gtc/matrix_transform.hpp>

namespace mesolight
{
namespace
{
using namespace walkthroughtest;
using namespace objecttest;

vtkSmartPointer<vtkPolyData> ToPolyData(const vlf::ObjectMesh& mesh, bool normals)
{
  auto poly = vtkTriangleSceneConverter::MeshToPolyData(mesh);
  if (!normals)
  {
    poly->GetPointData()->SetNormals(nullptr);
  }
  return poly;
}

const glm::vec3 AboveBlock(470.0f, 400.0f, 380.0f);   // seen directly and in the mirror wall
const glm::vec3 BeforeMirror(480.0f, 200.0f, 100.0f); // hides part of the mirror wall

// The viewer of the mirror Cornell box with a blue sphere (radius 55) drawn flat by the object
// mapper: flat pixels are exactly blue, and its gathered radiance (Kd blue) reflected in the
// mirror (Kd 0) has no red or green.
struct ObjectViewer
{
  const vlf::LightField& Field;
  Viewer View;
  vtkNew<vtkActor> Object;
  vtkNew<vtkLightFieldObjectMapper> Mapper;
  vlf::ObjectMesh Sphere = vlf::MakeSphere(0.5f, 16, 32);
  vtkSmartPointer<vtkPolyData> Input;

  explicit ObjectViewer(const vlf::LightField& field)
    : Field(field)
    , View(field)
  {
    this->Input = ToPolyData(this->Sphere, true);
    this->Mapper->SetInputData(this->Input);
    this->Mapper->SetLightFieldActor(this->View.Actor);
    this->Mapper->SetShadingToFlat();
    this->Object->SetMapper(this->Mapper);
    this->Object->GetProperty()->SetDiffuseColor(0.0, 0.0, 1.0);
    this->Object->SetScale(110.0);
    this->View.Actor->SetMovableObject(this->Object);
    this->View.Renderer->AddActor(this->Object);
    this->Place(AboveBlock);
  }
  void Place(const glm::vec3& world)
  {
    this->Object->SetPosition(world.x, world.y, world.z);
    this->View.Renderer->ResetCameraClippingRange();
  }
  std::vector<std::uint8_t> Masks()
  {
    const glm::mat4 placement =
      vtkLightFieldActorCore::UnitSpherePlacement(this->Field, this->Object->GetMatrix());
    return ReferenceMasks(
      this->Field, vlf::TransformMesh(this->Sphere, placement), CornellView(this->Field));
  }
  // Renders `mode` as the user would see it; progressive "moving" is the frame right after the
  // object moved, "rest" the frame after the traced reflections arrived.
  Images Render(const std::string& mode)
  {
    vtkLightFieldActor* actor = this->View.Actor;
    if (mode == "raytrace")
    {
      return this->View.Render(vtkLightFieldActor::Raytrace);
    }
    if (mode == "coherent")
    {
      return this->View.Render(vtkLightFieldActor::Coherent);
    }
    actor->SetRenderMode(vtkLightFieldActor::Progressive);
    if (mode == "moving")
    {
      double p[3];
      this->Object->GetPosition(p);
      this->Object->SetPosition(p[0] + 1.0, p[1], p[2]);
      this->View.Window->Render();
      this->Object->SetPosition(p);
      const Images images = this->View.Render(vtkLightFieldActor::Progressive);
      EXPECT_FALSE(actor->GetLastFrameConverged());
      return images;
    }
    this->View.Window->Render();
    EXPECT_TRUE(actor->WaitForTracedReflections(60.0));
    const Images images = this->View.Render(vtkLightFieldActor::Progressive);
    EXPECT_TRUE(actor->GetLastFrameConverged());
    return images;
  }
  // Alpha of the actor's screen image at a viewport pixel (0 outside its rectangle).
  float ScreenAlpha(int x, int y)
  {
    vtkLightFieldScreenImage& screen =
      vtkLightFieldActorCore::GetInternals(this->View.Actor).Screen;
    const vlf::PixelRect& r = screen.GetRect();
    if (!screen.IsValid() || x < r.X0 || y < r.Y0 || x >= r.X1 || y >= r.Y1)
    {
      return 0.0f;
    }
    return screen
      .GetPixels()[4 * (static_cast<std::size_t>(y - r.Y0) * r.Width() + (x - r.X0)) + 3];
  }
};

bool IsFlatBlue(const glm::vec3& d)
{
  return d.x < 1.5f / 255.0f && d.y < 1.5f / 255.0f && d.z > 253.5f / 255.0f;
}
bool IsBlueReflection(const glm::vec3& d)
{
  return d.x < 2.5f / 255.0f && d.y < 2.5f / 255.0f && d.z > 8.0f / 255.0f;
}

struct Counts
{
  std::size_t Object = 0, ObjectBlue = 0, OverMirror = 0, OverMirrorValued = 0;
  std::size_t Reflection = 0, ReflectionBlue = 0, Mirror = 0, MirrorBlue = 0;
};

Counts Count(ObjectViewer& viewer, const std::vector<std::uint8_t>& interior,
  const std::vector<vlf::PixelClass>& classes, const Images& images)
{
  Counts c;
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * Size + x;
      const glm::vec3 d = images.Display[i];
      switch (interior[i])
      {
        case Object:
          ++c.Object;
          c.ObjectBlue += IsFlatBlue(d) ? 1 : 0;
          if (classes[i] == vlf::PixelClass::Mirror)
          {
            ++c.OverMirror;
            c.OverMirrorValued += viewer.ScreenAlpha(x, y) > 0.0f ? 1 : 0;
          }
          break;
        case ObjectInMirror:
          ++c.Reflection;
          c.ReflectionBlue += IsBlueReflection(d) ? 1 : 0;
          break;
        case Mirror:
          ++c.Mirror;
          c.MirrorBlue += IsBlueReflection(d) ? 1 : 0;
          break;
        default:
          break;
      }
    }
  }
  return c;
}

TEST(LightFieldObject, OcclusionAndReflectionMasksInEveryMode)
{
  const vlf::LightField& field = MirrorCornellField(513);
  ObjectViewer viewer(field);
  // The mirror without the object (the pixels the object must hide in the mirror modes).
  const std::vector<vlf::PixelClass> classes =
    vlf::WalkthroughTracer(field).ClassifyView(CornellView(field));
  for (const bool ignore : { false, true })
  {
    vtkLightFieldActorTesting::SetIgnoreObject(viewer.View.Actor, ignore);
    for (const glm::vec3& place : { AboveBlock, BeforeMirror })
    {
      viewer.Place(place);
      const std::vector<std::uint8_t> interior = Interior(viewer.Masks(), Size, Size);
      for (const std::string mode : { "raytrace", "moving", "rest", "coherent" })
      {
        const Images images = viewer.Render(mode);
        Dump("object-" + mode + (place == AboveBlock ? "-above" : "-before") +
            (ignore ? "-ignored" : ""),
          images.Radiance);
        const Counts c = Count(viewer, interior, classes, images);
        std::cout << (ignore ? "ignored " : "object  ")
                  << (place == AboveBlock ? "above  " : "before ") << std::setw(9) << mode
                  << ": object pixels drawn " << c.ObjectBlue << "/" << c.Object
                  << ", mirror behind it given a screen value " << c.OverMirrorValued << "/"
                  << c.OverMirror << ", reflection shown " << c.ReflectionBlue << "/"
                  << c.Reflection << ", elsewhere in the mirror " << c.MirrorBlue << "/" << c.Mirror
                  << "\n";
        ASSERT_GT(c.Object, 50u);
        ASSERT_GT(c.Mirror, 200u);
        // The depth buffer hides the field behind the object in every case.
        EXPECT_GE(c.ObjectBlue, c.Object * 98 / 100) << mode;
        EXPECT_LE(c.MirrorBlue, c.Mirror / 100) << mode;
        if (place == AboveBlock)
        {
          ASSERT_GT(c.Reflection, 40u);
          if (!ignore)
          {
            EXPECT_GE(c.ReflectionBlue, c.Reflection * 95 / 100) << mode;
          }
          else
          {
            EXPECT_LT(c.ReflectionBlue, c.Reflection / 10) << mode; // the negative test
          }
        }
        else if (mode != "raytrace")
        {
          ASSERT_GT(c.OverMirror, 50u);
          if (!ignore)
          {
            EXPECT_EQ(c.OverMirrorValued, 0u) << mode;
          }
          else
          {
            // The negative test: the mirror behind the object would be overlaid.
            EXPECT_GT(c.OverMirrorValued, c.OverMirror * 9 / 10) << mode;
          }
        }
      }
    }
  }
}

// Centroid of the pixels a predicate picks (x, y), and their count.
template <typename Pick>
glm::vec3 Centroid(Pick pick)
{
  glm::vec3 sum(0.0f);
  for (int y = 0; y < Size; ++y)
  {
    for (int x = 0; x < Size; ++x)
    {
      if (pick(static_cast<std::size_t>(y) * Size + x))
      {
        sum += glm::vec3(x, y, 1.0f);
      }
    }
  }
  return sum.z > 0.0f ? glm::vec3(sum.x / sum.z, sum.y / sum.z, sum.z) : sum;
}

TEST(LightFieldObject, ActorMatrixMovesItAndInvalidatesTracedReflections)
{
  const vlf::LightField& field = MirrorCornellField(513);
  ObjectViewer viewer(field);
  glm::vec3 previous(0.0f), previousReflection(0.0f);
  const glm::vec3 places[] = { AboveBlock, AboveBlock + glm::vec3(-60.0f, -40.0f, 0.0f) };
  for (int k = 0; k < 2; ++k)
  {
    viewer.Place(places[k]);
    viewer.Object->SetOrientation(0.0, 30.0 * k, 0.0); // normals turn, the sphere looks the same
    const std::vector<std::uint8_t> masks = viewer.Masks();
    for (const std::string mode : { "coherent", "rest" })
    {
      const Images images = viewer.Render(mode);
      const glm::vec3 drawn =
        Centroid([&](std::size_t i) { return IsFlatBlue(images.Display[i]); });
      const glm::vec3 expected = Centroid([&](std::size_t i) { return masks[i] == Object; });
      const glm::vec3 reflection = Centroid(
        [&](std::size_t i)
        {
          return masks[i] == Mirror || masks[i] == ObjectInMirror
            ? IsBlueReflection(images.Display[i])
            : false;
        });
      const glm::vec3 expectedReflection =
        Centroid([&](std::size_t i) { return masks[i] == ObjectInMirror; });
      std::cout << mode << " placement " << k << ": object at (" << drawn.x << ", " << drawn.y
                << ") expected (" << expected.x << ", " << expected.y << "); reflection at ("
                << reflection.x << ", " << reflection.y << ") expected (" << expectedReflection.x
                << ", " << expectedReflection.y << ")\n";
      EXPECT_NEAR(drawn.x, expected.x, 1.0f);
      EXPECT_NEAR(drawn.y, expected.y, 1.0f);
      EXPECT_NEAR(reflection.x, expectedReflection.x, 1.0f);
      EXPECT_NEAR(reflection.y, expectedReflection.y, 1.0f);
      EXPECT_NEAR(reflection.z, expectedReflection.z, 0.15f * expectedReflection.z);
      if (k == 1)
      {
        EXPECT_GT(glm::length(glm::vec2(drawn - previous)), 5.0f);
        EXPECT_GT(glm::length(glm::vec2(reflection - previousReflection)), 3.0f);
      }
      else if (mode == "rest")
      {
        previous = drawn;
        previousReflection = reflection;
      }
    }
  }
  // At rest, a moved object makes the next frame the blurry one until it is traced again.
  viewer.View.Actor->SetRenderMode(vtkLightFieldActor::Progressive);
  viewer.View.Window->Render();
  ASSERT_TRUE(viewer.View.Actor->WaitForTracedReflections(60.0));
  viewer.View.Window->Render();
  EXPECT_TRUE(viewer.View.Actor->GetLastFrameConverged());
  viewer.Place(AboveBlock);
  viewer.View.Window->Render();
  EXPECT_FALSE(viewer.View.Actor->GetLastFrameConverged());
}

TEST(LightFieldObject, ShadingLevelsShareOneGatherAndKeepTheInput)
{
  const vlf::LightField& field = MirrorCornellField(513);
  ObjectViewer viewer(field);
  viewer.Object->GetProperty()->SetDiffuseColor(0.8, 0.8, 0.8);
  const vtkMTimeType inputTime = viewer.Input->GetMTime();
  const int inputArrays = viewer.Input->GetPointData()->GetNumberOfArrays();
  const vtkIdType inputPoints = viewer.Input->GetNumberOfPoints();
  const std::vector<std::uint8_t> masks = Interior(viewer.Masks(), Size, Size);
  for (const int shading : { vtkLightFieldObjectMapper::Flat, vtkLightFieldObjectMapper::Lights,
         vtkLightFieldObjectMapper::Gather })
  {
    viewer.Mapper->SetShading(shading);
    const Images images = viewer.View.Render(vtkLightFieldActor::Coherent);
    float low = 1.0f, high = 0.0f;
    double mean = 0.0;
    std::size_t n = 0;
    for (std::size_t i = 0; i < masks.size(); ++i)
    {
      if (masks[i] == Object)
      {
        const float v = (images.Display[i].x + images.Display[i].y + images.Display[i].z) / 3.0f;
        low = std::min(low, v);
        high = std::max(high, v);
        mean += v;
        ++n;
      }
    }
    mean /= std::max<std::size_t>(1, n);
    // The mapper's colours are what the screen shows (no VTK lighting on top).
    vtkDataArray* colours = viewer.Mapper->GetShadedMesh()->GetPointData()->GetScalars();
    ASSERT_NE(colours, nullptr);
    double colourLow = 255.0, colourHigh = 0.0;
    for (vtkIdType p = 0; p < colours->GetNumberOfTuples(); ++p)
    {
      const double v =
        (colours->GetComponent(p, 0) + colours->GetComponent(p, 1) + colours->GetComponent(p, 2)) /
        3.0;
      colourLow = std::min(colourLow, v);
      colourHigh = std::max(colourHigh, v);
    }
    std::cout << vtkLightFieldObjectMapper::GetShadingAsString(shading) << ": object pixels "
              << 255.0f * low << "-" << 255.0f * high << " (mean " << 255.0 * mean
              << "), vertex colours " << colourLow << "-" << colourHigh << "\n";
    EXPECT_GE(255.0f * low, colourLow - 1.5);
    EXPECT_LE(255.0f * high, colourHigh + 1.5);
    if (shading == vtkLightFieldObjectMapper::Flat)
    {
      EXPECT_NEAR(255.0f * low, 204.0f, 1.5f);
      EXPECT_NEAR(255.0f * high, 204.0f, 1.5f);
    }
    else
    {
      EXPECT_GT(255.0f * (high - low), 10.0f); // lit from one side: shaded, not flat
      EXPECT_GT(255.0 * mean, 5.0);
    }
  }
  // One gather for the frame, shared: the actor's result is what the gather mode drew.
  const vlf::ShadedObject* shaded = vtkLightFieldActorCore::GetShadedObject(viewer.View.Actor);
  ASSERT_NE(shaded, nullptr);
  EXPECT_EQ(static_cast<std::size_t>(viewer.Mapper->GetShadedMesh()->GetNumberOfPoints()),
    shaded->Mesh.Positions.size());
  EXPECT_EQ(viewer.Input->GetMTime(), inputTime);
  EXPECT_EQ(viewer.Input->GetPointData()->GetNumberOfArrays(), inputArrays);
  EXPECT_EQ(viewer.Input->GetNumberOfPoints(), inputPoints);
}

TEST(LightFieldObject, WeakReferencesNoCycle)
{
  const vlf::LightField& field = MirrorCornellField(513);
  Viewer viewer(field);
  const int before = viewer.Actor->GetReferenceCount();
  {
    vtkNew<vtkActor> object;
    vtkNew<vtkLightFieldObjectMapper> mapper;
    mapper->SetInputData(ToPolyData(vlf::MakeCube(1.0f), true));
    mapper->SetLightFieldActor(viewer.Actor);
    object->SetMapper(mapper);
    object->SetPosition(278.0, 100.0, 280.0);
    object->SetScale(80.0);
    viewer.Actor->SetMovableObject(object);
    EXPECT_EQ(viewer.Actor->GetReferenceCount(), before);
    viewer.Renderer->AddActor(object);
    viewer.Render(vtkLightFieldActor::Coherent);
    EXPECT_NE(vtkLightFieldActorCore::GetShadedObject(viewer.Actor), nullptr);
    viewer.Renderer->RemoveActor(object);
  }
  // The object is gone: the scene actor forgets it and renders on.
  EXPECT_EQ(viewer.Actor->GetMovableObject(), nullptr);
  viewer.Render(vtkLightFieldActor::Coherent);
  EXPECT_EQ(vtkLightFieldActorCore::GetShadedObject(viewer.Actor), nullptr);
  EXPECT_EQ(viewer.Actor->GetReferenceCount(), before);
}

TEST(LightFieldObject, BadObjectsAreReportedNotCrashed)
{
  const vlf::LightField& field = MirrorCornellField(513);
  ObjectViewer viewer(field);
  vtkLightFieldActor* actor = viewer.View.Actor;
  vtkNew<mesolight_test::MessageCapture> log;
  log->Watch(actor);
  // Outside the field, and through a wall: shown, with a warning.
  viewer.Place(glm::vec3(278.0f, 273.0f, -2000.0f));
  viewer.View.Render(vtkLightFieldActor::Coherent);
  EXPECT_TRUE(log->HasWarning("outside")) << log->AllWarnings();
  log->Clear();
  viewer.Place(glm::vec3(550.0f, 273.0f, 280.0f));
  viewer.View.Render(vtkLightFieldActor::Coherent);
  EXPECT_TRUE(log->HasWarning("intersects")) << log->AllWarnings();
  log->Clear();
  viewer.Place(AboveBlock);
  viewer.View.Render(vtkLightFieldActor::Coherent);
  EXPECT_EQ(log->AllWarnings() + log->AllErrors(), "");
  // No normals: computed (the same image as with them).
  const Images withNormals = viewer.View.Render(vtkLightFieldActor::Coherent);
  viewer.Mapper->SetInputData(ToPolyData(viewer.Sphere, false));
  const Images without = viewer.View.Render(vtkLightFieldActor::Coherent);
  std::size_t differ = 0;
  for (std::size_t i = 0; i < withNormals.Display.size(); ++i)
  {
    differ += glm::length(withNormals.Display[i] - without.Display[i]) > 3.0f / 255.0f ? 1 : 0;
  }
  EXPECT_LT(differ, 20u);
  // Lines only, zero scale: refused with a message, drawn plainly, no crash.
  vtkNew<vtkPolyData> lines;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  vtkNew<vtkCellArray> cells;
  const vtkIdType ids[2] = { 0, 1 };
  cells->InsertNextCell(2, ids);
  lines->SetPoints(points);
  lines->SetLines(cells);
  viewer.Mapper->SetInputData(lines);
  log->Clear();
  viewer.View.Render(vtkLightFieldActor::Raytrace);
  EXPECT_TRUE(log->HasError("no triangles")) << log->AllErrors();
  EXPECT_EQ(vtkLightFieldActorCore::GetShadedObject(actor), nullptr);
  viewer.Mapper->SetInputData(viewer.Input);
  viewer.Object->SetScale(0.0);
  log->Clear();
  viewer.View.Render(vtkLightFieldActor::Progressive);
  EXPECT_TRUE(log->HasError("movable object")) << log->AllErrors();
  viewer.Object->SetScale(110.0);
  viewer.View.Render(vtkLightFieldActor::Coherent);
  EXPECT_NE(vtkLightFieldActorCore::GetShadedObject(actor), nullptr);
  // The scene actor as its own object is refused.
  actor->SetMovableObject(actor);
  EXPECT_EQ(actor->GetMovableObject(), viewer.Object.GetPointer());
}

TEST(LightFieldObject, EmitterlessFieldIsRefusedBeforeAnyObject)
{
  // An emitter-less field never reaches the actor: building one is refused with a message, so
  // the object's lights and gathered shading always have a lit field (the mapper still warns
  // and shows the ambient term should an approximation come back without lights).
  TriangleScene dark = MakeCornellBox();
  for (SceneMaterial& m : dark.Materials)
  {
    m.Emission = glm::vec3(0.0f);
  }
  vlf::LightFieldSettings settings;
  settings.Directions = 33;
  settings.RaysPerSide = 8;
  settings.TilesPerSide = 1;
  try
  {
    vlf::LightField::Build(dark, settings);
    FAIL() << "an emitter-less field was built";
  }
  catch (const std::exception& e)
  {
    EXPECT_NE(std::string(e.what()).find("no emitter"), std::string::npos) << e.what();
  }
  // The lit field's estimate has lights (what the lights shading uses).
  const vlf::LightApproximation lights = vlf::EstimateEmitterLights(MirrorCornellField(513));
  EXPECT_FALSE(lights.Lights.empty());
}

} // namespace
} // namespace mesolight
