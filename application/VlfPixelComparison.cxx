// SPDX-License-Identifier: BSD-3-Clause
#include "VlfPixelComparison.h"
#include "LightField.h"
#include "Lookup.h"
#include "MathConstants.h"
#include "OrthonormalBasis.h"
#include "ParallelFor.h"
#include "PatchComparison.h" // ToUnit
#include "PathTracer.h"
#include <algorithm>
#include <cmath>
#include <cstdio>
#include <glm/geometric.hpp>

namespace mesolight
{
namespace vlf = mesolight::vlf;

namespace
{
// f(i, hits[i]) for every pixel i whose primary ray met the scene, in parallel (grain pixels
// per task).
template <typename Function>
void ForEachSceneHit(const std::vector<PixelHit>& hits, std::size_t grain, const Function& f)
{
  ParallelFor(0, hits.size(), grain,
    [&](std::size_t b, std::size_t e)
    {
      for (std::size_t i = b; i < e; ++i)
      {
        if (hits[i].Triangle != SceneHit::None)
        {
          f(i, hits[i]);
        }
      }
    });
}
} // namespace

std::vector<PixelHit> PrimaryHits(const AccuracyScene& s, const EmbreeScene& embree, int w, int h)
{
  std::vector<PixelHit> hits(static_cast<std::size_t>(w) * h);
  ParallelFor(0, static_cast<std::size_t>(h), 1,
    [&](std::size_t r0, std::size_t r1)
    {
      for (std::size_t row = r0; row < r1; ++row)
      {
        for (int column = 0; column < w; ++column)
        {
          const SceneRay ray = s.Camera.Ray(column + 0.5f, static_cast<float>(row) + 0.5f, w, h);
          const SceneHit hit = embree.Intersect(ray);
          if (hit.Triangle == SceneHit::None)
          {
            continue;
          }
          const glm::vec3 a = s.Scene.Vertex(hit.Triangle, 0), b = s.Scene.Vertex(hit.Triangle, 1),
                          c = s.Scene.Vertex(hit.Triangle, 2);
          const SceneMaterial& m = s.Scene.MaterialOf(hit.Triangle);
          if (glm::dot(glm::cross(b - a, c - a), ray.Direction) >= 0.0f ||
            glm::length(m.Emission) > 0.0f)
          {
            continue;
          }
          PixelHit& p = hits[row * static_cast<std::size_t>(w) + column];
          p.Triangle = hit.Triangle;
          p.Point = ray.Origin + hit.T * ray.Direction;
        }
      }
    });
  return hits;
}

// Half of the reference: `samples` paths per pixel, seeds of half `half`.
RgbImage ReferenceHalf(
  const EmbreeScene& embree, const std::vector<PixelHit>& hits, int w, int h, int samples, int half)
{
  PathTracer tracer(embree);
  RgbImage out(w, h);
  ForEachSceneHit(hits, 64,
    [&](std::size_t i, const PixelHit& hit)
    {
      const glm::vec3 r = tracer.DiffuseRadianceLeaving(hit.Triangle, hit.Point, samples,
        (static_cast<std::uint64_t>(half) << 40) ^ (i * 0x9e3779b97f4a7c15ull));
      std::copy(&r.x, &r.x + 3, out.Rgb.data() + 3 * i);
    });
  return out;
}

namespace
{
double Sum3(const float* v)
{
  return static_cast<double>(v[0]) + v[1] + v[2];
}

double Percentile(std::vector<double> v, double q)
{
  if (v.empty())
  {
    return 0.0;
  }
  const std::size_t k =
    std::min(v.size() - 1, static_cast<std::size_t>(q * static_cast<double>(v.size())));
  std::nth_element(v.begin(), v.begin() + static_cast<std::ptrdiff_t>(k), v.end());
  return v[k];
}

// The mean of the two reference halves over the pixels that see the scene.
double MeanReference(const std::vector<PixelHit>& hits, const RgbImage& a, const RgbImage& b)
{
  double mean = 0.0;
  std::size_t n = 0;
  for (std::size_t i = 0; i < hits.size(); ++i)
  {
    if (hits[i].Triangle != SceneHit::None)
    {
      mean += 0.5 * (Sum3(&a.Rgb[3 * i]) + Sum3(&b.Rgb[3 * i]));
      ++n;
    }
  }
  return mean / static_cast<double>(std::max<std::size_t>(n, 1));
}
} // namespace

// Lit pixels: reference above 1% of the mean over the compared pixels (shadows so deep that a
// relative error means nothing are left out; black-where-lit counts the rest).
PixelError ComparePixels(
  const std::vector<PixelHit>& hits, const RgbImage& field, const RgbImage& a, const RgbImage& b)
{
  const double mean = MeanReference(hits, a, b);
  std::vector<double> errors;
  PixelError e;
  std::size_t black = 0;
  for (std::size_t i = 0; i < hits.size(); ++i)
  {
    const double ra = Sum3(&a.Rgb[3 * i]), rb = Sum3(&b.Rgb[3 * i]);
    const double r = 0.5 * (ra + rb);
    if (hits[i].Triangle == SceneHit::None || !(r > 0.01 * mean))
    {
      continue;
    }
    const double f = Sum3(&field.Rgb[3 * i]);
    errors.push_back(std::abs(f - r) / r);
    e.ReferenceNoise += std::abs(ra - rb) / (ra + rb);
    black += f < 0.1 * r ? 1 : 0;
  }
  e.Pixels = errors.size();
  if (e.Pixels > 0)
  {
    double s = 0.0;
    for (double x : errors)
    {
      s += x;
    }
    e.Mean = s / static_cast<double>(e.Pixels);
    e.P95 = Percentile(errors, 0.95);
    e.Black = static_cast<double>(black) / static_cast<double>(e.Pixels);
    e.ReferenceNoise /= static_cast<double>(e.Pixels);
  }
  return e;
}

// Where the error is: the mean signed relative error (bias), and the mean |error| on pixels at
// an edge (a 4-neighbour shows another surface) against the rest, and on small surfaces
// (narrower than 4 texels) against the others.
std::string ErrorBreakdown(const vlf::LightField& field, const std::vector<PixelHit>& hits, int w,
  int h, const RgbImage& image, const RgbImage& a, const RgbImage& b)
{
  const double mean = MeanReference(hits, a, b);
  const auto surfaceAt = [&](int x, int y)
  {
    const PixelHit& p = hits[static_cast<std::size_t>(y) * w + x];
    return p.Triangle == SceneHit::None ? vlf::NoSurface : field.SurfaceOfTriangle(p.Triangle);
  };
  double bias = 0.0, sum[2][2] = { { 0, 0 }, { 0, 0 } };
  std::size_t count[2][2] = { { 0, 0 }, { 0, 0 } }, all = 0;
  for (int y = 0; y < h; ++y)
  {
    for (int x = 0; x < w; ++x)
    {
      const std::size_t i = static_cast<std::size_t>(y) * w + x;
      const double r = 0.5 * (Sum3(&a.Rgb[3 * i]) + Sum3(&b.Rgb[3 * i]));
      const std::uint32_t s = surfaceAt(x, y);
      if (s == vlf::NoSurface || !(r > 0.01 * mean))
      {
        continue;
      }
      const double e = (Sum3(&image.Rgb[3 * i]) - r) / r;
      bool edge = false;
      const int dx[4] = { 1, -1, 0, 0 }, dy[4] = { 0, 0, 1, -1 };
      for (int q = 0; q < 4; ++q)
      {
        const int nx = x + dx[q], ny = y + dy[q];
        edge = edge || (nx >= 0 && ny >= 0 && nx < w && ny < h && surfaceAt(nx, ny) != s);
      }
      const vlf::Surface& surface = field.Surfaces()[s];
      const bool small = std::min(surface.TextureWidth, surface.TextureHeight) < 4;
      bias += e;
      ++all;
      sum[0][edge ? 1 : 0] += std::abs(e);
      ++count[0][edge ? 1 : 0];
      sum[1][small ? 1 : 0] += std::abs(e);
      ++count[1][small ? 1 : 0];
    }
  }
  const auto ratio = [](double x, std::size_t c)
  { return c > 0 ? 100.0 * x / static_cast<double>(c) : 0.0; };
  char text[256];
  std::snprintf(text, sizeof(text),
    "bias %+.1f%%; interior %.1f%% (%zu px), edges %.1f%% (%zu px); large surfaces %.1f%% "
    "(%zu px), small %.1f%% (%zu px)",
    ratio(bias, all), ratio(sum[0][0], count[0][0]), count[0][0], ratio(sum[0][1], count[0][1]),
    count[0][1], ratio(sum[1][0], count[1][0]), count[1][0], ratio(sum[1][1], count[1][1]),
    count[1][1]);
  return text;
}

// Where the error is by surface class and position, per pixel: the surface large (at least a
// tenth of the largest surface's area: a floor, a wall) or small (a box's face, a rib, a shelf),
// facing up, sideways or down; the point inside its surface, at a contact (a concave edge: a
// ray along the surface within 1.5 texels meets another surface, as the floor beside a box or a
// box side above the floor) or at a border (not a contact, but a point 1.5 texels away along the
// surface is off it: a convex edge, as a box top's rim). Per class the mean |error|, the bias
// (mean signed error) and the pixels: a class whose error is mostly bias is resolution or
// placement, one whose bias is near zero is noise.
std::string ClassBreakdown(const vlf::LightField& field, const AccuracyScene& scene,
  const EmbreeScene& embree, const std::vector<PixelHit>& hits, float texelWorld,
  const RgbImage& image, const RgbImage& a, const RgbImage& b)
{
  const double mean = MeanReference(hits, a, b);
  double largest = 0.0;
  for (const vlf::Surface& s : field.Surfaces())
  {
    largest = std::max(largest, s.Area);
  }
  const char* facing[3] = { "up", "side", "down" };
  const char* where[3] = { "inside", "contact", "border" };
  double sum[2][3][3] = {}, bias[2][3][3] = {};
  std::size_t count[2][3][3] = {};
  const float reach = 1.5f * texelWorld, lift = 0.02f * texelWorld;
  for (std::size_t i = 0; i < hits.size(); ++i)
  {
    const double r = 0.5 * (Sum3(&a.Rgb[3 * i]) + Sum3(&b.Rgb[3 * i]));
    if (hits[i].Triangle == SceneHit::None || !(r > 0.01 * mean))
    {
      continue;
    }
    const std::uint32_t s = field.SurfaceOfTriangle(hits[i].Triangle);
    if (s == vlf::NoSurface)
    {
      continue;
    }
    const vlf::Surface& surface = field.Surfaces()[s];
    const glm::vec3 n = glm::normalize(scene.Scene.FaceNormal(hits[i].Triangle));
    const int large = surface.Area >= 0.1 * largest ? 1 : 0;
    const int face = n.y > 0.7f ? 0 : (n.y < -0.7f ? 2 : 1);
    glm::vec3 u, v;
    OrthonormalBasis(n, u, v);
    const glm::vec3 p = hits[i].Point + lift * n;
    int position = 0;
    for (int k = 0; k < 8 && position != 1; ++k)
    {
      const float angle = 2.0f * Pi<float> * static_cast<float>(k) / 8.0f;
      const glm::vec3 d = std::cos(angle) * u + std::sin(angle) * v;
      SceneRay along;
      along.Origin = p;
      along.Direction = d;
      along.TFar = reach;
      if (embree.Intersect(along).Hit())
      {
        position = 1;
        continue;
      }
      SceneRay down;
      down.Origin = p + reach * d;
      down.Direction = -n;
      down.TFar = 2.0f * lift;
      const SceneHit below = embree.Intersect(down);
      if (!below.Hit() || below.Triangle == SceneHit::None ||
        field.SurfaceOfTriangle(below.Triangle) != s)
      {
        position = 2;
      }
    }
    const double e = (Sum3(&image.Rgb[3 * i]) - r) / r;
    sum[large][face][position] += std::abs(e);
    bias[large][face][position] += e;
    ++count[large][face][position];
  }
  std::string out;
  for (int l = 1; l >= 0; --l)
  {
    for (int f = 0; f < 3; ++f)
    {
      for (int w = 0; w < 3; ++w)
      {
        const std::size_t c = count[l][f][w];
        if (c == 0)
        {
          continue;
        }
        char text[160];
        std::snprintf(text, sizeof(text), "%s%s %s %s %.1f%% (bias %+.1f%%, %zu px)",
          out.empty() ? "" : "; ", l ? "large" : "small", facing[f], where[w],
          100.0 * sum[l][f][w] / static_cast<double>(c),
          100.0 * bias[l][f][w] / static_cast<double>(c), c);
        out += text;
      }
    }
  }
  return out;
}

RgbImage FieldImage(const vlf::LightField& field, const std::vector<PixelHit>& hits, int w, int h)
{
  const vlf::Lookup lookup(field);
  RgbImage out(w, h);
  ForEachSceneHit(hits, 256,
    [&](std::size_t i, const PixelHit& hit)
    {
      const std::uint32_t s = field.SurfaceOfTriangle(hit.Triangle);
      if (s != vlf::NoSurface)
      {
        const glm::vec3 v = lookup.DiffuseRadiance(s, vlf::ToUnit(field, hit.Point));
        std::copy(&v.x, &v.x + 3, out.Rgb.data() + 3 * i);
      }
    });
  return out;
}
} // namespace mesolight
