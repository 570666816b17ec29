// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectReliefProbes.h"

#include "FieldIrradiance.h"
#include "LightField.h"
#include "Lookup.h"
#include "MathConstants.h"
#include "ObjectLineCache.h"
#include "ObjectSelfOcclusion.h"
#include "ParallelFor.h"

#include <glm/geometric.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <functional>
#include <limits>
#include <map>
#include <numeric>
#include <tuple>

namespace mesolight
{
namespace vlf
{

namespace
{
// Union-find over triangle indices.
struct Groups
{
  explicit Groups(std::size_t n)
    : Parent(n)
  {
    std::iota(this->Parent.begin(), this->Parent.end(), 0u);
  }
  std::uint32_t Find(std::uint32_t a)
  {
    while (this->Parent[a] != a)
    {
      this->Parent[a] = this->Parent[this->Parent[a]];
      a = this->Parent[a];
    }
    return a;
  }
  void Join(std::uint32_t a, std::uint32_t b) { this->Parent[this->Find(a)] = this->Find(b); }
  std::vector<std::uint32_t> Parent;
};

// The sets of `triangles` that `joined(a, b)` connects through a shared key of their corners.
template <typename Key, typename KeyOf>
std::vector<std::vector<std::uint32_t>> Connected(const ObjectMesh& mesh,
  const std::vector<std::uint32_t>& triangles, KeyOf keyOf,
  const std::function<bool(std::uint32_t, std::uint32_t)>& joinable)
{
  Groups groups(triangles.size());
  std::map<Key, std::vector<std::uint32_t>> byKey; // slot in `triangles` per corner key
  for (std::uint32_t s = 0; s < triangles.size(); ++s)
  {
    for (int k = 0; k < 3; ++k)
    {
      byKey[keyOf(mesh.Triangles[triangles[s]][k])].push_back(s);
    }
  }
  for (const auto& entry : byKey)
  {
    const std::vector<std::uint32_t>& slots = entry.second;
    for (std::size_t a = 0; a < slots.size(); ++a)
    {
      for (std::size_t b = a + 1; b < slots.size(); ++b)
      {
        if (joinable(triangles[slots[a]], triangles[slots[b]]))
        {
          groups.Join(slots[a], slots[b]);
        }
      }
    }
  }
  std::map<std::uint32_t, std::vector<std::uint32_t>> sets;
  for (std::uint32_t s = 0; s < triangles.size(); ++s)
  {
    sets[groups.Find(s)].push_back(triangles[s]);
  }
  std::vector<std::vector<std::uint32_t>> out;
  for (auto& entry : sets)
  {
    out.push_back(std::move(entry.second));
  }
  return out;
}

// The probes of a chart: rasterizes its triangles at the probes' texture coordinates.
ObjectChart LayOut(const ObjectMesh& mesh, std::vector<std::uint32_t> triangles, int nu, int nv)
{
  ObjectChart chart;
  chart.Triangles = std::move(triangles);
  chart.ProbesU = nu;
  chart.ProbesV = nv;
  const std::size_t count = static_cast<std::size_t>(nu) * nv;
  chart.Positions.assign(count, glm::vec3(0.0f));
  chart.Normals.assign(count, glm::vec3(0.0f, 0.0f, 1.0f));
  chart.Inside.assign(count, 0);
  std::vector<float> margin(count, -1.0f); // the winner's smallest barycentric
  // Texel centres on a shared edge (a quad's diagonal) belong to both triangles: only points
  // well inside two triangles are an overlap.
  constexpr float inner = 1e-3f;
  for (const std::uint32_t t : chart.Triangles)
  {
    const glm::uvec3 tri = mesh.Triangles[t];
    const glm::vec2 a = mesh.TextureCoordinates[tri.x], b = mesh.TextureCoordinates[tri.y],
                    c = mesh.TextureCoordinates[tri.z];
    const float area = (b.x - a.x) * (c.y - a.y) - (c.x - a.x) * (b.y - a.y);
    if (!(std::abs(area) > 0.0f))
    {
      continue; // degenerate in texture space: covers no probe
    }
    const glm::vec2 lower = glm::min(a, glm::min(b, c)), upper = glm::max(a, glm::max(b, c));
    const int i0 = std::max(0, static_cast<int>(std::floor(lower.x * nu - 0.5f)));
    const int i1 = std::min(nu - 1, static_cast<int>(std::ceil(upper.x * nu - 0.5f)));
    const int j0 = std::max(0, static_cast<int>(std::floor(lower.y * nv - 0.5f)));
    const int j1 = std::min(nv - 1, static_cast<int>(std::ceil(upper.y * nv - 0.5f)));
    for (int j = j0; j <= j1; ++j)
    {
      for (int i = i0; i <= i1; ++i)
      {
        const glm::vec2 p((i + 0.5f) / nu, (j + 0.5f) / nv);
        const float wb = ((p.x - a.x) * (c.y - a.y) - (c.x - a.x) * (p.y - a.y)) / area;
        const float wc = ((b.x - a.x) * (p.y - a.y) - (p.x - a.x) * (b.y - a.y)) / area;
        const float wa = 1.0f - wb - wc;
        const float least = std::min(wa, std::min(wb, wc));
        if (least < -1e-6f)
        {
          continue;
        }
        const std::size_t q = static_cast<std::size_t>(j) * nu + i;
        if (chart.Inside[q])
        {
          if (least > inner && margin[q] > inner)
          {
            ++chart.OverlappingProbes;
          }
          if (least <= margin[q])
          {
            continue;
          }
        }
        chart.Inside[q] = 1;
        margin[q] = least;
        chart.Positions[q] =
          wa * mesh.Positions[tri.x] + wb * mesh.Positions[tri.y] + wc * mesh.Positions[tri.z];
        glm::vec3 n =
          wa * mesh.Normals[tri.x] + wb * mesh.Normals[tri.y] + wc * mesh.Normals[tri.z];
        if (!(glm::length(n) > 0.0f))
        {
          n = mesh.FaceNormal(t);
        }
        chart.Normals[q] = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 0, 1);
      }
    }
  }
  // Probes under no triangle take the nearest one that is under one; a chart too small to cover
  // any probe centre takes its first triangle's centroid everywhere.
  std::vector<std::size_t> inside;
  for (std::size_t q = 0; q < count; ++q)
  {
    if (chart.Inside[q])
    {
      inside.push_back(q);
    }
  }
  if (inside.empty())
  {
    const glm::uvec3 tri = mesh.Triangles[chart.Triangles.front()];
    const glm::vec3 centre =
      (mesh.Positions[tri.x] + mesh.Positions[tri.y] + mesh.Positions[tri.z]) / 3.0f;
    glm::vec3 n = mesh.FaceNormal(chart.Triangles.front());
    n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0, 0, 1);
    std::fill(chart.Positions.begin(), chart.Positions.end(), centre);
    std::fill(chart.Normals.begin(), chart.Normals.end(), n);
    return chart;
  }
  for (std::size_t q = 0; q < count; ++q)
  {
    if (chart.Inside[q])
    {
      continue;
    }
    const long qi = static_cast<long>(q % nu), qj = static_cast<long>(q / nu);
    long best = std::numeric_limits<long>::max();
    std::size_t nearest = inside.front();
    for (const std::size_t r : inside)
    {
      const long di = static_cast<long>(r % nu) - qi, dj = static_cast<long>(r / nu) - qj;
      if (di * di + dj * dj < best)
      {
        best = di * di + dj * dj;
        nearest = r;
      }
    }
    chart.Positions[q] = chart.Positions[nearest];
    chart.Normals[q] = chart.Normals[nearest];
  }
  return chart;
}

// Outside the field: on its boundary, as the object gather does.
glm::vec3 Placed(const glm::vec3& p)
{
  const float radius = glm::length(p);
  return radius > 1.0f ? p / radius : p;
}

std::uint64_t HashMesh(const ObjectMesh& mesh)
{
  std::uint64_t h = 1469598103934665603ull;
  auto bytes = [&h](const void* data, std::size_t size)
  {
    const auto* p = static_cast<const unsigned char*>(data);
    for (std::size_t i = 0; i < size; ++i)
    {
      h = (h ^ p[i]) * 1099511628211ull;
    }
  };
  bytes(mesh.Positions.data(), mesh.Positions.size() * sizeof(glm::vec3));
  bytes(mesh.Triangles.data(), mesh.Triangles.size() * sizeof(glm::uvec3));
  bytes(mesh.Normals.data(), mesh.Normals.size() * sizeof(glm::vec3));
  bytes(mesh.TextureCoordinates.data(), mesh.TextureCoordinates.size() * sizeof(glm::vec2));
  return h;
}

// ProbeRadianceSH9 through the object's line cache when it holds p's lines (the gather's
// machinery: the same values as the lookup, read once per gather), else the lookup.
SH9 ProbeSH9(const LightField& field, const Lookup& lookup, const ObjectLineCache* lines,
  const glm::vec3& p, const glm::vec3& n, const ObjectSelfOcclusion* self = nullptr,
  const glm::vec3& surface = glm::vec3(0.0f))
{
  // FieldIrradiance's samples (IncidentRadianceSamples: both senses of every direction, weights
  // summing to 4 pi), but only the sense in front of the surface is looked up: the other is the
  // object's own body. Half the lookups of the whole sphere.
  const std::size_t count = field.SubfieldCount();
  const double scale = IncidentWeightScale(field);
  std::vector<IncidentSample> samples;
  samples.reserve(count + 8);
  for (std::size_t k = 0; k < count; ++k)
  {
    const Subfield& f = field.GetSubfield(k);
    const float c = glm::dot(f.Direction, n);
    for (const int sense : { 1, -1 })
    {
      if (static_cast<float>(sense) * c < 0.0f)
      {
        continue; // behind the surface
      }
      IncidentSample s;
      s.Direction = static_cast<float>(sense) * f.Direction;
      s.SolidAngle = static_cast<float>(scale * f.Weight);
      // The emitters' own radiance is left out: they are the relief's lights.
      if (!lines || !lines->Incident(k, sense, p, CellInterpolation::Bilinear, s.Radiance))
      {
        s.Radiance =
          lookup.IncidentRadiance(k, sense, p, CellInterpolation::Bilinear, NoSurface, true, false);
      }
      samples.push_back(s);
    }
  }
  if (self && self->SeesItself(surface, n))
  {
    // The object's own concavity: directions it blocks bring nothing (rays from the surface
    // point, 16 to a packet, as the object gather casts them).
    for (std::size_t first = 0; first < samples.size(); first += 16)
    {
      const int m = static_cast<int>(std::min<std::size_t>(16, samples.size() - first));
      glm::vec3 origins[16], normals[16], directions[16];
      ObjectSelfHit hits[16];
      for (int r = 0; r < m; ++r)
      {
        origins[r] = surface;
        normals[r] = n;
        directions[r] = samples[first + static_cast<std::size_t>(r)].Direction;
      }
      self->Trace16(origins, normals, directions, m, hits);
      for (int r = 0; r < m; ++r)
      {
        if (hits[r].Triangle != ObjectSelfHit::None)
        {
          samples[first + static_cast<std::size_t>(r)].Radiance = glm::vec3(0.0f);
        }
      }
    }
  }
  return ProjectIncidentSH9(samples);
}
} // namespace

//------------------------------------------------------------------------------
std::vector<ObjectChart> SplitIntoCharts(const ObjectMesh& input, int probesU, int probesV)
{
  if (probesU < 1 || probesV < 1)
  {
    throw std::invalid_argument("a relief's probe grid needs at least one probe a side");
  }
  if (input.TextureCoordinates.size() != input.Positions.size() || input.Positions.empty())
  {
    throw ObjectChartError("the movable object has no texture coordinates, which a relief needs: "
                           "give it an OBJ file with 'vt' coordinates on every face (e.g. a UV "
                           "unwrap exported from Blender), or use the built-in cube");
  }
  for (const glm::vec2& t : input.TextureCoordinates)
  {
    if (!std::isfinite(t.x) || !std::isfinite(t.y))
    {
      throw ObjectChartError("the movable object's texture coordinates are not finite");
    }
  }
  ObjectMesh mesh = input;
  if (mesh.Normals.size() != mesh.Positions.size())
  {
    mesh.ComputeNormals();
  }
  std::vector<std::uint32_t> all(mesh.Triangles.size());
  std::iota(all.begin(), all.end(), 0u);
  std::vector<ObjectChart> charts;
  // Connected through shared points (the same texture coordinates on both sides of an edge).
  const auto pieces = Connected<std::uint32_t>(
    mesh, all, [](std::uint32_t v) { return v; },
    [](std::uint32_t, std::uint32_t) { return true; });
  for (const std::vector<std::uint32_t>& piece : pieces)
  {
    ObjectChart chart = LayOut(mesh, piece, probesU, probesV);
    if (chart.OverlappingProbes == 0 || piece.size() == 1)
    {
      charts.push_back(std::move(chart));
      continue;
    }
    // Its texture folds over itself: planar groups, connected through shared positions.
    auto unitNormal = [&mesh](std::uint32_t t)
    {
      const glm::vec3 n = mesh.FaceNormal(t);
      return glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f);
    };
    const auto planar = Connected<std::tuple<float, float, float>>(
      mesh, piece,
      [&mesh](std::uint32_t v)
      { return std::make_tuple(mesh.Positions[v].x, mesh.Positions[v].y, mesh.Positions[v].z); },
      [&unitNormal](std::uint32_t a, std::uint32_t b)
      { return glm::dot(unitNormal(a), unitNormal(b)) > 0.9999f; });
    for (const std::vector<std::uint32_t>& group : planar)
    {
      charts.push_back(LayOut(mesh, group, probesU, probesV));
    }
  }
  return charts;
}

//------------------------------------------------------------------------------
SH9 ProbeRadianceSH9(const LightField& field, const glm::vec3& p, const glm::vec3& n)
{
  return ProbeSH9(field, Lookup(field), nullptr, p, n);
}

//------------------------------------------------------------------------------
ObjectReliefProbes::ObjectReliefProbes(const LightField& field)
  : Field(field)
  , Self(new ObjectSelfOcclusion)
{
}

//------------------------------------------------------------------------------
ObjectReliefProbes::~ObjectReliefProbes() = default;

//------------------------------------------------------------------------------
void ObjectReliefProbes::SetMesh(const ObjectMesh& model, int probesPerSide)
{
  const std::uint64_t hash = HashMesh(model);
  if (hash == this->MeshHash && probesPerSide == this->PerSide && !this->ChartList.empty())
  {
    return;
  }
  this->ChartList = SplitIntoCharts(model, probesPerSide, probesPerSide);
  this->Model = model;
  if (this->Model.Normals.size() != this->Model.Positions.size())
  {
    this->Model.ComputeNormals();
  }
  this->Self->Clear();
  this->MeshHash = hash;
  this->PerSide = probesPerSide;
  this->Values.assign(this->ChartList.size(), {});
  this->Points.assign(this->ChartList.size(), {});
  this->PointNormals.assign(this->ChartList.size(), {});
  this->Valid.assign(this->ChartList.size(), {});
  for (std::size_t c = 0; c < this->ChartList.size(); ++c)
  {
    const std::size_t n = this->ChartList[c].Positions.size();
    this->Values[c].assign(n, SH9{});
    this->Points[c].assign(n, glm::vec3(0.0f));
    this->PointNormals[c].assign(n, glm::vec3(0.0f));
    this->Valid[c].assign(n, 0);
  }
}

//------------------------------------------------------------------------------
std::size_t ObjectReliefProbes::ProbeCount() const
{
  std::size_t n = 0;
  for (const ObjectChart& c : this->ChartList)
  {
    n += c.Positions.size();
  }
  return n;
}

//------------------------------------------------------------------------------
glm::vec3 ObjectReliefProbes::PointOf(std::size_t chart, std::size_t probe) const
{
  return this->Points.at(chart).at(probe);
}

//------------------------------------------------------------------------------
glm::vec3 ObjectReliefProbes::NormalOf(std::size_t chart, std::size_t probe) const
{
  return this->PointNormals.at(chart).at(probe);
}

//------------------------------------------------------------------------------
std::size_t ObjectReliefProbes::Gather(
  const glm::mat4& modelToUnit, const ReliefProbeSettings& settings)
{
  const glm::mat3 normalMatrix = glm::transpose(glm::inverse(glm::mat3(modelToUnit)));
  const ObjectSelfOcclusion* self = nullptr;
  if (settings.ObjectOcclusion && !this->ChartList.empty())
  {
    this->Self->Prepare(this->Model, this->Model.Positions, this->MeshHash);
    this->Self->Place(modelToUnit);
    self = this->Self.get();
  }
  if (settings.ObjectOcclusion != this->GatheredWithOcclusion)
  {
    for (std::vector<std::uint8_t>& valid : this->Valid)
    {
      std::fill(valid.begin(), valid.end(), 0); // other values: gather everything again
    }
    this->GatheredWithOcclusion = settings.ObjectOcclusion;
  }
  const float positionTolerance =
    settings.CachePositionTolerance * this->Field.Settings().CellSize();
  const float normalCos = std::cos(settings.CacheNormalTolerance);
  // The probes to gather, as (chart, probe), with their placed points.
  std::vector<std::pair<std::uint32_t, std::uint32_t>> todo;
  for (std::size_t c = 0; c < this->ChartList.size(); ++c)
  {
    const ObjectChart& chart = this->ChartList[c];
    for (std::size_t q = 0; q < chart.Positions.size(); ++q)
    {
      const glm::vec3 p = glm::vec3(modelToUnit * glm::vec4(chart.Positions[q], 1.0f));
      glm::vec3 n = normalMatrix * chart.Normals[q];
      n = glm::length(n) > 0.0f ? glm::normalize(n) : glm::vec3(0.0f, 0.0f, 1.0f);
      if (settings.UseCache && this->Valid[c][q] &&
        glm::length(p - this->Points[c][q]) <= positionTolerance &&
        glm::dot(n, this->PointNormals[c][q]) >= normalCos)
      {
        continue;
      }
      this->Points[c][q] = p;
      this->PointNormals[c][q] = n;
      this->Valid[c][q] = 0;
      todo.emplace_back(static_cast<std::uint32_t>(c), static_cast<std::uint32_t>(q));
    }
  }
  // The probes' lines, read once when there are enough probes to pay for it (as the object
  // gather decides: more points than lines in the largest face of their box).
  const Lookup lookup(this->Field);
  ObjectLineCache lines;
  if (!todo.empty())
  {
    glm::vec3 lower(std::numeric_limits<float>::max()), upper(-lower);
    for (const auto& cq : todo)
    {
      const glm::vec3 p = Placed(this->Points[cq.first][cq.second] +
        settings.Offset * this->PointNormals[cq.first][cq.second]);
      lower = glm::min(lower, p);
      upper = glm::max(upper, p);
    }
    const float cell = this->Field.Settings().CellSize();
    const glm::vec3 extent = (upper - lower) / cell + 4.0f;
    const float windowLines =
      std::max({ extent.x * extent.y, extent.y * extent.z, extent.x * extent.z });
    if (static_cast<float>(todo.size()) >= windowLines && settings.UseLineCache)
    {
      std::vector<std::uint32_t> all;
      for (std::uint32_t k = 0; k < this->Field.SubfieldCount(); ++k)
      {
        if (this->Field.OwnsSubfield(k))
        {
          all.push_back(k);
        }
      }
      lines.Build(this->Field, all, lower, upper, settings.Threads, false);
    }
  }
  const ObjectLineCache* cache = lines.Windows.empty() ? nullptr : &lines;
  constexpr std::size_t batch = 256;
  for (std::size_t start = 0; start < todo.size(); start += batch)
  {
    if (!ReportProgress(settings.Progress, static_cast<double>(start) / todo.size()))
    {
      throw AbortedError();
    }
    const std::size_t stop = std::min(todo.size(), start + batch);
    ParallelFor(
      start, stop, 4,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t w = begin; w < end; ++w)
        {
          const std::uint32_t c = todo[w].first, q = todo[w].second;
          const glm::vec3 p =
            Placed(this->Points[c][q] + settings.Offset * this->PointNormals[c][q]);
          this->Values[c][q] = ProbeSH9(
            this->Field, lookup, cache, p, this->PointNormals[c][q], self, this->Points[c][q]);
          this->Valid[c][q] = 1;
        }
      },
      settings.Threads);
  }
  ReportProgress(settings.Progress, 1.0);
  return todo.size();
}

} // namespace vlf
} // namespace mesolight
