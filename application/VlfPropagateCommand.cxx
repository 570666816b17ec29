// SPDX-License-Identifier: BSD-3-Clause
// `mesolight vlf propagate`: the light field of a scene, written after every iteration (or every
// K-th); under mpiexec its directions split over the ranks (Distribution.h).
#include "VlfCommand.h"

#include "CommandLine.h"
#include "OutputFile.h"
#include "ProgressLine.h"
#include "Timing.h"

#include "AdaptiveTexels.h"
#include "AutomaticSettings.h"
#include "DirectionSet.h"
#include "Distribution.h"
#include "FinalGather.h"
#include "LightField.h"
#include "MemoryBudget.h"
#include "ObjScene.h"
#include "ParallelForThreads.h" // ParallelForThreadCount
#include "Propagation.h"
#include "Snapshot.h"
#include "TextureComparison.h"
#include "TriangleScene.h"
#include "vtkLightFieldReducer.h"

#include <vtkMultiProcessController.h>
#include <vtkSMPTools.h>

#include <sys/resource.h>

#include <algorithm>
#include <chrono>
#include <csignal>
#include <cstdio>
#include <cstdlib>
#include <iostream>
#include <memory>
#include <string>
#include <vector>

namespace mesolight
{
namespace
{
namespace vlf = mesolight::vlf;
using Clock = std::chrono::steady_clock;

// For the tests of a killed run (tests/cli/VlfMpiKill.cmake): MESOLIGHT_TEST_KILL_AFTER=K:R makes
// rank R (a number, or "all") kill itself with SIGKILL right after the snapshot of iteration K is
// on disk, at a point known in advance, as `kill -9` or the out-of-memory killer would; the
// other ranks are then inside iteration K+1. Unset, nothing happens.
void KillIfAsked(int iteration, int rank)
{
  const char* asked = std::getenv("MESOLIGHT_TEST_KILL_AFTER");
  if (!asked)
  {
    return;
  }
  const std::string text(asked);
  const std::size_t colon = text.find(':');
  if (colon == std::string::npos || std::atoi(text.c_str()) != iteration)
  {
    return;
  }
  const std::string who = text.substr(colon + 1);
  if (who == "all" || (!who.empty() && std::atoi(who.c_str()) == rank))
  {
    std::fflush(stdout);
    std::raise(SIGKILL);
  }
}

// CPU seconds of this process (every thread).
double ProcessCpuSeconds()
{
  timespec t{};
  ::clock_gettime(CLOCK_PROCESS_CPUTIME_ID, &t);
  return static_cast<double>(t.tv_sec) + 1e-9 * static_cast<double>(t.tv_nsec);
}

// The reducer with a clock: this rank's seconds inside collective calls (waiting for the slowest
// rank, then the transfer), which --rank-report splits from the work of each phase.
class TimedReducer : public vlf::Reducer
{
public:
  explicit TimedReducer(vlf::Reducer& inner)
    : Inner(inner)
  {
  }
  int Rank() const override { return this->Inner.Rank(); }
  int Size() const override { return this->Inner.Size(); }
  void SumInPlace(float* data, std::size_t n) override
  {
    const Timer timer(*this);
    this->Inner.SumInPlace(data, n);
  }
  void SumInPlace(double* data, std::size_t n) override
  {
    const Timer timer(*this);
    this->Inner.SumInPlace(data, n);
  }
  void Broadcast(std::string& bytes, int root) override
  {
    const Timer timer(*this);
    this->Inner.Broadcast(bytes, root);
  }
  void Send(const std::string& bytes, int to) override
  {
    const Timer timer(*this);
    this->Inner.Send(bytes, to);
  }
  std::string Receive(int from) override
  {
    const Timer timer(*this);
    return this->Inner.Receive(from);
  }
  double Seconds = 0.0;    // wall clock inside MPI calls
  double CpuSeconds = 0.0; // CPU inside them: Open MPI polls while it waits

private:
  struct Timer
  {
    explicit Timer(TimedReducer& owner)
      : Owner(owner)
      , Start(Clock::now())
      , Cpu(ProcessCpuSeconds())
    {
    }
    ~Timer()
    {
      this->Owner.Seconds += SecondsSince(this->Start);
      this->Owner.CpuSeconds += ProcessCpuSeconds() - this->Cpu;
    }
    TimedReducer& Owner;
    Clock::time_point Start;
    double Cpu;
  };
  vlf::Reducer& Inner;
};

int Propagate(const std::vector<std::string>& args)
{
  CommandLine cl("mesolight vlf propagate",
    "mesolight vlf propagate [SCENE.obj] --out FIELD [options]\n\n"
    "Propagates the scene's light (the built-in Cornell box without SCENE) into a "
    "virtual light field,\nwriting FIELD after every iteration.\n");
  cl.AddValue("--out", "FIELD", "light field snapshot to write after every iteration (required)");
  cl.AddValue("--directions", "N",
    "directions: 2n^2+1, e.g. 513, 2049, 8193; auto: from the lines per side", "auto");
  cl.AddValue("--rays", "N",
    "lines per subfield side; auto: from the scene's small features, time and memory", "auto");
  cl.AddValue("--tiles", "M", "tiles per subfield side (0 = rays / 8)", "0");
  cl.AddValue("--contact-texels", "H",
    "texels halved H times (0-3) on the surfaces others stand on (a floor under boxes, a wall "
    "behind ribs); auto: once with the automatic resolution and the final gather",
    "auto");
  cl.AddFlag("--adaptive-texels",
    "texels per surface refined from the light of a cheap first pass (AdaptiveTexels.h), halved "
    "or quartered where it varies between texels, on top of the contact texels, within "
    "--adaptive-budget; with the final gather and one process");
  cl.AddFlag("--no-adaptive-texels", "no first pass: the contact texels alone (the default)");
  cl.AddValue("--adaptive-budget", "F",
    "the adaptive texels' refinements beyond the contact texels add at most F times the contact "
    "texels' gathered texels, best gain per texel first; negative: unbounded",
    "0.5");
  cl.AddValue("--tolerance", "X",
    "shoot until at most this share of the emitted flux is left unshot", "0.01");
  cl.AddValue("--max-iterations", "K", "most iterations --tolerance may take (in total)", "100");
  cl.AddValue("--iterations", "K",
    "instead of --tolerance: exactly K shooting iterations (in total, when resuming)");
  cl.AddValue("--memory-budget", "GIB", "refuse fields needing more memory than this", "4");
  cl.AddValue("--snapshot-every", "K",
    "write FIELD after every K-th iteration (and the last) instead of after each: a run killed "
    "in between resumes from the last one written",
    "1");
  cl.AddFlag("--resume", "continue the propagation stored in FIELD");
  cl.AddFlag("--force", "replace an existing light field FIELD (never any other file)");
  cl.AddFlag("--rank-report",
    "print each rank's seconds (trace, iterations, snapshot writes, final gather; of which in "
    "MPI calls), CPU seconds, peak memory and bytes sent");
  cl.AddFlag("--no-gather",
    "keep the propagated diffuse textures: no final gather (exact rays from every texel to the "
    "emitters and into the field, FinalGather.h)");
  cl.AddValue("--gather-rays", "N", "the final gather's indirect rays per texel", "1024");
  cl.AddFlag("--filter",
    "write the diffuse totals smoothed by an edge-keeping (bilateral) "
    "filter against mottling; not with --resume");
  std::string error;
  int exitCode = 0;
  if (!cl.ParseArguments(args, exitCode))
  {
    return exitCode; // --help printed, or a usage error reported
  }
  int directions = 0, rays = 0, tiles = 0, iterations = -1, maxIterations = 0, snapshotEvery = 1;
  int contactHalvings = vlf::AutomaticContactTexelHalvings; // auto
  double budget = 0.0, tolerance = 0.0;
  // "auto" is 0: vlf::ResolveAutomaticSettings chooses once the scene is read.
  const auto getCount = [&](const char* name, int low, int high, int& value)
  { return cl.Get(name) == "auto" ? (value = 0, true) : cl.GetInt(name, low, high, value, error); };
  if (!getCount("--directions", 3, 1 << 26, directions) || !getCount("--rays", 1, 4096, rays) ||
    !cl.GetInt("--tiles", 0, 4096, tiles, error) ||
    (cl.Get("--contact-texels") != "auto" &&
      !cl.GetInt("--contact-texels", 0, vlf::MaxContactTexelHalvings, contactHalvings, error)) ||
    (cl.Has("--iterations") && !cl.GetInt("--iterations", 0, 10000, iterations, error)) ||
    !cl.GetDouble("--tolerance", 1e-9, 0.999, tolerance, error) ||
    !cl.GetInt("--max-iterations", 1, 10000, maxIterations, error) ||
    !cl.GetInt("--snapshot-every", 1, 10000, snapshotEvery, error) ||
    !cl.GetDouble("--memory-budget", 1e-3, 1e6, budget, error))
  {
    return cl.UsageError(error);
  }
  // Refused before the scene is read (it was reported after an "automatic resolution" line).
  if (directions > 0 && !vlf::DirectionSet::IsCount(static_cast<std::size_t>(directions), &error))
  {
    return cl.UsageError("--directions: " + error);
  }
  vlf::FinalGatherOptions gatherOptions;
  const bool gather = !cl.Has("--no-gather");
  if (!cl.GetInt("--gather-rays", 1, 1 << 20, gatherOptions.IndirectRays, error))
  {
    return cl.UsageError(error);
  }
  double adaptiveBudget = vlf::AdaptiveTexelOptions().GatherBudget;
  if (!cl.GetDouble("--adaptive-budget", -1.0, 1e6, adaptiveBudget, error))
  {
    return cl.UsageError(error);
  }
  if (cl.Has("--iterations") && (cl.Has("--tolerance") || cl.Has("--max-iterations")))
  {
    return cl.UsageError("--iterations (a fixed count) excludes --tolerance and --max-iterations");
  }
  const std::string out = cl.Get("--out");
  if (out.empty())
  {
    return cl.UsageError("--out FIELD is required");
  }
  if (cl.Positional().size() > 1)
  {
    return cl.UsageError("one scene at most");
  }
  {
    // The scene (and its .mtl) is read, FIELD rewritten after every iteration: check it first.
    std::vector<std::string> inputs(cl.Positional());
    if (!inputs.empty() && inputs[0].size() > 4)
    {
      inputs.push_back(inputs[0].substr(0, inputs[0].size() - 4) + ".mtl");
    }
    const std::string problem = CheckOutputFile(out, inputs);
    if (!problem.empty())
    {
      return cl.UsageError("--out: " + problem);
    }
  }
  const bool resume = cl.Has("--resume");
  if (resume && cl.Has("--force"))
  {
    return cl.UsageError("--resume and --force exclude each other");
  }
  // A filtered snapshot's totals are no longer sums of what was shot, so they cannot be continued.
  const bool filter = cl.Has("--filter");
  if (resume && filter)
  {
    return cl.UsageError("--resume and --filter exclude each other");
  }
  // The texels are chosen from a gathered first pass; a resumed field keeps its stored ones.
  if (cl.Has("--adaptive-texels") && cl.Has("--no-adaptive-texels"))
  {
    return cl.UsageError("--adaptive-texels and --no-adaptive-texels exclude each other");
  }
  if (cl.Has("--adaptive-texels") && (resume || !gather))
  {
    return cl.UsageError(
      "--adaptive-texels excludes --resume (the field keeps its texels) and --no-gather (it "
      "measures the gathered light)");
  }
  // Only when asked for: measured, the first pass and the refinement cost more time than the
  // error they save (docs/vlf.md, "Texels from the light").
  const bool adaptive = cl.Has("--adaptive-texels");
  if (vlf::FileExists(out) && !vlf::IsSnapshotFile(out))
  {
    std::cerr << "mesolight vlf propagate: '" << out
              << "' exists and is not a light field: it is left alone, choose another --out\n";
    return 1;
  }
  if (vlf::FileExists(out) && !resume && !cl.Has("--force"))
  {
    std::cerr
      << "mesolight vlf propagate: '" << out
      << "' already holds a light field: add --resume to continue it or --force to replace it\n";
    return 1;
  }
  if (resume && !vlf::FileExists(out))
  {
    std::cerr << "mesolight vlf propagate: --resume: '" << out << "' does not exist\n";
    return 1;
  }
  const std::uint64_t budgetBytes = static_cast<std::uint64_t>(budget * 1073741824.0);
  // Under mpiexec (vtkMPIController, mesolight.cxx) the directions are split among the ranks
  // (Distribution.h); rank 0 prints and writes FIELD. One rank is the serial path.
  vlf::ControllerReducer controllerReducer;
  TimedReducer reducer(controllerReducer);
  const bool distributed = reducer.Size() > 1;
  const bool root = reducer.Rank() == 0;
  if (adaptive && distributed)
  {
    if (root)
    {
      std::cerr << "mesolight vlf propagate: --adaptive-texels runs in one process only\n";
    }
    return 1;
  }
  int threadsPerRank = 0; // 0: vtkSMPTools' default (every hardware thread)
  if (distributed && !std::getenv("VTK_SMP_MAX_THREADS"))
  {
    // Each rank's parallel-for would start a thread per core: ranks sharing a machine split its
    // cores instead of oversubscribing them (two ranks on two cores: one thread each).
    threadsPerRank = ParallelForThreadCount(reducer.Size());
    vtkSMPTools::Initialize(threadsPerRank);
  }
  const bool rankReport = cl.Has("--rank-report");
  double traceSeconds = 0.0, traceCollective = 0.0, iterationSeconds = 0.0, writeSeconds = 0.0,
         writeCollective = 0.0, writeTotal = 0.0;
  // CPU seconds of the iterations (the shooting, excluding snapshot writes), and of those inside
  // MPI calls: the rest is this rank's work, which an idle machine turns into wall time.
  double iterationCpu = 0.0, iterationMpiCpu = 0.0, cpuMark = 0.0, mpiCpuMark = 0.0;
  const auto peakRss = []()
  {
    rusage usage{};
    ::getrusage(RUSAGE_SELF, &usage);
    return 1024.0 * static_cast<double>(usage.ru_maxrss); // Linux: KiB
  };
  double tracedPeakRss = 0.0; // after tracing (or reading) the field, before propagating
  double gatherSeconds = 0.0, gatherCollective = 0.0; // the final gather (with --rank-report)
  vlf::FinalGatherReport gatherReport;
  if (!root)
  {
    std::cout.setstate(std::ios::failbit); // one rank speaks; errors are agreed, rank 0 prints
  }
  try
  {
    std::unique_ptr<vlf::LightField> field;
    if (resume)
    {
      if (!cl.Positional().empty())
      {
        std::cerr << "mesolight vlf propagate: --resume takes the scene and settings from '" << out
                  << "'; do not name a scene\n";
        return 2;
      }
      if (distributed)
      {
        // Every rank reads FIELD, whatever the rank count it was written with, keeping its own
        // directions' maps only (the others' are read, checked and dropped one at a time).
        vlf::Agree(reducer, [&]() { field = vlf::ReadOwnedSubfields(out, budgetBytes, reducer); });
      }
      else
      {
        field = vlf::ReadSnapshot(out, budgetBytes);
      }
      // A resumed field keeps the settings it was traced with: other values given here would be
      // silently ignored, so they are refused, naming both.
      const vlf::LightFieldSettings& stored = field->Settings();
      const int storedRays = stored.RaysPerSide;
      const int givenRays = cl.Has("--rays") && rays > 0 ? rays : storedRays;
      const struct
      {
        const char* Option;
        long long Given;
        long long Stored;
      } checks[] = { { "--directions", directions, static_cast<long long>(stored.Directions) },
        { "--rays", rays, storedRays },
        { "--tiles", tiles > 0 ? tiles : std::max(1, givenRays / 8), stored.TilesPerSide },
        { "--contact-texels", contactHalvings, stored.ContactTexelHalvings } };
      for (const auto& check : checks)
      {
        if (cl.Has(check.Option) && cl.Get(check.Option) != "auto" && check.Given != check.Stored)
        {
          return cl.UsageError(std::string("--resume: ") + check.Option + " " +
            cl.Get(check.Option) + " differs from the " + std::to_string(check.Stored) +
            " stored in '" + out + "' (a resumed field keeps its settings: leave out " +
            check.Option + ", or start over with --force)");
        }
      }
      traceCollective = reducer.Seconds; // (the report's "trace" of a resumed run: its reading)
      std::cout << "resuming '" << out << "' after " << field->IterationsDone << " iterations\n";
    }
    else
    {
      TriangleScene scene;
      // A scene without an emitter gives a dark field: refused when read, not after the set-up.
      mesolight::ObjReadOptions withEmitter;
      withEmitter.RequireEmitter = true;
      if (distributed)
      {
        // Agreed: a rank that cannot read the scene stops every rank, with its message.
        vlf::Agree(reducer,
          [&]()
          {
            scene = cl.Positional().empty()
              ? MakeCornellBox()
              : mesolight::ReadObjScene(cl.Positional()[0], withEmitter).Scene;
          });
        std::cout << "scene: "
                  << (cl.Positional().empty() ? "the built-in Cornell box" : cl.Positional()[0])
                  << " (" << scene.TriangleCount() << " triangles)\n";
      }
      else if (cl.Positional().empty())
      {
        scene = MakeCornellBox();
        std::cout << "scene: the built-in Cornell box\n";
      }
      else
      {
        mesolight::ObjSceneRead read = mesolight::ReadObjScene(cl.Positional()[0], withEmitter);
        for (const std::string& w : read.Warnings)
        {
          std::cerr << "mesolight vlf propagate: warning: " << w << "\n";
        }
        scene = std::move(read.Scene);
        std::cout << "scene: " << cl.Positional()[0] << " (" << scene.TriangleCount()
                  << " triangles, " << scene.Materials.size() << " materials)\n";
      }
      vlf::LightFieldSettings settings;
      settings.Directions = static_cast<std::size_t>(directions);
      settings.RaysPerSide = rays;
      settings.TilesPerSide = tiles;
      settings.MemoryBudget = budgetBytes;
      const vlf::AutomaticChoice choice =
        vlf::ResolveAutomaticSettings(scene, settings, gather, contactHalvings);
      settings = choice.Settings;
      if (rays == 0)
      {
        std::cout << "automatic resolution: " << choice.Describe() << "\n";
      }
      if (adaptive)
      {
        vlf::AdaptiveTexelOptions adaptiveOptions;
        adaptiveOptions.Progress = PrintedProgress("first pass for the texels");
        adaptiveOptions.GatherBudget = adaptiveBudget;
        vlf::AdaptiveTexelReport report;
        settings = vlf::ChooseAdaptiveTexels(scene, settings, adaptiveOptions, &report);
        std::cout << "adaptive texels: " << report.Describe() << "\n";
      }
      const vlf::MemoryEstimate estimate =
        distributed ? vlf::MemoryEstimate() : vlf::EstimateMemory(scene, settings);
      std::cout << "light field: " << settings.Directions << " directions x "
                << settings.RaysPerSide << "x" << settings.RaysPerSide << " rays, "
                << settings.TilesPerSide << "x" << settings.TilesPerSide << " tiles";
      if (distributed)
      {
        std::cout << ", directions split over " << reducer.Size() << " MPI ranks";
        if (threadsPerRank > 0)
        {
          std::cout << ", " << threadsPerRank << " thread" << (threadsPerRank > 1 ? "s" : "")
                    << " per rank";
        }
        std::cout << "\n";
      }
      else
      {
        std::cout << "; memory " << (estimate.SampleStride > 1 ? "" : "up to ")
                  << estimate.Describe() << "\n";
      }
      const Clock::time_point start = Clock::now();
      field = vlf::LightField::Build(scene, settings,
        root ? PrintedProgress("tracing subfields") : ProgressCallback(),
        distributed ? &reducer : nullptr);
      traceSeconds = SecondsSince(start);
      traceCollective = reducer.Seconds;
      std::cout << "traced in " << SecondsSince(start) << " s, "
                << FormatBytes(field->AllocatedBytes()) << " allocated\n";
    }
    vlf::PropagationOptions options;
    options.Progress = root
      ? PrintedProgress(iterations < 0 ? "toward the tolerance" : "propagating")
      : ProgressCallback();
    options.Reduce = distributed ? &reducer : nullptr;
    int writtenIteration = resume ? field->IterationsDone : -1; // what FIELD holds
    tracedPeakRss = peakRss();
    cpuMark = ProcessCpuSeconds();
    mpiCpuMark = reducer.CpuSeconds;
    const auto write = [&](const vlf::LightField& f)
    {
      const Clock::time_point writeStart = Clock::now();
      const double collectiveBefore = reducer.Seconds;
      if (distributed)
      {
        vlf::WriteDistributedSnapshot(*field, out, reducer);
      }
      else
      {
        vlf::WriteSnapshot(f, out);
      }
      writeSeconds = SecondsSince(writeStart); // the last write (a serial part of each iteration)
      writeTotal += writeSeconds;
      writeCollective += reducer.Seconds - collectiveBefore;
      writtenIteration = f.IterationsDone;
    };
    const auto snapshot = [&](const vlf::LightField& f)
    {
      if (filter)
      {
        // The snapshot gets the filtered totals; the propagation goes on with the raw ones.
        const std::vector<glm::vec3> raw = f.TotalDiffuse;
        vlf::FilterTotalDiffuse(*field, vlf::TextureFilterSettings());
        write(f);
        field->TotalDiffuse = raw;
      }
      else
      {
        write(f);
      }
    };
    char toleranceText[32] = "none: fixed count";
    if (iterations < 0)
    {
      std::snprintf(toleranceText, sizeof(toleranceText), "%g%%", 100.0 * tolerance);
    }
    const auto afterIteration = [&](const vlf::LightField& f)
    {
      iterationCpu += ProcessCpuSeconds() - cpuMark;
      iterationMpiCpu += reducer.CpuSeconds - mpiCpuMark;
      const vlf::LightField::IterationEnergy& e = f.EnergyLog.back();
      const bool due = e.Iteration % snapshotEvery == 0;
      if (due)
      {
        snapshot(f);
      }
      iterationSeconds += e.Seconds;
      if (root)
      {
        EndProgressLine();
        char took[32];
        std::snprintf(took, sizeof(took), " in %.2f s", writeSeconds);
        const std::string written = due
          ? "wrote " + out + took
          : "not written (--snapshot-every " + std::to_string(snapshotEvery) + ")";
        std::printf(
          "iteration %d: %.2f s, shot %.4g, escaped %.4g, absorbed %.4g, left to shoot %.4g "
          "= %.2f%% of the emitted (tolerance %s) (energy balance error %.1e); %s\n",
          e.Iteration, e.Seconds, e.Shot[0] + e.Shot[1] + e.Shot[2],
          e.Escaped[0] + e.Escaped[1] + e.Escaped[2], e.Absorbed[0] + e.Absorbed[1] + e.Absorbed[2],
          e.Unshot[0] + e.Unshot[1] + e.Unshot[2], 100.0 * vlf::UnshotFraction(f), toleranceText,
          e.ConservationError(), written.c_str());
        std::fflush(stdout);
      }
      KillIfAsked(e.Iteration, reducer.Rank());
      cpuMark = ProcessCpuSeconds();
      mpiCpuMark = reducer.CpuSeconds;
    };
    if (iterations >= 0)
    {
      vlf::Propagate(*field, iterations, options, afterIteration);
    }
    // (Every rank decides alike: the unshot fraction is summed over the ranks.)
    else if (!vlf::PropagateToTolerance(
               *field, tolerance, maxIterations, options, afterIteration) &&
      root)
    {
      EndProgressLine();
      std::cerr << "mesolight vlf propagate: warning: " << 100.0 * vlf::UnshotFraction(*field)
                << "% of the emitted flux is still unshot after " << maxIterations
                << " iterations (--max-iterations)\n";
    }
    // The last iteration (with --snapshot-every), or with zero iterations the traced field.
    // (Decided alike on every rank: a file test could race with rank 0's write.)
    if (!gather && !field->PropagatedDiffuse.empty())
    {
      vlf::RestorePropagatedDiffuse(*field); // a gathered field resumed without iterating
      writtenIteration = -1;
    }
    if (writtenIteration != field->IterationsDone && !gather)
    {
      snapshot(*field);
    }
    if (gather)
    {
      // Each rank gathers its share of the texels and one sum gives every rank the whole
      // (FinalGather.h: the serial textures); the file gets the gathered totals and keeps the
      // propagated ones for --resume.
      const Clock::time_point gatherStart = Clock::now();
      const double gatherCollectiveBefore = reducer.Seconds;
      gatherOptions.Progress = root ? PrintedProgress("final gather") : ProgressCallback();
      gatherOptions.Reduce = distributed ? &reducer : nullptr;
      gatherReport = vlf::FinalGather(*field, gatherOptions);
      gatherSeconds = SecondsSince(gatherStart);
      gatherCollective = reducer.Seconds - gatherCollectiveBefore;
      if (root)
      {
        std::printf("final gather: %zu texels, %.3g rays in %.2f s", gatherReport.Texels,
          static_cast<double>(gatherReport.Rays), gatherSeconds);
        if (distributed)
        {
          std::printf(" (split over %d ranks: rank 0 gathered %zu texels in %.2f s, %llu bytes "
                      "summed per rank)",
            reducer.Size(), gatherReport.OwnTexels, gatherReport.OwnSeconds,
            static_cast<unsigned long long>(gatherReport.CombinedBytes));
        }
        std::printf("\n");
        std::fflush(stdout);
      }
      snapshot(*field);
    }
    if (vtkMultiProcessController::GetGlobalController()) // under mpiexec, even one rank
    {
      const std::uint64_t reduced = distributed ? vlf::ReducedBytesPerIteration(*field) : 0;
      std::cout << "MPI: " << reducer.Size() << " ranks, " << reduced << " bytes ("
                << FormatBytes(reduced) << ") summed per rank and iteration, "
                << controllerReducer.BytesContributed()
                << " bytes sent by rank 0 in all (with mirrors also the mirrored radiance handed "
                   "to the owners); rank 0 holds "
                << field->AllocatedBytes() << " bytes (" << FormatBytes(field->AllocatedBytes())
                << ")\n";
    }
    if (rankReport)
    {
      // One row per rank, summed onto every rank (each fills its own), printed by rank 0.
      constexpr std::size_t columns = 18;
      std::vector<double> rows(columns * static_cast<std::size_t>(reducer.Size()), 0.0);
      rusage usage{};
      ::getrusage(RUSAGE_SELF, &usage);
      const double cpu = static_cast<double>(usage.ru_utime.tv_sec + usage.ru_stime.tv_sec) +
        1e-6 * static_cast<double>(usage.ru_utime.tv_usec + usage.ru_stime.tv_usec);
      std::size_t owned = 0;
      for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
      {
        owned += field->OwnsSubfield(k) ? 1 : 0;
      }
      const double collective = reducer.Seconds;
      const double mine[columns] = { traceSeconds, traceCollective, iterationSeconds,
        collective - traceCollective - writeCollective - gatherCollective, writeTotal,
        writeCollective, cpu, peakRss(), static_cast<double>(field->AllocatedBytes()),
        static_cast<double>(owned), static_cast<double>(controllerReducer.BytesContributed()),
        iterationCpu, iterationMpiCpu, tracedPeakRss, gatherSeconds, gatherReport.OwnSeconds,
        gatherCollective, static_cast<double>(gatherReport.OwnTexels) };
      std::copy(
        mine, mine + columns, rows.begin() + columns * static_cast<std::size_t>(reducer.Rank()));
      reducer.SumInPlace(rows.data(), rows.size());
      for (int r = 0; root && r < reducer.Size(); ++r)
      {
        const double* v = rows.data() + columns * static_cast<std::size_t>(r);
        std::printf("rank %d: trace %.3f s (in MPI %.3f s), iterations %.3f s (in MPI %.3f s), "
                    "snapshot writes %.3f s (in MPI %.3f s), cpu %.3f s, peak RSS %.0f bytes, "
                    "holds %.0f bytes, %.0f directions, sent %.0f bytes, iteration cpu %.3f s "
                    "(in MPI %.3f s), peak RSS after trace %.0f bytes, final gather %.3f s "
                    "(own share %.3f s, in MPI %.3f s, %.0f texels)\n",
          r, v[0], v[1], v[2], v[3], v[4], v[5], v[6], v[7], v[8], v[9], v[10], v[11], v[12], v[13],
          v[14], v[15], v[16], v[17]);
      }
      std::fflush(stdout);
    }
    std::cout << "light field '" << out << "': " << field->IterationsDone << " iterations\n";
  }
  catch (const vlf::DistributedError& e)
  {
    if (root) // every rank has the same agreed message
    {
      std::cerr << "mesolight vlf propagate: " << e.what() << "\n";
    }
    return 1;
  }
  catch (const std::exception& e)
  {
    std::cerr << "mesolight vlf propagate: " << e.what() << "\n";
    return 1;
  }
  return 0;
}

} // namespace

int RunVlfPropagate(const std::vector<std::string>& args)
{
  return Propagate(args);
}

} // namespace mesolight
