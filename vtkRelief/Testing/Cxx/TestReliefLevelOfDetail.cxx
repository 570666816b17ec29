// SPDX-License-Identifier: BSD-3-Clause
// Level of detail and aliasing: a 1024^2 stone relief drawn at 160 x 120, where each pixel
// covers several texels, is compared with the same view rendered at 8 x 8 samples per pixel and
// box-filtered (the supersampled reference), with and without level of detail. Level of detail
// marches level 0 and shades with the footprint's visible mean normal (mip-mapped second moments
// of the normal, LEAN mapping, Olano and Baker 2010), its length dimming the light: it must bring
// the frame closer to the reference. The earlier design, marching the averaged height field,
// made it worse (3.80 against 3.28 levels): averaged depth fills the dark cracks the supersampled
// frame keeps (docs/relief-methods.md). A distant receding wall must come closer to an exact
// supersampled frame than without level of detail and than with the mean normal filter (Toksvig
// 2005); up close the frame and the hits of the exact-intersector comparison must stay as they
// are without it.
#include "ImageCompare.h"
#include "RealHeightMaps.h"
#include "ReliefReference.h"
#include "ReliefScene.h"

#include <vtkNew.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iostream>
#include <string>

namespace
{
using namespace mesolight;
constexpr int Width = 160;
constexpr int Height = 120;
constexpr int Supersampling = 8;

Frame Render(bool levelOfDetail, int scale)
{
  ReliefSceneOptions options;
  options.Pattern = "Stone";
  options.Resolution = 1024;
  options.LevelOfDetail = levelOfDetail;
  options.Width = Width * scale;
  options.Height = Height * scale;
  ReliefScene scene;
  std::string error;
  if (!BuildReliefScene(options, scene, error))
  {
    ADD_FAILURE() << error;
    return Frame();
  }
  auto window = MakeOffscreenWindow(options, scene.Renderer);
  return CaptureFrame(window);
}

struct AliasingError
{
  double Mean = 0.0;   // 8-bit levels over RGB, pixels whose every sample is covered
  double Signed = 0.0; // the mean of frame - reference over the same: too bright above 0
  long long Pixels = 0;
};

// Mean |frame - box-filtered reference| where the pixel and its whole footprint are covered.
AliasingError Compare(const Frame& frame, const Frame& reference)
{
  AliasingError result;
  double sum = 0.0;
  double signedSum = 0.0;
  const int s = Supersampling;
  const int w = frame.Width;
  const int h = frame.Height;
  if (reference.Width != w * s || reference.Height != h * s)
  {
    ADD_FAILURE() << "the reference is not " << s << " times the frame's size";
    return result;
  }
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const size_t p = size_t(y) * w + x;
      if (!frame.Covered(p))
      {
        continue;
      }
      double mean[3] = { 0.0, 0.0, 0.0 };
      bool whole = true;
      for (int j = 0; j < s && whole; ++j)
      {
        for (int i = 0; i < s; ++i)
        {
          const size_t q = size_t(y * s + j) * (w * s) + (x * s + i);
          if (!reference.Covered(q))
          {
            whole = false;
            break;
          }
          for (int c = 0; c < 3; ++c)
          {
            mean[c] += reference.Rgb[3 * q + c];
          }
        }
      }
      if (!whole)
      {
        continue;
      }
      for (int c = 0; c < 3; ++c)
      {
        sum += std::abs(mean[c] / (s * s) - frame.Rgb[3 * p + c]);
        signedSum += frame.Rgb[3 * p + c] - mean[c] / (s * s);
      }
      ++result.Pixels;
    }
  }
  result.Mean = result.Pixels > 0 ? sum / (3.0 * result.Pixels) : 255.0;
  result.Signed = result.Pixels > 0 ? signedSum / (3.0 * result.Pixels) : 0.0;
  return result;
}

// A relief scene at the test's frame size: a `pattern` wall of resolution^2 texels seen at
// viewAngle degrees from its normal, viewDistance wall widths away.
ReliefSceneOptions WallView(
  const char* pattern, int resolution, double viewAngle, double viewDistance)
{
  ReliefSceneOptions options;
  options.Pattern = pattern;
  options.Resolution = resolution;
  options.Width = Width;
  options.Height = Height;
  options.ViewAngle = viewAngle;
  options.ViewDistance = viewDistance;
  return options;
}

// A relief scene drawn as an untouched vtkReliefProperty draws it (its method, steps and level of
// detail), or the same with level of detail off, or the exact reference (maximum-mipmap tracing
// with 128 iterations, which is within 0.003 texel of the exact intersector: relief-methods.md).
enum class Drawn
{
  LevelOfDetailOn,       // the default: the visible normal of the masked facets
  LevelOfDetailMean,     // level of detail with the mean normal filter (Toksvig)
  LevelOfDetailUnmasked, // the visible normal filter (the moments, unmasked)
  LevelOfDetailOff,
  Exact
};

// relief10: relief 10+8 (the default before the exact traversal) instead of the default method;
// farViewRays: the view rays per far pixel (vtkReliefProperty::FarViewRays), 0 the default's.
Frame RenderView(ReliefSceneOptions options, Drawn drawn, int scale, int output,
  ReliefScene* keep = nullptr, bool relief10 = false, int farViewRays = 0)
{
  vtkNew<vtkReliefProperty> defaults;
  options.Method = drawn == Drawn::Exact ? std::string("max-mipmap")
    : relief10                           ? std::string("relief")
                                         : vtkReliefProperty::GetMethodName(defaults->GetMethod());
  options.LinearSteps = drawn == Drawn::Exact ? 128 : (relief10 ? 10 : defaults->GetLinearSteps());
  options.RefinementSteps = defaults->GetRefinementSteps();
  options.AdaptiveSteps = defaults->GetAdaptiveSteps();
  options.LevelOfDetail = drawn == Drawn::LevelOfDetailOn || drawn == Drawn::LevelOfDetailMean ||
    drawn == Drawn::LevelOfDetailUnmasked;
  options.Width *= scale;
  options.Height *= scale;
  ReliefScene scene;
  std::string error;
  if (!BuildReliefScene(options, scene, error))
  {
    ADD_FAILURE() << error;
    return Frame();
  }
  scene.Mapper->GetReliefProperty()->SetMinimumSteps(defaults->GetMinimumSteps());
  scene.Mapper->GetReliefProperty()->SetNormalFilter(drawn == Drawn::LevelOfDetailMean
      ? vtkReliefProperty::MeanNormalFilter
      : drawn == Drawn::LevelOfDetailUnmasked ? vtkReliefProperty::VisibleNormalFilter
                                              : defaults->GetNormalFilter());
  scene.Mapper->GetReliefProperty()->SetOutput(output);
  if (farViewRays > 0)
  {
    scene.Mapper->GetReliefProperty()->SetFarViewRays(farViewRays);
  }
  auto window = MakeOffscreenWindow(options, scene.Renderer);
  Frame frame = CaptureFrame(window);
  if (keep)
  {
    *keep = scene;
  }
  return frame;
}

// Hits of the drawn relief (its hit-coordinate outputs) against the exact CPU intersector.
HitComparison HitsAgainstExact(
  const ReliefSceneOptions& options, Drawn drawn, bool relief10 = false)
{
  ReliefScene scene;
  const Frame u = RenderView(options, drawn, 1, vtkReliefProperty::HitUOutput, &scene, relief10);
  const Frame v = RenderView(options, drawn, 1, vtkReliefProperty::HitVOutput, nullptr, relief10);
  ReliefReference reference;
  std::string error;
  EXPECT_TRUE(ComputeReliefReference(MakeReliefReferenceInput(scene, options), reference, error))
    << error;
  return CompareHits(reference, u, v);
}

// Mean error of the three filters against the exact 8 x 8 supersampled frame of one view.
struct FilterErrors
{
  AliasingError On, Mean, Off;
};

FilterErrors ErrorsOfTheFilters(const ReliefSceneOptions& options, const char* what)
{
  const int shaded = vtkReliefProperty::ShadedOutput;
  const Frame reference = RenderView(options, Drawn::Exact, Supersampling, shaded);
  FilterErrors e;
  e.On = Compare(RenderView(options, Drawn::LevelOfDetailOn, 1, shaded), reference);
  e.Mean = Compare(RenderView(options, Drawn::LevelOfDetailMean, 1, shaded), reference);
  e.Off = Compare(RenderView(options, Drawn::LevelOfDetailOff, 1, shaded), reference);
  std::cout << what << ", error against the " << Supersampling << "x" << Supersampling
            << " supersampled exact frame, " << e.On.Pixels << " pixels: level of detail "
            << e.On.Mean << " levels, with the mean normal filter " << e.Mean.Mean << ", off "
            << e.Off.Mean << std::endl;
  return e;
}
// A real height map (a game texture's height channel from Debian's redeclipse-data) on a wall two
// wall widths away, viewAngle degrees from its normal: the benchmark's far cell
// (`mesolight bench relief-aliasing`), 200 x 150 pixels.
ReliefSceneOptions FarRealMapWall(const std::string& file, double viewAngle)
{
  ReliefSceneOptions options;
  options.Pattern = "file";
  options.DepthFile = file;
  options.DepthFileIsHeight = true;
  options.DepthScale = 0.04;
  options.Width = 200;
  options.Height = 150;
  options.ViewAngle = viewAngle;
  options.ViewDistance = 2.0;
  return options;
}

// Mean error against the exact 8 x 8 supersampled frame of a far grazing real-map wall
// (FarRealMapWall) drawn by the default (several view rays per far pixel), by one view ray per
// far pixel and without level of detail.
struct FarViewRayErrors
{
  AliasingError Default, OneRay, Off;
};

FarViewRayErrors ErrorsOfTheFarViewRays(const std::string& file, double viewAngle, const char* what)
{
  const ReliefSceneOptions options = FarRealMapWall(file, viewAngle);
  const int shaded = vtkReliefProperty::ShadedOutput;
  const Frame reference = RenderView(options, Drawn::Exact, Supersampling, shaded);
  FarViewRayErrors e;
  e.Default = Compare(RenderView(options, Drawn::LevelOfDetailOn, 1, shaded), reference);
  e.OneRay =
    Compare(RenderView(options, Drawn::LevelOfDetailOn, 1, shaded, nullptr, false, 1), reference);
  e.Off = Compare(RenderView(options, Drawn::LevelOfDetailOff, 1, shaded), reference);
  std::cout << what << ", error against the " << Supersampling << "x" << Supersampling
            << " supersampled exact frame, " << e.Default.Pixels << " pixels: default "
            << e.Default.Mean << " levels, one view ray per far pixel " << e.OneRay.Mean
            << ", level of detail off " << e.Off.Mean << std::endl;
  return e;
}

// The errors of the default (masked facets), the visible normal's moments and level of detail
// off on a far real-map wall, against the supersampled exact frame; farViewRays as
// vtkReliefProperty::FarViewRays for the first two (0: the default's).
struct MaskedFacetErrors
{
  AliasingError Masked, Moments, Off;
};

MaskedFacetErrors ErrorsOfTheMaskedFacets(
  const std::string& file, double viewAngle, int farViewRays, const char* what)
{
  const ReliefSceneOptions options = FarRealMapWall(file, viewAngle);
  const int shaded = vtkReliefProperty::ShadedOutput;
  const Frame reference = RenderView(options, Drawn::Exact, Supersampling, shaded);
  MaskedFacetErrors e;
  e.Masked = Compare(
    RenderView(options, Drawn::LevelOfDetailOn, 1, shaded, nullptr, false, farViewRays), reference);
  e.Moments = Compare(
    RenderView(options, Drawn::LevelOfDetailUnmasked, 1, shaded, nullptr, false, farViewRays),
    reference);
  e.Off = Compare(RenderView(options, Drawn::LevelOfDetailOff, 1, shaded), reference);
  std::cout << what << ", error against the " << Supersampling << "x" << Supersampling
            << " supersampled exact frame, " << e.Masked.Pixels << " pixels: default "
            << e.Masked.Mean << " levels, the visible normal's moments " << e.Moments.Mean
            << ", level of detail off " << e.Off.Mean << std::endl;
  return e;
}
} // namespace

TEST(ReliefLevelOfDetail, ChangesTheFrameAgainstTheSupersampledReference)
{
  const Frame reference = Render(false, Supersampling);
  const Frame base = Render(false, 1);
  const Frame filtered = Render(true, 1);
  ASSERT_EQ(reference.Width, Width * Supersampling);
  ASSERT_EQ(base.Width, Width);

  long long differing = 0;
  for (size_t i = 0; i < base.Rgb.size(); ++i)
  {
    differing += std::abs(int(base.Rgb[i]) - int(filtered.Rgb[i])) > 2 ? 1 : 0;
  }
  const AliasingError without = Compare(base, reference);
  const AliasingError with = Compare(filtered, reference);
  std::cout << "aliasing error against the " << Supersampling << "x" << Supersampling
            << " supersampled reference, " << with.Pixels << " pixels: level of detail off "
            << without.Mean << " levels, on " << with.Mean << " levels; " << differing
            << " channel values differ by more than 2 levels" << std::endl;
  if (const char* dir = std::getenv("MESOLIGHT_TEST_OUTPUT"))
  {
    WritePng(base, (std::string(dir) + "/lod-off.png").c_str());
    WritePng(filtered, (std::string(dir) + "/lod-on.png").c_str());
  }
  ASSERT_GT(with.Pixels, Width * Height / 8) << "the relief should fill much of the view";
  EXPECT_GT(differing, 100) << "level of detail should change the frame";
  EXPECT_LT(with.Mean, 0.85 * without.Mean) << "level of detail should reduce the aliasing";
  EXPECT_LT(without.Mean, 8.0) << "the base-level march should be close to the reference";
}

// A distant, receding wall of fine detail (a 1024^2 stone at 70 degrees from its normal, two wall
// widths away: 10-30 texels per pixel) against its exact 8 x 8 supersampled frame. The default
// (level of detail on, visible normals) must come within a bound that the same relief with level
// of detail off misses: off is the negative case.
TEST(ReliefLevelOfDetail, FiltersADistantRecedingWall)
{
  ReliefSceneOptions options = WallView("Stone", 1024, 70.0, 2.0);
  const FilterErrors e = ErrorsOfTheFilters(options, "distant receding wall");
  ASSERT_GT(e.On.Pixels, Width * Height / 8) << "the wall should fill much of the view";
  // Measured 2.48 (on; 2.67 before the clamped Lambert term and the soft far shadows, 2.68
  // with the moments computed from the normals below mip level 2), 3.37 (off) and 2.85 levels
  // with the mean normal filter (the default's filter before): the bound lies 21% above on and
  // 12% below off. With three view rays per far pixel (FarViewRays, the default since): 1.71,
  // mean filter 2.79, off 3.36. With the rays spread across the pixel too (N-rooks): 1.72
  // (1.70 on the major axis alone), mean filter 2.48, off 3.46.
  const double bound = 3.0;
  EXPECT_LT(e.On.Mean, bound) << "level of detail should filter the distant wall";
  EXPECT_GT(e.Off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

// A rough wall seen at a grazing angle (running-bond bricks with deep mortar, 1024^2, 80 degrees
// from its normal, two wall widths away: about 35 texels per pixel), as real height maps are:
// the pixel sees the facets that face the viewer, and the footprint's mean normal, blind to
// which, shades the wall as if it saw them all. The visible normal filter must come within a
// bound that the mean normal filter (Toksvig) and no filter both miss: the negative cases.
TEST(ReliefLevelOfDetail, VisibleNormalsFilterARoughGrazingWall)
{
  ReliefSceneOptions options = WallView("Bricks", 1024, 80.0, 2.0);
  const FilterErrors e = ErrorsOfTheFilters(options, "rough grazing wall");
  ASSERT_GT(e.On.Pixels, Width * Height / 10) << "the wall should fill much of the view";
  // Measured 9.19 (visible; 9.53 before the clamped Lambert term and the soft far shadows),
  // 15.24 (mean) and 10.67 (off) levels: the bound lies 10% above the visible filter and 5%
  // below off. With three view rays per far pixel (the default since): 7.29, mean 16.25, off
  // 11.16. With the rays spread across the pixel too: 7.17 (7.04 on the major axis alone), mean
  // 13.26, off 11.26.
  const double bound = 10.1;
  EXPECT_LT(e.On.Mean, bound) << "the visible normal filter should filter the grazing wall";
  EXPECT_GT(e.Mean.Mean, bound) << "negative case: the mean normal shades facets the view hides";
  EXPECT_GT(e.Off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

// A far rough wall under a low light (running-bond bricks with deep mortar, 1024^2, 45 degrees
// from its normal, two wall widths away: about 10 texels per pixel; the key light 20 degrees
// above the wall, self-shadowing off so that only the shading normal counts). Many of the facets
// a pixel covers face away from the light and add nothing, max(0, n.l), where the footprint's
// mean normal lets them subtract: the default shades with the clamped mean of n.l over the
// moments' spread (mlFilteredLambert). It must come within a bound that level of detail off
// (the negative case) and the mean normal filter (Toksvig, the filter without the spread) miss.
TEST(ReliefLevelOfDetail, ClampsTheLightOfFacetsTurnedAway)
{
  ReliefSceneOptions options = WallView("Bricks", 1024, 45.0, 2.0);
  options.LightElevation = 20.0;
  options.SelfShadowing = false;
  const FilterErrors e = ErrorsOfTheFilters(options, "far rough wall under a low light");
  ASSERT_GT(e.On.Pixels, Width * Height / 8) << "the wall should fill much of the view";
  // Measured 4.92 (default), 5.47 (mean normal filter), 5.43 (off) levels, and 5.52 with the
  // visible normal filter but n.l unclamped (the filter before): the bound lies 6% above the
  // default and 4% below off. With three view rays per far pixel (the default since): 4.71, mean
  // filter 5.58, off 5.50. With the rays spread across the pixel too: 5.09 (5.11 on the major
  // axis alone), mean filter 5.35, off 5.59.
  const double bound = 5.2;
  EXPECT_LT(e.On.Mean, bound) << "the clamped Lambert term should light the far wall";
  EXPECT_GT(e.Mean.Mean, bound)
    << "negative case: the mean normal lets facets turned away subtract";
  EXPECT_GT(e.Off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

// Near (a 256^2 stone, 0.3 wall widths away: a texel covers a pixel or more) the default's frame
// is the one level of detail off draws, within a level of 8 bits. Negative case: on the distant
// wall the frames differ.
TEST(ReliefLevelOfDetail, NearFrameAsWithout)
{
  ReliefSceneOptions options = WallView("Stone", 256, 45.0, 0.3);
  const int shaded = vtkReliefProperty::ShadedOutput;
  auto largestDifference = [&](const ReliefSceneOptions& o)
  {
    const Frame on = RenderView(o, Drawn::LevelOfDetailOn, 1, shaded);
    const Frame off = RenderView(o, Drawn::LevelOfDetailOff, 1, shaded);
    EXPECT_EQ(on.Rgb.size(), off.Rgb.size());
    int largest = 0;
    for (size_t i = 0; i < std::min(on.Rgb.size(), off.Rgb.size()); ++i)
    {
      largest = std::max(largest, std::abs(int(on.Rgb[i]) - int(off.Rgb[i])));
    }
    return largest;
  };
  const int near = largestDifference(options);
  const ReliefSceneOptions far = WallView("Stone", 1024, 70.0, 2.0);
  const int distant = largestDifference(far);
  std::cout << "largest channel difference, level of detail on against off: near " << near
            << " levels, distant wall " << distant << std::endl;
  EXPECT_LE(near, 1) << "up close level of detail must not change the frame";
  EXPECT_GT(distant, 8) << "negative case: far away the comparison sees level of detail";
}

// Up close (a 256^2 stone, 0.3 wall widths away: every pixel under a texel) level of detail must
// not cost exactness: the hits with level of detail on against the exact intersector are those with
// it off. Negative case: on the distant wall, where the footprint exceeds a texel, level of detail
// does move hits (it takes no steps finer than the footprint), so the comparison can see a change.
TEST(ReliefLevelOfDetail, NearHitsAsExactAsWithout)
{
  ReliefSceneOptions options = WallView("Stone", 256, 45.0, 0.3);
  const HitComparison on = HitsAgainstExact(options, Drawn::LevelOfDetailOn);
  const HitComparison off = HitsAgainstExact(options, Drawn::LevelOfDetailOff);
  std::cout << "near hits against the exact intersector, " << on.CoveredBoth
            << " pixels: level of detail on, mean " << on.MeanTexels << " p99 " << on.P99Texels
            << " max " << on.MaxTexels << " texels; level of detail off mean " << off.MeanTexels
            << " p99 " << off.P99Texels << " max " << off.MaxTexels << std::endl;
  ASSERT_GT(on.CoveredBoth, Width * Height / 4);
  EXPECT_EQ(on.CoveredBoth, off.CoveredBoth);
  EXPECT_NEAR(on.MeanTexels, off.MeanTexels, 1e-9);
  EXPECT_NEAR(on.MaxTexels, off.MaxTexels, 1e-9);

  const ReliefSceneOptions far = WallView("Stone", 1024, 70.0, 2.0);
  // The default (the exact traversal) takes the same hits far away too: level of detail limits
  // only a search's refinement.
  const HitComparison farOn = HitsAgainstExact(far, Drawn::LevelOfDetailOn);
  const HitComparison farOff = HitsAgainstExact(far, Drawn::LevelOfDetailOff);
  std::cout << "far hits: level of detail on, mean " << farOn.MeanTexels << ", level of detail off "
            << farOff.MeanTexels << " texels" << std::endl;
  EXPECT_NEAR(farOn.MeanTexels, farOff.MeanTexels, 1e-9);
  // Relief 10+8 (the default before) far away: level of detail stops its refinement at the
  // footprint, which moves hits, and the comparison sees it.
  const HitComparison reliefOn = HitsAgainstExact(far, Drawn::LevelOfDetailOn, true);
  const HitComparison reliefOff = HitsAgainstExact(far, Drawn::LevelOfDetailOff, true);
  std::cout << "far hits, relief 10+8: level of detail on, mean " << reliefOn.MeanTexels
            << ", level of detail off " << reliefOff.MeanTexels << " texels" << std::endl;
  EXPECT_GT(std::abs(reliefOn.MeanTexels - reliefOff.MeanTexels), 1e-3)
    << "negative case: far away level of detail's march differs, and the comparison sees it";
}

// A far rough wall under a grazing light with self-shadowing (running-bond bricks with deep mortar,
// 1024^2, 45 degrees from its normal, two wall widths away: about 5 texels per pixel; the key
// light 5 degrees above the wall). Within a footprint the bricks' edges shadow the mortar
// beside them; the one shadow ray of a far pixel starts half a footprint towards the light and
// does not see that, and the clamped Lambert term drops only facets turned from the light. The
// default darkens the light by Smith's shadowing of the moments' slopes (mlFootprintShadowing).
// It must come within a bound that the default without that term (measured), level of detail
// off and the mean normal filter miss: the negative cases.
TEST(ReliefLevelOfDetail, ShadowsTheFacetsWithinAFarFootprint)
{
  ReliefSceneOptions options = WallView("Bricks", 1024, 45.0, 2.0);
  options.LightElevation = 5.0;
  const FilterErrors e =
    ErrorsOfTheFilters(options, "far rough wall under a grazing light, shadowed");
  ASSERT_GT(e.On.Pixels, Width * Height / 8) << "the wall should fill much of the view";
  // Measured 3.24 (default), 3.48 (the default without the footprint's shadowing, the default
  // before), 4.26 (mean normal filter) and 3.81 (off) levels: the bound lies 3% above the
  // default and 4% below the default before. Under a light 10 / 20 degrees above the wall the
  // term gains less: 3.52 against 3.61, 4.41 against 4.44. With three view rays per far pixel
  // (the default since): 3.10, mean filter 4.36, off 3.87. With the rays spread across the pixel
  // too: 3.12 (3.17 on the major axis alone), mean filter 3.82, off 3.88.
  const double bound = 3.35;
  EXPECT_LT(e.On.Mean, bound) << "the footprint's own shadows should darken the far wall";
  EXPECT_GT(e.Mean.Mean, bound) << "negative case: the mean normal filter";
  EXPECT_GT(e.Off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

// A far stone wall (dq_stones01_b's height, a real game texture from Debian's redeclipse-data,
// 512^2, rougher than the procedural patterns; RealHeightMaps.h), 45 degrees from its normal, two
// wall widths away (footprints of about 5 texels; the benchmark's cell, `mesolight bench
// relief-aliasing`). The moments weigh every facet by the area it turns to the viewer, signed:
// the facets turned away count negatively, as though the ones hiding them made up for them; the
// default takes the facets of the levels it computes per texel (0 and 1) one by one and leaves the
// ones turned away out. It must come within a bound that the visible normal's moments (the
// negative case) and level of detail off miss.
TEST(ReliefLevelOfDetail, MasksTheFacetsAFarViewHides)
{
  const std::string file = mesolight_test::FindRealHeightMap("dziq/dq_stones01_b.jpg");
  if (file.empty())
  {
    GTEST_SKIP() << "dziq/dq_stones01_b.jpg is absent (redeclipse-data)";
  }
  // One view ray per far pixel in both frames: the masking alone (the default's several rays
  // per far pixel are AveragesViewRaysAcrossAFarFootprint's).
  const MaskedFacetErrors e = ErrorsOfTheMaskedFacets(file, 45.0, 1, "far stone wall");
  const AliasingError& on = e.Masked;
  const AliasingError& unmasked = e.Moments;
  const AliasingError& off = e.Off;
  ASSERT_GT(on.Pixels, 200 * 150 / 4) << "the wall should fill much of the view";
  // Measured with the exact default traversal, one ray per far pixel: 10.91 (masked), 13.13
  // (without the masking) and 18.00 (off) levels; with relief 10+8, the default when the test
  // was written, 12.18, 13.18 and 18.34. Since the relief shades the surface's own normals and
  // its facets are the surface's cells (NormalsAreTheDepths; the reference too): 9.93, 12.34 and
  // 15.90: the bound lies 12% above the default and 10% below the unmasked filter. With the facets
  // weighed by their seen area alone (no height-correlated masking): 9.89 (default). Since the
  // masked filter leaves the facets turned away out of the moments' levels too: 9.13.
  const double bound = 11.1;
  EXPECT_LT(on.Mean, bound) << "the masked facets should shade the far wall";
  EXPECT_GT(unmasked.Mean, bound) << "negative case: the moments weigh the facets the view hides";
  EXPECT_GT(off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

// A far brick wall (brick_wall01_b's height, a real game texture from Debian's redeclipse-data;
// RealHeightMaps.h) 80 degrees from its normal, two wall widths away: a
// pixel's footprint is about 17 texels long along the wall and 3 across it, and one view ray,
// however exact, meets one of the bricks and joints it covers, where the supersampled frame
// averages them all. The default traces several view rays spread over the pixel, evenly along
// the footprint's major axis (vtkReliefProperty::FarViewRays), and averages their shading. It
// must come within a bound that one ray per far pixel (the default before, the negative case)
// and level of detail off miss.
TEST(ReliefLevelOfDetail, AveragesViewRaysAcrossAFarFootprint)
{
  const std::string file = mesolight_test::FindRealHeightMap("dziq/brick_wall01_b.jpg");
  if (file.empty())
  {
    GTEST_SKIP() << "dziq/brick_wall01_b.jpg is absent (redeclipse-data)";
  }
  const FarViewRayErrors e = ErrorsOfTheFarViewRays(file, 80.0, "far grazing brick wall");
  ASSERT_GT(e.Default.Pixels, 200 * 150 / 12) << "the receding wall should fill a band of the view";
  // Measured 9.05 (default: 3 rays), 14.19 (one ray, the default before) and 30.57 (off)
  // levels. Since the relief shades the surface's own normals (NormalsAreTheDepths; the
  // reference too): 6.34, 8.92 and 20.65: the bound lies 20% above the default and 15% below one
  // ray. Since each ray shadows hard from its own hit: 6.18 (default). Since the rays spread
  // across the pixel too (N-rooks): 5.67 (5.33 on the major axis alone).
  const double bound = 7.6;
  EXPECT_LT(e.Default.Mean, bound) << "several view rays should average the far footprint";
  EXPECT_GT(e.OneRay.Mean, bound) << "negative case: one view ray per far pixel aliases";
  EXPECT_GT(e.Off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

// A far stone wall (dq_stones01_b's height, a real game texture from Debian's redeclipse-data;
// RealHeightMaps.h) 80 degrees from its normal, two wall widths away: the benchmark's weakest
// cell while the default filter weighed each facet by Smith's height-correlated masking (8.79
// levels: too light, the tops over-weighted) and before that while each far view ray took the
// soft shadow (12.07). The default weighs the facets of levels 0 and 1 by the area they turn to
// the viewer, leaving out the ones turned away. It must come within a bound that the visible
// normal's moments (facets turned away counted negatively) and level of detail off miss.
TEST(ReliefLevelOfDetail, MaskedFacetsShadeAFarGrazingStoneWall)
{
  const std::string file = mesolight_test::FindRealHeightMap("dziq/dq_stones01_b.jpg");
  if (file.empty())
  {
    GTEST_SKIP() << "dziq/dq_stones01_b.jpg is absent (redeclipse-data)";
  }
  const MaskedFacetErrors e = ErrorsOfTheMaskedFacets(file, 80.0, 0, "far grazing stone wall");
  const AliasingError& masked = e.Masked;
  const AliasingError& moments = e.Moments;
  const AliasingError& off = e.Off;
  ASSERT_GT(masked.Pixels, 200 * 150 / 12) << "the receding wall should fill a band of the view";
  // Measured 6.31 (default), 9.23 (the moments) and 12.62 (off) levels; 8.79 with the
  // height-correlated masking (the default before: the test fails with it). The bound lies 24%
  // above the default and 15% below the moments. Since the masked filter leaves the facets
  // turned away out of the moments' levels too: 5.77 (default). With the rays spread across the
  // pixel too: 5.76.
  const double bound = 7.8;
  EXPECT_LT(masked.Mean, bound) << "the facets turned to the viewer should shade the far wall";
  EXPECT_GT(moments.Mean, bound) << "negative case: facets turned away counted negatively";
  EXPECT_GT(off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

// A far grazing plastered wall (paris_wall_z's height, a real game texture from Debian's
// redeclipse-data; RealHeightMaps.h) 80 degrees from its normal, two wall widths away: footprints
// of about 18 texels, shaded at levels where the masked filter reads the normal's moments. The
// moments weigh the facets by n.v and count the ones turned away negatively, which a grazing view
// makes many: the wall came out too dark. The default leaves them out there too, in the moments'
// Gaussian model of the footprint's normals (mlMomentsVisibleNormal). The wall's mean brightness
// must match the supersampled frame's, and its error stay under a bound the moments and level of
// detail off miss.
TEST(ReliefLevelOfDetail, MaskedMomentsLightAFarGrazingWallAsBrightlyAsItsFacets)
{
  const std::string file = mesolight_test::FindRealHeightMap("luckystrike/paris_wall_z.jpg");
  if (file.empty())
  {
    GTEST_SKIP() << "luckystrike/paris_wall_z.jpg is absent (redeclipse-data)";
  }
  const MaskedFacetErrors e = ErrorsOfTheMaskedFacets(file, 80.0, 0, "far grazing plastered wall");
  std::cout << "signed: default " << e.Masked.Signed << ", the moments " << e.Moments.Signed
            << ", off " << e.Off.Signed << std::endl;
  ASSERT_GT(e.Masked.Pixels, 200 * 150 / 12) << "the receding wall should fill a band of the view";
  // Measured 7.31 levels, 1.60 too dark on average (the moments 11.47, -7.10; off 27.18, +0.01).
  // The masked filter before, reading the moments unclamped at these levels, fails both checks
  // (9.64, -6.30; checked by running this test against its build). The bound lies 9% above the
  // default and 17% below the filter before. With the rays spread across the pixel too (N-rooks):
  // 7.66, -1.58 (the moments 11.98, -6.88).
  EXPECT_LT(std::abs(e.Masked.Signed), 3.0) << "the far wall should be as bright as its facets";
  const double bound = 8.0;
  EXPECT_LT(e.Masked.Mean, bound) << "the facets turned to the viewer should shade the far wall";
  EXPECT_GT(e.Moments.Mean, bound) << "negative case: facets turned away counted negatively";
  EXPECT_GT(e.Off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

// A far stone-and-brick wall (brick_wall01_b's height, a real game texture from Debian's
// redeclipse-data; RealHeightMaps.h) 45 degrees from its normal, two wall widths away, drawn with
// the mean normal filter (Toksvig 2005): the footprint's mean normal, whose length dims the light
// where the facets spread. With normals that are the depth's own it read the Sobel gradient of
// the mip-mapped depth, a unit normal of averaged-away slopes, and drew the rough wall far too
// light (37.8 levels, 1.43x level of detail off); it now takes the plain mean of the normal
// moments. It must come within a bound that level of detail off misses.
TEST(ReliefLevelOfDetail, MeanFilterDimsARoughFarWall)
{
  const std::string file = mesolight_test::FindRealHeightMap("dziq/brick_wall01_b.jpg");
  if (file.empty())
  {
    GTEST_SKIP() << "dziq/brick_wall01_b.jpg is absent (redeclipse-data)";
  }
  const ReliefSceneOptions options = FarRealMapWall(file, 45.0);
  const int shaded = vtkReliefProperty::ShadedOutput;
  const Frame reference = RenderView(options, Drawn::Exact, Supersampling, shaded);
  const AliasingError mean =
    Compare(RenderView(options, Drawn::LevelOfDetailMean, 1, shaded), reference);
  const AliasingError off =
    Compare(RenderView(options, Drawn::LevelOfDetailOff, 1, shaded), reference);
  std::cout << "far rough brick wall, error against the " << Supersampling << "x" << Supersampling
            << " supersampled exact frame, " << mean.Pixels << " pixels: mean normal filter "
            << mean.Mean << " levels, level of detail off " << off.Mean << std::endl;
  ASSERT_GT(mean.Pixels, 200 * 150 / 4) << "the wall should fill much of the view";
  // Measured 17.7 (mean filter) and 26.5 (off) levels; 37.8 with the filtered depth's Sobel
  // gradient (the filter before; checked: the test fails). The bound lies 24% above the filter
  // and 17% below off.
  const double bound = 22.0;
  EXPECT_LT(mean.Mean, bound) << "the mean normal filter should dim the rough far wall";
  EXPECT_GT(off.Mean, bound) << "negative case: without level of detail the wall aliases";
}

namespace
{
// A real height map's wall (FarRealMapWall, at viewDistance wall widths) lit by a real
// environment alone, one of Blender's (blender-data, HDRI Haven, CC0) as 64 median-cut lights:
// the errors against the supersampled exact frame of the default, one view ray per far pixel and
// level of detail off, and the relief-texture samples per pixel of the first two. False (and a
// skip) where the map or the environment is absent.
struct LightSetErrors
{
  AliasingError Default, OneRay, Off;
  double DefaultSamples = 0.0, OneRaySamples = 0.0;
};

bool ErrorsUnderAnEnvironment(const char* map, const char* world, double viewAngle,
  double viewDistance, LightSetErrors& e, std::string& skip)
{
  const std::string file = mesolight_test::FindRealHeightMap(map);
  const std::string environment =
    std::string("/usr/share/blender/datafiles/studiolights/world/") + world + ".exr";
  if (file.empty() || !std::ifstream(environment).good())
  {
    skip =
      (file.empty() ? std::string(map) + " (redeclipse-data)" : environment + " (blender-data)") +
      " is absent";
    return false;
  }
  ReliefSceneOptions options = FarRealMapWall(file, viewAngle);
  options.ViewDistance = viewDistance;
  options.Lights = 0;
  options.Environment = environment;
  options.EnvironmentLights = 64;
  options.ToneMapping = true;
  std::string error;
  options.EnvironmentLightSet = MakeEnvironmentLights(options, error);
  if (!options.EnvironmentLightSet)
  {
    ADD_FAILURE() << environment << ": " << error; // present but not made into lights
    skip = error;
    return false;
  }
  const int shaded = vtkReliefProperty::ShadedOutput;
  const int samples = vtkReliefProperty::SampleCountOutput;
  const Frame reference = RenderView(options, Drawn::Exact, Supersampling, shaded);
  e.Default = Compare(RenderView(options, Drawn::LevelOfDetailOn, 1, shaded), reference);
  e.OneRay =
    Compare(RenderView(options, Drawn::LevelOfDetailOn, 1, shaded, nullptr, false, 1), reference);
  e.Off = Compare(RenderView(options, Drawn::LevelOfDetailOff, 1, shaded), reference);
  e.DefaultSamples = MeanSampleCount(RenderView(options, Drawn::LevelOfDetailOn, 1, samples));
  e.OneRaySamples =
    MeanSampleCount(RenderView(options, Drawn::LevelOfDetailOn, 1, samples, nullptr, false, 1));
  std::cout << map << " at " << viewAngle << " degrees, " << viewDistance << " wall widths, under "
            << world << "'s 64 lights, error against the " << Supersampling << "x" << Supersampling
            << " supersampled exact frame, " << e.Default.Pixels << " pixels: default "
            << e.Default.Mean << " levels (" << e.Default.Signed << " signed; " << e.DefaultSamples
            << " samples per pixel), one view ray per far pixel " << e.OneRay.Mean << " ("
            << e.OneRaySamples << "), level of detail off " << e.Off.Mean << std::endl;
  return true;
}

// The default's error under the bound, and the negative cases' above it: one view ray per far
// pixel and level of detail off.
void ExpectTheDefaultAloneUnder(const LightSetErrors& e, double bound, const char* what)
{
  EXPECT_LT(e.Default.Mean, bound) << what;
  EXPECT_GT(e.OneRay.Mean, bound) << "negative case: one view ray per far pixel aliases";
  EXPECT_GT(e.Off.Mean, bound) << "negative case: without level of detail the wall aliases";
}
} // namespace

// A far grazing stone-and-brick wall (brick_wall01_b) under the courtyard's light. A far pixel's
// view rays take the light set's shadow marches in turn, each light's visibility from one ray's
// hit counting for every ray (interleaved sampling, Keller and Heidrich 2001): the pixel marches
// each light once, not once per view ray. Its samples must stay near one view ray's (each ray
// marching every light took three times them), its error below one view ray's and level of
// detail off's.
TEST(ReliefLevelOfDetail, FarViewRaysTakeTheLightSetsShadowsInTurn)
{
  LightSetErrors e;
  std::string skip;
  if (!ErrorsUnderAnEnvironment("dziq/brick_wall01_b.jpg", "courtyard", 80.0, 2.0, e, skip))
  {
    GTEST_SKIP() << skip;
  }
  ASSERT_GT(e.Default.Pixels, 200 * 150 / 12) << "the receding wall should fill a band of the view";
  // Measured 384.8 samples per pixel against one ray's 255.0 (1.51x; 1.44x while the far shadows
  // took the linear march); 520.8 against 174.3 (2.99x) while each ray marched every light
  // (checked: the test fails with it). Errors 5.30 (default; 5.56 with the rays on the major
  // axis alone, 5.77 with the linear far march, 5.58 with each ray marching every light), 10.09
  // (one ray) and 15.94 (off) levels: the bound lies 32% above the default and 31% below one ray.
  EXPECT_LT(e.DefaultSamples, 1.6 * e.OneRaySamples)
    << "a far pixel's view rays should share the light set's shadow marches";
  const double bound = 7.0;
  ExpectTheDefaultAloneUnder(e, bound, "several view rays should average the far footprint");
}

// A far stone wall (dq_stones01_b) 80 degrees from its normal, one wall width away (5.6 texels per
// pixel) under the courtyard's light. A far pixel's three view rays enter at the points of an
// N-rooks pattern, spread across the pixel as well as along its major axis, so that their hits,
// and the light set's shadows marched from them in turn, sample the whole footprint; on the
// major axis alone they sampled one line through it.
TEST(ReliefLevelOfDetail, FarViewRaysSpreadAcrossTheFootprint)
{
  LightSetErrors e;
  std::string skip;
  if (!ErrorsUnderAnEnvironment("dziq/dq_stones01_b.jpg", "courtyard", 80.0, 1.0, e, skip))
  {
    GTEST_SKIP() << skip;
  }
  ASSERT_GT(e.Default.Pixels, 200 * 150 / 12) << "the receding wall should fill a band of the view";
  // Measured 5.56 levels (-0.42 signed), one view ray 10.02, off 10.55; 6.89 (-0.73) with the
  // rays on the major axis alone (checked: the test fails with it). The bound lies 11% above the
  // default and 10% below the rays on one axis.
  const double bound = 6.2;
  ExpectTheDefaultAloneUnder(e, bound, "the far view rays should sample the whole footprint");
}

// The same wall 45 degrees from its normal, one wall width away (2.5 texels per pixel) under the
// sunset's light: far pixels at shading levels up to 1, where a light set's shadows take the exact
// march. With the linear far march (10 steps per unit of depth, as the VTK lights' there) it
// missed occluders and the environment lit the wall too brightly, worse than level of detail off.
TEST(ReliefLevelOfDetail, LightSetShadowsAWallJustPastTexelSizeExactly)
{
  LightSetErrors e;
  std::string skip;
  if (!ErrorsUnderAnEnvironment("dziq/brick_wall01_b.jpg", "sunset", 45.0, 1.0, e, skip))
  {
    GTEST_SKIP() << skip;
  }
  ASSERT_GT(e.Default.Pixels, 200 * 150 / 4) << "the wall should fill much of the view";
  // Measured 4.23 (default; 4.32 with the rays on the major axis alone, 4.63 with the mean
  // normal's n.l and shadows from the rays in turn), 5.85 (one ray) and 6.70 (off) levels; 7.97
  // with the linear far march (checked: the test fails with it). The bound lies 23% above the
  // default and 11% below one ray.
  const double bound = 5.2;
  ExpectTheDefaultAloneUnder(e, bound, "the light set's shadows should darken the wall as exactly");
}

// A far stone wall (dq_stones01_b) 45 degrees from its normal, two wall widths away (4.8 texels
// per pixel) under the courtyard's light. A far pixel's share of a light is its facets'
// visibility times max(0, n.l): the clamped Lambert term of the footprint's spread of normals
// times the visibility of a facet facing the light (mlLightSetIrradiance). The wall's mean
// brightness must match the supersampled frame's, and its error stay under a bound level of
// detail off misses.
TEST(ReliefLevelOfDetail, LightSetLightsAFarWallAsBrightlyAsItsFacets)
{
  LightSetErrors e;
  std::string skip;
  if (!ErrorsUnderAnEnvironment("dziq/dq_stones01_b.jpg", "courtyard", 45.0, 2.0, e, skip))
  {
    GTEST_SKIP() << skip;
  }
  ASSERT_GT(e.Default.Pixels, 200 * 150 / 12) << "the receding wall should fill a band of the view";
  // Measured 6.80 levels, 0.89 too bright on average (7.60 and -0.15 with the rays on the major
  // axis alone; off 14.35, one ray 10.67). The shadings before and beside it fail the brightness
  // check (checked by running this test against their builds): the mean normal's n.l with the
  // linear far march above level 1 (the shading before) +5.23 (8.89 levels); the clamped Lambert
  // term with the exact march from the rays in turn, facing the light or not, -2.24; from a facing
  // facet but with the mean normal's n.l -3.64; the clamped Lambert term and a facing facet with
  // the linear far march +11.75 (12.88 levels). The bound lies 23% above the default and 41% below
  // off.
  EXPECT_LT(std::abs(e.Default.Signed), 1.5) << "the far wall should be as bright as its facets";
  const double bound = 8.4;
  EXPECT_LT(e.Default.Mean, bound) << "far pixels should average their footprint's light";
  EXPECT_GT(e.Off.Mean, bound) << "negative case: without level of detail the wall aliases";
}
