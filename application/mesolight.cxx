// SPDX-License-Identifier: BSD-3-Clause
// mesolight: render, bake and benchmark relief surfaces from the command line. The commands are
// one table (Commands() below: name, usage, summary, handler); `mesolight --help` is printed from
// it, and `mesolight COMMAND --help` by each command's CommandLine.
#include "CommandLine.h"
#include "CommandTable.h"
#include "ConeBenchmark.h"
#include "CurvedReliefBenchmark.h"
#include "Distribution.h"
#include "GatherBenchmark.h"
#include "GeometryImageBenchmark.h"
#include "HallucinateCommand.h"
#include "ImageCommands.h"
#include "LightFieldViewCommand.h"
#include "LightSetActorsBenchmark.h"
#include "LightSetBenchmark.h"
#include "LightsCommand.h"
#include "ObjectBenchmark.h"
#include "ProgressLine.h"
#include "ReliefAliasingBenchmark.h"
#include "ReliefFieldCostBenchmark.h"
#include "ReliefSweep.h"
#include "RenderCommand.h"
#include "TraceCommand.h"
#include "VTKMessage.h"
#include "VlfAccuracyBenchmark.h"
#include "VlfCommand.h"
#include "VlfReliefBenchmark.h"
#include "VlfStorageBenchmark.h"
#include "WalkthroughBenchmark.h"

#include <vtkLogger.h>
#include <vtkMPI.h> // MPI_Abort
#include <vtkMPIController.h>
#include <vtkNew.h>
#include <vtkObjectFactory.h>
#include <vtkOutputWindow.h>
#include <vtkSmartPointer.h>
#include <vtkVersion.h>

#include <cstdlib>
#include <fstream>
#include <iostream>
#include <new>
#include <string>
#include <vector>

#include <unistd.h> // getppid

namespace
{
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
    mesolight::EndProgressLine();
    std::cerr << "mesolight: " << mesolight::NameOwnOptions(mesolight::CleanVTKMessage(message))
              << "\n";
    // VTK's X window aborts (SIGABRT, a core) right after this message when there is no X
    // server, even for offscreen rendering (Debian's VTK has no EGL or OSMesa): end the command
    // with an ordinary error and the way out instead.
    if (message.find("bad X server connection") != std::string::npos)
    {
      std::cerr << "mesolight: no X display to render with (DISPLAY='"
                << (std::getenv("DISPLAY") ? std::getenv("DISPLAY") : "")
                << "'); run the command under scripts/xvfb.sh or xvfb-run -a\n";
      std::cerr.flush();
      std::_Exit(1);
    }
  }
};
vtkStandardNewMacro(ConsoleOutputWindow);

const std::vector<mesolight::Command>& Commands();

// `mesolight help [COMMAND...]`: the usage, or a command's options.
int RunHelp(const std::vector<std::string>& args);

void PrintUsage(std::ostream& os)
{
  os << "mesolight - relief surfaces for VTK\n\nUsage:\n";
  mesolight::PrintCommandUsage(os, "mesolight", Commands());
  os << "\nRun 'mesolight COMMAND --help' for the options of a command, 'mesolight --version' "
        "for the version.\n";
}

// Every command: name, usage, summary (the lines of `mesolight --help`), handler.
const std::vector<mesolight::Command>& Commands()
{
  using namespace mesolight;
  static const std::vector<Command> commands = {
    { "render", "[options]", "render the default relief scene", RunRenderCommand, {} },
    { "bake", "DEPTH_IMAGE --out RELIEF_IMAGE [options]",
      "bake a relief texture from a depth image", RunBakeCommand, {} },
    { "cone", "DEPTH_IMAGE --out FILE.exr [options]", "bake a cone-packed relief texture",
      RunConeCommand, {} },
    { "probe", "PROBE_IMAGE --out FILE.exr",
      "light probe (angular map, mirror ball, two-view\nmerge) -> lat-long environment",
      RunProbeCommand, {} },
    { "lights", "ENV_IMAGE --count N --out lights.csv", "median-cut lights of an HDR environment",
      RunLightsCommand, {} },
    { "trace", "[--scene spheres|ring|cornell] [options]",
      "Embree ray tracer (textured material channels,\nglossy reflection, adaptive, progressive) "
      "or "
      "the\npath-traced Cornell box",
      RunTraceCommand, {} },
    { "vlf", "", "", nullptr,
      {
        { "propagate", "[SCENE.obj] --out FIELD [options]",
          "propagate a virtual light field (built-in\nCornell box without SCENE)", RunVlfPropagate,
          {} },
        { "render", "FIELD --out IMAGE.png [--mode MODE]",
          "render a light field: its diffuse totals on the\nCPU, or through vtkLightFieldActor "
          "with "
          "--mode;\nnamed surfaces as reliefs with --relief",
          RunVlfRender, {} },
        { "view", "FIELD [options]",
          "walk through a light field in a window\n(vtkLightFieldActor, four modes)",
          RunLightFieldView, {} },
      } },
    { "bench", "", "", nullptr,
      {
        { "", "[options]", "time and error: relief vs the dense mesh", RunReliefBenchmarkCommand,
          {} },
        { "relief", "[options]",
          "every method x steps x view angle x map:\ntime vs exact hit error, CSV and plots",
          static_cast<int (*)(const std::vector<std::string>&)>(RunReliefSweep), {} },
        { "relief-aliasing", "[options]",
          "the default relief vs an 8x8 supersampled exact\nreference where texels are smaller "
          "than pixels",
          RunReliefAliasingBenchmark, {} },
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
        { "vlf-accuracy", "[options]",
          "light field vs path tracer per pixel on five\nscenes: error, time, memory per setting",
          RunVlfAccuracyBenchmark, {} },
        { "vlf-relief", "--reference REF.exr --mask M.exr --images ..",
          "a relief lit by the light field vs the path-traced\ndense mesh; negative cases, cost",
          RunVlfReliefBenchmark, {} },
        { "relief-field-cost", "[options]",
          "GPU relief lit by SH9 probes + emitter lights vs\none VTK light: ms/frame, ratio",
          RunReliefFieldCostBenchmark, {} },
        { "walkthrough", "[FIELD] [options]",
          "light field walkthrough: frame time per mode and\nstage (vtkLightFieldActor)",
          RunWalkthroughBenchmark, {} },
        { "gather", "[FIELD] [options]",
          "a movable object's gathered irradiance: us per\nvertex, cache hits, error vs the path "
          "tracer",
          RunGatherBenchmark, {} },
        { "vlf-storage", "[SCENE.obj ...] [options]",
          "light field storage: memory and file size,\ndense float vs sparse shared-exponent, its "
          "error",
          RunVlfStorageBenchmark, {} },
        { "object", "[FIELD] [options]",
          "a movable object in the walkthrough: frame time\nper stage, directions and subdivision",
          RunObjectBenchmark, {} },
        { "geometry-image", "[options]",
          "geometry images: triangles vs Hausdorff distance\nand image error, stride vs adaptive",
          RunGeometryImageBenchmark, {} },
        { "curved-relief", "[options]",
          "relief on curved meshes vs the flat march:\noutline coverage vs the dense mesh, frame "
          "time",
          RunCurvedReliefBenchmark, {} },
        { "hallucinate", "[options]",
          "depth hallucination against path-traced\nphotographs of known height fields",
          RunHallucinationBenchmark, {} },
        { "light-set-actors", "[options]",
          "VTK actors lit by a light set: error vs K,\nshadows, frame time",
          RunLightSetActorsBenchmark, {} },
      } },
    { "hallucinate", "DIFFUSE FLASH --albedo A.exr --depth D.exr",
      "depth hallucination: albedo and depth from a\ndiffuse and a flash photograph",
      RunHallucinateCommand, {} },
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

// Whether this process' parent is an MPI launcher or its node daemon (Open MPI, MPICH's Hydra,
// PMIx, Slurm), not a program that happens to run under one.
static bool StartedByMpiLauncher()
{
  std::ifstream comm("/proc/" + std::to_string(static_cast<long>(::getppid())) + "/comm");
  std::string parent;
  std::getline(comm, parent);
  for (const char* launcher : { "mpiexec", "mpirun", "orterun", "orted", "prterun", "prted",
         "hydra_pmi_proxy", "mpiexec.hydra", "slurmstepd" })
  {
    if (parent == launcher)
    {
      return true;
    }
  }
  return false;
}

int main(int argc, char* argv[])
{
  vtkNew<ConsoleOutputWindow> console;
  vtkOutputWindow::SetInstance(console);
  vtkLogger::SetStderrVerbosity(vtkLogger::VERBOSITY_OFF); // messages go through the console window
  const std::vector<std::string> args(argv + 1, argv + argc);
  // Started by mpiexec (Open MPI, MPICH/PMI) for the commands that use MPI, `vlf propagate` and
  // `vlf render` (the distributed light field); otherwise MPI is not touched -- a tool run by an
  // MPI rank (e.g. `vlf render` from a pvbatch script under mpiexec) inherits the launcher's
  // variables but is no rank of the job. `vlf render` is often run that way, so it joins only
  // when its parent is the launcher itself.
  vtkSmartPointer<vtkMPIController> mpi;
  const bool launched =
    std::getenv("OMPI_COMM_WORLD_SIZE") || std::getenv("PMI_SIZE") || std::getenv("PMIX_RANK");
  if (args.size() >= 2 && args[0] == "vlf" && launched &&
    (args[1] == "propagate" || (args[1] == "render" && StartedByMpiLauncher())))
  {
    mpi = vtkSmartPointer<vtkMPIController>::New();
    mpi->Initialize(&argc, &argv);
    vtkMultiProcessController::SetGlobalController(mpi);
  }
  int status = 0;
  if (args.empty() || args[0] == "--help" || args[0] == "-h")
  {
    PrintUsage(std::cout);
    status = args.empty() ? 2 : 0;
  }
  else if (args[0] == "--version")
  {
    // What a bug report needs: this tool's version and the VTK it runs on.
    std::cout << "mesolight " << MESOLIGHT_VERSION << " (VTK " << vtkVersion::GetVTKVersion()
              << ")\n";
  }
  else
  {
    try
    {
      status = mesolight::DispatchCommand("mesolight", Commands(), args);
    }
    catch (const std::bad_alloc&)
    {
      // An allocation no memory estimate foresaw (an image source, a reader): one line and exit
      // 1, not "terminate called" and an abort.
      std::cerr << "mesolight " << args[0]
                << ": out of memory (std::bad_alloc); use a smaller input or a larger memory limit"
                   " (ulimit -v, the container's)\n";
      status = 1;
    }
  }
  if (mpi && status != 0 && mpi->GetNumberOfProcesses() > 1 && !mesolight::vlf::FailureWasAgreed())
  {
    // This rank failed alone (e.g. a usage error in an mpiexec line giving the ranks different
    // options): the others may wait for it in a collective call, so the job ends here.
    MPI_Abort(MPI_COMM_WORLD, status);
  }
  if (mpi)
  {
    vtkMultiProcessController::SetGlobalController(nullptr);
    mpi->Finalize();
  }
  return status;
}
