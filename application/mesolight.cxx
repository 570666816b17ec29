// mesolight: render, bake and benchmark relief surfaces from the command line.
//
//   mesolight render [options]                 the default scene (procedural brick wall) to PNG,
//                                              and an interactive window when a display exists
//   mesolight bake DEPTH_IMAGE --out RELIEF    a relief texture (normal RGB + depth A)
//   mesolight bench [options]                  time and error of relief vs the dense reference
#include "CommandLine.h"
#include "CommandTable.h"
#include "ConeBenchmark.h"
#include "ImageCompare.h"
#include "LightSetBenchmark.h"
#include "LightsCommand.h"
#include "TraceCommand.h"
#include "ReliefBenchmark.h"
#include "ReliefScene.h"
#include "ReliefSweep.h"
#include "VlfCommand.h"

#include "vtkConeMapFilter.h"
#include "vtkLightProbeToLatLong.h"
#include "core/EnvironmentMaps.h"
#include "vtkOIIOImageReader.h"
#include "vtkOIIOImageWriter.h"
#include "vtkReliefMapper.h"
#include "vtkReliefTextureFilter.h"

#include <vtkActor.h>
#include <vtkCallbackCommand.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkFloatArray.h>
#include <vtkImageData.h>
#include <vtkPointData.h>
#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkLogger.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>

#include <chrono>
#include <cstdio>
#include <iostream>
#include <sstream>
#include <string>
#include <sys/stat.h>
#include <vector>

namespace
{
using mesolight::CommandLine;
using mesolight::ReliefSceneOptions;

// Options shared by every command that builds the relief scene.
void AddSceneOptions(CommandLine& cl)
{
  cl.AddValue("--pattern", "NAME", "procedural map: Bricks, Stone, HemisphereTorus, Flat, SineWave", "Bricks");
  cl.AddValue("--depth-file", "IMAGE", "use this depth image (any OpenImageIO format) instead");
  cl.AddFlag("--height", "the depth image stores height (white = high) rather than depth");
  cl.AddValue("--resolution", "N", "texels per side of the procedural map", "512");
  cl.AddValue("--depth-scale", "K", "relief depth as a fraction of the wall width", "0.04");
  cl.AddValue("--method", "NAME",
    "texture, bump, parallax, parallax-limit, parallax-slope, iterative-parallax, binary, secant, "
    "linear (steep), pom, relief, interval, relaxed-cone, relaxed-cone-interval, cone, max-mipmap",
    "relief");
  cl.AddValue("--linear-steps", "N",
    "linear search steps (cone steps; iterations for iterative parallax and max-mipmap, "
    "which defaults to 128)",
    "10");
  cl.AddValue("--refinement-steps", "N", "binary / interval / secant refinement steps", "8");
  cl.AddFlag("--adaptive-steps", "fewer linear steps head-on, --linear-steps at grazing angles");
  cl.AddFlag("--level-of-detail", "march the height field at the pixel footprint's mipmap level");
  cl.AddFlag("--no-shadows", "no self-shadowing");
  cl.AddFlag("--no-silhouettes", "keep fragments whose hit leaves the texture");
  cl.AddFlag("--no-depth-write", "keep the mesh depth instead of the hit depth");
  cl.AddValue("--size", "WxH", "image size in pixels", "800x800");
  cl.AddValue("--view-angle", "DEG", "camera angle from the wall normal", "55");
  cl.AddValue("--azimuth", "DEG", "camera turn about the wall normal", "20");
  cl.AddValue("--lights", "N", "VTK lights: 0 = none, 1 = key light, 2 = key + fill", "2");
  cl.AddValue("--environment", "SPEC",
    "light also by an environment: procedural:sky, procedural:sun or a lat-long HDR file");
  cl.AddValue("--env-lights", "N", "median-cut lights of the environment", "128");
  cl.AddValue("--exposure", "X", "scale of the environment lighting", "1");
  cl.AddFlag("--tone-map", "Reinhard tone mapping of the environment-lit colour");
  cl.AddValue("--light-elevation", "DEG", "key light elevation above the wall", "35");
}

bool ReadSceneOptions(const CommandLine& cl, ReliefSceneOptions& o, std::string& error)
{
  o.Pattern = cl.Get("--pattern");
  o.DepthFile = cl.Get("--depth-file");
  o.DepthFileIsHeight = cl.Has("--height");
  o.Method = cl.Get("--method");
  o.SelfShadowing = !cl.Has("--no-shadows");
  o.Silhouettes = !cl.Has("--no-silhouettes");
  o.WriteDepth = !cl.Has("--no-depth-write");
  o.AdaptiveSteps = cl.Has("--adaptive-steps");
  o.Environment = cl.Get("--environment");
  o.ToneMapping = cl.Has("--tone-map");
  o.LevelOfDetail = cl.Has("--level-of-detail");
  if (!cl.GetInt("--resolution", 1, 16384, o.Resolution, error) ||
    !cl.GetDouble("--depth-scale", 0.0, 10.0, o.DepthScale, error) ||
    !cl.GetInt("--linear-steps", 1, 1024, o.LinearSteps, error) ||
    !cl.GetInt("--refinement-steps", 0, 64, o.RefinementSteps, error) ||
    !cl.GetDouble("--view-angle", 0.0, 89.9, o.ViewAngle, error) ||
    !cl.GetDouble("--azimuth", -360.0, 360.0, o.ViewAzimuth, error) ||
    !cl.GetInt("--lights", 0, 2, o.Lights, error) ||
    !cl.GetInt("--env-lights", 1, 4096, o.EnvironmentLights, error) ||
    !cl.GetDouble("--exposure", 0.0, 1e6, o.Exposure, error) ||
    !cl.GetDouble("--light-elevation", 0.0, 90.0, o.LightElevation, error))
  {
    return false;
  }
  if (!cl.Has("--linear-steps") && o.Method == "max-mipmap")
  {
    o.LinearSteps = 128; // an iteration budget for the pyramid traversal, not linear steps
  }
  const std::string size = cl.Get("--size");
  int w = 0, h = 0;
  char x = 0;
  std::istringstream in(size);
  if (!(in >> w >> x >> h) || x != 'x' || w < 16 || h < 16 || w > 8192 || h > 8192)
  {
    error = "option --size: '" + size + "' is not WxH with 16 <= W, H <= 8192";
    return false;
  }
  o.Width = w;
  o.Height = h;
  return true;
}

bool SameFile(const std::string& a, const std::string& b)
{
  struct stat sa, sb;
  if (stat(a.c_str(), &sa) != 0 || stat(b.c_str(), &sb) != 0)
  {
    return false;
  }
  return sa.st_dev == sb.st_dev && sa.st_ino == sb.st_ino;
}

// VTK reports a failing reader twice: the reader's own message, then the executive's dump of
// the pipeline request. A command-line user needs the first only, on one line.
class ConsoleOutputWindow : public vtkOutputWindow
{
public:
  static ConsoleOutputWindow* New();
  vtkTypeMacro(ConsoleOutputWindow, vtkOutputWindow);
  void DisplayErrorText(const char* text) override { this->DisplayText(text); }
  void DisplayWarningText(const char* text) override { this->DisplayText(text); }
  void DisplayGenericWarningText(const char* text) override { this->DisplayText(text); }
  void DisplayText(const char* text) override
  {
    const std::string message(text ? text : "");
    if (message.find("returned failure for request") != std::string::npos)
    {
      return;
    }
    // Drop VTK's "ERROR: In <source file>, line N" prefix line; keep what it says.
    const size_t firstLineEnd = message.find('\n');
    const bool hasLocation = message.compare(0, 10, "ERROR: In ") == 0 ||
      message.compare(0, 12, "Warning: In ") == 0;
    std::string body = hasLocation && firstLineEnd != std::string::npos
      ? message.substr(firstLineEnd + 1)
      : message;
    while (!body.empty() && (body.back() == '\n' || body.back() == ' '))
    {
      body.pop_back();
    }
    std::cerr << "mesolight: " << body << "\n";
  }
};
vtkStandardNewMacro(ConsoleOutputWindow);

// Interactive keys on top of the trackball camera; VTK's own keys keep working.
class ReliefInteractorStyle : public vtkInteractorStyleTrackballCamera
{
public:
  static ReliefInteractorStyle* New();
  vtkTypeMacro(ReliefInteractorStyle, vtkInteractorStyleTrackballCamera);

  vtkReliefMapper* Mapper = nullptr;
  vtkTextActor* Status = nullptr;

  void OnChar() override
  {
    vtkRenderWindowInteractor* rwi = this->Interactor;
    const char key = rwi->GetKeyCode();
    vtkReliefMapper* m = this->Mapper;
    switch (key)
    {
      case 'm':
        m->SetMethod((m->GetMethod() + 1) % vtkReliefMapper::NumberOfMethods);
        break;
      case '+':
      case '=':
        m->SetLinearSteps(m->GetLinearSteps() + 2);
        break;
      case '-':
        m->SetLinearSteps(m->GetLinearSteps() - 2);
        break;
      case ']':
        m->SetDepthScale(m->GetDepthScale() * 1.25);
        break;
      case '[':
        m->SetDepthScale(m->GetDepthScale() / 1.25);
        break;
      case 'x':
        m->SetSelfShadowing(!m->GetSelfShadowing());
        break;
      case 'o':
        m->SetSilhouettes(!m->GetSilhouettes());
        break;
      case 'z':
        m->SetWriteDepth(!m->GetWriteDepth());
        break;
      default:
        this->Superclass::OnChar();
        return;
    }
    this->UpdateStatus();
    rwi->Render();
  }

  void UpdateStatus()
  {
    std::ostringstream text;
    text << "method " << vtkReliefMapper::GetMethodName(this->Mapper->GetMethod()) << " [m]   steps "
         << this->Mapper->GetLinearSteps() << "+" << this->Mapper->GetRefinementSteps()
         << " [+/-]   depth " << this->Mapper->GetDepthScale() << " [ [ ] ]\nshadows "
         << (this->Mapper->GetSelfShadowing() ? "on" : "off") << " [x]   silhouettes "
         << (this->Mapper->GetSilhouettes() ? "on" : "off") << " [o]   depth write "
         << (this->Mapper->GetWriteDepth() ? "on" : "off") << " [z]   quit [q]";
    this->Status->SetInput(text.str().c_str());
  }
};
vtkStandardNewMacro(ReliefInteractorStyle);

int RunRender(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight render",
    "mesolight render [options]\n\nRenders the default relief scene (a procedural brick "
    "wall, two lights, an oblique camera)\nto a PNG, then opens an interactive window "
    "when a display is available.\nKeys: m method, +/- steps, [ ] depth, x shadows, o "
    "silhouettes, z depth write, q quit.\n");
  AddSceneOptions(cl);
  cl.AddValue("--out", "FILE", "PNG to write", "mesolight-render.png");
  cl.AddFlag("--offscreen", "only write the PNG, never open a window");
  std::string error;
  ReliefSceneOptions options;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (!ReadSceneOptions(cl, options, error))
  {
    return cl.UsageError(error);
  }
  if (!cl.Positional().empty())
  {
    std::cerr << "mesolight render: unexpected argument '" << cl.Positional()[0] << "'\n";
    return 2;
  }
  const std::string out = cl.Get("--out");
  if (!options.DepthFile.empty() && SameFile(out, options.DepthFile))
  {
    std::cerr << "mesolight render: --out would overwrite the input " << options.DepthFile << "\n";
    return 2;
  }

  mesolight::ReliefScene scene;
  if (!mesolight::BuildReliefScene(options, scene, error))
  {
    std::cerr << "mesolight render: " << error << "\n";
    return 1;
  }
  // One window for both the PNG and the interactive view: on screen when a display is there.
  const bool interactive = !cl.Has("--offscreen") && mesolight::HasDisplay();
  vtkSmartPointer<vtkRenderWindow> window;
  if (interactive)
  {
    window = vtkSmartPointer<vtkRenderWindow>::New();
    window->SetSize(options.Width, options.Height);
    window->SetMultiSamples(0);
    window->SetWindowName("mesolight");
    window->AddRenderer(scene.Renderer);
  }
  else
  {
    window = mesolight::MakeOffscreenWindow(options, scene.Renderer);
  }
  const mesolight::Frame frame = mesolight::CaptureFrame(window);
  if (!mesolight::WritePng(frame, out.c_str()))
  {
    std::cerr << "mesolight render: could not write " << out << "\n";
    return 1;
  }
  std::cout << "wrote " << out << " (" << options.Width << "x" << options.Height << ", method "
            << options.Method << ")" << std::endl;
  if (!interactive)
  {
    return 0;
  }
  vtkNew<vtkTextActor> status;
  status->GetTextProperty()->SetFontSize(14);
  status->GetTextProperty()->SetColor(0.9, 0.9, 0.9);
  status->SetPosition(8, 8);
  scene.Renderer->AddViewProp(status);
  vtkNew<vtkRenderWindowInteractor> interactor;
  vtkNew<ReliefInteractorStyle> style;
  style->Mapper = scene.Mapper;
  style->Status = status;
  style->UpdateStatus();
  interactor->SetInteractorStyle(style);
  interactor->SetRenderWindow(window);
  window->Render();
  interactor->Start();
  return 0;
}

int RunBake(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bake",
    "mesolight bake DEPTH_IMAGE --out RELIEF_IMAGE [options]\n\nBakes a relief "
    "texture: Sobel normals (packed (n+1)/2) in RGB, depth in A\n(0 = top, 1 = "
    "deepest).\n");
  cl.AddValue("--out", "RELIEF_IMAGE", "relief texture to write (.exr/.tif float, .png 8/16-bit)");
  cl.AddValue("--depth-scale", "K", "relief depth as a fraction of the texture width", "0.04");
  cl.AddValue("--border", "MODE", "clamp or wrap (tiling maps)", "clamp");
  cl.AddFlag("--height", "the input stores height (white = high) rather than depth");
  cl.AddFlag("--normalize", "stretch the input's value range to [0, 1]");
  cl.AddValue("--bits", "N", "8 or 16 bits per channel for PNG/TIFF output", "8");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (cl.Positional().size() != 1 || !cl.Has("--out"))
  {
    std::cerr << "mesolight bake: usage: mesolight bake DEPTH_IMAGE --out RELIEF_IMAGE\n";
    return 2;
  }
  const std::string in = cl.Positional()[0];
  const std::string out = cl.Get("--out");
  double depthScale = 0.04;
  int bits = 8;
  if (!cl.GetDouble("--depth-scale", 0.0, 100.0, depthScale, error) ||
    !cl.GetInt("--bits", 8, 16, bits, error))
  {
    return cl.UsageError(error);
  }
  if (bits != 8 && bits != 16)
  {
    std::cerr << "mesolight bake: --bits must be 8 or 16\n";
    return 2;
  }
  const std::string border = cl.Get("--border");
  if (border != "clamp" && border != "wrap")
  {
    std::cerr << "mesolight bake: --border must be clamp or wrap\n";
    return 2;
  }
  if (out == in || SameFile(out, in))
  {
    std::cerr << "mesolight bake: --out must differ from the input\n";
    return 2;
  }

  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(in.c_str());
  vtkNew<vtkReliefTextureFilter> bake;
  bake->SetInputConnection(reader->GetOutputPort());
  bake->SetDepthScale(depthScale);
  bake->SetInvertInput(cl.Has("--height"));
  bake->SetNormalizeRange(cl.Has("--normalize"));
  if (border == "wrap")
  {
    bake->SetBorderModeToWrap();
  }
  else
  {
    bake->SetBorderModeToClamp();
  }
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputConnection(bake->GetOutputPort());
  writer->SetFileName(out.c_str());
  writer->SetBitDepth(bits);
  // Errors from any stage are reported by VTK on stderr; the exit code tells the caller.
  bake->Update();
  if (bake->GetOutput()->GetNumberOfPoints() == 0 || reader->GetErrorCode() != 0)
  {
    std::cerr << "mesolight bake: could not bake " << in << "\n";
    return 1;
  }
  if (!writer->Write())
  {
    std::cerr << "mesolight bake: could not write " << out << "\n";
    return 1;
  }
  int dims[3];
  bake->GetOutput()->GetDimensions(dims);
  std::cout << "wrote " << out << " (" << dims[0] << "x" << dims[1] << " relief texture, depth scale "
            << depthScale << ")\n";
  return 0;
}

int RunCone(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight cone",
    "mesolight cone DEPTH_IMAGE --out FILE.exr [options]\n\nBakes a cone-packed relief "
    "texture for cone stepping: R,G normal x, y packed (n+1)/2,\nB cone ratio "
    "(width / height), A depth (0 top .. 1 deepest).\n");
  cl.AddValue("--out", "FILE", "cone map to write (.exr: float RGBA = normal x, y; cone ratio; depth)");
  cl.AddValue("--type", "TYPE", "relaxed or conservative", "relaxed");
  cl.AddValue("--depth-scale", "K", "relief depth as a fraction of the texture width", "0.04");
  cl.AddValue("--border", "MODE", "clamp or wrap (tiling maps)", "clamp");
  cl.AddFlag("--height", "the input stores height (white = high) rather than depth");
  cl.AddFlag("--normalize", "stretch the input's value range to [0, 1]");
  cl.AddFlag("--seed8", "the relief thesis' 8-bit packing (cone as c / (1 + c)) instead of float");
  std::string error;
  double depthScale = 0.04;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (!cl.GetDouble("--depth-scale", 0.0, 100.0, depthScale, error))
  {
    return cl.UsageError(error);
  }
  const std::string type = cl.Get("--type");
  const std::string border = cl.Get("--border");
  if (cl.Positional().size() != 1 || !cl.Has("--out") ||
    (type != "relaxed" && type != "conservative") || (border != "clamp" && border != "wrap"))
  {
    std::cerr << "mesolight cone: usage: mesolight cone DEPTH_IMAGE --out FILE.exr "
                 "[--type relaxed|conservative] [--border clamp|wrap]\n";
    return 2;
  }
  const std::string in = cl.Positional()[0];
  const std::string out = cl.Get("--out");
  if (out == in || SameFile(out, in))
  {
    std::cerr << "mesolight cone: --out must differ from the input\n";
    return 2;
  }
  vtkNew<vtkOIIOImageReader> reader;
  reader->SetFileName(in.c_str());
  vtkNew<vtkConeMapFilter> cones;
  cones->SetInputConnection(reader->GetOutputPort());
  cones->SetDepthScale(depthScale);
  cones->SetInvertInput(cl.Has("--height"));
  cones->SetNormalizeRange(cl.Has("--normalize"));
  cones->SetBorderMode(border == "wrap" ? 1 : 0);
  cones->SetConeType(type == "conservative" ? vtkConeMapFilter::CONSERVATIVE : vtkConeMapFilter::RELAXED);
  cones->SetPacking(cl.Has("--seed8") ? vtkConeMapFilter::SEED_8BIT : vtkConeMapFilter::FLOAT);
  const auto start = std::chrono::steady_clock::now();
  cones->Update();
  const double seconds =
    std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  if (cones->GetOutput()->GetNumberOfPoints() == 0)
  {
    std::cerr << "mesolight cone: could not make a cone map of " << in << "\n";
    return 1;
  }
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputConnection(cones->GetOutputPort());
  writer->SetFileName(out.c_str());
  if (!writer->Write())
  {
    std::cerr << "mesolight cone: could not write " << out << "\n";
    return 1;
  }
  int dims[3];
  cones->GetOutput()->GetDimensions(dims);
  std::cout << "wrote " << out << " (" << dims[0] << "x" << dims[1] << " " << type
            << " cone map, " << seconds << " s)" << std::endl;
  return 0;
}

mesolight::RgbImage ToRgb(vtkImageData* image)
{
  int dims[3];
  image->GetDimensions(dims);
  mesolight::RgbImage rgb(dims[0], dims[1]);
  vtkDataArray* values = image->GetPointData()->GetScalars();
  for (vtkIdType p = 0; p < static_cast<vtkIdType>(dims[0]) * dims[1]; ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      rgb.Rgb[3 * p + c] = static_cast<float>(values->GetComponent(p, std::min(c, values->GetNumberOfComponents() - 1)));
    }
  }
  return rgb;
}

int RunProbe(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight probe",
    "mesolight probe PROBE_IMAGE --out FILE.exr [options]\n\nConverts a light probe "
    "picture (angular map or mirror ball) into a lat-long environment\n(+Z up, v = 0 "
    "at the top row; docs/environment-maps.md).\n");
  cl.AddValue("--out", "FILE.exr", "lat-long environment to write");
  cl.AddValue("--type", "TYPE", "angular (Debevec light probe) or mirror-ball", "angular");
  cl.AddValue("--width", "W", "output width (height W/2); 0 = twice the probe size", "0");
  cl.AddValue("--forward", "X,Y,Z", "direction the probe camera looked in", "1,0,0");
  cl.AddValue("--up", "X,Y,Z", "up direction of the probe picture", "0,0,1");
  cl.AddValue("--merge", "PROBE_B", "second view of the same probe (the relief thesis' two-view merge)");
  cl.AddValue("--merge-forward", "X,Y,Z", "direction the second view looked in", "0,1,0");
  cl.AddValue("--mask", "IMAGE", "lat-long mask C: result = A C + B (1 - C)");
  std::string error;
  int width = 0;
  double forward[3], up[3], forwardB[3];
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (!cl.GetInt("--width", 0, 32768, width, error))
  {
    return cl.UsageError(error);
  }
  const std::string type = cl.Get("--type");
  if (cl.Positional().size() != 1 || !cl.Has("--out") || (type != "angular" && type != "mirror-ball") ||
    !cl.GetDoubleVector("--forward", 3, forward) || !cl.GetDoubleVector("--up", 3, up) ||
    !cl.GetDoubleVector("--merge-forward", 3, forwardB) || (cl.Has("--merge") != cl.Has("--mask")))
  {
    std::cerr << "mesolight probe: usage: mesolight probe PROBE_IMAGE --out FILE.exr "
                 "[--type angular|mirror-ball] [--forward x,y,z] [--up x,y,z] "
                 "[--merge PROBE_B --mask MASK]\n";
    return 2;
  }
  const std::string out = cl.Get("--out");
  for (const std::string& in : { cl.Positional()[0], cl.Get("--merge"), cl.Get("--mask") })
  {
    if (!in.empty() && (in == out || SameFile(in, out)))
    {
      std::cerr << "mesolight probe: --out must differ from the inputs\n";
      return 2;
    }
  }
  auto convert = [&](const std::string& file, const double f[3]) -> vtkSmartPointer<vtkImageData> {
    vtkNew<vtkOIIOImageReader> reader;
    reader->SetFileName(file.c_str());
    vtkNew<vtkLightProbeToLatLong> toLatLong;
    toLatLong->SetInputConnection(reader->GetOutputPort());
    toLatLong->SetProbeType(type == "mirror-ball" ? vtkLightProbeToLatLong::MIRROR_BALL
                                                  : vtkLightProbeToLatLong::ANGULAR_MAP);
    toLatLong->SetOutputWidth(width);
    toLatLong->SetForward(const_cast<double*>(f));
    toLatLong->SetUp(up);
    toLatLong->Update();
    if (toLatLong->GetOutput()->GetNumberOfPoints() == 0)
    {
      return nullptr;
    }
    auto result = vtkSmartPointer<vtkImageData>::New();
    result->DeepCopy(toLatLong->GetOutput());
    return result;
  };
  vtkSmartPointer<vtkImageData> map = convert(cl.Positional()[0], forward);
  if (!map)
  {
    std::cerr << "mesolight probe: could not convert " << cl.Positional()[0] << "\n";
    return 1;
  }
  if (cl.Has("--merge"))
  {
    vtkSmartPointer<vtkImageData> second = convert(cl.Get("--merge"), forwardB);
    vtkNew<vtkOIIOImageReader> maskReader;
    maskReader->SetFileName(cl.Get("--mask").c_str());
    maskReader->Update();
    int dims[3], maskDims[3];
    map->GetDimensions(dims);
    maskReader->GetOutput()->GetDimensions(maskDims);
    if (!second || maskDims[0] != dims[0] || maskDims[1] != dims[1])
    {
      std::cerr << "mesolight probe: the second view and the mask must convert to / be "
                << dims[0] << "x" << dims[1] << "\n";
      return 1;
    }
    vtkDataArray* maskValues = maskReader->GetOutput()->GetPointData()->GetScalars();
    const double maskScale = maskValues->GetDataType() == VTK_UNSIGNED_CHAR ? 1.0 / 255.0 : 1.0;
    std::vector<float> mask(static_cast<size_t>(dims[0]) * dims[1]);
    for (size_t p = 0; p < mask.size(); ++p)
    {
      mask[p] = static_cast<float>(maskValues->GetComponent(static_cast<vtkIdType>(p), 0) * maskScale);
    }
    const mesolight::RgbImage merged = mesolight::MergeWithMask(ToRgb(map), ToRgb(second), mask);
    std::copy(merged.Rgb.begin(), merged.Rgb.end(),
      vtkFloatArray::SafeDownCast(map->GetPointData()->GetScalars())->GetPointer(0));
  }
  vtkNew<vtkOIIOImageWriter> writer;
  writer->SetInputData(map);
  writer->SetFileName(out.c_str());
  if (!writer->Write())
  {
    std::cerr << "mesolight probe: could not write " << out << "\n";
    return 1;
  }
  int dims[3];
  map->GetDimensions(dims);
  std::cout << "wrote " << out << " (" << dims[0] << "x" << dims[1] << " lat-long)" << std::endl;
  return 0;
}

int RunBenchDefault(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench",
    "mesolight bench [options]\n\nMeasures ms/frame of a stock textured plane, relief "
    "mapping, parallax occlusion mapping\nand the dense displaced mesh, and the error "
    "of each against the dense mesh.\n");
  AddSceneOptions(cl);
  cl.AddValue("--sizes", "N,N,..", "relief map resolutions to measure", "512,1024");
  cl.AddValue("--frames", "N", "timed frames per configuration (median reported)", "20");
  cl.AddValue("--csv", "FILE", "also write the table as CSV");
  std::string error;
  ReliefSceneOptions options;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  if (!ReadSceneOptions(cl, options, error))
  {
    return cl.UsageError(error);
  }
  mesolight::BenchmarkSettings settings;
  settings.Scene = options;
  if (!cl.GetInt("--frames", 1, 10000, settings.Frames, error))
  {
    return cl.UsageError(error);
  }
  if (!cl.GetIntList("--sizes", 2, 8192, settings.Resolutions, error))
  {
    return cl.UsageError(error);
  }
  settings.CsvFile = cl.Get("--csv");
  return mesolight::RunReliefBenchmark(settings, std::cout) ? 0 : 1;
}
const std::vector<mesolight::Command>& Commands();

// `mesolight help [COMMAND...]`: the usage, or a command's options.
int RunHelp(const std::vector<std::string>& args);

void PrintUsage(std::ostream& os)
{
  os << "mesolight - relief surfaces for VTK\n\nUsage:\n";
  mesolight::PrintCommandUsage(os, "mesolight", Commands());
  os << "\nRun 'mesolight COMMAND --help' for the options of a command.\n";
}

// Every command: name, usage, summary (the lines of `mesolight --help`), handler.
const std::vector<mesolight::Command>& Commands()
{
  using namespace mesolight;
  static const std::vector<Command> commands = {
    { "render", "[options]", "render the default relief scene", RunRender, {} },
    { "bake", "DEPTH_IMAGE --out RELIEF_IMAGE [options]", "bake a relief texture from a depth image",
      RunBake, {} },
    { "cone", "DEPTH_IMAGE --out FILE.exr [options]", "bake a cone-packed relief texture", RunCone,
      {} },
    { "probe", "PROBE_IMAGE --out FILE.exr",
      "light probe (angular map, mirror ball, two-view\nmerge) -> lat-long environment", RunProbe,
      {} },
    { "lights", "ENV_IMAGE --count N --out lights.csv", "median-cut lights of an HDR environment",
      RunLightsCommand, {} },
    { "trace", "[--scene spheres|ring|cornell] [options]",
      "Embree ray tracer (textured material channels,\nglossy reflection, adaptive, progressive) or "
      "the\npath-traced Cornell box",
      RunTraceCommand, {} },
    { "vlf", "", "", nullptr,
      {
        { "propagate", "[SCENE.obj] --out FIELD [options]",
          "propagate a virtual light field (built-in\nCornell box without SCENE)", RunVlfPropagate,
          {} },
        { "render", "FIELD --out IMAGE.png", "render a light field's diffuse totals", RunVlfRender,
          {} },
      } },
    { "bench", "", "", nullptr,
      {
        { "", "[options]", "time and error: relief vs the dense mesh", RunBenchDefault, {} },
        { "relief", "[options]",
          "every method x steps x view angle x map:\ntime vs exact hit error, CSV and plots",
          static_cast<int (*)(const std::vector<std::string>&)>(RunReliefSweep), {} },
        { "cones", "[options]", "cone-map generation time, oracle speed-up", RunConeBenchmark, {} },
        { "lights", "[options]",
          "light-set irradiance error vs exact\nintegration and SH9; median-cut time",
          RunLightsBenchmark, {} },
        { "ibl", "[options]",
          "relief lit by 32..1024 median-cut lights: time,\neach skip, error vs Monte Carlo",
          RunLightSetBenchmark, {} },
        { "trace", "[options]", "rays/s (coherent vs incoherent), path samples/s",
          RunTraceBenchmark, {} },
        { "vlf", "[options]", "light field time, memory and accuracy sweep", RunVlfBenchmark, {} },
      } },
    { "help", "[COMMAND]", "this text, or one command's options", RunHelp, {} },
  };
  return commands;
}

int RunHelp(const std::vector<std::string>& args)
{
  if (args.empty())
  {
    PrintUsage(std::cout);
    return 0;
  }
  std::vector<std::string> withHelp = args;
  withHelp.emplace_back("--help");
  return mesolight::DispatchCommand("mesolight", Commands(), withHelp);
}
} // namespace

int main(int argc, char* argv[])
{
  vtkNew<ConsoleOutputWindow> console;
  vtkOutputWindow::SetInstance(console);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // messages go through the console window
  const std::vector<std::string> args(argv + 1, argv + argc);
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
  {
    PrintUsage(std::cout);
    return args.empty() ? 2 : 0;
  }
  return mesolight::DispatchCommand("mesolight", Commands(), args);
}
