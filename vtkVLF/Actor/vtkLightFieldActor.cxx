// SPDX-License-Identifier: BSD-3-Clause
#include "vtkLightFieldActor.h"

#include "vtkLightFieldActorInternals.h"
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
double SecondsSince(Clock::time_point t)
{
  return std::chrono::duration<double>(Clock::now() - t).count();
}

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
// The movable object (Wither 2005, "Interactive dynamic objects in a virtual light field").
//------------------------------------------------------------------------------
namespace
{
// The object's triangles in model coordinates, with its point normals when it has them (else
// area-weighted ones), and its reflectance from the property's diffuse colour.
vlf::ObjectMesh ReadObjectMesh(vtkPolyData* input, vtkActor* object)
{
  vtkNew<vtkPolyData> shallow;
  shallow->ShallowCopy(input); // the filter below never touches the user's polydata
  vtkNew<vtkTriangleFilter> triangles;
  triangles->SetInputData(shallow);
  triangles->PassVertsOff();
  triangles->PassLinesOff();
  triangles->Update();
  vtkPolyData* output = triangles->GetOutput();
  vlf::ObjectMesh mesh;
  if (!output->GetPoints())
  {
    return mesh;
  }
  mesh.Points.resize(static_cast<std::size_t>(output->GetNumberOfPoints()));
  for (vtkIdType i = 0; i < output->GetNumberOfPoints(); ++i)
  {
    double p[3];
    output->GetPoint(i, p);
    mesh.Points[static_cast<std::size_t>(i)] = glm::vec3(p[0], p[1], p[2]);
  }
  vtkCellArray* polys = output->GetPolys();
  const vtkIdType* ids = nullptr;
  vtkIdType n = 0;
  for (polys->InitTraversal(); polys->GetNextCell(n, ids);)
  {
    if (n == 3)
    {
      mesh.Triangles.emplace_back(static_cast<unsigned>(ids[0]), static_cast<unsigned>(ids[1]),
        static_cast<unsigned>(ids[2]));
    }
  }
  vtkDataArray* normals = output->GetPointData()->GetNormals();
  bool useNormals = normals && normals->GetNumberOfComponents() == 3 &&
    normals->GetNumberOfTuples() == output->GetNumberOfPoints();
  if (useNormals)
  {
    mesh.Normals.resize(mesh.Points.size());
    for (vtkIdType i = 0; i < output->GetNumberOfPoints() && useNormals; ++i)
    {
      double v[3];
      normals->GetTuple(i, v);
      const glm::vec3 nv(v[0], v[1], v[2]);
      const float length = glm::length(nv);
      useNormals = std::isfinite(length) && length > 0.0f;
      mesh.Normals[static_cast<std::size_t>(i)] = useNormals ? nv / length : nv;
    }
  }
  if (!useNormals)
  {
    mesh.ComputeNormals(); // a defined fallback for meshes without (usable) normals
  }
  double kd[3];
  object->GetProperty()->GetDiffuseColor(kd);
  const double k = object->GetProperty()->GetDiffuse();
  for (int c = 0; c < 3; ++c)
  {
    mesh.Kd[c] = static_cast<float>(std::min(1.0, std::max(0.0, kd[c] * k)));
  }
  return mesh;
}

glm::mat4 ToGlm(vtkMatrix4x4* m)
{
  glm::mat4 out(1.0f);
  for (int row = 0; row < 4; ++row)
  {
    for (int column = 0; column < 4; ++column)
    {
      out[column][row] = static_cast<float>(m->GetElement(row, column));
    }
  }
  return out;
}
} // namespace

//------------------------------------------------------------------------------
void vtkLightFieldActor::SetMovableObject(vtkActor* object)
{
  Internals& impl = *this->Impl;
  if (impl.Object == object)
  {
    return;
  }
  if (object == this)
  {
    vtkErrorMacro(<< "the light field actor cannot be its own movable object");
    return;
  }
  impl.StopWorker(); // the worker may be tracing the old object
  if (impl.Tracer)
  {
    impl.Tracer->ClearObject();
  }
  impl.Object = object;
  impl.ForgetObjectState();
  this->LastObjectProblem.clear();
  impl.ObjectProblemWarned.clear();
  this->Modified();
}

//------------------------------------------------------------------------------
vtkActor* vtkLightFieldActor::GetMovableObject()
{
  return this->Impl->Object;
}

//------------------------------------------------------------------------------
const mesolight::vlf::ShadedObject* vtkLightFieldActor::GetShadedObject() const
{
  const Internals& impl = *this->Impl;
  return impl.ObjectUsable && impl.Gathered && impl.Gatherer ? &impl.Gatherer->Result() : nullptr;
}

//------------------------------------------------------------------------------
const mesolight::vlf::LightApproximation* vtkLightFieldActor::GetEmitterLights()
{
  Internals& impl = *this->Impl;
  this->RefreshField();
  if (!impl.Field)
  {
    return nullptr;
  }
  if (!impl.Lights)
  {
    impl.Lights.reset(new vlf::LightApproximation(vlf::EstimateEmitterLights(*impl.Field)));
  }
  return impl.Lights.get();
}

//------------------------------------------------------------------------------
unsigned long vtkLightFieldActor::GetObjectVersion() const
{
  return this->Impl->ObjectVersion;
}

//------------------------------------------------------------------------------
bool vtkLightFieldActor::UpdateMovableObject()
{
  Internals& impl = *this->Impl;
  const Clock::time_point start = Clock::now();
  this->RefreshField();
  vtkActor* object = impl.Object;
  // Takes the object out of the tracer (the mesh stays read: a later placement may work).
  auto drop = [&]()
  {
    if (impl.ObjectPlaced || impl.Gathered || impl.Tracer->HasObject())
    {
      impl.StopWorker();
      impl.Tracer->ClearObject();
      impl.ObjectPlaced = false;
      impl.Gathered = false;
      impl.TracedMesh = 0;
      ++impl.ObjectVersion;
    }
  };
  auto fail = [&](const std::string& why)
  {
    drop();
    this->LastObjectProblem = why;
    if (impl.ObjectProblemWarned != why)
    {
      vtkErrorMacro(<< why);
      impl.ObjectProblemWarned = why;
    }
    return false;
  };
  if (!impl.Field || !impl.Tracer)
  {
    return false;
  }
  if (!object)
  {
    // None set, or the actor was deleted (held weakly): nothing of it may stay in the tracer.
    drop();
    impl.ObjectUsable = false;
    this->LastObjectProblem.clear();
    return false;
  }
  vtkMapper* mapper = object->GetMapper();
  if (!mapper)
  {
    return fail("the movable object has no mapper: nothing to place in the light field");
  }
  if (mapper->GetNumberOfInputConnections(0) > 0)
  {
    mapper->GetInputAlgorithm()->Update();
  }
  vtkPolyData* data = vtkPolyData::SafeDownCast(mapper->GetInputDataObject(0, 0));
  if (!data)
  {
    return fail("the movable object's mapper has no vtkPolyData input");
  }
  // 1. The mesh, reread only when the data (or the reflectance) changed.
  const vtkMTimeType dataTime = std::max(data->GetMTime(), object->GetProperty()->GetMTime());
  if (data != impl.ObjectData || dataTime != impl.ObjectDataTime)
  {
    impl.ObjectData = data;
    impl.ObjectDataTime = dataTime;
    impl.ObjectModel = ReadObjectMesh(data, object);
    ++impl.ObjectMeshVersion;
    impl.ObjectUsable = false;
    impl.ObjectProblemWarned.clear();
    const std::string problem = impl.ObjectModel.Validate();
    if (!problem.empty())
    {
      impl.ObjectModel = vlf::ObjectMesh{};
      return fail("the movable object cannot be used: " + problem);
    }
    impl.ObjectUsable = true;
    const std::size_t degenerate = impl.ObjectModel.DegenerateTriangleCount();
    if (degenerate > 0)
    {
      vtkWarningMacro(<< "the movable object has " << degenerate
                      << " triangles of zero area; they are skipped");
    }
  }
  if (!impl.ObjectUsable)
  {
    return false;
  }
  // 2. The placement: the actor's matrix, then the field's normalisation.
  const glm::mat4 placement = vlf::WorldToUnitSphere(*impl.Field) * ToGlm(object->GetMatrix());
  const bool ignore = this->IgnoreObjectForTesting;
  const bool meshChanged = impl.ObjectGatherMesh != impl.ObjectMeshVersion ||
    impl.ObjectGatherSubdivision != this->ObjectSubdivision;
  if (impl.ObjectPlaced && placement == impl.ObjectPlacement && !meshChanged &&
    ignore == impl.ObjectIgnored)
  {
    return true; // the figures stay those of the last update that did work
  }
  const vlf::ObjectMesh unit = vlf::TransformMesh(impl.ObjectModel, placement);
  const std::string unitProblem = unit.Validate();
  if (!unitProblem.empty())
  {
    return fail("the movable object's placement cannot be used (" + unitProblem +
      "): is its scale zero or its matrix not finite?");
  }
  // 3. Its shading: one gather per change, shared by the tracer and the object's mapper.
  impl.StopWorker(); // the worker must not trace while the instance and radiance change
  if (!impl.Gatherer)
  {
    impl.Gatherer.reset(new vlf::ObjectGatherer(*impl.Field));
  }
  const Clock::time_point gatherStart = Clock::now();
  vlf::GatherSettings settings;
  settings.Subdivision = this->ObjectSubdivision;
  try
  {
    impl.Gatherer->Gather(unit, settings);
  }
  catch (const std::exception& e)
  {
    impl.Gathered = false;
    return fail(std::string("cannot gather the light field onto the movable object: ") + e.what());
  }
  impl.Gathered = true;
  this->LastGatherSeconds = SecondsSince(gatherStart);
  const vlf::ShadedObject& shaded = impl.Gatherer->Result();
  // 4. The tracer's instance: its mesh is the gathered one (subdivided) in model coordinates,
  // rebuilt only when the mesh or the subdivision changed; a move changes its transform only.
  try
  {
    if (ignore)
    {
      impl.Tracer->ClearObject();
      impl.TracedMesh = 0;
    }
    else
    {
      if (impl.TracedMesh != impl.ObjectMeshVersion ||
        impl.TracedSubdivision != this->ObjectSubdivision ||
        impl.Tracer->Object().Points.size() != shaded.Mesh.Points.size())
      {
        vlf::ObjectMesh model = this->ObjectSubdivision == 0 &&
            shaded.Mesh.Points.size() == impl.ObjectModel.Points.size()
          ? impl.ObjectModel
          : vlf::TransformMesh(shaded.Mesh, glm::inverse(placement));
        impl.Tracer->SetObject(model);
        impl.TracedMesh = impl.ObjectMeshVersion;
        impl.TracedSubdivision = this->ObjectSubdivision;
      }
      impl.Tracer->SetObjectPlacement(placement);
      impl.Tracer->SetObjectRadiance(shaded.Radiance);
    }
  }
  catch (const std::exception& e)
  {
    return fail(std::string("cannot trace the movable object: ") + e.what());
  }
  impl.ObjectPlacement = placement;
  impl.ObjectPlaced = true;
  impl.ObjectGatherMesh = impl.ObjectMeshVersion;
  impl.ObjectGatherSubdivision = this->ObjectSubdivision;
  impl.ObjectIgnored = ignore;
  ++impl.ObjectVersion;

  // 5. Checks a user wants to hear about (the object is still shown): outside the field's unit
  // sphere (nothing gathered there is meaningful), or through a wall (rays from its centre to
  // its points cross a static surface).
  std::string problem;
  glm::vec3 lower, upper;
  unit.Bounds(lower, upper);
  const glm::vec3 centre = 0.5f * (lower + upper);
  for (const glm::vec3& p : unit.Points)
  {
    if (glm::length(p) > 1.0f)
    {
      problem = "the movable object reaches outside the light field's bounds: its shading there "
                "is not meaningful";
      break;
    }
  }
  if (problem.empty())
  {
    const std::size_t step = std::max<std::size_t>(1, unit.Points.size() / 256);
    for (std::size_t i = 0; i < unit.Points.size() && problem.empty(); i += step)
    {
      mesolight::SceneRay ray;
      ray.Origin = centre;
      ray.Direction = unit.Points[i] - centre;
      ray.TFar = 0.999f;
      if (glm::length(ray.Direction) > 0.0f &&
        impl.Tracer->Embree().Intersect(ray).Triangle != mesolight::SceneHit::None)
      {
        problem = "the movable object intersects a surface of the light field (a wall?)";
      }
    }
  }
  this->LastObjectProblem = problem;
  if (!problem.empty() && impl.ObjectProblemWarned != problem)
  {
    vtkWarningMacro(<< problem);
  }
  impl.ObjectProblemWarned = problem;
  this->LastObjectSeconds = SecondsSince(start);
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
  os << indent << "IgnoreObjectForTesting: " << this->IgnoreObjectForTesting << "\n";
}
