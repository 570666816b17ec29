// SPDX-License-Identifier: BSD-3-Clause
// vtkVirtualLightField: the Cornell box through the filter gives per-cell and per-point
// "Radiance" (the light at its emission plus what it reflects, the walls lit), progress and
// abort, a clear error over the memory budget, snapshots written / resumed / never over a
// foreign file, the irradiance query, PrintSelf; the radiance atlas it attaches for drawing
// (bilinear at each vertex's atlas coordinates = the vertex's Radiance); an empty parallel piece;
// ContactTexelHalvings on a box standing on a floor.
#include "TestDirectory.h"
#include "vtkVirtualLightFieldCore.h"

#include "AutomaticSettings.h"
#include "LightField.h"
#include "MessageCapture.h"
#include "Propagation.h"
#include "TriangleScene.h"
#include "VLFTestScenes.h"
#include "vtkCornellBoxSource.h"
#include "vtkTriangleSceneConverter.h"

#include <vtkCell.h>
#include <vtkCellData.h>
#include <vtkCleanPolyData.h>
#include <vtkCommand.h>
#include <vtkDataArray.h>
#include <vtkExecutive.h>
#include <vtkFieldData.h>
#include <vtkFloatArray.h>
#include <vtkNew.h>
#include <vtkPointData.h>
#include <vtkPolyData.h>
#include <vtkSMPTools.h>

#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <fstream>
#include <iostream>
#include <memory>
#include <sstream>
#include <string>
#include <vector>

namespace
{
using mesolight_test::MessageCapture;

// Counts progress events; aborts its filter at the AbortAt-th.
class ProgressCounter : public vtkCommand
{
public:
  static ProgressCounter* New() { return new ProgressCounter; }
  void Execute(vtkObject*, unsigned long, void*) override
  {
    ++this->ProgressEvents;
    if (this->AbortAt >= 0 && this->ProgressEvents >= this->AbortAt && this->Filter)
    {
      this->Filter->SetAbortExecute(1);
    }
  }
  int ProgressEvents = 0;
  int AbortAt = -1;
  vtkAlgorithm* Filter = nullptr;
};

std::string TempPath(const std::string& name)
{
  return mesolight_test::TestPath(name);
}

void SmallSettings(vtkVirtualLightField* filter)
{
  filter->SetDirections(33);
  filter->SetRaysPerSide(16);
  filter->SetIterations(2);
}

// The atlas travels with the output: GL's bilinear lookup (texel centres at (i + 1/2) / size,
// clamped) at each vertex's atlas coordinates gives that vertex's point Radiance, which the
// filter samples from the field itself. Upside down it does not.
TEST(VLFVirtualLightField, AttachedAtlasGivesThePointRadiance)
{
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkVirtualLightField> filter;
  filter->SetInputConnection(box->GetOutputPort());
  SmallSettings(filter);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  int size[2] = { 0, 0 };
  vtkFloatArray* atlas = vtkVirtualLightField::GetAttachedAtlas(out, size);
  ASSERT_NE(atlas, nullptr);
  EXPECT_EQ(out->GetCellData()->GetScalars(), nullptr); // displays colour by no array
  vtkDataArray* tc = out->GetPointData()->GetArray(vtkVirtualLightField::GetAtlasCoordinatesName());
  vtkDataArray* radiance = out->GetPointData()->GetArray("Radiance");
  ASSERT_NE(tc, nullptr);
  ASSERT_EQ(tc->GetNumberOfComponents(), 2);
  const auto sample = [&](double u, double v, int c, bool flip)
  {
    const double x = u * size[0] - 0.5, y = v * size[1] - 0.5;
    const double fx = std::floor(x), fy = std::floor(y);
    double sum = 0.0;
    for (int q = 0; q < 4; ++q)
    {
      const int dx = q & 1, dy = q >> 1;
      const int ix = std::clamp(static_cast<int>(fx) + dx, 0, size[0] - 1);
      int iy = std::clamp(static_cast<int>(fy) + dy, 0, size[1] - 1);
      iy = flip ? size[1] - 1 - iy : iy;
      const double w = (dx ? x - fx : 1.0 - (x - fx)) * (dy ? y - fy : 1.0 - (y - fy));
      sum += w * atlas->GetComponent(static_cast<vtkIdType>(iy) * size[0] + ix, c);
    }
    return sum;
  };
  double worst = 0.0, worstFlipped = 0.0;
  for (vtkIdType p = 0; p < out->GetNumberOfPoints(); ++p)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double want = radiance->GetComponent(p, c);
      const double scale = std::max(1e-3, want);
      const double u = tc->GetComponent(p, 0), v = tc->GetComponent(p, 1);
      worst = std::max(worst, std::abs(sample(u, v, c, false) - want) / scale);
      worstFlipped = std::max(worstFlipped, std::abs(sample(u, v, c, true) - want) / scale);
    }
  }
  std::cout << "atlas " << size[0] << "x" << size[1] << ": worst relative difference at the "
            << out->GetNumberOfPoints() << " vertices " << worst << ", upside down " << worstFlipped
            << "\n";
  EXPECT_LT(worst, 1e-4);
  EXPECT_GT(worstFlipped, 0.1);

  // Arrays that do not agree are no atlas.
  vtkNew<vtkPolyData> broken;
  broken->DeepCopy(out);
  broken->GetFieldData()->RemoveArray(vtkVirtualLightField::GetAtlasSizeName());
  EXPECT_EQ(vtkVirtualLightField::GetAttachedAtlas(broken, size), nullptr);
}

// An empty input: an error alone, an empty piece (no error) as one of several pieces.
TEST(VLFVirtualLightField, EmptyPieceInParallel)
{
  vtkNew<vtkPolyData> empty;
  vtkNew<vtkVirtualLightField> filter;
  filter->SetInputData(empty);
  SmallSettings(filter);
  vtkNew<MessageCapture> messages;
  messages->Watch(filter);
  filter->GetExecutive()->AddObserver(vtkCommand::ErrorEvent, messages);
  filter->UpdatePiece(1, 2, 0);
  EXPECT_TRUE(messages->Errors.empty()) << messages->AllErrors();
  EXPECT_EQ(filter->GetOutput()->GetNumberOfCells(), 0);
  filter->Modified();
  filter->UpdatePiece(0, 1, 0);
  EXPECT_TRUE(messages->HasError("cannot be used as a light field scene"));
}

TEST(VLFVirtualLightField, CornellBoxRadiance)
{
  vtkNew<vtkCornellBoxSource> box;
  // Merged points: walls, floor and blocks share the vertices along their edges, as most meshes do.
  vtkNew<vtkCleanPolyData> merged;
  merged->SetInputConnection(box->GetOutputPort());
  vtkNew<vtkVirtualLightField> filter;
  filter->SetInputConnection(merged->GetOutputPort());
  SmallSettings(filter);
  vtkNew<ProgressCounter> progress;
  filter->AddObserver(vtkCommand::ProgressEvent, progress);
  filter->Update();
  vtkPolyData* out = filter->GetOutput();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter)->IterationsDone, 2);
  EXPECT_GT(progress->ProgressEvents, 2);
  vtkDataArray* cells = out->GetCellData()->GetArray("Radiance");
  vtkDataArray* points = out->GetPointData()->GetArray("Radiance");
  ASSERT_NE(cells, nullptr);
  ASSERT_NE(points, nullptr);
  ASSERT_EQ(cells->GetNumberOfTuples(), out->GetNumberOfCells());
  vtkDataArray* emission = out->GetCellData()->GetArray("Emission");
  ASSERT_NE(emission, nullptr);
  int lit = 0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    const double e = emission->GetComponent(c, 0);
    const double r = cells->GetComponent(c, 0);
    if (e > 0.0)
    {
      EXPECT_GE(r, e); // the light: its emission and what it reflects
    }
    else
    {
      lit += r > 0.0 ? 1 : 0;
    }
  }
  EXPECT_EQ(lit, out->GetNumberOfCells() - 2); // every wall and block face receives light

  // No point is shared by two cells of different materials (the light and the ceiling, a red
  // wall and the floor): point radiance of one surface must not bleed into another.
  vtkDataArray* materials = out->GetCellData()->GetArray("MaterialId");
  ASSERT_NE(materials, nullptr);
  std::vector<double> materialOfPoint(static_cast<std::size_t>(out->GetNumberOfPoints()), -1.0);
  int shared = 0;
  for (vtkIdType c = 0; c < out->GetNumberOfCells(); ++c)
  {
    vtkCell* cell = out->GetCell(c);
    for (vtkIdType i = 0; i < cell->GetNumberOfPoints(); ++i)
    {
      double& m = materialOfPoint[static_cast<std::size_t>(cell->GetPointId(i))];
      const double mine = materials->GetComponent(c, 0);
      shared += (m >= 0.0 && m != mine) ? 1 : 0;
      m = mine;
    }
  }
  EXPECT_EQ(shared, 0);

  // Irradiance under the light on the floor's centre, facing up: positive and finite.
  const double p[3] = { 278.0, 1.0, 279.0 }, n[3] = { 0.0, 1.0, 0.0 };
  double e[3];
  ASSERT_TRUE(filter->ComputeIrradiance(p, n, e));
  EXPECT_GT(e[0], 0.0);

  std::ostringstream printed;
  filter->Print(printed);
  EXPECT_NE(printed.str().find("Directions: 33"), std::string::npos);
  EXPECT_NE(printed.str().find("2 iterations done"), std::string::npos);
}

TEST(VLFVirtualLightField, BudgetAbortAndSnapshots)
{
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkVirtualLightField> filter;
  filter->SetInputConnection(box->GetOutputPort());
  SmallSettings(filter);
  vtkNew<MessageCapture> messages;
  messages->Watch(filter);

  filter->SetMemoryBudget(4096);
  filter->Update();
  EXPECT_TRUE(messages->HasError("memory budget") || messages->HasWarning("memory budget"))
    << messages->AllErrors() << messages->AllWarnings();
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  filter->SetMemoryBudget(vtkTypeInt64(1) << 30);

  // A file the user made is never replaced.
  const std::string foreign = TempPath("user-notes.txt");
  {
    std::ofstream out(foreign);
    out << "precious";
  }
  messages->Clear();
  filter->SetSnapshotFileName(foreign.c_str());
  filter->Update();
  EXPECT_TRUE(messages->HasError("not a light field snapshot") ||
    messages->HasWarning("not a light field snapshot"))
    << messages->AllErrors() << messages->AllWarnings();
  std::ifstream in(foreign);
  std::string content;
  in >> content;
  EXPECT_EQ(content, "precious");

  // Snapshots after each iteration, then resume to more iterations.
  const std::string snapshot = TempPath("filter.vlf");
  std::remove(snapshot.c_str());
  filter->SetSnapshotFileName(snapshot.c_str());
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  filter->SetResumeFromSnapshot(true);
  filter->SetIterations(3);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter)->IterationsDone, 3);
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter)->EnergyLog.size(), 3u);
  EXPECT_FALSE(messages->HasWarning("Resumed")) << messages->AllWarnings();

  // Other rays per side asked of a resumed snapshot: it keeps its own, and says so (not ignored
  // without a word).
  const int rays = filter->GetRaysPerSide();
  messages->Clear();
  filter->SetRaysPerSide(2 * rays);
  filter->SetIterations(4);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter)->Settings().RaysPerSide, rays);
  EXPECT_TRUE(messages->HasWarning(
    "RaysPerSide " + std::to_string(rays) + " (asked: " + std::to_string(2 * rays) + ")"))
    << messages->AllWarnings();
  filter->SetRaysPerSide(rays);

  // Abort from a progress observer.
  vtkNew<vtkVirtualLightField> aborted;
  aborted->SetInputConnection(box->GetOutputPort());
  SmallSettings(aborted);
  vtkNew<ProgressCounter> stopper;
  stopper->AbortAt = 2;
  stopper->Filter = aborted;
  aborted->AddObserver(vtkCommand::ProgressEvent, stopper);
  vtkNew<MessageCapture> abortMessages;
  abortMessages->Watch(aborted);
  aborted->Update();
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(aborted), nullptr);
  EXPECT_TRUE(abortMessages->HasWarning("aborted")) << abortMessages->AllWarnings();
}

} // namespace

// The field does not depend on how many threads vtkSMPTools runs: the work is split into a fixed
// number of blocks whose sums are combined in a fixed order (RunInBlocks), so one thread and
// four give the same energies bit for bit, iteration by iteration.
TEST(VLFVirtualLightField, SameFieldForOneAndFourSMPThreads)
{
  using namespace mesolight::vlf;
  LightFieldSettings settings;
  settings.Directions = 513;
  settings.RaysPerSide = 8;
  settings.TilesPerSide = 2;
  auto propagate = [&settings](int threads)
  {
    vtkSMPTools::Initialize(threads);
    std::unique_ptr<LightField> field = LightField::Build(mesolight::MakeCornellBox(), settings);
    Propagate(*field, 3);
    return field;
  };
  const std::unique_ptr<LightField> one = propagate(1);
  const std::unique_ptr<LightField> four = propagate(4);
  std::cout << "vtkSMPTools backend " << vtkSMPTools::GetBackend() << ", "
            << vtkSMPTools::GetEstimatedNumberOfThreads() << " threads for the second field\n";
  vtkSMPTools::Initialize(0);
  ASSERT_EQ(one->EnergyLog.size(), four->EnergyLog.size());
  for (std::size_t i = 0; i < one->EnergyLog.size(); ++i)
  {
    const LightField::IterationEnergy& a = one->EnergyLog[i];
    const LightField::IterationEnergy& b = four->EnergyLog[i];
    EXPECT_EQ(a.Shot, b.Shot) << "iteration " << i;
    EXPECT_EQ(a.Escaped, b.Escaped) << "iteration " << i;
    EXPECT_EQ(a.Absorbed, b.Absorbed) << "iteration " << i;
    EXPECT_EQ(a.BackFaces, b.BackFaces) << "iteration " << i;
    EXPECT_EQ(a.Unshot, b.Unshot) << "iteration " << i;
  }
}

// By default the filter shoots until at most ConvergenceTolerance of the emitted flux is left
// unshot; a fixed Iterations count still overrides it; a tolerance outside (0, 1) is refused.
TEST(VLFVirtualLightField, DefaultStopsAtTheTolerance)
{
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkVirtualLightField> filter;
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetDirections(33);
  filter->SetRaysPerSide(16);
  EXPECT_EQ(filter->GetIterations(), -1);
  filter->SetConvergenceTolerance(0.05);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  const mesolight::vlf::LightField& field = *vtkVirtualLightFieldCore::GetLightField(filter);
  std::cout << "tolerance 0.05: " << field.IterationsDone << " iterations, unshot "
            << mesolight::vlf::UnshotFraction(field) << "\n";
  EXPECT_LE(mesolight::vlf::UnshotFraction(field), 0.05);
  EXPECT_GT(field.IterationsDone, 1);
  filter->SetIterations(1);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter)->IterationsDone, 1);
  EXPECT_GT(mesolight::vlf::UnshotFraction(*vtkVirtualLightFieldCore::GetLightField(filter)), 0.05);
  filter->SetIterations(-1);
  filter->SetConvergenceTolerance(0.0);
  vtkNew<MessageCapture> messages;
  messages->Watch(filter);
  filter->Update();
  EXPECT_TRUE(messages->HasError("ConvergenceTolerance")) << messages->AllErrors();
}

// Directions and RaysPerSide default to 0, automatic (AutomaticSettings.h): directions left
// automatic follow the lines given (16 lines: 513 directions; 48: 2049), a given count is kept,
// and a negative count is an error, not an automatic choice.
TEST(VLFVirtualLightField, AutomaticDirectionsFollowTheLines)
{
  vtkNew<vtkCornellBoxSource> box;
  vtkNew<vtkVirtualLightField> filter;
  EXPECT_EQ(filter->GetDirections(), 0);
  EXPECT_EQ(filter->GetRaysPerSide(), 0);
  filter->SetInputConnection(box->GetOutputPort());
  filter->SetRaysPerSide(16);
  filter->SetIterations(1);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter)->SubfieldCount(), 513u);
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter)->Settings().TilesPerSide, 2);
  filter->SetDirections(33);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter)->SubfieldCount(), 33u);
  // A negative count is said and clamped at the setter (it was stored and refused at Update),
  // as vtkReliefProperty's setters do; NaN is refused there.
  vtkNew<MessageCapture> messages;
  messages->Watch(filter);
  filter->SetDirections(-1);
  EXPECT_TRUE(messages->HasWarning("SetDirections: -1 is outside [0,")) << messages->AllWarnings();
  EXPECT_EQ(filter->GetDirections(), 0);
  filter->SetConvergenceTolerance(std::nan(""));
  EXPECT_TRUE(messages->HasError("SetConvergenceTolerance: NaN")) << messages->AllErrors();
  EXPECT_EQ(filter->GetConvergenceTolerance(), 0.01);
  // In the units the user set, naming nothing internal.
  filter->SetDirections(33);
  const double budget = filter->GetMemoryBudgetMiB();
  filter->SetMemoryBudgetMiB(0.0);
  messages->Clear();
  filter->Update();
  EXPECT_TRUE(messages->HasError("memory budget must be positive (it is 0 MiB)"))
    << messages->AllErrors();
  filter->SetMemoryBudgetMiB(budget);
  filter->SetDirections(7);
  messages->Clear();
  filter->Update();
  EXPECT_TRUE(messages->HasError("7 directions: a direction set holds 2n^2+1"))
    << messages->AllErrors();
  EXPECT_FALSE(messages->HasError("DirectionSet")) << messages->AllErrors();
}

// ContactTexelHalvings (LightFieldSettings::ContactTexelHalvings) on a box standing on a floor:
// each halving multiplies the texels of the floor (the one surface something stands on) by about
// four and leaves every other surface's alone; -1 (the default) resolves as `mesolight vlf
// propagate --contact-texels auto` does (ResolveAutomaticSettings: none with given lines, one
// with automatic lines and the gather, where a filter reading -1 as 0 fails); a value outside
// [-1, 3] is an error and no field.
TEST(VLFVirtualLightField, ContactTexelHalvingsRefineTheFloorUnderABox)
{
  using namespace mesolight;
  TriangleScene scene = vlf::MakeEmitterOverFloor(0.4f, 1.0f, 2.0f, 0.5f, 10.0f);
  SceneMaterial white;
  white.Name = "box";
  white.Diffuse = glm::vec3(0.5f);
  vlftest::AddBox(scene, glm::vec3(0.3f, -0.06f, 0.0f), glm::vec3(0.42f, 0.06f, 0.1f),
    scene.AddMaterial(white), false);
  vtkNew<vtkTriangleSceneConverter> converter;
  vtkSmartPointer<vtkPolyData> input = converter->ToPolyData(scene);

  vtkNew<vtkVirtualLightField> filter;
  EXPECT_EQ(filter->GetContactTexelHalvings(), -1);
  filter->SetInputData(input);
  filter->SetDirections(513);
  filter->SetRaysPerSide(32);
  filter->SetTiles(4);
  filter->SetIterations(0);
  filter->SetFinalGather(false);
  // Each surface's texel count in the field of the last update.
  const auto texels = [&]()
  {
    std::vector<std::size_t> counts;
    const vlf::LightField* field = vtkVirtualLightFieldCore::GetLightField(filter);
    for (const vlf::Surface& s : field ? field->Surfaces() : std::vector<vlf::Surface>())
    {
      counts.push_back(s.TexelCount());
    }
    return counts;
  };
  std::vector<std::vector<std::size_t>> perHalving;
  for (int halvings = 0; halvings <= 2; ++halvings)
  {
    filter->SetContactTexelHalvings(halvings);
    filter->Update();
    ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
    EXPECT_EQ(
      vtkVirtualLightFieldCore::GetLightField(filter)->Settings().ContactTexelHalvings, halvings);
    perHalving.push_back(texels());
  }
  ASSERT_EQ(perHalving[0].size(), perHalving[1].size());
  ASSERT_EQ(perHalving[0].size(), perHalving[2].size());
  int finer = 0;
  for (std::size_t i = 0; i < perHalving[0].size(); ++i)
  {
    const double once = static_cast<double>(perHalving[1][i]) / perHalving[0][i];
    const double twice = static_cast<double>(perHalving[2][i]) / perHalving[0][i];
    if (once != 1.0 || twice != 1.0)
    {
      ++finer;
      std::cout << "surface " << i << ": " << perHalving[0][i] << " texels, halved once "
                << perHalving[1][i] << ", twice " << perHalving[2][i] << "\n";
      EXPECT_GE(once, 3.0);
      EXPECT_LE(once, 5.0);
      EXPECT_GE(twice, 12.0);
      EXPECT_LE(twice, 20.0);
    }
  }
  EXPECT_EQ(finer, 1); // the floor

  // -1: as the command line's auto. Lines given: no halving (the uniform texels).
  filter->SetContactTexelHalvings(-1);
  filter->Update();
  EXPECT_EQ(texels(), perHalving[0]);
  // Automatic lines with the gather: the command line's choice, one halving on this scene. (No
  // iterations and one gather ray: only the settings matter here.)
  filter->SetDirections(0);
  filter->SetRaysPerSide(0);
  filter->SetTiles(0);
  filter->SetFinalGather(true);
  filter->SetFinalGatherRays(1);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  vlf::LightFieldSettings requested;
  requested.Directions = 0;
  requested.RaysPerSide = 0;
  requested.TilesPerSide = 0;
  requested.MemoryBudget = static_cast<std::uint64_t>(filter->GetMemoryBudget());
  const vlf::AutomaticChoice commandLine = vlf::ResolveAutomaticSettings(scene, requested, true,
    vlf::AutomaticContactTexelHalvings); // VlfPropagateCommand.cxx, `--contact-texels auto`
  const vlf::LightFieldSettings& chosen =
    vtkVirtualLightFieldCore::GetLightField(filter)->Settings();
  std::cout << "automatic: " << commandLine.Describe() << "\n";
  EXPECT_EQ(commandLine.Settings.ContactTexelHalvings, 1);
  EXPECT_EQ(chosen.ContactTexelHalvings, commandLine.Settings.ContactTexelHalvings);
  EXPECT_EQ(chosen.Directions, commandLine.Settings.Directions);
  EXPECT_EQ(chosen.RaysPerSide, commandLine.Settings.RaysPerSide);
  // By default the contact texels alone; asked for, the texels refined from the light on top of
  // them (AdaptiveTexels.h): every surface at least as fine as the contact texels make it.
  EXPECT_FALSE(filter->GetAdaptiveTexels());
  EXPECT_TRUE(chosen.SurfaceTexelLevels.empty());
  const std::vector<std::size_t> contactTexels = texels();
  filter->SetAdaptiveTexels(true);
  filter->Update();
  ASSERT_NE(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  const vlf::LightFieldSettings& adaptiveSettings =
    vtkVirtualLightFieldCore::GetLightField(filter)->Settings();
  ASSERT_EQ(adaptiveSettings.SurfaceTexelLevels.size(), perHalving[0].size());
  const std::vector<std::size_t> adaptiveTexels = texels();
  std::size_t finerThanContact = 0;
  for (std::size_t i = 0; i < adaptiveTexels.size(); ++i)
  {
    EXPECT_LE(adaptiveSettings.SurfaceTexelLevels[i], 0) << "surface " << i;
    EXPECT_GE(adaptiveTexels[i], contactTexels[i]) << "surface " << i;
    finerThanContact += adaptiveTexels[i] > contactTexels[i] ? 1 : 0;
  }
  std::cout << "adaptive texels: " << finerThanContact
            << " surfaces finer than the contact texels\n";
  filter->SetAdaptiveTexels(false);

  // Outside [-1, 3]: an error, no field.
  for (const int bad : { -2, vlf::MaxContactTexelHalvings + 1 })
  {
    filter->SetContactTexelHalvings(bad);
    vtkNew<MessageCapture> messages;
    messages->Watch(filter);
    filter->Update();
    EXPECT_TRUE(messages->HasError("ContactTexelHalvings")) << messages->AllErrors();
    EXPECT_EQ(vtkVirtualLightFieldCore::GetLightField(filter), nullptr);
  }
  std::ostringstream printed;
  filter->Print(printed);
  EXPECT_NE(printed.str().find("ContactTexelHalvings: 4"), std::string::npos);
}
