// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectReference.h"

#include "EmbreeScene.h"
#include "ParallelFor.h"
#include "PathTracer.h"

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>

namespace mesolight
{
namespace vlf
{

//------------------------------------------------------------------------------
ObjectReference TraceObjectReference(
  const LightField& field, const ObjectMesh& unitMesh, const ObjectReferenceSettings& settings)
{
  TriangleScene scene = field.Scene();
  const auto firstObjectTriangle = static_cast<std::uint32_t>(scene.TriangleCount());
  TriangleScene object;
  SceneMaterial material;
  material.Name = "object";
  material.Diffuse = unitMesh.Diffuse;
  object.AddMaterial(material);
  object.Positions = unitMesh.Positions;
  // Each point's triangle (for Kd): the first non-degenerate one that uses it.
  constexpr std::uint32_t none = std::numeric_limits<std::uint32_t>::max();
  std::vector<std::uint32_t> triangleOf(unitMesh.Positions.size(), none);
  for (const glm::uvec3& t : unitMesh.Triangles)
  {
    const glm::vec3 n = glm::cross(unitMesh.Positions[t.y] - unitMesh.Positions[t.x],
      unitMesh.Positions[t.z] - unitMesh.Positions[t.x]);
    if (!(glm::length(n) > 1e-12f))
    {
      continue;
    }
    const auto index = firstObjectTriangle + static_cast<std::uint32_t>(object.Triangles.size());
    object.Triangles.push_back(t);
    object.MaterialIds.push_back(0);
    for (int k = 0; k < 3; ++k)
    {
      if (triangleOf[t[k]] == none)
      {
        triangleOf[t[k]] = index;
      }
    }
  }
  scene.Append(object);
  const EmbreeScene embree(scene);
  const PathTracer tracer(embree);

  ObjectReference reference;
  std::vector<std::uint32_t> usable;
  for (std::uint32_t i = 0; i < unitMesh.Positions.size(); ++i)
  {
    if (triangleOf[i] != none && i < unitMesh.Normals.size())
    {
      usable.push_back(i);
    }
  }
  const std::size_t count = std::min(usable.size(), std::max<std::size_t>(1, settings.MaxPoints));
  for (std::size_t q = 0; q < count && !usable.empty(); ++q)
  {
    reference.Points.push_back(usable[q * usable.size() / count]);
  }
  reference.Radiance.assign(reference.Points.size(), glm::vec3(0.0f));
  ParallelFor(0, reference.Points.size(), 1,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t q = begin; q < end; ++q)
      {
        const std::uint32_t i = reference.Points[q];
        reference.Radiance[q] = tracer.DiffuseRadianceLeaving(triangleOf[i], unitMesh.Positions[i],
          unitMesh.Normals[i], settings.Samples, settings.Seed + i);
      }
    });
  return reference;
}

//------------------------------------------------------------------------------
double MeanRelativeError(const std::vector<glm::vec3>& radiance, const ObjectReference& reference)
{
  double sum = 0.0;
  std::size_t count = 0;
  for (std::size_t q = 0; q < reference.Points.size(); ++q)
  {
    const glm::vec3& r = reference.Radiance[q];
    const double total = static_cast<double>(r.x) + r.y + r.z;
    if (!(total > 0.0) || reference.Points[q] >= radiance.size())
    {
      continue;
    }
    const glm::vec3 d = glm::abs(radiance[reference.Points[q]] - r);
    sum += (static_cast<double>(d.x) + d.y + d.z) / total;
    ++count;
  }
  return count > 0 ? sum / static_cast<double>(count) : 0.0;
}

} // namespace vlf
} // namespace mesolight
