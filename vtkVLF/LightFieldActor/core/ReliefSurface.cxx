// SPDX-License-Identifier: BSD-3-Clause
#include "ReliefSurface.h"

#include "FieldIrradiance.h"
#include "LightField.h"
#include "ParallelFor.h"
#include "SurfaceRelief.h" // SurfacePlaneOf
#include "TriangleScene.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>
#include <glm/vec2.hpp>

#include <cmath>

namespace mesolight
{
namespace vlf
{
namespace
{
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
  const std::vector<std::size_t>& triangles = surface.Triangles;
  const SceneMaterial& material = scene.MaterialOf(triangles[0]);
  if (glm::length(material.Specular) > 0.0f)
  {
    throw ReliefSurfaceError("surface " + Quoted(name) + " is a mirror (material " +
      Quoted(material.Name) + ", Ks > 0): reliefs are diffuse so far");
  }
  surface.Diffuse = material.Diffuse;
  surface.Emission = material.Emission;
  surface.FieldSurface = field.SurfaceOfTriangle(triangles[0]);

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
    return surface;
  }
  surface.Origin = glm::dvec3(plane.Origin);
  surface.AxisU = glm::dvec3(plane.AxisU);
  surface.AxisV = glm::dvec3(plane.AxisV);
  return surface;
}

glm::vec3 ReliefProbePoint(const ReliefSurface& surface, int i, int j, int probesU, int probesV)
{
  const double u = (i + 0.5) / probesU;
  const double v = (j + 0.5) / probesV;
  return glm::vec3(surface.Point(u, v) + 1e-3 * surface.Normal);
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
          const glm::vec3 p =
            ReliefProbePoint(surface, static_cast<int>(i), j, probesU, probesV);
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
