// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor in a VTK renderer (offscreen; run under Xvfb): the field modes (raytrace,
// progressive, coherent; the geometry mode draws Kd colours, not the field) against the path
// tracer rendering the same camera of the same scene, and the negative tests (atlas upside down,
// no alpha composite, reflections one bounce short). Occlusion, composition and bad input are in
// TestLightFieldActorScenes.cxx.
#include "WalkthroughTestViewer.h"

namespace mesolight
{
namespace
{
using namespace walkthroughtest;

void ModesAgainstPathTracer(std::size_t directions)
{
  const vlf::LightField& field = MirrorCornellField(directions);
  const Reference& ref = PathTracedReference(field, "mirror");
  Viewer viewer(field);
  ASSERT_TRUE(viewer.Actor->HasMirrors());
  Images other;
  other.Radiance = ref.OtherSeed;
  const ModeErrors noise = Measure(other, ref);
  Print(directions, "path-tracer-seed2", noise);

  const std::string tag = std::to_string(directions) + "-";
  const ModeErrors raytrace =
    Measure(viewer.Render(vtkLightFieldActor::Raytrace), ref, tag + "raytrace");
  const ModeErrors moving =
    Measure(viewer.Render(vtkLightFieldActor::Progressive), ref, tag + "moving");
  EXPECT_FALSE(viewer.Actor->GetLastFrameConverged());
  ASSERT_TRUE(viewer.Actor->WaitForTracedReflections(60.0));
  const ModeErrors rest =
    Measure(viewer.Render(vtkLightFieldActor::Progressive), ref, tag + "rest");
  EXPECT_TRUE(viewer.Actor->GetLastFrameConverged());
  const ModeErrors coherent =
    Measure(viewer.Render(vtkLightFieldActor::Coherent), ref, tag + "coherent");
  Print(directions, "raytrace", raytrace);
  Print(directions, "progressive-moving", moving);
  Print(directions, "progressive-rest", rest);
  Print(directions, "coherent", coherent);

  // Negative tests: each must visibly fail.
  vtkLightFieldActorTesting::SetFlipAtlas(viewer.Actor, true);
  const ModeErrors flipped = Measure(viewer.Render(vtkLightFieldActor::Coherent), ref);
  vtkLightFieldActorTesting::SetFlipAtlas(viewer.Actor, false);
  vtkLightFieldActorTesting::SetOverwriteComposite(viewer.Actor, true);
  const ModeErrors overwrite = Measure(viewer.Render(vtkLightFieldActor::Coherent), ref);
  vtkLightFieldActorTesting::SetOverwriteComposite(viewer.Actor, false);
  vtkLightFieldActorTesting::SetReflectionBouncesShort(viewer.Actor, 1);
  const ModeErrors shortBounce = Measure(viewer.Render(vtkLightFieldActor::Coherent), ref);
  vtkLightFieldActorTesting::SetReflectionBouncesShort(viewer.Actor, 0);
  Print(directions, "neg:atlas-flipped", flipped);
  Print(directions, "neg:no-alpha", overwrite);
  Print(directions, "neg:one-short", shortBounce);

  // The per-pixel comparison is bounded below by the reference's own noise (two path-traced
  // seeds differ by `noise`): every mode must stay within 1.5 x that floor, and its mean bias
  // (the field's missing bounces and mirror losses) within 8%.
  for (const ModeErrors* e : { &raytrace, &rest, &coherent })
  {
    EXPECT_LT(e->Diffuse.Mean, 1.5 * noise.Diffuse.Mean);
    EXPECT_LT(std::abs(e->DiffuseBias), 0.08);
  }
  EXPECT_NEAR(rest.Diffuse.Mean, coherent.Diffuse.Mean, 0.005);
  // Mirror pixels: coherent ~ progressive at rest < raytrace < progressive moving.
  EXPECT_NEAR(coherent.Mirror.Mean, rest.Mirror.Mean, 0.01);
  EXPECT_LT(rest.Mirror.Mean, raytrace.Mirror.Mean);
  EXPECT_LT(raytrace.Mirror.Mean, moving.Mirror.Mean);
  EXPECT_LT(coherent.Mirror.Mean, 1.5 * noise.Mirror.Mean);
  EXPECT_LT(std::abs(coherent.MirrorBias), 0.08);
  // Negative tests: the upside-down atlas puts other texels on every diffuse pixel; pasting the
  // screen rectangle without alpha blackens the diffuse pixels around the mirror (the worst 5%
  // are 100% off); stopping one bounce short leaves the Kd = 0 mirror black.
  EXPECT_GT(flipped.Diffuse.Mean, coherent.Diffuse.Mean + 0.5);
  EXPECT_GT(overwrite.Diffuse.Percentile95, coherent.Diffuse.Percentile95 + 0.3);
  EXPECT_GT(overwrite.Diffuse.Mean, coherent.Diffuse.Mean + 0.03);
  EXPECT_GT(shortBounce.Mirror.Mean, 0.9);
}

TEST(Walkthrough, ModesAgainstPathTracer513)
{
  ModesAgainstPathTracer(513);
}

TEST(Walkthrough, ModesAgainstPathTracer2049)
{
  ModesAgainstPathTracer(2049);
}

// About 30 s and 1.2 GiB (the 8193-direction field with mirror maps).
TEST(Walkthrough, ModesAgainstPathTracer8193)
{
  ModesAgainstPathTracer(8193);
}

// The plain Cornell box (no mirror), 2049 directions, 10 iterations. First the display path
// alone: the GL image equals the CPU model of the draw (field texture at the primary hit, tone
// map, 8 bits). Then both texture and raytrace modes against the path tracer: what remains is
// the field's own error (texture noise of 32 rays per side, and a bias).
TEST(Walkthrough, PlainCornellBoxAgainstPathTracer)
{
  const vlf::LightField& field = walkthroughtest::PlainCornellField(2049);
  const Reference& ref = PathTracedReference(field, "plain");
  Viewer viewer(field);
  Images other;
  other.Radiance = ref.OtherSeed;
  const ModeErrors noise = Measure(other, ref);
  const ModeErrors coherent =
    Measure(viewer.Render(vtkLightFieldActor::Coherent), ref, "plain-coherent");
  const ModeErrors raytrace =
    Measure(viewer.Render(vtkLightFieldActor::Raytrace), ref, "plain-raytrace");
  {
    // The GL image against the CPU model of the same draw (texture at the primary hit, tone map,
    // round to 8 bits): the display path's own bias, in display levels.
    const Images gl = viewer.Render(vtkLightFieldActor::Coherent);
    const vlf::ViewFrame view = CornellView(field);
    const vlf::WalkthroughTracer walk(field);
    const vlf::Lookup lookup(field);
    double signedLevels = 0.0, worstLevels = 0.0;
    std::size_t n = 0;
    for (int y = 0; y < Size; ++y)
    {
      for (int x = 0; x < Size; ++x)
      {
        const SceneRay ray = view.Ray(x + 0.5f, y + 0.5f);
        const SceneHit hit = walk.Embree().Intersect(ray);
        std::uint32_t surface;
        if (walk.Classify(ray, hit, surface) != vlf::PixelClass::Diffuse)
        {
          continue;
        }
        const glm::vec3 cpu =
          vlf::ToneMap(lookup.DiffuseRadiance(surface, ray.Origin + hit.T * ray.Direction),
            Exposure, vlf::ToneMapOperator::Clamp);
        const glm::vec3 d = gl.Display[static_cast<std::size_t>(y) * Size + x];
        for (int c = 0; c < 3; ++c)
        {
          // The window holds 8-bit levels: compare levels, not their float images.
          const double levels = std::round(255.0 * d[c]) - std::round(255.0 * cpu[c]);
          signedLevels += levels;
          worstLevels = std::max(worstLevels, std::abs(levels));
          ++n;
        }
      }
    }
    std::cout << "GL display vs the CPU model: mean signed difference " << signedLevels / n
              << " levels, worst " << worstLevels << " over " << n / 3 << " diffuse pixels\n";
    EXPECT_LT(std::abs(signedLevels / n), 0.01);
    EXPECT_LE(worstLevels, 1.0);
  }
  Print(2049, "plain:path-tracer-seed2", noise);
  Print(2049, "plain:coherent", coherent);
  Print(2049, "plain:raytrace", raytrace);
  EXPECT_LT(coherent.Diffuse.Mean, 0.12);
  EXPECT_LT(raytrace.Diffuse.Mean, 0.14);
  EXPECT_LT(std::abs(coherent.DiffuseBias), 0.06);
  EXPECT_LT(std::abs(raytrace.DiffuseBias), 0.06);
}

// The tall block in front of the mirror wall hides exactly its pixels of it (a camera inside the
// box looking at the mirror across the block): the pixels the actor
// draws as mirror (found by comparing with reflections one bounce short, which leave the Kd = 0
// mirror black) are exactly the ray cast's visible mirror pixels, in the coherent and the
// progressive (at rest) modes.
} // namespace
} // namespace mesolight
