// SPDX-License-Identifier: BSD-3-Clause
// How the relief is stored on the GPU (vtkReliefTextureCache): the compact storage (the default:
// 16-bit depth, no normals when they are the depth's own, else 8-bit ones, 8-bit cones, 8-bit
// pyramid) must hit where the float RGBA storage hits, both measured against the exact CPU
// intersector (ReliefReference); the bytes the mapper reports must be those of the formats; and a
// storage that loses depth precision (8-bit depth on a deep map) must fail the same check.
#include "DenseMeshTestScene.h"
#include "ImageCompare.h"
#include "ReliefReference.h"
#include "ReliefScene.h"
#include "vtkConeMapFilter.h"
#include "vtkMinDepthPyramidTexture.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkActor.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkMapper.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>

#include <gtest/gtest.h>

#include <cmath>
#include <iostream>

namespace
{
using namespace mesolight;

enum class Storage
{
  Float,
  Compact
};

const char* Name(Storage s)
{
  return s == Storage::Float ? "float" : "compact";
}

struct Measured
{
  HitComparison Hits;
  long long Bytes = 0;
};

// A scene with its exact reference, drawn in any storage (and with any relief texture).
struct StorageScene
{
  ReliefSceneOptions Options;
  ReliefScene Scene;
  ReliefReference Reference;
  vtkSmartPointer<vtkRenderWindow> Window;

  explicit StorageScene(const ReliefSceneOptions& o)
    : Options(o)
  {
    std::string error;
    EXPECT_TRUE(BuildReliefScene(o, this->Scene, error)) << error;
    EXPECT_TRUE(
      ComputeReliefReference(MakeReliefReferenceInput(this->Scene, o), this->Reference, error))
      << error;
    this->Window = MakeOffscreenWindow(o, this->Scene.Renderer);
    const int cones =
      vtkReliefProperty::GetRequiredConeMap(vtkReliefProperty::GetMethodFromName(o.Method.c_str()));
    if (cones != vtkReliefProperty::NoConeMap)
    {
      vtkNew<vtkConeMapFilter> filter;
      filter->SetInputData(this->Scene.ReliefTexture);
      filter->SetDepthScale(o.DepthScale);
      if (cones == vtkReliefProperty::ConservativeConeMap)
      {
        filter->SetConeTypeToConservative();
      }
      filter->Update();
      vtkNew<vtkImageData> coneMap;
      coneMap->DeepCopy(filter->GetOutput());
      this->Scene.Mapper->SetReliefTextureData(coneMap);
    }
  }

  Measured Draw(Storage storage, const std::string& tag)
  {
    vtkReliefProperty* p = this->Scene.Mapper->GetReliefProperty();
    p->SetFloatTextures(storage == Storage::Float);
    p->SetOutput(vtkReliefProperty::HitUOutput);
    const Frame u = CaptureFrame(this->Window);
    p->SetOutput(vtkReliefProperty::HitVOutput);
    const Frame v = CaptureFrame(this->Window);
    Measured m;
    m.Hits = CompareHits(this->Reference, u, v);
    m.Bytes = this->Scene.Mapper->GetReliefTextureBytes();
    std::cout << "[" << tag << ", " << Name(storage) << "] hit error mean " << m.Hits.MeanTexels
              << " texels, p99 " << m.Hits.P99Texels << "; silhouette mismatch "
              << m.Hits.SilhouetteMismatch << "%; " << m.Bytes << " bytes on the GPU" << std::endl;
    EXPECT_GT(m.Hits.CoveredBoth, this->Options.Width * this->Options.Height / 10);
    return m;
  }
};

struct StorageCase
{
  const char* Pattern;
  const char* Method;
  int LinearSteps;
  int RefinementSteps;
  double ViewAngle;
  int Resolution;
};

void PrintTo(const StorageCase& c, std::ostream* os)
{
  *os << c.Pattern << " " << c.Method << " " << c.LinearSteps << "+" << c.RefinementSteps << " at "
      << c.ViewAngle << " deg, " << c.Resolution << "^2";
}

ReliefSceneOptions OptionsOf(const StorageCase& c)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Pattern = c.Pattern;
  o.Method = c.Method;
  o.LinearSteps = c.LinearSteps;
  o.RefinementSteps = c.RefinementSteps;
  o.ViewAngle = c.ViewAngle;
  o.Resolution = c.Resolution;
  o.FillViewport = true;
  return o;
}

class ReliefStorage : public ::testing::TestWithParam<StorageCase>
{
};
} // namespace

// Compact storage against float storage, both against the exact hits. The 301^2 map has rows of
// 602 bytes, not a multiple of 4: a wrong row alignment would shear it.
TEST_P(ReliefStorage, CompactHitsAsExactlyAsFloat)
{
  const StorageCase c = GetParam();
  StorageScene scene(OptionsOf(c));
  const std::string tag = std::string(c.Pattern) + " " + c.Method;
  const Measured f = scene.Draw(Storage::Float, tag);
  const Measured k = scene.Draw(Storage::Compact, tag);
  // 16-bit depth moves a hit by less than a hundredth of a texel here; 8-bit cone ratios are
  // rounded to narrower cones, which can only shorten steps.
  EXPECT_LE(k.Hits.MeanTexels, f.Hits.MeanTexels + 0.01);
  EXPECT_LE(k.Hits.P99Texels, f.Hits.P99Texels + 0.05);
  EXPECT_LE(k.Hits.SilhouetteMismatch, f.Hits.SilhouetteMismatch + 0.05);
  EXPECT_LT(double(k.Bytes), 0.25 * double(f.Bytes));
}

INSTANTIATE_TEST_SUITE_P(Methods, ReliefStorage,
  ::testing::Values(StorageCase{ "Bricks", "relief", 32, 8, 70.0, 256 },
    StorageCase{ "Stone", "relief", 10, 8, 55.0, 301 },
    StorageCase{ "Bricks", "max-mipmap", 128, 0, 80.0, 256 },
    StorageCase{ "Stone", "max-mipmap", 128, 0, 70.0, 301 },
    StorageCase{ "Bricks", "relaxed-cone", 32, 8, 70.0, 256 },
    StorageCase{ "Stone", "cone", 32, 4, 55.0, 256 }));

// The bytes the mapper reports are those of the formats uploaded: per texel 2 (16-bit depth; the
// maps' normals are their depth's own, not uploaded), + 1 (8-bit cone ratio) for cone methods;
// the max-mipmap pyramid at 4 bytes per cell from level 2 (16 in float storage); float storage 16
// per texel; level of detail adds the normal moments' 16 bytes per texel of mip levels 2 and up.
// Normals made apart add 2 (NormalsThatAreNotTheDepthsAreUploaded).
TEST(ReliefStorage, ReportedBytesAreThoseOfTheFormats)
{
  const int n = 301;
  const long long texels = static_cast<long long>(n) * n;
  // Pyramid cells from level 2 (levels 0-1 are not stored: level 0's corners come from the depth
  // texture), (n + 1)^2 cells at level 0, sizes halving rounding down.
  long long pyramid = 0;
  const int first = vtkMinDepthPyramidTexture::FirstLevel;
  for (int w = (n + 1) >> first, h = (n + 1) >> first;;
       w = std::max(1, w / 2), h = std::max(1, h / 2))
  {
    pyramid += static_cast<long long>(w) * h;
    if (w == 1 && h == 1)
    {
      break;
    }
  }
  struct Expected
  {
    const char* Method;
    Storage S;
    long long Bytes;
  };
  const Expected expected[] = {
    { "relief", Storage::Compact, 2 * texels },
    { "relief", Storage::Float, 16 * texels },
    // The compact pyramid: four 8-bit children's minima per cell from level 2 (RGBA8); the
    // float one the same in 32 bits.
    { "max-mipmap", Storage::Compact, 2 * texels + 4 * pyramid },
    { "max-mipmap", Storage::Float, 16 * texels + 16 * pyramid },
    { "relaxed-cone", Storage::Compact, 3 * texels },
  };
  for (const Expected& e : expected)
  {
    StorageCase c{ "Bricks", e.Method, 16, 4, 55.0, n };
    StorageScene scene(OptionsOf(c));
    const Measured m = scene.Draw(e.S, e.Method);
    EXPECT_EQ(m.Bytes, e.Bytes) << e.Method << " " << Name(e.S);
  }
  // Level of detail (the vtkReliefProperty default; these scenes draw without it) adds the
  // normal's second moments, two RGBA16F textures, 16 bytes per texel, from mip level 2 (75^2)
  // down to 1 x 1 (levels 0 and 1 follow from the depth's surface cells); the depth keeps no mip
  // chain (the visible normal filter reads its level 0 only).
  long long momentTexels = 0; // levels 2 and up, sizes halving rounding down
  for (int w = n / 4;; w = std::max(1, w / 2))
  {
    momentTexels += static_cast<long long>(w) * w;
    if (w == 1)
    {
      break;
    }
  }
  {
    StorageCase c{ "Bricks", "relief", 16, 4, 55.0, n };
    ReliefSceneOptions o = OptionsOf(c);
    o.LevelOfDetail = true;
    StorageScene scene(o);
    const Measured m = scene.Draw(Storage::Compact, "relief, level of detail");
    EXPECT_EQ(m.Bytes, 2 * texels + 16 * momentTexels) << "level of detail";
  }
  // The ratio the relief benchmark reports: the dense displaced mesh's 32 bytes per vertex and
  // 12 per triangle against the default method's compact textures.
  const double dense = 32.0 * texels + 12.0 * 2.0 * (n - 1) * (n - 1);
  EXPECT_GE(dense / (2.0 * texels), 10.0);
}

// What the default uploads (an untouched vtkReliefProperty: its method, level of detail on with
// the visible normal filter) stays within a tenth of the dense displaced mesh's bytes, counted
// from the mesh itself as the relief benchmark counts it (what VTK's stock mapper uploads:
// position, normal and texture coordinate, 32 bytes a vertex, three 32-bit indices a
// triangle). Negative case: the moments at every mip level in RGBA16F, with the depth's and
// normals' mip chains (the layout before, 26.7 bytes per texel), exceed it.
TEST(ReliefStorage, DefaultUploadsATenthOfTheDenseMesh)
{
  vtkNew<vtkReliefProperty> defaults;
  for (int n : { 256, 301 })
  {
    StorageCase c{ "Stone", vtkReliefProperty::GetMethodName(defaults->GetMethod()),
      defaults->GetLinearSteps(), defaults->GetRefinementSteps(), 55.0, n };
    ReliefSceneOptions o = OptionsOf(c);
    o.LevelOfDetail = defaults->GetLevelOfDetail();
    ASSERT_TRUE(o.LevelOfDetail) << "level of detail is the default";
    StorageScene scene(o);
    const Measured m = scene.Draw(Storage::Compact, "the default");
    // The default filter (masked facets) uploads the moments as the visible one.
    ASSERT_TRUE(scene.Scene.Mapper->GetReliefProperty()->GetNormalFilter() ==
      vtkReliefProperty::MaskedNormalFilter);
    ReliefScene dense;
    std::string error;
    ASSERT_TRUE(BuildDenseReferenceScene(o, dense, error)) << error;
    auto* mesh = vtkPolyData::SafeDownCast(dense.Actor->GetMapper()->GetInputAsDataSet());
    ASSERT_NE(mesh, nullptr);
    const double denseBytes = 32.0 * mesh->GetNumberOfPoints() + 12.0 * mesh->GetNumberOfPolys();
    const double texels = double(n) * n;
    std::cout << n << "^2: the default uploads " << m.Bytes << " bytes (" << m.Bytes / texels
              << " per texel), the dense mesh " << denseBytes << " (" << denseBytes / texels
              << "): " << denseBytes / double(m.Bytes) << "x" << std::endl;
    EXPECT_LE(10.0 * double(m.Bytes), denseBytes) << n << "^2";
    double mipTexels = 0.0; // the layout before: every level of n^2
    for (int w = n;; w = std::max(1, w / 2))
    {
      mipTexels += double(w) * w;
      if (w == 1)
      {
        break;
      }
    }
    EXPECT_GT(10.0 * (4 + 16) * mipTexels, denseBytes) << "negative case: the layout before";
  }
}

// Negative test: depth rounded to 8 bits on a deep map (HemisphereTorus, depth scale 0.15, 256
// texels: a depth step of 1/255 is 0.15 texel, several texels along a grazing ray) fails the
// check compact storage meets.
TEST(ReliefStorage, EightBitDepthOnADeepMapFailsTheCheck)
{
  StorageCase c{ "HemisphereTorus", "max-mipmap", 128, 0, 75.0, 256 };
  ReliefSceneOptions o = OptionsOf(c);
  o.DepthScale = 0.15;
  StorageScene scene(o);
  const Measured f = scene.Draw(Storage::Float, "deep map");
  const Measured k = scene.Draw(Storage::Compact, "deep map");
  EXPECT_LE(k.Hits.MeanTexels, f.Hits.MeanTexels + 0.01);

  vtkNew<vtkImageData> eightBit;
  eightBit->DeepCopy(scene.Scene.ReliefTexture);
  vtkDataArray* texels = eightBit->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < texels->GetNumberOfTuples(); ++i)
  {
    texels->SetComponent(i, 3, std::round(texels->GetComponent(i, 3) * 255.0) / 255.0);
  }
  scene.Scene.Mapper->SetReliefTextureData(eightBit);
  const Measured q = scene.Draw(Storage::Compact, "deep map, depth rounded to 8 bits");
  EXPECT_GT(q.Hits.MeanTexels, f.Hits.MeanTexels + 0.05);
}

// Only normals that are the depth's own (the Sobel normals vtkReliefTextureFilter bakes, at the
// depth scale it records) are left out; others are uploaded, as the shader shades them as given.
TEST(ReliefStorage, NormalsThatAreNotTheDepthsAreUploaded)
{
  StorageCase c{ "Stone", "relief", 16, 4, 55.0, 256 };
  StorageScene scene(OptionsOf(c));
  const Measured own = scene.Draw(Storage::Compact, "Sobel normals");
  EXPECT_EQ(own.Bytes, 2LL * 256 * 256);

  vtkNew<vtkImageData> tilted;
  tilted->DeepCopy(scene.Scene.ReliefTexture);
  vtkDataArray* texels = tilted->GetPointData()->GetScalars();
  for (vtkIdType i = 0; i < texels->GetNumberOfTuples(); ++i)
  {
    // A normal map baked at twice the slope: a few degrees off where the stone is steep.
    const double x = 2.0 * texels->GetComponent(i, 0) - 1.0;
    const double y = 2.0 * texels->GetComponent(i, 1) - 1.0;
    const double z = 2.0 * texels->GetComponent(i, 2) - 1.0;
    const double len = std::sqrt(4.0 * x * x + 4.0 * y * y + z * z);
    texels->SetComponent(i, 0, 0.5 * (2.0 * x / len + 1.0));
    texels->SetComponent(i, 1, 0.5 * (2.0 * y / len + 1.0));
    texels->SetComponent(i, 2, 0.5 * (z / len + 1.0));
  }
  scene.Scene.Mapper->SetReliefTextureData(tilted);
  const Measured stored = scene.Draw(Storage::Compact, "normals at twice the slope");
  EXPECT_EQ(stored.Bytes, 4LL * 256 * 256);

  // Without the depth scale they were baked with, they are not known to be the depth's either.
  vtkNew<vtkImageData> unscaled;
  unscaled->DeepCopy(scene.Scene.ReliefTexture);
  unscaled->GetFieldData()->RemoveArray("MesolightDepthScale");
  scene.Scene.Mapper->SetReliefTextureData(unscaled);
  const Measured unknown = scene.Draw(Storage::Compact, "Sobel normals, scale unknown");
  EXPECT_EQ(unknown.Bytes, 4LL * 256 * 256);
}

// The compact storage shades as the float one: colour against the dense displaced mesh where
// exact max-mipmap hits land on the bricks' walls, with the depth's own normals (none uploaded:
// the shader shades the surface from the 16-bit depth) and with normals whose depth scale is
// unknown (uploaded in 8 bits, octahedral: steep normals an encoding blended in its own
// coordinates would bend).
TEST(ReliefStorage, CompactNormalsShadeAsTheFloatOnes)
{
  ReliefSceneOptions o = test::DenseMeshTestScene();
  o.Method = "max-mipmap";
  o.LinearSteps = 128;
  o.RefinementSteps = 0;
  o.ViewAngle = 75.0;
  o.FillViewport = true;
  std::string error;
  ReliefScene dense;
  ASSERT_TRUE(BuildDenseReferenceScene(o, dense, error)) << error;
  auto denseWindow = MakeOffscreenWindow(o, dense.Renderer);
  const Frame reference = CaptureFrame(denseWindow);
  ReliefScene relief;
  ASSERT_TRUE(BuildReliefScene(o, relief, error)) << error;
  auto window = MakeOffscreenWindow(o, relief.Renderer);
  vtkNew<vtkImageData> unscaled;
  unscaled->DeepCopy(relief.ReliefTexture);
  unscaled->GetFieldData()->RemoveArray("MesolightDepthScale");
  for (bool depthsOwn : { true, false })
  {
    relief.Mapper->SetReliefTextureData(depthsOwn ? relief.ReliefTexture.Get() : unscaled.Get());
    const char* normals = depthsOwn ? "the depth's normals" : "normals uploaded";
    double mean[2] = { 0.0, 0.0 };
    for (Storage s : { Storage::Float, Storage::Compact })
    {
      relief.Mapper->GetReliefProperty()->SetFloatTextures(s == Storage::Float);
      const FrameDifference d = CompareFrames(CaptureFrame(window), reference, 0.05 * o.DepthScale);
      mean[static_cast<int>(s)] = d.MeanColorError;
      std::cout << "[bricks at 75 deg, max-mipmap, " << normals << ", " << Name(s)
                << "] colour RMSE against the dense mesh " << d.RmsColorError << " levels, mean "
                << d.MeanColorError << std::endl;
    }
    // Measured with uploaded normals: compact 2.7% above float; the octahedral coordinates
    // filtered by the GPU instead of blended normals were 15% above (and 0.9% in RMSE, which
    // hides it).
    EXPECT_LE(mean[1], 1.05 * mean[0]) << normals;
  }
}
