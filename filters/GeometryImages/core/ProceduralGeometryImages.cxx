// SPDX-License-Identifier: BSD-3-Clause
#include "ProceduralGeometryImages.h"

#include "MathConstants.h"

#include <cmath>
#include <sstream>
#include <stdexcept>

namespace mesolight
{
namespace
{
constexpr double CylinderSpan = 2.0 * Pi<double> / 3.0; // 120 degrees
constexpr double SphereSpan = 0.5 * Pi<double>;         // 90 degrees each way
constexpr double WaveAmplitude = 0.06;
constexpr double WavePeriods = 2.0;
constexpr double BumpHeight = 0.2;
constexpr double BumpSigma = 0.12;

glm::dvec3 HeightNormal(double dzdu, double dzdv)
{
  return glm::normalize(glm::dvec3(-dzdu, -dzdv, 1.0));
}
} // namespace

//------------------------------------------------------------------------------
GeometrySurface GeometrySurfaceFromName(const std::string& name)
{
  for (GeometrySurface s : { GeometrySurface::Plane, GeometrySurface::Cylinder,
         GeometrySurface::SpherePatch, GeometrySurface::Wave, GeometrySurface::Bump })
  {
    if (name == GeometrySurfaceName(s))
    {
      return s;
    }
  }
  throw std::invalid_argument(
    "unknown surface '" + name + "' (" + std::string(GeometrySurfaceNames()) + ")");
}

//------------------------------------------------------------------------------
const char* GeometrySurfaceName(GeometrySurface surface)
{
  switch (surface)
  {
    case GeometrySurface::Plane:
      return "plane";
    case GeometrySurface::Cylinder:
      return "cylinder";
    case GeometrySurface::SpherePatch:
      return "sphere";
    case GeometrySurface::Wave:
      return "wave";
    case GeometrySurface::Bump:
      return "bump";
  }
  return "plane";
}

//------------------------------------------------------------------------------
const char* GeometrySurfaceNames()
{
  return "plane|cylinder|sphere|wave|bump";
}

//------------------------------------------------------------------------------
glm::dvec3 SurfacePoint(GeometrySurface surface, double u, double v, glm::dvec3* normal)
{
  glm::dvec3 p(u, v, 0.0);
  glm::dvec3 n(0.0, 0.0, 1.0);
  switch (surface)
  {
    case GeometrySurface::Plane:
      break;
    case GeometrySurface::Cylinder:
    {
      // Arc length 1 across: radius 1 / span.
      const double r = 1.0 / CylinderSpan;
      const double phi = (u - 0.5) * CylinderSpan;
      p = glm::dvec3(0.5 + r * std::sin(phi), v, r * std::cos(phi) - r);
      n = glm::dvec3(std::sin(phi), 0.0, std::cos(phi));
      break;
    }
    case GeometrySurface::SpherePatch:
    {
      const double r = 1.0 / SphereSpan;
      const double phi = (u - 0.5) * SphereSpan;
      const double theta = (v - 0.5) * SphereSpan;
      n = glm::dvec3(
        std::cos(theta) * std::sin(phi), std::sin(theta), std::cos(theta) * std::cos(phi));
      p = glm::dvec3(0.5, 0.5, -r) + r * n;
      break;
    }
    case GeometrySurface::Wave:
    {
      const double k = 2.0 * Pi<double> * WavePeriods;
      p.z = WaveAmplitude * (std::cos(k * u) - 1.0);
      n = HeightNormal(-WaveAmplitude * k * std::sin(k * u), 0.0);
      break;
    }
    case GeometrySurface::Bump:
    {
      const double du = u - 0.5, dv = v - 0.5;
      const double g = std::exp(-(du * du + dv * dv) / (2.0 * BumpSigma * BumpSigma));
      p.z = BumpHeight * (g - 1.0);
      const double s = -BumpHeight * g / (BumpSigma * BumpSigma);
      n = HeightNormal(s * du, s * dv);
      break;
    }
  }
  if (normal)
  {
    *normal = n;
  }
  return p;
}

//------------------------------------------------------------------------------
GeometryImage MakeGeometryImage(GeometrySurface surface, int width, int height)
{
  GeometryImage image;
  image.Width = std::max(0, width);
  image.Height = std::max(0, height);
  const size_t n = static_cast<size_t>(image.Width) * image.Height;
  image.Positions.resize(n);
  image.Normals.resize(n);
  for (int j = 0; j < image.Height; ++j)
  {
    for (int i = 0; i < image.Width; ++i)
    {
      const size_t k = image.Index(i, j);
      image.Positions[k] = SurfacePoint(
        surface, TexelCentre(i, image.Width), TexelCentre(j, image.Height), &image.Normals[k]);
    }
  }
  return image;
}

//------------------------------------------------------------------------------
GeometryImage DisplaceGeometryImage(
  const GeometryImage& surface, const std::vector<float>& depth, double depthScale)
{
  const size_t n = static_cast<size_t>(surface.Width) * surface.Height;
  if (surface.Width < 2 || surface.Height < 2 || surface.Positions.size() != n)
  {
    throw GeometryImageMeshError("the geometry image must be at least 2 x 2 pixels");
  }
  if (depth.size() != n)
  {
    std::ostringstream s;
    s << "the depth map has " << depth.size() << " values; the " << surface.Width << " x "
      << surface.Height << " geometry image needs one per pixel";
    throw GeometryImageMeshError(s.str());
  }
  const std::vector<glm::dvec3> geometric = GeometryNormals(surface);
  GeometryImage displaced;
  displaced.Width = surface.Width;
  displaced.Height = surface.Height;
  displaced.Positions = surface.Positions;
  const int w = surface.Width;
  for (int j = 0; j < surface.Height; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      if (!surface.Valid(i, j))
      {
        continue;
      }
      const size_t k = surface.Index(i, j);
      glm::dvec3 normal = surface.Normals.empty() ? geometric[k] : surface.Normals[k];
      if (!(glm::length(normal) > 0.0))
      {
        normal = geometric[k];
      }
      if (!(glm::length(normal) > 0.0))
      {
        continue;
      }
      normal = glm::normalize(normal);
      // dP/du in world units per u unit (the image spans u in [0, 1] over W pixels).
      const bool left = i > 0 && surface.Valid(i - 1, j);
      const bool right = i + 1 < w && surface.Valid(i + 1, j);
      glm::dvec3 dPdu(0.0);
      if (left && right)
      {
        dPdu = (surface.At(i + 1, j) - surface.At(i - 1, j)) * (0.5 * w);
      }
      else if (right)
      {
        dPdu = (surface.At(i + 1, j) - surface.At(i, j)) * static_cast<double>(w);
      }
      else if (left)
      {
        dPdu = (surface.At(i, j) - surface.At(i - 1, j)) * static_cast<double>(w);
      }
      const double su = glm::length(dPdu - normal * glm::dot(normal, dPdu));
      displaced.Positions[k] -= normal * (static_cast<double>(depth[k]) * depthScale * su);
    }
  }
  return displaced;
}

} // namespace mesolight
