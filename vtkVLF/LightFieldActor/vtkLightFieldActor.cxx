// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldActor.h"

#include "vtkLightFieldActorInternals.h"
#include "vtkLightFieldActorShadows.h"
#include "vtkLightFieldMapper.h"

#include "PatchComparison.h" // ToWorld / ToUnit
#include "Snapshot.h"

#include "vtkActor.h"
#include "vtkAlgorithm.h"
#include "vtkCamera.h"
#include "vtkCellArray.h"
#include "vtkDataArray.h"
#include "vtkDataObject.h"
#include "vtkFloatArray.h"
#include "vtkMapper.h"
#include "vtkMath.h"
#include "vtkMatrix4x4.h"
#include "vtkObjectFactory.h"
#include "vtkPointData.h"
#include "vtkPoints.h"
#include "vtkProperty.h"
#include "vtkRenderer.h"
#include "vtkTriangleFilter.h"
#include "vtkUnsignedCharArray.h"
#include "vtkVirtualLightField.h"

#include "ParallelFor.h"

#include <glm/geometric.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>

namespace vlf = mesolight::vlf;

vtkStandardNewMacro(vtkLightFieldActor);

namespace
{
using Clock = std::chrono::steady_clock;

// The field's scene in world coordinates, three points per triangle (each carries its own
// surface's atlas coordinates), face normals, Kd colours for the geometry mode.
vtkSmartPointer<vtkPolyData> MakeScene(const vlf::LightField& field, const vlf::TextureAtlas& atlas)
{
  const mesolight::TriangleScene& scene = field.Scene();
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  vtkNew<vtkFloatArray> tcoords;
  tcoords->SetName(vtkLightFieldMapper::GetAtlasCoordinatesName());
  tcoords->SetNumberOfComponents(2);
  vtkNew<vtkFloatArray> normals;
  normals->SetName("Normals");
  normals->SetNumberOfComponents(3);
  vtkNew<vtkUnsignedCharArray> colours;
  colours->SetName("GeometryColour");
  colours->SetNumberOfComponents(3);
  // Shadows of the movable object: each receiver's unit-sphere point, normal and Kd
  // (vtkLightFieldShadowFS.glsl).
  vtkNew<vtkFloatArray> shadowPoints;
  shadowPoints->SetName("mlShadowPoint");
  shadowPoints->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> shadowNormals;
  shadowNormals->SetName("mlShadowNormal");
  shadowNormals->SetNumberOfComponents(3);
  vtkNew<vtkFloatArray> shadowKd;
  shadowKd->SetName("mlShadowKd");
  shadowKd->SetNumberOfComponents(3);
  vtkNew<vtkCellArray> polys;
  for (std::size_t t = 0; t < scene.TriangleCount(); ++t)
  {
    const std::uint32_t s = field.SurfaceOfTriangle(t);
    if (s == vlf::NoSurface)
    {
      continue;
    }
    const mesolight::SceneMaterial& m = field.MaterialOf(s);
    glm::vec3 colour = m.Diffuse;
    if (std::max(m.Emission.x, std::max(m.Emission.y, m.Emission.z)) > 0.0f)
    {
      colour = glm::vec3(1.0f);
    }
    else if (std::max(m.Specular.x, std::max(m.Specular.y, m.Specular.z)) > 0.0f)
    {
      colour = glm::vec3(0.55f, 0.65f, 0.8f); // mirrors: a light steel blue in geometry mode
    }
    const glm::vec3 n = field.Surfaces()[s].Normal;
    vtkIdType ids[3];
    for (int corner = 0; corner < 3; ++corner)
    {
      const glm::vec3 unit = scene.Vertex(t, corner);
      const glm::vec3 world = vlf::ToWorld(field, unit);
      ids[corner] = points->InsertNextPoint(world.x, world.y, world.z);
      const glm::vec2 tc = atlas.TextureCoordinates(s, unit);
      tcoords->InsertNextTuple2(tc.x, tc.y);
      normals->InsertNextTuple3(n.x, n.y, n.z);
      shadowPoints->InsertNextTuple3(unit.x, unit.y, unit.z);
      shadowNormals->InsertNextTuple3(n.x, n.y, n.z);
      shadowKd->InsertNextTuple3(m.Diffuse.x, m.Diffuse.y, m.Diffuse.z);
      colours->InsertNextTuple3(std::lround(255.0f * std::min(1.0f, colour.x)),
        std::lround(255.0f * std::min(1.0f, colour.y)),
        std::lround(255.0f * std::min(1.0f, colour.z)));
    }
    polys->InsertNextCell(3, ids);
  }
  vtkSmartPointer<vtkPolyData> poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  poly->GetPointData()->SetNormals(normals);
  poly->GetPointData()->SetScalars(colours);
  poly->GetPointData()->AddArray(tcoords);
  poly->GetPointData()->AddArray(shadowPoints);
  poly->GetPointData()->AddArray(shadowNormals);
  poly->GetPointData()->AddArray(shadowKd);
  return poly;
}
} // namespace

namespace
{
// Latest modification of an algorithm, its input data and everything upstream: what decides
// whether an Update() executes.
vtkMTimeType UpstreamModifiedTime(vtkAlgorithm* algorithm)
{
  vtkMTimeType time = algorithm->GetMTime();
  for (int port = 0; port < algorithm->GetNumberOfInputPorts(); ++port)
  {
    for (int c = 0; c < algorithm->GetNumberOfInputConnections(port); ++c)
    {
      if (vtkAlgorithm* producer = algorithm->GetInputAlgorithm(port, c))
      {
        time = std::max(time, UpstreamModifiedTime(producer));
      }
      if (vtkDataObject* data = algorithm->GetInputDataObject(port, c))
      {
        time = std::max(time, data->GetMTime());
      }
    }
  }
  return time;
}
} // namespace

//------------------------------------------------------------------------------
vtkLightFieldActor::vtkLightFieldActor()
  : Impl(new Internals)
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
  this->Impl->StopWorker();
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
void vtkLightFieldActor::SetLightField(const mesolight::vlf::LightField* field)
{
  this->Filter = nullptr;
  this->Impl->StopWorker();
  this->Impl->Owned.reset();
  this->UseField(field);
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::SetLightFieldFilter(vtkVirtualLightField* filter)
{
  if (this->Filter == filter)
  {
    return;
  }
  this->Impl->StopWorker();
  this->Impl->Owned.reset();
  this->Filter = filter;
  this->FilterUpstreamTime = 0;
  this->FilterOutputTime = 0;
  this->UseField(filter ? filter->GetLightField() : nullptr);
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::LoadLightField(const std::string& fileName)
{
  this->Filter = nullptr;
  this->Impl->StopWorker();
  std::unique_ptr<vlf::LightField> field;
  try
  {
    field = vlf::ReadSnapshot(fileName);
  }
  catch (const std::exception& e)
  {
    this->LastError = std::string("cannot use light field '") + fileName + "': " + e.what();
    vtkErrorMacro(<< this->LastError);
    return false;
  }
  this->Impl->Owned = std::move(field);
  return this->UseField(this->Impl->Owned.get());
}

//------------------------------------------------------------------------------
const mesolight::vlf::LightField* vtkLightFieldActor::GetLightField() const
{
  return this->Impl->Field;
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::HasMirrors() const
{
  return this->Impl->Tracer && this->Impl->Tracer->HasMirrors();
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::UseField(const mesolight::vlf::LightField* field)
{
  Internals& impl = *this->Impl;
  impl.StopWorker();
  impl.Field = nullptr;
  impl.Tracer.reset();
  impl.Atlas.reset();
  impl.Scene = nullptr;
  impl.SharpReady = false;
  impl.HaveLastView = false;
  impl.WarnedNoMirrors = false;
  impl.ForgetObjectState(); // the new tracer has no object yet
  impl.Volume.reset();      // it was the old field's
  impl.VolumeField = nullptr;
  this->LastError.clear();
  if (field)
  {
    try
    {
      impl.Tracer.reset(new vlf::WalkthroughTracer(*field));
      impl.Atlas.reset(new vlf::TextureAtlas(*field));
      impl.Scene = MakeScene(*field, *impl.Atlas);
      impl.Field = field;
    }
    catch (const std::exception& e)
    {
      impl.Tracer.reset();
      impl.Atlas.reset();
      impl.Scene = nullptr;
      this->LastError = std::string("cannot show the light field: ") + e.what();
      vtkErrorMacro(<< this->LastError);
    }
  }
  ++impl.AtlasVersion;
  if (this->ShadowData)
  {
    this->ShadowData->Dirty = true; // the maps belong to the field's emitters and unit sphere
  }
  vtkLightFieldMapper* mapper = vtkLightFieldMapper::SafeDownCast(this->Mapper);
  if (mapper)
  {
    if (impl.Scene)
    {
      mapper->SetInputData(impl.Scene);
    }
    else
    {
      vtkNew<vtkPolyData> empty;
      mapper->SetInputData(empty);
    }
  }
  this->Modified();
  return impl.Field != nullptr;
}

//------------------------------------------------------------------------------
mesolight::vlf::TraceOptions vtkLightFieldActor::CurrentTraceOptions() const
{
  vlf::TraceOptions options;
  options.MaximumDepth = this->MaximumReflectionDepth;
  options.BouncesShortForTesting = this->ReflectionBouncesShortForTesting;
  return options;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::TraceAtRest()
{
  Internals& impl = *this->Impl;
  if (!impl.Tracer || !impl.HaveLastView || this->RenderMode != Progressive)
  {
    return;
  }
  const vlf::ViewFrame view = impl.LastView;
  {
    std::lock_guard<std::mutex> lock(impl.Mutex);
    if ((impl.WorkerRunning && impl.WorkerView == view && impl.WorkerKey == this->TraceKey()) ||
      (impl.SharpReady && impl.SharpView == view && impl.SharpKey == this->TraceKey()))
    {
      return;
    }
  }
  const vlf::PixelRect rect = impl.Tracer->MirrorRect(view);
  if (rect.Empty())
  {
    std::lock_guard<std::mutex> lock(impl.Mutex);
    impl.Sharp.clear();
    impl.SharpRect = rect;
    impl.SharpView = view;
    impl.SharpKey = this->TraceKey();
    impl.SharpReady = true;
    return;
  }
  impl.StopWorker();
  const unsigned generation = impl.Generation.load();
  {
    std::lock_guard<std::mutex> lock(impl.Mutex);
    impl.WorkerRunning = true;
    impl.WorkerView = view;
    impl.WorkerKey = this->TraceKey();
  }
  const vlf::TraceOptions options = this->CurrentTraceOptions();
  const std::uint64_t key = this->TraceKey();
  const vlf::WalkthroughTracer* tracer = impl.Tracer.get();
  Internals* self = &impl;
  // One worker thread, row by row (Wither 2005 §2.4.2.2.3: the high-quality rendering
  // progresses in another thread), abandoned between rows when the view changes.
  impl.Worker = std::thread(
    [self, tracer, view, rect, options, generation, key]()
    {
      std::vector<float> image(rect.Pixels() * 4, 0.0f);
      bool cancelled = false;
      for (int row = rect.Y0; row < rect.Y1; ++row)
      {
        if (self->Generation.load() != generation)
        {
          cancelled = true;
          break;
        }
        tracer->ShadeRows(
          view, rect, false, vlf::SpecularQuality::Traced, options, row, row + 1, image.data());
      }
      if (!cancelled)
      {
        vlf::WalkthroughTracer::DilateEdges(rect, image.data());
      }
      {
        std::lock_guard<std::mutex> lock(self->Mutex);
        if (!cancelled)
        {
          self->Sharp = std::move(image);
          self->SharpRect = rect;
          self->SharpView = view;
          self->SharpKey = key;
          self->SharpReady = true;
        }
        self->WorkerRunning = false;
      }
      self->Done.notify_all();
    });
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::RefreshField()
{
  if (!this->Filter)
  {
    return;
  }
  // A filter that will execute again frees the field the progressive worker may be reading:
  // stop the worker first (only then, so a settled pipeline never cancels a trace).
  const vtkMTimeType upstream = UpstreamModifiedTime(this->Filter);
  if (upstream > this->FilterUpstreamTime)
  {
    this->Impl->StopWorker();
  }
  this->Filter->Update();
  this->FilterUpstreamTime = upstream;
  // A new field may sit at the old one's address: its output's time says it was rebuilt.
  const vtkMTimeType output =
    this->Filter->GetOutputDataObject(0) ? this->Filter->GetOutputDataObject(0)->GetMTime() : 0;
  if (this->Filter->GetLightField() != this->Impl->Field || output != this->FilterOutputTime)
  {
    this->FilterOutputTime = output;
    this->UseField(this->Filter->GetLightField());
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
bool vtkLightFieldActor::WaitForTracedReflections(double seconds)
{
  Internals& impl = *this->Impl;
  if (this->RenderMode != Progressive)
  {
    return true;
  }
  if (!impl.HaveLastView || !impl.Tracer)
  {
    return true; // no view (no field, zero-size viewport): nothing to trace
  }
  // The caller waits: the camera rests, so trace the last view if nothing is doing so.
  this->TraceAtRest();
  std::unique_lock<std::mutex> lock(impl.Mutex);
  impl.Done.wait_for(
    lock, std::chrono::duration<double>(seconds), [&] { return !impl.WorkerRunning; });
  return impl.HaveLastView && impl.SharpReady && impl.SharpView == impl.LastView &&
    impl.SharpKey == this->TraceKey();
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::GetLastScreenRect(int rect[4]) const
{
  rect[0] = this->Impl->Rect.X0;
  rect[1] = this->Impl->Rect.Y0;
  rect[2] = this->Impl->Rect.X1;
  rect[3] = this->Impl->Rect.Y1;
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::PrepareFrame(vtkRenderer* renderer)
{
  Internals& impl = *this->Impl;
  impl.ScreenValid = false;
  impl.AllScreen = false;
  impl.Rect = vlf::PixelRect{};
  this->LastSpecularSeconds = 0.0;
  this->LastScreenPixels = 0;
  this->LastFrameConverged = false;
  this->RefreshField();
  if (!impl.Field || !impl.Tracer)
  {
    return false;
  }
  // The movable object first: the screen pass below traces it where it stands now. A moved
  // object is a change like a moved camera (progressive: blurry now, sharp once at rest).
  this->UpdateMovableObject();
  const bool objectMoved = impl.ObjectVersion != impl.ObjectVersionAtLastFrame;
  impl.ObjectVersionAtLastFrame = impl.ObjectVersion;
  if (this->RenderMode == Geometry)
  {
    return true;
  }
  this->PrepareShadows(); // the movable object's shadow maps, if it moved or settings changed
  int width = 0, height = 0, x0 = 0, y0 = 0;
  renderer->GetTiledSizeAndOrigin(&width, &height, &x0, &y0);
  vtkCamera* camera = renderer->GetActiveCamera();
  if (width < 1 || height < 1 || !camera)
  {
    impl.HaveLastView = false;
    return true; // a zero-size viewport: nothing to compute, nothing drawn from the screen
  }
  if (camera->GetParallelProjection())
  {
    if (!impl.WarnedParallel)
    {
      vtkWarningMacro(
        << "the light field walkthrough needs a perspective camera; mirrors and "
           "raytrace pixels show only the diffuse textures under parallel projection");
      impl.WarnedParallel = true;
    }
    impl.HaveLastView = false;
    return true;
  }
  double position[3], focal[3], up[3];
  camera->GetPosition(position);
  camera->GetFocalPoint(focal);
  camera->GetViewUp(up);
  double angle = camera->GetViewAngle();
  if (camera->GetUseHorizontalViewAngle())
  {
    const double half =
      std::atan(std::tan(0.5 * vtkMath::RadiansFromDegrees(angle)) * height / width);
    angle = 2.0 * vtkMath::DegreesFromRadians(half);
  }
  const vlf::LightField& field = *impl.Field;
  vlf::ViewFrame view;
  if (!vlf::ViewFrame::Make(vlf::ToUnit(field, glm::vec3(position[0], position[1], position[2])),
        vlf::ToUnit(field, glm::vec3(focal[0], focal[1], focal[2])), glm::vec3(up[0], up[1], up[2]),
        static_cast<float>(angle), width, height, view))
  {
    vtkWarningMacro(<< "the camera does not define a view (position on the focal point or view up "
                       "along the view direction): nothing traced");
    impl.HaveLastView = false;
    return true;
  }
  if (!impl.HaveLastView || view != impl.LastView)
  {
    // A new view: say once if the eye sits behind surfaces (inside a wall or a block), where
    // the one-sided field shows black.
    int back = 0;
    for (int q = 0; q < 9; ++q)
    {
      const mesolight::SceneRay ray = view.Ray((0.5f + static_cast<float>(q % 3)) * width / 3.0f,
        (0.5f + static_cast<float>(q / 3)) * height / 3.0f);
      std::uint32_t s;
      if (impl.Tracer->Classify(ray, impl.Tracer->Embree().Intersect(ray), s) ==
        vlf::PixelClass::BackFace)
      {
        ++back;
      }
    }
    // Once per stay behind the surfaces, not once per frame of a moving camera.
    const bool warn = back >= 5 && !impl.WarnedInsideWall;
    impl.WarnedInsideWall = back >= 5;
    if (warn)
    {
      vtkWarningMacro(
        << "the camera sees the back of the light field's surfaces (is it inside a wall?): "
           "the field is one-sided, so they show black");
    }
  }
  const bool newView = !impl.HaveLastView || view != impl.LastView;
  impl.LastView = view;
  impl.HaveLastView = true;

  const vlf::TraceOptions options = this->CurrentTraceOptions();
  const vlf::WalkthroughTracer& tracer = *impl.Tracer;
  const Clock::time_point start = Clock::now();
  std::atomic<std::size_t> valued{ 0 };
  // One parallel pass over 4 x 4 pixel tiles: primary rays in 16-ray packets.
  auto shadeTiles = [&](const vlf::PixelRect& rect, bool all, vlf::SpecularQuality quality)
  {
    impl.Screen.assign(rect.Pixels() * 4, 0.0f);
    float* out = impl.Screen.data();
    mesolight::ParallelFor(0, vlf::WalkthroughTracer::TileCount(rect), 16,
      [&](std::size_t t0, std::size_t t1)
      { valued += tracer.ShadeTiles(view, rect, all, quality, options, t0, t1, out); });
  };

  if (this->RenderMode == Raytrace)
  {
    impl.Rect = vlf::PixelRect{ 0, 0, width, height };
    shadeTiles(impl.Rect, true, vlf::SpecularQuality::Raytrace);
    this->ApplyShadowsToScreen();
    impl.AllScreen = true;
    this->LastFrameConverged = true;
  }
  else
  {
    if (!tracer.HasMirrors() && !impl.WarnedNoMirrors)
    {
      vtkWarningMacro(<< "the light field has no mirror surfaces: the "
                      << GetRenderModeAsString(this->RenderMode)
                      << " mode shows only its diffuse textures");
      impl.WarnedNoMirrors = true;
    }
    impl.Rect = tracer.MirrorRect(view);
    if (this->RenderMode == Coherent)
    {
      shadeTiles(impl.Rect, false, vlf::SpecularQuality::Traced);
      vlf::WalkthroughTracer::DilateEdges(impl.Rect, impl.Screen.data());
      this->LastFrameConverged = true;
    }
    else
    {
      bool sharp = false;
      {
        std::lock_guard<std::mutex> lock(impl.Mutex);
        sharp = impl.SharpReady && impl.SharpView == view && impl.SharpKey == this->TraceKey();
        if (sharp)
        {
          impl.Screen = impl.Sharp;
          impl.Rect = impl.SharpRect;
        }
      }
      if (sharp)
      {
        this->LastFrameConverged = true;
        for (std::size_t i = 0; i < impl.Rect.Pixels(); ++i)
        {
          valued += impl.Screen[4 * i + 3] >= 1.0f ? 1 : 0;
        }
      }
      else
      {
        // Moving: the blurry field lookup now. A new view cancels the worker's trace of the
        // previous one; the view is traced once it rests (the same view rendered again, or
        // WaitForTracedReflections).
        if (newView || objectMoved)
        {
          ++impl.Generation;
        }
        shadeTiles(impl.Rect, false, vlf::SpecularQuality::Moving);
        vlf::WalkthroughTracer::DilateEdges(impl.Rect, impl.Screen.data());
        if (!newView && !objectMoved)
        {
          this->TraceAtRest();
        }
      }
    }
  }
  this->LastScreenPixels = static_cast<vtkIdType>(valued.load());
  this->LastSpecularSeconds = SecondsSince(start);
  impl.Origin[0] = x0 + impl.Rect.X0;
  impl.Origin[1] = y0 + impl.Rect.Y0;
  impl.ScreenValid = true;
  return true;
}

//------------------------------------------------------------------------------
void vtkLightFieldActor::PrintSelf(ostream& os, vtkIndent indent)
{
  this->Superclass::PrintSelf(os, indent);
  os << indent << "RenderMode: " << GetRenderModeAsString(this->RenderMode) << "\n";
  os << indent << "Exposure: " << this->Exposure << "\n";
  os << indent << "ToneMap: " << (this->ToneMap == Reinhard ? "Reinhard" : "Clamp") << "\n";
  os << indent << "MaximumReflectionDepth: " << this->MaximumReflectionDepth << "\n";
  os << indent << "LightField: " << (this->Impl->Field ? "set" : "(none)") << "\n";
  os << indent << "HasMirrors: " << (this->HasMirrors() ? "yes" : "no") << "\n";
  os << indent << "LastSpecularSeconds: " << this->LastSpecularSeconds << "\n";
  os << indent << "LastScreenPixels: " << this->LastScreenPixels << "\n";
  os << indent << "FlipAtlasForTesting: " << this->FlipAtlasForTesting << "\n";
  os << indent << "OverwriteCompositeForTesting: " << this->OverwriteCompositeForTesting << "\n";
  os << indent << "ReflectionBouncesShortForTesting: " << this->ReflectionBouncesShortForTesting
     << "\n";
  os << indent << "MovableObject: " << static_cast<void*>(this->Impl->Object.GetPointer()) << "\n";
  os << indent << "ObjectSubdivision: " << this->ObjectSubdivision << "\n";
  os << indent << "ObjectGatherDirections: " << this->ObjectGatherDirections << "\n";
  os << indent << "ObjectIrradianceVolume: " << this->ObjectIrradianceVolume << "\n";
  os << indent << "IgnoreObjectForTesting: " << this->IgnoreObjectForTesting << "\n";
  os << indent << "ShadowMode: " << GetShadowModeAsString(this->GetShadowMode()) << "\n";
  os << indent << "ShadowMapResolution: " << this->GetShadowMapResolution() << "\n";
  os << indent
     << "ShadowCaster: " << (this->ShadowData && this->ShadowData->Caster ? "set" : "(none)")
     << "\n";
}
