// SPDX-License-Identifier: BSD-3-Clause
// Tests of the VTK side of the light field's scenes: vtkTriangleSceneConverter (round trips,
// foreign polydata, bad input), vtkOBJSceneReader (the committed Cornell box OBJ against
// vtkCornellBoxSource, errors and warnings as VTK events) and vtkCornellBoxSource.
#include "MessageCapture.h"
#include "SceneTestUtilities.h"
#include "TriangleScene.h"
#include "vtkCornellBoxSource.h"
#include "vtkOBJSceneReader.h"
#include "vtkTriangleSceneConverter.h"

#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkIntArray.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkStringArray.h"
#include "vtkTransform.h"
#include "vtkTransformFilter.h"

#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <fstream>
#include <string>
#include <vector>

namespace
{
using mesolight::TriangleScene;
using mesolight::vlftest::ExpectSameScene;
using mesolight_test::MessageCapture;

std::string TempPath(const std::string& name)
{
  return std::string(MESOLIGHT_TEST_TEMP_DIR) + "/" + name;
}

TEST(TriangleSceneConverter, CornellBoxRoundTrip)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  vtkNew<vtkTriangleSceneConverter> converter;
  vtkNew<MessageCapture> messages;
  messages->Watch(converter);
  const vtkSmartPointer<vtkPolyData> polyData = converter->ToPolyData(box);
  ASSERT_EQ(polyData->GetNumberOfCells(), static_cast<vtkIdType>(box.TriangleCount()));
  for (const char* name : { "Diffuse", "Specular", "Emission" })
  {
    vtkDataArray* array = polyData->GetCellData()->GetArray(name);
    ASSERT_NE(array, nullptr) << name;
    EXPECT_EQ(array->GetNumberOfComponents(), 3);
  }
  ASSERT_NE(polyData->GetCellData()->GetArray("MaterialId"), nullptr);
  // The light's cells emit (17, 12, 4); others do not.
  vtkDataArray* emission = polyData->GetCellData()->GetArray("Emission");
  int emitting = 0;
  for (vtkIdType c = 0; c < polyData->GetNumberOfCells(); ++c)
  {
    emitting += emission->GetComponent(c, 0) == 17.0;
  }
  EXPECT_EQ(emitting, 2);
  TriangleScene back;
  ASSERT_TRUE(converter->ToTriangleScene(polyData, back));
  ExpectSameScene(box, back);
  EXPECT_EQ(converter->GetLastWarningCount(), 0);
  EXPECT_TRUE(messages->Warnings.empty());
  // The surfaces' names come through (a light field propagated from the polydata had none, so a
  // relief on "floor" was refused from Python): the same triangles for each name.
  ASSERT_NE(polyData->GetCellData()->GetArray("SurfaceId"), nullptr);
  EXPECT_EQ(back.SurfaceNames, box.SurfaceNames);
  EXPECT_EQ(back.SurfaceIds, box.SurfaceIds);
  EXPECT_EQ(mesolight::SurfaceTriangles(back, "floor"), mesolight::SurfaceTriangles(box, "floor"));
  // Polydata without them (a sphere) has no names, as before.
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  TriangleScene unnamed;
  ASSERT_TRUE(converter->ToTriangleScene(sphere->GetOutput(), unnamed));
  EXPECT_TRUE(unnamed.SurfaceIds.empty());
}

// A scene moved, scaled and rotated with vtkTransformFilter transforming every 3-component array
// (ParaView's Transform does by default): its cell colours are scaled and rotated like vectors
// (Kd halved, the lamp's Le turned negative), but its materials come through unchanged from the
// 9-component MaterialColours, with one warning naming the cause. Without it (the negative case)
// the transformed colours would have been the materials.
TEST(TriangleSceneConverter, ATransformedSceneKeepsItsMaterials)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  vtkNew<vtkTriangleSceneConverter> converter;
  vtkNew<MessageCapture> messages;
  messages->Watch(converter);
  vtkNew<vtkTransform> transform;
  transform->Scale(0.5, 0.5, 0.5);
  transform->RotateY(90.0);
  vtkNew<vtkTransformFilter> moved;
  moved->SetInputData(converter->ToPolyData(box));
  moved->SetTransform(transform);
  moved->TransformAllInputVectorsOn();
  moved->Update();
  vtkPolyData* output = vtkPolyData::SafeDownCast(moved->GetOutput());
  ASSERT_NE(output, nullptr);
  double range[2];
  output->GetCellData()->GetArray("Emission")->GetRange(range, 2);
  EXPECT_LT(range[0], -1.0) << "the filter turned the lamp's Le as a vector";
  double diffuse[2];
  output->GetCellData()->GetArray("Diffuse")->GetRange(diffuse, -1);
  std::printf("[ figures  ] after the Transform (scale 0.5, 90 degrees about y): cell Emission's "
              "z from %.1f, Diffuse magnitude up to %.3f (the box's Kd up to 0.78 per channel)\n",
    range[0], diffuse[1]);

  TriangleScene back;
  ASSERT_TRUE(converter->ToTriangleScene(output, back));
  ASSERT_EQ(back.Materials.size(), box.Materials.size());
  for (std::size_t k = 0; k < box.Materials.size(); ++k)
  {
    EXPECT_EQ(back.Materials[k].Name, box.Materials[k].Name);
    EXPECT_EQ(back.Materials[k].Diffuse, box.Materials[k].Diffuse) << box.Materials[k].Name;
    EXPECT_EQ(back.Materials[k].Emission, box.Materials[k].Emission) << box.Materials[k].Name;
  }
  EXPECT_EQ(back.MaterialIds, box.MaterialIds);
  EXPECT_TRUE(messages->HasWarning("Transform All Input Vectors")) << messages->AllWarnings();
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();

  // Negative: the same polydata without MaterialColours takes the transformed colours.
  vtkNew<vtkPolyData> untabled;
  untabled->DeepCopy(output);
  untabled->GetCellData()->RemoveArray("MaterialColours");
  messages->Clear();
  TriangleScene transformed;
  converter->ToTriangleScene(untabled, transformed);
  EXPECT_FALSE(messages->HasWarning("Transform All Input Vectors"));
  bool anyDiffers = false;
  for (std::size_t k = 0; k < transformed.Materials.size() && k < box.Materials.size(); ++k)
  {
    anyDiffers = anyDiffers || transformed.Materials[k].Diffuse != box.Materials[k].Diffuse;
  }
  EXPECT_TRUE(anyDiffers || !messages->Errors.empty());
}

// Two scenes appended, the first scaled by a Transform first (all vectors): their MaterialIds
// collide, and the cells of a collided id keep their own colours (MaterialColours, untouched by
// the Transform), one material per colour, with one warning. Before, every cell of an id took
// the first cell's colours.
TEST(TriangleSceneConverter, AppendedScenesKeepEachOnesMaterials)
{
  const TriangleScene box = mesolight::MakeCornellBox();
  TriangleScene repainted = box; // the same ids and names, other colours
  for (mesolight::SceneMaterial& m : repainted.Materials)
  {
    m.Diffuse = glm::vec3(0.25f, 0.5f, 0.125f) * (m.Emission.x > 0.0f ? 0.0f : 1.0f);
  }
  vtkNew<vtkTriangleSceneConverter> converter;
  vtkNew<MessageCapture> messages;
  messages->Watch(converter);
  vtkNew<vtkTransform> transform;
  transform->Scale(2.0, 2.0, 2.0);
  vtkNew<vtkTransformFilter> moved;
  moved->SetInputData(converter->ToPolyData(box));
  moved->SetTransform(transform);
  moved->TransformAllInputVectorsOn();
  vtkNew<vtkAppendPolyData> both;
  both->AddInputConnection(moved->GetOutputPort());
  both->AddInputData(converter->ToPolyData(repainted));
  both->Update();

  TriangleScene back;
  ASSERT_TRUE(converter->ToTriangleScene(both->GetOutput(), back));
  ASSERT_EQ(back.TriangleCount(), 2 * box.TriangleCount());
  std::size_t wrong = 0;
  for (std::size_t t = 0; t < box.TriangleCount(); ++t)
  {
    const std::size_t second = box.TriangleCount() + t;
    wrong += back.MaterialOf(t).Diffuse != box.MaterialOf(t).Diffuse ? 1 : 0;
    wrong += back.MaterialOf(second).Diffuse != repainted.MaterialOf(t).Diffuse ? 1 : 0;
    wrong += back.MaterialOf(t).Emission != box.MaterialOf(t).Emission ? 1 : 0;
  }
  EXPECT_EQ(wrong, 0u) << "of " << 3 * box.TriangleCount() << " colours compared";
  EXPECT_TRUE(messages->HasWarning("material ids collide")) << messages->AllWarnings();
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
}

TEST(TriangleSceneConverter, ForeignPolyData)
{
  vtkNew<vtkTriangleSceneConverter> converter;
  vtkNew<MessageCapture> messages;
  messages->Watch(converter);
  // A sphere without material arrays: default grey material, with a warning.
  vtkNew<vtkSphereSource> sphere;
  sphere->Update();
  TriangleScene scene;
  ASSERT_TRUE(converter->ToTriangleScene(sphere->GetOutput(), scene));
  EXPECT_EQ(
    scene.TriangleCount(), static_cast<std::size_t>(sphere->GetOutput()->GetNumberOfPolys()));
  ASSERT_EQ(scene.Materials.size(), 1u);
  EXPECT_EQ(scene.Materials[0].Diffuse, glm::vec3(0.5f));
  EXPECT_EQ(scene.Materials[0].Emission, glm::vec3(0.0f));
  EXPECT_EQ(scene.Normals.size(), scene.Positions.size()); // the sphere's point normals
  EXPECT_TRUE(messages->HasWarning("no cell array Diffuse, Specular, Emission"));
  EXPECT_TRUE(messages->Errors.empty());

  // Quads are triangulated (a warning); a 1-component Diffuse is grey; without MaterialId, cells
  // with equal colours share a material.
  messages->Warnings.clear();
  vtkNew<vtkPlaneSource> plane;
  plane->SetResolution(3, 2);
  plane->Update();
  vtkNew<vtkPolyData> quads;
  quads->DeepCopy(plane->GetOutput());
  vtkNew<vtkFloatArray> diffuse;
  diffuse->SetName("Diffuse");
  vtkNew<vtkFloatArray> emission;
  emission->SetName("Emission");
  emission->SetNumberOfComponents(3);
  for (vtkIdType c = 0; c < quads->GetNumberOfCells(); ++c)
  {
    diffuse->InsertNextValue(c < 3 ? 0.25f : 0.75f);
    const float e[3] = { c == 0 ? 1.0f : 0.0f, 0.0f, 0.0f };
    emission->InsertNextTypedTuple(e);
  }
  quads->GetCellData()->AddArray(diffuse);
  quads->GetCellData()->AddArray(emission);
  ASSERT_TRUE(converter->ToTriangleScene(quads, scene));
  EXPECT_EQ(scene.TriangleCount(), 12u);
  EXPECT_TRUE(messages->HasWarning("6 polygons/strips triangulated into 12 triangles"));
  EXPECT_TRUE(messages->HasWarning("no cell array Specular"));
  ASSERT_EQ(scene.Materials.size(), 3u); // emitting 0.25, plain 0.25, plain 0.75
  EXPECT_EQ(scene.MaterialOf(0).Diffuse, glm::vec3(0.25f));
  EXPECT_EQ(scene.MaterialOf(0).Emission, glm::vec3(1.0f, 0.0f, 0.0f));
  EXPECT_EQ(scene.MaterialOf(11).Diffuse, glm::vec3(0.75f));
  double area = 0.0;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    area += scene.Area(t);
  }
  EXPECT_NEAR(area, 1.0, 1e-6); // the unit plane
}

TEST(TriangleSceneConverter, BadInput)
{
  vtkNew<vtkTriangleSceneConverter> converter;
  vtkNew<MessageCapture> messages;
  messages->Watch(converter);
  TriangleScene scene;
  EXPECT_FALSE(converter->ToTriangleScene(nullptr, scene));
  vtkNew<vtkPolyData> empty;
  EXPECT_FALSE(converter->ToTriangleScene(empty, scene));
  EXPECT_TRUE(messages->HasError("no points or no cells"));

  // Only lines: nothing to light.
  vtkNew<vtkPolyData> lines;
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(0, 0, 0);
  points->InsertNextPoint(1, 0, 0);
  points->InsertNextPoint(0, 1, 0);
  lines->SetPoints(points);
  lines->AllocateEstimate(1, 2);
  const vtkIdType line[2] = { 0, 1 };
  lines->InsertNextCell(VTK_LINE, 2, line);
  EXPECT_FALSE(converter->ToTriangleScene(lines, scene));
  EXPECT_TRUE(messages->HasError("no polygons"));

  // A NaN point, a 2-component colour, a short array, a negative colour.
  const auto triangle = [&]
  {
    vtkNew<vtkPolyData> t;
    vtkNew<vtkPoints> p;
    p->InsertNextPoint(0, 0, 0);
    p->InsertNextPoint(1, 0, 0);
    p->InsertNextPoint(0, 1, 0);
    t->SetPoints(p);
    t->AllocateEstimate(1, 3);
    const vtkIdType ids[3] = { 0, 1, 2 };
    t->InsertNextCell(VTK_TRIANGLE, 3, ids);
    return vtkSmartPointer<vtkPolyData>(t);
  };
  vtkSmartPointer<vtkPolyData> nan = triangle();
  nan->GetPoints()->SetPoint(1, std::nan(""), 0, 0);
  EXPECT_FALSE(converter->ToTriangleScene(nan, scene));
  EXPECT_TRUE(messages->HasError("not finite"));
  EXPECT_TRUE(scene.Triangles.empty());

  vtkSmartPointer<vtkPolyData> twoComponents = triangle();
  vtkNew<vtkFloatArray> rg;
  rg->SetName("Diffuse");
  rg->SetNumberOfComponents(2);
  rg->InsertNextTuple2(0.5, 0.5);
  twoComponents->GetCellData()->AddArray(rg);
  EXPECT_FALSE(converter->ToTriangleScene(twoComponents, scene));
  EXPECT_TRUE(messages->HasError("'Diffuse' has 2 components"));

  vtkSmartPointer<vtkPolyData> shortArray = triangle();
  vtkNew<vtkFloatArray> none;
  none->SetName("Emission");
  none->SetNumberOfComponents(3);
  shortArray->GetCellData()->AddArray(none);
  EXPECT_FALSE(converter->ToTriangleScene(shortArray, scene));
  EXPECT_TRUE(messages->HasError("'Emission' has 0 values for 1 cells"));

  vtkSmartPointer<vtkPolyData> negative = triangle();
  vtkNew<vtkFloatArray> minus;
  minus->SetName("Diffuse");
  minus->InsertNextValue(-1.0f);
  negative->GetCellData()->AddArray(minus);
  EXPECT_FALSE(converter->ToTriangleScene(negative, scene));
  EXPECT_TRUE(messages->HasError("negative value"));
}

TEST(LightFieldSceneReader, CornellBoxObjMatchesSource)
{
  vtkNew<vtkOBJSceneReader> reader;
  vtkNew<MessageCapture> messages;
  messages->Watch(reader);
  reader->SetFileName(MESOLIGHT_SOURCE_DIR "/examples/data/cornell-box.obj");
  reader->RequireEmitterOn();
  reader->Update();
  EXPECT_TRUE(messages->Errors.empty());
  EXPECT_TRUE(messages->Warnings.empty());
  vtkNew<vtkCornellBoxSource> source;
  source->Update();
  vtkNew<vtkTriangleSceneConverter> converter;
  TriangleScene fromReader, fromSource;
  ASSERT_TRUE(converter->ToTriangleScene(reader->GetOutput(), fromReader));
  ASSERT_TRUE(converter->ToTriangleScene(source->GetOutput(), fromSource));
  ExpectSameScene(fromSource, fromReader);
  ExpectSameScene(mesolight::MakeCornellBox(), fromSource);
  auto* names = vtkStringArray::SafeDownCast(
    reader->GetOutput()->GetFieldData()->GetAbstractArray("MaterialNames"));
  ASSERT_NE(names, nullptr);
  EXPECT_EQ(names->GetValue(3), "light");

  // Normalised into the unit sphere: the bounding box's half-diagonal is 1, centred at 0.
  source->NormalizeToUnitSphereOn();
  source->Update();
  double bounds[6];
  source->GetOutput()->GetBounds(bounds);
  const double half = 0.5 *
    std::sqrt(std::pow(bounds[1] - bounds[0], 2) + std::pow(bounds[3] - bounds[2], 2) +
      std::pow(bounds[5] - bounds[4], 2));
  EXPECT_NEAR(half, 1.0, 1e-5);
  EXPECT_NEAR(bounds[0] + bounds[1], 0.0, 1e-5);
  EXPECT_NEAR(bounds[2] + bounds[3], 0.0, 1e-5);
}

TEST(LightFieldSceneReader, ErrorsAndWarnings)
{
  vtkNew<vtkOBJSceneReader> reader;
  vtkNew<MessageCapture> messages;
  messages->Watch(reader);
  // Quiet the executive's "algorithm returned failure" reports about the reader.
  reader->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, messages);
  reader->Update();
  EXPECT_TRUE(messages->HasError("no FileName"));

  const std::string missing = TempPath("no-such-scene.obj");
  reader->SetFileName(missing.c_str());
  reader->Update();
  EXPECT_TRUE(messages->HasError(missing + ": cannot open the file"));
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 0);

  const std::string corrupt = TempPath("corrupt.obj");
  std::ofstream(corrupt) << "v 0 0 0\nv 1 0 0\nv 0 1 0\nf 1 2 4\n";
  reader->SetFileName(corrupt.c_str());
  reader->Update();
  EXPECT_TRUE(messages->HasError(corrupt + ":4: face refers to vertex 4 of 3"));
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 0);

  // Missing MTL and no emitter: warnings, grey output.
  const std::string grey = TempPath("grey.obj");
  std::ofstream(grey) << "mtllib gone.mtl\nv 0 0 0\nv 1 0 0\nv 0 1 0\nv 1 1 0\n"
                         "usemtl wall\nf 1 2 4 3\n";
  messages->Errors.clear();
  reader->SetFileName(grey.c_str());
  reader->Update();
  EXPECT_TRUE(messages->Errors.empty());
  EXPECT_TRUE(messages->HasWarning("mtllib 'gone.mtl' not found"));
  EXPECT_TRUE(messages->HasWarning("no emitter"));
  EXPECT_EQ(reader->GetWarnings().size(), 3u);
  ASSERT_EQ(reader->GetOutput()->GetNumberOfCells(), 2);
  EXPECT_EQ(reader->GetOutput()->GetCellData()->GetArray("Diffuse")->GetComponent(1, 2), 0.5);
  // RequireEmitter turns the last warning into an error.
  reader->RequireEmitterOn();
  reader->Update();
  EXPECT_TRUE(messages->HasError("no emitter"));
  EXPECT_EQ(reader->GetOutput()->GetNumberOfCells(), 0);
}

} // namespace
