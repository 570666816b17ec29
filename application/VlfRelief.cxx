// SPDX-License-Identifier: BSD-3-Clause
#include "VlfRelief.h"

#include "EmbreeScene.h"
#include "FieldIrradiance.h"
#include "LightField.h"
#include "MathConstants.h"
#include "ReliefOcclusion.h" // EmitterSamples
#include "ReliefSurface.h"
#include "TraceRelief.h"
#include "TriangleScene.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <memory>
#include <sstream>

namespace mesolight
{
namespace
{
std::string Quoted(const std::string& text)
{
  return "'" + text + "'";
}
} // namespace

HeightField ReadDepthImage(const std::string& path, bool isHeight, bool normalize)
{
  // The depths exactly as the path tracer's dense mesh (trace --relief) and the relief mapper
  // read them: the same reader and relief filter, so NaN, out-of-range values, signed elevations
  // and a GeoTIFF's no-data value are handled, or refused with the filter's message, alike.
  std::vector<float> depth;
  int width = 0;
  int height = 0;
  std::string error;
  if (!ReadDepthMapImage(path, isHeight, normalize, depth, width, height, error))
  {
    throw ReliefSetupError("--relief: depth image " + Quoted(path) + ": " + error);
  }
  // A relief on a surface of the scene is recessed into it: walled at its texture rectangle's
  // border, as the path tracer's dense mesh closes it (docs/relief-against-path-tracer.md).
  return HeightField(width, height, std::move(depth), HeightField::Edge::Walled);
}

std::string ReliefProbesHelp()
{
  return "SH9 probes per side of each relief's texture (the scene's shadows and indirect light "
         "on it); 0: one per field line cell across the surface, " +
    std::to_string(vlf::DefaultReliefProbesPerSide) + " to " +
    std::to_string(vlf::MaximumAutomaticReliefProbesPerSide);
}

std::vector<FieldRelief> SetUpFieldReliefs(const vlf::LightField& field, const EmbreeScene& embree,
  const std::vector<std::string>& items, const FieldReliefOptions& options)
{
  const TriangleScene& scene = field.Scene();
  if (!options.KnownProbes.empty() && options.KnownProbes.size() != items.size())
  {
    throw std::invalid_argument("SetUpFieldReliefs: KnownProbes must hold the probes of every "
                                "item");
  }
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
    vlf::ReliefSurface surface;
    try
    {
      surface = vlf::FindReliefSurface(field, relief.Name);
    }
    catch (const vlf::ReliefSurfaceError& e)
    {
      throw ReliefSetupError(std::string("--relief: ") + e.what());
    }
    relief.Height =
      ReadDepthImage(relief.DepthImage, options.DepthIsHeight, options.NormalizeDepth);
    relief.Frame.Origin = surface.Origin;
    relief.Frame.AxisU = surface.AxisU;
    relief.Frame.AxisV = surface.AxisV;
    relief.Frame.Normal = surface.Normal;
    relief.Frame.DepthScale = options.DepthScale;
    relief.Albedo = surface.Diffuse;
    relief.Emission = surface.Emission;
    const SceneMaterial& material = scene.MaterialOf(surface.Triangles[0]);
    // Indirect: SH9 probes just in front of the macro surface (vlf::ReliefSurfaceProbes, the
    // walkthrough's relief mapper takes the same), the emitters' own radiance left out (the
    // emitter samples below carry it).
    ReliefLighting& lighting = relief.Lighting;
    const int n = vlf::ReliefProbesPerSide(field, surface, options.Probes);
    lighting.ProbesU = lighting.ProbesV = n;
    if (options.KnownProbes.empty())
    {
      lighting.Probes = vlf::ReliefSurfaceProbes(field, surface, n, n);
    }
    else if (options.KnownProbes[reliefs.size()].size() == static_cast<std::size_t>(n) * n)
    {
      lighting.Probes = options.KnownProbes[reliefs.size()];
    }
    else
    {
      throw std::invalid_argument("SetUpFieldReliefs: KnownProbes of " + Quoted(relief.Name) +
        " are not Probes x Probes (ReliefProbesPerSide)");
    }
    // The light the relief reflects onto itself (ReliefLighting::Albedo).
    relief.Lighting.Albedo = glm::dvec3(material.Diffuse);
    // Direct: the field's emitters, the scene's occlusion by Embree.
    lighting.Emitters = vlf::EmitterSamples(scene, std::max(1, options.EmitterSamplesPerSide));
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
