// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldReliefSurfaceProbes.h"

#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkImageData.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkReliefMapper.h"

#include "EmbreeScene.h"
#include "EmitterLights.h"
#include "HeightFieldTracer.h"
#include "LightField.h"
#include "PatchComparison.h" // ToWorld
#include "ReliefOcclusion.h"
#include "ReliefSurface.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <stdexcept>
#include <utility>
#include <vector>

namespace mesolight
{
namespace vlf
{
namespace reliefsurface
{
std::vector<vlf::EmitterLight> ReliefEmitterLights(
  const vlf::LightField& field, const vlf::ReliefSurface* surface)
{
  vlf::EmitterLightOptions options;
  options.MaxLights = static_cast<std::size_t>(vtkReliefMapper::GetMaximumNumberOfLights());
  if (surface)
  {
    // The receivers: the surface's texture rectangle, facing its front.
    options.ReceiverCorner = glm::vec3(surface->Origin);
    options.ReceiverEdgeU = glm::vec3(surface->AxisU);
    options.ReceiverEdgeV = glm::vec3(surface->AxisV);
    options.ReceiverNormal = glm::vec3(surface->Normal);
  }
  return vlf::EstimateEmitterLights(field, options).Lights;
}

// The field's emitter lights as VTK lights: radiant intensity Le x Area, the area in world units
// (world = centre + unit / scale). Packed 9 numbers a light (position, normal, intensity), the
// form in which they travel between MPI ranks.
std::vector<double> PackEmitterLights(
  const vlf::LightField& field, const std::vector<vlf::EmitterLight>& emitters)
{
  const double scale = field.NormalizationScale();
  std::vector<double> packed;
  for (const vlf::EmitterLight& emitter : emitters)
  {
    const glm::vec3 world = vlf::ToWorld(field, emitter.Position);
    const glm::vec3 unitIntensity = emitter.Intensity();
    packed.insert(packed.end(),
      { world.x, world.y, world.z, emitter.Normal.x, emitter.Normal.y, emitter.Normal.z,
        unitIntensity.x / (scale * scale), unitIntensity.y / (scale * scale),
        unitIntensity.z / (scale * scale) });
  }
  return packed;
}

void AddPackedLights(const std::vector<double>& packed, vtkLightCollection* lights)
{
  for (std::size_t i = 0; i + 9 <= packed.size(); i += 9)
  {
    vtkNew<vtkLight> light;
    vtkReliefMapper::ConfigureEmitterLight(light, &packed[i], &packed[i + 3], &packed[i + 6]);
    lights->AddItem(light);
  }
}

void AddEmitterLights(const vlf::LightField& field, const std::vector<vlf::EmitterLight>& emitters,
  vtkLightCollection* lights)
{
  AddPackedLights(PackEmitterLights(field, emitters), lights);
}

// The probe image of port 1 from n x n SH9 probes (pixel (9 i + k, j)), as floats.
std::vector<float> PackProbes(const std::vector<mesolight::SH9>& probes, int n)
{
  std::vector<float> values(static_cast<std::size_t>(27) * n * n);
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      const mesolight::SH9& sh = probes[static_cast<std::size_t>(j) * n + i];
      for (int k = 0; k < 9; ++k)
      {
        for (int c = 0; c < 3; ++c)
        {
          values[3 * (static_cast<std::size_t>(j) * 9 * n + 9 * i + k) + c] =
            static_cast<float>(sh.L[k][c]);
        }
      }
    }
  }
  return values;
}

// Port 1: the probes, and as a fourth component (when given: `lights` values per probe, as
// EmitterLightFactors makes them) the factor of light k < 9 at pixel (9 i + k, j).
void FillProbesImage(vtkImageData* image, const std::vector<float>& values, int n,
  const std::vector<float>* factors, std::size_t lights)
{
  image->SetExtent(0, 9 * n - 1, 0, n - 1, 0, 0);
  const int components = factors ? 4 : 3;
  image->AllocateScalars(VTK_FLOAT, components);
  float* out = static_cast<float*>(image->GetScalarPointer());
  const std::size_t pixels = static_cast<std::size_t>(9) * n * n;
  for (std::size_t p = 0; p < pixels; ++p)
  {
    std::copy(&values[3 * p], &values[3 * p] + 3, out + components * p);
    if (factors)
    {
      const std::size_t k = p % 9, probe = p / 9;
      out[4 * p + 3] = k < lights ? (*factors)[probe * lights + k] : 1.0f;
    }
  }
  image->GetPointData()->GetScalars()->SetName("IrradianceProbes");
}

// The emitter lights' factors at the surface's n x n probes (EmitterLightFactors), traced in `lent`
// (an Embree scene of field.Scene()) when given, else in a scene built here.
std::vector<float> LightFactors(const vlf::LightField& field, const vlf::ReliefSurface& surface,
  const std::vector<vlf::EmitterLight>& emitters, int n, const mesolight::EmbreeScene* lent)
{
  if (lent)
  {
    return vlf::EmitterLightFactors(field, *lent, surface, emitters, n, n);
  }
  const mesolight::EmbreeScene embree(field.Scene());
  return vlf::EmitterLightFactors(field, embree, surface, emitters, n, n);
}

// The depth (A) of a relief texture as a height field; throws std::runtime_error saying why not.
mesolight::HeightField ReliefHeightField(vtkImageData* texture, bool walled)
{
  vtkDataArray* rgba = texture ? texture->GetPointData()->GetScalars() : nullptr;
  int dims[3] = { 0, 0, 0 };
  if (texture)
  {
    texture->GetDimensions(dims);
  }
  if (!rgba || rgba->GetNumberOfComponents() != 4 || dims[0] < 1 || dims[1] < 1 ||
    rgba->GetNumberOfTuples() != static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    throw std::runtime_error("the relief texture for the visible-share map must be a 2D RGBA "
                             "image with the depth in A (vtkReliefTextureFilter's output)");
  }
  const bool bytes = rgba->GetDataType() == VTK_UNSIGNED_CHAR;
  std::vector<float> depth(static_cast<std::size_t>(rgba->GetNumberOfTuples()));
  for (vtkIdType i = 0; i < rgba->GetNumberOfTuples(); ++i)
  {
    const double d = rgba->GetComponent(i, 3) / (bytes ? 255.0 : 1.0);
    if (!std::isfinite(d))
    {
      throw std::runtime_error("the relief texture has a depth that is not a number");
    }
    depth[static_cast<std::size_t>(i)] = static_cast<float>(std::clamp(d, 0.0, 1.0));
  }
  return mesolight::HeightField(dims[0], dims[1], std::move(depth),
    walled ? mesolight::HeightField::Edge::Walled : mesolight::HeightField::Edge::Clamped);
}

SurfaceResult ComputeSurface(const vlf::LightField& field, vtkPolyData* whole, int probesPerSide,
  bool sceneOcclusion, const mesolight::ProgressCallback& progress)
{
  std::vector<glm::vec3> positions(static_cast<std::size_t>(whole->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < whole->GetNumberOfPoints(); ++i)
  {
    double p[3];
    whole->GetPoint(i, p);
    positions[i] = vlf::ToUnit(field, glm::vec3(p[0], p[1], p[2]));
  }
  std::vector<glm::vec2> tcoords;
  if (vtkDataArray* t = whole->GetPointData()->GetTCoords())
  {
    tcoords.resize(positions.size());
    for (vtkIdType i = 0; i < t->GetNumberOfTuples(); ++i)
    {
      tcoords[i] = glm::vec2(t->GetComponent(i, 0), t->GetComponent(i, 1));
    }
  }
  std::vector<glm::uvec3> triangles;
  vtkCellArray* polys = whole->GetPolys();
  vtkIdType count = 0;
  const vtkIdType* ids = nullptr;
  for (polys->InitTraversal(); polys->GetNextCell(count, ids);)
  {
    for (vtkIdType k = 1; k + 1 < count; ++k) // fans: the surface is planar
    {
      triangles.emplace_back(static_cast<unsigned>(ids[0]), static_cast<unsigned>(ids[k]),
        static_cast<unsigned>(ids[k + 1]));
    }
  }
  const vlf::ReliefSurface surface =
    vlf::ReliefSurfaceFromTriangles(field, positions, tcoords, triangles, "the relief surface");
  SurfaceResult result;
  const int n = vlf::ReliefProbesPerSide(field, surface, probesPerSide);
  result.ProbesPerSide = n;
  result.Probes = PackProbes(vlf::ReliefSurfaceProbes(field, surface, n, n, progress), n);
  const glm::dvec3 frame[4] = { surface.Origin, surface.AxisU, surface.AxisV, surface.Normal };
  for (int a = 0; a < 4; ++a)
  {
    for (int c = 0; c < 3; ++c)
    {
      result.Frame[3 * a + c] = frame[a][c];
    }
  }
  for (int c = 0; c < 3; ++c)
  {
    result.Frame[12 + c] = field.NormalizationCentre()[c];
    result.Diffuse[c] = surface.Diffuse[c];
    result.Emission[c] = surface.Emission[c];
  }
  result.Frame[15] = field.NormalizationScale();
  if (surface.FieldSurface != vlf::NoSurface && !surface.OtherMaterials.empty())
  {
    // One albedo for the whole relief (the representation's and the mapper's colour): say which,
    // and how to have each material's.
    std::string others;
    for (const std::string& name : surface.OtherMaterials)
    {
      others += (others.empty() ? "'" : ", '") + name + "'";
    }
    const std::string& chosen = field.MaterialOf(surface.FieldSurface).Name;
    result.Warning = "The relief surface lies on scene surfaces of several materials: '" + chosen +
      "' under its centre, and " + others + ". It takes one albedo, '" + chosen +
      "''s Kd, over all of it; to have each material's, split the surface where the materials "
      "meet (one relief per part).";
  }
  if (surface.FieldSurface != vlf::NoSurface)
  {
    // Halfway between the surface's plane and the wall's: in front of the wall by half their gap
    // (no depth fight with it), behind the surface's own plane (its flat parts keep their depth).
    const vlf::Surface& wall = field.Surfaces()[surface.FieldSurface];
    const glm::dvec3 front(wall.Normal);
    const double offset =
      0.5 * (static_cast<double>(wall.Offset) + glm::dot(front, surface.Origin));
    const glm::vec3 point = vlf::ToWorld(field, glm::vec3(front * offset));
    for (int c = 0; c < 3; ++c)
    {
      result.Limit[c] = point[c];
      result.Limit[3 + c] = front[c];
    }
    result.Limit[6] = 1.0;
  }
  const std::vector<vlf::EmitterLight> emitters = ReliefEmitterLights(field, &surface);
  result.Lights = PackEmitterLights(field, emitters);
  if (sceneOcclusion)
  {
    result.Factors = LightFactors(field, surface, emitters, n);
    result.LightSamples = PackEmitterSamples(FirstLightSamples(field, emitters));
  }
  return result;
}

// The relief's own shadow of the first emitter light's area goes into the visible-share map: a
// point light's hard shadow is not the emitter's penumbra (ReliefEmitterShadowMap).
std::vector<ReliefEmitterSample> FirstLightSamples(
  const vlf::LightField& field, const std::vector<vlf::EmitterLight>& emitters)
{
  return emitters.empty()
    ? std::vector<ReliefEmitterSample>()
    : vlf::EmitterSamplesOfLight(field.Scene(), vlf::LightPositions(emitters), 0);
}

std::vector<double> PackEmitterSamples(const std::vector<ReliefEmitterSample>& samples)
{
  std::vector<double> packed;
  packed.reserve(9 * samples.size());
  for (const ReliefEmitterSample& sample : samples)
  {
    for (const glm::dvec3& v : { sample.Position, sample.Normal, sample.RadianceArea })
    {
      packed.insert(packed.end(), { v.x, v.y, v.z });
    }
  }
  return packed;
}

std::vector<ReliefEmitterSample> UnpackEmitterSamples(const std::vector<double>& packed)
{
  std::vector<ReliefEmitterSample> samples(packed.size() / 9);
  for (std::size_t s = 0; s < samples.size(); ++s)
  {
    const double* p = &packed[9 * s];
    samples[s].Position = glm::dvec3(p[0], p[1], p[2]);
    samples[s].Normal = glm::dvec3(p[3], p[4], p[5]);
    samples[s].RadianceArea = glm::dvec3(p[6], p[7], p[8]);
  }
  return samples;
}
} // namespace reliefsurface
} // namespace vlf
} // namespace mesolight
