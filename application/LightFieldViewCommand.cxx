// SPDX-License-Identifier: BSD-3-Clause
#include "LightFieldViewCommand.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "LightFieldCamera.h"
#include "OutputFile.h"
#include "Timing.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldObjectMapper.h"

#include "ObjScene.h"
#include "ObjectGatherer.h"
#include "ObjectMesh.h"

#include "LightField.h"
#include "PatchComparison.h"
#include "Propagation.h"
#include "Snapshot.h"
#include "TriangleScene.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCamera.h>
#include <vtkCellArray.h>
#include <vtkCommand.h>
#include <vtkFloatArray.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkOpenGLRenderWindow.h>
#include <vtkPNGWriter.h>
#include <vtkPointData.h>
#include <vtkPoints.h>
#include <vtkPolyData.h>
#include <vtkProperty.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtkWindowToImageFilter.h>

#include <glm/geometric.hpp>

#include <algorithm>
#include <cctype>
#include <chrono>
#include <cmath>
#include <cstdlib>
#include <fstream>
#include <iomanip>
#include <iostream>
#include <memory>
#include <sstream>

namespace mesolight
{
namespace
{
namespace vlf = mesolight::vlf;
using Clock = std::chrono::steady_clock;

void AddViewOptions(CommandLine& cl)
{
  cl.AddValue("--mode", "MODE", "geometry, raytrace, progressive or coherent", "progressive");
  cl.AddValue("--size", "WxH", "window size in pixels", "800x800");
  AddLightFieldCameraOptions(cl);
  cl.AddValue("--exposure", "X", "radiance scale before tone mapping", "1");
  cl.AddValue("--tone-map", "OP", "clamp or reinhard", "clamp");
  cl.AddValue("--reflection-depth", "N", "mirror bounces traced", "8");
}

// Applies the shared view options to an actor and a renderer's camera.
bool ConfigureView(const CommandLine& cl, vtkLightFieldActor* actor, vtkRenderer* renderer,
  const char* command, int& width, int& height)
{
  const int mode = vtkLightFieldActor::GetRenderModeFromString(cl.Get("--mode"));
  if (mode < 0)
  {
    std::cerr << command << ": --mode '" << cl.Get("--mode")
              << "' is not geometry, raytrace, progressive or coherent\n";
    return false;
  }
  std::string error;
  if (!cl.GetSize("--size", 1, 16384, width, height, error))
  {
    std::cerr << command << ": " << error << "\n";
    return false;
  }
  double exposure = 1.0, angle = 39.3077;
  int depth = 8;
  if (!cl.GetDouble("--exposure", 0.0, 1e9, exposure, error) ||
    !cl.GetDouble("--view-angle", 1.0, 179.0, angle, error) ||
    !cl.GetInt("--reflection-depth", 1, 64, depth, error))
  {
    std::cerr << command << ": " << error << "\n";
    return false;
  }
  const std::string toneMap = cl.Get("--tone-map");
  if (toneMap != "clamp" && toneMap != "reinhard")
  {
    std::cerr << command << ": --tone-map '" << toneMap << "' is not clamp or reinhard\n";
    return false;
  }
  actor->SetRenderMode(mode);
  actor->SetExposure(exposure);
  actor->SetToneMap(
    toneMap == "reinhard" ? vtkLightFieldActor::Reinhard : vtkLightFieldActor::Clamp);
  actor->SetMaximumReflectionDepth(depth);

  double up[3] = { 0.0, 1.0, 0.0 };
  glm::vec3 eye, focal;
  if (!ReadLightFieldCamera(cl, *actor->GetLightField(), eye, focal, up, error))
  {
    std::cerr << command << ": " << error << "\n";
    return false;
  }
  const glm::vec3 forward = focal - eye;
  if (!(glm::length(forward) > 0.0f) ||
    !(glm::length(glm::cross(glm::normalize(forward), glm::vec3(up[0], up[1], up[2]))) > 1e-6f))
  {
    std::cerr << command
              << ": the camera needs distinct position and focal point and a view-up "
                 "direction not parallel to the view direction\n";
    return false;
  }
  vtkCamera* camera = renderer->GetActiveCamera();
  camera->SetPosition(eye.x, eye.y, eye.z);
  camera->SetFocalPoint(focal.x, focal.y, focal.z);
  camera->SetViewUp(up);
  camera->SetViewAngle(angle);
  renderer->ResetCameraClippingRange();
  return true;
}

bool WritePng(vtkRenderWindow* window, const std::string& out)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ShouldRerenderOff();
  grab->ReadFrontBufferOn();
  grab->Update();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(grab->GetOutputPort());
  writer->SetFileName(out.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

// The light field actor of FIELD (the command's one positional argument) in a renderer and a
// window set up by the view options.
struct WalkthroughWindow
{
  vtkNew<vtkLightFieldActor> Actor;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
};

// 0 when the window is ready, else the command's exit code (the message is printed).
int OpenWalkthrough(
  const CommandLine& cl, const char* command, bool offscreen, WalkthroughWindow& walkthrough)
{
  if (!walkthrough.Actor->LoadLightField(cl.Positional()[0]))
  {
    std::cerr << command << ": " << walkthrough.Actor->GetLastError() << "\n";
    return 1;
  }
  walkthrough.Window->SetOffScreenRendering(offscreen ? 1 : 0);
  walkthrough.Window->SetMultiSamples(0);
  walkthrough.Window->AddRenderer(walkthrough.Renderer);
  walkthrough.Renderer->AddActor(walkthrough.Actor);
  int width = 0, height = 0;
  if (!ConfigureView(cl, walkthrough.Actor, walkthrough.Renderer, command, width, height))
  {
    return 2;
  }
  walkthrough.Window->SetSize(width, height);
  return 0;
}

// --- The movable object (--object ...) ---------------------------------------------------------

void AddObjectOptions(CommandLine& cl)
{
  cl.AddValue("--object", "OBJECT",
    "a movable object in the field: sphere, cube (side 1, scaled to a fifth of the field) or "
    "FILE.obj (its own units)");
  cl.AddValue("--object-transform", "T",
    "tx,ty,tz[,rx,ry,rz[,s]]: the object's position (world units), orientation (degrees, as "
    "vtkProp3D::SetOrientation) and scale; default: the field's centre");
  cl.AddValue(
    "--object-colour", "R,G,B", "the object's diffuse reflectance, each in [0, 1]", "0.7,0.7,0.7");
  cl.AddValue("--shading", "S", "the object's shading: flat, lights or gather", "gather");
  cl.AddValue(
    "--subdivision", "N", "midpoint subdivision levels of the gathered object (0-3)", "0");
}

struct ObjectPlacement
{
  double Position[3] = { 0.0, 0.0, 0.0 };
  double Orientation[3] = { 0.0, 0.0, 0.0 };
  double Scale = 1.0;
};

// "tx,ty,tz[,rx,ry,rz[,s]]" over the defaults in `placement`; "" or why not.
std::string ParsePlacement(const std::string& text, ObjectPlacement& placement)
{
  std::vector<double> values;
  std::stringstream in(text);
  std::string item;
  while (std::getline(in, item, ','))
  {
    char* end = nullptr;
    const double v = std::strtod(item.c_str(), &end);
    if (item.empty() || end == item.c_str() || *end != '\0' || !std::isfinite(v))
    {
      return "'" + item + "' is not a finite number";
    }
    values.push_back(v);
  }
  if (values.size() != 3 && values.size() != 6 && values.size() != 7)
  {
    return "give tx,ty,tz or tx,ty,tz,rx,ry,rz or tx,ty,tz,rx,ry,rz,s (" +
      std::to_string(values.size()) + " numbers given)";
  }
  std::copy(values.begin(), values.begin() + 3, placement.Position);
  if (values.size() >= 6)
  {
    std::copy(values.begin() + 3, values.begin() + 6, placement.Orientation);
  }
  if (values.size() == 7)
  {
    if (!(values[6] > 0.0))
    {
      return "the scale must be positive";
    }
    placement.Scale = values[6];
  }
  return {};
}

void ApplyPlacement(vtkActor* object, const ObjectPlacement& p)
{
  object->SetPosition(p.Position[0], p.Position[1], p.Position[2]);
  object->SetOrientation(p.Orientation[0], p.Orientation[1], p.Orientation[2]);
  object->SetScale(p.Scale);
}

// The object's polydata of --object (sphere, cube or an OBJ file's triangles).
vtkSmartPointer<vtkPolyData> ObjectPolyData(const vlf::ObjectMesh& mesh)
{
  vtkNew<vtkPoints> points;
  points->SetDataTypeToFloat();
  for (const glm::vec3& p : mesh.Points)
  {
    points->InsertNextPoint(p.x, p.y, p.z);
  }
  vtkNew<vtkCellArray> polys;
  for (const glm::uvec3& t : mesh.Triangles)
  {
    const vtkIdType ids[3] = { t.x, t.y, t.z };
    polys->InsertNextCell(3, ids);
  }
  auto poly = vtkSmartPointer<vtkPolyData>::New();
  poly->SetPoints(points);
  poly->SetPolys(polys);
  if (mesh.Normals.size() == mesh.Points.size())
  {
    vtkNew<vtkFloatArray> normals;
    normals->SetName("Normals");
    normals->SetNumberOfComponents(3);
    for (const glm::vec3& n : mesh.Normals)
    {
      normals->InsertNextTuple3(n.x, n.y, n.z);
    }
    poly->GetPointData()->SetNormals(normals);
  }
  return poly;
}

// The object of the command line in the walkthrough's renderer.
struct MovableObject
{
  vtkNew<vtkActor> Actor;
  vtkNew<vtkLightFieldObjectMapper> Mapper;
  bool Active = false;
  ObjectPlacement Placement; // the one --object-transform (or the default) gave
  double Step = 1.0;         // world units per key press (a twentieth of the field)
};

// 0 when set up (or no --object), else the command's exit code (the message is printed).
// `inputs` gathers the files read, so no output overwrites them.
int SetUpObject(const CommandLine& cl, const char* command, WalkthroughWindow& walkthrough,
  MovableObject& object, std::vector<std::string>* inputs = nullptr)
{
  if (!cl.Has("--object"))
  {
    for (const char* option : { "--object-transform", "--path" })
    {
      if (cl.Has(option))
      {
        std::cerr << command << ": " << option << " needs --object\n";
        return 2;
      }
    }
    return 0;
  }
  std::string error;
  int subdivision = 0;
  if (!cl.GetInt("--subdivision", 0, 3, subdivision, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 2;
  }
  const int shading = vtkLightFieldObjectMapper::GetShadingFromString(cl.Get("--shading"));
  if (shading < 0)
  {
    std::cerr << command << ": --shading '" << cl.Get("--shading")
              << "' is not flat, lights or gather\n";
    return 2;
  }
  double colour[3] = { 0.7, 0.7, 0.7 };
  {
    std::vector<double> values;
    if (!cl.GetDoubleList("--object-colour", 0.0, 1.0, values, error) || values.size() != 3)
    {
      std::cerr << command << ": --object-colour: "
                << (error.empty() ? "give three values R,G,B in [0, 1]" : error) << "\n";
      return 2;
    }
    std::copy(values.begin(), values.end(), colour);
  }
  double bounds[6];
  walkthrough.Actor->GetBounds(bounds);
  const double extent =
    std::max(bounds[1] - bounds[0], std::max(bounds[3] - bounds[2], bounds[5] - bounds[4]));
  const std::string name = cl.Get("--object");
  vlf::ObjectMesh mesh;
  ObjectPlacement placement;
  for (int a = 0; a < 3; ++a)
  {
    placement.Position[a] = 0.5 * (bounds[2 * a] + bounds[2 * a + 1]);
  }
  if (name == "sphere" || name == "cube")
  {
    mesh = name == "sphere" ? vlf::MakeSphere(0.5f, 16, 32) : vlf::MakeCube(1.0f);
    placement.Scale = 0.2 * extent;
  }
  else
  {
    if (!vlf::FileExists(name))
    {
      std::cerr << command << ": --object '" << name
                << "' is not sphere, cube or an existing .obj file\n";
      return 2;
    }
    try
    {
      const vlf::ObjSceneRead read = vlf::ReadObjScene(name);
      mesh.Points = read.Scene.Positions;
      mesh.Triangles.assign(read.Scene.Triangles.begin(), read.Scene.Triangles.end());
    }
    catch (const std::exception& e)
    {
      std::cerr << command << ": --object: " << e.what() << "\n";
      return 1;
    }
    if (inputs)
    {
      inputs->push_back(name);
    }
  }
  // Bad meshes are refused here with one line (the actor would refuse them too).
  const std::string problem = mesh.Validate();
  if (!problem.empty())
  {
    std::cerr << command << ": --object '" << name << "': " << problem << "\n";
    return 1;
  }
  if (cl.Has("--object-transform"))
  {
    error = ParsePlacement(cl.Get("--object-transform"), placement);
    if (!error.empty())
    {
      std::cerr << command << ": --object-transform: " << error << "\n";
      return 2;
    }
  }
  object.Mapper->SetInputData(ObjectPolyData(mesh));
  object.Mapper->SetLightFieldActor(walkthrough.Actor);
  object.Mapper->SetShading(shading);
  object.Mapper->SetSubdivision(subdivision);
  object.Actor->SetMapper(object.Mapper);
  object.Actor->GetProperty()->SetDiffuseColor(colour);
  object.Actor->GetProperty()->SetDiffuse(1.0);
  object.Placement = placement;
  object.Step = extent > 0.0 ? extent / 20.0 : 1.0;
  ApplyPlacement(object.Actor, placement);
  walkthrough.Actor->SetMovableObject(object.Actor);
  walkthrough.Actor->SetObjectSubdivision(subdivision);
  walkthrough.Renderer->AddActor(object.Actor);
  walkthrough.Renderer->ResetCameraClippingRange();
  object.Active = true;
  return 0;
}

// --path FILE: one placement per line ("tx,ty,tz[,rx,ry,rz[,s]]"; '#' comments and a header
// line of names are skipped); rows without a scale keep `base`'s.
bool ReadPath(const std::string& file, const ObjectPlacement& base,
  std::vector<ObjectPlacement>& path, std::string& error)
{
  std::ifstream in(file);
  if (!in)
  {
    error = "cannot read '" + file + "'";
    return false;
  }
  std::string line;
  int number = 0;
  while (std::getline(in, line))
  {
    ++number;
    line.erase(0, line.find_first_not_of(" \t\r"));
    line.erase(line.find_last_not_of(" \t\r") + 1);
    if (line.empty() || line[0] == '#' || (number == 1 && std::isalpha(line[0])))
    {
      continue;
    }
    ObjectPlacement p = base;
    const std::string why = ParsePlacement(line, p);
    if (!why.empty())
    {
      error = file + ":" + std::to_string(number) + ": " + why;
      return false;
    }
    path.push_back(p);
  }
  if (path.empty())
  {
    error = "'" + file + "' holds no placement";
    return false;
  }
  return true;
}

// One line on the object after a frame: timings and anything wrong with its placement.
void PrintObjectNote(vtkLightFieldActor* actor, const MovableObject& object)
{
  if (!object.Active)
  {
    return;
  }
  if (!actor->GetLastObjectProblem().empty())
  {
    std::cout << "note: " << actor->GetLastObjectProblem() << "\n";
  }
}

int Render(const std::vector<std::string>& args)
{
  const char* command = "mesolight vlf render";
  CommandLine cl(command,
    "mesolight vlf render FIELD --mode MODE --out IMAGE.png [options]\n\n"
    "Renders a light field through vtkLightFieldActor in an offscreen VTK window "
    "(Wither 2005 §2.4.2.2 modes).\nWithout --mode, 'vlf render' is the CPU reference "
    "renderer (total diffuse textures, field radiance on mirrors).\n");
  cl.AddValue("--out", "IMAGE.png", "where to write the image (required)");
  AddViewOptions(cl);
  cl.AddFlag("--moving",
    "progressive: write the frame shown while the camera moves (field lookups "
    "on mirrors), not the converged one");
  cl.AddFlag("--force", "replace an existing IMAGE.png");
  AddObjectOptions(cl);
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (cl.Positional().size() != 1 || cl.Get("--out").empty())
  {
    std::cerr << command << ": give one FIELD and --out IMAGE.png\n";
    return 2;
  }
  const std::string out = cl.Get("--out");
  std::vector<std::string> inputs{ cl.Positional()[0] };
  if (cl.Has("--object") && cl.Get("--object") != "sphere" && cl.Get("--object") != "cube")
  {
    inputs.push_back(cl.Get("--object"));
  }
  const std::string problem = CheckOutputFile(out, inputs);
  if (!problem.empty())
  {
    std::cerr << command << ": --out: " << problem << "\n";
    return 2;
  }
  if (vlf::FileExists(out) && !cl.Has("--force"))
  {
    std::cerr << command << ": '" << out << "' exists; add --force to replace it\n";
    return 1;
  }
  WalkthroughWindow walkthrough;
  if (const int status = OpenWalkthrough(cl, command, true, walkthrough))
  {
    return status;
  }
  MovableObject object;
  if (const int status = SetUpObject(cl, command, walkthrough, object))
  {
    return status;
  }
  vtkLightFieldActor* actor = walkthrough.Actor;
  vtkRenderWindow* window = walkthrough.Window;
  if ((actor->GetRenderMode() == vtkLightFieldActor::Progressive ||
        actor->GetRenderMode() == vtkLightFieldActor::Coherent) &&
    !actor->HasMirrors())
  {
    std::cout << "note: the light field has no mirror surfaces; " << cl.Get("--mode")
              << " shows its diffuse textures\n";
  }
  const Clock::time_point start = Clock::now();
  window->Render();
  if (actor->GetRenderMode() == vtkLightFieldActor::Progressive && !cl.Has("--moving"))
  {
    if (!actor->WaitForTracedReflections(120.0))
    {
      std::cerr << command << ": the traced reflections did not finish in 120 s\n";
      return 1;
    }
    window->Render();
  }
  const double seconds = SecondsSince(start);
  if (!WritePng(window, out))
  {
    std::cerr << command << ": could not write '" << out << "'\n";
    return 1;
  }
  std::cout << "wrote " << out << " (" << window->GetSize()[0] << "x" << window->GetSize()[1]
            << ", mode " << cl.Get("--mode") << ", " << seconds << " s, "
            << actor->GetLastScreenPixels() << " pixels from the CPU pass)\n";
  if (object.Active)
  {
    PrintObjectNote(actor, object);
    std::cout << "object: " << cl.Get("--object") << ", shading " << cl.Get("--shading")
              << ", gather " << 1000.0 * actor->GetLastGatherSeconds() << " ms, "
              << (actor->GetShadedObject() ? actor->GetShadedObject()->Mesh.Points.size() : 0)
              << " points\n";
  }
  return 0;
}

// Keys and the progressive refresh of the interactive viewer.
struct ViewerState
{
  vtkLightFieldActor* Actor = nullptr;
  vtkRenderWindow* Window = nullptr;
  vtkTextActor* Text = nullptr;
  vtkCommand* Keys = nullptr;
  MovableObject* Object = nullptr;
  double LastFrameSeconds = 0.0;
  Clock::time_point LastRender = Clock::now();
  void UpdateText()
  {
    std::ostringstream s;
    s << std::fixed << std::setprecision(2)
      << vtkLightFieldActor::GetRenderModeAsString(this->Actor->GetRenderMode()) << "  exposure "
      << this->Actor->GetExposure() << "  "
      << (this->Actor->GetToneMap() == vtkLightFieldActor::Reinhard ? "reinhard" : "clamp")
      << "  depth " << this->Actor->GetMaximumReflectionDepth() << "  " << std::setprecision(1)
      << 1000.0 * this->LastFrameSeconds << " ms"
      << (this->Actor->GetLastFrameConverged() ? "" : "  (refining)")
      << "\n1-4/m mode  +/- exposure  t tone map  [ ] reflection depth  q quit"
      << (this->Object && this->Object->Active ? "\nobject: j/l x  k/i y  u/o z  y turn  (gather " +
               std::to_string(static_cast<int>(1000.0 * this->Actor->GetLastGatherSeconds())) +
               " ms)"
                                               : std::string());
    this->Text->SetInput(s.str().c_str());
  }
  void Render()
  {
    this->UpdateText();
    const Clock::time_point start = Clock::now();
    this->Window->Render();
    this->LastFrameSeconds = SecondsSince(start);
    this->LastRender = Clock::now();
    if (this->Record && this->Object && this->Object->Active)
    {
      // One placement per rendered frame: `--path` plays it back.
      const double* p = this->Object->Actor->GetPosition();
      const double* r = this->Object->Actor->GetOrientation();
      *this->Record << p[0] << "," << p[1] << "," << p[2] << "," << r[0] << "," << r[1] << ","
                    << r[2] << "," << this->Object->Actor->GetScale()[0] << "\n";
    }
  }
  std::ofstream* Record = nullptr;
};

void OnChar(vtkObject* caller, unsigned long, void* clientData, void*)
{
  auto* interactor = static_cast<vtkRenderWindowInteractor*>(caller);
  ViewerState* state = static_cast<ViewerState*>(clientData);
  vtkLightFieldActor* actor = state->Actor;
  const char key = interactor->GetKeyCode();
  bool handled = true;
  switch (key)
  {
    case '1':
    case '2':
    case '3':
    case '4':
      actor->SetRenderMode(key - '1');
      break;
    case 'm':
      actor->SetRenderMode((actor->GetRenderMode() + 1) % 4);
      break;
    case '+':
    case '=':
      actor->SetExposure(actor->GetExposure() * 1.25);
      break;
    case '-':
      actor->SetExposure(actor->GetExposure() / 1.25);
      break;
    case 't':
      actor->SetToneMap(1 - actor->GetToneMap());
      break;
    case ']':
      actor->SetMaximumReflectionDepth(actor->GetMaximumReflectionDepth() + 1);
      break;
    case '[':
      actor->SetMaximumReflectionDepth(actor->GetMaximumReflectionDepth() - 1);
      break;
    default:
      handled = false;
  }
  if (!handled && state->Object && state->Object->Active)
  {
    // The movable object: a twentieth of the field per press along world x, y, z; 15 degrees
    // about its own y axis.
    vtkActor* object = state->Object->Actor;
    const double step = state->Object->Step;
    double* p = object->GetPosition();
    const double position[3] = { p[0], p[1], p[2] };
    handled = true;
    switch (key)
    {
      case 'j':
        object->SetPosition(position[0] - step, position[1], position[2]);
        break;
      case 'l':
        object->SetPosition(position[0] + step, position[1], position[2]);
        break;
      case 'k':
        object->SetPosition(position[0], position[1] - step, position[2]);
        break;
      case 'i':
        object->SetPosition(position[0], position[1] + step, position[2]);
        break;
      case 'u':
        object->SetPosition(position[0], position[1], position[2] - step);
        break;
      case 'o':
        object->SetPosition(position[0], position[1], position[2] + step);
        break;
      case 'y':
        object->RotateY(15.0);
        break;
      default:
        handled = false;
    }
  }
  if (handled)
  {
    // Keep the trackball style from acting on the same key (e.g. '3' toggles stereo there).
    state->Keys->AbortFlagOn();
    state->Render();
  }
}

void OnTimer(vtkObject*, unsigned long, void* clientData, void*)
{
  ViewerState* state = static_cast<ViewerState*>(clientData);
  // Progressive: once no frame came for 0.15 s the camera rests; trace its reflections (on the
  // actor's worker) and show them as soon as they are ready.
  if (state->Actor->GetRenderMode() == vtkLightFieldActor::Progressive &&
    !state->Actor->GetLastFrameConverged() && SecondsSince(state->LastRender) > 0.15 &&
    state->Actor->WaitForTracedReflections(0.0))
  {
    state->Render();
  }
}

int View(const std::vector<std::string>& args)
{
  const char* command = "mesolight vlf view";
  CommandLine cl(command,
    "mesolight vlf view FIELD [options]\n\n"
    "Walks through a light field in a VTK window (vtkLightFieldActor). Mouse: rotate "
    "(left), pan\n(middle), zoom (right/wheel). Keys: 1-4 or m mode (geometry, raytrace, "
    "progressive,\ncoherent), +/- exposure, t tone map (clamp/Reinhard), [ ] reflection "
    "depth, q quit.\nWith --object: j/l move it along x, k/i along y, u/o along z (a twentieth "
    "of the field per press),\ny turns it 15 degrees about its y axis.\n");
  AddViewOptions(cl);
  AddObjectOptions(cl);
  cl.AddValue("--path", "FILE.csv",
    "with --object and --frames: the object's placement per frame, one 'tx,ty,tz[,rx,ry,rz[,s]]' "
    "a line (repeated when shorter; the camera stays still)");
  cl.AddValue("--record-path", "FILE.csv",
    "with --object: write the object's placement at every rendered frame (for --path)");
  cl.AddValue("--frames", "N",
    "render N frames (turning the camera 2 degrees each) and exit: a non-interactive check", "0");
  cl.AddFlag("--offscreen", "no window (with --frames)");
  cl.AddValue("--keys", "KEYS",
    "with --frames: press these keys, one before each frame (a check of the key bindings)");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  std::string error;
  if (cl.Positional().size() != 1)
  {
    std::cerr << command << ": give one FIELD\n";
    return 2;
  }
  int frames = 0;
  if (!cl.GetInt("--frames", 0, 100000, frames, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 2;
  }
  WalkthroughWindow walkthrough;
  if (const int status = OpenWalkthrough(cl, command, false, walkthrough))
  {
    return status;
  }
  MovableObject object;
  if (const int status = SetUpObject(cl, command, walkthrough, object))
  {
    return status;
  }
  std::vector<ObjectPlacement> path;
  if (cl.Has("--path") && !ReadPath(cl.Get("--path"), object.Placement, path, error))
  {
    std::cerr << command << ": --path: " << error << "\n";
    return 1;
  }
  std::ofstream record;
  if (cl.Has("--record-path"))
  {
    std::vector<std::string> inputs{ cl.Positional()[0] };
    for (const char* option : { "--object", "--path" })
    {
      if (cl.Has(option))
      {
        inputs.push_back(cl.Get(option));
      }
    }
    std::string problem = CheckOutputFile(cl.Get("--record-path"), inputs);
    if (problem.empty() && vlf::FileExists(cl.Get("--record-path")))
    {
      problem = "'" + cl.Get("--record-path") + "' exists; a recorded path is never replaced";
    }
    if (!object.Active || !problem.empty())
    {
      std::cerr << command
                << ": --record-path: " << (object.Active ? problem : std::string("needs --object"))
                << "\n";
      return 2;
    }
    record.open(cl.Get("--record-path"));
    record << "# tx,ty,tz,rx,ry,rz,s per frame (mesolight vlf view --record-path)\n";
    record << std::setprecision(9);
  }
  vtkLightFieldActor* actor = walkthrough.Actor;
  vtkRenderer* renderer = walkthrough.Renderer;
  vtkRenderWindow* window = walkthrough.Window;
  window->SetWindowName("mesolight vlf view");
  vtkNew<vtkTextActor> text;
  text->GetTextProperty()->SetFontSize(14);
  text->SetDisplayPosition(8, 8);
  renderer->AddViewProp(text);
  ViewerState state;
  state.Actor = actor;
  state.Window = window;
  state.Text = text;
  state.Object = &object;
  state.Record = record.is_open() ? &record : nullptr;
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<vtkInteractorStyleTrackballCamera> style;
  interactor->SetInteractorStyle(style);
  vtkNew<vtkCallbackCommand> keys;
  keys->SetCallback(OnChar);
  keys->SetClientData(&state);
  state.Keys = keys;
  interactor->AddObserver(vtkCommand::CharEvent, keys, 1.0);
  if (frames > 0)
  {
    window->SetOffScreenRendering(cl.Has("--offscreen") ? 1 : 0);
    const std::string pressed = cl.Get("--keys");
    double total = 0.0, gather = 0.0, update = 0.0, still = 0.0;
    int updates = 0;
    unsigned long version = actor->GetObjectVersion();
    for (int f = 0; f < frames; ++f)
    {
      if (static_cast<std::size_t>(f) < pressed.size())
      {
        interactor->SetKeyCode(pressed[static_cast<std::size_t>(f)]);
        interactor->InvokeEvent(vtkCommand::CharEvent, nullptr);
      }
      if (!path.empty())
      {
        ApplyPlacement(object.Actor, path[static_cast<std::size_t>(f) % path.size()]);
      }
      state.Render();
      total += state.LastFrameSeconds;
      if (actor->GetObjectVersion() == version)
      {
        still += state.LastFrameSeconds;
      }
      else
      {
        // The object moved (or changed) in this frame: one placement and one gather.
        version = actor->GetObjectVersion();
        gather += actor->GetLastGatherSeconds();
        update += actor->GetLastObjectSeconds();
        ++updates;
      }
      if (path.empty())
      {
        renderer->GetActiveCamera()->Azimuth(2.0);
      }
      renderer->ResetCameraClippingRange();
    }
    if (object.Active)
    {
      PrintObjectNote(actor, object);
      const double* position = object.Actor->GetPosition();
      std::ostringstream line;
      line << std::fixed << std::setprecision(2) << "object at " << position[0] << ","
           << position[1] << "," << position[2] << "; moved in " << updates << " of " << frames
           << " frames; per move: object update " << 1000.0 * update / std::max(1, updates)
           << " ms, of which gathering " << 1000.0 * gather / std::max(1, updates) << " ms ("
           << (actor->GetShadedObject() ? actor->GetShadedObject()->Mesh.Points.size() : 0)
           << " points); frames without a move " << 1000.0 * still / std::max(1, frames - updates)
           << " ms\n";
      std::cout << line.str();
    }
    std::cout << "rendered " << frames << " frames, mode "
              << vtkLightFieldActor::GetRenderModeAsString(actor->GetRenderMode()) << ", exposure "
              << actor->GetExposure() << ", tone map "
              << (actor->GetToneMap() == vtkLightFieldActor::Reinhard ? "reinhard" : "clamp")
              << ", reflection depth " << actor->GetMaximumReflectionDepth() << ", mean "
              << 1000.0 * total / frames << " ms per frame\n";
    return 0;
  }
  vtkNew<vtkCallbackCommand> timer;
  timer->SetCallback(OnTimer);
  timer->SetClientData(&state);
  interactor->AddObserver(vtkCommand::TimerEvent, timer);
  interactor->Initialize();
  interactor->CreateRepeatingTimer(50);
  state.Render();
  interactor->Start();
  return 0;
}

// --- Benchmark ---------------------------------------------------------------------------------

struct BenchRow
{
  std::string Mode;
  int Frames = 0;
  double FrameMs = 0.0;
  double SpecularMs = 0.0;
  double UploadMs = 0.0;
  double Coverage = 0.0; // fraction of the view given a CPU (screen-space) value
  double GoalMs = 0.0;   // frame time goal (convergence time for progressive-rest)
  std::string Goal;
  double DrawMs() const
  {
    const double ms = this->FrameMs - this->SpecularMs - this->UploadMs;
    return ms > 1e-6 ? ms : 0.0;
  }
  bool Met() const { return this->FrameMs <= this->GoalMs; }
};

std::unique_ptr<vlf::LightField> BenchField(
  const TriangleScene& scene, int directions, int rays, int iterations)
{
  vlf::LightFieldSettings settings;
  settings.Directions = static_cast<std::size_t>(directions);
  settings.RaysPerSide = rays;
  settings.TilesPerSide = std::max(1, rays / 8);
  std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(scene, settings);
  vlf::Propagate(*field, iterations);
  return field;
}

void WaitForGpu(vtkRenderWindow* window)
{
  if (vtkOpenGLRenderWindow* gl = vtkOpenGLRenderWindow::SafeDownCast(window))
  {
    gl->WaitForCompletion();
  }
}

// Renders `frames` frames turning the camera a little each (every frame a new view: the
// progressive mode never rests), after two warm-up frames.
BenchRow TimeFrames(vtkRenderWindow* window, vtkRenderer* renderer, vtkLightFieldActor* actor,
  int mode, int frames, const std::string& name)
{
  actor->SetRenderMode(mode);
  vtkCamera* camera = renderer->GetActiveCamera();
  BenchRow row;
  row.Mode = name;
  const int* size = window->GetSize();
  const double pixels = static_cast<double>(size[0]) * size[1];
  for (int f = -2; f < frames; ++f)
  {
    camera->Azimuth(f % 2 ? 0.25 : -0.125);
    renderer->ResetCameraClippingRange();
    const Clock::time_point start = Clock::now();
    window->Render();
    WaitForGpu(window);
    const double ms = 1000.0 * SecondsSince(start);
    if (f < 0)
    {
      continue;
    }
    row.FrameMs += ms;
    row.SpecularMs += 1000.0 * actor->GetLastSpecularSeconds();
    row.UploadMs += 1000.0 * actor->GetLastUploadSeconds();
    row.Coverage += static_cast<double>(actor->GetLastScreenPixels()) / pixels;
    ++row.Frames;
  }
  row.FrameMs /= row.Frames;
  row.SpecularMs /= row.Frames;
  row.UploadMs /= row.Frames;
  row.Coverage /= row.Frames;
  return row;
}

int Bench(const std::vector<std::string>& args)
{
  const char* command = "mesolight bench walkthrough";
  CommandLine cl(command,
    "mesolight bench walkthrough [FIELD] [options]\n\n"
    "Frame time of every walkthrough mode (vtkLightFieldActor) in an offscreen window: "
    "the Cornell box\nwith a mirror wall (or FIELD) and the plain Cornell box for the "
    "diffuse-only row, split into\nstages (CPU screen-space pass, texture upload, draw "
    "and composite).\n");
  cl.AddValue("--size", "WxH", "window size", "800x800");
  cl.AddValue("--frames", "N", "frames timed per mode (raytrace and rest: at most 5)", "30");
  cl.AddValue("--directions", "N", "directions of the built-in fields", "2049");
  cl.AddValue("--rays", "N", "rays per subfield side", "32");
  cl.AddValue("--iterations", "K", "propagation iterations", "6");
  cl.AddValue("--csv", "FILE", "write the table as CSV");
  cl.AddValue("--plot", "FILE.png", "write a chart of the stages (VTK charts)");
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (const std::string problem = CheckOutputOptions(cl, { "--csv", "--plot" }, cl.Positional());
      !problem.empty())
  {
    return cl.UsageError(problem);
  }
  std::string error;
  int width = 0, height = 0, frames = 0, directions = 0, rays = 0, iterations = 0;
  if (!cl.GetSize("--size", 1, 16384, width, height, error))
  {
    return cl.UsageError(error);
  }
  if (!cl.GetInt("--frames", 1, 100000, frames, error) ||
    !cl.GetInt("--directions", 5, 1 << 20, directions, error) ||
    !cl.GetInt("--rays", 4, 4096, rays, error) ||
    !cl.GetInt("--iterations", 1, 1000, iterations, error))
  {
    std::cerr << command << ": " << error << "\n";
    return 2;
  }
  std::unique_ptr<vlf::LightField> mirrorField, diffuseField;
  try
  {
    const Clock::time_point start = Clock::now();
    if (cl.Positional().size() == 1)
    {
      mirrorField = vlf::ReadSnapshot(cl.Positional()[0]);
    }
    else
    {
      mirrorField = BenchField(MakeCornellBoxWithMirror(), directions, rays, iterations);
    }
    diffuseField = BenchField(MakeCornellBox(), directions, rays, iterations);
    std::cout << "fields ready in " << SecondsSince(start) << " s ("
              << mirrorField->Directions().Size() << " directions, "
              << mirrorField->Settings().RaysPerSide << " rays per side)\n";
  }
  catch (const std::exception& e)
  {
    std::cerr << command << ": " << e.what() << "\n";
    return 1;
  }
  const std::size_t fieldDirections = mirrorField->Directions().Size();
  vtkNew<vtkRenderWindow> window;
  window->SetOffScreenRendering(1);
  window->SetMultiSamples(0);
  window->SetSize(width, height);
  vtkNew<vtkRenderer> renderer;
  window->AddRenderer(renderer);
  vtkNew<vtkLightFieldActor> actor;
  actor->SetLightField(mirrorField.get());
  renderer->AddActor(actor);
  auto resetCamera = [&]()
  {
    const CornellCamera c;
    vtkCamera* camera = renderer->GetActiveCamera();
    camera->SetPosition(c.Position.x, c.Position.y, c.Position.z);
    camera->SetFocalPoint(c.FocalPoint.x, c.FocalPoint.y, c.FocalPoint.z);
    camera->SetViewUp(c.ViewUp.x, c.ViewUp.y, c.ViewUp.z);
    camera->SetViewAngle(c.ViewAngleDegrees);
    renderer->ResetCameraClippingRange();
  };
  std::vector<BenchRow> rows;
  resetCamera();
  rows.push_back(
    TimeFrames(window, renderer, actor, vtkLightFieldActor::Geometry, frames, "geometry"));
  rows.back().GoalMs = 1000.0 / 30.0;
  rows.back().Goal = ">= 30 fps";
  actor->SetLightField(diffuseField.get());
  resetCamera();
  rows.push_back(
    TimeFrames(window, renderer, actor, vtkLightFieldActor::Progressive, frames, "diffuse-only"));
  rows.back().GoalMs = 1000.0 / 30.0;
  rows.back().Goal = ">= 30 fps";
  actor->SetLightField(mirrorField.get());
  resetCamera();
  rows.push_back(TimeFrames(
    window, renderer, actor, vtkLightFieldActor::Raytrace, std::min(frames, 5), "raytrace"));
  rows.back().GoalMs = 1000.0;
  rows.back().Goal = ">= 1 fps";
  resetCamera();
  rows.push_back(TimeFrames(
    window, renderer, actor, vtkLightFieldActor::Progressive, frames, "progressive-moving"));
  rows.back().GoalMs = 50.0;
  rows.back().Goal = ">= 20 fps";
  resetCamera();
  rows.push_back(
    TimeFrames(window, renderer, actor, vtkLightFieldActor::Coherent, frames, "coherent"));
  rows.back().GoalMs = 50.0;
  rows.back().Goal = ">= 20 fps";
  {
    // At rest: from the first frame of a new view to the frame showing its traced reflections.
    BenchRow rest;
    rest.Mode = "progressive-rest";
    resetCamera();
    actor->SetRenderMode(vtkLightFieldActor::Progressive);
    const int views = std::min(frames, 5);
    for (int v = 0; v < views; ++v)
    {
      renderer->GetActiveCamera()->Azimuth(0.5);
      renderer->ResetCameraClippingRange();
      const Clock::time_point start = Clock::now();
      window->Render();
      actor->WaitForTracedReflections(60.0);
      window->Render();
      WaitForGpu(window);
      rest.FrameMs += 1000.0 * SecondsSince(start);
      rest.UploadMs += 1000.0 * actor->GetLastUploadSeconds();
      rest.Coverage +=
        static_cast<double>(actor->GetLastScreenPixels()) / (static_cast<double>(width) * height);
      ++rest.Frames;
    }
    rest.FrameMs /= rest.Frames;
    rest.UploadMs /= rest.Frames;
    rest.Coverage /= rest.Frames;
    rest.SpecularMs = std::max(0.0, rest.FrameMs - rest.UploadMs); // the worker's trace dominates
    rest.GoalMs = 1000.0;
    rest.Goal = "converges <= 1 s";
    rows.push_back(rest);
  }

  // Stages: static diffuse = the diffuse-only row's draw (same shader and geometry, no screen
  // values); specular viewport = CPU pass + upload; composite = what a mode's draw adds to that.
  const double staticDiffuseMs = rows[1].DrawMs();
  std::cout << std::fixed << std::setprecision(2);
  std::cout << "\n"
            << width << "x" << height << ", " << fieldDirections
            << " directions; ms per frame (progressive-rest: ms to converge)\n";
  std::cout
    << "mode                 frames  frame ms     fps  specular ms  upload ms  draw+composite ms  "
       "(composite over static diffuse)  CPU-pass coverage  goal\n";
  for (const BenchRow& r : rows)
  {
    std::cout << std::left << std::setw(20) << r.Mode << std::right << std::setw(7) << r.Frames
              << std::setw(10) << r.FrameMs << std::setw(8) << 1000.0 / r.FrameMs << std::setw(13)
              << r.SpecularMs << std::setw(11) << r.UploadMs << std::setw(19) << r.DrawMs()
              << std::setw(33)
              << (r.Mode == "progressive-rest" ? 0.0 : r.DrawMs() - staticDiffuseMs)
              << std::setw(17) << 100.0 * r.Coverage << "%  " << r.Goal
              << (r.Met() ? " (met)" : " (NOT met)") << "\n";
  }
  if (cl.Has("--csv"))
  {
    std::ofstream csv(cl.Get("--csv"));
    csv << "mode,frames,frame_ms,fps,specular_ms,upload_ms,draw_composite_ms,static_diffuse_ms,"
           "composite_ms,"
           "cpu_pass_coverage,goal,met,width,height,directions\n";
    for (const BenchRow& r : rows)
    {
      csv << r.Mode << "," << r.Frames << "," << r.FrameMs << "," << 1000.0 / r.FrameMs << ","
          << r.SpecularMs << "," << r.UploadMs << "," << r.DrawMs() << "," << staticDiffuseMs << ","
          << (r.Mode == "progressive-rest" ? 0.0 : r.DrawMs() - staticDiffuseMs) << ","
          << r.Coverage << "," << r.Goal << "," << (r.Met() ? 1 : 0) << "," << width << ","
          << height << "," << fieldDirections << "\n";
    }
    if (!csv)
    {
      std::cerr << command << ": could not write '" << cl.Get("--csv") << "'\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--csv") << "\n";
  }
  if (cl.Has("--plot"))
  {
    ScatterChart chart;
    chart.Title = "Light field walkthrough, " + std::to_string(width) + "x" +
      std::to_string(height) + ", " + std::to_string(fieldDirections) +
      " directions\n(0 geometry, 1 diffuse-only, 2 raytrace, 3 progressive-moving, 4 coherent, "
      "5 progressive-rest: time to converge)";
    chart.XLabel = "mode";
    chart.YLabel = "milliseconds (log scale)";
    chart.LogY = true;
    chart.YFloor = 0.01;
    ChartSeries frame{ "frame", {}, {} }, specular{ "CPU screen pass", {}, {} },
      upload{ "texture upload", {}, {} }, draw{ "draw + composite", {}, {} };
    chart.Line.Name = "goal";
    for (std::size_t i = 0; i < rows.size(); ++i)
    {
      const double x = static_cast<double>(i);
      frame.X.push_back(x);
      frame.Y.push_back(rows[i].FrameMs);
      specular.X.push_back(x);
      specular.Y.push_back(rows[i].SpecularMs);
      upload.X.push_back(x);
      upload.Y.push_back(rows[i].UploadMs);
      draw.X.push_back(x);
      draw.Y.push_back(rows[i].DrawMs());
      chart.Line.X.push_back(x);
      chart.Line.Y.push_back(rows[i].GoalMs);
    }
    chart.Points = { frame, specular, upload, draw };
    if (!WriteScatterChartPng(chart, cl.Get("--plot"), error))
    {
      std::cerr << command << ": " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--plot") << "\n";
  }
  return 0;
}

} // namespace

int RunLightFieldView(const std::vector<std::string>& args)
{
  return View(args);
}

int RunLightFieldRender(const std::vector<std::string>& args)
{
  return Render(args);
}

int RunWalkthroughBenchmark(const std::vector<std::string>& args)
{
  return Bench(args);
}

} // namespace mesolight
