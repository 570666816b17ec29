// SPDX-License-Identifier: BSD-3-Clause
// vtkLightFieldActor, shadows of the movable object on the static scene (Wither 2005,
// "Interactive dynamic objects in a virtual light field", chapter 4): the maps of
// core/ObjectShadows.h rebuilt when the object or the field changed, and the raytrace mode's
// CPU darkening (the GPU's is in glsl/vtkLightFieldShadowFS.glsl).
#include "vtkLightFieldActor.h"

#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldActorShadows.h"

#include "ParallelFor.h"

#include <chrono>

namespace vlf = mesolight::vlf;

//------------------------------------------------------------------------------
// Shadows of the movable object (vtkLightFieldActorShadows.h, core/ObjectShadows.h).
//------------------------------------------------------------------------------
vtkLightFieldActor::ShadowState& vtkLightFieldActor::Shadows()
{
  if (!this->ShadowData)
  {
    this->ShadowData.reset(new ShadowState);
  }
  return *this->ShadowData;
}

vtkLightFieldActor::ShadowState* vtkLightFieldActor::GetShadowState()
{
  return &this->Shadows();
}

namespace
{
template <typename T>
void SetShadowSetting(
  vtkLightFieldActor* self, vtkLightFieldActor::ShadowState& state, T& setting, T value)
{
  if (setting != value)
  {
    setting = value;
    state.Dirty = true;
    self->Modified();
  }
}
} // namespace

void vtkLightFieldActor::SetShadowMode(int mode)
{
  SetShadowSetting(this, this->Shadows(), this->Shadows().Settings.Mode,
    static_cast<vlf::ShadowMode>(std::min(std::max(mode, 0), 5)));
}

int vtkLightFieldActor::GetShadowMode() const
{
  return this->ShadowData ? static_cast<int>(this->ShadowData->Settings.Mode) : ShadowField;
}

const char* vtkLightFieldActor::GetShadowModeAsString(int mode)
{
  return vlf::ShadowModeName(static_cast<vlf::ShadowMode>(mode));
}

int vtkLightFieldActor::GetShadowModeFromString(const std::string& name)
{
  vlf::ShadowMode mode;
  return vlf::ShadowModeFromName(name, mode) ? static_cast<int>(mode) : -1;
}

void vtkLightFieldActor::SetShadowMapResolution(int texels)
{
  SetShadowSetting(this, this->Shadows(), this->Shadows().Settings.Resolution,
    std::min(std::max(texels, 16), 4096));
}

int vtkLightFieldActor::GetShadowMapResolution() const
{
  return this->ShadowData ? this->ShadowData->Settings.Resolution
                          : vlf::ShadowSettings().Resolution;
}

void vtkLightFieldActor::SetShadowEmitterCount(int count)
{
  SetShadowSetting(this, this->Shadows(), this->Shadows().Settings.MaximumEmitters,
    std::min(std::max(count, 1), 8));
}

int vtkLightFieldActor::GetShadowEmitterCount() const
{
  return this->ShadowData ? this->ShadowData->Settings.MaximumEmitters
                          : vlf::ShadowSettings().MaximumEmitters;
}

void vtkLightFieldActor::SetShadowAreaSamples(int perSide)
{
  SetShadowSetting(
    this, this->Shadows(), this->Shadows().Settings.AreaSamples, std::min(std::max(perSide, 1), 4));
}

int vtkLightFieldActor::GetShadowAreaSamples() const
{
  return this->ShadowData ? this->ShadowData->Settings.AreaSamples
                          : vlf::ShadowSettings().AreaSamples;
}

void vtkLightFieldActor::SetShadowPCFKernel(int texels)
{
  const int k = std::min(std::max(texels, 1), 9);
  SetShadowSetting(
    this, this->Shadows(), this->Shadows().Settings.PcfKernel, k % 2 == 0 ? k + 1 : k);
}

int vtkLightFieldActor::GetShadowPCFKernel() const
{
  return this->ShadowData ? this->ShadowData->Settings.PcfKernel : vlf::ShadowSettings().PcfKernel;
}

void vtkLightFieldActor::SetShadowBackProjectionRemoval(bool remove)
{
  SetShadowSetting(this, this->Shadows(), this->Shadows().Settings.RemoveBackProjection, remove);
}

bool vtkLightFieldActor::GetShadowBackProjectionRemoval() const
{
  return !this->ShadowData || this->ShadowData->Settings.RemoveBackProjection;
}

void vtkLightFieldActor::SetShadowCasterForTesting(const mesolight::vlf::ObjectMesh* unitMesh)
{
  if (unitMesh)
  {
    this->UpdateObjectShadows(*unitMesh);
  }
  else
  {
    this->ClearObjectShadows();
  }
}

void vtkLightFieldActor::UpdateObjectShadows(const mesolight::vlf::ObjectMesh& unitMesh)
{
  ShadowState& state = this->Shadows();
  state.Caster.reset(new vlf::ObjectMesh(unitMesh));
  state.Dirty = true;
  this->Modified();
}

void vtkLightFieldActor::ClearObjectShadows()
{
  ShadowState& state = this->Shadows();
  state.Caster.reset();
  state.Dirty = true;
  this->Modified();
}

const mesolight::vlf::ObjectShadows* vtkLightFieldActor::GetObjectShadows() const
{
  return this->ShadowData && !this->ShadowData->Shadows.Empty() ? &this->ShadowData->Shadows
                                                                : nullptr;
}

std::string vtkLightFieldActor::GetShadowProblem() const
{
  return this->ShadowData ? this->ShadowData->Problem : std::string();
}

double vtkLightFieldActor::GetLastShadowSeconds() const
{
  return this->ShadowData ? this->ShadowData->Shadows.FillSeconds() : 0.0;
}

void vtkLightFieldActor::PrepareShadows()
{
  ShadowState& state = this->Shadows();
  Internals& impl = *this->Impl;
  const vlf::LightField* field = impl.Field;
  // The tracer darkens the diffuse points its mirrors show by the same maps (a new field makes
  // a new tracer: hand them over again).
  const vlf::ObjectShadows* shown = state.Shadows.Empty() ? nullptr : &state.Shadows;
  if (!state.Dirty && state.BuiltFor == field)
  {
    if (impl.Tracer && impl.Tracer->Shadows() != shown)
    {
      impl.StopWorker();
      impl.Tracer->SetShadows(shown);
    }
    return;
  }
  impl.StopWorker(); // the worker's reflections may be reading the maps rebuilt here
  if (impl.Tracer)
  {
    impl.Tracer->SetShadows(nullptr);
  }
  state.Dirty = false;
  state.BuiltFor = field;
  state.Shadows.Clear();
  state.Gpu = vlf::ShadowGpuData();
  const std::string before = state.Problem;
  state.Problem.clear();
  if (field && state.Caster && state.Settings.Mode != vlf::ShadowMode::None)
  {
    state.Problem = state.Shadows.Build(*field, *state.Caster, state.Settings);
    state.Gpu = vlf::PackShadowsForGpu(state.Shadows);
    if (!state.Problem.empty() && state.Problem != before)
    {
      vtkWarningMacro(<< "the movable object casts no shadow: " << state.Problem);
    }
  }
  ++state.Version;
  if (impl.Tracer && !state.Shadows.Empty())
  {
    impl.Tracer->SetShadows(&state.Shadows);
  }
}

std::uint64_t vtkLightFieldActor::TraceKey() const
{
  // Traced reflections of other options, of another placement of the object or of other
  // shadows (the mirrors show them) are not reused.
  const std::uint64_t shadows = this->ShadowData ? this->ShadowData->Version : 0;
  return (shadows << 40) + (static_cast<std::uint64_t>(this->GetObjectVersion()) << 16) +
    static_cast<std::uint64_t>(
      this->MaximumReflectionDepth * 16 + this->ReflectionBouncesShortForTesting);
}

void vtkLightFieldActor::ApplyShadowsToScreen()
{
  Internals& impl = *this->Impl;
  ShadowState& state = this->Shadows();
  if (!state.Active() || !impl.Tracer || !impl.Field || impl.Rect.Empty() || !impl.HaveLastView ||
    impl.Screen.size() != impl.Rect.Pixels() * 4)
  {
    return;
  }
  // Raytrace mode's CPU pixels: the same darkening as the GPU's on the diffuse surfaces.
  const vlf::ViewFrame view = impl.LastView;
  const vlf::PixelRect rect = impl.Rect;
  const vlf::LightField& field = *impl.Field;
  const vlf::WalkthroughTracer& tracer = *impl.Tracer;
  const vlf::ObjectShadows& shadows = state.Shadows;
  float* screen = impl.Screen.data();
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
          float* rgba = screen +
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
