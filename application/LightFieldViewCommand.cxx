// SPDX-License-Identifier: BSD-3-Clause
#include "LightFieldViewCommand.h"

#include "ChartPlot.h"
#include "CommandLine.h"
#include "CornellRegions.h" // WriteLinearImage
#include "LightFieldCamera.h"
#include "LightFieldObjectOptions.h"
#include "LightFieldReliefs.h"
#include "ObjectDragStyle.h"
#include "OutputFile.h"
#include "Timing.h"
#include "WalkthroughExr.h"
#include "vtkMessageCollector.h"

#include "vtkLightFieldActor.h"
#include "vtkLightFieldActorCore.h"
#include "vtkLightFieldObjectMapper.h"

#include "ObjScene.h"
#include "ObjectGatherer.h"
#include "ObjectMesh.h"
#include "ObjectShadows.h"

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
#include <vtkImageShrink3D.h>
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
  AddReliefOptions(cl);
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
  if (!cl.GetDouble("--exposure", 0.0, 1e9, exposure, error) || !ReadViewAngle(cl, angle, error) ||
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
  if (!ReadLightFieldCamera(
        cl, *vtkLightFieldActorCore::GetLightField(actor), eye, focal, up, error))
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

// The window's frame as a PNG; with supersampling s > 1 each s x s block of the window's pixels
// averaged into one (in its display codes: the PNG is the preview, the EXR the measurement).
bool WritePng(vtkRenderWindow* window, const std::string& out, int supersampling = 1)
{
  vtkNew<vtkWindowToImageFilter> grab;
  grab->SetInput(window);
  grab->SetInputBufferTypeToRGB();
  grab->ShouldRerenderOff();
  grab->ReadFrontBufferOn();
  grab->Update();
  vtkNew<vtkImageShrink3D> shrink;
  shrink->SetInputConnection(grab->GetOutputPort());
  shrink->SetShrinkFactors(supersampling, supersampling, 1);
  shrink->AveragingOn();
  vtkNew<vtkPNGWriter> writer;
  writer->SetInputConnection(supersampling > 1 ? shrink->GetOutputPort() : grab->GetOutputPort());
  writer->SetFileName(out.c_str());
  writer->Write();
  return writer->GetErrorCode() == 0;
}

// The light field actor of FIELD (the command's one positional argument) in a renderer and a
// window set up by the view options. The actor's messages are the command's own: its errors on
// stderr, its warnings (an object outside the field or through a wall, no mirrors) as notes,
// each once, when they happen.
struct WalkthroughWindow
{
  vtkNew<vtkLightFieldActor> Actor;
  vtkNew<MessageCollector> Messages;
  vtkNew<vtkRenderer> Renderer;
  vtkNew<vtkRenderWindow> Window;
  WalkthroughReliefs Reliefs; // --relief
};

// 0 when the window is ready, else the command's exit code (the message is printed). The window
// is `supersampling` times --size per side (vlf render --supersampling).
int OpenWalkthrough(const CommandLine& cl, const char* command, bool offscreen,
  WalkthroughWindow& walkthrough, int supersampling = 1)
{
  walkthrough.Messages->OnMessage = [command](bool error, const std::string& text)
  {
    if (error)
    {
      std::cerr << command << ": " << text << "\n";
    }
    else
    {
      std::cout << "note: " << text << "\n";
    }
  };
  walkthrough.Messages->Watch(walkthrough.Actor);
  if (!walkthrough.Actor->LoadLightField(cl.Positional()[0]))
  {
    return 1; // the actor's error is printed
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
  walkthrough.Window->SetSize(supersampling * width, supersampling * height);
  return SetUpWalkthroughReliefs(
    cl, command, walkthrough.Actor, walkthrough.Renderer, walkthrough.Window, walkthrough.Reliefs);
}

// --object and --object-relief: the object's relief charts join the reliefs' layer (lit by the
// field's emitters only, the walkthrough's display).
int SetUpObjectAndRelief(
  const CommandLine& cl, const char* command, WalkthroughWindow& walkthrough, MovableObject& object)
{
  if (const int status = SetUpObject(cl, command, walkthrough.Actor, walkthrough.Renderer, object))
  {
    return status;
  }
  if (!object.Active || !cl.Has("--object-relief"))
  {
    return 0;
  }
  vtkRenderer* layer =
    ReliefLayer(walkthrough.Actor, walkthrough.Renderer, walkthrough.Window, walkthrough.Reliefs);
  return SetUpObjectRelief(cl, command, walkthrough.Actor, layer, object.Actor, object.Relief);
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
  cl.AddValue("--exr", "FILE.exr",
    "also write the frame's linear radiance (recovered by exposure bracketing: independent of "
    "--exposure and --tone-map)");
  cl.AddValue("--supersampling", "S",
    "draw S x S pixels for each pixel of --size and write their mean (a box filter): the pixel "
    "average a path tracer's paths per pixel cover",
    "1");
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
  int supersampling = 1;
  {
    std::string error;
    if (!cl.GetInt("--supersampling", 1, 8, supersampling, error))
    {
      std::cerr << command << ": " << error << "\n";
      return 2;
    }
  }
  const std::string out = cl.Get("--out");
  std::vector<std::string> inputs = ReliefInputs(cl);
  inputs.push_back(cl.Positional()[0]);
  if (cl.Has("--object") && cl.Get("--object") != "sphere" && cl.Get("--object") != "cube")
  {
    inputs.push_back(cl.Get("--object"));
  }
  if (cl.Has("--object-relief"))
  {
    inputs.push_back(cl.Get("--object-relief"));
  }
  const std::string problem = CheckOutputFile(out, inputs);
  if (!problem.empty())
  {
    std::cerr << command << ": --out: " << problem << "\n";
    return 2;
  }
  if (cl.Has("--exr"))
  {
    std::vector<std::string> others = inputs;
    others.push_back(out);
    const std::string exrProblem = CheckOutputFile(cl.Get("--exr"), others);
    if (!exrProblem.empty())
    {
      std::cerr << command << ": --exr: " << exrProblem << "\n";
      return 2;
    }
  }
  if (const std::string format = CheckImageOutputNames(cl); !format.empty())
  {
    return cl.UsageError(format);
  }
  if (vlf::FileExists(out) && !cl.Has("--force"))
  {
    std::cerr << command << ": '" << out << "' exists; add --force to replace it\n";
    return 1;
  }
  WalkthroughWindow walkthrough;
  if (const int status = OpenWalkthrough(cl, command, true, walkthrough, supersampling))
  {
    return status;
  }
  MovableObject object;
  if (const int status = SetUpObjectAndRelief(cl, command, walkthrough, object))
  {
    return status;
  }
  vtkLightFieldActor* actor = walkthrough.Actor;
  vtkRenderWindow* window = walkthrough.Window;
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
  if (!WritePng(window, out, supersampling))
  {
    std::cerr << command << ": could not write '" << out << "'\n";
    return 1;
  }
  std::cout << "wrote " << out << " (" << window->GetSize()[0] / supersampling << "x"
            << window->GetSize()[1] / supersampling;
  if (supersampling > 1)
  {
    std::cout << ", the mean of " << supersampling << "x" << supersampling << " drawn pixels each";
  }
  std::cout << ", mode " << cl.Get("--mode") << ", " << seconds << " s, "
            << actor->GetLastScreenPixels() << " pixels from the CPU pass)\n";
  if (cl.Has("--exr"))
  {
    RgbImage radiance;
    std::string error;
    if (!CaptureWalkthroughRadiance(actor, window, radiance, error, supersampling) ||
      !WriteLinearImage(radiance, cl.Get("--exr"), error))
    {
      std::cerr << command << ": " << error << "\n";
      return 1;
    }
    std::cout << "wrote " << cl.Get("--exr")
              << (actor->GetRenderMode() == vtkLightFieldActor::Geometry
                     ? " (linear colour: the geometry mode draws materials under VTK lights, not "
                       "radiance)\n"
                     : " (linear radiance)\n");
  }
  if (object.Active)
  {
    const mesolight::vlf::ShadedObject* shaded = vtkLightFieldActorCore::GetShadedObject(actor);
    std::cout << "object: " << cl.Get("--object") << ", shading " << cl.Get("--shading")
              << ", gather " << 1000.0 * actor->GetLastGatherSeconds() << " ms, "
              << (shaded ? shaded->Mesh.Positions.size() : 0) << " points";
    if (actor->GetObjectIrradianceVolume() > 0)
    {
      std::cout << " from an irradiance volume of " << actor->GetObjectIrradianceVolume()
                << " points a side";
    }
    else if (shaded)
    {
      std::cout << " over " << shaded->DirectionsUsed << " directions";
      if (const std::size_t facing = shaded->SelfFacingPoints)
      {
        // A concave object: these points' directions were tested against the object itself.
        std::cout << " (" << facing << " face the object itself)";
      }
    }
    std::cout << ", shadows " << cl.Get("--shadows");
    if (const mesolight::vlf::ObjectShadows* shadows =
          vtkLightFieldActorCore::GetObjectShadows(actor))
    {
      std::cout << " (" << shadows->Maps().size() << " maps, "
                << 1000.0 * actor->GetLastShadowSeconds() << " ms)";
    }
    else if (!actor->GetShadowProblem().empty())
    {
      std::cout << " (none: " << actor->GetShadowProblem() << ")";
    }
    std::cout << "\n";
    if (object.Relief.Active)
    {
      vtkLightFieldObjectReliefProbes* probes = object.Relief.Probes;
      std::cout << "object relief: " << cl.Get("--object-relief") << ", "
                << probes->GetNumberOfCharts() << " charts, " << probes->GetNumberOfProbes()
                << " probes (" << probes->GetProbesPerSide() << " a side), gathered in "
                << 1000.0 * probes->GetLastSeconds() << " ms\n";
    }
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

// A left-button drag from the object's projected centre by (dx, dy) pixels, as the mouse sends it.
void DragObject(vtkRenderWindowInteractor* interactor, vtkRenderer* renderer, vtkActor* object,
  double dx, double dy)
{
  const double* centre = object->GetCenter();
  renderer->SetWorldPoint(centre[0], centre[1], centre[2], 1.0);
  renderer->WorldToDisplay();
  const double* display = renderer->GetDisplayPoint();
  const int x = static_cast<int>(display[0] + 0.5);
  const int y = static_cast<int>(display[1] + 0.5);
  interactor->SetEventInformation(x, y);
  interactor->InvokeEvent(vtkCommand::LeftButtonPressEvent, nullptr);
  interactor->SetEventInformation(x + static_cast<int>(dx), y + static_cast<int>(dy));
  interactor->InvokeEvent(vtkCommand::MouseMoveEvent, nullptr);
  interactor->InvokeEvent(vtkCommand::LeftButtonReleaseEvent, nullptr);
}

int View(const std::vector<std::string>& args)
{
  const char* command = "mesolight vlf view";
  CommandLine cl(command,
    "mesolight vlf view FIELD [options]\n\n"
    "Walks through a light field in a VTK window (vtkLightFieldActor). Mouse: rotate "
    "(left), pan\n(middle), zoom (right/wheel). Keys: 1-4 or m mode (geometry, raytrace, "
    "progressive,\ncoherent), +/- exposure, t tone map (clamp/Reinhard), [ ] reflection "
    "depth, q quit.\nWith --object: drag it with the left button (in the view plane); j/l move "
    "it along x, k/i along y,\nu/o along z (a twentieth of the field per press), y turns it 15 "
    "degrees about its y axis.\n");
  AddViewOptions(cl);
  AddObjectOptions(cl);
  cl.AddValue("--path", "FILE.csv",
    "with --object and --frames: the object's placement per frame, one 'tx,ty,tz[,rx,ry,rz[,s]]' "
    "a line (repeated when shorter; the camera stays still)");
  cl.AddValue("--record-path", "FILE.csv",
    "with --object: write the object's placement at every rendered frame (for --path)");
  cl.AppliesOnlyWith("--path", { "--object" });
  cl.AppliesOnlyWith("--record-path", { "--object" });
  cl.AddValue("--frames", "N",
    "render N frames (turning the camera 2 degrees each) and exit: a non-interactive check", "0");
  cl.AddFlag("--offscreen", "no window (with --frames)");
  cl.AddValue("--keys", "KEYS",
    "with --frames: press these keys, one before each frame (a check of the key bindings)");
  cl.AddValue("--drag", "DX,DY",
    "with --object and --frames: drag the object with the left button from its centre by DX,DY "
    "pixels after the first frame (a check of the mouse binding)");
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
  // Without frames the window waits for the user: with no window (--offscreen) it would wait
  // for ever, and keys would never be pressed.
  for (const char* option : { "--offscreen", "--keys" })
  {
    if (cl.Has(option) && frames < 1)
    {
      std::cerr << command << ": " << option << " needs --frames N (N >= 1)\n";
      return 2;
    }
  }
  std::vector<double> drag;
  if (cl.Has("--drag") &&
    (!cl.GetDoubleList("--drag", -1e4, 1e4, drag, error) || drag.size() != 2 ||
      !cl.Has("--object") || frames < 2))
  {
    std::cerr << command << ": --drag: "
              << (error.empty() ? "give DX,DY with --object and --frames 2 or more" : error)
              << "\n";
    return 2;
  }
  WalkthroughWindow walkthrough;
  if (const int status = OpenWalkthrough(cl, command, false, walkthrough))
  {
    return status;
  }
  MovableObject object;
  if (const int status = SetUpObjectAndRelief(cl, command, walkthrough, object))
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
    if (!problem.empty())
    {
      std::cerr << command << ": --record-path: " << problem << "\n";
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
  // On the top layer: the reliefs' renderer draws over the walkthrough's.
  (walkthrough.Reliefs.Followed ? walkthrough.Reliefs.Renderer.Get() : renderer)->AddViewProp(text);
  ViewerState state;
  state.Actor = actor;
  state.Window = window;
  state.Text = text;
  state.Object = &object;
  state.Record = record.is_open() ? &record : nullptr;
  vtkNew<vtkRenderWindowInteractor> interactor;
  interactor->SetRenderWindow(window);
  vtkNew<ObjectDragStyle> style; // left drag on the object moves it; elsewhere the camera
  style->SetObject(object.Active ? static_cast<vtkActor*>(object.Actor) : nullptr);
  for (vtkActor* chart : object.Relief.Actors)
  {
    style->AddStandIn(chart, walkthrough.Reliefs.Renderer);
  }
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
      if (f == 1 && !drag.empty())
      {
        DragObject(interactor, renderer, object.Actor, drag[0], drag[1]);
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
      const double* position = object.Actor->GetPosition();
      std::ostringstream line;
      line << std::fixed << std::setprecision(2) << "object at " << position[0] << ","
           << position[1] << "," << position[2] << "; moved in " << updates << " of " << frames
           << " frames; per move: object update " << 1000.0 * update / std::max(1, updates)
           << " ms, of which gathering " << 1000.0 * gather / std::max(1, updates) << " ms ("
           << (vtkLightFieldActorCore::GetShadedObject(actor)
                  ? vtkLightFieldActorCore::GetShadedObject(actor)->Mesh.Positions.size()
                  : 0)
           << " points); frames without a move " << 1000.0 * still / std::max(1, frames - updates)
           << " ms\n";
      if (object.Relief.Active)
      {
        const ObjectRelief& relief = object.Relief;
        line << "relief probes: " << relief.Probes->GetNumberOfProbes() << " in "
             << relief.Probes->GetNumberOfCharts() << " charts, regathered in " << relief.Moves
             << " frames, per move " << 1000.0 * relief.ProbeSeconds / std::max(1, relief.Moves)
             << " ms for " << static_cast<double>(relief.GatheredProbes) / std::max(1, relief.Moves)
             << " probes\n";
      }
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

} // namespace

int RunLightFieldView(const std::vector<std::string>& args)
{
  return View(args);
}

int RunLightFieldRender(const std::vector<std::string>& args)
{
  return Render(args);
}

} // namespace mesolight
