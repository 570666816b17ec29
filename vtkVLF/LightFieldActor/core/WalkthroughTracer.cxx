// SPDX-License-Identifier: BSD-3-Clause
#include "WalkthroughTracer.h"

#include "ObjectShadows.h"

#include <glm/geometric.hpp>
#include <glm/trigonometric.hpp>

#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>

namespace mesolight
{
namespace vlf
{

namespace
{
float MaxComponent(const glm::vec3& v)
{
  return std::max(v.x, std::max(v.y, v.z));
}

void Store(float* out, const glm::vec3& radiance, float alpha)
{
  out[0] = radiance.x;
  out[1] = radiance.y;
  out[2] = radiance.z;
  out[3] = alpha;
}
} // namespace

bool ViewFrame::Make(const glm::vec3& eye, const glm::vec3& focal, const glm::vec3& viewUp,
  float viewAngleDegrees, int width, int height, ViewFrame& frame)
{
  const glm::vec3 forward = focal - eye;
  const float length = glm::length(forward);
  if (width < 1 || height < 1 || !(length > 0.0f) || !std::isfinite(length) ||
    !(viewAngleDegrees > 0.0f && viewAngleDegrees < 180.0f))
  {
    return false;
  }
  const glm::vec3 side = glm::cross(forward / length, viewUp);
  if (!(glm::length(side) > 1e-6f * glm::length(viewUp)))
  {
    return false;
  }
  frame.Eye = eye;
  frame.Forward = forward / length;
  frame.Right = glm::normalize(side);
  frame.Up = glm::cross(frame.Right, frame.Forward);
  frame.TanHalfHeight = std::tan(glm::radians(0.5f * viewAngleDegrees));
  frame.Width = width;
  frame.Height = height;
  return true;
}

SceneRay ViewFrame::Ray(float x, float y) const
{
  const float halfWidth =
    this->TanHalfHeight * static_cast<float>(this->Width) / static_cast<float>(this->Height);
  const float sx = (2.0f * x / static_cast<float>(this->Width) - 1.0f) * halfWidth;
  const float sy = (2.0f * y / static_cast<float>(this->Height) - 1.0f) * this->TanHalfHeight;
  SceneRay ray;
  ray.Origin = this->Eye;
  ray.Direction = glm::normalize(this->Forward + sx * this->Right + sy * this->Up);
  return ray;
}

bool ViewFrame::operator==(const ViewFrame& o) const
{
  return this->Eye == o.Eye && this->Forward == o.Forward && this->Right == o.Right &&
    this->Up == o.Up && this->TanHalfHeight == o.TanHalfHeight && this->Width == o.Width &&
    this->Height == o.Height;
}

WalkthroughTracer::WalkthroughTracer(const LightField& field)
  : LightFieldRef(field)
  , Scene(new EmbreeScene(field.Scene()))
  , FieldLookup(field)
{
  this->Mirror.assign(field.Surfaces().size(), 0);
  for (std::uint32_t s = 0; s < field.Surfaces().size(); ++s)
  {
    if (MaxComponent(field.MaterialOf(s).Specular) > 0.0f)
    {
      this->Mirror[s] = 1;
      ++this->MirrorCount;
    }
  }
  // A mirror with another mirror's vertex in front of its plane may reflect into it: only
  // those reflections follow the chain for the object beyond the first bounce.
  this->MirrorFacesMirror.assign(field.Surfaces().size(), 0);
  const TriangleScene& scene = field.Scene();
  std::vector<glm::vec3> onPlane(field.Surfaces().size(), glm::vec3(0.0f));
  std::vector<std::uint8_t> havePoint(field.Surfaces().size(), 0);
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const std::uint32_t s = field.SurfaceOfTriangle(t);
    if (s != NoSurface && this->Mirror[s] && !havePoint[s])
    {
      onPlane[s] = scene.Vertex(t, 0);
      havePoint[s] = 1;
    }
  }
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const std::uint32_t other = field.SurfaceOfTriangle(t);
    if (other == NoSurface || !this->Mirror[other])
    {
      continue;
    }
    for (std::uint32_t s = 0; s < field.Surfaces().size(); ++s)
    {
      for (int corner = 0; corner < 3 && havePoint[s] && s != other; ++corner)
      {
        if (glm::dot(field.Surfaces()[s].Normal, scene.Vertex(t, corner) - onPlane[s]) > 1e-5f)
        {
          this->MirrorFacesMirror[s] = 1;
        }
      }
    }
  }
}

WalkthroughTracer::~WalkthroughTracer() = default;

void WalkthroughTracer::SetObject(const ObjectMesh& model)
{
  const std::string problem = model.Validate();
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  this->ClearObject();
  this->Scene->SetObject(model.Positions, model.Triangles);
  this->ObjectModel = model;
  this->ObjectSet = true;
  this->SetObjectPlacement(this->Placement);
}

void WalkthroughTracer::SetObjectPlacement(const glm::mat4& modelToUnit)
{
  this->Placement = modelToUnit;
  if (!this->ObjectSet)
  {
    return;
  }
  this->Scene->SetObjectTransform(modelToUnit);
  glm::vec3 lower, upper;
  this->ObjectModel.Bounds(lower, upper);
  const glm::vec3 centre = 0.5f * (lower + upper);
  this->ObjectCentre = glm::vec3(modelToUnit * glm::vec4(centre, 1.0f));
  // The largest column length bounds how far the matrix stretches any direction.
  const float stretch = std::max(glm::length(glm::vec3(modelToUnit[0])),
    std::max(glm::length(glm::vec3(modelToUnit[1])), glm::length(glm::vec3(modelToUnit[2]))));
  this->ObjectRadius = 1.001f * std::sqrt(3.0f) * stretch * 0.5f * MaxComponent(upper - lower);
}

void WalkthroughTracer::SetObjectRadiance(std::vector<glm::vec3> radiance)
{
  this->ObjectRadianceValues = std::move(radiance);
}

void WalkthroughTracer::ClearObject()
{
  this->Scene->ClearObject();
  this->ObjectSet = false;
  this->ObjectModel = ObjectMesh{};
  this->ObjectRadianceValues.clear();
  this->ObjectRadius = 0.0f;
}

glm::vec3 WalkthroughTracer::ObjectRadiance(const SceneHit& hit) const
{
  if (hit.ObjectTriangle == SceneHit::None ||
    hit.ObjectTriangle >= this->ObjectModel.Triangles.size() ||
    this->ObjectRadianceValues.size() != this->ObjectModel.Positions.size())
  {
    return glm::vec3(0.0f);
  }
  const glm::uvec3 t = this->ObjectModel.Triangles[hit.ObjectTriangle];
  // Gouraud: the same interpolation the object's own mapper draws with.
  return (1.0f - hit.U - hit.V) * this->ObjectRadianceValues[t.x] +
    hit.U * this->ObjectRadianceValues[t.y] + hit.V * this->ObjectRadianceValues[t.z];
}

bool WalkthroughTracer::MayHitObject(const SceneRay& ray) const
{
  // Most reflected rays miss the object's bounding sphere: no Embree query for them.
  const glm::vec3 d = glm::normalize(ray.Direction);
  const glm::vec3 f = this->ObjectCentre - ray.Origin;
  const float along = glm::dot(f, d);
  const float r2 = this->ObjectRadius * this->ObjectRadius;
  return !(glm::dot(f, f) - along * along > r2 || (along < 0.0f && glm::dot(f, f) > r2));
}

glm::vec3 WalkthroughTracer::ShadedDiffuse(std::uint32_t s, const glm::vec3& p) const
{
  const glm::vec3 total = this->FieldLookup.DiffuseRadiance(s, p);
  if (!this->ShadowsRef || this->ShadowsRef->Empty())
  {
    return total;
  }
  return this->ShadowsRef->Shade(
    total, p, this->LightFieldRef.Surfaces()[s].Normal, this->LightFieldRef.MaterialOf(s).Diffuse);
}

glm::vec3 WalkthroughTracer::LandingRadiance(
  const SceneRay& ray, const SceneHit& hit, std::uint32_t s, const glm::vec3& p) const
{
  glm::vec3 relief;
  if (this->ReliefsRef && this->ReliefsRef->Covers(hit.Triangle) &&
    this->ReliefsRef->Radiance(hit.Triangle, ray.Origin, ray.Direction, relief))
  {
    if (!this->ShadowsRef || this->ShadowsRef->Empty())
    {
      return relief;
    }
    // The object's shadow at the macro point the ray reached, as the walkthrough's relief
    // mapper darkens the relief (by the share of the light, at the wall's normal).
    return this->ShadowsRef->Shade(relief, p, this->LightFieldRef.Surfaces()[s].Normal,
      this->LightFieldRef.MaterialOf(s).Diffuse);
  }
  return this->ShadedDiffuse(s, p);
}

glm::vec3 WalkthroughTracer::MirrorChain::Apply(const glm::vec3& field) const
{
  switch (this->End)
  {
    case Object:
    case Relief:
      return this->Own + this->Throughput * this->Value;
    case Shadow:
      return glm::max(glm::vec3(0.0f), field - this->Throughput * this->Value);
    case Field:
    default:
      return field;
  }
}

WalkthroughTracer::MirrorChain WalkthroughTracer::FollowMirrorChain(
  std::uint32_t s, glm::vec3 p, glm::vec3 d, const TraceOptions& options) const
{
  MirrorChain chain;
  const bool shadows = this->ShadowsRef && !this->ShadowsRef->Empty();
  // With reliefs every chain is followed: the field's value holds the flat wall's light.
  const bool reliefs = this->ReliefsRef != nullptr;
  if (!this->ObjectSet && !shadows && !reliefs)
  {
    return chain;
  }
  glm::vec3 throughput(1.0f);
  for (int depth = 0; depth < std::max(1, options.MaximumDepth); ++depth)
  {
    const glm::vec3 n = this->LightFieldRef.Surfaces()[s].Normal;
    chain.Own += throughput * this->ShadedDiffuse(s, p);
    throughput *= this->LightFieldRef.MaterialOf(s).Specular;
    const glm::vec3 dn = glm::normalize(d);
    SceneRay reflected;
    reflected.Origin = p + this->Epsilon * n;
    reflected.Direction = dn - 2.0f * glm::dot(dn, n) * n;
    const bool deeper = !this->IgnoreDeeperObjectForTesting;
    const bool object = this->ObjectSet && this->MayHitObject(reflected);
    if (!object && !shadows && !reliefs &&
      !(deeper && this->ObjectSet && this->MirrorFacesMirror[s]))
    {
      return MirrorChain{}; // nothing the field does not know along this reflection
    }
    const SceneHit hit = this->Scene->Intersect(reflected);
    std::uint32_t next;
    const PixelClass c = this->Classify(reflected, hit, next);
    if (c == PixelClass::Object)
    {
      chain.End = MirrorChain::Object;
      chain.Throughput = throughput;
      chain.Value = this->ObjectRadiance(hit);
      return chain;
    }
    const glm::vec3 q = reflected.Origin + hit.T * reflected.Direction;
    if (c == PixelClass::Mirror && deeper)
    {
      s = next;
      p = q;
      d = reflected.Direction;
      continue;
    }
    if ((c == PixelClass::Diffuse || c == PixelClass::Emitter) && reliefs &&
      this->ReliefsRef->Covers(hit.Triangle))
    {
      chain.End = MirrorChain::Relief;
      chain.Throughput = throughput;
      chain.Value = this->LandingRadiance(reflected, hit, next, q);
      return chain;
    }
    if (c == PixelClass::Diffuse && shadows)
    {
      // The field's value at the mirror holds this point's unshadowed light: take off what the
      // object's shadow takes off there.
      const glm::vec3 lost =
        this->FieldLookup.DiffuseRadiance(next, q) - this->ShadedDiffuse(next, q);
      if (MaxComponent(lost) > 0.0f)
      {
        chain.End = MirrorChain::Shadow;
        chain.Throughput = throughput;
        chain.Value = lost;
        return chain;
      }
    }
    return MirrorChain{};
  }
  return MirrorChain{};
}

PixelClass WalkthroughTracer::Classify(
  const SceneRay& ray, const SceneHit& hit, std::uint32_t& surface) const
{
  surface = NoSurface;
  if (hit.ObjectTriangle != SceneHit::None)
  {
    return PixelClass::Object;
  }
  if (hit.Triangle == SceneHit::None)
  {
    return PixelClass::Background;
  }
  surface = this->LightFieldRef.SurfaceOfTriangle(hit.Triangle);
  if (surface == NoSurface)
  {
    return PixelClass::Background;
  }
  const Surface& s = this->LightFieldRef.Surfaces()[surface];
  if (!(glm::dot(s.Normal, ray.Direction) < 0.0f))
  {
    return PixelClass::BackFace;
  }
  if (this->Mirror[surface])
  {
    return PixelClass::Mirror;
  }
  return MaxComponent(this->LightFieldRef.MaterialOf(surface).Emission) > 0.0f
    ? PixelClass::Emitter
    : PixelClass::Diffuse;
}

glm::vec3 WalkthroughTracer::RaytraceRadiance(const SceneRay& ray) const
{
  const SceneHit hit = this->Scene->Intersect(ray);
  std::uint32_t s;
  const PixelClass c = this->Classify(ray, hit, s);
  if (c == PixelClass::Background || c == PixelClass::BackFace)
  {
    return glm::vec3(0.0f);
  }
  if (c == PixelClass::Object)
  {
    return this->ObjectRadiance(hit);
  }
  const glm::vec3 p = ray.Origin + hit.T * ray.Direction;
  if (c == PixelClass::Mirror)
  {
    return this->MirrorRadiance(s, p, ray.Direction, SpecularQuality::Raytrace, TraceOptions{});
  }
  return this->FieldLookup.RadianceLeaving(s, p, -glm::normalize(ray.Direction),
    CellInterpolation::Bilinear, DirectionInterpolation::Spherical);
}

glm::vec3 WalkthroughTracer::TracedRadiance(
  const SceneRay& primary, const TraceOptions& options) const
{
  glm::vec3 sum(0.0f), throughput(1.0f);
  SceneRay ray = primary;
  for (int depth = 0; depth <= options.MaximumDepth; ++depth)
  {
    const SceneHit hit = this->Scene->Intersect(ray);
    std::uint32_t s;
    const PixelClass c = this->Classify(ray, hit, s);
    if (c == PixelClass::Background || c == PixelClass::BackFace)
    {
      break;
    }
    if (c == PixelClass::Object)
    {
      sum += throughput * this->ObjectRadiance(hit);
      break;
    }
    const glm::vec3 p = ray.Origin + hit.T * ray.Direction;
    if (c != PixelClass::Mirror)
    {
      if (options.BouncesShortForTesting <= 0)
      {
        sum += throughput * this->LandingRadiance(ray, hit, s, p);
      }
      break;
    }
    // A mirror: its own diffuse part, then the perfect reflection.
    sum += throughput * this->ShadedDiffuse(s, p);
    const glm::vec3 n = this->LightFieldRef.Surfaces()[s].Normal;
    throughput *= this->LightFieldRef.MaterialOf(s).Specular;
    const glm::vec3 d = glm::normalize(ray.Direction);
    ray.Origin = p + this->Epsilon * n;
    ray.Direction = d - 2.0f * glm::dot(d, n) * n;
    ray.TNear = 0.0f;
    ray.TFar = std::numeric_limits<float>::infinity();
  }
  return sum;
}

void WalkthroughTracer::TracedRadiance16(
  const SceneRay* rays, int count, const TraceOptions& options, glm::vec3* out) const
{
  SceneRay active[16];
  SceneHit hits[16];
  int slot[16];
  glm::vec3 throughput[16];
  int n = 0;
  for (int q = 0; q < count; ++q)
  {
    out[q] = glm::vec3(0.0f);
    active[n] = rays[q];
    slot[n] = q;
    throughput[n] = glm::vec3(1.0f);
    ++n;
  }
  for (int depth = 0; depth <= options.MaximumDepth && n > 0; ++depth)
  {
    this->Scene->Intersect16(active, hits, n);
    int next = 0;
    for (int q = 0; q < n; ++q)
    {
      std::uint32_t s;
      const PixelClass c = this->Classify(active[q], hits[q], s);
      if (c == PixelClass::Background || c == PixelClass::BackFace)
      {
        continue;
      }
      if (c == PixelClass::Object)
      {
        out[slot[q]] += throughput[q] * this->ObjectRadiance(hits[q]);
        continue;
      }
      const glm::vec3 p = active[q].Origin + hits[q].T * active[q].Direction;
      if (c != PixelClass::Mirror)
      {
        if (options.BouncesShortForTesting <= 0)
        {
          out[slot[q]] += throughput[q] * this->LandingRadiance(active[q], hits[q], s, p);
        }
        continue;
      }
      out[slot[q]] += throughput[q] * this->ShadedDiffuse(s, p);
      const glm::vec3 normal = this->LightFieldRef.Surfaces()[s].Normal;
      const glm::vec3 d = glm::normalize(active[q].Direction);
      SceneRay reflected;
      reflected.Origin = p + this->Epsilon * normal;
      reflected.Direction = d - 2.0f * glm::dot(d, normal) * normal;
      // Compacting in place: next <= q, so entries not yet read are never overwritten.
      throughput[next] = throughput[q] * this->LightFieldRef.MaterialOf(s).Specular;
      slot[next] = slot[q];
      active[next] = reflected;
      ++next;
    }
    n = next;
  }
}

glm::vec3 WalkthroughTracer::MirrorRadiance(std::uint32_t s, const glm::vec3& p, const glm::vec3& d,
  SpecularQuality quality, const TraceOptions& options) const
{
  const glm::vec3 toEye = -glm::normalize(d);
  MirrorChain chain;
  if (quality != SpecularQuality::Traced)
  {
    chain = this->FollowMirrorChain(s, p, d, options);
    if (chain.End == MirrorChain::Object || chain.End == MirrorChain::Relief)
    {
      return chain.Apply(glm::vec3(0.0f));
    }
  }
  switch (quality)
  {
    case SpecularQuality::Moving:
      // One direction instead of three (nearest cells leave holes where a line just misses).
      return chain.Apply(this->FieldLookup.RadianceLeaving(
        s, p, toEye, CellInterpolation::Bilinear, DirectionInterpolation::Nearest));
    case SpecularQuality::Raytrace:
      return chain.Apply(this->FieldLookup.RadianceLeaving(
        s, p, toEye, CellInterpolation::Bilinear, DirectionInterpolation::Spherical));
    case SpecularQuality::Traced:
    default:
    {
      const glm::vec3 n = this->LightFieldRef.Surfaces()[s].Normal;
      const glm::vec3 dn = -toEye;
      SceneRay reflected;
      reflected.Origin = p + this->Epsilon * n;
      reflected.Direction = dn - 2.0f * glm::dot(dn, n) * n;
      TraceOptions rest = options;
      rest.MaximumDepth = options.MaximumDepth - 1;
      const glm::vec3 own = this->ShadedDiffuse(s, p);
      return own +
        this->LightFieldRef.MaterialOf(s).Specular * this->TracedRadiance(reflected, rest);
    }
  }
}

std::size_t WalkthroughTracer::ShadeRows(const ViewFrame& view, const PixelRect& rect,
  bool allSurfaces, SpecularQuality quality, const TraceOptions& options, int rowBegin, int rowEnd,
  float* out) const
{
  std::size_t valued = 0;
  for (int row = rowBegin; row < rowEnd; ++row)
  {
    for (int column = rect.X0; column < rect.X1; ++column)
    {
      float* rgba =
        out + (static_cast<std::size_t>(row - rect.Y0) * rect.Width() + (column - rect.X0)) * 4;
      const SceneRay ray =
        view.Ray(static_cast<float>(column) + 0.5f, static_cast<float>(row) + 0.5f);
      const SceneHit hit = this->Scene->Intersect(ray);
      std::uint32_t s;
      const PixelClass c = this->Classify(ray, hit, s);
      if (c == PixelClass::Background || c == PixelClass::BackFace || c == PixelClass::Object ||
        (!allSurfaces && c != PixelClass::Mirror))
      {
        // The object occludes: no screen value, so its own actor's fragment shows.
        Store(rgba, glm::vec3(0.0f), allSurfaces && c == PixelClass::BackFace ? 1.0f : 0.0f);
        continue;
      }
      const glm::vec3 p = ray.Origin + hit.T * ray.Direction;
      const glm::vec3 radiance = c == PixelClass::Mirror
        ? this->MirrorRadiance(s, p, ray.Direction, quality, options)
        : this->FieldLookup.RadianceLeaving(
            s, p, -ray.Direction, CellInterpolation::Bilinear, DirectionInterpolation::Spherical);
      Store(rgba, radiance, 1.0f);
      ++valued;
    }
  }
  return valued;
}

std::size_t WalkthroughTracer::TileCount(const PixelRect& rect)
{
  if (rect.Empty())
  {
    return 0;
  }
  return static_cast<std::size_t>((rect.Width() + 3) / 4) *
    static_cast<std::size_t>((rect.Height() + 3) / 4);
}

std::size_t WalkthroughTracer::ShadeTiles(const ViewFrame& view, const PixelRect& rect,
  bool allSurfaces, SpecularQuality quality, const TraceOptions& options, std::size_t tileBegin,
  std::size_t tileEnd, float* out) const
{
  const int tilesX = (rect.Width() + 3) / 4;
  std::size_t valued = 0;
  SceneRay rays[16];
  SceneHit hits[16];
  int columns[16], rows[16];
  SceneRay reflected[16];
  int reflectedSlot[16];
  glm::vec3 own[16], ks[16], traced[16];
  TraceOptions rest = options;
  rest.MaximumDepth = options.MaximumDepth - 1;
  for (std::size_t tile = tileBegin; tile < tileEnd; ++tile)
  {
    const int tx = static_cast<int>(tile % static_cast<std::size_t>(tilesX));
    const int ty = static_cast<int>(tile / static_cast<std::size_t>(tilesX));
    int n = 0;
    for (int dy = 0; dy < 4; ++dy)
    {
      for (int dx = 0; dx < 4; ++dx)
      {
        const int column = rect.X0 + 4 * tx + dx, row = rect.Y0 + 4 * ty + dy;
        if (column >= rect.X1 || row >= rect.Y1)
        {
          continue;
        }
        columns[n] = column;
        rows[n] = row;
        rays[n] = view.Ray(static_cast<float>(column) + 0.5f, static_cast<float>(row) + 0.5f);
        ++n;
      }
    }
    this->Scene->Intersect16(rays, hits, n);
    int m = 0;
    std::uint32_t blockSurface[4] = { NoSurface, NoSurface, NoSurface, NoSurface };
    glm::vec3 blockValue[4];
    for (int q = 0; q < n; ++q)
    {
      float* rgba = out +
        (static_cast<std::size_t>(rows[q] - rect.Y0) * rect.Width() + (columns[q] - rect.X0)) * 4;
      std::uint32_t s;
      const PixelClass c = this->Classify(rays[q], hits[q], s);
      if (c == PixelClass::Background || c == PixelClass::BackFace || c == PixelClass::Object ||
        (!allSurfaces && c != PixelClass::Mirror))
      {
        Store(rgba, glm::vec3(0.0f), allSurfaces && c == PixelClass::BackFace ? 1.0f : 0.0f);
        continue;
      }
      const glm::vec3 p = rays[q].Origin + hits[q].T * rays[q].Direction;
      if (c == PixelClass::Mirror && quality == SpecularQuality::Moving)
      {
        // While the camera moves one lookup serves each 2 x 2 pixel block of one surface (the
        // mode is blurry by design; this quarters its cost).
        const MirrorChain chain = this->FollowMirrorChain(s, p, rays[q].Direction, options);
        if (chain.End == MirrorChain::Object)
        {
          Store(rgba, chain.Apply(glm::vec3(0.0f)), 1.0f); // per pixel: a sharp outline
          ++valued;
          continue;
        }
        const int block = ((rows[q] - rect.Y0) / 2 % 2) * 2 + (columns[q] - rect.X0) / 2 % 2;
        if (blockSurface[block] != s)
        {
          blockSurface[block] = s;
          blockValue[block] =
            this->FieldLookup.RadianceLeaving(s, p, -glm::normalize(rays[q].Direction),
              CellInterpolation::Bilinear, DirectionInterpolation::Nearest);
        }
        Store(rgba, chain.Apply(blockValue[block]), 1.0f); // the shadow per pixel too
        ++valued;
        continue;
      }
      if (c != PixelClass::Mirror || quality != SpecularQuality::Traced)
      {
        Store(rgba,
          c == PixelClass::Mirror
            ? this->MirrorRadiance(s, p, rays[q].Direction, quality, options)
            : this->FieldLookup.RadianceLeaving(s, p, -rays[q].Direction,
                CellInterpolation::Bilinear, DirectionInterpolation::Spherical),
          1.0f);
        ++valued;
        continue;
      }
      const glm::vec3 normal = this->LightFieldRef.Surfaces()[s].Normal;
      const glm::vec3 d = rays[q].Direction;
      reflected[m].Origin = p + this->Epsilon * normal;
      reflected[m].Direction = d - 2.0f * glm::dot(d, normal) * normal;
      own[m] = this->ShadedDiffuse(s, p);
      ks[m] = this->LightFieldRef.MaterialOf(s).Specular;
      reflectedSlot[m] = q;
      ++m;
    }
    if (m == 0)
    {
      continue;
    }
    this->TracedRadiance16(reflected, m, rest, traced);
    for (int r = 0; r < m; ++r)
    {
      const int q = reflectedSlot[r];
      float* rgba = out +
        (static_cast<std::size_t>(rows[q] - rect.Y0) * rect.Width() + (columns[q] - rect.X0)) * 4;
      Store(rgba, own[r] + ks[r] * traced[r], 1.0f);
      ++valued;
    }
  }
  return valued;
}

void WalkthroughTracer::DilateEdges(const PixelRect& rect, float* rgba)
{
  const int w = rect.Width(), h = rect.Height();
  if (w <= 0 || h <= 0)
  {
    return;
  }
  // Reads the original alpha only: fill from pixels valued before this pass.
  std::vector<std::uint8_t> had(static_cast<std::size_t>(w) * h);
  for (std::size_t i = 0; i < had.size(); ++i)
  {
    had[i] = rgba[4 * i + 3] > 0.0f ? 1 : 0;
  }
  static const int offsets[8][2] = { { -1, 0 }, { 1, 0 }, { 0, -1 }, { 0, 1 }, { -1, -1 },
    { 1, -1 }, { -1, 1 }, { 1, 1 } };
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      if (had[i])
      {
        continue;
      }
      for (const auto& o : offsets)
      {
        const int nx = x + o[0], ny = y + o[1];
        if (nx < 0 || ny < 0 || nx >= w || ny >= h)
        {
          continue;
        }
        const std::size_t j = static_cast<std::size_t>(ny) * w + nx;
        if (had[j])
        {
          std::copy_n(rgba + 4 * j, 3, rgba + 4 * i);
          // Alpha 1/2 marks a borrowed value: used only where GL rasterises a mirror fragment.
          rgba[4 * i + 3] = 0.5f;
          break;
        }
      }
    }
  }
}

PixelRect WalkthroughTracer::MirrorRect(const ViewFrame& view) const
{
  PixelRect full{ 0, 0, view.Width, view.Height };
  if (!this->HasMirrors())
  {
    return PixelRect{};
  }
  const TriangleScene& scene = this->LightFieldRef.Scene();
  const float halfWidth =
    view.TanHalfHeight * static_cast<float>(view.Width) / static_cast<float>(view.Height);
  float xmin = 1e30f, xmax = -1e30f, ymin = 1e30f, ymax = -1e30f;
  bool any = false;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const std::uint32_t s = this->LightFieldRef.SurfaceOfTriangle(t);
    if (s == NoSurface || !this->Mirror[s])
    {
      continue;
    }
    for (int corner = 0; corner < 3; ++corner)
    {
      const glm::vec3 r = scene.Vertex(t, corner) - view.Eye;
      const float z = glm::dot(r, view.Forward);
      if (!(z > 1e-6f))
      {
        return full; // a mirror vertex behind the eye: its projection is unbounded
      }
      const float x =
        (glm::dot(r, view.Right) / z / halfWidth + 1.0f) * 0.5f * static_cast<float>(view.Width);
      const float y = (glm::dot(r, view.Up) / z / view.TanHalfHeight + 1.0f) * 0.5f *
        static_cast<float>(view.Height);
      xmin = std::min(xmin, x);
      xmax = std::max(xmax, x);
      ymin = std::min(ymin, y);
      ymax = std::max(ymax, y);
      any = true;
    }
  }
  if (!any)
  {
    return PixelRect{};
  }
  // One pixel of margin for the edge dilation.
  PixelRect rect;
  rect.X0 = std::max(0, static_cast<int>(std::floor(xmin)) - 1);
  rect.Y0 = std::max(0, static_cast<int>(std::floor(ymin)) - 1);
  rect.X1 = std::min(view.Width, static_cast<int>(std::ceil(xmax)) + 1);
  rect.Y1 = std::min(view.Height, static_cast<int>(std::ceil(ymax)) + 1);
  if (rect.Empty())
  {
    return PixelRect{};
  }
  return rect;
}

std::vector<PixelClass> WalkthroughTracer::ClassifyView(const ViewFrame& view) const
{
  std::vector<PixelClass> classes(
    static_cast<std::size_t>(view.Width) * view.Height, PixelClass::Background);
  for (int row = 0; row < view.Height; ++row)
  {
    for (int column = 0; column < view.Width; ++column)
    {
      const SceneRay ray =
        view.Ray(static_cast<float>(column) + 0.5f, static_cast<float>(row) + 0.5f);
      std::uint32_t s;
      classes[static_cast<std::size_t>(row) * view.Width + column] =
        this->Classify(ray, this->Scene->Intersect(ray), s);
    }
  }
  return classes;
}

} // namespace vlf
} // namespace mesolight
