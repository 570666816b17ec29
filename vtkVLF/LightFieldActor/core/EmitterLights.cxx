// SPDX-License-Identifier: BSD-3-Clause
#include "EmitterLights.h"

#include "LightField.h"
#include "MathConstants.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vec3.hpp>

#include <algorithm>
#include <cmath>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>
#include <vector>

namespace mesolight
{
namespace vlf
{

namespace
{
// Sutherland-Hodgman: the part of a convex polygon (2D) with coordinate `axis` on the side
// `keepBelow` ? <= limit : >= limit.
std::vector<glm::dvec2> ClipPolygon(
  const std::vector<glm::dvec2>& polygon, int axis, double limit, bool keepBelow)
{
  std::vector<glm::dvec2> out;
  const std::size_t n = polygon.size();
  for (std::size_t i = 0; i < n; ++i)
  {
    const glm::dvec2& a = polygon[i];
    const glm::dvec2& b = polygon[(i + 1) % n];
    const bool inA = keepBelow ? a[axis] <= limit : a[axis] >= limit;
    const bool inB = keepBelow ? b[axis] <= limit : b[axis] >= limit;
    if (inA)
    {
      out.push_back(a);
    }
    if (inA != inB)
    {
      const double t = (limit - a[axis]) / (b[axis] - a[axis]);
      out.push_back(a + t * (b - a));
    }
  }
  return out;
}

// Area and area-weighted centroid sum (centroid x area) of a 2D polygon.
void PolygonMoments(const std::vector<glm::dvec2>& polygon, double& area, glm::dvec2& moment)
{
  area = 0.0;
  moment = glm::dvec2(0.0);
  for (std::size_t i = 1; i + 1 < polygon.size(); ++i)
  {
    const glm::dvec2 e1 = polygon[i] - polygon[0], e2 = polygon[i + 1] - polygon[0];
    const double a = 0.5 * std::abs(e1.x * e2.y - e1.y * e2.x);
    area += a;
    moment += a * (polygon[0] + polygon[i] + polygon[i + 1]) / 3.0;
  }
}

float Brightness(const EmitterLight& light)
{
  const glm::vec3 i = light.Intensity();
  return i.x + i.y + i.z;
}

// A cluster of lights for MergeEmitterLights: its members (indices), their positions' bounds,
// their brightness-weighted position and normal sums and a cone about the normal sum's direction
// that holds their normals (kept as clusters merge, so that a merge's cost takes constant time);
// with receivers, its lights' own irradiance at the receivers' points and the summed relative
// error of its one light there.
struct LightCluster
{
  std::vector<std::size_t> Members;
  glm::dvec3 Lower{ 0.0 }, Upper{ 0.0 };
  glm::dvec3 PositionSum{ 0.0 };
  glm::dvec3 NormalSum{ 0.0 };
  double Brightness = 0.0;
  double HalfAngle = 0.0; // radians, about Axis()
  std::vector<double> Exact;
  double Error = 0.0;
  glm::dvec3 Axis() const
  {
    const double length = glm::length(this->NormalSum);
    return length > 1e-12 ? this->NormalSum / length : glm::dvec3(0.0, 0.0, 1.0);
  }
};

// Where the merged lights will be seen, when the caller knows: the centres of an 8 x 8 grid over
// the receivers' parallelogram, their normal, and all the lights' irradiance at each point.
struct Receivers
{
  static constexpr int SamplesPerSide = 8;
  std::vector<glm::dvec3> Points;
  glm::dvec3 Normal{ 0.0, 0.0, 1.0 };
  std::vector<double> Total; // floored at a thousandth of the mean: a dark point weighs little
  bool Known() const { return !this->Points.empty(); }
};

// The unshadowed irradiance (in brightness units) at p, facing n, from a light of that brightness
// at `position` whose cosine lobe faces `normal`.
double LightIrradiance(const glm::dvec3& position, const glm::dvec3& normal, double brightness,
  const glm::dvec3& p, const glm::dvec3& n)
{
  const glm::dvec3 d = position - p;
  const double r2 = glm::dot(d, d);
  if (!(r2 > 1e-12))
  {
    return 0.0;
  }
  const glm::dvec3 w = d / std::sqrt(r2);
  return brightness * std::max(0.0, -glm::dot(w, normal)) * std::max(0.0, glm::dot(w, n)) / r2;
}

// The summed relative error at the receivers of one light standing for lights whose own
// irradiance there is `exact` (brightness-weighted position and normal sums, total brightness).
double ClusterError(const Receivers& receivers, const glm::dvec3& positionSum,
  const glm::dvec3& normalSum, double brightness, const std::vector<double>& exact,
  const std::vector<double>* more = nullptr)
{
  if (!(brightness > 0.0))
  {
    return 0.0;
  }
  const double length = glm::length(normalSum);
  const glm::dvec3 normal = length > 1e-12 ? normalSum / length : glm::dvec3(0.0);
  const glm::dvec3 position = positionSum / brightness;
  double error = 0.0;
  for (std::size_t k = 0; k < receivers.Points.size(); ++k)
  {
    const double want = exact[k] + (more ? (*more)[k] : 0.0);
    const double have =
      LightIrradiance(position, normal, brightness, receivers.Points[k], receivers.Normal);
    error += std::abs(have - want) / receivers.Total[k];
  }
  return error;
}

// The half-angle of the cone about the joint axis (the merged normal sum's direction) that holds
// both clusters' cones (pi when the sum vanishes: normals all around).
double MergedHalfAngle(const LightCluster& a, const LightCluster& b)
{
  const glm::dvec3 sum = a.NormalSum + b.NormalSum;
  const double length = glm::length(sum);
  if (!(length > 1e-12))
  {
    return Pi<double>;
  }
  const glm::dvec3 axis = sum / length;
  double half = 0.0;
  for (const LightCluster* c : { &a, &b })
  {
    const double apart = std::acos(std::clamp(glm::dot(axis, c->Axis()), -1.0, 1.0));
    half = std::max(half, apart + c->HalfAngle);
  }
  return std::min(half, Pi<double>);
}

// `into` becomes the cluster of both.
void Absorb(LightCluster& into, const LightCluster& from, const Receivers& receivers)
{
  into.HalfAngle = MergedHalfAngle(into, from);
  into.Members.insert(into.Members.end(), from.Members.begin(), from.Members.end());
  into.Lower = glm::min(into.Lower, from.Lower);
  into.Upper = glm::max(into.Upper, from.Upper);
  into.PositionSum += from.PositionSum;
  into.NormalSum += from.NormalSum;
  into.Brightness += from.Brightness;
  if (receivers.Known())
  {
    for (std::size_t k = 0; k < into.Exact.size(); ++k)
    {
      into.Exact[k] += from.Exact[k];
    }
    into.Error =
      ClusterError(receivers, into.PositionSum, into.NormalSum, into.Brightness, into.Exact);
  }
}

// What merging two clusters costs. Without receivers, Lightcuts' metric for a cluster of oriented
// lights (Walter et al. 2005, §4.1): its brightness x (the squared diagonal of its positions'
// bounds + (c (1 - cos of its normal cone))^2), c the scene's diameter (the field's unit sphere:
// 2). With receivers, the error the merge adds there: the merged light's summed relative error
// at the receivers' points less the two clusters' own (Lightcuts bounds a cluster's error at each
// receiver; here it is evaluated at sample points, so that lamps facing apart, near or far, are
// weighed by what they do to the receivers).
double MergeCost(const LightCluster& a, const LightCluster& b, const Receivers& receivers)
{
  if (receivers.Known())
  {
    return ClusterError(receivers, a.PositionSum + b.PositionSum, a.NormalSum + b.NormalSum,
             a.Brightness + b.Brightness, a.Exact, &b.Exact) -
      a.Error - b.Error;
  }
  const glm::dvec3 lower = glm::min(a.Lower, b.Lower), upper = glm::max(a.Upper, b.Upper);
  const glm::dvec3 extent = upper - lower;
  const double cone = 2.0 * (1.0 - std::cos(MergedHalfAngle(a, b)));
  return (a.Brightness + b.Brightness) * (glm::dot(extent, extent) + cone * cone);
}

// The receivers' points and all the lights' irradiance there; none (Known() false) when the
// options name no receivers or no light reaches them.
Receivers ReceiversOf(const std::vector<EmitterLight>& lights, const EmitterLightOptions& options)
{
  Receivers out;
  const glm::dvec3 corner(options.ReceiverCorner), edgeU(options.ReceiverEdgeU),
    edgeV(options.ReceiverEdgeV), normal(options.ReceiverNormal);
  const double normalLength = glm::length(normal);
  if (!(glm::length(glm::cross(edgeU, edgeV)) > 0.0) || !(normalLength > 0.0) ||
    !std::isfinite(glm::dot(corner + edgeU + edgeV, normal)))
  {
    return out;
  }
  out.Normal = normal / normalLength;
  const int n = Receivers::SamplesPerSide;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      out.Points.push_back(corner + (i + 0.5) / n * edgeU + (j + 0.5) / n * edgeV);
    }
  }
  out.Total.assign(out.Points.size(), 0.0);
  for (const EmitterLight& light : lights)
  {
    for (std::size_t k = 0; k < out.Points.size(); ++k)
    {
      out.Total[k] += LightIrradiance(glm::dvec3(light.Position), glm::dvec3(light.Normal),
        Brightness(light), out.Points[k], out.Normal);
    }
  }
  const double mean = std::accumulate(out.Total.begin(), out.Total.end(), 0.0) /
    static_cast<double>(out.Total.size());
  if (!(mean > 0.0) || !std::isfinite(mean))
  {
    return Receivers(); // no light reaches them: merge as if they were unknown
  }
  for (double& total : out.Total)
  {
    total = std::max(total, 1e-3 * mean);
  }
  return out;
}

// One light for a cluster: at the brightness-weighted centroid, facing along the mean normal,
// with the members' summed intensity Le A, so their power (pi Le A for a cosine lobe). For lamps
// of one plane that is also their intensity along the normal; for a curved lamp's pieces it
// spreads the power of a cap over one cosine lobe (too bright along the axis, too dark far from
// it, right on average).
EmitterLight ClusterLight(const std::vector<EmitterLight>& lights, const LightCluster& cluster)
{
  const glm::dvec3 axis = glm::length(cluster.NormalSum) > 1e-12
    ? cluster.Axis()
    : glm::dvec3(lights[cluster.Members.front()].Normal);
  EmitterLight out = lights[cluster.Members.front()];
  out.Triangles.clear();
  bool cells = false; // a member is a cell of a cut lamp: no triangles of its own
  glm::dvec3 position(0.0), intensity(0.0);
  double weight = 0.0, area = 0.0;
  float brightest = -1.0f;
  for (const std::size_t m : cluster.Members)
  {
    const EmitterLight& light = lights[m];
    const double b = Brightness(light);
    position += b * glm::dvec3(light.Position);
    weight += b;
    intensity += glm::dvec3(light.Intensity());
    area += light.Area;
    cells = cells || light.Triangles.empty();
    out.Triangles.insert(out.Triangles.end(), light.Triangles.begin(), light.Triangles.end());
    if (Brightness(light) > brightest)
    {
      brightest = Brightness(light);
      out.Surface = light.Surface;
    }
  }
  out.Position =
    weight > 0.0 ? glm::vec3(position / weight) : lights[cluster.Members.front()].Position;
  if (cells)
  {
    out.Triangles.clear();
  }
  out.Normal = glm::vec3(axis);
  out.Area = area;
  out.Radiance = area > 0.0 ? glm::vec3(intensity / area) : glm::vec3(0.0f);
  return out;
}
} // namespace

//------------------------------------------------------------------------------
std::vector<std::vector<std::uint32_t>> LampsOf(
  const TriangleScene& scene, const std::vector<std::uint32_t>& triangles)
{
  std::vector<std::size_t> parent(triangles.size());
  std::iota(parent.begin(), parent.end(), std::size_t{ 0 });
  const auto root = [&parent](std::size_t i)
  {
    while (parent[i] != i)
    {
      i = parent[i] = parent[parent[i]];
    }
    return i;
  };
  std::map<std::tuple<float, float, float>, std::size_t> firstAtCorner;
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    for (int c = 0; c < 3; ++c)
    {
      const glm::vec3 x = scene.Vertex(triangles[i], c);
      const auto found = firstAtCorner.emplace(std::make_tuple(x.x, x.y, x.z), i);
      parent[root(i)] = root(found.first->second);
    }
  }
  std::map<std::size_t, std::vector<std::uint32_t>> pieces;
  for (std::size_t i = 0; i < triangles.size(); ++i)
  {
    pieces[root(i)].push_back(triangles[i]);
  }
  std::vector<std::vector<std::uint32_t>> out;
  for (auto& piece : pieces)
  {
    out.push_back(std::move(piece.second));
  }
  return out;
}

//------------------------------------------------------------------------------
std::vector<glm::vec3> LightPositions(const std::vector<EmitterLight>& lights)
{
  std::vector<glm::vec3> positions;
  positions.reserve(lights.size());
  for (const EmitterLight& light : lights)
  {
    positions.push_back(light.Position);
  }
  return positions;
}

std::vector<EmitterLight> MergeEmitterLights(
  std::vector<EmitterLight> lights, const EmitterLightOptions& options)
{
  const std::size_t maxLights = options.MaxLights;
  if (maxLights == 0 || lights.size() <= maxLights)
  {
    return lights;
  }
  const Receivers receivers = ReceiversOf(lights, options);
  std::vector<LightCluster> clusters(lights.size());
  for (std::size_t i = 0; i < lights.size(); ++i)
  {
    LightCluster& c = clusters[i];
    c.Members = { i };
    c.Lower = c.Upper = glm::dvec3(lights[i].Position);
    c.Brightness = Brightness(lights[i]);
    c.PositionSum = c.Brightness * glm::dvec3(lights[i].Position);
    c.NormalSum = c.Brightness * glm::dvec3(lights[i].Normal);
    for (const glm::dvec3& p : receivers.Points) // a light alone is exact: Error stays 0
    {
      c.Exact.push_back(
        LightIrradiance(c.Lower, glm::dvec3(lights[i].Normal), c.Brightness, p, receivers.Normal));
    }
  }
  // The pairing below costs about n^2 merge costs; a curved lamp (each of its triangles a field
  // surface, so a light) can bring thousands. Past 256 lights they are first gathered into the
  // cells of a 3 x 3 x 3 grid over their positions times the 6 axis directions their normals
  // lean to (at most 162 clusters).
  if (clusters.size() > 256)
  {
    glm::dvec3 lower(std::numeric_limits<double>::max()), upper(-lower);
    for (const LightCluster& c : clusters)
    {
      lower = glm::min(lower, c.Lower);
      upper = glm::max(upper, c.Upper);
    }
    const glm::dvec3 size = glm::max(upper - lower, glm::dvec3(1e-12));
    std::map<int, LightCluster> cells;
    for (LightCluster& c : clusters)
    {
      const glm::ivec3 cell = glm::clamp(glm::ivec3(3.0 * (c.Lower - lower) / size), 0, 2);
      const glm::dvec3 n = c.Axis(), a = glm::abs(n);
      const int axis = a.x >= a.y && a.x >= a.z ? 0 : (a.y >= a.z ? 1 : 2);
      const int key = ((cell.x * 3 + cell.y) * 3 + cell.z) * 6 + 2 * axis + (n[axis] < 0.0 ? 1 : 0);
      const auto found = cells.find(key);
      if (found == cells.end())
      {
        cells.emplace(key, std::move(c));
        continue;
      }
      Absorb(found->second, c, receivers);
    }
    clusters.clear();
    for (auto& cell : cells)
    {
      clusters.push_back(std::move(cell.second));
    }
  }
  // Greedy pairing with each cluster's cheapest partner cached (as Lightcuts builds its tree).
  std::vector<bool> alive(clusters.size(), true);
  std::vector<std::size_t> partner(clusters.size(), 0);
  std::vector<double> partnerCost(clusters.size(), 0.0);
  const auto findPartner = [&](std::size_t i)
  {
    partnerCost[i] = std::numeric_limits<double>::infinity();
    for (std::size_t j = 0; j < clusters.size(); ++j)
    {
      if (j != i && alive[j])
      {
        const double cost = MergeCost(clusters[i], clusters[j], receivers);
        if (cost < partnerCost[i])
        {
          partnerCost[i] = cost;
          partner[i] = j;
        }
      }
    }
  };
  for (std::size_t i = 0; i < clusters.size(); ++i)
  {
    findPartner(i);
  }
  for (std::size_t count = clusters.size(); count > maxLights; --count)
  {
    std::size_t a = clusters.size();
    for (std::size_t i = 0; i < clusters.size(); ++i)
    {
      if (alive[i] && (a == clusters.size() || partnerCost[i] < partnerCost[a]))
      {
        a = i;
      }
    }
    const std::size_t b = partner[a];
    LightCluster& merged = clusters[a];
    Absorb(merged, clusters[b], receivers);
    alive[b] = false;
    findPartner(a);
    for (std::size_t k = 0; k < clusters.size(); ++k)
    {
      if (!alive[k] || k == a)
      {
        continue;
      }
      if (partner[k] == a || partner[k] == b)
      {
        findPartner(k);
      }
      else
      {
        const double cost = MergeCost(clusters[k], merged, receivers);
        if (cost < partnerCost[k])
        {
          partnerCost[k] = cost;
          partner[k] = a;
        }
      }
    }
  }
  std::vector<EmitterLight> out;
  for (std::size_t i = 0; i < clusters.size(); ++i)
  {
    if (alive[i])
    {
      out.push_back(ClusterLight(lights, clusters[i]));
    }
  }
  std::sort(out.begin(), out.end(),
    [](const EmitterLight& a, const EmitterLight& b) { return Brightness(a) > Brightness(b); });
  return out;
}

//------------------------------------------------------------------------------
LightApproximation EstimateEmitterLights(const LightField& field)
{
  return EstimateEmitterLights(field, EmitterLightOptions());
}

//------------------------------------------------------------------------------
LightApproximation EstimateEmitterLights(
  const LightField& field, const EmitterLightOptions& options)
{
  LightApproximation out;
  const TriangleScene& scene = field.Scene();
  glm::dvec3 radianceArea(0.0);
  double area = 0.0;
  for (std::uint32_t s = 0; s < field.Surfaces().size(); ++s)
  {
    const Surface& surface = field.Surfaces()[s];
    const glm::vec3 le = field.MaterialOf(s).Emission;
    if (std::max({ le.x, le.y, le.z }) <= 0.0f)
    {
      // The ambient term: the mean radiance the non-emitting surfaces leave (their texels
      // weighted by the surface's area per texel).
      if (surface.TexelCount() > 0 && surface.Area > 0.0 && !field.TotalDiffuse.empty())
      {
        glm::dvec3 sum(0.0);
        for (std::size_t t = 0; t < surface.TexelCount(); ++t)
        {
          sum += glm::dvec3(field.TotalDiffuse[surface.TexelOffset + t]);
        }
        radianceArea += sum / static_cast<double>(surface.TexelCount()) * surface.Area;
        area += surface.Area;
      }
      continue;
    }
    // A light per lamp; but a surface of more lamps than a MaxSplit x MaxSplit grid has cells
    // (a wall of LED tiles) is cut into that grid instead, a light per cell with lamp area in it,
    // so that the count of lights, each a shadow on the GPU, stays bounded.
    const int maxSplit = std::max(1, options.MaxSplit);
    std::vector<std::vector<std::uint32_t>> lamps = LampsOf(scene, surface.Triangles);
    const bool grid = lamps.size() > static_cast<std::size_t>(maxSplit * maxSplit);
    if (grid)
    {
      lamps = { surface.Triangles };
    }
    for (const std::vector<std::uint32_t>& lamp : lamps)
    {
      EmitterLight light;
      light.Surface = s;
      light.Normal = surface.Normal;
      light.Radiance = le;
      glm::dvec3 centroid(0.0);
      for (const std::uint32_t t : lamp)
      {
        const double a = scene.Area(t);
        centroid +=
          a * glm::dvec3(scene.Vertex(t, 0) + scene.Vertex(t, 1) + scene.Vertex(t, 2)) / 3.0;
        light.Area += a;
      }
      if (light.Area <= 0.0)
      {
        continue;
      }
      light.Position = glm::vec3(centroid / light.Area);
      // Splitting: the lamp's triangles in its plane's (u, v) frame.
      const double distance = glm::length(glm::dvec3(light.Position - options.ReferencePoint));
      glm::dvec2 lower(1e300), upper(-1e300);
      std::vector<std::vector<glm::dvec2>> flat;
      for (const std::uint32_t t : lamp)
      {
        std::vector<glm::dvec2> corners;
        for (int c = 0; c < 3; ++c)
        {
          const glm::dvec3 x(scene.Vertex(t, c) - surface.Origin);
          const glm::dvec2 uv(
            glm::dot(x, glm::dvec3(surface.AxisU)), glm::dot(x, glm::dvec3(surface.AxisV)));
          corners.push_back(uv);
          lower = glm::min(lower, uv);
          upper = glm::max(upper, uv);
        }
        flat.push_back(corners);
      }
      const double limit = std::max(1e-12, static_cast<double>(options.SplitRatio) * distance);
      // Cells along an extent: the grid's, the split's (up to maxSplit), or one.
      const auto cells = [&](double extent)
      {
        if (grid)
        {
          return maxSplit;
        }
        if (!options.Split)
        {
          return 1;
        }
        return std::min(maxSplit, std::max(1, static_cast<int>(std::ceil(extent / limit))));
      };
      const int nu = cells(upper.x - lower.x), nv = cells(upper.y - lower.y);
      if (nu * nv == 1)
      {
        light.Triangles = lamp;
        out.Lights.push_back(light);
        continue;
      }
      for (int a = 0; a < nu; ++a)
      {
        for (int b = 0; b < nv; ++b)
        {
          const double u0 = lower.x + (upper.x - lower.x) * a / nu;
          const double u1 = lower.x + (upper.x - lower.x) * (a + 1) / nu;
          const double v0 = lower.y + (upper.y - lower.y) * b / nv;
          const double v1 = lower.y + (upper.y - lower.y) * (b + 1) / nv;
          double cellArea = 0.0;
          glm::dvec2 moment(0.0);
          for (const std::vector<glm::dvec2>& triangle : flat)
          {
            std::vector<glm::dvec2> part = ClipPolygon(triangle, 0, u0, false);
            part = ClipPolygon(part, 0, u1, true);
            part = ClipPolygon(part, 1, v0, false);
            part = ClipPolygon(part, 1, v1, true);
            double partArea = 0.0;
            glm::dvec2 partMoment(0.0);
            PolygonMoments(part, partArea, partMoment);
            cellArea += partArea;
            moment += partMoment;
          }
          if (!(cellArea > 0.0))
          {
            continue;
          }
          EmitterLight cell = light;
          const glm::dvec2 uv = moment / cellArea;
          cell.Position = glm::vec3(glm::dvec3(surface.Origin) + uv.x * glm::dvec3(surface.AxisU) +
            uv.y * glm::dvec3(surface.AxisV));
          cell.Area = cellArea;
          out.Lights.push_back(cell);
        }
      }
    }
  }
  std::sort(out.Lights.begin(), out.Lights.end(),
    [](const EmitterLight& a, const EmitterLight& b) { return Brightness(a) > Brightness(b); });
  out.Lights = MergeEmitterLights(std::move(out.Lights), options);
  if (area > 0.0)
  {
    out.Ambient = glm::vec3(radianceArea / area);
  }
  return out;
}

//------------------------------------------------------------------------------
glm::vec3 ShadeWithLights(
  const LightApproximation& lights, const glm::vec3& p, const glm::vec3& n, const glm::vec3& kd)
{
  glm::vec3 radiance = kd * lights.Ambient;
  for (const EmitterLight& light : lights.Lights)
  {
    const glm::vec3 toLight = light.Position - p;
    const float d2 = glm::dot(toLight, toLight);
    if (!(d2 > 0.0f))
    {
      continue;
    }
    const glm::vec3 w = toLight / std::sqrt(d2);
    const float cosLight = std::max(0.0f, -glm::dot(light.Normal, w));
    const float cosPoint = std::max(0.0f, glm::dot(n, w));
    radiance += kd / Pi<float> * light.Intensity() * (cosLight * cosPoint / d2);
  }
  return radiance;
}

} // namespace vlf
} // namespace mesolight
