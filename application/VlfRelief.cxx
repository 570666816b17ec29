// SPDX-License-Identifier: BSD-3-Clause
#include "VlfRelief.h"

#include "EmbreeScene.h"
#include "FieldIrradiance.h"
#include "ImageFile.h"
#include "LightField.h"
#include "MathConstants.h"
#include "ParallelFor.h"
#include "TriangleScene.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <memory>
#include <sstream>

namespace mesolight
{
namespace
{
// Points this far off a surface's plane (unit-sphere units, the field's own plane tolerance)
// make it non-planar, unless within PlaneExtentTolerance of its extent: the published Cornell
// box's red wall bends by 3.2 mm over 559 mm (0.6%), which the relief's macro plane (through the
// points' centroid) leaves at most 1.6 mm off, far below a relief's depth.
constexpr float PlaneTolerance = 1e-4f;
constexpr double PlaneExtentTolerance = 0.01;

std::string Quoted(const std::string& text)
{
  return "'" + text + "'";
}

// The texture frame of a planar surface: from its texture coordinates when the scene has them
// (one affine map of the plane), else from its plane (u along the plane's horizontal, v up it,
// the bounding rectangle of its points mapped to [0, 1]^2).
ReliefFrame SurfaceFrame(
  const TriangleScene& scene, const std::vector<std::size_t>& triangles, const std::string& name)
{
  glm::dvec3 normal(0.0);
  for (const std::size_t t : triangles)
  {
    normal += glm::dvec3(scene.FaceNormal(t));
  }
  if (!(glm::length(normal) > 0.0))
  {
    throw ReliefSetupError("surface " + Quoted(name) + " has no area");
  }
  normal = glm::normalize(normal);
  glm::dvec3 p0(0.0), lower(1e30), upper(-1e30);
  for (const std::size_t t : triangles)
  {
    for (int c = 0; c < 3; ++c)
    {
      const glm::dvec3 p(scene.Vertex(t, c));
      p0 += p / (3.0 * static_cast<double>(triangles.size()));
      lower = glm::min(lower, p);
      upper = glm::max(upper, p);
    }
  }
  double off = 0.0;
  for (const std::size_t t : triangles)
  {
    for (int c = 0; c < 3; ++c)
    {
      off = std::max(off, std::abs(glm::dot(normal, glm::dvec3(scene.Vertex(t, c)) - p0)));
    }
  }
  const bool tcoords =
    scene.TextureCoordinates.size() == scene.Positions.size() && !scene.TextureCoordinates.empty();
  const double allowed =
    std::max<double>(PlaneTolerance, PlaneExtentTolerance * glm::length(upper - lower));
  if (off > allowed)
  {
    std::ostringstream message;
    message << "surface " << Quoted(name) << " is not planar (its points lie up to " << off
            << " scene radii off its plane): a relief needs a planar surface"
            << (tcoords ? "" : " or texture coordinates")
            << "; split it into planar surfaces with their own `g` names in the OBJ file";
    if (!tcoords)
    {
      message << ", or give it texture coordinates (vt) on planar pieces";
    }
    throw ReliefSetupError(message.str());
  }
  ReliefFrame frame;
  frame.Normal = normal;
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
      throw ReliefSetupError("surface " + Quoted(name) +
        " has degenerate texture coordinates (a triangle maps to a line)");
    }
    frame.AxisU = ((b - a) * dv2 - (c - a) * dv1) / det;
    frame.AxisV = ((c - a) * du1 - (b - a) * du2) / det;
    frame.Origin = a - ta.x * frame.AxisU - ta.y * frame.AxisV;
    for (const std::size_t t : triangles)
    {
      for (int k = 0; k < 3; ++k)
      {
        const std::uint32_t v = scene.Triangles[t][k];
        const glm::dvec2 uv(scene.TextureCoordinates[v]);
        if (glm::length(frame.Point(uv.x, uv.y, 0.0) - glm::dvec3(scene.Positions[v])) >
          2.0 * allowed + 10.0 * PlaneTolerance)
        {
          throw ReliefSetupError("the texture coordinates of surface " + Quoted(name) +
            " are not one affine map of its plane; give it planar, undistorted (vt) coordinates "
            "or none (then its plane gives them)");
        }
      }
    }
    return frame;
  }
  const glm::dvec3 helper = std::abs(normal.y) < 0.9 ? glm::dvec3(0, 1, 0) : glm::dvec3(0, 0, 1);
  const glm::dvec3 v = glm::normalize(helper - normal * glm::dot(normal, helper));
  const glm::dvec3 u = glm::cross(v, normal);
  double lowU = 1e30, highU = -1e30, lowV = 1e30, highV = -1e30;
  for (const std::size_t t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const glm::dvec3 p = glm::dvec3(scene.Vertex(t, k)) - p0;
      lowU = std::min(lowU, glm::dot(p, u));
      highU = std::max(highU, glm::dot(p, u));
      lowV = std::min(lowV, glm::dot(p, v));
      highV = std::max(highV, glm::dot(p, v));
    }
  }
  frame.Origin = p0 + lowU * u + lowV * v;
  frame.AxisU = (highU - lowU) * u;
  frame.AxisV = (highV - lowV) * v;
  return frame;
}

// n x n stratified samples of every emitting triangle (Shirley's square-to-triangle map).
std::vector<ReliefEmitterSample> EmitterSamples(const TriangleScene& scene, int n)
{
  std::vector<ReliefEmitterSample> samples;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const glm::vec3 ke = scene.MaterialOf(t).Emission;
    const double area = scene.Area(t);
    if (!(ke.x + ke.y + ke.z > 0.0f) || !(area > 0.0))
    {
      continue;
    }
    const glm::dvec3 a(scene.Vertex(t, 0)), b(scene.Vertex(t, 1)), c(scene.Vertex(t, 2));
    const glm::dvec3 normal = glm::normalize(glm::dvec3(scene.FaceNormal(t)));
    for (int i = 0; i < n; ++i)
    {
      for (int j = 0; j < n; ++j)
      {
        const double s = (i + 0.5) / n, r = std::sqrt((j + 0.5) / n);
        ReliefEmitterSample sample;
        sample.Position = (1.0 - r) * a + r * (1.0 - s) * b + r * s * c;
        sample.Normal = normal;
        sample.RadianceArea = glm::dvec3(ke) * (area / (n * n));
        samples.push_back(sample);
      }
    }
  }
  return samples;
}
} // namespace

HeightField ReadDepthImage(const std::string& path)
{
  try
  {
    const ImageFileInfo info = ReadImageFileInfo(path, std::int64_t(1) << 30);
    std::vector<unsigned char> bytes(static_cast<std::size_t>(info.ByteSize()));
    ReadImageFilePixels(path, info, bytes.data());
    const std::size_t count = static_cast<std::size_t>(info.Width) * info.Height;
    std::vector<float> depth(count);
    for (std::size_t p = 0; p < count; ++p)
    {
      const std::size_t index = p * static_cast<std::size_t>(info.Channels);
      float value = 0.0f;
      switch (info.Type)
      {
        case ImageSampleType::UInt8:
          value = bytes[index] / 255.0f;
          break;
        case ImageSampleType::UInt16:
        {
          std::uint16_t v;
          std::memcpy(&v, &bytes[index * 2], 2);
          value = v / 65535.0f;
          break;
        }
        case ImageSampleType::Float:
          std::memcpy(&value, &bytes[index * 4], 4);
          break;
      }
      if (!std::isfinite(value))
      {
        throw ReliefSetupError("depth image " + Quoted(path) + " has a pixel that is not a number");
      }
      depth[p] = std::clamp(value, 0.0f, 1.0f);
    }
    return HeightField(info.Width, info.Height, std::move(depth));
  }
  catch (const ImageFileError& e)
  {
    throw ReliefSetupError(std::string("--relief: ") + e.what());
  }
}

std::vector<FieldRelief> SetUpFieldReliefs(const vlf::LightField& field, const EmbreeScene& embree,
  const std::vector<std::string>& items, const FieldReliefOptions& options)
{
  const TriangleScene& scene = field.Scene();
  std::vector<FieldRelief> reliefs;
  for (const std::string& item : items)
  {
    const std::size_t equals = item.find('=');
    if (equals == std::string::npos || equals == 0 || equals + 1 == item.size())
    {
      throw ReliefSetupError("--relief " + Quoted(item) +
        ": give SURFACE=DEPTH_IMAGE (the field's surfaces: " + SurfaceNameList(scene) + ")");
    }
    FieldRelief relief;
    relief.Name = item.substr(0, equals);
    relief.DepthImage = item.substr(equals + 1);
    for (const FieldRelief& other : reliefs)
    {
      if (other.Name == relief.Name)
      {
        throw ReliefSetupError("--relief names surface " + Quoted(relief.Name) + " twice");
      }
    }
    std::vector<std::size_t> triangles;
    try
    {
      triangles = SurfaceTriangles(scene, relief.Name);
    }
    catch (const SceneSurfaceError& e)
    {
      throw ReliefSetupError(std::string("--relief: ") + e.what());
    }
    relief.Height = ReadDepthImage(relief.DepthImage);
    relief.Frame = SurfaceFrame(scene, triangles, relief.Name);
    relief.Frame.DepthScale = options.DepthScale;
    const SceneMaterial& material = scene.MaterialOf(triangles[0]);
    if (glm::length(material.Specular) > 0.0f)
    {
      throw ReliefSetupError("surface " + Quoted(relief.Name) + " is a mirror (material " +
        Quoted(material.Name) + ", Ks > 0): reliefs are diffuse so far");
    }
    relief.Albedo = material.Diffuse;
    relief.Emission = scene.MaterialOf(triangles[0]).Emission;
    // Indirect: SH9 probes just in front of the macro surface, the wall's own crossing ignored
    // and the emitters' own radiance left out (the emitter samples below carry it).
    const int n = std::max(1, options.Probes);
    relief.Lighting.ProbesU = relief.Lighting.ProbesV = n;
    relief.Lighting.Probes.resize(static_cast<std::size_t>(n) * n);
    vlf::IncidentOptions incident;
    incident.Ignore = field.SurfaceOfTriangle(triangles[0]);
    incident.Emission = false;
    const ReliefFrame frame = relief.Frame;
    ReliefLighting& lighting = relief.Lighting;
    ParallelFor(0, lighting.Probes.size(), 1,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t q = begin; q < end; ++q)
        {
          const double u = (static_cast<double>(q % n) + 0.5) / n;
          const double v = (static_cast<double>(q / n) + 0.5) / n;
          const glm::vec3 p(frame.Point(u, v, 0.0) + 1e-3 * frame.Normal);
          lighting.Probes[q] =
            vlf::ProjectIncidentSH9(vlf::IncidentRadianceSamples(field, p, incident));
        }
      });
    // The light the relief reflects onto itself (ReliefLighting::Albedo).
    relief.Lighting.Albedo = glm::dvec3(material.Diffuse);
    // Direct: the field's emitters, the scene's occlusion by Embree.
    lighting.Emitters = EmitterSamples(scene, std::max(1, options.EmitterSamplesPerSide));
    const EmbreeScene* occluders = &embree;
    lighting.SceneVisible = [occluders](const glm::dvec3& from, const glm::dvec3& to)
    {
      const glm::dvec3 d = to - from;
      const double length = glm::length(d);
      SceneRay ray;
      ray.Origin = glm::vec3(from);
      ray.Direction = glm::vec3(d / length);
      ray.TNear = 1e-4f;
      ray.TFar = static_cast<float>(length * (1.0 - 1e-4));
      return !occluders->Occluded(ray);
    };
    reliefs.push_back(std::move(relief));
  }
  return reliefs;
}

std::vector<int> ReliefOfTriangle(
  const vlf::LightField& field, const std::vector<FieldRelief>& reliefs)
{
  std::vector<int> of(field.Scene().TriangleCount(), -1);
  for (std::size_t r = 0; r < reliefs.size(); ++r)
  {
    for (const std::size_t t : SurfaceTriangles(field.Scene(), reliefs[r].Name))
    {
      of[t] = static_cast<int>(r);
    }
  }
  return of;
}

bool ReliefRadiance(
  const FieldRelief& relief, const glm::vec3& origin, const glm::vec3& dir, glm::vec3& radiance)
{
  const auto shade = ShadeReliefRay(
    relief.Height, relief.Frame, relief.Lighting, glm::dvec3(origin), glm::dvec3(dir));
  if (!shade)
  {
    return false;
  }
  radiance =
    relief.Emission + relief.Albedo * glm::vec3((shade->Indirect + shade->Direct) / Pi<double>);
  return true;
}

} // namespace mesolight
