// SPDX-License-Identifier: BSD-3-Clause
#include "HallucinationReference.h"

#include "EmbreeScene.h"
#include "MathConstants.h"
#include "ParallelFor.h"
#include "PathTracer.h"
#include "PinholeCamera.h"
#include "TriangleScene.h"

#include <glm/trigonometric.hpp>

#include <algorithm>
#include <cmath>
#include <map>
#include <tuple>

namespace mesolight
{
namespace
{
constexpr float CameraHeightInWidths = 20.0f;

// One vertex per texel centre plus a ring on the image border (depth clamped), so pixel centres
// land on vertices and the border pixels still see the surface.
TriangleScene HeightFieldScene(const std::vector<float>& depth, int w, int h,
  const std::vector<glm::vec3>& albedo, float reliefDepth)
{
  TriangleScene scene;
  const auto coordinate = [](int a, int n)
  { return a == 0 ? 0.0f : (a == n + 1 ? static_cast<float>(n) : static_cast<float>(a) - 0.5f); };
  for (int b = 0; b <= h + 1; ++b)
  {
    for (int a = 0; a <= w + 1; ++a)
    {
      const int i = std::clamp(a - 1, 0, w - 1), j = std::clamp(b - 1, 0, h - 1);
      scene.Positions.emplace_back(coordinate(a, w), coordinate(b, h),
        -reliefDepth * depth[static_cast<std::size_t>(j) * w + i]);
    }
  }
  std::map<std::tuple<float, float, float>, std::uint32_t> materials;
  const auto materialOf = [&](int i, int j)
  {
    const glm::vec3 kd = albedo[static_cast<std::size_t>(j) * w + i];
    const auto key = std::make_tuple(kd.x, kd.y, kd.z);
    auto found = materials.find(key);
    if (found == materials.end())
    {
      SceneMaterial material;
      material.Diffuse = kd;
      found = materials.emplace(key, scene.AddMaterial(material)).first;
    }
    return found->second;
  };
  const auto vertex = [w](int a, int b) { return static_cast<std::uint32_t>(b * (w + 2) + a); };
  for (int b = 0; b <= h; ++b)
  {
    for (int a = 0; a <= w; ++a)
    {
      // The texel nearest the quad's centre gives its albedo.
      const std::uint32_t material = materialOf(std::clamp(a, 0, w - 1), std::clamp(b, 0, h - 1));
      scene.Triangles.emplace_back(vertex(a, b), vertex(a + 1, b), vertex(a + 1, b + 1));
      scene.Triangles.emplace_back(vertex(a, b), vertex(a + 1, b + 1), vertex(a, b + 1));
      scene.MaterialIds.push_back(material);
      scene.MaterialIds.push_back(material);
    }
  }
  return scene;
}

PinholeCamera TopDownCamera(int w, int h)
{
  PinholeCamera camera;
  const float height = CameraHeightInWidths * static_cast<float>(w);
  camera.Position = glm::vec3(0.5f * w, 0.5f * h, height);
  camera.FocalPoint = glm::vec3(0.5f * w, 0.5f * h, 0.0f);
  camera.ViewUp = glm::vec3(0.0f, 1.0f, 0.0f);
  camera.ViewAngleDegrees = glm::degrees(2.0f * std::atan(0.5f * h / height));
  return camera;
}

// The flash: a square facing down (counter-clockwise seen from below) just above the camera,
// bright enough to light the surface about as much as the sky does (irradiance pi L).
void AddFlash(TriangleScene& scene, int w, int h, const HallucinationPhotoSettings& settings)
{
  const float z = CameraHeightInWidths * static_cast<float>(w) + 1.0f;
  const float s = settings.FlashSizeTexels;
  const float x0 = 0.5f * w - 0.5f * s, x1 = x0 + s, y0 = 0.5f * h - 0.5f * s, y1 = y0 + s;
  SceneMaterial flash;
  flash.Name = "flash";
  flash.Diffuse = glm::vec3(0.0f);
  flash.Emission = glm::vec3(Pi<float> * settings.SkyRadiance * z * z / (s * s));
  const std::uint32_t id = scene.AddMaterial(flash);
  scene.AddPolygon({ { x0, y0, z }, { x0, y1, z }, { x1, y1, z }, { x1, y0, z } }, id);
}

EnvironmentLight OvercastSky(float radiance)
{
  // Lat-long, VTK row order (row 0 = nadir): the upper half radiance, the lower half black; 64
  // rows keep the bilinear blend within 3 degrees of the horizon.
  EnvironmentLight sky;
  sky.Map = RgbImage(4, 64);
  for (int j = 32; j < 64; ++j)
  {
    for (int i = 0; i < 4; ++i)
    {
      std::fill(sky.Map.Pixel(i, j), sky.Map.Pixel(i, j) + 3, radiance);
    }
  }
  return sky;
}

RgbImage Render(const TriangleScene& scene, const EnvironmentLight* sky, int w, int h, int samples,
  std::uint64_t seed, const ProgressCallback& progress)
{
  const EmbreeScene embree(scene);
  PathTracerSettings settings;
  settings.RayEpsilon = 1e-6f;
  PathTracer tracer(embree, settings);
  if (sky)
  {
    tracer.SetEnvironment(*sky);
  }
  return tracer.RenderImage(TopDownCamera(w, h), w, h, samples, seed, progress);
}
} // namespace

//------------------------------------------------------------------------------
glm::vec3 HallucinationTestAlbedo(int i, int j)
{
  static const glm::vec3 colours[4] = { { 0.80f, 0.72f, 0.60f }, { 0.25f, 0.28f, 0.32f },
    { 0.65f, 0.22f, 0.18f }, { 0.45f, 0.60f, 0.30f } };
  const std::uint32_t cell = static_cast<std::uint32_t>((i / 16) * 7919 + (j / 16) * 104729);
  std::uint32_t x = cell * 2654435761u;
  x ^= x >> 15;
  return colours[x % 4u];
}

//------------------------------------------------------------------------------
HallucinationPhotographs RenderHallucinationPhotographs(const std::vector<float>& depth, int w,
  int h, const std::vector<glm::vec3>& albedoIn, const HallucinationPhotoSettings& settings,
  const ProgressCallback& progress)
{
  std::vector<glm::vec3> albedo = albedoIn;
  if (albedo.empty())
  {
    albedo.resize(static_cast<std::size_t>(w) * h);
    for (int j = 0; j < h; ++j)
    {
      for (int i = 0; i < w; ++i)
      {
        albedo[static_cast<std::size_t>(j) * w + i] = HallucinationTestAlbedo(i, j);
      }
    }
  }
  HallucinationPhotographs photos;
  const TriangleScene surface = HeightFieldScene(depth, w, h, albedo, settings.ReliefDepthTexels);
  const EnvironmentLight sky = OvercastSky(settings.SkyRadiance);
  photos.Diffuse =
    Render(surface, &sky, w, h, settings.Samples, settings.Seed, SubProgress(progress, 0, 0.6));
  TriangleScene flashScene = surface;
  AddFlash(flashScene, w, h, settings);
  const RgbImage flashOnly = Render(
    flashScene, nullptr, w, h, settings.Samples, settings.Seed, SubProgress(progress, 0.6, 0.9));
  // The white card: the flat map (depth 0), albedo 1.
  TriangleScene card = HeightFieldScene(std::vector<float>(static_cast<std::size_t>(w) * h, 0.0f),
    w, h, std::vector<glm::vec3>(static_cast<std::size_t>(w) * h, glm::vec3(1.0f)), 0.0f);
  AddFlash(card, w, h, settings);
  photos.Calibration =
    Render(card, nullptr, w, h, settings.Samples, settings.Seed, SubProgress(progress, 0.9, 1.0));
  if (photos.Diffuse.Width == 0 || flashOnly.Width == 0 || photos.Calibration.Width == 0)
  {
    return {};
  }
  photos.Flash = photos.Diffuse;
  for (std::size_t k = 0; k < photos.Flash.Rgb.size(); ++k)
  {
    photos.Flash.Rgb[k] += flashOnly.Rgb[k];
  }
  // The albedo each pixel sees: Kd at the first hit, 4 x 4 stratified rays per pixel.
  const EmbreeScene embree(surface);
  const PinholeCamera camera = TopDownCamera(w, h);
  photos.TrueAlbedo = RgbImage(w, h);
  ParallelFor(0, static_cast<std::size_t>(h), 1,
    [&](std::size_t begin, std::size_t end)
    {
      for (int j = static_cast<int>(begin); j < static_cast<int>(end); ++j)
      {
        for (int i = 0; i < w; ++i)
        {
          glm::vec3 sum(0.0f);
          for (int s = 0; s < 16; ++s)
          {
            const SceneHit hit = embree.Intersect(
              camera.Ray(i + (s % 4 + 0.5f) / 4.0f, j + (s / 4 + 0.5f) / 4.0f, w, h));
            sum += hit.Hit() ? surface.MaterialOf(hit.Triangle).Diffuse : glm::vec3(0.0f);
          }
          std::copy(&sum.x, &sum.x + 3, photos.TrueAlbedo.Pixel(i, j));
          for (int c = 0; c < 3; ++c)
          {
            photos.TrueAlbedo.Pixel(i, j)[c] /= 16.0f;
          }
        }
      }
    });
  return photos;
}

//------------------------------------------------------------------------------
HallucinationTestSurface MakeHallucinationTestSurface(bool panels)
{
  HallucinationTestSurface s;
  s.Side = panels ? 256 : 128;
  s.ReliefTexels = panels ? 16.0f : 8.0f;
  s.FeatureTexels = panels ? 100.0f : 8.0f;
  s.Depth.assign(static_cast<std::size_t>(s.Side) * static_cast<std::size_t>(s.Side), 0.0f);
  for (int j = 0; j < s.Side; ++j)
  {
    for (int i = 0; i < s.Side; ++i)
    {
      bool deep = false;
      if (panels)
      {
        deep = (i % 128) >= 14 && (i % 128) < 114 && (j % 128) >= 14 && (j % 128) < 114;
      }
      else
      {
        const float x = static_cast<float>(i % 16) - 7.5f, y = static_cast<float>(j % 16) - 7.5f;
        deep = x * x + y * y <= 16.0f;
      }
      s.Depth[static_cast<std::size_t>(j) * static_cast<std::size_t>(s.Side) +
        static_cast<std::size_t>(i)] = deep ? 1.0f : 0.0f;
    }
  }
  return s;
}

//------------------------------------------------------------------------------
DepthAgreement CompareDepth(
  const std::vector<float>& estimate, const std::vector<float>& truth, int w, int h, int margin)
{
  DepthAgreement agreement;
  double n = 0, se = 0, st = 0, see = 0, stt = 0, set = 0;
  const auto inside = [&](int i, int j)
  { return i >= margin && j >= margin && i < w - margin && j < h - margin; };
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      if (!inside(i, j))
      {
        continue;
      }
      const double e = estimate[static_cast<std::size_t>(j) * w + i];
      const double t = truth[static_cast<std::size_t>(j) * w + i];
      n += 1;
      se += e;
      st += t;
      see += e * e;
      stt += t * t;
      set += e * t;
    }
  }
  if (n < 2)
  {
    return agreement;
  }
  const double ve = see - se * se / n, vt = stt - st * st / n, cov = set - se * st / n;
  agreement.Correlation = (ve > 0 && vt > 0) ? cov / std::sqrt(ve * vt) : 0.0;
  // A depth map read upside down is wrong, not rescaled: the scale may not be negative.
  agreement.Scale = (ve > 0 && cov > 0) ? cov / ve : 0.0;
  agreement.Offset = (st - agreement.Scale * se) / n;
  double mae = 0, mad = 0;
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      if (!inside(i, j))
      {
        continue;
      }
      const double e = estimate[static_cast<std::size_t>(j) * w + i];
      const double t = truth[static_cast<std::size_t>(j) * w + i];
      mae += std::abs(agreement.Scale * e + agreement.Offset - t);
      mad += std::abs(t - st / n);
    }
  }
  agreement.MeanAbsoluteError = mae / n;
  agreement.TruthMeanAbsoluteDeviation = mad / n;
  return agreement;
}

} // namespace mesolight
