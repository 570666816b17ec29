// SPDX-License-Identifier: BSD-3-Clause
#include "LightSetReference.h"

#include "MathConstants.h"
#include "ParallelFor.h"

#include "CompactReliefStorage.h"
#include "HeightFieldTracer.h"
#include "ImageCompare.h"
#include "ReliefReference.h"
#include "vtkReliefPlaneFilter.h"

#include "EnvironmentMaps.h"

#include <glm/geometric.hpp>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>

#include <algorithm>
#include <cmath>
#include <memory>
#include <random>

namespace mesolight
{
namespace
{

// Environment pixels as a discrete distribution proportional to luminance x solid angle.
struct EnvironmentSampler
{
  int Width = 0, Height = 0;
  std::vector<double> Cdf;     // cumulative, normalized
  std::vector<double> Weights; // probability of each pixel
  std::vector<float> Radiance; // RGB per pixel, VTK row order
};

EnvironmentSampler MakeSampler(vtkImageData* environment)
{
  EnvironmentSampler s;
  int dims[3];
  environment->GetDimensions(dims);
  s.Width = dims[0];
  s.Height = dims[1];
  vtkDataArray* values = environment->GetPointData()->GetScalars();
  const size_t n = static_cast<size_t>(s.Width) * s.Height;
  s.Radiance.resize(3 * n);
  s.Weights.resize(n);
  s.Cdf.resize(n);
  double total = 0.0;
  for (int j = 0; j < s.Height; ++j)
  {
    const double omega = PixelSolidAngle(j, s.Width, s.Height);
    for (int i = 0; i < s.Width; ++i)
    {
      const size_t p = static_cast<size_t>(j) * s.Width + i;
      for (int c = 0; c < 3; ++c)
      {
        s.Radiance[3 * p + c] =
          static_cast<float>(values->GetComponent(static_cast<vtkIdType>(p), c));
      }
      const double w = std::max(
        0.0, Luminance(s.Radiance[3 * p], s.Radiance[3 * p + 1], s.Radiance[3 * p + 2]) * omega);
      s.Weights[p] = w;
      total += w;
      s.Cdf[p] = total;
    }
  }
  for (size_t p = 0; p < n; ++p)
  {
    s.Weights[p] /= total;
    s.Cdf[p] /= total;
  }
  return s;
}

// GL_LINEAR + CLAMP_TO_EDGE sample of the packed normal (RGB) of a relief texture.
glm::dvec3 SampleNormal(vtkDataArray* rgba, double unit, int w, int h, double u, double v)
{
  const double x = u * w - 0.5, y = v * h - 0.5;
  const int i0 = static_cast<int>(std::floor(x)), j0 = static_cast<int>(std::floor(y));
  const double fx = x - i0, fy = y - j0;
  auto texel = [&](int i, int j)
  {
    i = std::min(std::max(i, 0), w - 1);
    j = std::min(std::max(j, 0), h - 1);
    const vtkIdType id = static_cast<vtkIdType>(j) * w + i;
    return unit *
      glm::dvec3(rgba->GetComponent(id, 0), rgba->GetComponent(id, 1), rgba->GetComponent(id, 2));
  };
  return (texel(i0, j0) * (1 - fx) + texel(i0 + 1, j0) * fx) * (1 - fy) +
    (texel(i0, j0 + 1) * (1 - fx) + texel(i0 + 1, j0 + 1) * fx) * fy;
}

// What the two references share: the exact bilinear height field of a relief texture, the
// reference pixels, and the shading normal at each pixel's exact hit.
struct ReferenceSetup
{
  int Dims[3] = { 0, 0, 0 };
  double TexelAspect = 1.0; // rows / columns: how the baked normals are encoded
  double Aspect = 1.0;      // the wall's height for a width of 1 (its ground proportions)
  double DepthScale = 1.0;
  vtkDataArray* Rgba = nullptr;
  // What a stored value of 1 is: 8-bit textures hold 0-255, as the relief mapper reads them
  // (vtkReliefTextureCache), float ones 0-1.
  double Unit = 1.0;
  bool ConePacked = false; // vtkConeMapFilter's packing: normal x, y in RG, cone ratio in B
  std::vector<float> Depth;
  std::unique_ptr<HeightField> Surface; // set when the normals are the depth's own

  ReferenceSetup(vtkImageData* relief, double depthScale)
    : DepthScale(depthScale)
    , Rgba(relief->GetPointData()->GetScalars())
    , ConePacked(relief->GetFieldData()->GetAbstractArray("MesolightConeType") != nullptr)
  {
    this->Unit = this->Rgba->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
    relief->GetDimensions(this->Dims);
    this->TexelAspect = static_cast<double>(this->Dims[1]) / this->Dims[0];
    this->Aspect = vtkReliefPlaneFilter::GetGroundProportions(relief);
    this->Depth.resize(static_cast<size_t>(this->Dims[0]) * this->Dims[1]);
    for (size_t i = 0; i < this->Depth.size(); ++i)
    {
      this->Depth[i] =
        static_cast<float>(this->Unit * this->Rgba->GetComponent(static_cast<vtkIdType>(i), 3));
    }
    // Normals that are the depth's own shade as the relief mapper shades them: with the
    // gradient of the bilinear surface (NormalsAreTheDepths).
    vtkDataArray* baked = relief->GetFieldData()->GetArray("MesolightDepthScale");
    if (baked && baked->GetNumberOfTuples() > 0)
    {
      std::vector<float> normalXY(2 * this->Depth.size());
      for (size_t i = 0; i < this->Depth.size(); ++i)
      {
        for (int c = 0; c < 2; ++c)
        {
          normalXY[2 * i + c] = static_cast<float>(
            2.0 * this->Unit * this->Rgba->GetComponent(static_cast<vtkIdType>(i), c) - 1.0);
        }
      }
      if (NormalsAreTheDepths(this->Depth.data(), normalXY.data(), this->Dims[0], this->Dims[1],
            baked->GetComponent(0, 0)))
      {
        this->Surface = std::make_unique<HeightField>(this->Field());
      }
    }
  }

  // A relief texture this can read: 4 components (normal or cone packing, depth in A), 2D.
  static bool Usable(vtkImageData* relief)
  {
    vtkDataArray* rgba = relief ? relief->GetPointData()->GetScalars() : nullptr;
    int dims[3] = { 0, 0, 0 };
    if (relief)
    {
      relief->GetDimensions(dims);
    }
    return rgba && rgba->GetNumberOfComponents() == 4 && dims[0] >= 1 && dims[1] >= 1 &&
      rgba->GetNumberOfTuples() == static_cast<vtkIdType>(dims[0]) * dims[1];
  }

  HeightField Field() const { return HeightField(this->Dims[0], this->Dims[1], this->Depth); }

  // Covered pixels, evenly strided down to maxPixels.
  static std::vector<EnvironmentIrradianceSample> Pixels(const ReliefReference& hits, int maxPixels)
  {
    std::vector<size_t> covered;
    for (size_t p = 0; p < hits.State.size(); ++p)
    {
      if (hits.IsCovered(p))
      {
        covered.push_back(p);
      }
    }
    const size_t stride = std::max<size_t>(1, covered.size() / std::max(1, maxPixels));
    std::vector<EnvironmentIrradianceSample> samples;
    for (size_t k = 0; k < covered.size(); k += stride)
    {
      samples.push_back(EnvironmentIrradianceSample{ covered[k], { 0.0, 0.0, 0.0 } });
    }
    return samples;
  }

  // The shading normal as the relief mapper takes it: the bilinear surface's when the texture's
  // normals are its depth's own, else the texture's (bilinearly sampled, as the GPU does: a
  // normal map made apart is part of the scene). Only visibility and irradiance are referenced.
  glm::dvec3 WorldNormal(const glm::dvec3& hit) const
  {
    if (this->Surface)
    {
      const glm::dvec2 g = this->Surface->GradientAt(hit.x, hit.y);
      return glm::normalize(
        glm::dvec3(this->DepthScale * this->Aspect * g.x, this->DepthScale * g.y, this->Aspect));
    }
    const glm::dvec3 packed =
      SampleNormal(this->Rgba, this->Unit, this->Dims[0], this->Dims[1], hit.x, hit.y);
    glm::dvec3 nt = packed * 2.0 - 1.0;
    if (this->ConePacked) // as the shader decodes it: z from the filtered x, y
    {
      nt.z = std::sqrt(std::max(0.0, 1.0 - nt.x * nt.x - nt.y * nt.y));
    }
    const double nz = std::max(nt.z, 1e-4);
    // Depth gradient from the baked normal (depth scale k), then the world normal of the
    // surface (u, aspect v, -k d): Pu x Pv.
    const glm::dvec2 g(
      nt.x / (nz * this->DepthScale), nt.y * this->TexelAspect / (nz * this->DepthScale));
    return glm::normalize(
      glm::dvec3(this->DepthScale * this->Aspect * g.x, this->DepthScale * g.y, this->Aspect));
  }

  // A world direction (+Z out of the wall) as a height-field ray direction per unit of t.
  glm::dvec3 FieldDirection(const double d[3]) const
  {
    return glm::dvec3(d[0], d[1] / this->Aspect, -d[2] / this->DepthScale);
  }

  // irradiance(sample, exact hit, shading normal) for every reference pixel, in parallel.
  template <typename Irradiance>
  void ForEachPixel(const ReliefReference& hits, std::vector<EnvironmentIrradianceSample>& samples,
    Irradiance irradiance) const
  {
    mesolight::ParallelFor(0, samples.size(), 0,
      [&](std::size_t begin, std::size_t end)
      {
        for (std::size_t s = begin; s < end; ++s)
        {
          EnvironmentIrradianceSample& sample = samples[static_cast<size_t>(s)];
          const size_t p = sample.Pixel;
          const glm::dvec3 hit(hits.HitU[p], hits.HitV[p], hits.HitD[p]);
          irradiance(sample, hit, this->WorldNormal(hit));
        }
      });
  }
};

} // namespace

//------------------------------------------------------------------------------
std::vector<EnvironmentIrradianceSample> ComputeEnvironmentReference(const ReliefReference& hits,
  vtkImageData* relief, vtkImageData* environment, double depthScale, int maxPixels,
  int samplesPerPixel, bool shadows)
{
  if (!ReferenceSetup::Usable(relief) || !environment)
  {
    return {};
  }
  const ReferenceSetup setup(relief, depthScale);
  const HeightField field = setup.Field();
  const EnvironmentSampler sampler = MakeSampler(environment);
  std::vector<EnvironmentIrradianceSample> samples = ReferenceSetup::Pixels(hits, maxPixels);

  setup.ForEachPixel(hits, samples,
    [&](EnvironmentIrradianceSample& sample, const glm::dvec3& hit, const glm::dvec3& n)
    {
      std::mt19937 rng(static_cast<unsigned>(sample.Pixel) * 2654435761u + 17u);
      std::uniform_real_distribution<double> uniform(0.0, 1.0);
      for (int k = 0; k < samplesPerPixel; ++k)
      {
        const double x = uniform(rng);
        const size_t pixel = static_cast<size_t>(
          std::lower_bound(sampler.Cdf.begin(), sampler.Cdf.end(), x) - sampler.Cdf.begin());
        if (pixel >= sampler.Cdf.size() || sampler.Weights[pixel] <= 0.0)
        {
          continue;
        }
        const int i = static_cast<int>(pixel % sampler.Width);
        const int j = static_cast<int>(pixel / sampler.Width);
        double d[3];
        DirectionFromMapUV(PixelCenterU(i, sampler.Width), PixelCenterV(j, sampler.Height), d);
        const double cosine = n.x * d[0] + n.y * d[1] + n.z * d[2];
        if (cosine <= 0.0 || d[2] <= 0.0)
        {
          continue;
        }
        if (shadows && !Visible(field, hit, setup.FieldDirection(d)))
        {
          continue;
        }
        const double weight = PixelSolidAngle(j, sampler.Width, sampler.Height) * cosine /
          (sampler.Weights[pixel] * samplesPerPixel);
        for (int c = 0; c < 3; ++c)
        {
          sample.Irradiance[c] += sampler.Radiance[3 * pixel + c] * weight;
        }
      }
    });
  return samples;
}

//------------------------------------------------------------------------------
std::vector<EnvironmentIrradianceSample> ComputeLightSetReference(const ReliefReference& hits,
  vtkImageData* relief, vtkImageData* lights, double depthScale, int maxPixels)
{
  // Row 0: unit directions toward the lights (world); row 1: irradiance at normal incidence.
  vtkDataArray* texels = lights ? lights->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (lights)
  {
    lights->GetDimensions(dims);
  }
  if (!texels || dims[0] < 1 || dims[1] != 2 || texels->GetNumberOfComponents() < 3 ||
    texels->GetNumberOfTuples() != 2 * static_cast<vtkIdType>(dims[0]) ||
    !ReferenceSetup::Usable(relief))
  {
    return {}; // not a light texture of vtkMedianCutLights, or not a relief texture
  }
  const int count = dims[0];
  const ReferenceSetup setup(relief, depthScale);
  const HeightField field = setup.Field();
  std::vector<EnvironmentIrradianceSample> samples = ReferenceSetup::Pixels(hits, maxPixels);

  setup.ForEachPixel(hits, samples,
    [&](EnvironmentIrradianceSample& sample, const glm::dvec3& hit, const glm::dvec3& n)
    {
      for (int l = 0; l < count; ++l)
      {
        double d[3];
        for (int c = 0; c < 3; ++c)
        {
          d[c] = texels->GetComponent(l, c);
        }
        const double cosine = n.x * d[0] + n.y * d[1] + n.z * d[2];
        if (cosine <= 0.0 || d[2] <= 0.0 || !Visible(field, hit, setup.FieldDirection(d)))
        {
          continue;
        }
        for (int c = 0; c < 3; ++c)
        {
          sample.Irradiance[c] += texels->GetComponent(count + l, c) * cosine;
        }
      }
    });
  return samples;
}

//------------------------------------------------------------------------------
double EnvironmentError(
  const Frame& frame, const std::vector<EnvironmentIrradianceSample>& ref, double exposure)
{
  double sum = 0.0;
  long long n = 0;
  for (const EnvironmentIrradianceSample& s : ref)
  {
    if (!frame.Covered(s.Pixel))
    {
      continue;
    }
    double expected = 0.0, rendered = 0.0;
    for (int c = 0; c < 3; ++c)
    {
      expected += 255.0 * exposure * s.Irradiance[c] / Pi<double> / 3.0;
      rendered += frame.Rgb[3 * s.Pixel + c] / 3.0;
    }
    if (expected < 8.0 || expected > 250.0)
    {
      continue; // too dark for 8-bit relative errors, or clipped
    }
    sum += std::abs(rendered - expected) / expected;
    ++n;
  }
  return n > 0 ? 100.0 * sum / n : 0.0;
}

} // namespace mesolight
