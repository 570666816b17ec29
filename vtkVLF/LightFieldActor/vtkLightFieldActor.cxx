// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldActor.h"

#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldMapper.h"

#include "vtkObjectFactory.h"
#include "vtkPolyData.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkVirtualLightField.h"

#include "LightField.h"
#include "ObjectShadows.h"
#include "WalkthroughTracer.h"

#include <algorithm>
#include <chrono>

namespace vlf = mesolight::vlf;

vtkStandardNewMacro(vtkLightFieldActor);

namespace
{
using Clock = std::chrono::steady_clock;
}

//------------------------------------------------------------------------------
vtkLightFieldActor::vtkLightFieldActor()
  : Impl(new Internals(this))
{
  vtkNew<vtkLightFieldMapper> mapper;
  this->SetMapper(mapper);
  // Geometry mode: walls seen edge-on by the headlight would be black without some ambient.
  this->GetProperty()->SetAmbient(0.35);
  this->GetProperty()->SetDiffuse(0.65);
}

//------------------------------------------------------------------------------
vtkLightFieldActor::~vtkLightFieldActor()
{
  this->Impl->Worker.Stop();
}

//------------------------------------------------------------------------------
const char* vtkLightFieldActor::GetRenderModeAsString(int mode)
{
  switch (mode)
  {
    case Geometry:
      return "geometry";
    case Raytrace:
      return "raytrace";
    case Progressive:
      return "progressive";
    case Coherent:
      return "coherent";
    default:
      return "unknown";
  }
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetRenderModeFromString(const std::string& name)
{
  for (int mode = Geometry; mode <= Coherent; ++mode)
  {
    if (name == GetRenderModeAsString(mode))
    {
      return mode;
    }
  }
  return -1;
}

//------------------------------------------------------------------------------
// The field.
//------------------------------------------------------------------------------
void vtkLightFieldActor::SetLightFieldFilter(vtkVirtualLightField* filter)
{
  Internals& impl = *this->Impl;
  if (impl.Input.GetFilter() == filter)
  {
    return;
  }
  impl.Worker.Stop();
  impl.Input.SetFilter(filter);
  impl.UseField(*this, impl.Input.GetFilterField());
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::LoadLightField(const std::string& fileName)
{
  Internals& impl = *this->Impl;
  impl.Worker.Stop();
  std::string error;
  const vlf::LightField* field = impl.Input.Load(fileName, error);
  if (!field)
  {
    vtkErrorMacro(<< error);
    return false;
  }
  return impl.UseField(*this, field);
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::HasMirrors() const
{
  const vlf::WalkthroughTracer* tracer = this->Impl->Scene.GetTracer();
  return tracer && tracer->HasMirrors();
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::Internals::UseField(
  vtkLightFieldActor& actor, const mesolight::vlf::LightField* field)
{
  this->Worker.Stop();
  this->Worker.Forget();
  this->View.Forget();
  this->WarnedNoMirrors = false;
  this->Object.ForgetField(); // the new tracer has no object yet; the volume was the old field's
  std::string error;
  if (!this->Scene.Build(field, error))
  {
    vtkErrorWithObjectMacro(&actor, << error);
  }
  this->Shadows.Invalidate(); // the maps belong to the field's emitters and unit sphere
  this->ApplyHiddenSurfaces(actor);
  return this->Scene.GetField() != nullptr;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::Internals::ApplyHiddenSurfaces(vtkLightFieldActor& actor)
{
  std::string error;
  if (!this->Scene.SetHiddenSurfaces(this->HiddenSurfaces, error))
  {
    vtkErrorWithObjectMacro(&actor, << error);
  }
  if (vtkLightFieldMapper* mapper = vtkLightFieldMapper::SafeDownCast(actor.GetMapper()))
  {
    if (this->Scene.GetScene())
    {
      mapper->SetInputData(this->Scene.GetScene());
    }
    else
    {
      vtkNew<vtkPolyData> empty;
      mapper->SetInputData(empty);
    }
  }
  actor.Modified();
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::AddHiddenSurface(const std::string& name)
{
  Internals& impl = *this->Impl;
  if (std::find(impl.HiddenSurfaces.begin(), impl.HiddenSurfaces.end(), name) !=
    impl.HiddenSurfaces.end())
  {
    return;
  }
  impl.HiddenSurfaces.push_back(name);
  impl.ApplyHiddenSurfaces(*this);
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::RemoveHiddenSurface(const std::string& name)
{
  Internals& impl = *this->Impl;
  const auto hidden = std::find(impl.HiddenSurfaces.begin(), impl.HiddenSurfaces.end(), name);
  if (hidden == impl.HiddenSurfaces.end())
  {
    return;
  }
  impl.HiddenSurfaces.erase(hidden);
  impl.ApplyHiddenSurfaces(*this);
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::RemoveAllHiddenSurfaces()
{
  Internals& impl = *this->Impl;
  if (impl.HiddenSurfaces.empty())
  {
    return;
  }
  impl.HiddenSurfaces.clear();
  impl.ApplyHiddenSurfaces(*this);
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetNumberOfHiddenSurfaces() const
{
  return static_cast<int>(this->Impl->HiddenSurfaces.size());
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::RefreshField()
{
  Internals& impl = *this->Impl;
  if (impl.Input.Refresh(impl.Scene.GetField(), impl.StopReaders()))
  {
    impl.UseField(*this, impl.Input.GetFilterField());
  }
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::Render(vtkRenderer* ren, vtkMapper* mapper)
{
  // Before the mapper looks at its input: a field that appeared since the last frame brings the
  // scene polydata the mapper draws.
  this->RefreshField();
  this->Superclass::Render(ren, mapper);
}

//------------------------------------------------------------------------------
double* vtkLightFieldActor::GetBounds()
{
  // The renderer culls by bounds before anything draws: a filter's field must be there first.
  this->RefreshField();
  return this->Superclass::GetBounds();
}

//------------------------------------------------------------------------------
// The frame.
//------------------------------------------------------------------------------
bool vtkLightFieldActor::PrepareFrame(vtkRenderer* renderer)
{
  Internals& impl = *this->Impl;
  impl.Screen.Clear();
  this->LastSpecularSeconds = 0.0;
  this->LastScreenPixels = 0;
  this->LastFrameConverged = false;
  this->RefreshField();
  const vlf::LightField* field = impl.Scene.GetField();
  vlf::WalkthroughTracer* tracer = impl.Scene.GetTracer();
  if (!field || !tracer)
  {
    return false;
  }
  // The movable object first: the screen pass below traces it where it stands now. A moved
  // object is a change like a moved camera (progressive: blurry now, sharp once at rest).
  this->UpdateMovableObject();
  const bool objectMoved = impl.Object.ChangedSinceLastFrame();
  if (this->RenderMode == Geometry)
  {
    return true;
  }
  impl.Shadows.Prepare(field, tracer, impl.StopReaders());
  if (!impl.View.Update(renderer, *field, *tracer))
  {
    return true; // no view: nothing computed, nothing drawn from the screen
  }
  const Clock::time_point start = Clock::now();
  const std::size_t valued =
    this->RenderMode == Raytrace ? this->ShadeRaytrace() : this->ShadeMirrors(objectMoved);
  this->LastScreenPixels = static_cast<vtkIdType>(valued);
  this->LastSpecularSeconds = std::chrono::duration<double>(Clock::now() - start).count();
  impl.Screen.Place(
    impl.View.GetOrigin()[0], impl.View.GetOrigin()[1], this->RenderMode == Raytrace);
  return true;
}

//------------------------------------------------------------------------------
std::size_t vtkLightFieldActor::ShadeRaytrace()
{
  Internals& impl = *this->Impl;
  const vlf::WalkthroughTracer& tracer = *impl.Scene.GetTracer();
  const vlf::PixelRect all{ 0, 0, impl.View.GetWidth(), impl.View.GetHeight() };
  vlf::TraceOptions options;
  options.MaximumDepth = this->MaximumReflectionDepth;
  options.BouncesShortForTesting = impl.ReflectionBouncesShort;
  const std::size_t valued = impl.Screen.Shade(
    tracer, impl.View.GetView(), all, true, vlf::SpecularQuality::Raytrace, options);
  impl.Shadows.ApplyToScreen(*impl.Scene.GetField(), tracer, impl.View.GetView(), impl.Screen);
  this->LastFrameConverged = true;
  return valued;
}

//------------------------------------------------------------------------------
std::size_t vtkLightFieldActor::ShadeMirrors(bool objectMoved)
{
  Internals& impl = *this->Impl;
  const vlf::WalkthroughTracer& tracer = *impl.Scene.GetTracer();
  const vlf::ViewFrame& view = impl.View.GetView();
  // Progressive, the default, adapts to the scene: without mirrors its diffuse textures are the
  // whole picture. Only the modes a user picks for mirrors say that they have none to trace.
  if (!tracer.HasMirrors() && !impl.WarnedNoMirrors && this->RenderMode != Progressive)
  {
    vtkWarningMacro(<< "the light field has no mirror surfaces: the "
                    << GetRenderModeAsString(this->RenderMode)
                    << " mode shows only its diffuse textures");
    impl.WarnedNoMirrors = true;
  }
  vlf::TraceOptions options;
  options.MaximumDepth = this->MaximumReflectionDepth;
  options.BouncesShortForTesting = impl.ReflectionBouncesShort;
  const vlf::PixelRect rect = tracer.MirrorRect(view);
  if (this->RenderMode == Coherent)
  {
    // All at once: traced reflections in 16-ray packets on all cores (§2.4.2.2.4).
    const std::size_t valued =
      impl.Screen.Shade(tracer, view, rect, false, vlf::SpecularQuality::Traced, options);
    impl.Screen.Dilate();
    this->LastFrameConverged = true;
    return valued;
  }
  // Progressive: the worker's traced reflections once it has them for this view.
  std::vector<float> sharp;
  vlf::PixelRect sharpRect;
  if (impl.Worker.Take(view, this->TraceKey(), sharp, sharpRect))
  {
    this->LastFrameConverged = true;
    return impl.Screen.Adopt(std::move(sharp), sharpRect);
  }
  // Moving: the blurry field lookup now. A new view cancels the worker's trace of the previous
  // one; the view is traced once it rests (the same view rendered again, or
  // WaitForTracedReflections).
  const bool changed = impl.View.IsNew() || objectMoved;
  if (changed)
  {
    impl.Worker.Cancel();
  }
  const std::size_t valued =
    impl.Screen.Shade(tracer, view, rect, false, vlf::SpecularQuality::Moving, options);
  impl.Screen.Dilate();
  if (!changed)
  {
    this->TraceAtRest();
  }
  return valued;
}

//------------------------------------------------------------------------------
std::uint64_t vtkLightFieldActor::TraceKey() const
{
  // Traced reflections of other options, of another placement of the object or of other
  // shadows (the mirrors show them) are not reused.
  const Internals& impl = *this->Impl;
  return (static_cast<std::uint64_t>(impl.Shadows.GetVersion()) << 40) +
    (static_cast<std::uint64_t>(impl.Object.GetVersion()) << 16) +
    static_cast<std::uint64_t>(this->MaximumReflectionDepth * 16 + impl.ReflectionBouncesShort);
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::TraceAtRest()
{
  Internals& impl = *this->Impl;
  const vlf::WalkthroughTracer* tracer = impl.Scene.GetTracer();
  if (!tracer || !impl.View.HasView() || this->RenderMode != Progressive)
  {
    return;
  }
  vlf::TraceOptions options;
  options.MaximumDepth = this->MaximumReflectionDepth;
  options.BouncesShortForTesting = impl.ReflectionBouncesShort;
  impl.Worker.Trace(*tracer, impl.View.GetView(), options, this->TraceKey());
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::WaitForTracedReflections(double seconds)
{
  Internals& impl = *this->Impl;
  if (this->RenderMode != Progressive)
  {
    return true;
  }
  if (!impl.View.HasView() || !impl.Scene.GetTracer())
  {
    return true; // no view (no field, zero-size viewport): nothing to trace
  }
  // The caller waits: the camera rests, so trace the last view if nothing is doing so.
  this->TraceAtRest();
  return impl.Worker.Wait(seconds, impl.View.GetView(), this->TraceKey());
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::GetLastScreenRect(int rect[4]) const
{
  const vlf::PixelRect& r = this->Impl->Screen.GetRect();
  rect[0] = r.X0;
  rect[1] = r.Y0;
  rect[2] = r.X1;
  rect[3] = r.Y1;
}

//------------------------------------------------------------------------------
// The movable object (vtkLightFieldMovableObject).
//------------------------------------------------------------------------------
int vtkLightFieldActor::GetGatherDirectionsFromString(const std::string& name)
{
  return name == "all"     ? AllDirections
    : name == "half"       ? HalfDirections
    : name == "importance" ? ImportanceDirections
                           : -1;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::SetMovableObject(vtkActor* object)
{
  Internals& impl = *this->Impl;
  if (impl.Object.GetActor() == object)
  {
    return;
  }
  if (object == this)
  {
    vtkErrorMacro(<< "the light field actor cannot be its own movable object");
    return;
  }
  impl.Worker.Stop(); // the worker may be tracing the old object
  if (vlf::WalkthroughTracer* tracer = impl.Scene.GetTracer())
  {
    tracer->ClearObject();
  }
  impl.Object.SetActor(object);
  this->Modified();
}

//------------------------------------------------------------------------------
vtkActor* vtkLightFieldActor::GetMovableObject()
{
  return this->Impl->Object.GetActor();
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::UpdateMovableObject()
{
  Internals& impl = *this->Impl;
  const Clock::time_point start = Clock::now();
  this->RefreshField();
  vtkLightFieldMovableObject::Settings settings;
  settings.Subdivision = this->ObjectSubdivision;
  settings.Directions = this->ObjectGatherDirections;
  settings.IrradianceVolume = this->ObjectIrradianceVolume;
  settings.Ignore = impl.IgnoreObject;
  return impl.Object.Update(impl.Scene.GetField(), impl.Scene.GetTracer(), settings, impl.Shadows,
    impl.StopReaders(), start);
}

//------------------------------------------------------------------------------
unsigned long vtkLightFieldActor::GetObjectVersion() const
{
  return this->Impl->Object.GetVersion();
}

//------------------------------------------------------------------------------
double vtkLightFieldActor::GetLastObjectSeconds() const
{
  return this->Impl->Object.GetLastSeconds();
}

//------------------------------------------------------------------------------
double vtkLightFieldActor::GetLastGatherSeconds() const
{
  return this->Impl->Object.GetLastGatherSeconds();
}

//------------------------------------------------------------------------------
// The object's shadows (vtkLightFieldObjectShadows).
//------------------------------------------------------------------------------
void vtkLightFieldActor::SetShadowMode(int mode)
{
  this->Impl->Shadows.SetMode(mode);
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetShadowMode() const
{
  return static_cast<int>(this->Impl->Shadows.GetSettings().Mode);
}

//------------------------------------------------------------------------------
const char* vtkLightFieldActor::GetShadowModeAsString(int mode)
{
  return vlf::ShadowModeName(static_cast<vlf::ShadowMode>(mode));
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetShadowModeFromString(const std::string& name)
{
  vlf::ShadowMode mode;
  return vlf::ShadowModeFromName(name, mode) ? static_cast<int>(mode) : -1;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::SetShadowMapResolution(int texels)
{
  this->Impl->Shadows.SetResolution(texels);
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetShadowMapResolution() const
{
  return this->Impl->Shadows.GetSettings().Resolution;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::SetShadowEmitterCount(int count)
{
  this->Impl->Shadows.SetEmitterCount(count);
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetShadowEmitterCount() const
{
  return this->Impl->Shadows.GetSettings().MaximumEmitters;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::SetShadowAreaSamples(int perSide)
{
  this->Impl->Shadows.SetAreaSamples(perSide);
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetShadowAreaSamples() const
{
  return this->Impl->Shadows.GetSettings().AreaSamples;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::SetShadowPCFKernel(int texels)
{
  this->Impl->Shadows.SetPCFKernel(texels);
}

//------------------------------------------------------------------------------
int vtkLightFieldActor::GetShadowPCFKernel() const
{
  return this->Impl->Shadows.GetSettings().PcfKernel;
}

//------------------------------------------------------------------------------
std::string vtkLightFieldActor::GetShadowProblem() const
{
  return this->Impl->Shadows.GetProblem();
}

//------------------------------------------------------------------------------
double vtkLightFieldActor::GetLastShadowSeconds() const
{
  return this->Impl->Shadows.GetFillSeconds();
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::PrintSelf(ostream& os, vtkIndent indent)
{
  const Internals& impl = *this->Impl;
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << GetRenderModeAsString(this->RenderMode) << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMap: " << (this->ToneMap == Reinhard ? "Reinhard" : "Clamp") << "\n";
  os << indent << "MaximumReflectionDepth: " << this->MaximumReflectionDepth << "\n";
  os << indent << "LightField: " << (impl.Scene.GetField() ? "set" : "(none)") << "\n";
  os << indent << "HasMirrors: " << (this->HasMirrors() ? "yes" : "no") << "\n";
  os << indent << "LastSpecularSeconds: " << this->LastSpecularSeconds << "\n";
  os << indent << "LastScreenPixels: " << this->LastScreenPixels << "\n";
  os << indent << "MovableObject: " << static_cast<void*>(impl.Object.GetActor()) << "\n";
  os << indent << "ObjectSubdivision: " << this->ObjectSubdivision << "\n";
  os << indent << "ObjectGatherDirections: " << this->ObjectGatherDirections << "\n";
  os << indent << "ObjectIrradianceVolume: " << this->ObjectIrradianceVolume << "\n";
  os << indent << "ShadowMode: " << GetShadowModeAsString(this->GetShadowMode()) << "\n";
  os << indent << "ShadowMapResolution: " << this->GetShadowMapResolution() << "\n";
  os << indent << "ShadowCaster: " << (impl.Shadows.HasCaster() ? "set" : "(none)") << "\n";
}
