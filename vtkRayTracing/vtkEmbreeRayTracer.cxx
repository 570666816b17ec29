// SPDX-License-Identifier: BSD-3-Clause
#include "vtkEmbreeRayTracer.h"
#include "vtkUnitScale.h"

#include "TexturedRayTracer.h"

#include "vtkActor.h"
#include "vtkActorCollection.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkCellArrayIterator.h"
#include "vtkDataArray.h"
#include "vtkFloatArray.h"
#include "vtkImageData.h"
#include "vtkInformation.h"
#include "vtkInformationVector.h"
#include "vtkLight.h"
#include "vtkLightCollection.h"
#include "vtkMapper.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkSphereSource.h"
#include "vtkStreamingDemandDrivenPipeline.h"
#include "vtkTexture.h"
#include "vtkTriangleSceneConverter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkWeakPointer.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>
#include <memory>
#include <stdexcept>
#include <string>
#include <vector>

vtkStandardNewMacro(vtkEmbreeRayTracer);

struct vtkEmbreeRayTracer::Internals
{
  vtkSmartPointer<vtkRenderer> Renderer;
  struct MapEntry
  {
    vtkWeakPointer<vtkActor> Actor;
    int Channel;
    vtkSmartPointer<vtkImageData> Image;
  };
  std::vector<MapEntry> Maps;
  vtkNew<vtkImageData> Partial;
};

namespace
{
using mesolight::RgbImage;

glm::vec3 Point(vtkMatrix4x4* m, const double p[3])
{
  double in[4] = { p[0], p[1], p[2], 1.0 };
  double out[4];
  m->MultiplyPoint(in, out);
  const double w = out[3] != 0.0 ? out[3] : 1.0;
  return glm::vec3(out[0] / w, out[1] / w, out[2] / w);
}

glm::vec3 Column(vtkMatrix4x4* m, int c)
{
  return glm::vec3(m->GetElement(0, c), m->GetElement(1, c), m->GetElement(2, c));
}

glm::vec3 Vec3(const double v[3])
{
  return glm::vec3(static_cast<float>(v[0]), static_cast<float>(v[1]), static_cast<float>(v[2]));
}

// An image's first slice as RGB floats in [0, 1] for 8/16-bit integers, as-is for floats.
// Empty when the image has no usable scalars.
std::shared_ptr<const RgbImage> ToRgb(vtkImageData* image)
{
  if (!image)
  {
    return nullptr;
  }
  int dims[3];
  image->GetDimensions(dims);
  vtkDataArray* scalars = image->GetPointData()->GetScalars();
  if (!scalars || dims[0] < 1 || dims[1] < 1 ||
    scalars->GetNumberOfTuples() < static_cast<vtkIdType>(dims[0]) * dims[1])
  {
    return std::make_shared<RgbImage>(); // empty: the tracer warns and ignores it
  }
  const double scale = mesolight::UnitScale(scalars);
  const int components = scalars->GetNumberOfComponents();
  auto rgb = std::make_shared<RgbImage>(dims[0], dims[1]);
  for (int j = 0; j < dims[1]; ++j)
  {
    for (int i = 0; i < dims[0]; ++i)
    {
      const vtkIdType id = static_cast<vtkIdType>(j) * dims[0] + i;
      float* out = rgb->Pixel(i, j);
      for (int c = 0; c < 3; ++c)
      {
        // Grey (1 or 2 components: luminance, alpha) fills all three channels.
        const int source = components >= 3 ? c : 0;
        out[c] = static_cast<float>(scalars->GetComponent(id, source) * scale);
      }
    }
  }
  return rgb;
}

bool IsSimilarity(vtkMatrix4x4* m, float& scale)
{
  const float sx = glm::length(Column(m, 0));
  const float sy = glm::length(Column(m, 1));
  const float sz = glm::length(Column(m, 2));
  scale = sx;
  const bool affine = m->GetElement(3, 0) == 0.0 && m->GetElement(3, 1) == 0.0 &&
    m->GetElement(3, 2) == 0.0 && m->GetElement(3, 3) == 1.0;
  const bool orthogonal = std::abs(glm::dot(Column(m, 0), Column(m, 1))) < 1e-4f * sx * sy &&
    std::abs(glm::dot(Column(m, 1), Column(m, 2))) < 1e-4f * sy * sz &&
    std::abs(glm::dot(Column(m, 0), Column(m, 2))) < 1e-4f * sx * sz;
  return affine && orthogonal && sx > 0.0f && std::abs(sx - sy) < 1e-4f * sx &&
    std::abs(sx - sz) < 1e-4f * sx;
}

bool FullSphere(vtkSphereSource* source)
{
  return source->GetStartTheta() <= 0.0 && source->GetEndTheta() >= 360.0 &&
    source->GetStartPhi() <= 0.0 && source->GetEndPhi() >= 180.0 && source->GetRadius() > 0.0;
}
} // namespace

vtkEmbreeRayTracer::vtkEmbreeRayTracer()
  : Impl(new Internals)
{
  this->SetNumberOfInputPorts(0);
  this->SetNumberOfOutputPorts(1);
}

vtkEmbreeRayTracer::~vtkEmbreeRayTracer() = default;

void vtkEmbreeRayTracer::SetRenderer(vtkRenderer* renderer)
{
  if (this->Impl->Renderer != renderer)
  {
    this->Impl->Renderer = renderer;
    this->Modified();
  }
}

vtkRenderer* vtkEmbreeRayTracer::GetRenderer()
{
  return this->Impl->Renderer;
}

void vtkEmbreeRayTracer::SetMaterialMap(vtkActor* actor, int channel, vtkImageData* image)
{
  if (!actor)
  {
    vtkErrorMacro("SetMaterialMap: no actor given");
    return;
  }
  if (channel < 0 || channel >= NUMBER_OF_MATERIAL_CHANNELS)
  {
    vtkErrorMacro("SetMaterialMap: channel " << channel
                                             << " is not one of DIFFUSE_MAP .. ROUGHNESS_MAP (0.."
                                             << NUMBER_OF_MATERIAL_CHANNELS - 1 << ")");
    return;
  }
  auto& maps = this->Impl->Maps;
  maps.erase(std::remove_if(maps.begin(), maps.end(),
               [&](const Internals::MapEntry& e)
               { return !e.Actor || (e.Actor == actor && e.Channel == channel); }),
    maps.end());
  if (image)
  {
    maps.push_back(Internals::MapEntry{ actor, channel, image });
  }
  this->Modified();
}

void vtkEmbreeRayTracer::RemoveAllMaterialMaps()
{
  this->Impl->Maps.clear();
  this->Modified();
}

vtkImageData* vtkEmbreeRayTracer::GetPartialImage()
{
  return this->Impl->Partial;
}

vtkMTimeType vtkEmbreeRayTracer::GetMTime()
{
  vtkMTimeType time = this->Superclass::GetMTime();
  vtkRenderer* renderer = this->Impl->Renderer;
  if (!renderer)
  {
    return time;
  }
  time = std::max(time, renderer->GetMTime());
  if (renderer->GetActiveCamera())
  {
    time = std::max(time, renderer->GetActiveCamera()->GetMTime());
  }
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    time = std::max(time, actor->GetMTime());
  }
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal(it);
  while (vtkLight* light = lights->GetNextLight(it))
  {
    time = std::max(time, light->GetMTime());
  }
  for (const auto& entry : this->Impl->Maps)
  {
    if (entry.Image)
    {
      time = std::max(time, entry.Image->GetMTime());
    }
  }
  return time;
}

bool vtkEmbreeRayTracer::ImageSize(int& width, int& height)
{
  width = this->Width;
  height = this->Height;
  if ((width == 0 || height == 0) && this->Impl->Renderer)
  {
    const int* size = this->Impl->Renderer->GetSize();
    width = width == 0 ? size[0] : width;
    height = height == 0 ? size[1] : height;
  }
  return width > 0 && height > 0;
}

int vtkEmbreeRayTracer::RequestInformation(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  int width = 0, height = 0;
  if (!this->ImageSize(width, height))
  {
    width = height = 1; // RequestData reports the error
  }
  vtkInformation* info = outputVector->GetInformationObject(0);
  const int extent[6] = { 0, width - 1, 0, height - 1, 0, 0 };
  info->Set(vtkStreamingDemandDrivenPipeline::WHOLE_EXTENT(), extent, 6);
  vtkDataObject::SetPointDataActiveScalarInfo(info, VTK_UNSIGNED_CHAR, 3);
  return 1;
}

int vtkEmbreeRayTracer::RequestData(
  vtkInformation*, vtkInformationVector**, vtkInformationVector* outputVector)
{
  vtkImageData* output = vtkImageData::GetData(outputVector);
  this->PrimaryRays = this->ShadowRays = this->SecondaryRays = this->SupersampledPixels = 0;
  this->AnalyticSphereCount = 0;
  this->TriangleCount = 0;
  vtkRenderer* renderer = this->Impl->Renderer;
  if (!renderer)
  {
    vtkErrorMacro("No renderer: call SetRenderer first.");
    return 0;
  }
  int width = 0, height = 0;
  if (!this->ImageSize(width, height))
  {
    vtkErrorMacro(
      "No image size: set Width and Height, or give the renderer a render window with a size.");
    return 0;
  }
  vtkCamera* camera = renderer->GetActiveCamera();

  // The scene: one material per actor.
  mesolight::TexturedScene scene;
  vtkActorCollection* actors = renderer->GetActors();
  vtkCollectionSimpleIterator it;
  actors->InitTraversal(it);
  while (vtkActor* actor = actors->GetNextActor(it))
  {
    vtkMapper* mapper = actor->GetMapper();
    if (!actor->GetVisibility() || !mapper)
    {
      continue;
    }
    vtkProperty* property = actor->GetProperty();
    mesolight::TexturedMaterial material;
    material.Name = std::string("actor ") + std::to_string(scene.Materials.size());
    material.Ambient =
      static_cast<float>(property->GetAmbient()) * Vec3(property->GetAmbientColor());
    material.Diffuse =
      static_cast<float>(property->GetDiffuse()) * Vec3(property->GetDiffuseColor());
    material.Specular =
      static_cast<float>(property->GetSpecular()) * Vec3(property->GetSpecularColor());
    material.SpecularPower = static_cast<float>(property->GetSpecularPower());
    material.BumpScale = static_cast<float>(property->GetNormalScale());
    if (vtkTexture* texture = actor->GetTexture())
    {
      if (texture->GetInputAlgorithm())
      {
        texture->GetInputAlgorithm()->Update();
      }
      if (texture->GetInput())
      {
        material.DiffuseMap = ToRgb(texture->GetInput());
      }
      else
      {
        vtkWarningMacro("Actor " << actor << " has a texture without an image; it is ignored.");
      }
    }
    for (const auto& entry : this->Impl->Maps)
    {
      if (entry.Actor != actor)
      {
        continue;
      }
      std::shared_ptr<const RgbImage> map = ToRgb(entry.Image);
      switch (entry.Channel)
      {
        case DIFFUSE_MAP:
          material.DiffuseMap = map;
          break;
        case SPECULAR_MAP:
          material.SpecularMap = map;
          break;
        case AMBIENT_MAP:
          material.AmbientMap = map;
          break;
        case SHININESS_MAP:
          material.ShininessMap = map;
          break;
        case BUMP_MAP:
          material.BumpMap = map;
          break;
        case ROUGHNESS_MAP:
          material.RoughnessMap = map;
          material.Roughness = 1.0f; // roughness comes from the map (Ahern 1999 §2)
          break;
        default:
          break;
      }
    }
    const auto materialId = static_cast<std::uint32_t>(scene.Materials.size());
    scene.Materials.push_back(material);

    vtkMatrix4x4* matrix = actor->GetMatrix();
    auto* sphereSource = vtkSphereSource::SafeDownCast(mapper->GetInputAlgorithm());
    float scale = 1.0f;
    if (this->AnalyticSpheres && sphereSource && FullSphere(sphereSource) &&
      IsSimilarity(matrix, scale))
    {
      mesolight::TexturedSphere sphere;
      sphere.Geometry.Center = Point(matrix, sphereSource->GetCenter());
      sphere.Geometry.Radius = static_cast<float>(sphereSource->GetRadius()) * scale;
      sphere.Axis = glm::normalize(Column(matrix, 2));
      sphere.Meridian = glm::normalize(Column(matrix, 0));
      sphere.Material = materialId;
      scene.Spheres.push_back(sphere);
      continue;
    }
    if (mapper->GetInputAlgorithm())
    {
      mapper->GetInputAlgorithm()->Update();
    }
    vtkPolyData* input = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
    if (!input)
    {
      vtkWarningMacro(
        "Actor " << actor << ": the mapper's input is not vtkPolyData; it is not traced.");
      continue;
    }
    if (input->GetNumberOfPolys() + input->GetNumberOfStrips() == 0)
    {
      if (input->GetNumberOfCells() > 0)
      {
        vtkWarningMacro("Actor " << actor << " has only points or lines; they are not traced.");
      }
      continue;
    }
    mesolight::TriangleMesh mesh;
    vtkTriangleSceneConverter::ToTriangleMesh(input, mesh);
    const bool normals = !mesh.Normals.empty();
    const bool tcoords = !mesh.TextureCoordinates.empty();
    if (!tcoords &&
      (material.DiffuseMap || material.SpecularMap || material.AmbientMap ||
        material.ShininessMap || material.BumpMap || material.RoughnessMap))
    {
      vtkWarningMacro(
        "Actor " << actor << " has texture maps but no texture coordinates: they read at (0, 0).");
    }
    // Append with the scene's per-vertex attributes kept only when every actor has them:
    // meshes without normals get their own face normals, without texture coordinates (0, 0).
    mesolight::TriangleScene& out = scene.Mesh;
    const auto first = static_cast<std::uint32_t>(out.Positions.size());
    vtkNew<vtkMatrix4x4> normalMatrix;
    vtkMatrix4x4::Invert(matrix, normalMatrix);
    normalMatrix->Transpose();
    for (std::size_t p = 0; p < mesh.Positions.size(); ++p)
    {
      const glm::vec3& position = mesh.Positions[p];
      const double point[3] = { position.x, position.y, position.z };
      out.Positions.push_back(Point(matrix, point));
      glm::vec3 n(0.0f);
      if (normals)
      {
        const double in[4] = { mesh.Normals[p].x, mesh.Normals[p].y, mesh.Normals[p].z, 0.0 };
        double transformed[4];
        normalMatrix->MultiplyPoint(in, transformed);
        n = glm::vec3(transformed[0], transformed[1], transformed[2]);
      }
      out.Normals.push_back(n);
      out.TextureCoordinates.push_back(tcoords ? mesh.TextureCoordinates[p] : glm::vec2(0.0f));
    }
    for (const glm::uvec3& t : mesh.Triangles)
    {
      out.Triangles.push_back(t + glm::uvec3(first));
      out.MaterialIds.push_back(materialId);
    }
  }
  // Meshes without normals: their zero normals make the tracer use face normals.
  scene.Background = Vec3(renderer->GetBackground());

  // Lights, in world coordinates.
  vtkLightCollection* lights = renderer->GetLights();
  lights->InitTraversal(it);
  int lightCount = 0;
  while (vtkLight* light = lights->GetNextLight(it))
  {
    ++lightCount;
    if (!light->GetSwitch())
    {
      continue;
    }
    glm::vec3 position = Vec3(light->GetPosition());
    glm::vec3 focal = Vec3(light->GetFocalPoint());
    if (light->LightTypeIsHeadlight())
    {
      position = Vec3(camera->GetPosition());
      focal = Vec3(camera->GetFocalPoint());
    }
    else if (light->LightTypeIsCameraLight())
    {
      vtkMatrix4x4* toWorld = camera->GetCameraLightTransformMatrix();
      position = Point(toWorld, light->GetPosition());
      focal = Point(toWorld, light->GetFocalPoint());
    }
    mesolight::SceneLightSource source;
    source.Positional = light->GetPositional() != 0;
    source.Position = position;
    source.Direction = focal - position;
    if (!(glm::length(source.Direction) > 0.0f))
    {
      source.Direction = glm::vec3(0.0f, 0.0f, -1.0f);
      vtkWarningMacro(
        "Light " << light << " has its position at its focal point; it shines along -z.");
    }
    source.Colour = static_cast<float>(light->GetIntensity()) * Vec3(light->GetDiffuseColor());
    source.ConeAngleDegrees = static_cast<float>(light->GetConeAngle());
    source.Exponent = static_cast<float>(light->GetExponent());
    source.Attenuation = Vec3(light->GetAttenuationValues());
    scene.Lights.push_back(source);
  }
  if (lightCount == 0 && renderer->GetAutomaticLightCreation())
  {
    mesolight::SceneLightSource headlight;
    headlight.Direction = Vec3(camera->GetFocalPoint()) - Vec3(camera->GetPosition());
    scene.Lights.push_back(headlight);
  }

  mesolight::PinholeCamera pinhole;
  pinhole.Position = Vec3(camera->GetPosition());
  pinhole.FocalPoint = Vec3(camera->GetFocalPoint());
  pinhole.ViewUp = Vec3(camera->GetViewUp());
  pinhole.ViewAngleDegrees = static_cast<float>(camera->GetViewAngle());
  if (camera->GetParallelProjection())
  {
    vtkWarningMacro("Parallel projection is not supported: the image uses a perspective camera.");
  }
  if (!pinhole.Valid())
  {
    vtkErrorMacro("The renderer's camera is degenerate (position at the focal point, or view up "
                  "along the view).");
    return 0;
  }

  mesolight::RayTracerSettings settings;
  settings.MaxDepth = this->MaxDepth;
  settings.Shadows = this->Shadows;
  settings.Reflections = this->Reflections;
  settings.GlossySamples = this->GlossySamples;
  settings.Filter =
    this->BilinearTextures ? mesolight::TextureFilter::Bilinear : mesolight::TextureFilter::Nearest;
  settings.AdaptiveSupersampling = this->AdaptiveSupersampling;
  settings.AdaptiveThreshold = static_cast<float>(this->AdaptiveThreshold);
  settings.Progressive = this->Progressive;
  settings.Threads = this->NumberOfThreads;
  settings.Seed = this->Seed;

  std::unique_ptr<mesolight::TexturedRayTracer> tracer;
  try
  {
    tracer.reset(new mesolight::TexturedRayTracer(std::move(scene), settings));
  }
  catch (const std::exception& e)
  {
    vtkErrorMacro("Cannot trace the renderer's scene: " << e.what());
    return 0;
  }
  for (const std::string& warning : tracer->Warnings())
  {
    vtkWarningMacro(<< warning);
  }
  this->AnalyticSphereCount = static_cast<int>(tracer->Scene().Spheres.size());
  this->TriangleCount = static_cast<vtkIdType>(tracer->Scene().Mesh.TriangleCount());

  auto fill = [width, height](vtkImageData* image, const RgbImage& rgb)
  {
    image->SetDimensions(width, height, 1);
    vtkNew<vtkUnsignedCharArray> bytes;
    bytes->SetName("RGB");
    bytes->SetNumberOfComponents(3);
    bytes->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
    vtkNew<vtkFloatArray> radiance;
    radiance->SetName("Radiance");
    radiance->SetNumberOfComponents(3);
    radiance->SetNumberOfTuples(static_cast<vtkIdType>(width) * height);
    for (std::size_t v = 0; v < rgb.Rgb.size(); ++v)
    {
      const float value = rgb.Rgb[v];
      radiance->SetValue(static_cast<vtkIdType>(v), value);
      const float clamped = std::isfinite(value) ? std::min(1.0f, std::max(0.0f, value)) : 0.0f;
      bytes->SetValue(
        static_cast<vtkIdType>(v), static_cast<unsigned char>(clamped * 255.0f + 0.5f));
    }
    image->GetPointData()->SetScalars(bytes);
    image->GetPointData()->AddArray(radiance);
  };

  int levels = 1;
  while ((1 << (levels - 1)) < std::max(width, height))
  {
    ++levels;
  }
  int level = 0;
  const RgbImage image = tracer->Render(
    pinhole, width, height,
    [&](const RgbImage& partial, int)
    {
      fill(this->Impl->Partial, partial);
      this->UpdateProgress(std::min(0.99, static_cast<double>(++level) / levels));
      this->InvokeEvent(RefinementEvent, nullptr);
      return !this->GetAbortExecute();
    },
    [this](double) { return !this->GetAbortExecute(); });
  const mesolight::RayCounts counts = tracer->LastCounts();
  this->PrimaryRays = counts.Primary;
  this->ShadowRays = counts.Shadow;
  this->SecondaryRays = counts.Secondary;
  this->SupersampledPixels = counts.SupersampledPixels;
  if (image.Width == 0)
  {
    if (!this->GetAbortExecute())
    {
      vtkErrorMacro("Ray tracing failed.");
    }
    return 0;
  }
  fill(output, image);
  this->UpdateProgress(1.0);
  return 1;
}

void vtkEmbreeRayTracer::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "Renderer: " << this->Impl->Renderer.GetPointer() << "\n";
  os << indent << "Width: " << this->Width << "\n";
  os << indent << "Height: " << this->Height << "\n";
  os << indent << "MaxDepth: " << this->MaxDepth << "\n";
  os << indent << "Shadows: " << this->Shadows << "\n";
  os << indent << "Reflections: " << this->Reflections << "\n";
  os << indent << "AnalyticSpheres: " << this->AnalyticSpheres << "\n";
  os << indent << "GlossySamples: " << this->GlossySamples << "\n";
  os << indent << "BilinearTextures: " << this->BilinearTextures << "\n";
  os << indent << "AdaptiveSupersampling: " << this->AdaptiveSupersampling << "\n";
  os << indent << "AdaptiveThreshold: " << this->AdaptiveThreshold << "\n";
  os << indent << "Progressive: " << this->Progressive << "\n";
  os << indent << "NumberOfThreads: " << this->NumberOfThreads << "\n";
  os << indent << "Seed: " << this->Seed << "\n";
  os << indent << "MaterialMaps: " << this->Impl->Maps.size() << "\n";
  os << indent << "PrimaryRays: " << this->PrimaryRays << "\n";
  os << indent << "ShadowRays: " << this->ShadowRays << "\n";
  os << indent << "SecondaryRays: " << this->SecondaryRays << "\n";
  os << indent << "SupersampledPixels: " << this->SupersampledPixels << "\n";
}
