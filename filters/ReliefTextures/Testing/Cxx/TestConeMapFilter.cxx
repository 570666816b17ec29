// SPDX-License-Identifier: BSD-3-Clause
// vtkConeMapFilter: the core's cones packed (float and 8-bit), progress and abort, the memory
// budget, and depth images read as vtkReliefTextureFilter reads them (elevation maps, no-data
// values, GDAL Raster Reader's cells, the true vertical scale). The cores: TestConeMaps.cxx.
#include "ConeMaps.h"
#include "vtkConeMapFilter.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefTextureFilter.h"

#include "vtkCellData.h"
#include "vtkCommand.h"
#include "vtkDataArray.h"
#include "vtkDataSetAttributes.h"
#include "vtkDoubleArray.h"
#include "vtkFieldData.h"
#include "vtkImageData.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkShortArray.h"
#include "vtkStringArray.h"
#include "vtkUnsignedCharArray.h"

#include "MesolightTestUtilities.h"

#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

TEST(vtkConeMapFilter, PacksTheCoreConesReportsProgressAndAborts)
{
  vtkNew<vtkProceduralReliefSource> source;
  source->SetPatternToHemisphereTorus();
  source->SetResolution(40, 33);
  vtkNew<vtkConeMapFilter> filter;
  filter->SetInputConnection(source->GetOutputPort(0));
  std::vector<double> progress;
  struct Progress : public vtkCommand
  {
    static Progress* New() { return new Progress; }
    void Execute(vtkObject* caller, unsigned long, void* data) override
    {
      this->Values->push_back(*static_cast<double*>(data));
      if (this->AbortAt >= 0.0 && this->Values->back() >= this->AbortAt)
      {
        static_cast<vtkAlgorithm*>(caller)->SetAbortExecute(1);
      }
    }
    std::vector<double>* Values = nullptr;
    double AbortAt = -1.0;
  };
  vtkNew<Progress> observer;
  observer->Values = &progress;
  filter->AddObserver(vtkCommand::ProgressEvent, observer);
  filter->Update();
  vtkImageData* out = filter->GetOutput();
  int dims[3];
  out->GetDimensions(dims);
  ASSERT_EQ(dims[0], 40);
  ASSERT_EQ(dims[1], 33);
  vtkDataArray* packed = out->GetPointData()->GetScalars();
  ASSERT_NE(packed, nullptr);
  ASSERT_EQ(packed->GetNumberOfComponents(), 4);
  auto* type =
    vtkStringArray::SafeDownCast(out->GetFieldData()->GetAbstractArray("MesolightConeType"));
  ASSERT_NE(type, nullptr);
  EXPECT_EQ(type->GetValue(0), "relaxed");
  // B is the core's relaxed cone map of the depth in A.
  std::vector<float> depth(40 * 33);
  for (size_t k = 0; k < depth.size(); ++k)
  {
    depth[k] = static_cast<float>(packed->GetComponent(static_cast<vtkIdType>(k), 3));
  }
  const auto cones = mesolight::ComputeRelaxedConeMap(depth.data(), 40, 33);
  for (size_t k = 0; k < depth.size(); ++k)
  {
    ASSERT_EQ(static_cast<float>(packed->GetComponent(static_cast<vtkIdType>(k), 2)), cones[k]);
  }
  ASSERT_GE(progress.size(), 3u);
  EXPECT_TRUE(std::is_sorted(progress.begin(), progress.end())); // the bake's, then the cones'
  EXPECT_LE(progress.front(), 0.1);
  EXPECT_EQ(progress.back(), 1.0);

  // 8-bit packing: the never-widening code of each cone, computed for the depth as stored
  // (rounded to 1/255), which is the surface the renderer samples.
  filter->SetPackingToRatio8Bit();
  filter->SetConeTypeToConservative();
  filter->Update();
  vtkDataArray* bytes = filter->GetOutput()->GetPointData()->GetScalars();
  ASSERT_EQ(bytes->GetDataType(), VTK_UNSIGNED_CHAR);
  std::vector<float> stored(depth.size());
  for (size_t k = 0; k < depth.size(); ++k)
  {
    stored[k] = static_cast<float>(bytes->GetComponent(static_cast<vtkIdType>(k), 3) / 255.0);
  }
  const auto conservative = mesolight::ComputeConservativeConeMap(stored.data(), 40, 33);
  for (size_t k = 0; k < depth.size(); ++k)
  {
    ASSERT_EQ(bytes->GetComponent(static_cast<vtkIdType>(k), 2),
      mesolight::EncodeConeRatio8(conservative[k]));
  }

  // Abort half-way: no error, no cone map.
  progress.clear();
  observer->AbortAt = 0.3;
  filter->SetConeTypeToRelaxed();
  filter->Update();
  EXPECT_LT(progress.back(), 1.0);
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
}

// Above MemoryBudget the cone map is refused before anything is allocated, with the size needed.
TEST(vtkConeMapFilter, MemoryBudgetRefusesBeforeAllocating)
{
  vtkNew<vtkProceduralReliefSource> source;
  source->SetResolution(64, 64);
  vtkNew<vtkConeMapFilter> filter;
  filter->SetInputConnection(source->GetOutputPort(0));
  filter->SetMemoryBudget(4096);
  vtkNew<mesolight_test::MessageCapture> capture;
  capture->Watch(filter);
  filter->Update();
  EXPECT_TRUE(capture->HasError("64 x 64 cone map needs about")) << capture->AllErrors();
  EXPECT_TRUE(capture->HasError("budget of 4 KiB")) << capture->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 0);
  filter->SetMemoryBudget(0); // the machine's memory: plenty
  capture->Errors.clear();
  filter->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfPoints(), 64 * 64);
}

// A depth map is read exactly as vtkReliefTextureFilter reads it, with the same options: an int16
// elevation map with holes at the no-data value its file names, and the same raster as ParaView's
// GDAL Raster Reader gives it (pixels as cells, the holes hidden).
TEST(vtkConeMapFilter, ReadsElevationMapsAsTheReliefFilterDoes)
{
  const int w = 24;
  const int h = 20;
  auto elevation = [](int i, int j) -> short
  {
    if ((i - 6) * (i - 6) + (j - 5) * (j - 5) < 9)
    {
      return -32768; // no data
    }
    return static_cast<short>(140 + 12 * i + 7 * ((i * j) % 5));
  };
  auto withNoDataValue = [](vtkImageData* image)
  {
    vtkNew<vtkDoubleArray> noData;
    noData->SetName("MesolightNoDataValue");
    noData->InsertNextValue(-32768.0);
    image->GetFieldData()->AddArray(noData);
  };
  vtkNew<vtkImageData> dem; // the Mesolight Image Reader's image: pixels as points
  dem->SetDimensions(w, h, 1);
  vtkNew<vtkShortArray> points;
  points->SetName("Elevation");
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      points->InsertNextValue(elevation(i, j));
    }
  }
  dem->GetPointData()->SetScalars(points);
  withNoDataValue(dem);

  vtkNew<vtkReliefTextureFilter> bake;
  bake->SetInputData(dem);
  bake->InvertInputOn();
  bake->NormalizeRangeOn();
  bake->Update();
  ASSERT_EQ(bake->GetNumberOfNoDataTexels(), 25);
  vtkDataArray* relief = bake->GetOutput()->GetPointData()->GetScalars();

  vtkNew<vtkConeMapFilter> cones;
  vtkNew<mesolight_test::MessageCapture> capture;
  capture->Watch(cones);
  cones->SetInputData(dem);
  cones->InvertInputOn();
  cones->NormalizeRangeOn();
  cones->Update();
  ASSERT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  vtkDataArray* packed = cones->GetOutput()->GetPointData()->GetScalars();
  ASSERT_NE(packed, nullptr);
  ASSERT_EQ(packed->GetNumberOfTuples(), w * h);
  for (vtkIdType k = 0; k < w * h; ++k)
  {
    ASSERT_EQ(packed->GetComponent(k, 3), relief->GetComponent(k, 3)) << "texel " << k;
  }
  // The holes lie at the lowest ground (depth 1), not 32 km below the map's top.
  EXPECT_EQ(packed->GetComponent(5 * w + 6, 3), 1.0);
  // What the bake applied is reported as the relief filter reports it.
  EXPECT_TRUE(cones->GetAppliedNoData());
  EXPECT_EQ(cones->GetAppliedNoDataValue(), -32768.0);
  EXPECT_EQ(cones->GetNumberOfNoDataTexels(), bake->GetNumberOfNoDataTexels());

  // Negative cases. The file's value off: the holes are elevations, and the rest is squeezed
  // into a sliver at the top.
  cones->UseInputNoDataValueOff();
  cones->Update();
  EXPECT_LT(cones->GetOutput()->GetPointData()->GetScalars()->GetComponent(10 * w + 20, 3), 0.01);
  // Signed metres without NormalizeRange: refused, naming the option.
  cones->UseInputNoDataValueOn();
  cones->NormalizeRangeOff();
  capture->Errors.clear();
  cones->Update();
  EXPECT_TRUE(capture->HasError("NormalizeRange")) << capture->AllErrors();
  EXPECT_EQ(cones->GetOutput()->GetNumberOfPoints(), 0);
  // A value set here wins over the file's: 0 is in no texel, so -32768 is terrain again.
  cones->NormalizeRangeOn();
  cones->UseNoDataValueOn();
  cones->SetNoDataValue(0.0);
  capture->Errors.clear();
  cones->Update();
  EXPECT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  EXPECT_LT(cones->GetOutput()->GetPointData()->GetScalars()->GetComponent(10 * w + 20, 3), 0.01);

  // Georeferenced (pixels 100 m wide): the true vertical scale times the exaggeration, as the
  // relief filter bakes it, normals included; without a pixel size, refused.
  cones->UseNoDataValueOff();
  cones->UseTrueDepthScaleOn();
  cones->SetVerticalExaggeration(3.0);
  capture->Errors.clear();
  cones->Update();
  EXPECT_TRUE(capture->HasError("carries its pixel size on the ground")) << capture->AllErrors();
  vtkNew<vtkDoubleArray> pixelSize;
  pixelSize->SetName("MesolightPixelSize");
  pixelSize->SetNumberOfComponents(2);
  pixelSize->InsertNextTuple2(100.0, 100.0);
  dem->GetFieldData()->AddArray(pixelSize);
  dem->Modified();
  capture->Errors.clear();
  cones->Update();
  ASSERT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  bake->SetInputData(dem);
  bake->UseTrueDepthScaleOn();
  bake->SetVerticalExaggeration(3.0);
  bake->Update();
  ASSERT_GT(bake->GetTrueDepthScale(), 0.0);
  EXPECT_EQ(cones->GetOutput()->GetFieldData()->GetArray("MesolightDepthScale")->GetComponent(0, 0),
    bake->GetOutput()->GetFieldData()->GetArray("MesolightDepthScale")->GetComponent(0, 0));
  relief = bake->GetOutput()->GetPointData()->GetScalars();
  packed = cones->GetOutput()->GetPointData()->GetScalars();
  for (vtkIdType k = 0; k < w * h; ++k)
  {
    ASSERT_FLOAT_EQ(static_cast<float>(packed->GetComponent(k, 0)),
      static_cast<float>(relief->GetComponent(k, 0)))
      << "texel " << k;
  }
  cones->UseTrueDepthScaleOff();
  bake->UseTrueDepthScaleOff();

  // The same raster as cells of a grid one point larger, the holes hidden: the cone map is that
  // of the relief filter's corner means, not refused for want of point scalars.
  vtkNew<vtkImageData> cellsRaster;
  cellsRaster->SetDimensions(w + 1, h + 1, 1);
  vtkNew<vtkShortArray> cells;
  cells->DeepCopy(points);
  cellsRaster->GetCellData()->SetScalars(cells);
  cellsRaster->AllocateCellGhostArray();
  for (vtkIdType k = 0; k < w * h; ++k)
  {
    if (cells->GetValue(k) == -32768)
    {
      cellsRaster->GetCellGhostArray()->SetValue(k, vtkDataSetAttributes::HIDDENCELL);
    }
  }
  bake->SetInputData(cellsRaster);
  bake->Update();
  cones->SetInputData(cellsRaster);
  cones->UseNoDataValueOff();
  capture->Errors.clear();
  cones->Update();
  ASSERT_TRUE(capture->Errors.empty()) << capture->AllErrors();
  relief = bake->GetOutput()->GetPointData()->GetScalars();
  packed = cones->GetOutput()->GetPointData()->GetScalars();
  ASSERT_EQ(packed->GetNumberOfTuples(), (w + 1) * (h + 1));
  for (vtkIdType k = 0; k < (w + 1) * (h + 1); ++k)
  {
    ASSERT_EQ(packed->GetComponent(k, 3), relief->GetComponent(k, 3)) << "texel " << k;
  }
  EXPECT_GT(bake->GetNumberOfNoDataTexels(), 0);
}
