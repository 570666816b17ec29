// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldObjectShadows.h"

#include "vtkLightFieldScreenImage.h"

#include "vtkObject.h"

#include "LightField.h"
#include "ParallelFor.h"
#include "WalkthroughTracer.h"

#include <algorithm>

namespace vlf = mesolight::vlf;

//------------------------------------------------------------------------------
vtkLightFieldObjectShadows::vtkLightFieldObjectShadows(vtkObject* owner)
  : Owner(owner)
{
}

//------------------------------------------------------------------------------
vtkLightFieldObjectShadows::~vtkLightFieldObjectShadows() = default;

//------------------------------------------------------------------------------
template <typename T>
void vtkLightFieldObjectShadows::Change(T& setting, T value)
{
  if (setting != value)
  {
    setting = value;
    this->Dirty = true;
    this->Owner->Modified();
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::SetMode(int mode)
{
  this->Change(this->Settings.Mode, static_cast<vlf::ShadowMode>(std::min(std::max(mode, 0), 5)));
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::SetResolution(int texels)
{
  this->Change(this->Settings.Resolution, std::min(std::max(texels, 16), 4096));
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::SetEmitterCount(int count)
{
  this->Change(this->Settings.MaximumEmitters, std::min(std::max(count, 1), 8));
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::SetAreaSamples(int perSide)
{
  this->Change(this->Settings.AreaSamples, std::min(std::max(perSide, 1), 4));
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::SetPCFKernel(int texels)
{
  const int k = std::min(std::max(texels, 1), 9);
  this->Change(this->Settings.PcfKernel, k % 2 == 0 ? k + 1 : k);
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::SetBackProjectionRemoval(bool remove)
{
  this->Change(this->Settings.RemoveBackProjection, remove);
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::SetCaster(const vlf::ObjectMesh& unitMesh)
{
  this->Caster.reset(new vlf::ObjectMesh(unitMesh));
  this->Dirty = true;
  this->Owner->Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::ClearCaster()
{
  this->Caster.reset();
  this->Dirty = true;
  this->Owner->Modified();
}

//------------------------------------------------------------------------------
const vlf::ObjectShadows* vtkLightFieldObjectShadows::GetMaps() const
{
  return this->Shadows.Empty() ? nullptr : &this->Shadows;
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::Prepare(const vlf::LightField* field,
  vlf::WalkthroughTracer* tracer, const std::function<void()>& stopReaders)
{
  // A new field makes a new tracer: hand it the maps again.
  const vlf::ObjectShadows* shown = this->GetMaps();
  if (!this->Dirty && this->BuiltFor == field)
  {
    if (tracer && tracer->Shadows() != shown)
    {
      stopReaders();
      tracer->SetShadows(shown);
    }
    return;
  }
  stopReaders(); // the worker's reflections may be reading the maps rebuilt here
  if (tracer)
  {
    tracer->SetShadows(nullptr);
  }
  this->Dirty = false;
  this->BuiltFor = field;
  this->Shadows.Clear();
  this->Gpu = vlf::ShadowGpuData();
  const std::string before = this->Problem;
  this->Problem.clear();
  if (field && this->Caster && this->Settings.Mode != vlf::ShadowMode::None)
  {
    this->Problem = this->Shadows.Build(*field, *this->Caster, this->Settings);
    this->Gpu = vlf::PackShadowsForGpu(this->Shadows);
    if (!this->Problem.empty() && this->Problem != before)
    {
      vtkWarningWithObjectMacro(
        this->Owner, << "the movable object casts no shadow: " << this->Problem);
    }
  }
  ++this->Version;
  if (tracer && !this->Shadows.Empty())
  {
    tracer->SetShadows(&this->Shadows);
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldObjectShadows::ApplyToScreen(const vlf::LightField& field,
  const vlf::WalkthroughTracer& tracer, const vlf::ViewFrame& view,
  vtkLightFieldScreenImage& screen) const
{
  const vlf::PixelRect rect = screen.GetRect();
  if (!this->Active() || rect.Empty() || screen.GetPixels().size() != rect.Pixels() * 4)
  {
    return;
  }
  const vlf::ObjectShadows& shadows = this->Shadows;
  float* pixels = screen.GetPixels().data();
  mesolight::ParallelFor(static_cast<std::size_t>(rect.Y0), static_cast<std::size_t>(rect.Y1), 4,
    [&](std::size_t r0, std::size_t r1)
    {
      for (int row = static_cast<int>(r0); row < static_cast<int>(r1); ++row)
      {
        for (int column = rect.X0; column < rect.X1; ++column)
        {
          const mesolight::SceneRay ray =
            view.Ray(static_cast<float>(column) + 0.5f, static_cast<float>(row) + 0.5f);
          const mesolight::SceneHit hit = tracer.Embree().Intersect(ray);
          std::uint32_t s;
          if (tracer.Classify(ray, hit, s) != vlf::PixelClass::Diffuse)
          {
            continue;
          }
          float* rgba = pixels +
            (static_cast<std::size_t>(row - rect.Y0) * rect.Width() + (column - rect.X0)) * 4;
          const glm::vec3 shaded =
            shadows.Shade(glm::vec3(rgba[0], rgba[1], rgba[2]), ray.Origin + hit.T * ray.Direction,
              field.Surfaces()[s].Normal, field.MaterialOf(s).Diffuse);
          rgba[0] = shaded.x;
          rgba[1] = shaded.y;
          rgba[2] = shaded.z;
        }
      }
    });
}
