// SPDX-License-Identifier: BSD-3-Clause
// The movable object's tests share an independent ray-cast reference: the field's static
// triangles and the object's triangles (placed in the unit sphere) merged into ONE plain
// triangle scene (no instancing, no WalkthroughTracer), cast per pixel centre. It says which
// pixels see the object first and which see a mirror whose reflection hits the object first.
#ifndef mesolight_ObjectTestReference_h
#define mesolight_ObjectTestReference_h

#include "EmbreeScene.h"
#include "LightField.h"
#include "ObjectMesh.h"
#include "WalkthroughTracer.h"

#include <glm/geometric.hpp>

#include <cstdint>
#include <vector>

namespace mesolight
{
namespace objecttest
{

enum Mask : std::uint8_t
{
  Other = 0,
  Object = 1,         // the primary ray hits the object first
  ObjectInMirror = 2, // a mirror, whose reflected ray hits the object first
  Mirror = 3          // a mirror reflecting something else
};

// The field's static triangles followed by the object's (placed in the unit sphere), as one plain
// scene: triangle indices below field.Scene().TriangleCount() are the field's.
inline TriangleScene MergedScene(const vlf::LightField& field, const vlf::ObjectMesh& unitObject)
{
  TriangleScene merged = field.Scene();
  const auto base = static_cast<std::uint32_t>(merged.Positions.size());
  const auto material = static_cast<std::uint32_t>(merged.Materials.size());
  merged.Materials.push_back(SceneMaterial{});
  merged.Positions.insert(
    merged.Positions.end(), unitObject.Positions.begin(), unitObject.Positions.end());
  for (const glm::uvec3& t : unitObject.Triangles)
  {
    merged.Triangles.emplace_back(t.x + base, t.y + base, t.z + base);
    merged.MaterialIds.push_back(material);
  }
  // Attributes other than positions would no longer match: the references need none.
  merged.Normals.clear();
  merged.TextureCoordinates.clear();
  return merged;
}

// Per-pixel masks (row 0 at the bottom) of `unitObject` (already in the unit sphere) in `field`.
inline std::vector<std::uint8_t> ReferenceMasks(
  const vlf::LightField& field, const vlf::ObjectMesh& unitObject, const vlf::ViewFrame& view)
{
  const std::size_t staticTriangles = field.Scene().TriangleCount();
  const EmbreeScene embree(MergedScene(field, unitObject));
  std::vector<std::uint8_t> masks(static_cast<std::size_t>(view.Width) * view.Height, Other);
  for (int y = 0; y < view.Height; ++y)
  {
    for (int x = 0; x < view.Width; ++x)
    {
      const SceneRay ray = view.Ray(x + 0.5f, y + 0.5f);
      const SceneHit hit = embree.Intersect(ray);
      std::uint8_t& m = masks[static_cast<std::size_t>(y) * view.Width + x];
      if (hit.Triangle == SceneHit::None)
      {
        continue;
      }
      if (hit.Triangle >= staticTriangles)
      {
        m = Object;
        continue;
      }
      const std::uint32_t s = field.SurfaceOfTriangle(hit.Triangle);
      if (s == vlf::NoSurface || glm::length(field.MaterialOf(s).Specular) <= 0.0f)
      {
        continue;
      }
      const glm::vec3 n = field.Surfaces()[s].Normal;
      const glm::vec3 d = glm::normalize(ray.Direction);
      if (!(glm::dot(n, d) < 0.0f))
      {
        continue;
      }
      SceneRay reflected;
      reflected.Origin = ray.Origin + hit.T * ray.Direction + 1e-4f * n;
      reflected.Direction = d - 2.0f * glm::dot(d, n) * n;
      const SceneHit second = embree.Intersect(reflected);
      m = second.Triangle != SceneHit::None && second.Triangle >= staticTriangles ? ObjectInMirror
                                                                                  : Mirror;
    }
  }
  return masks;
}

// Pixels whose 8 neighbours share their mask: rasterised edges may differ by a pixel.
inline std::vector<std::uint8_t> Interior(const std::vector<std::uint8_t>& masks, int w, int h)
{
  std::vector<std::uint8_t> out(masks.size(), Other);
  for (int y = 1; y + 1 < h; ++y)
  {
    for (int x = 1; x + 1 < w; ++x)
    {
      const std::uint8_t m = masks[static_cast<std::size_t>(y) * w + x];
      bool same = true;
      for (int dy = -1; dy <= 1 && same; ++dy)
      {
        for (int dx = -1; dx <= 1 && same; ++dx)
        {
          same = masks[static_cast<std::size_t>(y + dy) * w + x + dx] == m;
        }
      }
      out[static_cast<std::size_t>(y) * w + x] = same ? m : static_cast<std::uint8_t>(Other);
    }
  }
  return out;
}

} // namespace objecttest
} // namespace mesolight

#endif
