// SPDX-License-Identifier: BSD-3-Clause
// vtkAttachReliefTexture: the relief texture, light set and colour image travel with the surface
// as field data and come back as the same images; a bad colour image is refused with a message.
#include "vtkAttachReliefTexture.h"

#include "MesolightTestUtilities.h"

#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPlaneSource.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
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
  vtkNew<vtkPlaneSource> plane;
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
  attach->Update();
  EXPECT_TRUE(messages->HasError("colour texture")) << messages->AllErrors();
}
