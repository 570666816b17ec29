// SPDX-License-Identifier: BSD-3-Clause
// EmbreeScene: a committed Embree 3 scene built from a TriangleScene, with single-ray and
// 16-ray-packet queries. Shared by the ray tracer, the path tracer and the light field's
// propagation (parallel rays suit packets; PLATFORM.md: 35 Mrays/s with 16-wide packets
// against 13 Mrays/s single rays on one thread).
#ifndef mesolight_EmbreeScene_h
#define mesolight_EmbreeScene_h

#include "TriangleScene.h"

#include <glm/mat4x4.hpp>
#include <glm/vec3.hpp>

#include <cstdint>
#include <limits>
#include <memory>
#include <vector>

namespace mesolight
{

struct SceneRay
{
  glm::vec3 Origin{ 0.0f };
  glm::vec3 Direction{ 0.0f, 0.0f, 1.0f }; // need not be unit length; t is in its units
  float TNear = 0.0f;
  float TFar = std::numeric_limits<float>::infinity();
};

struct SceneHit
{
  static constexpr std::uint32_t None = std::numeric_limits<std::uint32_t>::max();
  std::uint32_t Triangle = None; // index into TriangleScene::Triangles, None if missed
  float T = std::numeric_limits<float>::infinity();
  float U = 0.0f, V = 0.0f; // barycentrics: point = (1-U-V) v0 + U v1 + V v2
  // Index into the scene's analytic spheres when a sphere was hit (Triangle is None then).
  std::uint32_t Sphere = None;
  // Index into the instanced object's triangles (SetObject) when the object was hit (Triangle
  // and Sphere are None then); U and V are the barycentrics on that triangle.
  std::uint32_t ObjectTriangle = None;
  bool Hit() const
  {
    return this->Triangle != None || this->Sphere != None || this->ObjectTriangle != None;
  }
};

// An analytic sphere, intersected exactly (Embree user geometry) rather than tessellated.
struct SceneSphere
{
  glm::vec3 Center{ 0.0f };
  float Radius = 1.0f;
};

class EmbreeScene
{
public:
  // Builds and commits the Embree scene. Degenerate triangles are kept (Embree never reports
  // hits on them). Throws std::runtime_error when Embree fails (message says why).
  explicit EmbreeScene(const TriangleScene& scene);
  // The triangles and analytic spheres (hits report SceneHit::Sphere). Spheres with a
  // non-positive or non-finite radius or centre are never hit.
  EmbreeScene(const TriangleScene& scene, std::vector<SceneSphere> spheres);
  ~EmbreeScene();
  EmbreeScene(const EmbreeScene&) = delete;
  EmbreeScene& operator=(const EmbreeScene&) = delete;

  // Nearest hit of the ray in [TNear, TFar]. Thread-safe.
  SceneHit Intersect(const SceneRay& ray) const;
  // True when anything lies on the ray in [TNear, TFar]. Thread-safe.
  bool Occluded(const SceneRay& ray) const;
  // Nearest hits of up to 16 rays (count <= 16) traced as one coherent packet. Thread-safe.
  void Intersect16(const SceneRay* rays, SceneHit* hits, int count) const;

  ///@{
  // A movable object (Wither 2005, "Interactive dynamic objects in a virtual light field"):
  // its triangles in their own model coordinates become a separate Embree scene, joined to
  // this one as a single instanced geometry. The first SetObject moves the static geometries
  // into a scene of their own, instanced once (built once more, then never again; their rays
  // pass one instance level more). Moving the object changes only its instance transform
  // (SetObjectTransform): the commit rebuilds the top level over two instances, never the
  // static BVH. Hits on it report
  // SceneHit::ObjectTriangle. Not thread-safe against queries running at the same time:
  // callers stop their tracing threads first. SetObject throws std::runtime_error when Embree
  // fails; degenerate triangles are kept and never hit.
  void SetObject(const std::vector<glm::vec3>& points, const std::vector<glm::uvec3>& triangles);
  // Model -> scene coordinates of the object (an affine matrix).
  void SetObjectTransform(const glm::mat4& objectToScene);
  void ClearObject();
  bool HasObject() const;
  ///@}

  const TriangleScene& Scene() const { return *this->Triangles; }
  const std::vector<SceneSphere>& Spheres() const { return this->SphereList; }

private:
  struct Internals;
  std::unique_ptr<Internals> Impl;
  const TriangleScene* Triangles;
  std::vector<SceneSphere> SphereList;
  void Build(const TriangleScene& scene);
};

} // namespace mesolight

#endif
