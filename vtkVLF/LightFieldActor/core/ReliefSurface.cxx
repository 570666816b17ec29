// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefSurface.h"

#include "FieldIrradiance.h"
#include "LightField.h"
#include "ParallelFor.h"
#include "SurfaceRelief.h" // SurfacePlaneOf
#include "TriangleScene.h"

#include <algorithm>
#include <array>
#include <cmath>
#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>
#include <glm/vector_relational.hpp>
#include <sstream>

namespace mesolight
{
namespace vlf
{
namespace
{
// How far behind a scene wall (unit-sphere units) a relief patch still counts as on it: the
// published Cornell box's red wall bends by 3.2 mm over 559 mm (0.6%).
constexpr double PlaneExtentTolerance = 0.01;
// How far in front of a scene wall (unit-sphere units, 5% of the scene radius) a relief patch
// still counts as mounted on it (ReliefSurfaceFromTriangles).
constexpr double MountTolerance = 0.05;

std::string Quoted(const std::string& text)
{
  return "'" + text + "'";
}
} // namespace

glm::dvec3 ReliefSurface::TextureOf(const glm::dvec3& point) const
{
  const glm::dmat3 m(this->AxisU, this->AxisV, this->Normal);
  return glm::inverse(m) * (point - this->Origin);
}

namespace
{
// Whether p lies inside the triangle (either winding; on an edge counts).
bool InTriangle(const glm::dvec2& p, const glm::dvec2 (&t)[3])
{
  const auto side = [](const glm::dvec2& a, const glm::dvec2& b, const glm::dvec2& q)
  { return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x); };
  const double d0 = side(t[0], t[1], p), d1 = side(t[1], t[2], p), d2 = side(t[2], t[0], p);
  return (d0 >= 0.0 && d1 >= 0.0 && d2 >= 0.0) || (d0 <= 0.0 && d1 <= 0.0 && d2 <= 0.0);
}

// Points on a patch, in its texture coordinates: the centres of a 16 x 16 grid over its bounds
// that lie on one of its triangles (where scene surfaces under it are looked for).
std::vector<glm::dvec2> PatchSamples(const ReliefSurface& surface,
  const std::vector<glm::vec3>& positions, const std::vector<glm::uvec3>& triangles)
{
  std::vector<std::array<glm::dvec2, 3>> flat;
  glm::dvec2 low(1e30), high(-1e30);
  for (const glm::uvec3& t : triangles)
  {
    std::array<glm::dvec2, 3> uv;
    for (std::size_t c = 0; c < 3; ++c)
    {
      uv[c] = glm::dvec2(surface.TextureOf(glm::dvec3(positions[t[static_cast<int>(c)]])));
      low = glm::min(low, uv[c]);
      high = glm::max(high, uv[c]);
    }
    flat.push_back(uv);
  }
  constexpr int grid = 16;
  std::vector<glm::dvec2> samples;
  for (int j = 0; j < grid; ++j)
  {
    for (int i = 0; i < grid; ++i)
    {
      const glm::dvec2 p = low + (high - low) * glm::dvec2((i + 0.5) / grid, (j + 0.5) / grid);
      for (const auto& uv : flat)
      {
        const glm::dvec2 corners[3] = { uv[0], uv[1], uv[2] };
        if (InTriangle(p, corners))
        {
          samples.push_back(p);
          break;
        }
      }
    }
  }
  return samples;
}

// The texture frame of surface.Triangles of `scene` (FindReliefSurface and
// ReliefSurfaceFromTriangles); `name` is how messages call the surface.
void FitTextureFrame(const TriangleMesh& scene, const std::string& name, ReliefSurface& surface)
{
  const std::vector<std::size_t>& triangles = surface.Triangles;
  // The plane and the plane rule's texture frame (SurfacePlaneOf, shared with `trace --relief`'s
  // dense mesh); the frame is replaced by the texture coordinates' own when the scene has them.
  SurfacePlane plane;
  try
  {
    plane = SurfacePlaneOf(scene, triangles, "surface " + Quoted(name));
  }
  catch (const SurfaceReliefError& e)
  {
    throw ReliefSurfaceError(e.what());
  }
  const bool tcoords =
    scene.TextureCoordinates.size() == scene.Positions.size() && !scene.TextureCoordinates.empty();
  surface.Normal = glm::dvec3(plane.Normal);
  surface.SceneTextureCoordinates = tcoords;
  if (tcoords)
  {
    // The affine map of the first triangle, checked against every point of the surface.
    const glm::uvec3 tri = scene.Triangles[triangles[0]];
    const glm::dvec3 a(scene.Positions[tri[0]]), b(scene.Positions[tri[1]]),
      c(scene.Positions[tri[2]]);
    const glm::dvec2 ta(scene.TextureCoordinates[tri[0]]), tb(scene.TextureCoordinates[tri[1]]),
      tc(scene.TextureCoordinates[tri[2]]);
    const double du1 = tb.x - ta.x, dv1 = tb.y - ta.y, du2 = tc.x - ta.x, dv2 = tc.y - ta.y;
    const double det = du1 * dv2 - du2 * dv1;
    if (!(std::abs(det) > 1e-12))
    {
      throw ReliefSurfaceError("surface " + Quoted(name) +
        " has degenerate texture coordinates (a triangle maps to a line)");
    }
    surface.AxisU = ((b - a) * dv2 - (c - a) * dv1) / det;
    surface.AxisV = ((c - a) * du1 - (b - a) * du2) / det;
    surface.Origin = a - ta.x * surface.AxisU - ta.y * surface.AxisV;
    // A point may lie off the affine map as far as the plane allows it off the plane (twice:
    // the map's triangle may be off the other way), plus 1e-3 unit-sphere radii for the rounding
    // of the file's written coordinates.
    const double slack =
      2.0 * SurfacePlanarTolerance * glm::length(glm::dvec3(plane.AxisU + plane.AxisV)) + 1e-3;
    for (const std::size_t t : triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t v = scene.Triangles[t][k];
        const glm::dvec2 uv(scene.TextureCoordinates[v]);
        if (glm::length(surface.Point(uv.x, uv.y) - glm::dvec3(scene.Positions[v])) > slack)
        {
          throw ReliefSurfaceError("the texture coordinates of surface " + Quoted(name) +
            " are not one affine map of its plane; give it planar, undistorted (vt) coordinates "
            "or none (then its plane gives them)");
        }
      }
    }
    return;
  }
  surface.Origin = glm::dvec3(plane.Origin);
  surface.AxisU = glm::dvec3(plane.AxisU);
  surface.AxisV = glm::dvec3(plane.AxisV);
}

} // namespace

ReliefSurface FindReliefSurface(const LightField& field, const std::string& name)
{
  const TriangleScene& scene = field.Scene();
  ReliefSurface surface;
  surface.Name = name;
  try
  {
    surface.Triangles = SurfaceTriangles(scene, name);
  }
  catch (const SceneSurfaceError& e)
  {
    throw ReliefSurfaceError(e.what());
  }
  const SceneMaterial& material = scene.MaterialOf(surface.Triangles[0]);
  if (glm::length(material.Specular) > 0.0f)
  {
    throw ReliefSurfaceError("surface " + Quoted(name) + " is a mirror (material " +
      Quoted(material.Name) + ", Ks > 0): reliefs are diffuse so far");
  }
  surface.Diffuse = material.Diffuse;
  surface.Emission = material.Emission;
  surface.FieldSurface = field.SurfaceOfTriangle(surface.Triangles[0]);

  FitTextureFrame(scene, name, surface);
  return surface;
}

ReliefSurface ReliefSurfaceFromTriangles(const LightField& field,
  const std::vector<glm::vec3>& positions, const std::vector<glm::vec2>& textureCoordinates,
  const std::vector<glm::uvec3>& triangles, const std::string& name)
{
  if (triangles.empty())
  {
    throw ReliefSurfaceError(Quoted(name) + " has no triangles to carry a relief");
  }
  TriangleMesh mesh;
  mesh.Positions = positions;
  mesh.Triangles = triangles;
  if (textureCoordinates.size() == positions.size())
  {
    mesh.TextureCoordinates = textureCoordinates;
  }
  for (const glm::uvec3& t : triangles)
  {
    if (std::max({ t.x, t.y, t.z }) >= positions.size())
    {
      throw std::invalid_argument("a relief surface's triangle names a point it does not have");
    }
  }
  ReliefSurface surface;
  surface.Name = name;
  surface.FieldSurface = NoSurface;
  surface.Triangles.resize(triangles.size());
  for (std::size_t t = 0; t < triangles.size(); ++t)
  {
    surface.Triangles[t] = t;
  }
  FitTextureFrame(mesh, name, surface);

  // The scene surface it lies on, facing the same way (a patch on a wall): the probes then
  // ignore that wall's crossing as they do for the wall itself, and its material is the
  // surface's. A relief's depth lies behind its plane, so a patch mounted on a wall stands in
  // front of it by that depth: up to MountTolerance of the scene radius; the nearest such
  // surface's bounds.
  glm::dvec3 centroid(0.0), lower(1e30), upper(-1e30);
  for (const glm::vec3& p : positions)
  {
    centroid += glm::dvec3(p) / static_cast<double>(positions.size());
    lower = glm::min(lower, glm::dvec3(p));
    upper = glm::max(upper, glm::dvec3(p));
  }
  const double planeTolerance = MountTolerance;
  double nearest = 1e30;
  const TriangleScene& scene = field.Scene();
  std::vector<std::uint32_t> overlapped; // mounting candidates under some of the patch
  const std::vector<glm::dvec2> samples = PatchSamples(surface, positions, triangles);
  for (std::uint32_t s = 0; s < field.Surfaces().size(); ++s)
  {
    const Surface& candidate = field.Surfaces()[s];
    const glm::dvec3 n(candidate.Normal);
    if (glm::dot(n, surface.Normal) < 0.999 ||
      glm::dot(n, centroid) - static_cast<double>(candidate.Offset) > planeTolerance ||
      glm::dot(n, centroid) - static_cast<double>(candidate.Offset) < -PlaneExtentTolerance)
    {
      continue;
    }
    glm::dvec3 low(1e30), high(-1e30);
    bool under = false;
    for (const std::uint32_t t : candidate.Triangles)
    {
      glm::dvec2 uv[3];
      for (int c = 0; c < 3; ++c)
      {
        const glm::dvec3 p(scene.Vertex(t, c));
        low = glm::min(low, p);
        high = glm::max(high, p);
        uv[c] = glm::dvec2(surface.TextureOf(p));
      }
      for (std::size_t k = 0; k < samples.size() && !under; ++k)
      {
        under = InTriangle(samples[k], uv);
      }
    }
    const double distance = glm::length(centroid - glm::clamp(centroid, low, high));
    if (distance < nearest)
    {
      nearest = distance;
      surface.FieldSurface = s;
    }
    if (under)
    {
      overlapped.push_back(s);
    }
  }
  if (surface.FieldSurface != NoSurface)
  {
    const SceneMaterial& material = field.MaterialOf(surface.FieldSurface);
    surface.Diffuse = material.Diffuse;
    surface.Emission = material.Emission;
    for (const std::uint32_t s : overlapped)
    {
      const SceneMaterial& other = field.MaterialOf(s);
      const bool same =
        glm::all(glm::lessThan(glm::abs(other.Diffuse - material.Diffuse), glm::vec3(1e-3f))) &&
        glm::all(glm::lessThan(glm::abs(other.Emission - material.Emission), glm::vec3(1e-3f)));
      if (!same &&
        std::find(surface.OtherMaterials.begin(), surface.OtherMaterials.end(), other.Name) ==
          surface.OtherMaterials.end())
      {
        surface.OtherMaterials.push_back(other.Name);
      }
    }
  }
  return surface;
}

glm::vec3 ReliefProbePoint(const ReliefSurface& surface, int i, int j, int probesU, int probesV)
{
  const double u = (i + 0.5) / probesU;
  const double v = (j + 0.5) / probesV;
  return glm::vec3(surface.Point(u, v) + 1e-3 * surface.Normal);
}

int ReliefProbesPerSide(const LightField& field, const ReliefSurface& surface, int requested)
{
  if (requested > 0)
  {
    return requested;
  }
  const double side = std::max(glm::length(surface.AxisU), glm::length(surface.AxisV));
  const double cells = std::ceil(2.0 * side / static_cast<double>(field.Settings().CellSize()));
  return std::isfinite(cells)
    ? static_cast<int>(std::clamp(cells, static_cast<double>(DefaultReliefProbesPerSide),
        static_cast<double>(MaximumAutomaticReliefProbesPerSide)))
    : DefaultReliefProbesPerSide;
}

std::vector<SH9> ReliefSurfaceProbes(const LightField& field, const ReliefSurface& surface,
  int probesU, int probesV, const ProgressCallback& progress)
{
  if (probesU < 1 || probesV < 1)
  {
    throw std::invalid_argument("a relief needs at least one irradiance probe per side");
  }
  std::vector<SH9> probes(static_cast<std::size_t>(probesU) * static_cast<std::size_t>(probesV));
  IncidentOptions incident;
  incident.Ignore = surface.FieldSurface;
  incident.Emission = false;
  for (int j = 0; j < probesV; ++j)
  {
    if (!ReportProgress(progress, static_cast<double>(j) / probesV))
    {
      throw AbortedError();
    }
    ParallelFor(0, static_cast<std::size_t>(probesU), 1,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t i = begin; i < end; ++i)
        {
          const glm::vec3 p = ReliefProbePoint(surface, static_cast<int>(i), j, probesU, probesV);
          probes[static_cast<std::size_t>(j) * probesU + i] =
            ProjectIncidentSH9(IncidentRadianceSamples(field, p, incident));
        }
      });
  }
  ReportProgress(progress, 1.0);
  return probes;
}

} // namespace vlf
} // namespace mesolight
