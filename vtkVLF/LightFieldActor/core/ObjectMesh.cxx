// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectMesh.h"

#include "LightField.h"
#include "MathConstants.h"

#include <glm/geometric.hpp>
#include <glm/gtc/matrix_transform.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <limits>

namespace mesolight
{
namespace vlf
{

namespace
{
bool Finite(const glm::vec3& v)
{
  return std::isfinite(v.x) && std::isfinite(v.y) && std::isfinite(v.z);
}
}

//------------------------------------------------------------------------------
std::string ObjectMesh::Validate() const
{
  if (this->Triangles.empty())
  {
    return "the object has no triangles";
  }
  if (!this->Normals.empty() && this->Normals.size() != this->Positions.size())
  {
    return "the object has " + std::to_string(this->Normals.size()) + " normals for " +
      std::to_string(this->Positions.size()) + " points";
  }
  for (const glm::vec3& p : this->Positions)
  {
    if (!Finite(p))
    {
      return "the object has a point that is not a finite number";
    }
  }
  for (const glm::uvec3& t : this->Triangles)
  {
    if (std::max({ t.x, t.y, t.z }) >= this->Positions.size())
    {
      return "a triangle of the object refers to point " +
        std::to_string(std::max({ t.x, t.y, t.z })) + " of " +
        std::to_string(this->Positions.size());
    }
  }
  if (!Finite(this->Diffuse) ||
    std::min({ this->Diffuse.x, this->Diffuse.y, this->Diffuse.z }) < 0.0f ||
    std::max({ this->Diffuse.x, this->Diffuse.y, this->Diffuse.z }) > 1.0f)
  {
    return "the object's diffuse reflectance must lie in [0, 1]";
  }
  if (this->DegenerateTriangleCount() == this->Triangles.size())
  {
    return "every triangle of the object has zero area";
  }
  return {};
}

//------------------------------------------------------------------------------
void ObjectMesh::ComputeNormals()
{
  this->Normals.assign(this->Positions.size(), glm::vec3(0.0f));
  for (const glm::uvec3& t : this->Triangles)
  {
    if (std::max({ t.x, t.y, t.z }) >= this->Positions.size())
    {
      continue;
    }
    // The cross product's length is twice the area: an area-weighted sum.
    const glm::vec3 n = glm::cross(
      this->Positions[t.y] - this->Positions[t.x], this->Positions[t.z] - this->Positions[t.x]);
    if (!Finite(n))
    {
      continue;
    }
    this->Normals[t.x] += n;
    this->Normals[t.y] += n;
    this->Normals[t.z] += n;
  }
  for (glm::vec3& n : this->Normals)
  {
    const float length = glm::length(n);
    n = length > 0.0f ? n / length : glm::vec3(0.0f, 0.0f, 1.0f);
  }
}

//------------------------------------------------------------------------------
std::size_t ObjectMesh::DegenerateTriangleCount() const
{
  glm::vec3 lower, upper;
  this->Bounds(lower, upper);
  const float size = glm::length(upper - lower);
  // Relative to the object's size: a triangle whose doubled area is below this is a sliver.
  const float threshold = 1e-12f * size * size;
  std::size_t count = 0;
  for (const glm::uvec3& t : this->Triangles)
  {
    if (std::max({ t.x, t.y, t.z }) >= this->Positions.size())
    {
      ++count;
      continue;
    }
    const glm::vec3 n = glm::cross(
      this->Positions[t.y] - this->Positions[t.x], this->Positions[t.z] - this->Positions[t.x]);
    count += !(glm::length(n) > threshold);
  }
  return count;
}

//------------------------------------------------------------------------------
void ObjectMesh::Bounds(glm::vec3& lower, glm::vec3& upper) const
{
  if (this->Positions.empty())
  {
    lower = upper = glm::vec3(0.0f);
    return;
  }
  lower = glm::vec3(std::numeric_limits<float>::max());
  upper = -lower;
  for (const glm::vec3& p : this->Positions)
  {
    lower = glm::min(lower, p);
    upper = glm::max(upper, p);
  }
}

//------------------------------------------------------------------------------
glm::mat4 WorldToUnitSphere(const LightField& field)
{
  const float scale = field.NormalizationScale();
  return glm::translate(
    glm::scale(glm::mat4(1.0f), glm::vec3(scale)), -field.NormalizationCentre());
}

//------------------------------------------------------------------------------
ObjectMesh TransformMesh(const ObjectMesh& mesh, const glm::mat4& transform)
{
  ObjectMesh out;
  out.Triangles = mesh.Triangles;
  out.Diffuse = mesh.Diffuse;
  out.Positions.reserve(mesh.Positions.size());
  for (const glm::vec3& p : mesh.Positions)
  {
    out.Positions.emplace_back(transform * glm::vec4(p, 1.0f));
  }
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(transform)));
  out.Normals.reserve(mesh.Normals.size());
  for (const glm::vec3& n : mesh.Normals)
  {
    const glm::vec3 m = normalMatrix * n;
    const float length = glm::length(m);
    out.Normals.push_back(length > 0.0f ? m / length : n);
  }
  return out;
}

//------------------------------------------------------------------------------
ObjectMesh MakeSphere(float radius, int rings, int segments)
{
  rings = std::max(rings, 2);
  segments = std::max(segments, 3);
  ObjectMesh mesh;
  const float pi = Pi<float>;
  for (int r = 0; r <= rings; ++r)
  {
    const float theta = pi * static_cast<float>(r) / static_cast<float>(rings);
    for (int s = 0; s <= segments; ++s)
    {
      const float phi = 2.0f * pi * static_cast<float>(s) / static_cast<float>(segments);
      const glm::vec3 n(
        std::sin(theta) * std::cos(phi), std::sin(theta) * std::sin(phi), std::cos(theta));
      mesh.Positions.push_back(radius * n);
      mesh.Normals.push_back(n);
    }
  }
  const unsigned row = static_cast<unsigned>(segments + 1);
  for (unsigned r = 0; r < static_cast<unsigned>(rings); ++r)
  {
    for (unsigned s = 0; s < static_cast<unsigned>(segments); ++s)
    {
      const unsigned a = r * row + s, b = a + 1, c = a + row, d = c + 1;
      if (r != 0)
      {
        mesh.Triangles.emplace_back(a, c, b); // outward: theta grows toward -Z
      }
      if (r + 1 != static_cast<unsigned>(rings))
      {
        mesh.Triangles.emplace_back(b, c, d);
      }
    }
  }
  return mesh;
}

//------------------------------------------------------------------------------
ObjectMesh MakeCube(float side)
{
  ObjectMesh mesh;
  const float h = 0.5f * side;
  for (int axis = 0; axis < 3; ++axis)
  {
    for (int sign = -1; sign <= 1; sign += 2)
    {
      glm::vec3 n(0.0f);
      n[axis] = static_cast<float>(sign);
      glm::vec3 u(0.0f), v(0.0f);
      u[(axis + 1) % 3] = 1.0f;
      v[(axis + 2) % 3] = 1.0f;
      if (sign < 0)
      {
        std::swap(u, v); // keep u x v = n: counter-clockwise seen from outside
      }
      const unsigned first = static_cast<unsigned>(mesh.Positions.size());
      const glm::vec3 centre = h * n;
      mesh.Positions.push_back(centre - h * u - h * v);
      mesh.Positions.push_back(centre + h * u - h * v);
      mesh.Positions.push_back(centre + h * u + h * v);
      mesh.Positions.push_back(centre - h * u + h * v);
      mesh.Normals.insert(mesh.Normals.end(), 4, n);
      // Each face maps the whole texture (u along u, v along v), so a relief tiles every face.
      mesh.TextureCoordinates.insert(mesh.TextureCoordinates.end(),
        { glm::vec2(0.0f, 0.0f), glm::vec2(1.0f, 0.0f), glm::vec2(1.0f, 1.0f),
          glm::vec2(0.0f, 1.0f) });
      mesh.Triangles.emplace_back(first, first + 1, first + 2);
      mesh.Triangles.emplace_back(first, first + 2, first + 3);
    }
  }
  return mesh;
}

ObjectMesh MakeBracket(float width, float height, float thickness, float depth)
{
  ObjectMesh mesh;
  // The C profile, counter-clockwise seen from +z, centred on the origin.
  const float w = width, h = height, t = thickness;
  const glm::vec2 profile[8] = { { 0, 0 }, { w, 0 }, { w, t }, { t, t }, { t, h - t }, { w, h - t },
    { w, h }, { 0, h } };
  const glm::vec2 centre(0.5f * w, 0.5f * h);
  const float z = 0.5f * depth;
  auto at = [&](int corner, float zz) { return glm::vec3(profile[corner] - centre, zz); };
  // The sides: one quad per profile edge, flat normals (right of the edge: outside).
  for (int e = 0; e < 8; ++e)
  {
    const int a = e, b = (e + 1) % 8;
    const glm::vec2 edge = profile[b] - profile[a];
    const glm::vec3 n = glm::normalize(glm::vec3(edge.y, -edge.x, 0.0f));
    const unsigned first = static_cast<unsigned>(mesh.Positions.size());
    mesh.Positions.insert(mesh.Positions.end(), { at(a, -z), at(b, -z), at(b, z), at(a, z) });
    mesh.Normals.insert(mesh.Normals.end(), 4, n);
    mesh.Triangles.emplace_back(first, first + 1, first + 2);
    mesh.Triangles.emplace_back(first, first + 2, first + 3);
  }
  // The caps: the concave octagon as six triangles (no T-junctions).
  static const int caps[6][3] = { { 0, 1, 2 }, { 0, 2, 3 }, { 0, 3, 4 }, { 0, 4, 7 }, { 7, 4, 5 },
    { 7, 5, 6 } };
  for (int side = -1; side <= 1; side += 2)
  {
    const unsigned first = static_cast<unsigned>(mesh.Positions.size());
    for (int corner = 0; corner < 8; ++corner)
    {
      mesh.Positions.push_back(at(corner, static_cast<float>(side) * z));
      mesh.Normals.emplace_back(0.0f, 0.0f, static_cast<float>(side));
    }
    for (const auto& c : caps)
    {
      if (side > 0)
      {
        mesh.Triangles.emplace_back(first + c[0], first + c[1], first + c[2]);
      }
      else
      {
        mesh.Triangles.emplace_back(first + c[0], first + c[2], first + c[1]);
      }
    }
  }
  return mesh;
}

} // namespace vlf
} // namespace mesolight
