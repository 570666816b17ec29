// SPDX-License-Identifier: BSD-3-Clause
// vtkAttachReliefTexture: the relief texture, light set and colour image travel with the surface
// as field data and come back as the same images; a bad colour image is refused with a message;
// a flat surface that draws the map out of its ground proportions is warned about.
#include "vtkAttachReliefTexture.h"
#include "vtkReliefPlaneFilter.h"

#include "MesolightTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkDoubleArray.h"
#include "vtkExecutive.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkTexturedSphereSource.h"
#include "vtkTransform.h"
#include "vtkTransformPolyDataFilter.h"
#include "vtkTrivialProducer.h"

#include <gtest/gtest.h>

namespace
{
vtkSmartPointer<vtkImageData> Image(int w, int h, int components, float value)
{
  auto image = vtkSmartPointer<vtkImageData>::New();
  image->SetDimensions(w, h, 1);
  vtkNew<vtkFloatArray> texels;
  texels->SetNumberOfComponents(components);
  texels->SetNumberOfTuples(static_cast<vtkIdType>(w) * h);
  texels->FillValue(value);
  image->GetPointData()->SetScalars(texels);
  return image;
}
} // namespace

TEST(AttachReliefTexture, ColorTextureTravelsWithTheSurface)
{
  vtkNew<vtkPlaneSource> plane; // in the map's proportions: twice as wide as tall
  plane->SetPoint2(-0.5, 0.0, 0.0);
  vtkNew<vtkTrivialProducer> relief;
  relief->SetOutput(Image(8, 4, 4, 0.5f));
  vtkNew<vtkTrivialProducer> color;
  auto albedo = Image(8, 4, 3, 0.25f);
  albedo->GetPointData()->GetScalars()->SetComponent(5, 2, 0.75);
  color->SetOutput(albedo);
  vtkNew<vtkAttachReliefTexture> attach;
  attach->SetInputConnection(plane->GetOutputPort());
  attach->SetReliefTextureConnection(relief->GetOutputPort());
  attach->SetColorTextureConnection(color->GetOutputPort());
  attach->Update();
  vtkDataObject* surface = attach->GetOutputDataObject(0);
  auto back = vtkAttachReliefTexture::GetAttachedColorTexture(surface);
  ASSERT_NE(back, nullptr);
  int dims[3];
  back->GetDimensions(dims);
  EXPECT_EQ(dims[0], 8);
  EXPECT_EQ(dims[1], 4);
  EXPECT_EQ(back->GetPointData()->GetScalars()->GetNumberOfComponents(), 3);
  EXPECT_FLOAT_EQ(back->GetPointData()->GetScalars()->GetComponent(5, 2), 0.75f);
  EXPECT_EQ(vtkAttachReliefTexture::GetAttachedLightSet(surface), nullptr);
  EXPECT_NE(vtkAttachReliefTexture::GetAttachedReliefTexture(surface), nullptr);

  // Without the colour input nothing is attached.
  attach->SetColorTextureConnection(nullptr);
  attach->Update();
  EXPECT_EQ(
    vtkAttachReliefTexture::GetAttachedColorTexture(attach->GetOutputDataObject(0)), nullptr);

  // An empty colour image is refused, naming what to connect.
  vtkNew<vtkTrivialProducer> empty;
  empty->SetOutput(vtkNew<vtkImageData>());
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(attach);
  attach->SetColorTextureConnection(empty->GetOutputPort());
  // ... but the filter does not fail, and the relief stays (drawn in its own colour), as with an
  // empty light set (what Median Cut Lights leaves after refusing a 1 x 1 map): a failed filter
  // left ParaView's view without the surface.
  EXPECT_EQ(attach->GetExecutive()->Update(), 1);
  EXPECT_TRUE(messages->HasError("colour texture")) << messages->AllErrors();
  EXPECT_NE(
    vtkAttachReliefTexture::GetAttachedReliefTexture(attach->GetOutputDataObject(0)), nullptr);
  attach->SetColorTextureConnection(nullptr);
  attach->SetLightSetConnection(empty->GetOutputPort());
  messages->Clear();
  EXPECT_EQ(attach->GetExecutive()->Update(), 1);
  EXPECT_TRUE(messages->HasError("light set")) << messages->AllErrors();
  EXPECT_TRUE(messages->HasError("drawn without it")) << messages->AllErrors();
  EXPECT_NE(
    vtkAttachReliefTexture::GetAttachedReliefTexture(attach->GetOutputDataObject(0)), nullptr);
  EXPECT_EQ(vtkAttachReliefTexture::GetAttachedLightSet(attach->GetOutputDataObject(0)), nullptr);
}

namespace
{
// The warnings of attaching relief to surface.
std::string AttachWarnings(vtkAlgorithm* surface, vtkImageData* relief)
{
  vtkNew<vtkTrivialProducer> texture;
  texture->SetOutput(relief);
  vtkNew<vtkAttachReliefTexture> attach;
  attach->SetInputConnection(surface->GetOutputPort());
  attach->SetReliefTextureConnection(texture->GetOutputPort());
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(attach);
  attach->Update();
  EXPECT_EQ(messages->AllErrors(), "");
  EXPECT_NE(vtkAttachReliefTexture::GetAttachedReliefTexture(attach->GetOutputDataObject(0)),
    nullptr); // a warning, not a refusal
  return messages->AllWarnings();
}
} // namespace

// Applied without its Relief Texture (ParaView's input dialog lets one press OK): one error that
// says what to connect and how, not the executive's "has 0 connections but is not optional",
// and the surface passes on (the view does not go empty behind a pipeline failure).
TEST(AttachReliefTexture, AMissingReliefTextureIsSaidAndTheSurfacePasses)
{
  vtkNew<vtkPlaneSource> square;
  vtkNew<vtkAttachReliefTexture> attach;
  attach->SetInputConnection(square->GetOutputPort());
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(attach);
  attach->Update();
  EXPECT_NE(messages->AllErrors().find("No Relief Texture input"), std::string::npos)
    << messages->AllErrors();
  EXPECT_NE(messages->AllErrors().find("Change Input"), std::string::npos) << messages->AllErrors();
  EXPECT_EQ(messages->AllErrors().find("not optional"), std::string::npos) << messages->AllErrors();
  vtkDataSet* output = vtkDataSet::SafeDownCast(attach->GetOutputDataObject(0));
  ASSERT_NE(output, nullptr);
  EXPECT_EQ(output->GetNumberOfPoints(), 4);
  EXPECT_EQ(vtkAttachReliefTexture::GetAttachedReliefTexture(output), nullptr);
}

TEST(AttachReliefTexture, AMapOutOfItsProportionsOnTheSurfaceIsWarnedAbout)
{
  // ParaView's Plane (square) under a map twice as wide as tall: drawn twice too tall.
  auto wide = Image(8, 4, 4, 0.5f);
  vtkNew<vtkPlaneSource> square;
  std::string warnings = AttachWarnings(square, wide);
  EXPECT_NE(warnings.find("Mesolight Relief Plane"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("2 times too tall"), std::string::npos) << warnings;
  EXPECT_NE(warnings.find("height / width on the ground is 0.5"), std::string::npos) << warnings;

  // The plane Relief Plane makes for it, moved, turned and scaled as a user may: no warning.
  vtkNew<vtkReliefPlaneFilter> fitted;
  fitted->SetInputData(wide);
  fitted->SetWidth(3.0);
  vtkNew<vtkTransform> placement;
  placement->Translate(1, 2, 3);
  placement->RotateWXYZ(50, 1, 2, 0.5);
  placement->Scale(7, 7, 7);
  vtkNew<vtkTransformPolyDataFilter> placed;
  placed->SetInputConnection(fitted->GetOutputPort());
  placed->SetTransform(placement);
  EXPECT_EQ(AttachWarnings(placed, wide), "");

  // A georeferenced square map whose pixels are twice as tall as wide on the ground (what a
  // geographic raster's are away from the equator), on the square Plane: drawn twice too wide.
  auto geographic = Image(4, 4, 4, 0.5f);
  vtkNew<vtkDoubleArray> pixelSize;
  pixelSize->SetName("MesolightPixelSize");
  pixelSize->SetNumberOfComponents(2);
  pixelSize->InsertNextTuple2(10.0, 20.0);
  geographic->GetFieldData()->AddArray(pixelSize);
  warnings = AttachWarnings(square, geographic);
  EXPECT_NE(warnings.find("2 times too wide"), std::string::npos) << warnings;

  // Within 2% no warning (a square map on a plane 1% taller than wide).
  vtkNew<vtkPlaneSource> nearlySquare;
  nearlySquare->SetPoint2(-0.5, 0.51, 0.0);
  EXPECT_EQ(AttachWarnings(nearlySquare, Image(4, 4, 4, 0.5f)), "");

  // A curved surface has a stretch of its own parametrisation: no warning.
  vtkNew<vtkTexturedSphereSource> sphere;
  EXPECT_EQ(AttachWarnings(sphere, wide), "");
}

// A re-execution for another input (a colour texture attached, ParaView's Apply) keeps the relief
// texture's attached array: the Relief Surface keeps its visible-share map (seconds of work) per
// array and recomputed it for every colour texture attached or removed. A new relief texture, or
// the same one modified, is a new array. The stretch warning is said once, not per re-execution,
// and again when the stretch changes; it says how to tile the map on a wall.
TEST(AttachReliefTexture, AReExecutionKeepsTheReliefArrayAndSaysTheStretchOnce)
{
  vtkNew<vtkPlaneSource> square;
  vtkNew<vtkTrivialProducer> relief;
  auto wide = Image(8, 4, 4, 0.5f);
  relief->SetOutput(wide);
  vtkNew<vtkAttachReliefTexture> attach;
  attach->SetInputConnection(square->GetOutputPort());
  attach->SetReliefTextureConnection(relief->GetOutputPort());
  vtkNew<mesolight_test::MessageCapture> messages;
  messages->Watch(attach);
  attach->Update();
  const auto texels = [&attach]()
  { return attach->GetOutputDataObject(0)->GetFieldData()->GetArray("MesolightReliefTexture"); };
  vtkDataArray* first = texels();
  ASSERT_NE(first, nullptr);
  const std::string warned = messages->AllWarnings();
  EXPECT_NE(warned.find("2 times too tall"), std::string::npos) << warned;
  // Twice too tall: the map repeated twice up the surface keeps its proportions.
  EXPECT_NE(warned.find("TextureCoordinates_X * 1 * iHat + TextureCoordinates_Y * 2 * jHat"),
    std::string::npos)
    << warned;

  vtkNew<vtkTrivialProducer> color;
  color->SetOutput(Image(8, 4, 3, 0.25f));
  attach->SetColorTextureConnection(color->GetOutputPort());
  attach->Update();
  EXPECT_EQ(texels(), first) << "a colour texture attached made a new relief array";
  EXPECT_EQ(messages->AllWarnings(), warned) << "the same stretch was said again";

  wide->GetPointData()->GetScalars()->SetComponent(0, 3, 0.75);
  wide->GetPointData()->GetScalars()->Modified();
  relief->Modified();
  attach->Update();
  EXPECT_NE(texels(), first) << "a modified relief texture kept the old array";
  EXPECT_EQ(texels()->GetComponent(0, 3), 0.75);

  // Another stretch (a square map on the square plane: none), then the wide map again: said.
  relief->SetOutput(Image(4, 4, 4, 0.5f));
  attach->Update();
  relief->SetOutput(Image(8, 4, 4, 0.5f));
  attach->Update();
  const std::string all = messages->AllWarnings();
  EXPECT_NE(all.find("2 times too tall", warned.size()), std::string::npos) << all;
}
