// SPDX-License-Identifier: BSD-3-Clause
// Bad input reaches the user as a clear VTK error, never as a crash or garbage pixels.
#include "ImageCompare.h"
#include "ReliefScene.h"
#include "TestReliefTestUtilities.h"
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"
#include "vtkReliefMapper.h"
#include "vtkReliefTextureFilter.h"

#include <vtkActor.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkLight.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderer.h>
#include <vtkShaderProperty.h>
#include <vtkStringOutputWindow.h>
#include <vtkTexture.h>

#include <gtest/gtest.h>

#include <cmath>
#include <fstream>
#include <limits>

namespace
{
using namespace mesolight;

// Draws polydata with a relief mapper in a small offscreen window; returns the frame.
Frame DrawWithRelief(vtkReliefMapper* mapper, vtkPolyData* mesh, vtkTexture* albedo = nullptr)
{
  mapper->SetInputData(mesh);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->SetTexture(albedo);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  vtkNew<vtkLight> light;
  light->SetLightTypeToSceneLight();
  light->SetPosition(0.3, -0.5, 1.0);
  renderer->AddLight(light);
  renderer->GetActiveCamera()->SetPosition(0.0, -1.0, 1.5);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->GetActiveCamera()->SetClippingRange(0.1, 10.0);
  ReliefSceneOptions size;
  size.Width = size.Height = 96;
  auto window = MakeOffscreenWindow(size, renderer);
  return CaptureFrame(window);
}

vtkSmartPointer<vtkPolyData> PlaneWithTCoords()
{
  vtkNew<vtkPlaneSource> plane;
  plane->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(plane->GetOutput());
  return mesh;
}

vtkSmartPointer<vtkImageData> SmallRelief()
{
  return test::BakeRelief(
    test::MakeDepthMap(16, 16, [](double u, double v) { return 0.5 + 0.4 * std::sin(9 * u) * v; }),
    0.05);
}

long long CoveredPixels(const Frame& frame)
{
  long long n = 0;
  for (size_t p = 0; p < frame.Depth.size(); ++p)
  {
    n += frame.Covered(p) ? 1 : 0;
  }
  return n;
}
} // namespace

TEST(ReliefBadInput, MissingTextureCoordinatesIsAnError)
{
  auto mesh = PlaneWithTCoords();
  mesh->GetPointData()->SetTCoords(nullptr);
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetReliefTextureData(SmallRelief());
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  const Frame frame = DrawWithRelief(mapper, mesh);
  EXPECT_TRUE(messages->HasError("texture coordinates")) << messages->AllErrors();
  // Named after the mapper the user made, not the helper that found it.
  EXPECT_TRUE(messages->HasError("vtkReliefMapper (")) << messages->AllErrors();
  EXPECT_FALSE(messages->HasError("vtkReliefGeometryCache (")) << messages->AllErrors();
  EXPECT_EQ(CoveredPixels(frame), 0);
}

TEST(ReliefBadInput, MissingReliefTextureIsAnError)
{
  vtkNew<vtkReliefMapper> mapper;
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  DrawWithRelief(mapper, PlaneWithTCoords());
  EXPECT_TRUE(messages->HasError("No relief texture")) << messages->AllErrors();
}

// A surface with neither texture coordinates nor a relief texture (a plain Sphere in ParaView)
// hears first about the relief texture, the first thing a relief surface needs; and each error
// is reported once, not at every render of an interactor or a ParaView view, until something
// changes. A test of the repeats: without the memo of the failed frame each render reports
// again.
TEST(ReliefBadInput, EachErrorIsReportedOnceUntilSomethingChanges)
{
  auto mesh = PlaneWithTCoords();
  vtkSmartPointer<vtkDataArray> tcoords = mesh->GetPointData()->GetTCoords();
  mesh->GetPointData()->SetTCoords(nullptr);
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetInputData(mesh);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->GetActiveCamera()->SetPosition(0.0, -1.0, 1.5);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  ReliefSceneOptions size;
  size.Width = size.Height = 96;
  auto window = MakeOffscreenWindow(size, renderer);
  for (int render = 0; render < 3; ++render)
  {
    window->Render();
  }
  ASSERT_EQ(messages->Errors.size(), 1u) << messages->AllErrors();
  EXPECT_TRUE(messages->HasError("No relief texture")) << messages->AllErrors();

  // A relief texture given: the next error is the missing texture coordinates, once.
  mapper->SetReliefTextureData(SmallRelief());
  messages->Clear();
  for (int render = 0; render < 3; ++render)
  {
    window->Render();
  }
  ASSERT_EQ(messages->Errors.size(), 1u) << messages->AllErrors();
  EXPECT_TRUE(messages->HasError("texture coordinates")) << messages->AllErrors();

  // Mended: drawn, without a word.
  mesh->GetPointData()->SetTCoords(tcoords);
  messages->Clear();
  const Frame frame = CaptureFrame(window);
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  EXPECT_GT(CoveredPixels(frame), 1000);
}

// A light set its source left empty (the source reported why), and one wider than the GPU's
// widest texture, which would otherwise be dropped without a word: each a clear error, and the
// relief still drawn, lit by the renderer's lights as without a light set (as malformed probes).
TEST(ReliefBadInput, EmptyOrTooWideLightSetsAreErrors)
{
  vtkNew<vtkReliefMapper> plain;
  plain->SetReliefTextureData(SmallRelief());
  vtkNew<vtkImageData> empty;
  vtkNew<vtkReliefMapper> emptyMapper;
  emptyMapper->SetReliefTextureData(SmallRelief());
  emptyMapper->SetLightSetData(empty);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(emptyMapper);
  Frame frame = DrawWithRelief(emptyMapper, PlaneWithTCoords());
  EXPECT_TRUE(messages->HasError("The light set is empty")) << messages->AllErrors();
  EXPECT_FALSE(messages->HasError("N x 2")) << messages->AllErrors();
  const Frame withoutLightSet = DrawWithRelief(plain, PlaneWithTCoords());
  EXPECT_GT(CoveredPixels(withoutLightSet), 1000);
  EXPECT_EQ(CompareFrames(frame, withoutLightSet, 1e-6).MeanColorError, 0.0);
  EXPECT_EQ(CompareCoverage(frame, withoutLightSet).Mismatched, 0);

  const int count = 70000; // wider than any GPU's 2D textures (16384 here, 32768 on most)
  vtkNew<vtkImageData> wide;
  wide->SetDimensions(count, 2, 1);
  vtkNew<vtkFloatArray> values;
  values->SetNumberOfComponents(4);
  values->SetNumberOfTuples(2 * count);
  for (int i = 0; i < count; ++i)
  {
    values->SetTuple4(i, 0.0, 0.0, 1.0, 0.0);
    values->SetTuple4(count + i, 1e-4, 1e-4, 1e-4, 0.0);
  }
  wide->GetPointData()->SetScalars(values);
  vtkNew<vtkReliefMapper> wideMapper;
  wideMapper->SetReliefTextureData(SmallRelief());
  wideMapper->SetLightSetData(wide);
  messages->Clear();
  messages->Watch(wideMapper);
  frame = DrawWithRelief(wideMapper, PlaneWithTCoords());
  EXPECT_TRUE(messages->HasError("textures hold at most")) << messages->AllErrors();
  EXPECT_EQ(CompareFrames(frame, withoutLightSet, 1e-6).MeanColorError, 0.0);
  EXPECT_EQ(CompareCoverage(frame, withoutLightSet).Mismatched, 0);
}

TEST(ReliefBadInput, ReliefTextureWithoutFourComponentsIsAnError)
{
  auto depthOnly = test::MakeDepthMap(8, 8, [](double, double) { return 0.5; });
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetReliefTextureData(depthOnly);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  DrawWithRelief(mapper, PlaneWithTCoords());
  EXPECT_TRUE(messages->HasError("4 components")) << messages->AllErrors();
}

TEST(ReliefBadInput, NaNDepthIsRejectedByTheBake)
{
  auto depth = test::MakeDepthMap(16, 16,
    [](double u, double v)
    { return (u > 0.5 && v > 0.5) ? std::numeric_limits<double>::quiet_NaN() : 0.5; });
  vtkNew<vtkReliefTextureFilter> bake;
  bake->SetInputData(depth);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(bake);
  bake->Update();
  EXPECT_FALSE(messages->Errors.empty());
}

TEST(ReliefBadInput, NaNInTheReliefTextureIsRejectedByTheMapper)
{
  auto relief = SmallRelief();
  relief->GetPointData()->GetScalars()->SetComponent(5, 3, std::nan(""));
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetReliefTextureData(relief);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  const Frame frame = DrawWithRelief(mapper, PlaneWithTCoords());
  EXPECT_TRUE(messages->HasError("non-finite")) << messages->AllErrors();
  EXPECT_EQ(CoveredPixels(frame), 0);
}

// A NaN texel of a float albedo texture became a number (black) in VTK's upload, where the
// shader's NaN/Inf check cannot see it: the mapper refuses it, naming the texel.
TEST(ReliefBadInput, NaNInTheAlbedoTextureIsRejectedByTheMapper)
{
  for (const bool bad : { false, true })
  {
    vtkNew<vtkFloatArray> texels;
    texels->SetNumberOfComponents(3);
    texels->SetNumberOfTuples(16);
    texels->FillValue(0.5f);
    if (bad)
    {
      texels->SetComponent(6, 1, std::nan(""));
    }
    vtkNew<vtkImageData> image;
    image->SetDimensions(4, 4, 1);
    image->GetPointData()->SetScalars(texels);
    vtkNew<vtkTexture> albedo;
    albedo->SetInputData(image);
    albedo->SetColorModeToDirectScalars();
    vtkNew<vtkReliefMapper> mapper;
    mapper->SetReliefTextureData(SmallRelief());
    vtkNew<mesolight_test::MessageCapture> messages;
    messages->Watch(mapper);
    const Frame frame = DrawWithRelief(mapper, PlaneWithTCoords(), albedo);
    if (bad)
    {
      EXPECT_TRUE(messages->HasError("albedo texture has a non-finite value at texel 6"))
        << messages->AllErrors();
      EXPECT_EQ(CoveredPixels(frame), 0);
    }
    else
    {
      EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
      EXPECT_GT(CoveredPixels(frame), 100);
    }
  }
}

TEST(ReliefBadInput, OneByOneDepthMapRendersFlat)
{
  auto depth = test::MakeDepthMap(1, 1, [](double, double) { return 0.3; });
  vtkNew<vtkReliefTextureFilter> bake;
  bake->SetInputData(depth);
  vtkNew<mesolight_test::MessageCapture> bakeMessages;
  bakeMessages->Watch(bake);
  bake->Update();
  EXPECT_TRUE(bakeMessages->Errors.empty()) << bakeMessages->AllErrors();
  EXPECT_FALSE(bakeMessages->Warnings.empty()) << "a 1x1 map should be flagged";
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetReliefTextureConnection(bake->GetOutputPort());
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  const Frame frame = DrawWithRelief(mapper, PlaneWithTCoords());
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  EXPECT_GT(CoveredPixels(frame), 100);
}

TEST(ReliefBadInput, DegenerateTrianglesRenderWithoutErrors)
{
  // Two good triangles, one with zero area and one whose texture coordinates coincide.
  vtkNew<vtkPoints> points;
  points->InsertNextPoint(-0.5, -0.5, 0);
  points->InsertNextPoint(0.5, -0.5, 0);
  points->InsertNextPoint(0.5, 0.5, 0);
  points->InsertNextPoint(-0.5, 0.5, 0);
  points->InsertNextPoint(0.0, 0.0, 0);
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetNumberOfComponents(2);
  const float uv[5][2] = { { 0, 0 }, { 1, 0 }, { 1, 1 }, { 0, 1 }, { 1, 1 } };
  for (const auto& t : uv)
  {
    tcoords->InsertNextTypedTuple(t);
  }
  vtkNew<vtkCellArray> polys;
  const vtkIdType tris[4][3] = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 0, 1 }, { 2, 4, 2 } };
  for (const auto& t : tris)
  {
    polys->InsertNextCell(3, t);
  }
  vtkNew<vtkPolyData> mesh;
  mesh->SetPoints(points);
  mesh->SetPolys(polys);
  mesh->GetPointData()->SetTCoords(tcoords);
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetReliefTextureData(SmallRelief());
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  const Frame frame = DrawWithRelief(mapper, mesh);
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  EXPECT_GT(CoveredPixels(frame), 100);
  vtkDataArray* tangents = mapper->GetPreparedInput()->GetPointData()->GetTangents();
  ASSERT_NE(tangents, nullptr);
  for (vtkIdType i = 0; i < tangents->GetNumberOfTuples(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      EXPECT_TRUE(std::isfinite(tangents->GetComponent(i, c)));
    }
  }
}

TEST(ReliefBadInput, UnreadableFilesAreErrors)
{
  const std::string garbage = test::OutputPath("garbage.png");
  {
    std::ofstream out(garbage, std::ios::binary);
    out << "this is not a PNG file at all";
  }
  for (const std::string& file : { test::OutputPath("no-such-file.exr"), garbage })
  {
    vtkNew<vtkOIIOImageReader> reader;
    reader->SetFileName(file.c_str());
    vtkNew<mesolight_test::MessageCapture> messages;
    messages->Watch(reader);
    reader->Update();
    EXPECT_FALSE(messages->Errors.empty()) << file;
    EXPECT_TRUE(messages->HasError(file)) << "the message names the file";
  }
}

// A depth image one texel wide or high leaves the wall (spanning texel centres) without area: the
// scene builder reports it instead of crashing on a plane without texture coordinates.
TEST(ReliefBadInput, DegenerateDepthImagesAreSceneErrors)
{
  const int sizes[][2] = { { 1, 1 }, { 1, 7 }, { 7, 1 } };
  for (const auto& size : sizes)
  {
    const std::string file = test::OutputPath(
      "degenerate-" + std::to_string(size[0]) + "x" + std::to_string(size[1]) + ".png");
    vtkNew<vtkOIIOImageWriter> writer;
    writer->SetInputData(test::MakeDepthMap(size[0], size[1], [](double, double) { return 0.5; }));
    writer->SetFileName(file.c_str());
    writer->Write();
    ReliefSceneOptions options;
    options.DepthFile = file;
    ReliefScene scene;
    std::string error;
    EXPECT_FALSE(BuildReliefScene(options, scene, error)) << file;
    EXPECT_NE(error.find("at least 2x2"), std::string::npos) << error;
  }
  ReliefSceneOptions procedural;
  procedural.Resolution = 1;
  ReliefScene scene;
  std::string error;
  EXPECT_FALSE(BuildReliefScene(procedural, scene, error));
  EXPECT_NE(error.find("at least 2x2"), std::string::npos) << error;
  procedural.Resolution = 2; // the smallest wall still builds
  EXPECT_TRUE(BuildReliefScene(procedural, scene, error)) << error;
}

// A degenerate vtkPlaneSource outputs an empty mesh, without texture coordinates: the mapper
// draws nothing and does not crash.
TEST(ReliefBadInput, DegeneratePlaneDrawsNothing)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0.5, 0.5, 0.0);
  plane->SetPoint1(0.5, 0.5, 0.0);
  plane->SetPoint2(0.5, 1.0, 0.0);
  vtkNew<mesolight_test::MessageCapture> planeMessages; // the source's own complaint is expected
  planeMessages->Watch(plane);
  plane->Update();
  auto mesh = vtkSmartPointer<vtkPolyData>::New();
  mesh->DeepCopy(plane->GetOutput());
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetReliefTextureData(SmallRelief());
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  const Frame frame = DrawWithRelief(mapper, mesh);
  EXPECT_EQ(mesh->GetNumberOfPoints(), 0);
  EXPECT_EQ(CoveredPixels(frame), 0);
}

// A shader that does not compile (here broken through the actor's shader replacements, as a
// user's edit could) is a clear error of the mapper and draws nothing, frame after frame; VTK
// alone would crash on the failed program. It is not compiled again each frame (the compiler's
// message would repeat) until what it is built from changes. Repaired, the same mapper draws again.
TEST(ReliefBadInput, ShaderThatDoesNotCompileIsAnError)
{
  vtkNew<vtkReliefMapper> mapper;
  mapper->SetReliefTextureData(SmallRelief());
  mapper->SetInputData(PlaneWithTCoords());
  vtkNew<vtkActor> actor;
  actor->SetMapper(mapper);
  actor->GetShaderProperty()->AddFragmentShaderReplacement(
    "//VTK::Coincident::Impl", true, "this is not GLSL;", false);
  vtkNew<vtkRenderer> renderer;
  renderer->AddActor(actor);
  renderer->GetActiveCamera()->SetPosition(0.0, -1.0, 1.5);
  renderer->GetActiveCamera()->SetFocalPoint(0.0, 0.0, 0.0);
  renderer->GetActiveCamera()->SetClippingRange(0.1, 10.0);
  ReliefSceneOptions size;
  size.Width = size.Height = 64;
  auto window = MakeOffscreenWindow(size, renderer);
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(mapper);
  // The GLSL compiler's messages go to VTK's output window (vtkShaderProgram's errors).
  vtkSmartPointer<vtkOutputWindow> previousOutput = vtkOutputWindow::GetInstance();
  vtkNew<vtkStringOutputWindow> compilerLog;
  vtkOutputWindow::SetInstance(compilerLog);
  const Frame broken = CaptureFrame(window);
  const std::string afterFirstFrame = compilerLog->GetOutput();
  EXPECT_TRUE(mapper->GetShaderFailed());
  EXPECT_TRUE(messages->HasError("did not compile")) << messages->AllErrors();
  EXPECT_NE(afterFirstFrame.find("vtkShaderProgram"), std::string::npos) << afterFirstFrame;
  EXPECT_EQ(CoveredPixels(broken), 0);
  EXPECT_EQ(CoveredPixels(CaptureFrame(window)), 0); // a second frame: no crash either
  EXPECT_EQ(CoveredPixels(CaptureFrame(window)), 0);
  EXPECT_TRUE(mapper->GetShaderFailed());
  EXPECT_EQ(compilerLog->GetOutput(), afterFirstFrame) << "compiled again with nothing changed";
  vtkOutputWindow::SetInstance(previousOutput);
  actor->GetShaderProperty()->ClearAllShaderReplacements();
  const Frame repaired = CaptureFrame(window);
  EXPECT_FALSE(mapper->GetShaderFailed());
  EXPECT_GT(CoveredPixels(repaired), 0);
}
