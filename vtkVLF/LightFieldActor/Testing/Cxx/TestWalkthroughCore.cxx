// SPDX-License-Identifier: BSD-3-Clause
// The walkthrough's plain C++ cores: the texture atlas reproduces the field's textures (no seams,
// orientation matters), traced reflections (single rays = packets; one bounce short fails),
// mirror rectangles and tone mapping.
#include "DisplayTransform.h"
#include "TextureAtlas.h"
#include "WalkthroughImage.h"
#include "WalkthroughTestFields.h"
#include "WalkthroughTracer.h"

#include "Lookup.h"
#include "PinholeCamera.h"

#include <gtest/gtest.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <iostream>
#include <random>

namespace mesolight
{
namespace
{
using walkthroughtest::MirrorCornellField;

// Uniform random point on triangle t.
glm::vec3 PointOn(const TriangleScene& scene, std::size_t t, std::mt19937& rng)
{
  std::uniform_real_distribution<float> u(0.0f, 1.0f);
  float a = u(rng), b = u(rng);
  if (a + b > 1.0f)
  {
    a = 1.0f - a;
    b = 1.0f - b;
  }
  return (1.0f - a - b) * scene.Vertex(t, 0) + a * scene.Vertex(t, 1) + b * scene.Vertex(t, 2);
}

vlf::ViewFrame CornellView(const vlf::LightField& field, int width, int height)
{
  const CornellCamera camera;
  const glm::vec3 eye =
    (camera.Position - field.NormalizationCentre()) * field.NormalizationScale();
  const glm::vec3 focal =
    (camera.FocalPoint - field.NormalizationCentre()) * field.NormalizationScale();
  vlf::ViewFrame view;
  EXPECT_TRUE(
    vlf::ViewFrame::Make(eye, focal, camera.ViewUp, camera.ViewAngleDegrees, width, height, view));
  return view;
}

TEST(LightFieldActorCore, AtlasMatchesFieldTexturesWithoutSeams)
{
  const vlf::LightField& field = MirrorCornellField(513);
  const vlf::TextureAtlas atlas(field);
  std::cout << "atlas " << atlas.Width() << "x" << atlas.Height() << ", occupancy "
            << atlas.Occupancy() << ", " << field.Surfaces().size() << " surfaces\n";
  const TriangleScene& scene = field.Scene();
  std::mt19937 rng(7);
  double worst = 0.0, worstFlipped = 0.0;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const std::uint32_t s = field.SurfaceOfTriangle(t);
    ASSERT_NE(s, vlf::NoSurface);
    // Interior points and the triangle's corners (shared with neighbouring surfaces: seams).
    for (int q = 0; q < 203; ++q)
    {
      const glm::vec3 p = q < 3 ? scene.Vertex(t, q) : PointOn(scene, t, rng);
      const glm::vec3 expected = field.SampleTexture(field.TotalDiffuse, s, p);
      const glm::vec2 tc = atlas.TextureCoordinates(s, p);
      const glm::vec4 got = atlas.SampleBilinear(tc);
      const float scale = std::max(1e-3f, expected.x + expected.y + expected.z);
      worst = std::max(worst, static_cast<double>(glm::length(glm::vec3(got) - expected) / scale));
      EXPECT_NEAR(got.w, glm::length(field.MaterialOf(s).Specular) > 0.0f ? 1.0f : 0.0f, 1e-6f);
    }
  }
  // A wrong orientation: sample rows mirrored (v -> 1 - v).
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const std::uint32_t s = field.SurfaceOfTriangle(t);
    for (int q = 0; q < 50; ++q)
    {
      const glm::vec3 p = PointOn(scene, t, rng);
      const glm::vec3 expected = field.SampleTexture(field.TotalDiffuse, s, p);
      const glm::vec2 tc = atlas.TextureCoordinates(s, p);
      const glm::vec4 got = atlas.SampleBilinear(glm::vec2(tc.x, 1.0f - tc.y));
      const float scale = std::max(1e-3f, expected.x + expected.y + expected.z);
      worstFlipped =
        std::max(worstFlipped, static_cast<double>(glm::length(glm::vec3(got) - expected) / scale));
    }
  }
  std::cout << "atlas vs field textures: worst relative difference " << worst
            << "; upside-down atlas: " << worstFlipped << "\n";
  EXPECT_LT(worst, 1e-5);
  EXPECT_GT(worstFlipped, 0.5);
}

TEST(LightFieldActorCore, PacketsTraceLikeSingleRaysAndOneBounceShortFails)
{
  const vlf::LightField& field = MirrorCornellField(513);
  const vlf::WalkthroughTracer tracer(field);
  ASSERT_TRUE(tracer.HasMirrors());
  const vlf::ViewFrame view = CornellView(field, 96, 96);
  const std::vector<vlf::PixelClass> classes = tracer.ClassifyView(view);
  const std::size_t mirrors =
    static_cast<std::size_t>(std::count(classes.begin(), classes.end(), vlf::PixelClass::Mirror));
  std::cout << "mirror pixels " << mirrors << " of " << classes.size() << "\n";
  ASSERT_GT(mirrors, classes.size() / 50);

  const vlf::PixelRect rect = tracer.MirrorRect(view);
  std::vector<float> rows(rect.Pixels() * 4), tiles(rect.Pixels() * 4),
    shortRows(rect.Pixels() * 4);
  vlf::TraceOptions options;
  tracer.ShadeRows(
    view, rect, false, vlf::SpecularQuality::Traced, options, rect.Y0, rect.Y1, rows.data());
  tracer.ShadeTiles(view, rect, false, vlf::SpecularQuality::Traced, options, 0,
    vlf::WalkthroughTracer::TileCount(rect), tiles.data());
  vlf::TraceOptions shortOptions;
  shortOptions.BouncesShortForTesting = 1;
  tracer.ShadeRows(view, rect, false, vlf::SpecularQuality::Traced, shortOptions, rect.Y0, rect.Y1,
    shortRows.data());
  // Every mirror pixel lies in the rectangle and has a value; nothing else does.
  std::size_t inRect = 0, differ = 0, bright = 0, shortBright = 0;
  for (int y = 0; y < view.Height; ++y)
  {
    for (int x = 0; x < view.Width; ++x)
    {
      const bool mirror =
        classes[static_cast<std::size_t>(y) * view.Width + x] == vlf::PixelClass::Mirror;
      const bool inside = x >= rect.X0 && x < rect.X1 && y >= rect.Y0 && y < rect.Y1;
      if (mirror)
      {
        EXPECT_TRUE(inside) << x << "," << y;
      }
      if (!inside)
      {
        continue;
      }
      const std::size_t i =
        (static_cast<std::size_t>(y - rect.Y0) * rect.Width() + (x - rect.X0)) * 4;
      EXPECT_EQ(rows[i + 3] > 0.0f, mirror);
      inRect += mirror ? 1 : 0;
      float d = 0.0f;
      for (int c = 0; c < 3; ++c)
      {
        d = std::max(d, std::abs(rows[i + c] - tiles[i + c]) / std::max(1e-3f, rows[i + c]));
      }
      differ += d > 1e-3f ? 1 : 0;
      bright += mirror && rows[i] + rows[i + 1] + rows[i + 2] > 1e-3f ? 1 : 0;
      shortBright += mirror && shortRows[i] + shortRows[i + 1] + shortRows[i + 2] > 1e-3f ? 1 : 0;
    }
  }
  std::cout << "rect " << rect.Width() << "x" << rect.Height()
            << ": packets differ from single rays at " << differ << " of " << inRect
            << " mirror pixels; lit mirror pixels " << bright << ", one bounce short "
            << shortBright << "\n";
  EXPECT_EQ(inRect, mirrors);
  EXPECT_LE(differ, mirrors / 100 + 2);
  EXPECT_GT(bright, mirrors * 9 / 10);
  EXPECT_EQ(shortBright, 0u); // Kd 0 mirrors: without the last segment they are black
}

// Where the mirror box's light goes (the walkthrough tests see the field about 5% darker than the
// path tracer on diffuse pixels in every field mode): conserved per iteration, the losses bounded.
TEST(LightFieldActorCore, MirrorFieldEnergyBudget)
{
  for (const std::size_t directions : { std::size_t(513), std::size_t(2049) })
  {
    const vlf::LightField& field = MirrorCornellField(directions);
    double shot = 0.0, lost = 0.0, back = 0.0, escaped = 0.0, absorbed = 0.0;
    for (const auto& e : field.EnergyLog)
    {
      for (int c = 0; c < 3; ++c)
      {
        shot += e.Shot[c];
        lost += e.SpecularLost[c];
        back += e.BackFaces[c];
        escaped += e.Escaped[c];
        absorbed += e.Absorbed[c];
      }
    }
    double unshot = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      unshot += field.EnergyLog.back().Unshot[c];
    }
    const double emitted = shot;
    std::cout << directions << " directions, " << field.EnergyLog.size()
              << " iterations: of all flux shot, "
              << "specular lost " << 100.0 * lost / emitted << "%, back faces "
              << 100.0 * back / emitted << "%, escaped " << 100.0 * escaped / emitted
              << "%, absorbed " << 100.0 * absorbed / emitted
              << "%; unshot after the last iteration " << 100.0 * unshot / emitted << "%\n";
    // Every iteration accounts for what it shot (escaped + absorbed + back faces + specular
    // lost + unshot), and the mirrors' losses stay the small share measured (a regression in
    // the specular transfer shows up here before the pictures).
    for (const auto& e : field.EnergyLog)
    {
      EXPECT_LT(e.ConservationError(), 1e-3) << "iteration " << e.Iteration;
    }
    // Measured (513 / 2049 directions): absorbed 28.2%, escaped 16.8%, back faces 0.31 /
    // 0.29%, specular lost 0.014 / 0.020% of all flux shot.
    EXPECT_NEAR(absorbed / emitted, 0.282, 0.03);
    EXPECT_NEAR(escaped / emitted, 0.168, 0.02);
    EXPECT_LT(back / emitted, 0.006);
    EXPECT_LT(lost / emitted, 0.0005);
  }
}

TEST(LightFieldActorCore, DiffuseSurfacesAreNotMirrorsAndWarnNothing)
{
  const vlf::LightField& field = walkthroughtest::DiffuseCornellField();
  const vlf::WalkthroughTracer tracer(field);
  EXPECT_FALSE(tracer.HasMirrors());
  EXPECT_TRUE(tracer.MirrorRect(CornellView(field, 64, 64)).Empty());
}

TEST(LightFieldActorCore, ToneMapInverts)
{
  for (const vlf::ToneMapOperator op :
    { vlf::ToneMapOperator::Clamp, vlf::ToneMapOperator::Reinhard })
  {
    for (float v : { 0.0f, 0.001f, 0.05f, 0.3f, 0.9f })
    {
      const glm::vec3 display = vlf::ToneMap(glm::vec3(v), 1.0f, op);
      EXPECT_NEAR(vlf::InverseToneMap(display, 1.0f, op).x, v, 1e-5f);
    }
  }
  EXPECT_FLOAT_EQ(vlf::ToneMap(glm::vec3(4.0f), 1.0f, vlf::ToneMapOperator::Clamp).x, 1.0f);
}

// common/DisplayTransform.h, the one C++ display transform: the sRGB curve of IEC 61966-2-1 at
// both precisions, its inverse, and the transform without sRGB (as relief light sets show it).
TEST(LightFieldActorCore, DisplayTransform)
{
  EXPECT_FLOAT_EQ(ToSRGB(0.002f), 12.92f * 0.002f);
  EXPECT_NEAR(ToSRGB(0.5), 1.055 * std::pow(0.5, 1.0 / 2.4) - 0.055, 1e-15);
  EXPECT_FLOAT_EQ(ToSRGB(2.0f), 1.0f); // 1.055 - 0.055: 1 within rounding
  EXPECT_EQ(ToSRGB(-1.0), 0.0);
  for (double v : { 0.0, 0.001, 0.04, 0.2, 0.7, 1.0 })
  {
    EXPECT_NEAR(FromSRGB(ToSRGB(v)), v, 1e-12);
  }
  DisplayTransform linear;
  linear.Exposure = 2.0;
  linear.EncodeSRGB = false;
  EXPECT_EQ(ApplyDisplayTransform(linear, 0.25), 0.5);
  EXPECT_EQ(ApplyDisplayTransform(linear, 3.0), 1.0);
  linear.ToneMap = ToneMapOperator::Reinhard;
  EXPECT_EQ(ApplyDisplayTransform(linear, 0.5), 0.5);
  EXPECT_NEAR(InvertDisplayTransform(linear, 0.5), 0.5, 1e-15);
}

TEST(LightFieldActorCore, RelativeErrorStatistics)
{
  const std::vector<glm::vec3> ref(100, glm::vec3(1.0f));
  std::vector<glm::vec3> image(100, glm::vec3(1.0f));
  for (int i = 0; i < 10; ++i)
  {
    image[static_cast<std::size_t>(i)] = glm::vec3(2.0f); // 10% of pixels 100% off
  }
  const std::vector<std::uint8_t> mask(100, 1);
  const vlf::ErrorStatistics e = vlf::RelativeError(image, ref, mask, 1);
  EXPECT_EQ(e.Pixels, 100u);
  EXPECT_NEAR(e.Mean, 0.1, 1e-9);
  EXPECT_NEAR(e.Percentile95, 1.0, 1e-9);
}

} // namespace
} // namespace mesolight
