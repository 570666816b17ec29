// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectGatherer.h"

#include "IrradianceVolume.h"

#include "MathConstants.h"
#include "ParallelFor.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <unordered_map>

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

// FNV-1a over raw bytes: a fingerprint of the model mesh and of the settings that change values.
void HashBytes(std::uint64_t& h, const void* data, std::size_t size)
{
  const auto* bytes = static_cast<const unsigned char*>(data);
  for (std::size_t i = 0; i < size; ++i)
  {
    h = (h ^ bytes[i]) * 1099511628211ull;
  }
}

template <class T>
void HashVector(std::uint64_t& h, const std::vector<T>& values)
{
  const std::size_t n = values.size();
  HashBytes(h, &n, sizeof(n));
  if (n > 0)
  {
    HashBytes(h, values.data(), n * sizeof(T));
  }
}

template <class T>
void HashValue(std::uint64_t& h, const T& value)
{
  HashBytes(h, &value, sizeof(T));
}

// Normals as the gather needs them: computed when missing, an unusable one (zero, NaN) replaced
// by the area-weighted normal of its triangles, the rest renormalised.
void RepairNormals(ObjectMesh& mesh)
{
  if (mesh.Normals.size() != mesh.Points.size())
  {
    mesh.ComputeNormals();
    return;
  }
  ObjectMesh computed;
  bool haveComputed = false;
  for (std::size_t i = 0; i < mesh.Normals.size(); ++i)
  {
    glm::vec3& n = mesh.Normals[i];
    const float length = Finite(n) ? glm::length(n) : 0.0f;
    if (length > 1e-12f && std::isfinite(length))
    {
      n /= length;
      continue;
    }
    if (!haveComputed)
    {
      computed = mesh;
      computed.ComputeNormals();
      haveComputed = true;
    }
    n = computed.Normals[i];
  }
}

// Splits every triangle of `mesh` into four (one level).
ObjectMesh SubdivideOnce(const ObjectMesh& mesh)
{
  ObjectMesh out;
  out.Kd = mesh.Kd;
  out.Points = mesh.Points;
  out.Normals = mesh.Normals;
  out.Triangles.reserve(mesh.Triangles.size() * 4);
  std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
  midpoints.reserve(mesh.Triangles.size() * 2);
  for (const glm::uvec3& t : mesh.Triangles)
  {
    const glm::vec3 face =
      glm::cross(mesh.Points[t.y] - mesh.Points[t.x], mesh.Points[t.z] - mesh.Points[t.x]);
    std::uint32_t mid[3];
    for (int e = 0; e < 3; ++e)
    {
      const std::uint32_t a = t[e], b = t[(e + 1) % 3];
      const std::uint64_t key = (static_cast<std::uint64_t>(std::min(a, b)) << 32) | std::max(a, b);
      const auto found = midpoints.find(key);
      if (found != midpoints.end())
      {
        mid[e] = found->second;
        continue;
      }
      const auto index = static_cast<std::uint32_t>(out.Points.size());
      out.Points.push_back(0.5f * (mesh.Points[a] + mesh.Points[b]));
      glm::vec3 n = mesh.Normals[a] + mesh.Normals[b];
      float length = glm::length(n);
      if (!(length > 1e-6f))
      {
        // Opposite normals (a fold): the face's own direction.
        n = face;
        length = glm::length(n);
      }
      out.Normals.push_back(length > 0.0f && std::isfinite(length) ? n / length : mesh.Normals[a]);
      midpoints.emplace(key, index);
      mid[e] = index;
    }
    out.Triangles.emplace_back(t.x, mid[0], mid[2]);
    out.Triangles.emplace_back(t.y, mid[1], mid[0]);
    out.Triangles.emplace_back(t.z, mid[2], mid[1]);
    out.Triangles.emplace_back(mid[0], mid[1], mid[2]);
  }
  return out;
}

// Batches between progress reports (and abort checks).
constexpr std::size_t ProgressBatch = 2048;

// The object's lines: for every direction, the crossings of the lines of the small window of
// cells the object's points project to, each with its sending orientation and the radiance it
// sends (Lookup's CellRadiance), read from the field once per Gather instead of once per vertex.
// Lookups through it give exactly Lookup::IncidentRadiance's values (the test compares them).
struct LineCache
{
  struct Entry
  {
    float Depth;
    int Orientation; // of the surface along the direction (LightField::Orientation)
    glm::vec3 Radiance;
  };
  struct Window
  {
    int I0 = 0, J0 = 0, Width = 0, Height = 0;
    // LightField::CellCoordinates and DepthOf inlined: c = (p . U + 1) / h - 1/2,
    // depth = p . D + start.
    glm::vec3 U{ 0.0f }, V{ 0.0f }, D{ 0.0f };
    float InverseCell = 1.0f, DepthStart = 0.0f;
    std::vector<std::uint32_t> Start; // Width * Height + 1 offsets into Entries
    std::vector<Entry> Entries;
  };
  std::vector<Window> Windows; // per direction (Width 0: not cached, use the lookup)

  // Limits the memory for objects that cover much of the field.
  static constexpr int MaxLines = 400;

  void Build(const LightField& field, const std::vector<std::uint32_t>& directions,
    const glm::vec3& lower, const glm::vec3& upper, int threads)
  {
    this->Windows.assign(field.SubfieldCount(), Window());
    ParallelFor(
      0, directions.size(), 4,
      [&](std::size_t begin, std::size_t end)
      {
        std::vector<Crossing> crossings;
        for (std::size_t q = begin; q < end; ++q)
        {
          const std::uint32_t k = directions[q];
          glm::vec2 cmin(std::numeric_limits<float>::max()), cmax(-cmin);
          for (int corner = 0; corner < 8; ++corner)
          {
            const glm::vec3 x((corner & 1) ? upper.x : lower.x, (corner & 2) ? upper.y : lower.y,
              (corner & 4) ? upper.z : lower.z);
            const glm::vec2 c = field.CellCoordinates(k, x);
            cmin = glm::min(cmin, c);
            cmax = glm::max(cmax, c);
          }
          Window& w = this->Windows[k];
          w.I0 = static_cast<int>(std::floor(cmin.x)) - 1;
          w.J0 = static_cast<int>(std::floor(cmin.y)) - 1;
          const int width = static_cast<int>(std::floor(cmax.x)) + 2 - w.I0 + 1;
          const int height = static_cast<int>(std::floor(cmax.y)) + 2 - w.J0 + 1;
          if (width * height > MaxLines)
          {
            continue;
          }
          const Subfield& f = field.GetSubfield(k);
          w.Start.reserve(static_cast<std::size_t>(width * height) + 1);
          for (int b = 0; b < height; ++b)
          {
            for (int a = 0; a < width; ++a)
            {
              w.Start.push_back(static_cast<std::uint32_t>(w.Entries.size()));
              field.LineCrossings(k, w.I0 + a, w.J0 + b, crossings);
              for (const Crossing& c : crossings)
              {
                const glm::vec3 x = field.PointOnLine(k, w.I0 + a, w.J0 + b, c.Depth);
                glm::vec3 radiance =
                  f.Radiance[c.Cell] + field.SampleTexture(field.UnshotDiffuse, c.Surface, x);
                if (!f.UnshotSpecular.empty())
                {
                  radiance += f.UnshotSpecular[c.Cell];
                }
                w.Entries.push_back({ c.Depth, field.Orientation(k, c.Surface), radiance });
              }
            }
          }
          w.Start.push_back(static_cast<std::uint32_t>(w.Entries.size()));
          w.Width = width;
          w.Height = height;
          w.U = f.AxisU;
          w.V = f.AxisV;
          w.D = f.Direction;
          w.InverseCell = 1.0f / field.Settings().CellSize();
          w.DepthStart = field.DepthOf(k, glm::vec3(0.0f));
        }
      },
      threads);
  }

  // Lookup::IncidentRadiance through the window; false when p's cells are not in it.
  bool Incident(
    std::size_t k, int sense, const glm::vec3& p, CellInterpolation cells, glm::vec3& out) const
  {
    const Window& w = this->Windows[k];
    if (w.Width == 0)
    {
      return false;
    }
    int is[4], js[4];
    float ws[4];
    const glm::vec2 coordinates((glm::dot(p, w.U) + 1.0f) * w.InverseCell - 0.5f,
      (glm::dot(p, w.V) + 1.0f) * w.InverseCell - 0.5f);
    const int count = CellsAround(coordinates, cells, is, js, ws);
    const float depth = glm::dot(p, w.D) + w.DepthStart;
    glm::vec3 sum(0.0f), fallback(0.0f);
    float weight = 0.0f, fallbackWeight = -1.0f;
    for (int q = 0; q < count; ++q)
    {
      if (ws[q] <= 0.0f)
      {
        continue;
      }
      const int a = is[q] - w.I0, b = js[q] - w.J0;
      if (a < 0 || b < 0 || a >= w.Width || b >= w.Height)
      {
        return false;
      }
      const std::size_t line = static_cast<std::size_t>(b) * w.Width + a;
      const Entry* first = w.Entries.data() + w.Start[line];
      const Entry* last = w.Entries.data() + w.Start[line + 1];
      const Entry* before = nullptr;
      const Entry* after = nullptr;
      for (const Entry* e = first; e != last; ++e)
      {
        if (e->Depth < depth - SelfDepth)
        {
          before = e;
        }
        else if (e->Depth > depth + SelfDepth)
        {
          after = e;
          break;
        }
      }
      const Entry* sender = sense > 0 ? after : before;
      const glm::vec3 radiance =
        sender && sender->Orientation == -sense ? sender->Radiance : glm::vec3(0.0f);
      const bool open =
        (!before || before->Orientation > 0) && (!after || after->Orientation < 0) && first != last;
      if (open)
      {
        sum += ws[q] * radiance;
        weight += ws[q];
      }
      else if (ws[q] > fallbackWeight)
      {
        fallback = radiance;
        fallbackWeight = ws[q];
      }
    }
    out = weight > 0.0f ? sum / weight : fallback;
    return true;
  }
};
} // namespace

//------------------------------------------------------------------------------
std::string GatherSettings::Validate() const
{
  if (this->Subdivision < 0 || this->Subdivision > 3)
  {
    return "subdivision " + std::to_string(this->Subdivision) + " is outside 0-3";
  }
  if (!(this->ImportanceFraction > 0.0f && this->ImportanceFraction <= 1.0f))
  {
    return "the importance fraction must lie in (0, 1]";
  }
  if (!(this->CachePositionTolerance >= 0.0f) || !(this->CacheNormalTolerance >= 0.0f) ||
    !std::isfinite(this->CachePositionTolerance) || !std::isfinite(this->CacheNormalTolerance))
  {
    return "the cache tolerances must be finite and >= 0";
  }
  if (this->SkipBackFacing && !Finite(this->Eye))
  {
    return "the eye for skipping back faces is not a finite point";
  }
  return {};
}

//------------------------------------------------------------------------------
ObjectGatherer::ObjectGatherer(const LightField& field)
  : Field(field)
{
}

//------------------------------------------------------------------------------
void ObjectGatherer::Invalidate()
{
  this->ModelHash = 0;
  this->ModelLevels = -1;
  this->Model = ObjectMesh();
  this->CachedPositions.clear();
  this->CachedNormals.clear();
  this->CachedValid.clear();
  this->CacheKey = 0;
}

//------------------------------------------------------------------------------
ObjectMesh ObjectGatherer::Subdivide(const ObjectMesh& mesh, int levels)
{
  ObjectMesh out = mesh;
  RepairNormals(out);
  for (int level = 0; level < levels; ++level)
  {
    out = SubdivideOnce(out);
  }
  return out;
}

//------------------------------------------------------------------------------
const std::vector<double>& ObjectGatherer::DirectionImportance() const
{
  if (this->Importance.size() == this->Field.SubfieldCount())
  {
    return this->Importance;
  }
  std::vector<double> importance(this->Field.SubfieldCount(), 0.0);
  ParallelFor(0, importance.size(), 1,
    [&](std::size_t begin, std::size_t end)
    {
      for (std::size_t k = begin; k < end; ++k)
      {
        const Subfield& f = this->Field.GetSubfield(k);
        double sum = 0.0;
        for (std::size_t c = 0; c < f.Radiance.size(); ++c)
        {
          if (c < f.Depth.size() && f.Depth[c] >= 0.0f)
          {
            const glm::vec3& r = f.Radiance[c];
            sum += 0.2125 * r.x + 0.7154 * r.y + 0.0721 * r.z;
          }
        }
        importance[k] = std::max(0.0, sum);
      }
    });
  this->Importance = std::move(importance);
  return this->Importance;
}

//------------------------------------------------------------------------------
void ObjectGatherer::DirectionsFor(const GatherSettings& settings,
  std::vector<std::uint32_t>& directions, std::vector<float>& multipliers) const
{
  directions.clear();
  multipliers.clear();
  const std::size_t count = this->Field.SubfieldCount();
  if (settings.Directions == DirectionSampling::All)
  {
    for (std::size_t k = 0; k < count; ++k)
    {
      directions.push_back(static_cast<std::uint32_t>(k));
      multipliers.push_back(1.0f);
    }
    return;
  }
  if (settings.Directions == DirectionSampling::Half)
  {
    for (std::size_t k = 0; k < count; k += 2)
    {
      directions.push_back(static_cast<std::uint32_t>(k));
      multipliers.push_back(static_cast<float>(count) / static_cast<float>((count + 1) / 2));
    }
    return;
  }
  // Importance: a mixture of the radiance along each direction and its solid angle (the
  // defensive half keeps every direction possible), drawn by systematic sampling with a fixed
  // offset, so the same directions serve every vertex and every frame (no flicker).
  const std::vector<double>& importance = this->DirectionImportance();
  double importanceSum = 0.0, solidSum = 0.0;
  for (std::size_t k = 0; k < count; ++k)
  {
    importanceSum += importance[k];
    solidSum += this->Field.Directions().SolidAngle(k);
  }
  std::vector<double> pdf(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    const double solid = this->Field.Directions().SolidAngle(k) / solidSum;
    pdf[k] = importanceSum > 0.0 ? 0.5 * solid + 0.5 * importance[k] / importanceSum : solid;
  }
  const auto draws = static_cast<std::size_t>(
    std::max(1.0, std::round(settings.ImportanceFraction * static_cast<double>(count))));
  double cumulative = 0.0;
  std::size_t drawn = 0;
  for (std::size_t k = 0; k < count; ++k)
  {
    cumulative += pdf[k] * static_cast<double>(draws);
    // Draws at 0.5, 1.5, ... fall into this direction's interval of the cumulative sum.
    std::size_t m = 0;
    while (drawn < draws && static_cast<double>(drawn) + 0.5 < cumulative)
    {
      ++drawn;
      ++m;
    }
    if (m > 0 && pdf[k] > 0.0)
    {
      directions.push_back(static_cast<std::uint32_t>(k));
      multipliers.push_back(
        static_cast<float>(static_cast<double>(m) / (static_cast<double>(draws) * pdf[k])));
    }
  }
}

//------------------------------------------------------------------------------
const ShadedObject& ObjectGatherer::Gather(
  const ObjectMesh& unitMesh, const GatherSettings& settings)
{
  return this->Gather(unitMesh, glm::mat4(1.0f), settings);
}

//------------------------------------------------------------------------------
const ShadedObject& ObjectGatherer::Gather(
  const ObjectMesh& modelMesh, const glm::mat4& modelToUnit, const GatherSettings& settings)
{
  const std::string problem = modelMesh.Validate();
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  const std::string settingsProblem = settings.Validate();
  if (!settingsProblem.empty())
  {
    throw std::invalid_argument(settingsProblem);
  }
  const float determinant = glm::determinant(glm::mat3(modelToUnit));
  bool finiteMatrix = true;
  for (int c = 0; c < 4; ++c)
  {
    for (int r = 0; r < 4; ++r)
    {
      finiteMatrix = finiteMatrix && std::isfinite(modelToUnit[c][r]);
    }
  }
  if (!finiteMatrix || !(std::abs(determinant) > 1e-30f))
  {
    throw std::invalid_argument("the object's placement is singular (a scale of 0) or not finite");
  }

  // The subdivision in model coordinates, once per mesh and level.
  // The topology alone keys the cache: the subdivision numbers its points from the triangles
  // only, so a mesh handed over already moved (the unit-mesh overload) keeps its cache too.
  std::uint64_t topology = 1469598103934665603ull;
  HashVector(topology, modelMesh.Triangles);
  HashValue(topology, modelMesh.Points.size());
  std::uint64_t hash = topology;
  HashVector(hash, modelMesh.Points);
  HashVector(hash, modelMesh.Normals);
  if (hash != this->ModelHash || settings.Subdivision != this->ModelLevels)
  {
    this->Model = Subdivide(modelMesh, settings.Subdivision);
    this->ModelHash = hash;
    this->ModelLevels = settings.Subdivision;
  }
  this->Model.Kd = modelMesh.Kd;
  ShadedObject& shaded = this->Shaded;
  shaded.Mesh = TransformMesh(this->Model, modelToUnit);
  shaded.DegenerateTriangles = shaded.Mesh.DegenerateTriangleCount();
  const std::size_t n = shaded.Mesh.Points.size();

  // Settings that change the gathered values invalidate the whole cache.
  std::uint64_t key = topology;
  HashValue(key, settings.Subdivision);
  HashValue(key, settings.Lookup.Cells);
  HashValue(key, settings.Lookup.SolidAngleWeights);
  HashValue(key, settings.Lookup.ProjectedAreaNormalization);
  HashValue(key, settings.Lookup.SceneOcclusion);
  HashValue(key, settings.Directions);
  HashValue(key, settings.ImportanceFraction);
  HashValue(key, reinterpret_cast<std::uintptr_t>(settings.Volume));
  if (!settings.UseCache || key != this->CacheKey || this->CachedValid.size() != n)
  {
    this->CachedValid.assign(n, 0);
    this->CachedPositions.assign(n, glm::vec3(0.0f));
    this->CachedNormals.assign(n, glm::vec3(0.0f));
    shaded.Irradiance.assign(n, glm::vec3(0.0f));
    this->CacheKey = key;
  }
  shaded.Irradiance.resize(n, glm::vec3(0.0f));
  shaded.Radiance.assign(n, glm::vec3(0.0f));

  // Which points need a value: all, or those of a triangle facing the eye.
  std::vector<std::uint8_t> needed(n, 1);
  if (settings.SkipBackFacing && !settings.ReflectionsNeedBackFaces)
  {
    std::fill(needed.begin(), needed.end(), 0);
    for (const glm::uvec3& t : shaded.Mesh.Triangles)
    {
      const glm::vec3 a = shaded.Mesh.Points[t.x], b = shaded.Mesh.Points[t.y],
                      c = shaded.Mesh.Points[t.z];
      const glm::vec3 face = glm::cross(b - a, c - a);
      if (glm::dot(face, settings.Eye - (a + b + c) / 3.0f) > 0.0f)
      {
        needed[t.x] = needed[t.y] = needed[t.z] = 1;
      }
    }
  }

  // Which points to gather now.
  const float cell = this->Field.Settings().CellSize();
  const float positionTolerance = settings.CachePositionTolerance * cell;
  const float normalCos = std::cos(std::min(settings.CacheNormalTolerance, Pi<float>));
  std::vector<std::uint32_t> todo;
  todo.reserve(n);
  shaded.CachedPoints = shaded.SkippedPoints = shaded.OutsidePoints = 0;
  for (std::size_t i = 0; i < n; ++i)
  {
    const glm::vec3& p = shaded.Mesh.Points[i];
    if (glm::dot(p, p) > 1.0f)
    {
      ++shaded.OutsidePoints;
    }
    if (!needed[i])
    {
      ++shaded.SkippedPoints;
      continue;
    }
    if (settings.UseCache && this->CachedValid[i] &&
      glm::length(p - this->CachedPositions[i]) <= positionTolerance &&
      glm::dot(shaded.Mesh.Normals[i], this->CachedNormals[i]) >= normalCos)
    {
      ++shaded.CachedPoints;
      continue;
    }
    todo.push_back(static_cast<std::uint32_t>(i));
  }

  std::vector<std::uint32_t> directions;
  std::vector<float> multipliers;
  this->DirectionsFor(settings, directions, multipliers);
  shaded.DirectionsUsed = settings.Volume ? 0 : directions.size();
  const Lookup lookup(this->Field);
  const GatherOptions& options = settings.Lookup;
  const float uniform = 2.0f * Pi<float> / static_cast<float>(this->Field.SubfieldCount());
  const DirectionSet& set = this->Field.Directions();
  auto placed = [](glm::vec3 p)
  {
    const float radius = glm::length(p);
    return radius > 1.0f ? p / radius : p; // outside the field: on its boundary (the header)
  };
  // The object's lines, read once when enough points need them (a few points after a small
  // move are cheaper through the lookup). The occlusion switch of the negative tests uses the
  // lookup.
  LineCache lines;
  if (options.SceneOcclusion && !todo.empty() && !settings.Volume)
  {
    glm::vec3 lower(std::numeric_limits<float>::max()), upper(-lower);
    for (const std::uint32_t i : todo)
    {
      const glm::vec3 p = placed(shaded.Mesh.Points[i]);
      lower = glm::min(lower, p);
      upper = glm::max(upper, p);
    }
    const glm::vec3 extent = (upper - lower) / cell + 4.0f;
    const float windowLines =
      std::max({ extent.x * extent.y, extent.y * extent.z, extent.x * extent.z });
    if (static_cast<float>(todo.size()) >= windowLines)
    {
      lines.Build(this->Field, directions, lower, upper, settings.Threads);
    }
  }
  // Direction-major over small chunks of points: each direction's window of lines stays in
  // the cache while the chunk's points read it (point-major reads every window once per point,
  // and at 2049 directions the windows no longer fit in the cache).
  constexpr std::size_t chunk = 64;
  auto gatherChunk = [&](const std::uint32_t* points, std::size_t count)
  {
    glm::vec3 p[chunk], normal[chunk], sum[chunk];
    float total[chunk];
    const bool windows = !lines.Windows.empty();
    for (std::size_t v = 0; v < count; ++v)
    {
      p[v] = placed(shaded.Mesh.Points[points[v]]);
      normal[v] = shaded.Mesh.Normals[points[v]];
      sum[v] = glm::vec3(0.0f);
      total[v] = 0.0f;
    }
    if (settings.Volume) // the precomputed irradiance instead of the directions
    {
      for (std::size_t v = 0; v < count; ++v)
      {
        const std::uint32_t i = points[v];
        shaded.Irradiance[i] = settings.Volume->Irradiance(p[v], normal[v]);
        this->CachedPositions[i] = shaded.Mesh.Points[i];
        this->CachedNormals[i] = shaded.Mesh.Normals[i];
        this->CachedValid[i] = 1;
      }
      return;
    }
    for (std::size_t q = 0; q < directions.size(); ++q)
    {
      const std::uint32_t k = directions[q];
      const glm::vec3 d = this->Field.GetSubfield(k).Direction;
      const float scale =
        (options.SolidAngleWeights ? set.SolidAngle(k) : uniform) * multipliers[q];
      for (std::size_t v = 0; v < count; ++v)
      {
        const float c = glm::dot(d, normal[v]);
        if (c == 0.0f)
        {
          continue;
        }
        const float weight = scale * std::abs(c);
        const int sense = c > 0.0f ? 1 : -1;
        glm::vec3 incident;
        if (!windows || !lines.Incident(k, sense, p[v], options.Cells, incident))
        {
          incident = lookup.IncidentRadiance(
            k, sense, p[v], options.Cells, NoSurface, options.SceneOcclusion);
        }
        total[v] += weight;
        sum[v] += weight * incident;
      }
    }
    for (std::size_t v = 0; v < count; ++v)
    {
      const std::uint32_t i = points[v];
      shaded.Irradiance[i] = !options.ProjectedAreaNormalization
        ? sum[v]
        : (total[v] > 0.0f ? sum[v] * (Pi<float> / total[v]) : glm::vec3(0.0f));
      this->CachedPositions[i] = shaded.Mesh.Points[i];
      this->CachedNormals[i] = shaded.Mesh.Normals[i];
      this->CachedValid[i] = 1;
    }
  };

  for (std::size_t start = 0; start < todo.size(); start += ProgressBatch)
  {
    if (!ReportProgress(settings.Progress,
          static_cast<double>(start) / static_cast<double>(std::max<std::size_t>(1, todo.size()))))
    {
      this->CachedValid.assign(n, 0); // part of this frame is missing
      throw AbortedError();
    }
    const std::size_t stop = std::min(todo.size(), start + ProgressBatch);
    const std::size_t chunks = (stop - start + chunk - 1) / chunk;
    ParallelFor(
      0, chunks, 1,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t c = begin; c < end; ++c)
        {
          const std::size_t first = start + c * chunk;
          gatherChunk(todo.data() + first, std::min(chunk, stop - first));
        }
      },
      settings.Threads);
  }
  ReportProgress(settings.Progress, 1.0);
  shaded.GatheredPoints = todo.size();
  const glm::vec3 albedo = shaded.Mesh.Kd / Pi<float>;
  for (std::size_t i = 0; i < n; ++i)
  {
    shaded.Radiance[i] = albedo * shaded.Irradiance[i];
  }
  return shaded;
}

} // namespace vlf
} // namespace mesolight
