// SPDX-License-Identifier: BSD-3-Clause
// The per-patch comparison (used against the path tracer for the Cornell box) checked against an
// analytic reference: a floor under a square emitter has diffuse radiance rho Le F(x), F the
// point-to-square form factor. A reference 10% off must show as a 10% error.
#include "PatchComparison.h"
#include "Propagation.h"
#include "VLFTestScenes.h"

#include <gtest/gtest.h>

#include <cstdio>

namespace
{
using namespace mesolight;
using namespace mesolight::vlf;

TEST(VLFPatchComparison, FloorUnderAnEmitterAgainstTheFormFactor)
{
  const float albedo = 0.5f, le = 2.0f;
  LightFieldSettings settings;
  settings.Directions = 513;
  settings.RaysPerSide = 32;
  settings.TilesPerSide = 4;
  std::unique_ptr<LightField> field =
    LightField::Build(vlftest::MakeEmitterOverFloor(1.0f, 1.0f, 2.0f, albedo, le), settings);
  Propagate(*field, 1);
  const TriangleScene& unit = field->Scene();
  auto analytic = [&](double factor)
  {
    return [&, factor](std::uint32_t triangle, const glm::vec3& world)
    {
      if (unit.MaterialOf(triangle).Emission.x > 0.0f)
      {
        return glm::vec3(le);
      }
      const double f = vlftest::SquareFormFactor(1.0, 1.0, world.x, world.y);
      return glm::vec3(static_cast<float>(factor * albedo * le * f));
    };
  };
  const PatchComparisonResult exact = ComparePatches(*field, analytic(1.0), 400);
  std::printf("%s", exact.Table().c_str());
  ASSERT_EQ(exact.Patches.size(), 2u);
  EXPECT_LT(exact.WorstMeanError, 0.03);
  EXPECT_LT(exact.Patches[1].MeanError, 1e-6); // the emitter: Le both ways
  const PatchComparisonResult off = ComparePatches(*field, analytic(1.1), 400);
  EXPECT_GT(off.WorstMeanError, 0.06);
  EXPECT_NE(exact.Csv().find("floor, normal +z"), std::string::npos);
  EXPECT_THROW(ComparePatches(*field, analytic(1.0), 0), std::invalid_argument);
  EXPECT_THROW(ComparePatches(*field, ReferenceRadiance(), 10), std::invalid_argument);
}

} // namespace
