#include "LightSetBenchmark.h"

#include "CommandLine.h"
#include "ImageCompare.h"
#include "ReliefReference.h"
#include "ReliefScene.h"
#include "vtkReliefMapper.h"

#include "core/EnvironmentMaps.h"
#include "HeightFieldTracer.h"

#include <glm/geometric.hpp>
#include <vtkActor.h>
#include <vtkDataArray.h>
#include <vtkFieldData.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkSMPTools.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <random>
#include <sstream>

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
        s.Radiance[3 * p + c] = static_cast<float>(values->GetComponent(static_cast<vtkIdType>(p), c));
      }
      const double w = std::max(0.0,
        Luminance(s.Radiance[3 * p], s.Radiance[3 * p + 1], s.Radiance[3 * p + 2]) * omega);
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

struct Timing
{
  double MedianMs = 0.0;
};

double MedianFrameMs(vtkRenderWindow* window, int frames)
{
  using Clock = std::chrono::steady_clock;
  window->Render(); // warm-up: shader compilation, uploads
  window->WaitForCompletion();
  std::vector<double> times;
  for (int i = 0; i < frames; ++i)
  {
    const auto t = Clock::now();
    window->Render();
    window->WaitForCompletion();
    times.push_back(std::chrono::duration<double, std::milli>(Clock::now() - t).count());
  }
  std::nth_element(times.begin(), times.begin() + times.size() / 2, times.end());
  return times[times.size() / 2];
}

// GL_LINEAR + CLAMP_TO_EDGE sample of the packed normal (RGB) of a relief texture.
glm::dvec3 SampleNormal(vtkDataArray* rgba, int w, int h, double u, double v)
{
  const double x = u * w - 0.5, y = v * h - 0.5;
  const int i0 = static_cast<int>(std::floor(x)), j0 = static_cast<int>(std::floor(y));
  const double fx = x - i0, fy = y - j0;
  auto texel = [&](int i, int j) {
    i = std::min(std::max(i, 0), w - 1);
    j = std::min(std::max(j, 0), h - 1);
    const vtkIdType id = static_cast<vtkIdType>(j) * w + i;
    return glm::dvec3(rgba->GetComponent(id, 0), rgba->GetComponent(id, 1), rgba->GetComponent(id, 2));
  };
  return (texel(i0, j0) * (1 - fx) + texel(i0 + 1, j0) * fx) * (1 - fy) +
    (texel(i0, j0 + 1) * (1 - fx) + texel(i0 + 1, j0 + 1) * fx) * fy;
}

// What the two references share: the exact bilinear height field of a relief texture, the
// reference pixels, and the shading normal at each pixel's exact hit.
struct ReferenceSetup
{
  int Dims[3] = { 0, 0, 0 };
  double Aspect = 1.0;
  double DepthScale = 1.0;
  vtkDataArray* Rgba = nullptr;
  bool ConePacked = false; // vtkConeMapFilter's packing: normal x, y in RG, cone ratio in B
  std::vector<float> Depth;

  ReferenceSetup(vtkImageData* relief, double depthScale)
    : DepthScale(depthScale)
    , Rgba(relief->GetPointData()->GetScalars())
    , ConePacked(relief->GetFieldData()->GetAbstractArray("MesolightConeType") != nullptr)
  {
    relief->GetDimensions(this->Dims);
    this->Aspect = static_cast<double>(this->Dims[1]) / this->Dims[0];
    this->Depth.resize(static_cast<size_t>(this->Dims[0]) * this->Dims[1]);
    for (size_t i = 0; i < this->Depth.size(); ++i)
    {
      this->Depth[i] = static_cast<float>(this->Rgba->GetComponent(static_cast<vtkIdType>(i), 3));
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

  // The shading normal is the relief texture's (bilinearly sampled, as the GPU does): the asset's
  // normals are part of the scene; only visibility and irradiance are referenced.
  glm::dvec3 WorldNormal(const glm::dvec3& hit) const
  {
    const glm::dvec3 packed = SampleNormal(this->Rgba, this->Dims[0], this->Dims[1], hit.x, hit.y);
    glm::dvec3 nt = packed * 2.0 - 1.0;
    if (this->ConePacked) // as the shader decodes it: z from the filtered x, y
    {
      nt.z = std::sqrt(std::max(0.0, 1.0 - nt.x * nt.x - nt.y * nt.y));
    }
    const double nz = std::max(nt.z, 1e-4);
    // Depth gradient from the baked normal (depth scale k), then the world normal of the
    // surface (u, aspect v, -k d): Pu x Pv.
    const glm::dvec2 g(nt.x / (nz * this->DepthScale), nt.y * this->Aspect / (nz * this->DepthScale));
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
    vtkSMPTools::For(0, static_cast<vtkIdType>(samples.size()), [&](vtkIdType begin, vtkIdType end) {
      for (vtkIdType s = begin; s < end; ++s)
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
    [&](EnvironmentIrradianceSample& sample, const glm::dvec3& hit, const glm::dvec3& n) {
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
    [&](EnvironmentIrradianceSample& sample, const glm::dvec3& hit, const glm::dvec3& n) {
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

//------------------------------------------------------------------------------
int RunLightSetBenchmark(const std::vector<std::string>& args)
{
  CommandLine cl;
  cl.AddValue("--environment", "SPEC", "procedural:sky, procedural:sun or a lat-long HDR file",
    "procedural:sun");
  cl.AddValue("--counts", "N,N,..", "light counts (one run for all)", "32,64,128,256,512,1024");
  cl.AddValue("--skip-count", "N", "light count of the skip measurements", "256");
  cl.AddValue("--frames", "N", "timed frames per configuration (median)", "10");
  cl.AddValue("--size", "WxH", "window size", "512x512");
  cl.AddValue("--samples", "N", "Monte Carlo samples per reference pixel", "2048");
  cl.AddValue("--csv", "FILE", "also write the rows as CSV");
  cl.AddValue("--map", "PATTERN", "procedural height map (HemisphereTorus, Bricks, Stone, ...)",
    "HemisphereTorus");
  cl.AddValue("--compare-count", "N",
    "light count of the relief vs relaxed-cone comparison at equal error (0: skip it)", "64");
  cl.AddFlag("--help", "show this help");
  std::string error;
  int frames = 10, samples = 2048, skipCount = 256, compareCount = 64;
  if (!cl.Parse(args, error) || !cl.GetInt("--frames", 1, 1000, frames, error) ||
    !cl.GetInt("--samples", 16, 1 << 20, samples, error) ||
    !cl.GetInt("--skip-count", 1, 4096, skipCount, error) ||
    !cl.GetInt("--compare-count", 0, 4096, compareCount, error))
  {
    std::cerr << "mesolight bench ibl: " << error << "\n";
    return 2;
  }
  if (cl.Has("--help"))
  {
    std::cout << "mesolight bench ibl [options]\n\nA relief (--map, relief 16+8, self-shadowed) "
                 "lit only by median-cut light\nsets of an environment: frame time per light "
                 "count, the effect of each skip, the error\nagainst a Monte Carlo reference with "
                 "exact height-field visibility, and relief vs relaxed\ncone stepping at equal "
                 "error against the exact render of the same lights\n(--compare-count "
                 "lights).\n\nOptions:\n";
    cl.PrintOptions(std::cout);
    return 0;
  }
  std::vector<int> counts;
  {
    std::istringstream in(cl.Get("--counts"));
    std::string item;
    while (std::getline(in, item, ','))
    {
      const int n = std::atoi(item.c_str());
      if (n < 1 || n > 4096)
      {
        std::cerr << "mesolight bench ibl: bad count '" << item << "'\n";
        return 2;
      }
      counts.push_back(n);
    }
  }
  ReliefSceneOptions o;
  o.Pattern = cl.Get("--map");
  o.Resolution = 256;
  o.DepthScale = 0.12;
  o.ViewAngle = 40.0;
  o.ViewDistance = 2.2;
  o.Lights = 0;
  o.LinearSteps = 16;
  o.RefinementSteps = 8;
  o.Environment = cl.Get("--environment");
  o.EnvironmentLights = counts.front();
  {
    const std::string size = cl.Get("--size");
    char x = 0;
    std::istringstream in(size);
    if (!(in >> o.Width >> x >> o.Height) || x != 'x' || o.Width < 16 || o.Height < 16)
    {
      std::cerr << "mesolight bench ibl: bad --size " << size << "\n";
      return 2;
    }
  }

  ReliefScene scene;
  if (!BuildReliefScene(o, scene, error))
  {
    std::cerr << "mesolight bench ibl: " << error << "\n";
    return 1;
  }
  // White Lambertian surface, lit by the environment only: the reference is albedo / pi x E.
  scene.Actor->SetTexture(nullptr);
  scene.Actor->GetProperty()->SetAmbient(0.0);
  scene.Actor->GetProperty()->SetDiffuse(1.0);
  scene.Actor->GetProperty()->SetSpecular(0.0);
  vtkSmartPointer<vtkImageData> environment = LoadEnvironment(o.Environment, error);
  if (!environment)
  {
    std::cerr << "mesolight bench ibl: " << error << "\n";
    return 1;
  }
  ReliefReference hits;
  if (!ComputeReliefReference(MakeReliefReferenceInput(scene, o), hits, error))
  {
    std::cerr << "mesolight bench ibl: " << error << "\n";
    return 1;
  }
  const auto referenceStart = std::chrono::steady_clock::now();
  const std::vector<EnvironmentIrradianceSample> reference = ComputeEnvironmentReference(
    hits, scene.ReliefTexture, environment, o.DepthScale, 3000, samples, true);
  const double referenceSeconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - referenceStart).count();
  // Exposure: the brightest reference pixel at about 200 of 255.
  double brightest = 0.0;
  for (const auto& s : reference)
  {
    brightest = std::max(brightest, (s.Irradiance[0] + s.Irradiance[1] + s.Irradiance[2]) / 3.0);
  }
  const double exposure = brightest > 0.0 ? 200.0 / 255.0 * Pi<double> / brightest : 1.0;
  scene.Mapper->SetExposure(exposure);

  auto window = MakeOffscreenWindow(o, scene.Renderer);
  struct Row
  {
    std::string Config;
    int Lights;
    double Ms;
    double ErrorMc;
    double DiffFull; // mean |difference| to the unskipped render, 8-bit levels (-1: n/a)
  };
  std::vector<Row> rows;
  auto setLights = [&](int count) {
    ReliefSceneOptions lo = o;
    lo.EnvironmentLights = count;
    vtkSmartPointer<vtkImageData> lights = MakeEnvironmentLights(lo, error);
    scene.Mapper->SetLightSetData(lights);
    return lights;
  };
  auto measure = [&](const std::string& config, int count, const Frame* full) {
    const double ms = MedianFrameMs(window, frames);
    const Frame frame = CaptureFrame(window);
    rows.push_back({ config, count, ms, EnvironmentError(frame, reference, exposure),
      full ? CompareFrames(frame, *full, 1e30).MeanColorError : -1.0 });
    return frame;
  };

  for (int count : counts)
  {
    setLights(count);
    measure("every light marches its shadow", count, nullptr);
  }
  scene.Mapper->SetShadowedLights(32);
  for (int count : counts)
  {
    setLights(count);
    measure("shadows for the 32 strongest facing lights", count, nullptr);
  }
  scene.Mapper->SetShadowedLights(0);
  setLights(skipCount);
  const Frame full = measure("reference configuration", skipCount, nullptr);
  scene.Mapper->ShadowCullingOff();
  measure("no culling of lights behind the normal", skipCount, &full);
  scene.Mapper->ShadowCullingOn();
  for (double threshold : { 0.01, 0.05 })
  {
    scene.Mapper->SetLightSetThreshold(threshold);
    std::ostringstream label;
    label << "skip lights < " << threshold * 100 << "% of the strongest";
    measure(label.str(), skipCount, &full);
  }
  scene.Mapper->SetLightSetThreshold(0.0);
  for (int k : { 8, 32 })
  {
    scene.Mapper->SetShadowedLights(k);
    measure("shadows for the " + std::to_string(k) + " strongest lights only", skipCount, &full);
  }
  scene.Mapper->SetShadowedLights(0);
  scene.Mapper->SelfShadowingOff();
  measure("no self-shadowing (negative reference)", skipCount, &full);
  scene.Mapper->SelfShadowingOn();

  // Relief vs relaxed cone stepping under many self-shadowing lights (the relief thesis' multi-light
  // table: relaxed cone 1.8-1.9x relief's frame rate at 32-1024 lights, 10 linear or cone steps +
  // 8 binary). Every light marches its shadow, with the method's search; each setting's time, its
  // relief-texture samples per pixel, its error against the exact render of the same lights (the
  // method's own error: hits and visibility), and against the Monte Carlo reference of the whole
  // environment (which adds the light set's sampling error, the same for both methods).
  struct MethodRow
  {
    int Method;
    int Steps;
    double Ms, ErrorLights, ErrorMc, Samples;
  };
  double lightsReferenceSeconds = 0.0;
  std::vector<MethodRow> methodRows;
  vtkSmartPointer<vtkImageData> coneRelief;
  vtkSmartPointer<vtkTexture> unusedAlbedo;
  if (compareCount > 0 &&
    !BuildReliefTextures(o, coneRelief, unusedAlbedo, error, vtkReliefMapper::RelaxedConeMap))
  {
    std::cerr << "mesolight bench ibl: relaxed cone map: " << error << "\n";
    return 1;
  }
  if (compareCount > 0)
  {
    vtkSmartPointer<vtkImageData> lights = setLights(compareCount);
    const auto start = std::chrono::steady_clock::now();
    // One per texture: each method is shaded with its own texture's normals (the cone packing
    // reconstructs z from the filtered x, y), which is the asset, not the method's error.
    const std::vector<EnvironmentIrradianceSample> lightsReference[2] = {
      ComputeLightSetReference(hits, scene.ReliefTexture, lights, o.DepthScale, 3000),
      ComputeLightSetReference(hits, coneRelief, lights, o.DepthScale, 3000)
    };
    lightsReferenceSeconds =
      std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
    if (lightsReference[0].empty() || lightsReference[1].empty())
    {
      std::cerr << "mesolight bench ibl: no pixel for the light-set reference (empty light set or "
                   "relief texture, or nothing covered)\n";
      return 1;
    }
    for (int method : { int(vtkReliefMapper::Relief), int(vtkReliefMapper::RelaxedConeBinary) })
    {
      scene.Mapper->SetReliefTextureData(
        method == vtkReliefMapper::Relief ? scene.ReliefTexture.Get() : coneRelief.Get());
      scene.Mapper->SetMethod(method);
      for (int steps : { 4, 6, 8, 10, 12, 16, 24, 32, 48, 64 })
      {
        scene.Mapper->SetLinearSteps(steps);
        scene.Mapper->SetRefinementSteps(8);
        MethodRow row{ method, steps, MedianFrameMs(window, frames), 0.0, 0.0, 0.0 };
        const Frame frame = CaptureFrame(window);
        row.ErrorLights = EnvironmentError(
          frame, lightsReference[method == vtkReliefMapper::Relief ? 0 : 1], exposure);
        row.ErrorMc = EnvironmentError(frame, reference, exposure);
        scene.Mapper->SetOutput(vtkReliefMapper::SampleCountOutput);
        row.Samples = MeanSampleCount(CaptureFrame(window));
        scene.Mapper->SetOutput(vtkReliefMapper::ShadedOutput);
        methodRows.push_back(row);
      }
    }
    scene.Mapper->SetReliefTextureData(scene.ReliefTexture);
    scene.Mapper->SetMethod(vtkReliefMapper::Relief);
    scene.Mapper->SetLinearSteps(o.LinearSteps);
    scene.Mapper->SetRefinementSteps(o.RefinementSteps);
  }

  std::cout << "Relief lit by median-cut lights of " << o.Environment << " (relief 16+8, "
            << o.Width << "x" << o.Height << ", " << frames << " timed frames, median)\n"
            << "Error: mean relative error of the rendered radiance against a Monte Carlo "
               "reference\n(exact first hits and exact height-field visibility, "
            << samples << " samples per pixel, " << reference.size() << " pixels, "
            << std::fixed << std::setprecision(1) << referenceSeconds << " s).\n\n";
  std::cout << std::left << std::setw(46) << "configuration" << std::right << std::setw(7)
            << "lights" << std::setw(11) << "ms/frame" << std::setw(11) << "error %"
            << std::setw(13) << "vs full lvl" << "\n";
  for (const Row& r : rows)
  {
    std::cout << std::left << std::setw(46) << r.Config << std::right << std::setw(7) << r.Lights
              << std::fixed << std::setprecision(1) << std::setw(11) << r.Ms
              << std::setprecision(2) << std::setw(11) << r.ErrorMc << std::setw(13);
    if (r.DiffFull >= 0.0)
    {
      std::cout << r.DiffFull;
    }
    else
    {
      std::cout << "-";
    }
    std::cout << "\n";
  }
  for (const char* series :
    { "every light marches its shadow", "shadows for the 32 strongest facing lights" })
  {
    const Row* first = nullptr;
    const Row* last = nullptr;
    for (const Row& r : rows)
    {
      if (r.Config == series)
      {
        first = first ? first : &r;
        last = &r;
      }
    }
    if (first && last && first != last)
    {
      std::cout << "\n" << series << ": " << last->Lights << " lights take "
                << std::setprecision(1) << last->Ms / first->Ms << "x the time of "
                << first->Lights << " (the relief thesis: 29x from 32 to 1024).";
    }
  }
  std::cout << "\n";

  if (!methodRows.empty())
  {
    std::cout << "\nRelief vs relaxed cone stepping, " << compareCount
              << " lights, every light marches its shadow with the method's search (steps + 8 "
                 "binary).\nError: against the exact render of the same lights (exact hits and "
                 "visibility, "
              << std::setprecision(1) << lightsReferenceSeconds
              << " s), and against the Monte Carlo reference above.\n"
              << std::left << std::setw(16) << "method" << std::right << std::setw(7) << "steps"
              << std::setw(11) << "ms/frame" << std::setw(11) << "samples" << std::setw(11)
              << "error %" << std::setw(11) << "vs MC %" << "\n";
    for (const MethodRow& r : methodRows)
    {
      std::cout << std::left << std::setw(16)
                << (r.Method == vtkReliefMapper::Relief ? "relief" : "relaxed-cone") << std::right
                << std::setw(7) << r.Steps << std::fixed << std::setprecision(1) << std::setw(11)
                << r.Ms << std::setw(11) << r.Samples << std::setprecision(2) << std::setw(11)
                << r.ErrorLights << std::setw(11) << r.ErrorMc << "\n";
    }
    // Equal error (the method's own, against the same lights): each relief setting's error E
    // (plus 0.05 points: 8-bit quantization) is a target; each method's cheapest setting reaching
    // it, in ms and in samples.
    std::vector<double> msRatios, sampleRatios;
    for (const MethodRow& target : methodRows)
    {
      if (target.Method != vtkReliefMapper::Relief)
      {
        continue;
      }
      const MethodRow* fastest[2] = { nullptr, nullptr };
      const MethodRow* leanest[2] = { nullptr, nullptr };
      for (const MethodRow& r : methodRows)
      {
        const int k = r.Method == vtkReliefMapper::Relief ? 0 : 1;
        if (r.ErrorLights > target.ErrorLights + 0.05)
        {
          continue;
        }
        fastest[k] = !fastest[k] || r.Ms < fastest[k]->Ms ? &r : fastest[k];
        leanest[k] = !leanest[k] || r.Samples < leanest[k]->Samples ? &r : leanest[k];
      }
      if (fastest[0] && fastest[1] && fastest[1]->Ms > 0.0 && leanest[1]->Samples > 0.0)
      {
        msRatios.push_back(fastest[0]->Ms / fastest[1]->Ms);
        sampleRatios.push_back(leanest[0]->Samples / leanest[1]->Samples);
      }
    }
    if (!msRatios.empty())
    {
      std::sort(msRatios.begin(), msRatios.end());
      std::sort(sampleRatios.begin(), sampleRatios.end());
      std::cout << "At equal error (each relief setting's error a target, " << msRatios.size()
                << " targets): relief / relaxed cone = " << std::setprecision(2)
                << msRatios[msRatios.size() / 2] << "x in ms/frame (range " << msRatios.front()
                << " - " << msRatios.back() << "), "
                << sampleRatios[sampleRatios.size() / 2] << "x in samples per pixel (range "
                << sampleRatios.front() << " - " << sampleRatios.back()
                << ").\nThe relief thesis, 10 steps each at 32-1024 lights: 1.8-1.9x in frame "
                   "rate.\n";
    }
  }
  const std::string csvFile = cl.Get("--csv");
  if (!csvFile.empty())
  {
    std::ofstream csv(csvFile);
    csv << "configuration,lights,ms_per_frame,error_pct_vs_monte_carlo,mean_diff_vs_full\n";
    for (const Row& r : rows)
    {
      csv << '"' << r.Config << "\"," << r.Lights << ',' << r.Ms << ',' << r.ErrorMc << ','
          << (r.DiffFull >= 0.0 ? std::to_string(r.DiffFull) : std::string()) << "\n";
    }
    std::cout << "wrote " << csvFile << "\n";
  }
  return 0;
}

} // namespace mesolight
