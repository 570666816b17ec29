// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectSelfOcclusion.h"

#include "EmbreeScene.h"
#include "TriangleScene.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>

namespace mesolight
{
namespace vlf
{
namespace
{
// Of the object's bounding radius: shallower dents count as flat (the header).
constexpr float ConcavityTolerance = 0.05f;
// The tangent-plane test reads at most this many input points (evenly strided): it costs
// O(points) per gathered point, which a large surface (a ParaView dataset) cannot afford.
constexpr std::size_t MaximumHorizonPoints = 4096;
}

ObjectSelfOcclusion::ObjectSelfOcclusion() = default;
ObjectSelfOcclusion::~ObjectSelfOcclusion() = default;

void ObjectSelfOcclusion::Clear()
{
  this->Scene.reset();
  this->Mesh.reset();
  this->InputPoints.clear();
  this->PlacedPoints.clear();
  this->Key = 0;
}

void ObjectSelfOcclusion::Prepare(
  const ObjectMesh& model, const std::vector<glm::vec3>& inputPoints, std::uint64_t key)
{
  if (this->Scene && key == this->Key)
  {
    return;
  }
  this->Scene.reset(); // the scene holds a pointer to the mesh: drop it first
  this->Mesh.reset(new TriangleScene);
  SceneMaterial material;
  material.Name = "object";
  this->Mesh->AddMaterial(material);
  this->Mesh->Positions = model.Positions;
  this->Mesh->Triangles = model.Triangles;
  this->Mesh->MaterialIds.assign(model.Triangles.size(), 0);
  this->Scene.reset(new EmbreeScene(*this->Mesh));
  this->InputPoints = inputPoints;
  this->Key = key;
  this->PlacedPoints.clear();
}

void ObjectSelfOcclusion::Place(const glm::mat4& modelToUnit)
{
  this->UnitToModel = glm::inverse(modelToUnit);
  this->DirectionToModel = glm::mat3(this->UnitToModel);
  this->PlacedPoints.clear();
  const std::size_t n = this->InputPoints.size();
  const std::size_t kept = std::min(n, MaximumHorizonPoints);
  glm::vec3 lower(0.0f), upper(0.0f);
  for (std::size_t i = 0; i < n; ++i)
  {
    const glm::vec3 p = glm::vec3(modelToUnit * glm::vec4(this->InputPoints[i], 1.0f));
    lower = i == 0 ? p : glm::min(lower, p);
    upper = i == 0 ? p : glm::max(upper, p);
  }
  for (std::size_t k = 0; k < kept; ++k)
  {
    const std::size_t i = k * n / kept;
    this->PlacedPoints.push_back(glm::vec3(modelToUnit * glm::vec4(this->InputPoints[i], 1.0f)));
  }
  this->Centre = 0.5f * (lower + upper);
  this->Radius = 0.5f * glm::length(upper - lower);
  // Coplanar points (a flat face's own) and the sag of a tessellated smooth surface (a
  // subdivided point lies below its neighbours' facets: a sphere of 8 x 16 facets sags 2% of its
  // radius) must not count as facing the object; rays start just off the surface so that they
  // do not hit the triangle they leave.
  this->PlaneTolerance = ConcavityTolerance * this->Radius;
  this->RayOffset = 1e-4f * this->Radius;
}

bool ObjectSelfOcclusion::SeesItself(const glm::vec3& p, const glm::vec3& n) const
{
  if (!this->Scene)
  {
    return false;
  }
  // The whole bounding sphere below the plane: nothing to test (a sphere's points, for one).
  if (glm::dot(this->Centre - p, n) + this->Radius <= this->PlaneTolerance)
  {
    return false;
  }
  for (const glm::vec3& q : this->PlacedPoints)
  {
    if (glm::dot(q - p, n) > this->PlaneTolerance)
    {
      return true;
    }
  }
  return false;
}

void ObjectSelfOcclusion::Trace16(const glm::vec3* origins, const glm::vec3* normals,
  const glm::vec3* directions, int count, ObjectSelfHit* hits) const
{
  SceneRay rays[16];
  SceneHit found[16];
  count = std::min(count, 16);
  for (int q = 0; q < count; ++q)
  {
    const glm::vec3 start = origins[q] + this->RayOffset * normals[q];
    rays[q].Origin = glm::vec3(this->UnitToModel * glm::vec4(start, 1.0f));
    rays[q].Direction = this->DirectionToModel * directions[q];
    rays[q].TNear = 0.0f;
  }
  this->Scene->Intersect16(rays, found, count);
  for (int q = 0; q < count; ++q)
  {
    hits[q] = ObjectSelfHit();
    const std::uint32_t t = found[q].Triangle;
    if (t == SceneHit::None)
    {
      continue;
    }
    // In model coordinates the winding says outside whatever the placement (a mirroring scale
    // turns the normals, not the triangles).
    hits[q].Front = glm::dot(this->Mesh->FaceNormal(t), rays[q].Direction) < 0.0f;
    hits[q].Triangle = t;
    hits[q].U = found[q].U;
    hits[q].V = found[q].V;
  }
}

} // namespace vlf
} // namespace mesolight
