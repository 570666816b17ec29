// SPDX-License-Identifier: BSD-3-Clause
// The distributed light field (Distribution.h) against the serial one, run under
// `mpiexec -n N` (ctest runs it at 1, 2, 3, 4 and 8 ranks). Every rank also propagates the serial
// field itself (the reference, independent of any reduction) and compares every texel.
//
//   TestDistributedPropagation equal DIR   distributed == serial (textures, energy, snapshot,
//                                          gathered irradiance); without the reductions they
//                                          must differ
//   TestDistributedPropagation fail        one rank's memory budget refused, one rank aborting:
//                                          every rank stops with the failing rank's message
//   TestDistributedPropagation compare A B two snapshots' total diffuse textures equal (1e-5)
//   TestDistributedPropagation mirror OBJ DIR  a scene with mirrors (OBJ/MTL): the mirrored
//                                          radiance crosses to the owners of the mirrored
//                                          directions; textures, every direction's radiance and
//                                          unshot specular maps, the energy, and the mirrors'
//                                          lookups (each rank asking its own points) equal the
//                                          serial field's; a rank's own answers alone differ
//   TestDistributedPropagation gather OBJ  the final gather split over the ranks (FinalGather.h)
//                                          on a scene with mirrors, the floor under its blocks
//                                          at finer texels: equal to the serial gather,
//                                          bit for bit to this rank's own gather of the same
//                                          field; every texel gathered by exactly one rank, the
//                                          shares balanced; an abort on one rank stops all; with
//                                          the shares not combined the textures differ
// Exit 0 when every check holds on this rank.
#include "Distribution.h"
#include "FinalGather.h"
#include "LightField.h"
#include "Lookup.h"
#include "ObjScene.h"
#include "Propagation.h"
#include "Snapshot.h"
#include "TriangleScene.h"
#include "vtkLightFieldReducer.h"

#include "DistributedTestRun.h"  // tests/support
#include "NotCombiningReducer.h" // tests/support

#include <glm/geometric.hpp>
#include <vtkNew.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <iostream>
#include <string>

namespace
{
namespace vlf = mesolight::vlf;

using mesolight_test::Check;
using mesolight_test::Failures;
using mesolight_test::Rank;

vlf::LightFieldSettings SmallSettings()
{
  vlf::LightFieldSettings s;
  s.Directions = 129; // 2 * 8^2 + 1
  s.RaysPerSide = 16;
  s.TilesPerSide = 2;
  return s;
}

// Largest relative difference over every texel and channel (a texel below a billionth of the
// brightest is compared against that floor, so that two zeros agree).
double WorstRelative(const std::vector<glm::vec3>& a, const std::vector<glm::vec3>& b)
{
  if (a.size() != b.size())
  {
    return 1e30;
  }
  float brightest = 0.0f;
  for (const glm::vec3& v : a)
  {
    brightest = std::max({ brightest, v.x, v.y, v.z });
  }
  const double floor = 1e-9 * static_cast<double>(brightest);
  double worst = 0.0;
  for (std::size_t t = 0; t < a.size(); ++t)
  {
    for (int c = 0; c < 3; ++c)
    {
      const double x = a[t][c], y = b[t][c];
      worst = std::max(worst, std::abs(x - y) / std::max({ std::abs(x), std::abs(y), floor }));
    }
  }
  return worst;
}

int Equal(vtkMultiProcessController* controller, const std::string& dir)
{
  vlf::ControllerReducer reducer(controller);
  const int ranks = reducer.Size();
  const mesolight::TriangleScene scene = mesolight::MakeCornellBox();
  const int iterations = 3;
  std::unique_ptr<vlf::LightField> serial = vlf::LightField::Build(scene, SmallSettings());
  vlf::Propagate(*serial, iterations);

  std::unique_ptr<vlf::LightField> field =
    vlf::LightField::Build(scene, SmallSettings(), {}, &reducer);
  // This rank traced its share only; together the ranks traced every direction once.
  std::vector<double> held(field->SubfieldCount(), 0.0);
  for (std::size_t k = 0; k < field->SubfieldCount(); ++k)
  {
    const bool owns = field->OwnsSubfield(k);
    held[k] = owns ? 1.0 : 0.0;
    Check(owns == !field->GetSubfield(k).TileStart.empty(),
      "direction " + std::to_string(k) + ": maps held iff owned");
  }
  reducer.SumInPlace(held.data(), held.size());
  Check(std::all_of(held.begin(), held.end(), [](double h) { return h == 1.0; }),
    "every direction owned by exactly one rank");
  Check(
    WorstRelative(std::vector<glm::vec3>(serial->Capacity.size()), std::vector<glm::vec3>()) > 1.0,
    "the comparison sees a size mismatch");
  for (std::size_t t = 0; t < field->Capacity.size(); ++t)
  {
    const float a = field->Capacity[t], b = serial->Capacity[t];
    if (std::abs(a - b) > 1e-5f * std::max(std::abs(a), std::abs(b)))
    {
      Check(false, "capacity of texel " + std::to_string(t));
      break;
    }
  }
  // Balance: the estimated cost of each rank's share within 5% of the mean (129 directions).
  const std::vector<double> cost = vlf::DirectionCosts(*field);
  double mine = 0.0, total = 0.0;
  for (std::size_t k = 0; k < cost.size(); ++k)
  {
    total += cost[k];
    mine += field->OwnsSubfield(k) ? cost[k] : 0.0;
  }
  Check(std::abs(mine - total / ranks) <= 0.05 * total / ranks,
    "balanced share: " + std::to_string(mine) + " of " + std::to_string(total));

  vlf::PropagationOptions options;
  options.Reduce = &reducer;
  const std::string snapshot = dir + "/distributed-" + std::to_string(ranks) + ".vlf";
  // Snapshot batches: the default (everything in one here), one subfield each, and several
  // subfields each (the last, which is read back below).
  const std::size_t batches[] = { 0, 1, 20000 };
  vlf::Propagate(*field, iterations, options,
    [&](const vlf::LightField& f)
    {
      vlf::WriteDistributedSnapshot(
        *field, snapshot, reducer, batches[static_cast<std::size_t>(f.IterationsDone - 1) % 3]);
    });
  const double worst = WorstRelative(field->TotalDiffuse, serial->TotalDiffuse);
  std::printf("rank %d of %d: worst relative texel difference %.3g (unshot %.3g)\n", Rank, ranks,
    worst, WorstRelative(field->UnshotDiffuse, serial->UnshotDiffuse));
  Check(worst <= 1e-5, "total diffuse equals the serial field within 1e-5");
  Check(WorstRelative(field->UnshotDiffuse, serial->UnshotDiffuse) <= 1e-5, "unshot diffuse");
  for (int c = 0; c < 3; ++c)
  {
    const double a = field->EnergyLog.back().Shot[c], b = serial->EnergyLog.back().Shot[c];
    Check(std::abs(a - b) <= 1e-5 * std::abs(b), "energy shot in the last iteration");
  }
  // The snapshot rank 0 wrote holds every direction's maps, equal to the serial field's.
  controller->Barrier();
  std::unique_ptr<vlf::LightField> read = vlf::ReadSnapshot(snapshot);
  Check(WorstRelative(read->TotalDiffuse, serial->TotalDiffuse) <= 1e-5, "snapshot textures");
  double worstMap = 0.0;
  for (std::size_t k = 0; k < read->SubfieldCount(); ++k)
  {
    Check(read->GetSubfield(k).Depth == serial->GetSubfield(k).Depth,
      "snapshot depths of direction " + std::to_string(k));
    worstMap = std::max(worstMap,
      WorstRelative(
        read->GetSubfield(k).Radiance.ToVector(), serial->GetSubfield(k).Radiance.ToVector()));
  }
  Check(worstMap <= 1e-5, "snapshot radiance maps (worst " + std::to_string(worstMap) + ")");
  // Read as a resuming rank does: its own maps only, equal to the serial ones, the others empty.
  std::unique_ptr<vlf::LightField> share = vlf::ReadOwnedSubfields(snapshot, 0, reducer);
  Check(WorstRelative(share->TotalDiffuse, serial->TotalDiffuse) <= 1e-5, "share's textures");
  for (std::size_t k = 0; k < share->SubfieldCount(); ++k)
  {
    const bool owns = field->OwnsSubfield(k);
    Check(share->OwnsSubfield(k) == owns, "the share owns what the split gives this rank");
    Check(owns
        ? share->GetSubfield(k).Radiance == read->GetSubfield(k).Radiance &&
          share->GetSubfield(k).Depth == read->GetSubfield(k).Depth
        : share->GetSubfield(k).Radiance.empty() && share->GetSubfield(k).Depth.Start.empty(),
      "the share's maps of direction " + std::to_string(k) + " (held iff owned)");
  }
  if (ranks > 1)
  {
    Check(2 * share->AllocatedBytes() < read->AllocatedBytes() + read->AllocatedBytes() / ranks,
      "a share holds about 1/" + std::to_string(ranks) + " of the field: " +
        std::to_string(share->AllocatedBytes()) + " of " + std::to_string(read->AllocatedBytes()));
  }

  // Gathering (a movable object's points): the ranks' sums over their directions, reduced, equal
  // the serial gather over every direction; without the reduction a rank has its share only.
  std::vector<glm::vec3> points, normals;
  for (int i = 0; i < 64; ++i)
  {
    const float a = 0.1f * static_cast<float>(i);
    points.emplace_back(
      0.4f * std::cos(a), -0.3f + 0.01f * static_cast<float>(i), 0.4f * std::sin(a));
    normals.push_back(glm::normalize(glm::vec3(std::sin(3.0f * a), std::cos(a), 0.5f)));
  }
  const std::vector<glm::vec3> gathered = vlf::GatherIrradiance(*field, points, normals, reducer);
  std::vector<glm::vec3> reference, partial;
  const vlf::Lookup serialLookup(*serial), ownLookup(*field);
  for (std::size_t i = 0; i < points.size(); ++i)
  {
    reference.push_back(serialLookup.Irradiance(points[i], normals[i]));
    partial.push_back(ownLookup.Irradiance(points[i], normals[i]));
  }
  const double worstGather = WorstRelative(gathered, reference);
  std::printf("rank %d of %d: gather at %zu points, worst relative difference %.3g\n", Rank, ranks,
    points.size(), worstGather);
  Check(worstGather <= 1e-5, "the reduced gather equals the serial gather");
  if (ranks > 1)
  {
    Check(WorstRelative(partial, reference) > 1e-2, "a rank's own directions alone differ");
  }

  // Negative case: without the reduction each rank has only its share of the light.
  if (ranks > 1)
  {
    std::unique_ptr<vlf::LightField> alone =
      vlf::LightField::Build(scene, SmallSettings(), {}, &reducer);
    vlf::PropagationOptions none; // no Reduce: each rank shoots its directions only
    vlf::Propagate(*alone, iterations, none);
    Check(WorstRelative(alone->TotalDiffuse, serial->TotalDiffuse) > 1e-2,
      "without the reduction the field differs (the comparison can fail)");
  }
  return Failures;
}

// Runs step on every rank, expecting every rank to throw an error whose message contains want.
void ExpectAgreedFailure(
  const std::function<void()>& step, const std::string& want, const std::string& what)
{
  try
  {
    step();
    Check(false, what + ": no error");
  }
  catch (const std::exception& e)
  {
    std::printf("rank %d: %s: %s\n", Rank, what.c_str(), e.what());
    Check(std::string(e.what()).find(want) != std::string::npos,
      what + ": the message names '" + want + "'");
  }
}

int Fail(vtkMultiProcessController* controller)
{
  vlf::ControllerReducer reducer(controller);
  const int ranks = reducer.Size();
  const mesolight::TriangleScene scene = mesolight::MakeCornellBox();
  const int last = ranks - 1;
  // The last rank's budget is refused; the others would go on and wait in the capacity sum.
  vlf::LightFieldSettings settings = SmallSettings();
  if (Rank == last)
  {
    settings.MemoryBudget = 1 << 16;
  }
  const std::string rankName = ranks > 1 ? "rank " + std::to_string(last) + " of " : "";
  ExpectAgreedFailure([&]() { vlf::LightField::Build(scene, settings, {}, &reducer); },
    rankName + (ranks > 1 ? std::to_string(ranks) + ": " : "") + "the light field would need",
    "memory budget refused on one rank");
  // A bad scene on one rank (no emitter).
  mesolight::TriangleScene dark = scene;
  if (Rank == last)
  {
    for (mesolight::SceneMaterial& m : dark.Materials)
    {
      m.Emission = glm::vec3(0.0f);
    }
  }
  ExpectAgreedFailure([&]() { vlf::LightField::Build(dark, SmallSettings(), {}, &reducer); },
    "emitter", "a scene without an emitter on one rank");
  // One rank aborts during the second iteration: every rank stops (AbortedError).
  std::unique_ptr<vlf::LightField> field =
    vlf::LightField::Build(scene, SmallSettings(), {}, &reducer);
  vlf::PropagationOptions options;
  options.Reduce = &reducer;
  vlf::Propagate(*field, 1, options);
  options.Progress = [&](double) { return Rank != last; };
  ExpectAgreedFailure(
    [&]() { vlf::Propagate(*field, 2, options); }, "aborted", "abort on one rank");
  return Failures;
}

int Mirror(vtkMultiProcessController* controller, const std::string& obj, const std::string& dir)
{
  vlf::ControllerReducer reducer(controller);
  const int ranks = reducer.Size();
  const mesolight::TriangleScene scene = mesolight::ReadObjScene(obj).Scene;
  const int iterations = 4; // light through the mirror twice (emitter, wall, mirror, wall)
  std::unique_ptr<vlf::LightField> serial = vlf::LightField::Build(scene, SmallSettings());
  Check(serial->HasSpecular(), "the scene has mirrors");
  vlf::Propagate(*serial, iterations);

  std::unique_ptr<vlf::LightField> field =
    vlf::LightField::Build(scene, SmallSettings(), {}, &reducer);
  vlf::PropagationOptions options;
  options.Reduce = &reducer;
  const std::string snapshot = dir + "/mirror-" + std::to_string(ranks) + ".vlf";
  const std::uint64_t before = reducer.BytesContributed();
  vlf::Propagate(*field, iterations, options);
  const std::uint64_t propagationBytes = reducer.BytesContributed() - before;
  vlf::WriteDistributedSnapshot(*field, snapshot, reducer);
  const double worst = WorstRelative(field->TotalDiffuse, serial->TotalDiffuse);
  std::printf("rank %d of %d: mirrors: worst relative texel difference %.3g, %llu bytes sent in "
              "%d iterations\n",
    Rank, ranks, worst, static_cast<unsigned long long>(propagationBytes), iterations);
  Check(worst <= 1e-5, "total diffuse equals the serial field within 1e-5 (mirrors)");
  Check(WorstRelative(field->UnshotDiffuse, serial->UnshotDiffuse) <= 1e-5, "unshot diffuse");
  for (int c = 0; c < 3; ++c)
  {
    const auto& a = field->EnergyLog.back();
    const auto& b = serial->EnergyLog.back();
    Check(std::abs(a.Shot[c] - b.Shot[c]) <= 1e-5 * std::abs(b.Shot[c]), "energy shot");
    Check(std::abs(a.Unshot[c] - b.Unshot[c]) <= 1e-5 * std::abs(b.Unshot[c]), "energy unshot");
    Check(std::abs(a.SpecularLost[c] - b.SpecularLost[c]) <= 1e-5 * std::abs(b.Shot[c]),
      "mirrored flux lost");
  }
  // Every direction's maps (radiance sent, unshot mirrored radiance), as rank 0 wrote them.
  controller->Barrier();
  std::unique_ptr<vlf::LightField> read = vlf::ReadSnapshot(snapshot);
  double worstMap = 0.0, worstSpecular = 0.0;
  bool anySpecular = false;
  for (std::size_t k = 0; k < read->SubfieldCount(); ++k)
  {
    worstMap = std::max(worstMap,
      WorstRelative(
        read->GetSubfield(k).Radiance.ToVector(), serial->GetSubfield(k).Radiance.ToVector()));
    worstSpecular = std::max(worstSpecular,
      WorstRelative(read->GetSubfield(k).UnshotSpecular.ToVector(),
        serial->GetSubfield(k).UnshotSpecular.ToVector()));
    for (const glm::vec3& v : serial->GetSubfield(k).UnshotSpecular)
    {
      anySpecular = anySpecular || v.x > 0.0f;
    }
  }
  std::printf("rank %d of %d: mirrors: maps worst %.3g, unshot specular worst %.3g\n", Rank, ranks,
    worstMap, worstSpecular);
  Check(anySpecular, "the serial field holds unshot mirrored radiance (the check sees some)");
  Check(worstMap <= 1e-5, "radiance maps equal the serial field's (mirrors)");
  Check(worstSpecular <= 1e-5, "unshot specular maps equal the serial field's");

  // Lookups on the mirrors, each rank asking its own points (every ranks-th of a grid on each
  // mirror triangle, toward eyes in front of it), both direction interpolations.
  std::vector<vlf::RadianceQuery> queries;
  const mesolight::TriangleScene& unit = field->Scene();
  int index = 0;
  for (std::size_t t = 0; t < unit.Triangles.size(); ++t)
  {
    const std::uint32_t s = field->SurfaceOfTriangle(t);
    if (s == vlf::NoSurface || glm::length(field->MaterialOf(s).Specular) <= 0.0f)
    {
      continue;
    }
    const glm::vec3 normal = field->Surfaces()[s].Normal;
    for (int a = 1; a < 6; ++a)
    {
      for (int b = 1; b < 6 - a; ++b, ++index)
      {
        if (index % ranks != Rank)
        {
          continue;
        }
        const float u = 0.18f * static_cast<float>(a), v = 0.18f * static_cast<float>(b);
        const glm::vec3 p =
          (1.0f - u - v) * unit.Vertex(t, 0) + u * unit.Vertex(t, 1) + v * unit.Vertex(t, 2);
        const glm::vec3 side = glm::normalize(glm::cross(normal, glm::vec3(0.3f, 0.5f, 0.8f)));
        const float turn = 0.37f * static_cast<float>(index % 7);
        queries.push_back({ s, p, glm::normalize(normal + turn * side) });
      }
    }
  }
  Check(!queries.empty() || ranks > 1, "mirror points to look up");
  const vlf::Lookup serialLookup(*serial), ownLookup(*field);
  for (const vlf::DirectionInterpolation mode :
    { vlf::DirectionInterpolation::Spherical, vlf::DirectionInterpolation::Nearest })
  {
    const std::vector<glm::vec3> answers =
      vlf::RadianceLeaving(*field, queries, reducer, vlf::CellInterpolation::Bilinear, mode);
    std::vector<glm::vec3> reference, alone;
    for (const vlf::RadianceQuery& q : queries)
    {
      reference.push_back(serialLookup.RadianceLeaving(
        q.Surface, q.Point, q.Toward, vlf::CellInterpolation::Bilinear, mode));
      const glm::vec4 share = ownLookup.RadianceLeavingShare(
        q.Surface, q.Point, q.Toward, vlf::CellInterpolation::Bilinear, mode);
      alone.push_back(share.w > 0.0f ? glm::vec3(share) / share.w : glm::vec3(0.0f));
    }
    const double worstLookup = WorstRelative(answers, reference);
    const char* name = mode == vlf::DirectionInterpolation::Spherical ? "spherical" : "nearest";
    std::printf("rank %d of %d: mirror lookups (%s) at %zu points, worst relative difference "
                "%.3g\n",
      Rank, ranks, name, queries.size(), worstLookup);
    Check(
      worstLookup <= 1e-5, std::string("mirror lookups equal the serial field's (") + name + ")");
    if (ranks > 1)
    {
      Check(WorstRelative(alone, reference) > 1e-2,
        std::string("a rank's own directions alone differ (") + name + ")");
    }
  }
  return Failures;
}

int Gather(vtkMultiProcessController* controller, const std::string& obj)
{
  vlf::ControllerReducer reducer(controller);
  const int ranks = reducer.Size();
  const mesolight::TriangleScene scene = mesolight::ReadObjScene(obj).Scene;
  const int iterations = 3;
  vlf::FinalGatherOptions options; // fewer rays than the default: the split, not the noise
  options.IndirectRays = 64;
  options.DirectSamples = 16;
  // Finer texels on the floor the blocks stand on (LightFieldSettings::ContactTexelHalvings), as
  // the automatic settings take with the gather: surfaces of two texel sizes split over the ranks.
  vlf::LightFieldSettings settings = SmallSettings();
  settings.ContactTexelHalvings = 1;
  std::unique_ptr<vlf::LightField> serial = vlf::LightField::Build(scene, settings);
  Check(serial->HasSpecular(), "the scene has mirrors (the gather follows them)");
  Check(serial->TexelCount() > vlf::LightField::Build(scene, SmallSettings())->TexelCount(),
    "the floor under the blocks has finer texels");
  vlf::Propagate(*serial, iterations);
  const vlf::FinalGatherReport serialReport = vlf::FinalGather(*serial, options);

  std::unique_ptr<vlf::LightField> field = vlf::LightField::Build(scene, settings, {}, &reducer);
  vlf::PropagationOptions propagation;
  propagation.Reduce = &reducer;
  vlf::Propagate(*field, iterations, propagation);
  const std::vector<glm::vec3> propagated = field->TotalDiffuse;
  vlf::FinalGatherOptions distributed = options;
  distributed.Reduce = &reducer;
  const std::uint64_t before = reducer.BytesContributed();
  const vlf::FinalGatherReport report = vlf::FinalGather(*field, distributed);
  const std::uint64_t bytes = reducer.BytesContributed() - before;
  const std::vector<glm::vec3> gathered = field->TotalDiffuse;
  const double worst = WorstRelative(gathered, serial->TotalDiffuse);
  std::printf("rank %d of %d: final gather of %zu texels (%zu own), worst relative texel "
              "difference to the serial gather %.3g, %llu bytes contributed\n",
    Rank, ranks, report.Texels, report.OwnTexels, worst, static_cast<unsigned long long>(bytes));
  Check(worst <= 1e-5, "the distributed final gather equals the serial one within 1e-5");
  Check(WorstRelative(gathered, propagated) > 1e-2, "the gather changed the textures");
  Check(field->PropagatedDiffuse == propagated, "the propagated totals kept");
  Check(report.Texels == serialReport.Texels && report.Filled == serialReport.Filled,
    "as many texels gathered and filled as the serial gather");
  Check(report.Rays == serialReport.Rays, "as many rays in all as the serial gather");
  // Every texel with triangles gathered by exactly one rank, the shares within a block of even.
  double shares[2] = { static_cast<double>(report.OwnTexels), static_cast<double>(report.OwnRays) };
  reducer.SumInPlace(shares, 2);
  std::vector<double> own(static_cast<std::size_t>(ranks), 0.0);
  own[static_cast<std::size_t>(Rank)] = static_cast<double>(report.OwnTexels);
  reducer.SumInPlace(own.data(), own.size());
  const double even = shares[0] / ranks;
  for (const double o : own)
  {
    Check(std::abs(o - even) <= static_cast<double>(vlf::GatherBlockTexels),
      "a rank's share within a block of " + std::to_string(even) + " texels: " + std::to_string(o));
  }
  Check(shares[1] == static_cast<double>(serialReport.Rays), "the ranks' rays add up");
  Check(ranks == 1 || report.OwnTexels < report.Texels, "a rank gathers a share only");

  // The same field gathered by this rank alone: the combined shares are that, bit for bit.
  vlf::RestorePropagatedDiffuse(*field);
  Check(field->TotalDiffuse == propagated, "the propagated totals restored");
  vlf::FinalGather(*field, options);
  Check(field->TotalDiffuse == gathered,
    "the combined shares equal this rank's whole gather "
    "bit for bit");

  // An abort on one rank: every rank stops, the field as propagated everywhere.
  vlf::FinalGatherOptions aborting = distributed;
  aborting.Progress = [&](double) { return Rank != ranks - 1; };
  ExpectAgreedFailure(
    [&]() { vlf::FinalGather(*field, aborting); }, "aborted", "final gather aborted on one rank");
  Check(field->TotalDiffuse == propagated, "an aborted gather leaves the propagated totals");

  // The shares not combined: every rank holds its own texels' gathered values only.
  mesolight_test::NotCombiningReducer uncombined(reducer);
  vlf::FinalGatherOptions alone = options;
  alone.Reduce = &uncombined;
  vlf::FinalGather(*field, alone);
  const double apart = WorstRelative(field->TotalDiffuse, serial->TotalDiffuse);
  std::printf(
    "rank %d of %d: shares not combined: worst relative difference %.3g\n", Rank, ranks, apart);
  if (ranks > 1)
  {
    Check(apart > 1e-2, "without the combining sum the textures differ from the serial gather");
  }
  return Failures;
}

int Compare(const std::string& a, const std::string& b)
{
  const double worst =
    WorstRelative(vlf::ReadSnapshot(a)->TotalDiffuse, vlf::ReadSnapshot(b)->TotalDiffuse);
  std::printf("worst relative texel difference %.3g\n", worst);
  Check(worst <= 1e-5, a + " and " + b + " differ");
  return Failures;
}
} // namespace

int main(int argc, char* argv[])
{
  return mesolight_test::RunDistributedTest(argc, argv,
    [](vtkMultiProcessController* controller, int count, char** args)
    {
      const std::string mode = count > 1 ? args[1] : "";
      if (mode == "equal" && count == 3)
      {
        return Equal(controller, args[2]);
      }
      if (mode == "fail")
      {
        return Fail(controller);
      }
      if (mode == "mirror" && count == 4)
      {
        return Mirror(controller, args[2], args[3]);
      }
      if (mode == "gather" && count == 3)
      {
        return Gather(controller, args[2]);
      }
      if (mode == "compare" && count == 4)
      {
        return Compare(args[2], args[3]);
      }
      std::cerr << "usage: TestDistributedPropagation equal DIR | fail | compare A B | "
                   "mirror OBJ DIR | gather OBJ\n";
      return 1;
    });
}
