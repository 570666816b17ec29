// SPDX-License-Identifier: BSD-3-Clause
#include "FinalGather.h"

#include "Distribution.h"
#include "Luminance.h"

#include "MathConstants.h"
#include "OrthonormalBasis.h"
#include "ParallelFor.h"

#include "EmbreeScene.h"
#include "RandomSequence.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <atomic>
#include <chrono>
#include <cmath>
#include <stdexcept>

namespace mesolight
{
namespace vlf
{
namespace
{

// Mirrors followed in a row from one gathered ray (a light path between two facing mirrors ends
// there).
constexpr int MirrorBounces = 4;

// One emitter triangle for next-event estimation.
struct EmitterTriangle
{
  glm::vec3 A{ 0.0f }, B{ 0.0f }, C{ 0.0f };
  glm::vec3 Normal{ 0.0f, 0.0f, 1.0f }; // front, unit
  glm::vec3 Emission{ 0.0f };
  float Area = 0.0f;
};

struct Emitters
{
  std::vector<EmitterTriangle> Triangles;
  std::vector<float> Cumulative; // of area x luminance, last = Total
  float Total = 0.0f;

  // Index of the triangle for u in [0, 1) and its probability.
  std::size_t Pick(float u, float& probability) const
  {
    const float target = u * this->Total;
    std::size_t i = static_cast<std::size_t>(
      std::upper_bound(this->Cumulative.begin(), this->Cumulative.end(), target) -
      this->Cumulative.begin());
    i = std::min(i, this->Triangles.size() - 1);
    const float before = i == 0 ? 0.0f : this->Cumulative[i - 1];
    probability = (this->Cumulative[i] - before) / this->Total;
    return i;
  }
};

Emitters CollectEmitters(const TriangleScene& scene)
{
  Emitters e;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const SceneMaterial& m = scene.MaterialOf(t);
    const float power = Luminance(m.Emission.x, m.Emission.y, m.Emission.z);
    const glm::vec3 n = scene.FaceNormal(t);
    const float twiceArea = glm::length(n);
    if (!(power > 0.0f) || !(twiceArea > 0.0f))
    {
      continue;
    }
    EmitterTriangle tri;
    tri.A = scene.Vertex(t, 0);
    tri.B = scene.Vertex(t, 1);
    tri.C = scene.Vertex(t, 2);
    tri.Normal = n / twiceArea;
    tri.Emission = m.Emission;
    tri.Area = 0.5f * twiceArea;
    e.Total += tri.Area * power;
    e.Triangles.push_back(tri);
    e.Cumulative.push_back(e.Total);
  }
  return e;
}

// A surface's triangles in its continuous texel coordinates (texel centres at integers), and per
// texel the triangles whose bounding box reaches it.
struct SurfaceTriangles
{
  std::vector<std::array<glm::vec2, 3>> Triangles;
  // Their corners in unit-sphere coordinates: a surface groups triangles within 1e-4 of one
  // plane, so points are put on the triangle itself, not on the surface's plane (which may lie
  // that far inside a box whose top joined its neighbours' slightly lower ones).
  std::vector<std::array<glm::vec3, 3>> Corners;
  std::vector<std::uint32_t> Start; // per texel + 1: offsets into Lists
  std::vector<std::uint32_t> Lists;
};

SurfaceTriangles BucketTriangles(const LightField& field, const Surface& s)
{
  SurfaceTriangles out;
  const TriangleScene& scene = field.Scene();
  const std::size_t texels = s.TexelCount();
  std::vector<std::uint32_t> counts(texels + 1, 0);
  std::vector<std::array<int, 4>> boxes;
  for (const std::uint32_t t : s.Triangles)
  {
    std::array<glm::vec2, 3> tri;
    glm::vec2 lo(1e30f), hi(-1e30f);
    for (int c = 0; c < 3; ++c)
    {
      tri[c] = s.TexelCoordinates(scene.Vertex(t, c));
      lo = glm::min(lo, tri[c]);
      hi = glm::max(hi, tri[c]);
    }
    // Texel (a, b) covers [a - 1/2, a + 1/2] x [b - 1/2, b + 1/2].
    const std::array<int, 4> box = { std::max(0, static_cast<int>(std::floor(lo.x + 0.5f))),
      std::min(s.TextureWidth - 1, static_cast<int>(std::floor(hi.x + 0.5f))),
      std::max(0, static_cast<int>(std::floor(lo.y + 0.5f))),
      std::min(s.TextureHeight - 1, static_cast<int>(std::floor(hi.y + 0.5f))) };
    out.Triangles.push_back(tri);
    out.Corners.push_back({ scene.Vertex(t, 0), scene.Vertex(t, 1), scene.Vertex(t, 2) });
    boxes.push_back(box);
    for (int b = box[2]; b <= box[3]; ++b)
    {
      for (int a = box[0]; a <= box[1]; ++a)
      {
        ++counts[static_cast<std::size_t>(b) * s.TextureWidth + a + 1];
      }
    }
  }
  for (std::size_t i = 0; i < texels; ++i)
  {
    counts[i + 1] += counts[i];
  }
  out.Start = counts;
  out.Lists.resize(counts[texels]);
  for (std::size_t q = 0; q < boxes.size(); ++q)
  {
    const std::array<int, 4>& box = boxes[q];
    for (int b = box[2]; b <= box[3]; ++b)
    {
      for (int a = box[0]; a <= box[1]; ++a)
      {
        out.Lists[counts[static_cast<std::size_t>(b) * s.TextureWidth + a]++] =
          static_cast<std::uint32_t>(q);
      }
    }
  }
  return out;
}

// Whether p lies in t; if so, b1 and b2 get its barycentric weights of t[1] and t[2].
bool InsideTriangle(const std::array<glm::vec2, 3>& t, const glm::vec2& p, float& b1, float& b2)
{
  const auto edge = [](const glm::vec2& a, const glm::vec2& b, const glm::vec2& q)
  { return (b.x - a.x) * (q.y - a.y) - (b.y - a.y) * (q.x - a.x); };
  const float d0 = edge(t[0], t[1], p);
  const float d1 = edge(t[1], t[2], p);
  const float d2 = edge(t[2], t[0], p);
  const bool negative = d0 < 0.0f || d1 < 0.0f || d2 < 0.0f;
  const bool positive = d0 > 0.0f || d1 > 0.0f || d2 > 0.0f;
  const float area = d0 + d1 + d2;
  if ((negative && positive) || area == 0.0f)
  {
    return false;
  }
  b1 = d2 / area;
  b2 = d0 / area;
  return true;
}

// Cosine-distributed direction in the frame (u, v, n) from a point of the unit square.
glm::vec3 CosineDirection(
  const glm::vec3& u, const glm::vec3& v, const glm::vec3& n, float r1, float r2)
{
  const float phi = 2.0f * Pi<float> * r1;
  const float radius = std::sqrt(r2);
  const float z = std::sqrt(std::max(0.0f, 1.0f - r2));
  return radius * std::cos(phi) * u + radius * std::sin(phi) * v + z * n;
}

struct TexelResult
{
  glm::vec3 Value{ 0.0f };
  bool Gathered = false;
  std::uint32_t Rays = 0;
};

class Gatherer
{
public:
  Gatherer(const LightField& field, const FinalGatherOptions& options)
    : Field(field)
    , Options(options)
    , Embree(field.Scene())
    , Light(CollectEmitters(field.Scene()))
    , Source(&field.TotalDiffuse)
  {
  }

  TexelResult Gather(
    std::uint32_t surfaceIndex, const SurfaceTriangles& tris, int a, int b, std::size_t texel) const
  {
    TexelResult result;
    const Surface& s = this->Field.Surfaces()[surfaceIndex];
    const std::size_t local = static_cast<std::size_t>(b) * s.TextureWidth + a;
    const std::uint32_t first = tris.Start[local];
    const std::uint32_t last = tris.Start[local + 1];
    if (first == last)
    {
      return result;
    }
    const SceneMaterial& material = this->Field.MaterialOf(surfaceIndex);
    const glm::vec3 n = s.Normal;
    glm::vec3 u, v;
    OrthonormalBasis(n, u, v);
    RandomSequence random(SampleSeed(this->Options.Sequence, texel, 0));

    // A jittered point of stratum q of a side x side grid over the texel, on a triangle of the
    // surface (a few tries), or false.
    const auto pointOf = [&](int q, int side, glm::vec3& x) -> bool
    {
      for (int attempt = 0; attempt < 6; ++attempt)
      {
        // The footprint first; a texel whose footprint misses the triangles (a polygon's edge
        // crosses it) tries its whole area.
        const float extent = attempt < 3 ? this->Options.Footprint : 1.0f;
        const float su = (static_cast<float>(q % side) + random.NextFloat()) / side;
        const float sv = (static_cast<float>(q / side) + random.NextFloat()) / side;
        const glm::vec2 p(static_cast<float>(a) + extent * (su - 0.5f),
          static_cast<float>(b) + extent * (sv - 0.5f));
        for (std::uint32_t i = first; i < last; ++i)
        {
          float b1 = 0.0f, b2 = 0.0f;
          const std::uint32_t q2 = tris.Lists[i];
          if (InsideTriangle(tris.Triangles[q2], p, b1, b2))
          {
            const std::array<glm::vec3, 3>& c = tris.Corners[q2];
            x = c[0] + b1 * (c[1] - c[0]) + b2 * (c[2] - c[0]) + this->Offset * n;
            return true;
          }
        }
      }
      return false;
    };

    // Indirect: stratified cosine directions, positions stratified independently (a shuffled
    // stratum per ray) so direction and position strata do not line up.
    const int rays = this->Options.IndirectRays;
    const int side = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(rays))));
    const int strata = side * side;
    std::vector<int> positions(static_cast<std::size_t>(strata));
    for (int q = 0; q < strata; ++q)
    {
      positions[q] = q;
    }
    for (int q = strata - 1; q > 0; --q)
    {
      std::swap(positions[q], positions[random.NextUInt() % static_cast<std::uint32_t>(q + 1)]);
    }
    glm::dvec3 indirect(0.0);
    int indirectValid = 0;
    for (int r = 0; r < rays; ++r)
    {
      const int q = r % strata;
      glm::vec3 x;
      if (!pointOf(positions[q], side, x))
      {
        continue;
      }
      const float r1 = r < strata ? (static_cast<float>(q % side) + random.NextFloat()) / side
                                  : random.NextFloat();
      const float r2 = r < strata ? (static_cast<float>(q / side) + random.NextFloat()) / side
                                  : random.NextFloat();
      SceneRay ray;
      ray.Origin = x;
      ray.Direction = CosineDirection(u, v, n, r1, r2);
      ++result.Rays;
      glm::vec3 l;
      if (this->ArrivingAlong(ray, l))
      {
        indirect += glm::dvec3(l);
        ++indirectValid;
      }
    }
    if (indirectValid == 0)
    {
      return result;
    }

    // Direct: emitter triangles by area x luminance, a uniform point on the triangle, an exact
    // shadow ray (nearest hit: a back face first means the point is inside a solid).
    glm::dvec3 direct(0.0);
    int directValid = 0;
    const int samples = this->Light.Triangles.empty() ? 0 : this->Options.DirectSamples;
    const int dside = std::max(1, static_cast<int>(std::sqrt(static_cast<double>(samples))));
    // Independent shuffles of the strata of texel positions and of emitter points.
    const auto shuffled = [&](int count)
    {
      std::vector<int> order(static_cast<std::size_t>(count));
      for (int i = 0; i < count; ++i)
      {
        order[static_cast<std::size_t>(i)] = i;
      }
      for (int i = count - 1; i > 0; --i)
      {
        std::swap(order[static_cast<std::size_t>(i)],
          order[random.NextUInt() % static_cast<std::uint32_t>(i + 1)]);
      }
      return order;
    };
    const std::vector<int> directPositions = shuffled(dside * dside);
    const std::vector<int> pointOrder = shuffled(dside * dside);
    for (int d = 0; d < samples; ++d)
    {
      glm::vec3 x;
      const int q = d % (dside * dside);
      if (!pointOf(directPositions[static_cast<std::size_t>(q)], dside, x))
      {
        continue;
      }
      // Stratified over the emitters' area: a jittered 2D stratum (in its own shuffled order)
      // whose first coordinate picks the triangle from the luminous-area distribution and,
      // rescaled within that triangle's share, is the first coordinate on it, mapped onto the
      // triangle by Shirley, Wang, Zimmerman's square-to-triangle map ("Monte Carlo techniques
      // for direct lighting calculations", 1996): strata stay strata over all emitters.
      const int cell = pointOrder[static_cast<std::size_t>(q)];
      const bool stratified = d < dside * dside;
      const float su = stratified
        ? (static_cast<float>(cell % dside) + random.NextFloat()) / static_cast<float>(dside)
        : random.NextFloat();
      const float sv = stratified
        ? (static_cast<float>(cell / dside) + random.NextFloat()) / static_cast<float>(dside)
        : random.NextFloat();
      float probability = 0.0f;
      const std::size_t picked = this->Light.Pick(su, probability);
      const EmitterTriangle& e = this->Light.Triangles[picked];
      const float before = picked == 0 ? 0.0f : this->Light.Cumulative[picked - 1];
      const float share = this->Light.Cumulative[picked] - before;
      float r1 = share > 0.0f
        ? std::min(0.99999994f, std::max(0.0f, (su * this->Light.Total - before) / share))
        : random.NextFloat();
      float r2 = sv;
      {
        const float root = std::sqrt(r1);
        r1 = root * (1.0f - r2);
        r2 = root * r2;
      }
      const glm::vec3 y = e.A + r1 * (e.B - e.A) + r2 * (e.C - e.A);
      const glm::vec3 toLight = y - x;
      const float distance2 = glm::dot(toLight, toLight);
      const float distance = std::sqrt(distance2);
      ++result.Rays;
      if (!(distance > 0.0f))
      {
        continue;
      }
      const glm::vec3 w = toLight / distance;
      const float cosX = glm::dot(n, w);
      const float cosY = -glm::dot(e.Normal, w);
      if (cosX <= 0.0f || cosY <= 0.0f)
      {
        ++directValid;
        continue;
      }
      SceneRay ray;
      ray.Origin = x;
      ray.Direction = w;
      ray.TFar = distance * (1.0f - 1e-4f);
      const SceneHit hit = this->Embree.Intersect(ray);
      if (hit.Hit() && hit.Triangle != SceneHit::None)
      {
        const std::uint32_t hs = this->Field.SurfaceOfTriangle(hit.Triangle);
        if (hs != NoSurface && glm::dot(this->Field.Surfaces()[hs].Normal, w) >= 0.0f)
        {
          continue; // inside a solid: not a point in the open
        }
        ++directValid; // shadowed
        continue;
      }
      if (hit.Hit())
      {
        ++directValid;
        continue;
      }
      direct += glm::dvec3(e.Emission) *
        static_cast<double>(cosX * cosY / distance2 * e.Area / probability);
      ++directValid;
    }
    glm::dvec3 irradianceOverPi = indirect / static_cast<double>(indirectValid);
    if (directValid > 0)
    {
      irradianceOverPi += direct / (static_cast<double>(directValid) * Pi<double>);
    }
    result.Value = material.Emission + material.Diffuse * glm::vec3(irradianceOverPi);
    result.Gathered = true;
    return result;
  }

  const LightField& Field;
  const FinalGatherOptions& Options;
  EmbreeScene Embree;
  Emitters Light;
  // The totals a ray's hit reads (the propagated ones, or a first gather's).
  const std::vector<glm::vec3>* Source;
  // The indirect radiance arriving at ray.Origin from ray.Direction: the diffuse radiance
  // leaving the first diffuse surface hit, less its emission (the direct part, sampled apart).
  // Mirrors (surfaces that store radiance) are followed by exact reflection, their Ks times the
  // radiance arriving along the reflected ray (emission included: light reflected by a mirror is
  // not in the direct part), plus their own diffuse radiance. Exact reflection is finer than the
  // field's direction set, and needs no directional map, which under MPI only one rank holds.
  // False where the ray meets a back face first (inside a solid or behind a one-sided surface).
  bool ArrivingAlong(SceneRay ray, glm::vec3& radiance) const
  {
    radiance = glm::vec3(0.0f);
    glm::vec3 throughput(1.0f);
    for (int bounce = 0; bounce <= MirrorBounces; ++bounce)
    {
      const SceneHit hit = this->Embree.Intersect(ray);
      if (!hit.Hit() || hit.Triangle == SceneHit::None)
      {
        return true; // escapes: nothing arrives
      }
      const std::uint32_t hs = this->Field.SurfaceOfTriangle(hit.Triangle);
      if (hs == NoSurface)
      {
        return bounce > 0;
      }
      const Surface& other = this->Field.Surfaces()[hs];
      if (glm::dot(other.Normal, ray.Direction) >= 0.0f)
      {
        return bounce > 0;
      }
      const glm::vec3 p = ray.Origin + hit.T * ray.Direction;
      const SceneMaterial& m = this->Field.MaterialOf(hs);
      glm::vec3 l = this->Field.SampleTexture(*this->Source, hs, p);
      if (bounce == 0)
      {
        l = glm::max(l - m.Emission, glm::vec3(0.0f));
      }
      radiance += throughput * l;
      if (!this->Field.StoresRadiance(hs))
      {
        return true;
      }
      throughput *= m.Specular;
      if (!(glm::max(throughput.x, glm::max(throughput.y, throughput.z)) > 1e-4f))
      {
        return true;
      }
      ray.Direction = glm::reflect(ray.Direction, other.Normal);
      ray.Origin = p + this->Offset * other.Normal;
    }
    return true;
  }

  // Rays start this far off the surface (unit sphere): well below the coincident-face distance
  // (1e-4) and the Cornell light's 0.1 mm under its ceiling (2e-4 here), above float rounding
  // of unit-sphere coordinates.
  float Offset = 2e-5f;
};

// Texels without a point in the open, ring after ring (up to 16), so that bilinear reads near
// an edge or a contact blend gathered values only, never a propagated texel finer than the
// lines (which may hold nothing). The first ring extrapolates: the mean over the 8 directions
// of 2 g1 - g2 (g1 the gathered neighbour, g2 the gathered texel beyond it), at least g1 / 2 (a
// value near 0 would turn the last digits of g1 and g2 into a large relative change), so a
// read between the last gathered texel and a filled one under a box keeps the slope of a
// contact shadow (the plain mean of the neighbours brightened it: it took texels further from
// the box); without such a pair, and in later rings, the mean of the gathered 8-neighbours.
void FillFromNeighbours(const std::vector<Surface>& surfaces, std::vector<glm::vec3>& gathered,
  std::vector<std::uint8_t>& done, FinalGatherReport& report)
{
  for (int ring = 0; ring < 16; ++ring)
  {
    const std::size_t filledBefore = report.Filled;
    std::vector<std::uint8_t> next = done;
    for (const Surface& s : surfaces)
    {
      for (int b = 0; b < s.TextureHeight; ++b)
      {
        for (int a = 0; a < s.TextureWidth; ++a)
        {
          const std::size_t texel =
            s.TexelOffset + static_cast<std::size_t>(b) * s.TextureWidth + a;
          if (done[texel])
          {
            continue;
          }
          glm::vec3 sum(0.0f);
          int count = 0;
          for (int db = -1; db <= 1; ++db)
          {
            for (int da = -1; da <= 1; ++da)
            {
              const int na = a + da;
              const int nb = b + db;
              if (na < 0 || nb < 0 || na >= s.TextureWidth || nb >= s.TextureHeight)
              {
                continue;
              }
              const std::size_t other =
                s.TexelOffset + static_cast<std::size_t>(nb) * s.TextureWidth + na;
              if (done[other])
              {
                sum += gathered[other];
                ++count;
              }
            }
          }
          if (count > 0 && ring == 0)
          {
            glm::vec3 line(0.0f);
            int lines = 0;
            for (int db = -1; db <= 1; ++db)
            {
              for (int da = -1; da <= 1; ++da)
              {
                const int a2 = a + 2 * da, b2 = b + 2 * db;
                if ((da == 0 && db == 0) || a2 < 0 || b2 < 0 || a2 >= s.TextureWidth ||
                  b2 >= s.TextureHeight)
                {
                  continue;
                }
                const std::size_t n1 =
                  s.TexelOffset + static_cast<std::size_t>(b + db) * s.TextureWidth + (a + da);
                const std::size_t n2 =
                  s.TexelOffset + static_cast<std::size_t>(b2) * s.TextureWidth + a2;
                if (done[n1] && done[n2])
                {
                  line += glm::max(2.0f * gathered[n1] - gathered[n2], 0.5f * gathered[n1]);
                  ++lines;
                }
              }
            }
            if (lines > 0)
            {
              sum = line;
              count = lines;
            }
          }
          if (count > 0)
          {
            gathered[texel] = sum / static_cast<float>(count);
            next[texel] = 1;
            ++report.Filled;
          }
        }
      }
    }
    done.swap(next);
    if (report.Filled == filledBefore)
    {
      break;
    }
  }
}

// One gather of every texel with triangles (`work`) into a copy of field.TotalDiffuse, the
// rays' hits reading `source`; texels without a point in the open filled from their gathered
// neighbours. Progress over [begin, end] of options.Progress. Under MPI (options.Reduce) this
// rank gathers its share, every ranks-th block of `work` (FinalGather.h), and one sum gives every
// rank every value; the fill then runs on each rank alike.
std::vector<glm::vec3> GatherPass(const LightField& field, const FinalGatherOptions& options,
  const std::vector<glm::vec3>& source, const std::vector<SurfaceTriangles>& buckets,
  const std::vector<std::pair<std::uint32_t, std::uint32_t>>& work, double begin, double end,
  FinalGatherReport& report)
{
  const auto start = std::chrono::steady_clock::now();
  Gatherer gatherer(field, options);
  gatherer.Source = &source;
  const std::vector<Surface>& surfaces = field.Surfaces();
  const std::size_t ranks =
    options.Reduce ? static_cast<std::size_t>(std::max(1, options.Reduce->Size())) : 1;
  const std::size_t rank =
    options.Reduce ? static_cast<std::size_t>(std::max(0, options.Reduce->Rank())) : 0;
  // The o-th texel of this rank's share is work[ownIndex(o)].
  const auto ownIndex = [&](std::size_t o)
  { return (o / GatherBlockTexels * ranks + rank) * GatherBlockTexels + o % GatherBlockTexels; };
  std::size_t ownCount = 0;
  for (std::size_t first = rank * GatherBlockTexels; first < work.size();
       first += ranks * GatherBlockTexels)
  {
    ownCount += std::min(GatherBlockTexels, work.size() - first);
  }
  // Per texel with triangles: its value and 1 where gathered, zeros where another rank gathers.
  std::vector<float> shares(4 * work.size(), 0.0f);
  std::atomic<std::uint64_t> ownRays{ 0 };
  const auto gatherOwn = [&]()
  {
    // Rounds of work between progress reports: abort is checked between them.
    const std::size_t rounds = std::max<std::size_t>(1, std::min<std::size_t>(50, ownCount / 256));
    for (std::size_t round = 0; round < rounds; ++round)
    {
      if (!ReportProgress(
            options.Progress, begin + (end - begin) * static_cast<double>(round) / rounds))
      {
        throw AbortedError();
      }
      const std::size_t first = ownCount * round / rounds;
      const std::size_t last = ownCount * (round + 1) / rounds;
      ParallelFor(first, last, 16,
        [&](std::size_t b, std::size_t e)
        {
          std::uint64_t rays = 0;
          for (std::size_t o = b; o < e; ++o)
          {
            const std::size_t i = ownIndex(o);
            const Surface& s = surfaces[work[i].first];
            const int a =
              static_cast<int>(work[i].second % static_cast<std::uint32_t>(s.TextureWidth));
            const int bb =
              static_cast<int>(work[i].second / static_cast<std::uint32_t>(s.TextureWidth));
            const TexelResult r = gatherer.Gather(
              work[i].first, buckets[work[i].first], a, bb, s.TexelOffset + work[i].second);
            rays += r.Rays;
            if (r.Gathered)
            {
              shares[4 * i] = r.Value.x;
              shares[4 * i + 1] = r.Value.y;
              shares[4 * i + 2] = r.Value.z;
              shares[4 * i + 3] = 1.0f;
            }
          }
          ownRays += rays;
        });
    }
    if (!ReportProgress(options.Progress, end))
    {
      throw AbortedError();
    }
  };
  if (options.Reduce)
  {
    Agree(*options.Reduce, gatherOwn); // an abort on one rank stops every rank before the sum
  }
  else
  {
    gatherOwn();
  }
  report.OwnTexels = ownCount; // the same in each pass
  report.OwnRays += ownRays.load();
  report.OwnSeconds +=
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  std::uint64_t passRays = ownRays.load();
  if (ranks > 1)
  {
    // One sum combines the shares: a value plus the other ranks' zeros is that value exactly.
    options.Reduce->SumInPlace(shares.data(), shares.size());
    double rays = static_cast<double>(passRays);
    options.Reduce->SumInPlace(&rays, 1);
    passRays = static_cast<std::uint64_t>(rays);
    report.CombinedBytes += shares.size() * sizeof(float) + sizeof(double);
  }
  report.Rays += passRays;
  std::vector<glm::vec3> gathered = field.TotalDiffuse;
  std::vector<std::uint8_t> done(gathered.size(), 0);
  report.Texels = 0;
  report.Filled = 0;
  for (std::size_t i = 0; i < work.size(); ++i)
  {
    if (shares[4 * i + 3] > 0.5f)
    {
      const std::size_t texel = surfaces[work[i].first].TexelOffset + work[i].second;
      gathered[texel] = glm::vec3(shares[4 * i], shares[4 * i + 1], shares[4 * i + 2]);
      done[texel] = 1;
      ++report.Texels;
    }
  }
  shares.clear();
  shares.shrink_to_fit();
  FillFromNeighbours(surfaces, gathered, done, report);
  return gathered;
}

} // namespace

FinalGatherReport FinalGather(LightField& field, const FinalGatherOptions& options)
{
  if (!(options.Footprint > 0.0f && options.Footprint <= 1.0f))
  {
    throw std::invalid_argument("the final gather's footprint must be in (0, 1] texels");
  }
  if (options.IndirectRays <= 0 || options.DirectSamples < 0)
  {
    throw std::invalid_argument("the final gather needs a positive number of indirect rays and "
                                "a non-negative number of emitter samples per texel");
  }
  const auto start = std::chrono::steady_clock::now();
  RestorePropagatedDiffuse(field); // a second gather starts from the propagated totals
  FinalGatherReport report;
  const std::vector<Surface>& surfaces = field.Surfaces();
  std::vector<SurfaceTriangles> buckets(surfaces.size());
  std::vector<std::pair<std::uint32_t, std::uint32_t>>
    work; // (surface, local texel) with triangles
  for (std::uint32_t s = 0; s < surfaces.size(); ++s)
  {
    buckets[s] = BucketTriangles(field, surfaces[s]);
    for (std::size_t t = 0; t < surfaces[s].TexelCount(); ++t)
    {
      if (buckets[s].Start[t] != buckets[s].Start[t + 1])
      {
        work.emplace_back(s, static_cast<std::uint32_t>(t));
      }
    }
  }
  // Two passes: the first, with a quarter of the rays, replaces the propagated totals the
  // second pass's rays read at their hits (FinalGatherOptions::Prepass); progress is shared by
  // their rays.
  std::vector<glm::vec3> gathered;
  if (options.Prepass)
  {
    FinalGatherOptions first = options;
    first.IndirectRays = std::max(1, options.IndirectRays / 4);
    first.DirectSamples = (options.DirectSamples + 3) / 4;
    first.Sequence = options.Sequence ^ 0x5bd1e995ull; // its own random numbers
    const double share = static_cast<double>(first.IndirectRays + first.DirectSamples) /
      static_cast<double>(
        first.IndirectRays + first.DirectSamples + options.IndirectRays + options.DirectSamples);
    const std::vector<glm::vec3> prepass =
      GatherPass(field, first, field.TotalDiffuse, buckets, work, 0.0, share, report);
    gathered = GatherPass(field, options, prepass, buckets, work, share, 1.0, report);
  }
  else
  {
    gathered = GatherPass(field, options, field.TotalDiffuse, buckets, work, 0.0, 1.0, report);
  }
  field.PropagatedDiffuse.swap(field.TotalDiffuse);
  field.TotalDiffuse.swap(gathered);
  report.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  return report;
}

void RestorePropagatedDiffuse(LightField& field)
{
  if (!field.PropagatedDiffuse.empty())
  {
    field.TotalDiffuse.swap(field.PropagatedDiffuse);
    field.PropagatedDiffuse.clear();
    field.PropagatedDiffuse.shrink_to_fit();
  }
}

} // namespace vlf
} // namespace mesolight
