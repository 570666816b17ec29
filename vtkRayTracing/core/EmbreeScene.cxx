// SPDX-License-Identifier: BSD-3-Clause
#include "EmbreeScene.h"

#include <embree3/rtcore.h>

#include <glm/geometric.hpp>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>

namespace mesolight
{

struct EmbreeScene::Internals
{
  RTCDevice Device = nullptr;
  RTCScene Scene = nullptr;
  unsigned SphereGeometry = RTC_INVALID_GEOMETRY_ID;
  unsigned TriangleGeometry = RTC_INVALID_GEOMETRY_ID;
  // With an object: the static geometries move into StaticScene, instanced once (identity) in
  // Scene beside the object's instance, so a commit of Scene after a move rebuilds only the
  // top level over two instances (Embree rebuilds every BVH of a scene it commits).
  RTCScene StaticScene = nullptr;
  unsigned StaticInstance = RTC_INVALID_GEOMETRY_ID;
  RTCScene ObjectScene = nullptr; // the instanced object's own triangles
  unsigned ObjectInstance = RTC_INVALID_GEOMETRY_ID;
  bool IsObject(unsigned instance) const
  {
    return instance != RTC_INVALID_GEOMETRY_ID && instance == this->ObjectInstance;
  }
};

namespace
{
std::string DeviceError(RTCDevice device)
{
  switch (rtcGetDeviceError(device))
  {
    case RTC_ERROR_NONE:
      return "no error";
    case RTC_ERROR_INVALID_ARGUMENT:
      return "invalid argument";
    case RTC_ERROR_INVALID_OPERATION:
      return "invalid operation";
    case RTC_ERROR_OUT_OF_MEMORY:
      return "out of memory";
    case RTC_ERROR_UNSUPPORTED_CPU:
      return "unsupported CPU";
    case RTC_ERROR_CANCELLED:
      return "cancelled";
    default:
      return "unknown error";
  }
}

bool UsableSphere(const SceneSphere& sphere)
{
  return std::isfinite(sphere.Center.x) && std::isfinite(sphere.Center.y) &&
    std::isfinite(sphere.Center.z) && std::isfinite(sphere.Radius) && sphere.Radius > 0.0f;
}

void SphereBounds(const RTCBoundsFunctionArguments* args)
{
  const auto* spheres = static_cast<const SceneSphere*>(args->geometryUserPtr);
  const SceneSphere& sphere = spheres[args->primID];
  RTCBounds* bounds = args->bounds_o;
  const float r = UsableSphere(sphere) ? sphere.Radius : 0.0f;
  const glm::vec3 c = UsableSphere(sphere) ? sphere.Center : glm::vec3(0.0f);
  bounds->lower_x = c.x - r;
  bounds->lower_y = c.y - r;
  bounds->lower_z = c.z - r;
  bounds->upper_x = c.x + r;
  bounds->upper_y = c.y + r;
  bounds->upper_z = c.z + r;
}

// Nearest root of |o + t d - c| = r in (tnear, tfar), in the numerically robust form (Haines
// et al., "Precision improvements for ray/sphere intersection", Ray Tracing Gems, 2019).
bool IntersectSphere(const SceneSphere& sphere, const glm::vec3& origin, const glm::vec3& direction,
  float tnear, float tfar, float& t)
{
  if (!UsableSphere(sphere))
  {
    return false;
  }
  const glm::vec3 f = origin - sphere.Center;
  const float a = glm::dot(direction, direction);
  if (!(a > 0.0f))
  {
    return false;
  }
  const float b = -glm::dot(f, direction);
  const glm::vec3 l = f + (b / a) * direction;
  const float discriminant = a * (sphere.Radius * sphere.Radius - glm::dot(l, l));
  if (discriminant < 0.0f)
  {
    return false;
  }
  const float c = glm::dot(f, f) - sphere.Radius * sphere.Radius;
  const float q = b + std::copysign(std::sqrt(discriminant), b);
  float t0 = c / q;
  float t1 = q / a;
  if (t0 > t1)
  {
    std::swap(t0, t1);
  }
  if (t0 > tnear && t0 < tfar)
  {
    t = t0;
    return true;
  }
  if (t1 > tnear && t1 < tfar)
  {
    t = t1;
    return true;
  }
  return false;
}

void SphereIntersect(const RTCIntersectFunctionNArguments* args)
{
  const auto* spheres = static_cast<const SceneSphere*>(args->geometryUserPtr);
  const SceneSphere& sphere = spheres[args->primID];
  RTCRayN* rays = RTCRayHitN_RayN(args->rayhit, args->N);
  RTCHitN* hits = RTCRayHitN_HitN(args->rayhit, args->N);
  for (unsigned i = 0; i < args->N; ++i)
  {
    if (args->valid[i] == 0)
    {
      continue;
    }
    const unsigned n = args->N;
    const glm::vec3 origin(
      RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i));
    const glm::vec3 direction(
      RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i));
    float t = 0.0f;
    if (!IntersectSphere(
          sphere, origin, direction, RTCRayN_tnear(rays, n, i), RTCRayN_tfar(rays, n, i), t))
    {
      continue;
    }
    const glm::vec3 normal = origin + t * direction - sphere.Center;
    RTCRayN_tfar(rays, n, i) = t;
    RTCHitN_Ng_x(hits, n, i) = normal.x;
    RTCHitN_Ng_y(hits, n, i) = normal.y;
    RTCHitN_Ng_z(hits, n, i) = normal.z;
    RTCHitN_u(hits, n, i) = 0.0f;
    RTCHitN_v(hits, n, i) = 0.0f;
    RTCHitN_primID(hits, n, i) = args->primID;
    RTCHitN_geomID(hits, n, i) = args->geomID;
    RTCHitN_instID(hits, n, i, 0) = args->context->instID[0];
  }
}

void SphereOccluded(const RTCOccludedFunctionNArguments* args)
{
  const auto* spheres = static_cast<const SceneSphere*>(args->geometryUserPtr);
  const SceneSphere& sphere = spheres[args->primID];
  for (unsigned i = 0; i < args->N; ++i)
  {
    if (args->valid[i] == 0)
    {
      continue;
    }
    const unsigned n = args->N;
    RTCRayN* rays = args->ray;
    const glm::vec3 origin(
      RTCRayN_org_x(rays, n, i), RTCRayN_org_y(rays, n, i), RTCRayN_org_z(rays, n, i));
    const glm::vec3 direction(
      RTCRayN_dir_x(rays, n, i), RTCRayN_dir_y(rays, n, i), RTCRayN_dir_z(rays, n, i));
    float t = 0.0f;
    if (IntersectSphere(
          sphere, origin, direction, RTCRayN_tnear(rays, n, i), RTCRayN_tfar(rays, n, i), t))
    {
      RTCRayN_tfar(rays, n, i) = -std::numeric_limits<float>::infinity();
    }
  }
}

void ToEmbree(const SceneRay& in, RTCRay& out)
{
  out.org_x = in.Origin.x;
  out.org_y = in.Origin.y;
  out.org_z = in.Origin.z;
  out.dir_x = in.Direction.x;
  out.dir_y = in.Direction.y;
  out.dir_z = in.Direction.z;
  out.tnear = in.TNear;
  out.tfar = in.TFar;
  out.time = 0.0f;
  out.mask = 0xFFFFFFFFu;
  out.id = 0;
  out.flags = 0;
}
} // namespace

EmbreeScene::EmbreeScene(const TriangleScene& scene)
  : Impl(new Internals)
  , Triangles(&scene)
{
  this->Build(scene);
}

EmbreeScene::EmbreeScene(const TriangleScene& scene, std::vector<SceneSphere> spheres)
  : Impl(new Internals)
  , Triangles(&scene)
  , SphereList(std::move(spheres))
{
  this->Build(scene);
}

void EmbreeScene::Build(const TriangleScene& scene)
{
  this->Impl->Device = rtcNewDevice(nullptr);
  if (!this->Impl->Device)
  {
    throw std::runtime_error("Embree: cannot create a device");
  }
  this->Impl->Scene = rtcNewScene(this->Impl->Device);
  if (!scene.Triangles.empty())
  {
    RTCGeometry geometry = rtcNewGeometry(this->Impl->Device, RTC_GEOMETRY_TYPE_TRIANGLE);
    auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_VERTEX,
      0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), scene.Positions.size()));
    auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(geometry, RTC_BUFFER_TYPE_INDEX,
      0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), scene.Triangles.size()));
    if (!vertices || !indices)
    {
      const std::string why = DeviceError(this->Impl->Device);
      rtcReleaseGeometry(geometry);
      rtcReleaseScene(this->Impl->Scene);
      rtcReleaseDevice(this->Impl->Device);
      throw std::runtime_error("Embree: cannot allocate the triangle buffers (" + why + ")");
    }
    for (std::size_t v = 0; v < scene.Positions.size(); ++v)
    {
      vertices[3 * v + 0] = scene.Positions[v].x;
      vertices[3 * v + 1] = scene.Positions[v].y;
      vertices[3 * v + 2] = scene.Positions[v].z;
    }
    for (std::size_t t = 0; t < scene.Triangles.size(); ++t)
    {
      indices[3 * t + 0] = scene.Triangles[t].x;
      indices[3 * t + 1] = scene.Triangles[t].y;
      indices[3 * t + 2] = scene.Triangles[t].z;
    }
    rtcCommitGeometry(geometry);
    this->Impl->TriangleGeometry = rtcAttachGeometry(this->Impl->Scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  if (!this->SphereList.empty())
  {
    RTCGeometry geometry = rtcNewGeometry(this->Impl->Device, RTC_GEOMETRY_TYPE_USER);
    rtcSetGeometryUserPrimitiveCount(geometry, static_cast<unsigned>(this->SphereList.size()));
    rtcSetGeometryUserData(geometry, this->SphereList.data());
    rtcSetGeometryBoundsFunction(geometry, SphereBounds, nullptr);
    rtcSetGeometryIntersectFunction(geometry, SphereIntersect);
    rtcSetGeometryOccludedFunction(geometry, SphereOccluded);
    rtcCommitGeometry(geometry);
    this->Impl->SphereGeometry = rtcAttachGeometry(this->Impl->Scene, geometry);
    rtcReleaseGeometry(geometry);
  }
  rtcSetSceneBuildQuality(this->Impl->Scene, RTC_BUILD_QUALITY_HIGH);
  rtcCommitScene(this->Impl->Scene);
  if (rtcGetDeviceError(this->Impl->Device) != RTC_ERROR_NONE)
  {
    const std::string why = DeviceError(this->Impl->Device);
    rtcReleaseScene(this->Impl->Scene);
    rtcReleaseDevice(this->Impl->Device);
    throw std::runtime_error("Embree: cannot build the scene (" + why + ")");
  }
}

EmbreeScene::~EmbreeScene()
{
  if (this->Impl->ObjectScene)
  {
    rtcReleaseScene(this->Impl->ObjectScene);
  }
  if (this->Impl->StaticScene)
  {
    rtcReleaseScene(this->Impl->StaticScene);
  }
  rtcReleaseScene(this->Impl->Scene);
  rtcReleaseDevice(this->Impl->Device);
}

void EmbreeScene::SetObject(
  const std::vector<glm::vec3>& points, const std::vector<glm::uvec3>& triangles)
{
  this->ClearObject();
  if (points.empty() || triangles.empty())
  {
    return;
  }
  RTCDevice device = this->Impl->Device;
  RTCScene object = rtcNewScene(device);
  RTCGeometry geometry = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_TRIANGLE);
  auto* vertices = static_cast<float*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_VERTEX, 0, RTC_FORMAT_FLOAT3, 3 * sizeof(float), points.size()));
  auto* indices = static_cast<unsigned*>(rtcSetNewGeometryBuffer(
    geometry, RTC_BUFFER_TYPE_INDEX, 0, RTC_FORMAT_UINT3, 3 * sizeof(unsigned), triangles.size()));
  if (!vertices || !indices)
  {
    const std::string why = DeviceError(device);
    rtcReleaseGeometry(geometry);
    rtcReleaseScene(object);
    throw std::runtime_error("Embree: cannot allocate the object's buffers (" + why + ")");
  }
  for (std::size_t v = 0; v < points.size(); ++v)
  {
    vertices[3 * v + 0] = points[v].x;
    vertices[3 * v + 1] = points[v].y;
    vertices[3 * v + 2] = points[v].z;
  }
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    indices[3 * t + 0] = triangles[t].x;
    indices[3 * t + 1] = triangles[t].y;
    indices[3 * t + 2] = triangles[t].z;
  }
  rtcCommitGeometry(geometry);
  rtcAttachGeometry(object, geometry);
  rtcReleaseGeometry(geometry);
  rtcCommitScene(object);

  if (!this->Impl->StaticScene)
  {
    // Once: the static geometries (same ids) into their own scene, built once more here.
    RTCScene statics = rtcNewScene(device);
    rtcSetSceneBuildQuality(statics, RTC_BUILD_QUALITY_HIGH);
    for (const unsigned id : { this->Impl->TriangleGeometry, this->Impl->SphereGeometry })
    {
      if (id != RTC_INVALID_GEOMETRY_ID)
      {
        rtcAttachGeometryByID(statics, rtcGetGeometry(this->Impl->Scene, id), id);
        rtcDetachGeometry(this->Impl->Scene, id);
      }
    }
    rtcCommitScene(statics);
    RTCGeometry identity = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
    rtcSetGeometryInstancedScene(identity, statics);
    rtcSetGeometryTimeStepCount(identity, 1);
    const glm::mat4 one(1.0f);
    rtcSetGeometryTransform(identity, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &one[0][0]);
    rtcCommitGeometry(identity);
    this->Impl->StaticInstance = rtcAttachGeometry(this->Impl->Scene, identity);
    rtcReleaseGeometry(identity);
    this->Impl->StaticScene = statics;
  }
  RTCGeometry instance = rtcNewGeometry(device, RTC_GEOMETRY_TYPE_INSTANCE);
  rtcSetGeometryInstancedScene(instance, object);
  rtcSetGeometryTimeStepCount(instance, 1);
  const glm::mat4 identity(1.0f);
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &identity[0][0]);
  rtcCommitGeometry(instance);
  this->Impl->ObjectInstance = rtcAttachGeometry(this->Impl->Scene, instance);
  rtcReleaseGeometry(instance);
  this->Impl->ObjectScene = object;
  rtcCommitScene(this->Impl->Scene);
  if (rtcGetDeviceError(device) != RTC_ERROR_NONE)
  {
    const std::string why = DeviceError(device);
    this->ClearObject();
    throw std::runtime_error("Embree: cannot build the object (" + why + ")");
  }
}

void EmbreeScene::SetObjectTransform(const glm::mat4& objectToScene)
{
  if (!this->HasObject())
  {
    return;
  }
  RTCGeometry instance = rtcGetGeometry(this->Impl->Scene, this->Impl->ObjectInstance);
  // glm stores columns contiguously: Embree's column-major 4 x 4 layout.
  rtcSetGeometryTransform(instance, 0, RTC_FORMAT_FLOAT4X4_COLUMN_MAJOR, &objectToScene[0][0]);
  rtcCommitGeometry(instance);
  rtcCommitScene(this->Impl->Scene);
}

void EmbreeScene::ClearObject()
{
  if (this->Impl->ObjectInstance != RTC_INVALID_GEOMETRY_ID)
  {
    rtcDetachGeometry(this->Impl->Scene, this->Impl->ObjectInstance);
    this->Impl->ObjectInstance = RTC_INVALID_GEOMETRY_ID;
    rtcCommitScene(this->Impl->Scene);
  }
  if (this->Impl->ObjectScene)
  {
    rtcReleaseScene(this->Impl->ObjectScene);
    this->Impl->ObjectScene = nullptr;
  }
}

bool EmbreeScene::HasObject() const
{
  return this->Impl->ObjectInstance != RTC_INVALID_GEOMETRY_ID;
}

SceneHit EmbreeScene::Intersect(const SceneRay& ray) const
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRayHit rayHit;
  ToEmbree(ray, rayHit.ray);
  rayHit.hit.geomID = RTC_INVALID_GEOMETRY_ID;
  rayHit.hit.instID[0] = RTC_INVALID_GEOMETRY_ID;
  rtcIntersect1(this->Impl->Scene, &context, &rayHit);
  SceneHit hit;
  if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID && this->Impl->IsObject(rayHit.hit.instID[0]))
  {
    hit.ObjectTriangle = rayHit.hit.primID;
    hit.T = rayHit.ray.tfar;
    hit.U = rayHit.hit.u;
    hit.V = rayHit.hit.v;
  }
  else if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID &&
    rayHit.hit.geomID == this->Impl->SphereGeometry)
  {
    hit.Sphere = rayHit.hit.primID;
    hit.T = rayHit.ray.tfar;
  }
  else if (rayHit.hit.geomID != RTC_INVALID_GEOMETRY_ID)
  {
    hit.Triangle = rayHit.hit.primID;
    hit.T = rayHit.ray.tfar;
    hit.U = rayHit.hit.u;
    hit.V = rayHit.hit.v;
  }
  return hit;
}

bool EmbreeScene::Occluded(const SceneRay& ray) const
{
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  RTCRay embreeRay;
  ToEmbree(ray, embreeRay);
  rtcOccluded1(this->Impl->Scene, &context, &embreeRay);
  // Embree sets tfar to -inf when the ray is occluded.
  return embreeRay.tfar < 0.0f;
}

void EmbreeScene::Intersect16(const SceneRay* rays, SceneHit* hits, int count) const
{
  // Packets and their valid masks must be 64-byte aligned (PLATFORM.md).
  alignas(64) RTCRayHit16 packet;
  alignas(64) int valid[16];
  for (int i = 0; i < 16; ++i)
  {
    const bool active = i < count;
    valid[i] = active ? -1 : 0;
    const SceneRay ray = active ? rays[i] : SceneRay{};
    packet.ray.org_x[i] = ray.Origin.x;
    packet.ray.org_y[i] = ray.Origin.y;
    packet.ray.org_z[i] = ray.Origin.z;
    packet.ray.dir_x[i] = ray.Direction.x;
    packet.ray.dir_y[i] = ray.Direction.y;
    packet.ray.dir_z[i] = ray.Direction.z;
    packet.ray.tnear[i] = ray.TNear;
    packet.ray.tfar[i] = ray.TFar;
    packet.ray.time[i] = 0.0f;
    packet.ray.mask[i] = 0xFFFFFFFFu;
    packet.ray.id[i] = static_cast<unsigned>(i);
    packet.ray.flags[i] = 0;
    packet.hit.geomID[i] = RTC_INVALID_GEOMETRY_ID;
    packet.hit.instID[0][i] = RTC_INVALID_GEOMETRY_ID;
  }
  RTCIntersectContext context;
  rtcInitIntersectContext(&context);
  context.flags = RTC_INTERSECT_CONTEXT_FLAG_COHERENT;
  rtcIntersect16(valid, this->Impl->Scene, &context, &packet);
  for (int i = 0; i < count; ++i)
  {
    SceneHit hit;
    if (packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID &&
      this->Impl->IsObject(packet.hit.instID[0][i]))
    {
      hit.ObjectTriangle = packet.hit.primID[i];
      hit.T = packet.ray.tfar[i];
      hit.U = packet.hit.u[i];
      hit.V = packet.hit.v[i];
    }
    else if (packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID &&
      packet.hit.geomID[i] == this->Impl->SphereGeometry)
    {
      hit.Sphere = packet.hit.primID[i];
      hit.T = packet.ray.tfar[i];
    }
    else if (packet.hit.geomID[i] != RTC_INVALID_GEOMETRY_ID)
    {
      hit.Triangle = packet.hit.primID[i];
      hit.T = packet.ray.tfar[i];
      hit.U = packet.hit.u[i];
      hit.V = packet.hit.v[i];
    }
    hits[i] = hit;
  }
}

} // namespace mesolight
