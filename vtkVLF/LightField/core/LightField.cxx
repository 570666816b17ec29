// SPDX-License-Identifier: BSD-3-Clause
#include "LightField.h"
#include "LightFieldMemory.h"

#include "Distribution.h"

#include "MathConstants.h"
#include "OrthonormalBasis.h"
#include "ParallelFor.h"

#include "EmbreeScene.h"

#include <glm/common.hpp>
#include <glm/geometric.hpp>
#include <glm/vector_relational.hpp>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <map>
#include <sstream>
#include <thread> // hardware_concurrency() only: fixes the number of bands/blocks (no thread started)
#include <tuple>

namespace mesolight
{
namespace vlf
{

namespace
{
// After a hit the next query starts a few float steps beyond it: Embree computes a triangle's
// distance independently of TNear, so the same triangle is never found again, while a crossing
// right behind it (a line clipping a corner of a closed box) still is; a larger step would
// lose such pairs and let light escape from closed scenes.
float NextQueryStart(float t)
{
  return t + std::max(1e-7f, 4e-7f * t);
}

// The number of worker blocks follows the hardware threads (DefaultBlockCount); the energies
// depend on it through the per-block sums, so it stays this count (no thread is started here).
std::size_t HardwareThreads()
{
  const unsigned n = std::thread::hardware_concurrency();
  return n == 0 ? 2 : n;
}

} // namespace

// Subfield k's frame: OrthonormalBasis() (Duff et al.; d.z >= 0 for the hemisphere
// directions) turned about d by a golden-ratio angle. The turn keeps lines off
// systematic alignments with the scene (an axis-aligned box's face diagonals lie in planes
// that symmetric directions and an unturned grid hit exactly, where Embree may miss both
// triangles of the shared edge); the [-1, 1]^2 grid covers the unit disk at any angle.
void SubfieldFrame(std::size_t k, const glm::vec3& d, glm::vec3& u, glm::vec3& v)
{
  glm::vec3 u0, v0;
  OrthonormalBasis(d, u0, v0);
  const double turns = 0.1 + static_cast<double>(k) * 0.6180339887498949;
  const float angle = static_cast<float>(2.0 * Pi<double> * (turns - std::floor(turns)));
  u = std::cos(angle) * u0 + std::sin(angle) * v0;
  v = -std::sin(angle) * u0 + std::cos(angle) * v0;
}

namespace
{
std::string Join(const std::vector<std::string>& items)
{
  std::string out;
  for (const std::string& item : items)
  {
    out += (out.empty() ? "" : "; ") + item;
  }
  return out;
}
} // namespace

std::size_t DefaultBlockCount(std::size_t count)
{
  return std::max<std::size_t>(1, std::min(count, 2 * HardwareThreads()));
}

void RunInBlocks(std::size_t count, std::size_t blocks, const ProgressCallback& progress,
  double begin, double end, const std::function<void(std::size_t block, std::size_t item)>& work)
{
  blocks = std::max<std::size_t>(1, blocks);
  const std::size_t perBlock = 4; // items per block per round
  const std::size_t round = blocks * perBlock;
  for (std::size_t start = 0; start < count; start += round)
  {
    const double done = static_cast<double>(start) / static_cast<double>(count);
    if (!ReportProgress(progress, begin + (end - begin) * done))
    {
      throw AbortedError();
    }
    ParallelFor(0, blocks, 1,
      [&](std::size_t b0, std::size_t b1)
      {
        for (std::size_t b = b0; b < b1; ++b)
        {
          for (std::size_t q = 0; q < perBlock; ++q)
          {
            const std::size_t item = start + b * perBlock + q;
            if (item < count)
            {
              work(b, item);
            }
          }
        }
      });
  }
  if (!ReportProgress(progress, end))
  {
    throw AbortedError();
  }
}

std::string LightFieldSettings::Validate() const
{
  std::ostringstream e;
  if (this->RaysPerSide < 1 || this->RaysPerSide > 4096)
  {
    e << "rays per side " << this->RaysPerSide << " is outside [1, 4096]";
  }
  else if (this->TilesPerSide < 1 || this->TilesPerSide > this->RaysPerSide)
  {
    e << "tiles per side " << this->TilesPerSide
      << " is outside [1, rays per side = " << this->RaysPerSide << "]";
  }
  else if (this->RaysPerSide % this->TilesPerSide != 0)
  {
    e << "rays per side " << this->RaysPerSide << " is not a multiple of tiles per side "
      << this->TilesPerSide;
  }
  else if (!(this->TexelSize >= 0.0f) || !std::isfinite(this->TexelSize) ||
    (this->TexelSize > 0.0f && this->TexelSize < 1e-4f))
  {
    e << "texel size " << this->TexelSize << " is not 0 (= cell size) or in [1e-4, inf)";
  }
  else if (this->ContactTexelHalvings < 0 || this->ContactTexelHalvings > MaxContactTexelHalvings)
  {
    e << "contact texel halvings " << this->ContactTexelHalvings << " is outside [0, "
      << MaxContactTexelHalvings << "]";
  }
  else if (std::any_of(this->SurfaceTexelLevels.begin(), this->SurfaceTexelLevels.end(),
             [](std::int8_t l) { return l < MinSurfaceTexelLevel || l > MaxSurfaceTexelLevel; }))
  {
    e << "a surface texel level is outside [" << MinSurfaceTexelLevel << ", "
      << MaxSurfaceTexelLevel << "]";
  }
  else if (this->MemoryBudget == 0)
  {
    e << "memory budget is 0 bytes";
  }
  return e.str();
}

double LightField::IterationEnergy::ConservationError() const
{
  double worst = 0.0;
  for (int c = 0; c < 3; ++c)
  {
    const double out = this->Escaped[c] + this->Absorbed[c] + this->BackFaces[c] +
      this->SpecularLost[c] + this->Unshot[c];
    if (this->Shot[c] > 0.0)
    {
      worst = std::max(worst, std::abs(this->Shot[c] - out) / this->Shot[c]);
    }
    else if (out > 0.0)
    {
      worst = std::max(worst, 1.0);
    }
  }
  return worst;
}

glm::vec2 Surface::TexelCoordinates(const glm::vec3& x) const
{
  const glm::vec3 r = x - this->Origin;
  return glm::vec2(
    glm::dot(r, this->AxisU) / this->TexelU - 0.5f, glm::dot(r, this->AxisV) / this->TexelV - 0.5f);
}

glm::vec3 Surface::TexelCentre(int a, int b) const
{
  return this->Origin + (static_cast<float>(a) + 0.5f) * this->TexelU * this->AxisU +
    (static_cast<float>(b) + 0.5f) * this->TexelV * this->AxisV;
}

std::vector<std::uint8_t> ContactSurfaces(const TriangleScene& scene,
  const std::vector<Surface>& surfaces, const std::vector<std::uint32_t>& triangleSurface,
  float probe)
{
  const float onPlane = 1e-4f; // as GroupSurfaces' planes
  const std::size_t triangles = scene.TriangleCount();
  std::vector<glm::vec3> normal(triangles), lower(triangles), upper(triangles);
  for (std::size_t t = 0; t < triangles; ++t)
  {
    const glm::vec3 n = scene.FaceNormal(t);
    const float length = glm::length(n);
    normal[t] = length > 0.0f ? n / length : glm::vec3(0.0f);
    lower[t] = glm::min(scene.Vertex(t, 0), glm::min(scene.Vertex(t, 1), scene.Vertex(t, 2)));
    upper[t] = glm::max(scene.Vertex(t, 0), glm::max(scene.Vertex(t, 1), scene.Vertex(t, 2)));
  }
  std::vector<std::uint8_t> contact(surfaces.size(), 0);
  std::vector<glm::vec2> corners;
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    const Surface& s = surfaces[i];
    const auto flat = [&s](const glm::vec3& x)
    { return glm::vec2(glm::dot(x, s.AxisU), glm::dot(x, s.AxisV)); };
    corners.clear();
    glm::vec3 boxLower(1e30f), boxUpper(-1e30f);
    for (const std::uint32_t t : s.Triangles)
    {
      for (int c = 0; c < 3; ++c)
      {
        corners.push_back(flat(scene.Vertex(t, c)));
      }
      boxLower = glm::min(boxLower, lower[t]);
      boxUpper = glm::max(boxUpper, upper[t]);
    }
    boxLower -= glm::vec3(2.0f * onPlane);
    boxUpper += glm::vec3(2.0f * onPlane);
    const auto inside = [&corners](const glm::vec2& q)
    {
      for (std::size_t c = 0; c + 2 < corners.size(); c += 3)
      {
        const glm::vec2 a = corners[c], b = corners[c + 1], d = corners[c + 2];
        const float area = (b.x - a.x) * (d.y - a.y) - (b.y - a.y) * (d.x - a.x);
        const float u = ((b.x - q.x) * (d.y - q.y) - (b.y - q.y) * (d.x - q.x)) / area;
        const float v = ((d.x - q.x) * (a.y - q.y) - (d.y - q.y) * (a.x - q.x)) / area;
        if (u >= 0.0f && v >= 0.0f && u + v <= 1.0f)
        {
          return true;
        }
      }
      return false;
    };
    for (std::size_t t = 0; t < triangles && contact[i] == 0; ++t)
    {
      if (triangleSurface[t] == NoSurface || triangleSurface[t] == i ||
        std::abs(glm::dot(normal[t], s.Normal)) > 0.99f ||
        glm::any(glm::lessThan(upper[t], boxLower)) ||
        glm::any(glm::greaterThan(lower[t], boxUpper)))
      {
        continue; // another surface, parallel to this one (coincident faces), or far from it
      }
      float d[3];
      for (int c = 0; c < 3; ++c)
      {
        d[c] = glm::dot(s.Normal, scene.Vertex(t, c)) - s.Offset;
      }
      for (int a = 0; a < 3; ++a)
      {
        const int b = (a + 1) % 3, o = (a + 2) % 3;
        if (std::abs(d[a]) > onPlane || std::abs(d[b]) > onPlane || d[o] <= onPlane)
        {
          continue; // not an edge on the plane of a triangle rising in front of it
        }
        const glm::vec2 pa = flat(scene.Vertex(t, a)), pb = flat(scene.Vertex(t, b));
        const float length = glm::length(pb - pa);
        if (!(length > 0.0f))
        {
          continue;
        }
        const glm::vec2 across = probe * glm::vec2(pa.y - pb.y, pb.x - pa.x) / length;
        const glm::vec2 middle = 0.5f * (pa + pb);
        if (inside(middle + across) && inside(middle - across))
        {
          contact[i] = 1;
          break;
        }
      }
    }
  }
  return contact;
}

std::vector<Surface> GroupSurfaces(const TriangleScene& scene, float texelSize,
  std::vector<std::uint32_t>& triangleSurface, int contactHalvings,
  const std::vector<std::int8_t>& levels)
{
  std::vector<Surface> surfaces;
  triangleSurface.assign(scene.TriangleCount(), 0);
  std::map<std::tuple<std::uint32_t, long, long, long, long>, std::uint32_t> byPlane;
  const float quantum = 1e4f; // planes equal within 1e-4 share a surface
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const glm::vec3 doubleArea = scene.FaceNormal(t);
    const float length = glm::length(doubleArea);
    if (!(length > 0.0f) || !std::isfinite(length))
    {
      triangleSurface[t] = NoSurface; // degenerate: Embree never reports hits on it
      continue;
    }
    const glm::vec3 n = doubleArea / length;
    const float offset = glm::dot(n, scene.Vertex(t, 0));
    const auto key = std::make_tuple(scene.MaterialIds[t], std::lround(n.x * quantum),
      std::lround(n.y * quantum), std::lround(n.z * quantum), std::lround(offset * quantum));
    auto found = byPlane.find(key);
    if (found == byPlane.end())
    {
      Surface s;
      s.Material = scene.MaterialIds[t];
      s.Normal = n;
      s.Offset = offset;
      // Texture axes along the first triangle's first edge: a fan-triangulated rectangle then
      // gets a texture that fits it exactly.
      const glm::vec3 edge = scene.Vertex(t, 1) - scene.Vertex(t, 0);
      s.AxisU = glm::normalize(edge - glm::dot(edge, n) * n);
      s.AxisV = glm::cross(n, s.AxisU);
      s.Origin = scene.Vertex(t, 0);
      found = byPlane.emplace(key, static_cast<std::uint32_t>(surfaces.size())).first;
      surfaces.push_back(s);
    }
    Surface& s = surfaces[found->second];
    s.Triangles.push_back(static_cast<std::uint32_t>(t));
    s.Area += static_cast<double>(scene.Area(t));
    triangleSurface[t] = found->second;
  }
  // Finer texels where other surfaces stand (LightFieldSettings::ContactTexelHalvings); probed a
  // quarter texel either side of a contact edge.
  // Per-surface levels (LightFieldSettings::SurfaceTexelLevels) replace the contact halvings.
  if (!levels.empty() && levels.size() != surfaces.size())
  {
    throw std::invalid_argument("the surface texel levels name " + std::to_string(levels.size()) +
      " surfaces; the scene has " + std::to_string(surfaces.size()));
  }
  const std::vector<std::uint8_t> contact = contactHalvings > 0 && levels.empty()
    ? ContactSurfaces(scene, surfaces, triangleSurface, 0.25f * texelSize)
    : std::vector<std::uint8_t>(surfaces.size(), 0);
  std::size_t texelOffset = 0;
  for (std::size_t i = 0; i < surfaces.size(); ++i)
  {
    Surface& s = surfaces[i];
    const float texel = !levels.empty() ? std::ldexp(texelSize, levels[i])
      : contact[i] != 0                 ? texelSize / static_cast<float>(1 << contactHalvings)
                                        : texelSize;
    float lo[2] = { 1e30f, 1e30f }, hi[2] = { -1e30f, -1e30f };
    const glm::vec3 reference = s.Origin;
    for (std::uint32_t t : s.Triangles)
    {
      for (int c = 0; c < 3; ++c)
      {
        const glm::vec3 r = scene.Vertex(t, c) - reference;
        const float st[2] = { glm::dot(r, s.AxisU), glm::dot(r, s.AxisV) };
        for (int a = 0; a < 2; ++a)
        {
          lo[a] = std::min(lo[a], st[a]);
          hi[a] = std::max(hi[a], st[a]);
        }
      }
    }
    const float extentU = std::max(hi[0] - lo[0], 1e-6f);
    const float extentV = std::max(hi[1] - lo[1], 1e-6f);
    // Sides in double: a scene far larger than the texel (a corrupt snapshot's scene is not
    // normalized) must be refused, not overflow int (found by fuzz/snapshot.cxx).
    const double sideU = std::ceil(static_cast<double>(extentU / texel) - 1e-3);
    const double sideV = std::ceil(static_cast<double>(extentV / texel) - 1e-3);
    if (!(sideU <= MaxTextureSide) || !(sideV <= MaxTextureSide))
    {
      throw std::invalid_argument("a surface of the scene would need a texture of " +
        std::to_string(sideU) + " x " + std::to_string(sideV) + " texels (at most " +
        std::to_string(MaxTextureSide) + " per side)");
    }
    s.TextureWidth = std::max(1, static_cast<int>(sideU));
    s.TextureHeight = std::max(1, static_cast<int>(sideV));
    s.TexelU = extentU / static_cast<float>(s.TextureWidth);
    s.TexelV = extentV / static_cast<float>(s.TextureHeight);
    // Origin on the plane at the rectangle's lower corner.
    const glm::vec3 onPlane = reference - (glm::dot(s.Normal, reference) - s.Offset) * s.Normal;
    s.Origin = onPlane + lo[0] * s.AxisU + lo[1] * s.AxisV;
    s.TexelOffset = texelOffset;
    texelOffset += s.TexelCount();
  }
  return surfaces;
}

void LightField::Setup(
  const TriangleScene& scene, const LightFieldSettings& settings, bool normalize)
{
  const std::string problem = settings.Validate();
  if (!problem.empty())
  {
    throw std::invalid_argument(problem);
  }
  const SceneCheck check = CheckScene(scene, /*requireEmitter=*/true);
  if (!check.Ok())
  {
    throw std::invalid_argument("the scene cannot be used: " + Join(check.Errors));
  }
  for (const SceneMaterial& m : scene.Materials)
  {
    const glm::vec3 reflect = m.Diffuse + m.Specular;
    if (reflect.x > 1.0f || reflect.y > 1.0f || reflect.z > 1.0f || m.Diffuse.x < 0.0f ||
      m.Diffuse.y < 0.0f || m.Diffuse.z < 0.0f || m.Specular.x < 0.0f || m.Specular.y < 0.0f ||
      m.Specular.z < 0.0f)
    {
      throw std::invalid_argument("material '" + m.Name +
        "' reflects more light than it receives or a negative amount (Kd + Ks must lie in [0, 1] "
        "per channel)");
    }
    this->AnySpecular = this->AnySpecular || glm::length(m.Specular) > 0.0f;
  }
  this->Config = settings;
  this->NormalizedScene = scene;
  if (normalize)
  {
    glm::vec3 lower, upper;
    SceneBounds(scene, lower, upper);
    this->Centre = 0.5f * (lower + upper);
    this->Scale = NormalizeToUnitSphere(this->NormalizedScene);
  }
  // The direction set (its lattice holds about two points per direction) and the subfields are
  // allocated before the full estimate below: refuse a count whose share alone exceeds the budget
  // (a corrupt snapshot's count; a 2n^2+1 count up to n = 4096 is otherwise valid).
  const std::uint64_t perDirection = sizeof(Subfield) + 2 * sizeof(glm::vec3) + sizeof(double) +
    (static_cast<std::uint64_t>(settings.TilesPerSide) * settings.TilesPerSide + 1) *
      sizeof(std::uint32_t);
  if (settings.Directions > settings.MemoryBudget / perDirection)
  {
    throw MemoryBudgetError("the light field's " + std::to_string(settings.Directions) +
      " directions alone (each of " + std::to_string(settings.RaysPerSide) + "x" +
      std::to_string(settings.RaysPerSide) + " rays in " + std::to_string(settings.TilesPerSide) +
      "x" + std::to_string(settings.TilesPerSide) +
      " tiles) would need more than the memory budget of " + FormatBytes(settings.MemoryBudget) +
      "; use fewer directions or rays per side, or raise the budget");
  }
  this->DirectionsPtr.reset(new DirectionSet(DirectionSet::WithCount(settings.Directions)));
  const float texel = settings.TexelSize > 0.0f ? settings.TexelSize : settings.CellSize();
  this->SurfaceList = GroupSurfaces(this->NormalizedScene, texel, this->TriangleSurface,
    settings.ContactTexelHalvings, settings.SurfaceTexelLevels);
  this->TexelTotal = 0;
  for (const Surface& s : this->SurfaceList)
  {
    this->TexelTotal += s.TexelCount();
  }
  this->EstimateUsed = EstimateWithinBudget(this->NormalizedScene, this->SurfaceList,
    *this->DirectionsPtr, settings, this->AnySpecular, this->BudgetShareRanks);
  // A distributed field holds about 1/ranks of the maps on each rank (Distribution.h).
  if (this->EstimateUsed.TotalBytes - this->EstimateUsed.MapBytes +
      this->EstimateUsed.MapBytes / this->BudgetShareRanks >
    settings.MemoryBudget)
  {
    std::ostringstream message;
    message << "the light field would need "
            << (this->EstimateUsed.SampleStride > 1 ? "" : "up to ")
            << this->EstimateUsed.Describe() << " for " << settings.Directions << " directions x "
            << settings.RaysPerSide << "x" << settings.RaysPerSide
            << " rays, above the memory budget of " << FormatBytes(settings.MemoryBudget)
            << "; use fewer directions or rays per side, or raise the budget";
    throw MemoryBudgetError(message.str());
  }
  const std::size_t count = this->DirectionsPtr->Size();
  this->Subfields.assign(count, Subfield());
  const float uniform = 2.0f * Pi<float> / static_cast<float>(count);
  for (std::size_t k = 0; k < count; ++k)
  {
    Subfield& f = this->Subfields[k];
    f.Direction = this->DirectionsPtr->Direction(k);
    SubfieldFrame(k, f.Direction, f.AxisU, f.AxisV);
    f.Weight = settings.UseSolidAngleWeights ? this->DirectionsPtr->SolidAngle(k) : uniform;
  }
}

std::unique_ptr<LightField> LightField::CreateEmpty(
  const TriangleScene& scene, const LightFieldSettings& settings)
{
  std::unique_ptr<LightField> field(new LightField());
  field->Setup(scene, settings, /*normalize=*/true);
  return field;
}

std::unique_ptr<LightField> LightField::Build(
  const TriangleScene& scene, const LightFieldSettings& settings, const ProgressCallback& progress)
{
  return Build(scene, settings, progress, nullptr);
}

std::unique_ptr<LightField> LightField::Build(const TriangleScene& scene,
  const LightFieldSettings& settings, const ProgressCallback& progress, Reducer* reducer)
{
  std::unique_ptr<LightField> field(new LightField());
  const bool distributed = reducer && reducer->Size() > 1;
  if (distributed)
  {
    field->BudgetShareRanks = static_cast<std::size_t>(reducer->Size());
    Agree(*reducer,
      [&]()
      {
        field->Setup(scene, settings, /*normalize=*/true);
        const std::vector<std::uint32_t> owner = BalanceDirections(*field, reducer->Size());
        field->OwnedSubfields.assign(owner.size(), 0);
        for (std::size_t k = 0; k < owner.size(); ++k)
        {
          field->OwnedSubfields[k] = owner[k] == static_cast<std::uint32_t>(reducer->Rank());
        }
      });
  }
  else
  {
    field->Setup(scene, settings, /*normalize=*/true);
  }
  const EmbreeScene embree(field->NormalizedScene);
  const std::size_t count = field->Subfields.size();
  std::exception_ptr failure;
  try
  {
    RunInBlocks(count, DefaultBlockCount(count), progress, 0.0, 0.8,
      [&](std::size_t, std::size_t k)
      {
        if (field->OwnsSubfield(k))
        {
          field->TraceSubfield(k, embree);
        }
      });
  }
  catch (...)
  {
    failure = std::current_exception();
  }
  if (distributed)
  {
    AgreeOnFailure(*reducer, failure);
  }
  else if (failure)
  {
    std::rethrow_exception(failure);
  }

  // Shooting capacity of each texel (Propagation.h): the flux a unit diffuse radiance there
  // sends along all lines that leave it into the scene (not into a solid: Receiver), sum over
  // those crossings of w_texel * cellArea * weight_k.
  // It is the discrete counterpart of pi * texelArea (Wither 2005 §3.6.3's total projected cell
  // area).
  const std::size_t texels = field->TexelTotal;
  const std::size_t blocks = DefaultBlockCount(count);
  std::vector<std::vector<double>> partial(blocks, std::vector<double>(texels, 0.0));
  const float cellArea = settings.CellSize() * settings.CellSize();
  const int n = settings.RaysPerSide;
  // Distributed: an abort here is left to the first agreed step after (propagation's).
  ProgressCallback capacityProgress = progress;
  if (distributed && progress)
  {
    capacityProgress = [progress](double f)
    {
      progress(f);
      return true;
    };
  }
  RunInBlocks(count, blocks, capacityProgress, 0.8, 1.0,
    [&](std::size_t b, std::size_t k)
    {
      if (!field->OwnsSubfield(k))
      {
        return;
      }
      std::vector<Crossing> crossings;
      const Subfield& f = field->Subfields[k];
      for (int j = 0; j < n; ++j)
      {
        for (int i = 0; i < n; ++i)
        {
          field->LineCrossings(k, i, j, crossings);
          for (std::size_t q = 0; q < crossings.size(); ++q)
          {
            // A line from the texel into a solid (or a coincident face) carries nothing the
            // surface shows: counting it would dilute the visible part's radiance.
            const Crossing& c = crossings[q];
            if (field->Orientation(k, c.Surface) == 0 ||
              field->Receiver(k, crossings, q) == LightField::LineBlocked)
            {
              continue;
            }
            const TexelWeights w =
              field->WeightsAt(c.Surface, field->PointOnLine(k, i, j, c.Depth));
            for (int t = 0; t < 4; ++t)
            {
              partial[b][w.Texel[t]] += static_cast<double>(w.Weight[t] * cellArea * f.Weight);
            }
          }
        }
      }
    });
  field->Capacity.assign(texels, 0.0f);
  for (std::size_t t = 0; t < texels; ++t)
  {
    double sum = 0.0;
    for (const std::vector<double>& p : partial)
    {
      sum += p[t];
    }
    partial[0][t] = sum;
  }
  if (distributed)
  {
    reducer->SumInPlace(partial[0].data(), texels); // every direction's lines, all ranks
  }
  for (std::size_t t = 0; t < texels; ++t)
  {
    field->Capacity[t] = static_cast<float>(partial[0][t]);
  }
  // Emitters shoot first: before iteration 1 the unshot radiance is the emission.
  field->TotalDiffuse.assign(texels, glm::vec3(0.0f));
  for (std::size_t s = 0; s < field->SurfaceList.size(); ++s)
  {
    const Surface& surface = field->SurfaceList[s];
    const glm::vec3 emission = field->NormalizedScene.Materials[surface.Material].Emission;
    std::fill(field->TotalDiffuse.begin() + static_cast<std::ptrdiff_t>(surface.TexelOffset),
      field->TotalDiffuse.begin() +
        static_cast<std::ptrdiff_t>(surface.TexelOffset + surface.TexelCount()),
      emission);
  }
  field->UnshotDiffuse = field->TotalDiffuse;
  // An emitter no line leaves (every direction parallel to it, or it is smaller than a cell, as
  // when one far vertex shrinks the rest of the scene) shoots nothing: the field would stay dark
  // however long it propagates, so say so now.
  double emitterCapacity = 0.0;
  for (const Surface& surface : field->SurfaceList)
  {
    const glm::vec3 emission = field->NormalizedScene.Materials[surface.Material].Emission;
    if (emission.x + emission.y + emission.z > 0.0f)
    {
      for (std::size_t t = 0; t < surface.TexelCount(); ++t)
      {
        emitterCapacity += field->Capacity[surface.TexelOffset + t];
      }
    }
  }
  if (!(emitterCapacity > 0.0))
  {
    std::ostringstream e;
    e << "no line of the light field leaves an emitter (" << settings.Directions << " directions x "
      << settings.RaysPerSide << "x" << settings.RaysPerSide
      << " rays), so nothing would ever be shot: ";
    if (settings.Directions < 33)
    {
      e << "so few directions may all lie along the emitters; use more (e.g. 513)";
    }
    else
    {
      e << "the emitters are smaller than a line cell once the scene is scaled into the unit "
           "sphere; check the scene for triangles far from the rest, or use more rays";
    }
    throw std::invalid_argument(e.str());
  }
  return field;
}

void LightField::TraceSubfield(std::size_t k, const EmbreeScene& embree)
{
  Subfield& f = this->Subfields[k];
  const int n = this->Config.RaysPerSide;
  const int m = this->Config.TilesPerSide;
  const int ts = this->Config.TileSide();
  const float h = this->Config.CellSize();
  struct Hit
  {
    std::uint32_t Tile, Surface, Local;
    float Depth;
  };
  std::vector<Hit> hits;
  alignas(64) SceneRay rays[16];
  alignas(64) SceneHit results[16];
  int cellOf[16];
  std::uint32_t lastSurface[16];
  for (int j = 0; j < n; ++j)
  {
    const float b = -1.0f + (static_cast<float>(j) + 0.5f) * h;
    for (int i0 = 0; i0 < n; i0 += 16)
    {
      int count = 0;
      for (int i = i0; i < std::min(n, i0 + 16); ++i)
      {
        const float a = -1.0f + (static_cast<float>(i) + 0.5f) * h;
        if (a * a + b * b > 1.0001f)
        {
          continue; // the line misses the unit sphere
        }
        rays[count].Origin = a * f.AxisU + b * f.AxisV - LineStart * f.Direction;
        rays[count].Direction = f.Direction;
        rays[count].TNear = 0.0f;
        rays[count].TFar = 2.0f * LineStart;
        cellOf[count] = i;
        lastSurface[count] = SceneHit::None;
        ++count;
      }
      // Repeated nearest hits: every crossing along the line, in depth order.
      while (count > 0)
      {
        embree.Intersect16(rays, results, count);
        int alive = 0;
        for (int r = 0; r < count; ++r)
        {
          if (!results[r].Hit())
          {
            continue;
          }
          const std::uint32_t s = this->TriangleSurface[results[r].Triangle];
          if (s != NoSurface && s != lastSurface[r] && this->Orientation(k, s) != 0)
          {
            const int i = cellOf[r];
            const std::uint32_t tile = static_cast<std::uint32_t>((j / ts) * m + i / ts);
            const std::uint32_t local = static_cast<std::uint32_t>((j % ts) * ts + i % ts);
            hits.push_back({ tile, s, local, results[r].T });
            lastSurface[r] = s;
          }
          rays[alive] = rays[r];
          rays[alive].TNear = NextQueryStart(results[r].T);
          cellOf[alive] = cellOf[r];
          lastSurface[alive] = lastSurface[r];
          ++alive;
        }
        count = alive;
      }
    }
  }
  std::sort(hits.begin(), hits.end(),
    [](const Hit& x, const Hit& y)
    { return std::tie(x.Tile, x.Surface, x.Local) < std::tie(y.Tile, y.Surface, y.Local); });
  const std::size_t tiles = static_cast<std::size_t>(m) * m;
  f.TileStart.assign(tiles + 1, 0);
  f.Entries.clear();
  for (std::size_t q = 0; q < hits.size(); ++q)
  {
    if (q == 0 || hits[q].Tile != hits[q - 1].Tile || hits[q].Surface != hits[q - 1].Surface)
    {
      f.Entries.push_back({ hits[q].Surface, static_cast<std::uint32_t>(f.Entries.size()) });
      ++f.TileStart[hits[q].Tile + 1];
    }
  }
  for (std::size_t t = 0; t < tiles; ++t)
  {
    f.TileStart[t + 1] += f.TileStart[t];
  }
  // Maps numbered mirrors first: their crossings take the first slots, the only ones whose
  // radiance is stored (SpecularSlots, SentRadiance).
  std::uint32_t next = 0;
  for (int pass = 0; pass < 2; ++pass)
  {
    for (TileEntry& e : f.Entries)
    {
      if (this->StoresRadiance(e.Surface) == (pass == 0))
      {
        e.Map = next++;
      }
    }
  }
  const std::size_t cellsPerMap = static_cast<std::size_t>(ts) * ts;
  // One crossing per cell (a line crosses a plane once; a hit on a shared edge may repeat it),
  // in slot order: by map, then cell.
  struct Found
  {
    std::size_t Cell;
    float Depth;
    std::uint32_t Surface;
    std::int32_t I, J;
  };
  std::vector<Found> found;
  found.reserve(hits.size());
  std::size_t entry = 0;
  for (std::size_t q = 0; q < hits.size(); ++q)
  {
    if (q > 0 && (hits[q].Tile != hits[q - 1].Tile || hits[q].Surface != hits[q - 1].Surface))
    {
      ++entry;
    }
    const std::size_t cell = f.Entries[entry].Map * cellsPerMap + hits[q].Local;
    if (q > 0 && hits[q].Tile == hits[q - 1].Tile && hits[q].Surface == hits[q - 1].Surface &&
      hits[q].Local == hits[q - 1].Local)
    {
      found.back().Depth = hits[q].Depth;
      continue;
    }
    found.push_back({ cell, hits[q].Depth, hits[q].Surface,
      static_cast<std::int32_t>((hits[q].Tile % m) * ts + hits[q].Local % ts),
      static_cast<std::int32_t>((hits[q].Tile / m) * ts + hits[q].Local / ts) });
  }
  std::sort(
    found.begin(), found.end(), [](const Found& x, const Found& y) { return x.Cell < y.Cell; });
  std::vector<std::size_t> occupied(found.size());
  std::vector<float> depth(found.size());
  std::vector<std::uint32_t> mapOf(found.size());
  for (std::size_t q = 0; q < found.size(); ++q)
  {
    occupied[q] = found[q].Cell;
    depth[q] = found[q].Depth;
    mapOf[q] = static_cast<std::uint32_t>(found[q].Cell / cellsPerMap);
  }
  f.Cells.Build(f.Entries.size(), cellsPerMap, occupied);
  // Depths: none for maps whose crossings lie on their surface's plane (CrossingDepths).
  std::vector<std::uint8_t> offPlane(f.Entries.size(), 0);
  for (std::size_t q = 0; q < occupied.size(); ++q)
  {
    const float plane = this->PlaneDepth(k, found[q].I, found[q].J, found[q].Surface);
    if (!(std::abs(plane - depth[q]) <= PlaneDepthTolerance))
    {
      offPlane[mapOf[q]] = 1;
    }
  }
  f.Depth.Clear();
  f.Depth.Start.assign(f.Entries.size(), CrossingDepths::FromPlane);
  for (std::size_t e = 0; e < f.Entries.size(); ++e)
  {
    if (offPlane[e])
    {
      f.Depth.Start[e] = static_cast<std::uint32_t>(f.Depth.Values.size());
      const std::size_t first = f.Cells.MapFirstSlot(e);
      f.Depth.Values.insert(f.Depth.Values.end(),
        depth.begin() + static_cast<std::ptrdiff_t>(first),
        depth.begin() + static_cast<std::ptrdiff_t>(first + f.Cells.MapSlots(e)));
    }
  }
  f.Depth.Values.shrink_to_fit();
  f.Entries.shrink_to_fit(); // grown by push_back: up to twice its size otherwise
  // Radiance of the mirrors' crossings only: the others' follows from the textures.
  f.Radiance.assign(this->SpecularSlots(f), glm::vec3(0.0f));
  f.UnshotSpecular.assign(this->SpecularSlots(f), glm::vec3(0.0f));
  this->MarkBlocked(k);
}

std::uint64_t LightField::AllocatedBytes() const
{
  std::uint64_t bytes = 0;
  for (const Subfield& f : this->Subfields)
  {
    bytes += f.Depth.Bytes() + f.Radiance.Bytes() + f.UnshotSpecular.Bytes() + f.Cells.Bytes() +
      f.Entries.capacity() * sizeof(TileEntry) + f.TileStart.capacity() * sizeof(std::uint32_t) +
      sizeof(Subfield);
  }
  bytes += (this->TotalDiffuse.capacity() + this->UnshotDiffuse.capacity() +
             this->PropagatedDiffuse.capacity()) *
      sizeof(glm::vec3) +
    this->Capacity.capacity() * sizeof(float);
  return bytes;
}

void LightField::CompactRadiance()
{
  ParallelFor(0, this->Subfields.size(), 1,
    [this](std::size_t k0, std::size_t k1)
    {
      for (std::size_t k = k0; k < k1; ++k)
      {
        this->Subfields[k].Radiance.MakeCompact();
        this->Subfields[k].UnshotSpecular.MakeCompact();
      }
    });
}

bool LightField::StoresRadiance(std::uint32_t surface) const
{
  const glm::vec3& ks = this->MaterialOf(surface).Specular;
  return ks.x > 0.0f || ks.y > 0.0f || ks.z > 0.0f;
}

std::size_t LightField::SpecularSlots(const Subfield& f) const
{
  std::size_t maps = 0;
  for (const TileEntry& e : f.Entries)
  {
    maps += this->StoresRadiance(e.Surface) ? 1 : 0;
  }
  return maps < f.Cells.Maps() ? f.Cells.MapFirstSlot(maps) : f.Cells.Slots();
}

} // namespace vlf
} // namespace mesolight
