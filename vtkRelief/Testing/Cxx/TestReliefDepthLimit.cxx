// SPDX-License-Identifier: BSD-3-Clause
// vtkReliefProperty::SetDepthLimitPlane: a relief mounted a little in front of a wall drawn by
// another actor replaces the wall instead of being hidden by it. Analytic scene, looking straight
// down a parallel camera: the unit square's relief is flat at depth 0 on its left half and at
// depth 1 (0.1 below the square) on its right half; a red wall lies 0.02 below the square, the
// limit plane halfway (0.01 below). Without the limit the wall hides the right half (the negative
// case); with it the right half shows as the relief does alone, its depth exactly the plane's,
// while a quad in front of the plane (0.005 below the square) still hides the right half.
#include "ImageCompare.h"
#include "TestReliefTestUtilities.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkActor.h>
#include <vtkImageData.h>
#include <vtkNew.h>
#include <vtkPlaneSource.h>
#include <vtkPolyDataMapper.h>
#include <vtkProperty.h>

#include <gtest/gtest.h>

#include <cmath>
#include <cstdlib>
#include <vector>

namespace
{
using namespace mesolight;
constexpr int Pixels = 128;
constexpr double DepthScale = 0.1;
constexpr double WallZ = -0.02;
constexpr double LimitZ = -0.01;

vtkSmartPointer<vtkActor> Quad(double z, double r, double g, double b)
{
  vtkNew<vtkPlaneSource> plane;
  plane->SetOrigin(0, 0, z);
  plane->SetPoint1(1, 0, z);
  plane->SetPoint2(0, 1, z);
  vtkNew<vtkPolyDataMapper> mapper;
  mapper->SetInputConnection(plane->GetOutputPort());
  auto actor = vtkSmartPointer<vtkActor>::New();
  actor->SetMapper(mapper);
  actor->GetProperty()->SetColor(r, g, b);
  actor->GetProperty()->SetAmbient(1.0);
  actor->GetProperty()->SetDiffuse(0.0);
  return actor;
}

struct Options
{
  bool Wall = true;
  bool Limit = false;
  bool Blade = false; // a green quad between the square and the limit plane
};

Frame Render(const Options& o)
{
  auto relief = test::BakeRelief(
    test::MakeDepthMap(64, 64, [](double u, double) { return u < 0.5 ? 0.0 : 1.0; }), DepthScale);
  vtkNew<vtkReliefMapper> mapper;
  auto actor = test::UnitSquareRelief(mapper, relief, DepthScale);
  vtkReliefProperty* property = mapper->GetReliefProperty();
  property->SelfShadowingOff();
  property->SilhouettesOff();
  if (o.Limit)
  {
    const double origin[3] = { 0.0, 0.0, LimitZ }, normal[3] = { 0.0, 0.0, 1.0 };
    property->SetDepthLimitPlane(origin, normal);
  }
  const auto wall = Quad(WallZ, 1.0, 0.0, 0.0);
  const auto blade = Quad(-0.005, 0.0, 1.0, 0.0);
  std::vector<vtkActor*> actors{ actor };
  if (o.Wall)
  {
    actors.push_back(wall);
  }
  if (o.Blade)
  {
    actors.push_back(blade);
  }
  return test::CaptureTopDown(actors, Pixels);
}

// Pixels of the right half (the deep relief), away from the step and the edges.
template <typename Visit>
void RightHalf(Visit visit)
{
  for (int y = 4; y < Pixels - 4; ++y)
  {
    for (int x = Pixels / 2 + 4; x < Pixels - 4; ++x)
    {
      visit(std::size_t(y) * Pixels + x);
    }
  }
}

bool Red(const Frame& f, std::size_t p)
{
  return f.Rgb[3 * p] > 200 && f.Rgb[3 * p + 1] < 40 && f.Rgb[3 * p + 2] < 40;
}
} // namespace

TEST(ReliefDepthLimit, WithoutTheLimitTheWallHidesTheDeepRelief)
{
  const Frame f = Render({ true, false, false });
  int red = 0, total = 0;
  RightHalf([&](std::size_t p) { red += Red(f, p) ? 1 : 0, ++total; });
  EXPECT_EQ(red, total) << "the negative case: the wall 0.02 below wins over the relief 0.1 below";
}

TEST(ReliefDepthLimit, TheReliefReplacesTheWallItIsMountedOn)
{
  const Frame alone = Render({ false, false, false });
  const Frame mounted = Render({ true, true, false });
  int red = 0, total = 0, differ = 0;
  double worstDepth = 0.0, worstTop = 0.0;
  RightHalf(
    [&](std::size_t p)
    {
      ++total;
      red += Red(mounted, p) ? 1 : 0;
      for (int c = 0; c < 3; ++c)
      {
        differ += std::abs(int(mounted.Rgb[3 * p + c]) - int(alone.Rgb[3 * p + c])) > 1 ? 1 : 0;
      }
      // The written depth is the limit plane's: 2 - LimitZ from the camera at z = 2.
      worstDepth = std::max(worstDepth, std::abs(mounted.EyeDepth(p) - (2.0 - LimitZ)));
      // Its left twin (depth 0) keeps the square's own depth.
      const std::size_t left = p - Pixels / 2;
      worstTop = std::max(worstTop, std::abs(mounted.EyeDepth(left) - 2.0));
    });
  EXPECT_EQ(red, 0) << "the wall shows through the relief mounted on it";
  EXPECT_EQ(differ, 0) << "the relief looks as it does without the wall";
  EXPECT_LT(worstDepth, 1e-3) << "the deep relief's depth is the limit plane's";
  EXPECT_LT(worstTop, 1e-3) << "the relief above the plane keeps its own depth";
  EXPECT_GT(total, 1000);
}

TEST(ReliefDepthLimit, SurfacesInFrontOfThePlaneStillHideTheDeepRelief)
{
  const Frame f = Render({ true, true, true });
  int green = 0, total = 0;
  RightHalf(
    [&](std::size_t p)
    {
      ++total;
      green += f.Rgb[3 * p] < 40 && f.Rgb[3 * p + 1] > 200 && f.Rgb[3 * p + 2] < 40 ? 1 : 0;
    });
  EXPECT_EQ(green, total) << "a quad 0.005 below the square is in front of the limit plane";
}

TEST(ReliefDepthLimit, RemovingThePlaneRestoresTheDepth)
{
  vtkNew<vtkReliefProperty> property;
  const double origin[3] = { 0.0, 0.0, LimitZ }, normal[3] = { 0.0, 0.0, 1.0 };
  EXPECT_FALSE(property->GetHasDepthLimitPlane());
  property->SetDepthLimitPlane(origin, normal);
  const vtkMTimeType set = property->GetMTime();
  property->SetDepthLimitPlane(origin, normal);
  EXPECT_EQ(property->GetMTime(), set) << "the same plane again is no change";
  EXPECT_TRUE(property->GetHasDepthLimitPlane());
  property->RemoveDepthLimitPlane();
  EXPECT_FALSE(property->GetHasDepthLimitPlane());
  EXPECT_GT(property->GetMTime(), set);
}
