// SPDX-License-Identifier: BSD-3-Clause
#include "ObjectGatherer.h"

#include "IrradianceVolume.h"
#include "ObjectLineCache.h"
#include "ObjectSelfOcclusion.h"

#include "MathConstants.h"
#include "ParallelFor.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <atomic>
#include <cmath>
#include <cstring>
#include <exception>
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
  if (mesh.Normals.size() != mesh.Positions.size())
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
  out.Diffuse = mesh.Diffuse;
  out.Positions = mesh.Positions;
  out.Normals = mesh.Normals;
  out.Triangles.reserve(mesh.Triangles.size() * 4);
  std::unordered_map<std::uint64_t, std::uint32_t> midpoints;
  midpoints.reserve(mesh.Triangles.size() * 2);
  for (const glm::uvec3& t : mesh.Triangles)
  {
    const glm::vec3 face = glm::cross(
      mesh.Positions[t.y] - mesh.Positions[t.x], mesh.Positions[t.z] - mesh.Positions[t.x]);
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
      const auto index = static_cast<std::uint32_t>(out.Positions.size());
      out.Positions.push_back(0.5f * (mesh.Positions[a] + mesh.Positions[b]));
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
  if (this->ObjectInterreflections < 0 || this->ObjectInterreflections > 8)
  {
    return "the object's inter-reflection iterations must lie in [0, 8]";
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
  , Self(new ObjectSelfOcclusion)
{
}

ObjectGatherer::ObjectGatherer(const LightField& field, Reducer* reducer)
  : Field(field)
  , Reduce(reducer && reducer->Size() > 1 ? reducer : nullptr)
  , Self(new ObjectSelfOcclusion)
{
}

ObjectGatherer::~ObjectGatherer() = default;

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
  this->Self->Clear();
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
        const Subfield& f = this->Field.GetSubfield(k); // empty maps when held elsewhere
        double sum = 0.0;
        // Every crossing's sent radiance (LightField::SentRadiance: stored or from the textures).
        const int n = this->Field.Settings().RaysPerSide;
        std::vector<Crossing> crossings;
        for (int j = 0; j < n && !f.TileStart.empty(); ++j)
        {
          for (int i = 0; i < n; ++i)
          {
            this->Field.LineCrossings(k, i, j, crossings);
            for (const Crossing& c : crossings)
            {
              const glm::vec3 r = this->Field.SentRadiance(k, i, j, c.Surface, c.Cell);
              sum += 0.2125 * r.x + 0.7154 * r.y + 0.0721 * r.z;
            }
          }
        }
        importance[k] = std::max(0.0, sum);
      }
    });
  if (this->Reduce)
  {
    this->Reduce->SumInPlace(importance.data(), importance.size()); // each from its owner
  }
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
  HashValue(topology, modelMesh.Positions.size());
  std::uint64_t hash = topology;
  HashVector(hash, modelMesh.Positions);
  HashVector(hash, modelMesh.Normals);
  if (hash != this->ModelHash || settings.Subdivision != this->ModelLevels)
  {
    this->Model = Subdivide(modelMesh, settings.Subdivision);
    this->ModelHash = hash;
    this->ModelLevels = settings.Subdivision;
    this->InputPoints = modelMesh.Positions;
  }
  if (settings.ObjectOcclusion && !settings.Volume)
  {
    std::uint64_t selfKey = hash;
    HashValue(selfKey, settings.Subdivision);
    this->Self->Prepare(this->Model, this->InputPoints, selfKey);
    this->Self->Place(modelToUnit);
  }
  // The irradiance volume holds the field's light only: no rays against the object there.
  const ObjectSelfOcclusion* self =
    settings.ObjectOcclusion && !settings.Volume ? this->Self.get() : nullptr;
  this->Model.Diffuse = modelMesh.Diffuse;
  ShadedObject& shaded = this->Shaded;
  shaded.Mesh = TransformMesh(this->Model, modelToUnit);
  shaded.DegenerateTriangles = shaded.Mesh.DegenerateTriangleCount();
  const std::size_t n = shaded.Mesh.Positions.size();

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
  HashValue(key, settings.ObjectOcclusion);
  HashValue(key, settings.ObjectInterreflections);
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
      const glm::vec3 a = shaded.Mesh.Positions[t.x], b = shaded.Mesh.Positions[t.y],
                      c = shaded.Mesh.Positions[t.z];
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
    const glm::vec3& p = shaded.Mesh.Positions[i];
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
  ObjectLineCache lines;
  if (options.SceneOcclusion && !todo.empty() && !settings.Volume)
  {
    glm::vec3 lower(std::numeric_limits<float>::max()), upper(-lower);
    for (const std::uint32_t i : todo)
    {
      const glm::vec3 p = placed(shaded.Mesh.Positions[i]);
      lower = glm::min(lower, p);
      upper = glm::max(upper, p);
    }
    const glm::vec3 extent = (upper - lower) / cell + 4.0f;
    const float windowLines =
      std::max({ extent.x * extent.y, extent.y * extent.z, extent.x * extent.z });
    if (static_cast<float>(todo.size()) >= windowLines)
    {
      std::vector<std::uint32_t> held; // a distributed field: the lines of this rank's directions
      for (const std::uint32_t k : directions)
      {
        if (this->Field.OwnsSubfield(k))
        {
          held.push_back(k);
        }
      }
      lines.Build(this->Field, held, lower, upper, settings.Threads);
    }
  }
  // Direction-major over small chunks of points: each direction's window of lines stays in
  // the cache while the chunk's points read it (point-major reads every window once per point,
  // and at 2049 directions the windows no longer fit in the cache).
  constexpr std::size_t chunk = 64;
  auto normalised = [&](const glm::vec3& sum, float total)
  {
    return !options.ProjectedAreaNormalization
      ? sum
      : (total > 0.0f ? sum * (Pi<float> / total) : glm::vec3(0.0f));
  };
  // The object's own occlusion: per point that faces part of the object, the directions it
  // blocks (the hit and the direction's weight), the field's part and the weights' total.
  struct Blocked
  {
    std::uint32_t Triangle;
    float U, V, Weight;
  };
  std::vector<std::vector<Blocked>> blocked;
  std::vector<glm::vec3> fieldSum;
  std::vector<float> weightTotal;
  std::atomic<std::size_t> selfFacing{ 0 }, selfBlocked{ 0 };
  // A distributed field: the sums are this rank's share until reduced below.
  const bool distributed = this->Reduce != nullptr;
  if (distributed && settings.Volume)
  {
    throw std::invalid_argument("an irradiance volume cannot be read from a light field "
                                "distributed over ranks");
  }
  if (self)
  {
    blocked.resize(n);
  }
  if (self || distributed)
  {
    fieldSum.assign(n, glm::vec3(0.0f));
    weightTotal.assign(n, 0.0f);
  }
  auto gatherChunk = [&](const std::uint32_t* points, std::size_t count)
  {
    glm::vec3 p[chunk], normal[chunk], sum[chunk];
    float total[chunk];
    const bool windows = !lines.Windows.empty();
    std::uint32_t facing[chunk]; // chunk slots of the points that face part of the object
    std::size_t facingCount = 0;
    for (std::size_t v = 0; v < count; ++v)
    {
      p[v] = placed(shaded.Mesh.Positions[points[v]]);
      normal[v] = shaded.Mesh.Normals[points[v]];
      sum[v] = glm::vec3(0.0f);
      total[v] = 0.0f;
      if (self && self->SeesItself(shaded.Mesh.Positions[points[v]], normal[v]))
      {
        facing[facingCount++] = static_cast<std::uint32_t>(v);
        blocked[points[v]].clear();
      }
    }
    if (settings.Volume) // the precomputed irradiance instead of the directions
    {
      for (std::size_t v = 0; v < count; ++v)
      {
        const std::uint32_t i = points[v];
        shaded.Irradiance[i] = settings.Volume->Irradiance(p[v], normal[v]);
        this->CachedPositions[i] = shaded.Mesh.Positions[i];
        this->CachedNormals[i] = shaded.Mesh.Normals[i];
        this->CachedValid[i] = 1;
      }
      return;
    }
    selfFacing += facingCount;
    std::uint8_t isBlocked[chunk] = {};
    std::size_t blockedRays = 0;
    for (std::size_t q = 0; q < directions.size(); ++q)
    {
      const std::uint32_t k = directions[q];
      const glm::vec3 d = this->Field.GetSubfield(k).Direction;
      const float scale =
        (options.SolidAngleWeights ? set.SolidAngle(k) : uniform) * multipliers[q];
      // Rays of this direction from the points facing the object, 16 to a packet.
      for (std::size_t f = 0; f < facingCount; f += 16)
      {
        glm::vec3 origins[16], normals[16], along[16];
        ObjectSelfHit hits[16];
        int slots[16], m = 0;
        for (std::size_t g = f; g < std::min(facingCount, f + 16); ++g)
        {
          const std::uint32_t v = facing[g];
          const float c = glm::dot(d, normal[v]);
          isBlocked[v] = 0;
          if (c == 0.0f)
          {
            continue;
          }
          origins[m] = shaded.Mesh.Positions[points[v]];
          normals[m] = normal[v];
          along[m] = c > 0.0f ? d : -d;
          slots[m++] = static_cast<int>(v);
        }
        if (m == 0)
        {
          continue;
        }
        self->Trace16(origins, normals, along, m, hits);
        for (int r = 0; r < m; ++r)
        {
          if (hits[r].Triangle == ObjectSelfHit::None)
          {
            continue;
          }
          const int v = slots[r];
          isBlocked[v] = 1;
          const float weight = scale * std::abs(glm::dot(d, normal[v]));
          // The inside of the object (a back face) sends nothing: no triangle to read.
          blocked[points[v]].push_back({ hits[r].Front ? hits[r].Triangle : ObjectSelfHit::None,
            hits[r].U, hits[r].V, weight });
          total[v] += weight;
          ++blockedRays;
        }
      }
      for (std::size_t v = 0; v < count; ++v)
      {
        const float c = glm::dot(d, normal[v]);
        if (c == 0.0f || isBlocked[v])
        {
          continue;
        }
        const float weight = scale * std::abs(c);
        const int sense = c > 0.0f ? 1 : -1;
        if (!this->Field.OwnsSubfield(k))
        {
          total[v] += weight; // its owner adds the light: the normalisation counts it here too
          continue;
        }
        glm::vec3 incident;
        if (!windows || !lines.Incident(k, sense, p[v], options.Cells, incident))
        {
          incident = lookup.IncidentRadiance(
            k, sense, p[v], options.Cells, NoSurface, options.SceneOcclusion);
        }
        total[v] += weight;
        sum[v] += weight * incident;
      }
      for (std::size_t g = 0; g < facingCount; ++g)
      {
        isBlocked[facing[g]] = 0;
      }
    }
    selfBlocked += blockedRays;
    for (std::size_t v = 0; v < count; ++v)
    {
      const std::uint32_t i = points[v];
      // Blocked directions send nothing yet: the iterations below add the object's radiance.
      shaded.Irradiance[i] = normalised(sum[v], total[v]);
      if (self || distributed)
      {
        fieldSum[i] = sum[v];
        weightTotal[i] = total[v];
      }
      this->CachedPositions[i] = shaded.Mesh.Positions[i];
      this->CachedNormals[i] = shaded.Mesh.Normals[i];
      this->CachedValid[i] = 1;
    }
  };

  std::exception_ptr failure;
  try
  {
    for (std::size_t start = 0; start < todo.size(); start += ProgressBatch)
    {
      if (!ReportProgress(settings.Progress,
            static_cast<double>(start) /
              static_cast<double>(std::max<std::size_t>(1, todo.size()))))
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
  }
  catch (...)
  {
    failure = std::current_exception();
  }
  if (distributed)
  {
    // A rank that stopped (an abort) stops every rank instead of leaving them in the sum.
    try
    {
      AgreeOnFailure(*this->Reduce, failure);
    }
    catch (...)
    {
      this->CachedValid.assign(n, 0);
      throw;
    }
  }
  else if (failure)
  {
    std::rethrow_exception(failure);
  }
  if (distributed)
  {
    // The field's part of every gathered point from every rank's directions: one sum.
    std::vector<glm::vec3> share(todo.size());
    for (std::size_t q = 0; q < todo.size(); ++q)
    {
      share[q] = fieldSum[todo[q]];
    }
    this->Reduce->SumInPlace(reinterpret_cast<float*>(share.data()), 3 * share.size());
    for (std::size_t q = 0; q < todo.size(); ++q)
    {
      const std::uint32_t i = todo[q];
      fieldSum[i] = share[q];
      shaded.Irradiance[i] = normalised(share[q], weightTotal[i]);
    }
  }
  ReportProgress(settings.Progress, 1.0);
  shaded.GatheredPoints = todo.size();
  shaded.SelfFacingPoints = selfFacing;
  shaded.SelfBlockedRays = selfBlocked;
  const glm::vec3 albedo = shaded.Mesh.Diffuse / Pi<float>;
  // The object's inter-reflection: Jacobi iterations of E = field part + sum over the blocked
  // directions of the radiance leaving the object at their hits (Gouraud, from the last
  // iterate; cached points keep theirs).
  if (self && shaded.SelfBlockedRays > 0)
  {
    std::vector<std::uint32_t> facingPoints;
    for (const std::uint32_t i : todo)
    {
      if (!blocked[i].empty())
      {
        facingPoints.push_back(i);
      }
    }
    std::vector<glm::vec3> radiance(n), next(facingPoints.size());
    for (int iteration = 0; iteration < settings.ObjectInterreflections; ++iteration)
    {
      for (std::size_t i = 0; i < n; ++i)
      {
        radiance[i] = albedo * shaded.Irradiance[i];
      }
      ParallelFor(
        0, facingPoints.size(), 64,
        [&](std::size_t begin, std::size_t end)
        {
          for (std::size_t f = begin; f < end; ++f)
          {
            const std::uint32_t i = facingPoints[f];
            glm::vec3 sum = fieldSum[i];
            for (const Blocked& b : blocked[i])
            {
              if (b.Triangle == ObjectSelfHit::None)
              {
                continue;
              }
              const glm::uvec3 t = shaded.Mesh.Triangles[b.Triangle];
              sum += b.Weight *
                ((1.0f - b.U - b.V) * radiance[t.x] + b.U * radiance[t.y] + b.V * radiance[t.z]);
            }
            next[f] = normalised(sum, weightTotal[i]);
          }
        },
        settings.Threads);
      for (std::size_t f = 0; f < facingPoints.size(); ++f)
      {
        shaded.Irradiance[facingPoints[f]] = next[f];
      }
    }
  }
  for (std::size_t i = 0; i < n; ++i)
  {
    shaded.Radiance[i] = albedo * shaded.Irradiance[i];
  }
  return shaded;
}

} // namespace vlf
} // namespace mesolight
