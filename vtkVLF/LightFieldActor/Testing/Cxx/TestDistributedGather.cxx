// SPDX-License-Identifier: BSD-3-Clause
// Downstream of a light field distributed over MPI ranks (Distribution.h), run under
// `mpiexec -n N` (ctest: 1, 2 and 3 ranks). Every rank also builds the serial pipeline itself (a
// vtkVirtualLightField asked for piece 0 of 1 propagates alone, and Light Field Gather on the
// whole sphere), the reference the distributed one must equal:
//   - vtkVirtualLightField's output: each rank its piece of the triangles (together every triangle
//     once, the cell radiance equal to the serial output's), each with the whole atlas (equal to
//     the serial atlas); no rank holds every direction's maps;
//   - vtkLightFieldGatherFilter on a sphere split across the ranks: every point's irradiance equals
//     the serial gather's (matched by position), no field sent between ranks; a concave object
//     (the object's own occlusion) too;
//   - negative: one rank's directions alone (ObjectGatherer without the sum) differ;
//   - a relief's visible-share map with its rows split over the ranks (ReliefVisibleShareGrid
//     with a reducer) equals the one-process map bit for bit; without the float sums (each rank's
//     rows alone) it does not; a stop on one rank stops every rank (AbortedError everywhere).
// Exit 0 when every check holds on this rank.
#include "vtkAppendPolyData.h"
#include "vtkCellData.h"
#include "vtkCornellBoxSource.h"
#include "vtkDataArray.h"
#include "vtkFieldData.h"
#include "vtkFloatArray.h"
#include "vtkLightFieldGatherFilter.h"
#include "vtkLightFieldReducer.h"
#include "vtkNew.h"
#include "vtkPointData.h"
#include "vtkPolyData.h"
#include "vtkSphereSource.h"
#include "vtkTriangleSceneConverter.h"
#include "vtkVirtualLightField.h"
#include "vtkVirtualLightFieldCore.h"

#include "HeightFieldTracer.h"
#include "LightField.h"
#include "ObjectGatherer.h"
#include "ObjectShadows.h"
#include "ReliefOcclusion.h"
#include "ReliefSurface.h"

#include "DistributedTestRun.h"  // tests/support
#include "NotCombiningReducer.h" // tests/support

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <map>
#include <string>
#include <tuple>
#include <vector>

namespace
{
namespace vlf = mesolight::vlf;

using mesolight_test::Check;
using mesolight_test::Failures;
using mesolight_test::Rank;

void Configure(vtkVirtualLightField* field, vtkAlgorithmOutput* scene)
{
  field->SetInputConnection(scene);
  field->SetDirections(129);
  field->SetRaysPerSide(16);
  field->SetIterations(3);
}

using Key = std::tuple<long, long, long>;
Key KeyOf(const double p[3])
{
  return Key(std::lround(p[0] * 1000.0), std::lround(p[1] * 1000.0), std::lround(p[2] * 1000.0));
}

// Worst relative difference of array `name` at each of a's points against b's point at the same
// position; missing counts a's points without a twin in b.
double WorstByPosition(vtkPolyData* a, vtkPolyData* b, const char* name, int& missing)
{
  std::map<Key, vtkIdType> index;
  for (vtkIdType i = 0; i < b->GetNumberOfPoints(); ++i)
  {
    index[KeyOf(b->GetPoint(i))] = i;
  }
  vtkDataArray* x = a->GetPointData()->GetArray(name);
  vtkDataArray* y = b->GetPointData()->GetArray(name);
  missing = 0;
  if (!x || !y)
  {
    missing = -1;
    return 1e30;
  }
  double worst = 0.0;
  for (vtkIdType i = 0; i < a->GetNumberOfPoints(); ++i)
  {
    const auto found = index.find(KeyOf(a->GetPoint(i)));
    if (found == index.end())
    {
      ++missing;
      continue;
    }
    for (int c = 0; c < 3; ++c)
    {
      const double u = x->GetComponent(i, c), v = y->GetComponent(found->second, c);
      worst = std::max(worst, std::abs(u - v) / std::max({ std::abs(u), std::abs(v), 1e-6 }));
    }
  }
  return worst;
}

// A concave object (a bowl: a hemisphere open at the top, both sides gathered) exercises the
// object's own occlusion, whose inter-reflection iterations follow the reduced sums.
void MakeBowl(vtkSphereSource* bowl)
{
  bowl->SetCenter(200.0, 200.0, 300.0);
  bowl->SetRadius(70.0);
  bowl->SetThetaResolution(16);
  bowl->SetPhiResolution(10);
  bowl->SetStartPhi(90.0); // the lower half
  bowl->SetEndPhi(180.0);
}

int Run(vtkMultiProcessController* controller)
{
  const int ranks = controller->GetNumberOfProcesses();
  vtkNew<vtkCornellBoxSource> box;

  // The serial reference on every rank (piece 0 of 1: this rank propagates alone). Light Field
  // Gather under MPI with a whole field on every rank: rank 0's is broadcast (the old path).
  vtkNew<vtkVirtualLightField> serialField;
  Configure(serialField, box->GetOutputPort());
  serialField->DistributeDirectionsOff(); // piece 0 of 1 is serial anyway; explicit
  serialField->Update();
  vtkPolyData* serialOut = serialField->GetOutput();

  // The distributed field: each rank asks for its own piece.
  vtkNew<vtkVirtualLightField> field;
  Configure(field, box->GetOutputPort());
  field->UpdatePiece(Rank, ranks, 0);
  vtkPolyData* piece = field->GetOutput();
  const vlf::LightField* core = vtkVirtualLightFieldCore::GetLightField(field);
  Check(core != nullptr, "every rank keeps its field");
  if (!core)
  {
    return Failures;
  }
  std::size_t held = 0;
  for (std::size_t k = 0; k < core->SubfieldCount(); ++k)
  {
    held += core->OwnsSubfield(k) && !core->GetSubfield(k).TileStart.empty() ? 1 : 0;
  }
  std::printf("rank %d of %d: holds %zu of %zu directions' maps, %lld of %lld triangles\n", Rank,
    ranks, held, core->SubfieldCount(), static_cast<long long>(piece->GetNumberOfCells()),
    static_cast<long long>(serialOut->GetNumberOfCells()));
  if (ranks > 1)
  {
    Check(held < core->SubfieldCount(), "no rank holds every direction's maps");
    double irradiance[3];
    const double p[3] = { 278.0, 100.0, 280.0 }, n[3] = { 0.0, 1.0, 0.0 };
    Check(!field->ComputeIrradiance(p, n, irradiance),
      "ComputeIrradiance refuses a distributed field (a rank holds part of it)");
  }
  // The pieces together: every triangle once, in order, with the serial cell radiance.
  vtkNew<vtkPolyData> mine;
  mine->ShallowCopy(piece);
  std::vector<vtkSmartPointer<vtkDataObject>> pieces;
  controller->AllGather(mine, pieces);
  vtkNew<vtkAppendPolyData> append;
  for (const auto& p : pieces)
  {
    auto* poly = vtkPolyData::SafeDownCast(p);
    if (poly && poly->GetNumberOfCells() > 0)
    {
      append->AddInputData(poly);
    }
  }
  append->Update();
  vtkPolyData* whole = append->GetOutput();
  Check(whole->GetNumberOfCells() == serialOut->GetNumberOfCells(),
    "the pieces hold every triangle once");
  vtkDataArray* a = whole->GetCellData()->GetArray("Radiance");
  vtkDataArray* b = serialOut->GetCellData()->GetArray("Radiance");
  double worstCell = a && b && a->GetNumberOfTuples() == b->GetNumberOfTuples() ? 0.0 : 1e30;
  for (vtkIdType c = 0; worstCell < 1e30 && c < a->GetNumberOfTuples(); ++c)
  {
    for (int q = 0; q < 3; ++q)
    {
      const double u = a->GetComponent(c, q), v = b->GetComponent(c, q);
      worstCell =
        std::max(worstCell, std::abs(u - v) / std::max({ std::abs(u), std::abs(v), 1e-9 }));
    }
  }
  // The atlas on this rank's piece: whole, equal to the serial atlas.
  int sizeA[2] = { 0, 0 }, sizeB[2] = { 0, 0 };
  vtkFloatArray* atlas = vtkVirtualLightField::GetAttachedAtlas(piece, sizeA);
  vtkFloatArray* serialAtlas = vtkVirtualLightField::GetAttachedAtlas(serialOut, sizeB);
  double worstAtlas =
    atlas && serialAtlas && sizeA[0] == sizeB[0] && sizeA[1] == sizeB[1] ? 0.0 : 1e30;
  for (vtkIdType i = 0; worstAtlas < 1e30 && i < atlas->GetNumberOfValues(); ++i)
  {
    const double u = atlas->GetValue(i), v = serialAtlas->GetValue(i);
    worstAtlas =
      std::max(worstAtlas, std::abs(u - v) / std::max({ std::abs(u), std::abs(v), 1e-9 }));
  }
  std::printf("rank %d of %d: output pieces vs serial: cell radiance worst %.3g, atlas (%dx%d) "
              "worst %.3g\n",
    Rank, ranks, worstCell, sizeA[0], sizeA[1], worstAtlas);
  Check(worstCell <= 1e-5, "the pieces' cell radiance equals the serial output's");
  Check(worstAtlas <= 1e-5, "every rank's atlas equals the serial atlas");

  // Light Field Gather: a sphere (convex) and a bowl (concave), split across the ranks.
  for (int object = 0; object < 2; ++object)
  {
    vtkNew<vtkSphereSource> shape;
    if (object == 0)
    {
      shape->SetCenter(278.0, 250.0, 280.0);
      shape->SetRadius(60.0);
      shape->SetThetaResolution(24);
      shape->SetPhiResolution(12);
    }
    else
    {
      MakeBowl(shape);
    }
    const char* name = object == 0 ? "sphere" : "bowl";
    vtkNew<vtkLightFieldGatherFilter> serialGather;
    serialGather->SetInputConnection(shape->GetOutputPort());
    serialGather->SetLightFieldConnection(serialField->GetOutputPort());
    serialGather->Update(); // piece 0 of 1 on every rank: the whole object
    vtkNew<vtkLightFieldGatherFilter> gather;
    gather->SetInputConnection(shape->GetOutputPort());
    gather->SetLightFieldConnection(field->GetOutputPort());
    gather->UpdatePiece(Rank, ranks, 0);
    vtkPolyData* out = gather->GetOutput();
    int missing = 0;
    const double worst = WorstByPosition(out, serialGather->GetOutput(), "Irradiance", missing);
    std::printf("rank %d of %d: gather (%s): %lld points of %lld, worst relative difference %.3g, "
                "%d without a serial twin; propagations %d, broadcasts %d, distributed %d\n",
      Rank, ranks, name, static_cast<long long>(out->GetNumberOfPoints()),
      static_cast<long long>(serialGather->GetOutput()->GetNumberOfPoints()), worst, missing,
      gather->GetFieldPropagations(), gather->GetFieldBroadcasts(),
      gather->GetFieldDistributed() ? 1 : 0);
    Check(missing == 0, std::string("every gathered point has its serial twin (") + name + ")");
    Check(worst <= 1e-5, std::string("the gather equals the serial gather (") + name + ")");
    Check(ranks == 1 || out->GetNumberOfPoints() < serialGather->GetOutput()->GetNumberOfPoints(),
      std::string("each rank outputs its own piece (") + name + ")");
    Check(gather->GetFieldBroadcasts() == 0, "no field sent between the ranks");
    Check(gather->GetFieldDistributed() == (ranks > 1), "the field is distributed over the ranks");
  }

  // Negative: this rank's directions alone (no sum over the ranks) differ from the serial gather.
  if (ranks > 1)
  {
    vtkNew<vtkSphereSource> sphere;
    sphere->SetCenter(278.0, 250.0, 280.0);
    sphere->SetRadius(60.0);
    sphere->Update();
    vlf::ObjectMesh mesh;
    vtkTriangleSceneConverter::ToTriangleMesh(sphere->GetOutput(), mesh);
    mesh.TextureCoordinates.clear();
    vlf::GatherSettings settings;
    settings.UseCache = false;
    settings.ObjectOcclusion = false;
    vlf::ObjectGatherer alone(*core); // no reducer: this rank's directions only
    vlf::ControllerReducer reducer(controller);
    vlf::ObjectGatherer together(*core, &reducer);
    const glm::mat4 toUnit = vlf::WorldToUnitSphere(*core);
    const std::vector<glm::vec3> partial = alone.Gather(mesh, toUnit, settings).Irradiance;
    const std::vector<glm::vec3> summed = together.Gather(mesh, toUnit, settings).Irradiance;
    double worst = 0.0;
    for (std::size_t i = 0; i < partial.size(); ++i)
    {
      for (int c = 0; c < 3; ++c)
      {
        worst = std::max(worst,
          static_cast<double>(
            std::abs(partial[i][c] - summed[i][c]) / std::max(1e-6f, std::abs(summed[i][c]))));
      }
    }
    std::printf("rank %d of %d: one rank's directions alone: worst relative difference %.3g\n",
      Rank, ranks, worst);
    Check(worst > 1e-2, "one rank's directions alone differ (the comparison can fail)");
  }
  return Failures;
}

// The relief's visible-share map (vtkLightFieldReliefSurface's, ParaView's Relief Surface) split
// by rows over the ranks against the one-process map every rank also computes: V-grooves walled
// as the command line's reliefs, 37 rows (a multiple of neither 2 nor 3).
int ShareMap(vtkMultiProcessController* controller)
{
  vlf::ControllerReducer reducer(controller);
  const int ranks = reducer.Size();
  const int w = 64, h = 37;
  std::vector<float> depth(static_cast<std::size_t>(w) * h);
  for (int j = 0; j < h; ++j)
  {
    for (int i = 0; i < w; ++i)
    {
      const double offset = std::abs((i % 16) * 2 + 1 - 16);
      depth[static_cast<std::size_t>(j) * w + i] =
        static_cast<float>(std::clamp(1.0 - offset / 12.0, 0.0, 1.0));
    }
  }
  const mesolight::HeightField relief(w, h, depth, mesolight::HeightField::Edge::Walled);
  vlf::ReliefSurface surface; // the unit square, facing +z
  surface.Origin = glm::dvec3(0.0);
  surface.AxisU = glm::dvec3(1.0, 0.0, 0.0);
  surface.AxisV = glm::dvec3(0.0, 1.0, 0.0);
  surface.Normal = glm::dvec3(0.0, 0.0, 1.0);
  const mesolight::ReliefFrame frame = vlf::ReliefFrameOf(surface, 0.1);
  // A small area light low over the grooves, so that the fourth value (the relief's shadow of
  // it, ReliefEmitterShadowMap) is split too.
  std::vector<mesolight::ReliefEmitterSample> light;
  for (int k = 0; k < 4; ++k)
  {
    mesolight::ReliefEmitterSample sample;
    sample.Position = glm::dvec3(-0.5 + 0.05 * (k % 2), 0.5 + 0.05 * (k / 2), 0.4);
    sample.Normal = glm::normalize(glm::dvec3(1.0, 0.0, -0.4));
    sample.RadianceArea = glm::dvec3(0.25);
    light.push_back(sample);
  }
  int sw = 0, sh = 0, width = 0, height = 0;
  // With the side walls' map (the grooves end at the walled borders v = 0 and 1), split too.
  std::vector<float> serialWalls, splitWalls;
  const std::vector<float> serial =
    vlf::ReliefVisibleShareGrid(relief, frame, sw, sh, {}, light, nullptr, &serialWalls);
  const std::vector<float> split =
    vlf::ReliefVisibleShareGrid(relief, frame, width, height, {}, light, &reducer, &splitWalls);
  Check(width == sw && height == sh && split.size() == serial.size(), "the same grid");
  Check(!serialWalls.empty() && splitWalls == serialWalls,
    "the split side walls' map equals the one-process map bit for bit");
  const float lowest = *std::min_element(serial.begin(), serial.end());
  std::size_t differing = 0;
  for (std::size_t k = 0; k < std::min(split.size(), serial.size()); ++k)
  {
    differing += split[k] != serial[k] ? 1 : 0;
  }
  std::printf("rank %d of %d: visible-share map %d x %d split by rows: %zu of %zu values differ "
              "from the one-process map (lowest value %.3f)\n",
    Rank, ranks, width, height, differing, serial.size(), lowest);
  Check(lowest < 0.9f, "the grooves hide part of the hemisphere");
  Check(differing == 0, "the split map equals the one-process map bit for bit");
  if (ranks > 1)
  {
    mesolight_test::NotCombiningReducer alone(reducer);
    std::vector<float> ownWalls;
    const std::vector<float> own =
      vlf::ReliefVisibleShareGrid(relief, frame, width, height, {}, light, &alone, &ownWalls);
    Check(ownWalls.size() == serialWalls.size() && ownWalls != serialWalls,
      "a rank's rows of the side walls alone differ");
    std::size_t zero = 0;
    for (std::size_t k = 0; k < own.size(); ++k)
    {
      zero += own[k] != serial[k] ? 1 : 0;
    }
    std::printf("rank %d of %d: this rank's rows alone: %zu values differ\n", Rank, ranks, zero);
    Check(zero > own.size() / 3, "a rank's rows alone differ (the comparison can fail)");
    // A stop on the last rank only: every rank stops, none waits for it in a sum.
    bool aborted = false;
    try
    {
      vlf::ReliefVisibleShareGrid(
        relief, frame, width, height,
        [&](double fraction) { return !(Rank == ranks - 1 && fraction > 0.2); }, light, &reducer);
    }
    catch (const vlf::AbortedError&)
    {
      aborted = true;
    }
    Check(aborted, "a stop on one rank stops every rank (AbortedError)");
  }
  return Failures;
}
} // namespace

int main(int argc, char* argv[])
{
  return mesolight_test::RunDistributedTest(argc, argv,
    [](vtkMultiProcessController* controller, int, char**)
    {
      Run(controller);
      ShareMap(controller);
      return Failures; // both parts' checks
    });
}
