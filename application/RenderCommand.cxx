// SPDX-License-Identifier: BSD-3-Clause
#include "RenderCommand.h"

#include "CommandLine.h"
#include "GeometryImageScene.h"
#include "ImageCommands.h"
#include "ImageCompare.h"
#include "OutputFile.h"
#include "ReliefBenchmark.h"
#include "ReliefScene.h"
#include "vtkProceduralReliefSource.h"
#include "vtkReliefMapper.h"
#include "vtkReliefProperty.h"

#include <vtkInteractorStyleTrackballCamera.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkPolyData.h>
#include <vtkRenderWindow.h>
#include <vtkRenderWindowInteractor.h>
#include <vtkRenderer.h>
#include <vtkTextActor.h>
#include <vtkTextProperty.h>
#include <vtksys/SystemTools.hxx>

#include <iostream>
#include <sstream>
#include <string>
#include <vector>

namespace mesolight
{
namespace
{

// Options shared by every command that builds the relief scene.
void AddSceneOptions(CommandLine& cl)
{
  cl.AddValue("--pattern", "NAME", "procedural map: Bricks, Stone, HemisphereTorus, Flat, SineWave",
    "Bricks");
  cl.AddValue("--depth-file", "IMAGE", "use this depth image (any OpenImageIO format) instead");
  cl.AddFlag("--height", "the depth image stores height (white = high) rather than depth");
  cl.AddFlag("--normalize",
    "stretch the depth image's value range to [0, 1] (elevations in metres, as in DEMs)");
  cl.AddValue("--no-data", "VALUE", CommandLine::NoDataHelp);
  for (const char* option : { "--height", "--normalize", "--no-data" })
  {
    cl.AppliesOnlyWith(option, { "--depth-file" });
  }
  cl.AddValue("--resolution", "N", "texels per side of the procedural map", "512");
  cl.AddValue("--depth-scale", "K", "relief depth as a fraction of the wall width", "0.04");
  cl.AddValue("--vertical-exaggeration", "E", CommandLine::VerticalExaggerationHelp);
  cl.AddValue("--method", "NAME",
    "texture, bump, parallax, parallax-limit, parallax-slope, iterative-parallax, binary, secant, "
    "linear (steep), pom, relief, interval, relaxed-cone, relaxed-cone-interval, cone, max-mipmap "
    "(the mapper's default: exact)",
    "max-mipmap");
  cl.AddValue("--linear-steps", "N",
    "linear search steps (cone steps; iterations for iterative parallax and max-mipmap). "
    "Default: 64 iterations for max-mipmap (the default method, as the mapper's), 10 for the "
    "other methods");
  cl.AddValue("--refinement-steps", "N", "binary / interval / secant refinement steps", "8");
  cl.AddFlag("--adaptive-steps", "fewer linear steps head-on, --linear-steps at grazing angles");
  cl.AddFlag("--level-of-detail",
    "filter where texels are smaller than pixels (the default: the footprint's visible normal, "
    "no steps finer than the footprint)");
  cl.AddFlag("--no-level-of-detail", "no filtering where texels are smaller than pixels");
  cl.AddValue("--normal-filter", "NAME",
    "with level of detail, the shading normal over a pixel footprint: mean (Toksvig), visible "
    "(the visible normal's moments) or masked (the facets the viewer sees; the mapper's "
    "default)");
  cl.AddValue("--far-view-rays", "N",
    "with level of detail, the most view rays averaged across a far pixel, 1-8 (1: one ray; the "
    "mapper's default is 3)");
  cl.AddFlag("--no-shadows", "no self-shadowing");
  cl.AddFlag("--no-silhouettes", "keep fragments whose hit leaves the texture");
  cl.AddFlag("--no-surface-curvature",
    "march a curved mesh in the flat tangent plane (no per-vertex quadrics)");
  cl.AddFlag("--no-depth-write", "keep the mesh depth instead of the hit depth");
  cl.AddValue("--size", "WxH", "image size in pixels", "800x800");
  cl.AddValue("--view-angle", "DEG", "camera angle from the wall normal", "55");
  cl.AddValue("--azimuth", "DEG", "camera turn about the wall normal", "20");
  cl.AddValue("--lights", "N", "VTK lights: 0 = none, 1 = key light, 2 = key + fill", "2");
  cl.AddValue("--environment", "SPEC",
    "light also by an environment: procedural:sky, procedural:sun or a lat-long HDR file");
  cl.AddValue("--env-lights", "N", "median-cut lights of the environment", "128");
  cl.AddValue("--lights-csv", "FILE", "light also by a light set written by `mesolight lights`");
  cl.AddValue("--exposure", "X", "scale of the environment lighting", "1");
  // On by default, as vtkReliefProperty and ParaView have it: a light set carries the whole
  // environment's irradiance, so clamped shading blows out a first image.
  cl.AddFlag("--tone-map", "Reinhard tone mapping of the environment-lit colour (the default)");
  cl.AddFlag("--no-tone-map", "clamp the environment-lit colour instead of tone mapping it");
  cl.AddValue("--light-elevation", "DEG", "key light elevation above the wall", "35");
}

bool ReadSceneOptions(const CommandLine& cl, ReliefSceneOptions& o, std::string& error)
{
  o.Pattern = cl.Get("--pattern");
  o.DepthFile = cl.Get("--depth-file");
  o.DepthFileIsHeight = cl.Has("--height");
  o.NormalizeDepthFile = cl.Has("--normalize");
  CommandLine::NoDataOption noData;
  if (!cl.GetNoData("--no-data", noData, error))
  {
    return false;
  }
  o.UseNoDataValue = noData.Use;
  o.NoDataValue = noData.Value;
  o.UseFileNoDataValue = noData.UseFileValue;
  o.Method = cl.Get("--method");
  // A misspelt name is a usage error that lists the names, before any work.
  if (vtkReliefProperty::GetMethodFromName(o.Method.c_str()) < 0)
  {
    error = "--method: unknown method '" + o.Method + "'; the methods are " +
      vtkReliefProperty::GetMethodNameList();
    return false;
  }
  bool knownPattern = false;
  std::string patterns;
  for (int p = 0; vtkProceduralReliefSource::GetPatternName(p); ++p)
  {
    const std::string name = vtkProceduralReliefSource::GetPatternName(p);
    knownPattern =
      knownPattern || vtksys::SystemTools::Strucmp(name.c_str(), o.Pattern.c_str()) == 0;
    patterns += (p > 0 ? ", " : " ") + name;
  }
  if (!knownPattern)
  {
    error = "--pattern: unknown pattern '" + o.Pattern + "'; the patterns are" + patterns;
    return false;
  }
  o.SelfShadowing = !cl.Has("--no-shadows");
  o.Silhouettes = !cl.Has("--no-silhouettes");
  o.SurfaceCurvature = !cl.Has("--no-surface-curvature");
  o.WriteDepth = !cl.Has("--no-depth-write");
  o.AdaptiveSteps = cl.Has("--adaptive-steps");
  o.Environment = cl.Get("--environment");
  o.LightsCsv = cl.Get("--lights-csv");
  if (!o.Environment.empty() && !o.LightsCsv.empty())
  {
    error = "--environment and --lights-csv: give one light set, not both";
    return false;
  }
  if (cl.Has("--tone-map") && cl.Has("--no-tone-map"))
  {
    error = "--tone-map and --no-tone-map: give one";
    return false;
  }
  o.ToneMapping = !cl.Has("--no-tone-map");
  o.LevelOfDetail = !cl.Has("--no-level-of-detail");
  if (cl.Has("--normal-filter"))
  {
    const std::string filter = cl.Get("--normal-filter");
    o.NormalFilter = vtkReliefProperty::GetNormalFilterFromName(filter.c_str());
    if (o.NormalFilter < 0)
    {
      error = "--normal-filter: '" + filter + "' is not mean, visible or masked";
      return false;
    }
  }
  if (cl.Has("--far-view-rays") && !cl.GetInt("--far-view-rays", 1, 8, o.FarViewRays, error))
  {
    return false;
  }
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
  if (cl.Has("--vertical-exaggeration") &&
    (!cl.GetDouble("--vertical-exaggeration", 1e-6, 1000.0, o.VerticalExaggeration, error) ||
      !CommandLine::CheckVerticalExaggeration(cl, error)))
  {
    return false;
  }
  if (!cl.Has("--linear-steps") && o.Method == "max-mipmap")
  {
    // An iteration budget for the pyramid traversal, not linear steps: the mapper's default.
    o.LinearSteps = vtkSmartPointer<vtkReliefProperty>::New()->GetLinearSteps();
  }
  return cl.GetSize("--size", 16, 8192, o.Width, o.Height, error);
}

// The arguments of a command that takes the scene options (render, bench): false, with the exit
// code, when --help was printed or the arguments are wrong.
bool ParseSceneCommand(
  CommandLine& cl, const std::vector<std::string>& args, ReliefSceneOptions& options, int& exitCode)
{
  if (!cl.ParseArguments(args, exitCode))
  {
    return false;
  }
  std::string error;
  if (!ReadSceneOptions(cl, options, error))
  {
    exitCode = cl.UsageError(error);
    return false;
  }
  return true;
}

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
    vtkReliefProperty* m = this->Mapper->GetReliefProperty();
    switch (key)
    {
      case 'm':
        m->SetMethod((m->GetMethod() + 1) % vtkReliefProperty::NumberOfMethods);
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
    vtkReliefProperty* p = this->Mapper->GetReliefProperty();
    text << "method " << vtkReliefProperty::GetMethodName(p->GetMethod()) << " [m]   steps "
         << p->GetLinearSteps() << "+" << p->GetRefinementSteps() << " [+/-]   depth "
         << p->GetDepthScale() << " [ [ ] ]\nshadows " << (p->GetSelfShadowing() ? "on" : "off")
         << " [x]   silhouettes " << (p->GetSilhouettes() ? "on" : "off") << " [o]   depth write "
         << (p->GetWriteDepth() ? "on" : "off") << " [z]   quit [q]";
    this->Status->SetInput(text.str().c_str());
  }
};
vtkStandardNewMacro(ReliefInteractorStyle);

// `render --geometry-image FILE [--stride K | --tolerance T] [--color IMAGE]`: the relief on the
// coarse mesh of a geometry image (GeometryImageScene.h). False with a message (usage: exit 2).
bool BuildGeometryImageRender(const CommandLine& cl, const ReliefSceneOptions& relief,
  ReliefScene& scene, std::string& error, int& exitCode)
{
  exitCode = 2;
  if (cl.Has("--stride") && cl.Has("--tolerance"))
  {
    error = "--stride and --tolerance exclude each other (regular or adaptive sampling)";
    return false;
  }
  GeometryImageSceneOptions o;
  o.Relief = relief;
  o.GeometryImage = cl.Get("--geometry-image");
  o.ColorFile = cl.Get("--color");
  if (!cl.GetInt("--stride", 1, 1 << 20, o.Stride, error) ||
    !cl.GetDouble("--tolerance", 0.0, 1e30, o.Tolerance, error))
  {
    return false;
  }
  if (cl.Has("--tolerance") && !(o.Tolerance > 0.0))
  {
    error = "--tolerance must be a positive world distance";
    return false;
  }
  exitCode = 1;
  vtkSmartPointer<vtkPolyData> mesh;
  if (!BuildGeometryImageReliefScene(o, scene, error, &mesh))
  {
    return false;
  }
  std::cout << o.GeometryImage << ": " << mesh->GetNumberOfPolys() << " triangles (";
  if (o.Tolerance > 0.0)
  {
    std::cout << "tolerance " << o.Tolerance << ")" << std::endl;
  }
  else
  {
    std::cout << "stride " << o.Stride << ")" << std::endl;
  }
  return true;
}
} // namespace

int RunRenderCommand(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight render",
    "mesolight render [options]\n\nRenders the default relief scene (a procedural brick "
    "wall, two lights, an oblique camera)\nto a PNG, then opens an interactive window "
    "when a display is available.\nKeys: m method, +/- steps, [ ] depth, x shadows, o "
    "silhouettes, z depth write, q quit.\n");
  AddSceneOptions(cl);
  cl.AddValue("--out", "FILE.png", "PNG to write", "mesolight-render.png");
  cl.AddFlag("--offscreen", "only write the PNG, never open a window");
  cl.AddValue("--geometry-image", "FILE",
    "relief on a geometry image's mesh: RGB = XYZ image or "
    "procedural:cylinder|sphere|plane|wave|bump");
  cl.AddValue("--stride", "K", "geometry image: a vertex every K pixels", "20");
  cl.AddValue("--tolerance", "T", "geometry image: adaptive, to T world units (not with --stride)");
  cl.AddValue("--color", "IMAGE", "geometry image: albedo in its parameterization");
  for (const char* option : { "--stride", "--tolerance", "--color" })
  {
    cl.AppliesOnlyWith(option, { "--geometry-image" });
  }
  ReliefSceneOptions options;
  int exitCode = 0;
  if (!ParseSceneCommand(cl, args, options, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  std::string error;
  if (!cl.Positional().empty())
  {
    std::cerr << "mesolight render: unexpected argument '" << cl.Positional()[0] << "'\n";
    return 2;
  }
  const std::string out = cl.Get("--out");
  std::string problem = CheckOutputFile(out,
    { options.DepthFile, options.Environment, options.LightsCsv, cl.Get("--geometry-image"),
      cl.Get("--color") });
  if (!problem.empty())
  {
    return cl.UsageError("--out: " + problem);
  }
  problem = CheckImageOutputNames(cl);
  if (!problem.empty())
  {
    return cl.UsageError(problem);
  }

  ReliefScene scene;
  if (cl.Has("--geometry-image") || cl.Has("--stride") || cl.Has("--tolerance") ||
    cl.Has("--color"))
  {
    if (!BuildGeometryImageRender(cl, options, scene, error, exitCode))
    {
      return exitCode == 2 ? cl.UsageError(error)
                           : (std::cerr << "mesolight render: " << error << "\n", exitCode);
    }
  }
  else if (!BuildReliefScene(options, scene, error))
  {
    std::cerr << "mesolight render: " << error << "\n";
    return 1;
  }
  else
  {
    ReportFileNoDataValue(options.DepthFile, !options.UseNoDataValue && options.UseFileNoDataValue);
    ReportTrueDepthScale(options.DepthFile, scene.ReliefTexture);
  }
  // One window for both the PNG and the interactive view: on screen when a display is there.
  const bool interactive = !cl.Has("--offscreen") && HasDisplay();
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
    window = MakeOffscreenWindow(options, scene.Renderer);
  }
  const Frame frame = CaptureFrame(window);
  if (!WritePng(frame, out.c_str()))
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

int RunReliefBenchmarkCommand(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight bench",
    "mesolight bench [options]\n\nMeasures ms/frame of a stock textured plane, relief "
    "mapping, parallax occlusion mapping\nand the dense displaced mesh, and the error "
    "of each against the dense mesh.\n");
  AddSceneOptions(cl);
  cl.AddValue("--sizes", "N,N,..", "relief map resolutions to measure", "512,1024");
  cl.AddValue("--frames", "N", "timed frames per configuration (median reported)", "20");
  cl.AddValue("--csv", "FILE", "also write the table as CSV");
  ReliefSceneOptions options;
  int exitCode = 0;
  if (!ParseSceneCommand(cl, args, options, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  // Its rows fix their own methods and steps; a method asked for would be silently ignored.
  for (const char* fixed : { "--method", "--linear-steps", "--refinement-steps" })
  {
    if (cl.Has(fixed))
    {
      return cl.UsageError(std::string(fixed) +
        " does not apply: `mesolight bench` draws fixed rows (relief 10+8, POM, steep "
        "parallax); `mesolight bench relief --methods NAME --steps L+R` measures any method");
    }
  }
  std::string error;
  BenchmarkSettings settings;
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
  if (cl.Has("--csv"))
  {
    const std::string problem =
      CheckOutputFile(settings.CsvFile, { options.DepthFile, options.Environment });
    if (!problem.empty())
    {
      return cl.UsageError("--csv: " + problem);
    }
  }
  return RunReliefBenchmark(settings, std::cout) ? 0 : 1;
}

} // namespace mesolight
