// SPDX-License-Identifier: BSD-3-Clause
// The path tracer's radiance at texel points: the independent reference of the light field tests.
#ifndef mesolight_PathTracedTexels_h
#define mesolight_PathTracedTexels_h

#include "EmbreeScene.h"
#include "LightField.h"
#include "PathTracer.h"
#include "TextureComparison.h"
#include "TriangleScene.h"

#include <cmath>
#include <cstdint>
#include <vector>

namespace mesolight
{
namespace vlftest
{

// The diffuse radiance leaving each texel point of `world`, `samples` paths per point.
inline std::vector<glm::vec3> PathTraced(const TriangleScene& world, const vlf::LightField& field,
  const std::vector<vlf::TexelPoint>& texels, int samples, std::uint64_t seed)
{
  EmbreeScene embree(world);
  PathTracer tracer(embree);
  return vlf::ReferenceAtTexels(field, texels,
    [&](std::uint32_t triangle, const glm::vec3& point)
    {
      // Random numbers keyed by the point itself, so the reference needs no per-texel state.
      const std::uint64_t key = (static_cast<std::uint64_t>(triangle) << 40) ^
        static_cast<std::uint64_t>(std::llround(point.x * 4096.0f + 1e6)) * 1000003ull ^
        static_cast<std::uint64_t>(std::llround(point.y * 4096.0f + 1e6)) * 998244353ull ^
        static_cast<std::uint64_t>(std::llround(point.z * 4096.0f + 1e6));
      return tracer.DiffuseRadianceLeaving(triangle, point, samples, key * 31 + seed);
    });
}

} // namespace vlftest
} // namespace mesolight

#endif
