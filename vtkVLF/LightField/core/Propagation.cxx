// SPDX-License-Identifier: BSD-3-Clause
#include "Propagation.h"

#include "FinalGather.h"

#include "MathConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstring>
#include <exception>
#include <stdexcept>

namespace mesolight
{
namespace vlf
{

namespace
{

void Add(std::array<double, 3>& sum, const glm::vec3& value)
{
  sum[0] += static_cast<double>(value.x);
  sum[1] += static_cast<double>(value.y);
  sum[2] += static_cast<double>(value.z);
}

void Add(std::array<double, 3>& sum, const std::array<double, 3>& value)
{
  for (int c = 0; c < 3; ++c)
  {
    sum[c] += value[c];
  }
}

struct SpecularDeposit
{
  std::uint32_t Subfield;
  std::size_t Cell;
  glm::vec3 Radiance;
};

// Mirrored radiance for a direction another rank holds (a distributed field): the owner finds
// the cells, as DepositSpecular does here (it alone holds the direction's tile lists).
struct RemoteSpecular
{
  std::uint32_t Target;  // direction
  std::uint32_t Surface; // the mirror
  glm::vec3 Point;       // where the line met it
  glm::vec3 Radiance;    // Ks x the radiance that arrived
  float SourceWeight;    // solid angle of the arriving direction
};

// What one worker block accumulates during an iteration.
struct BlockState
{
  std::vector<glm::vec3> Reflected; // reflected diffuse flux per texel
  std::vector<SpecularDeposit> Specular;
  std::vector<RemoteSpecular> Remote;
  LightField::IterationEnergy Energy;
};

// Mirrored radiance into the lines of direction `target` around x on the mirror (bilinear over
// the cells that cross the same surface), scaled by w_source / w_target so the flux is kept;
// false when no cell there crosses the mirror (the flux is lost).
bool DepositSpecular(const LightField& field, std::size_t target, std::uint32_t surface,
  const glm::vec3& x, const glm::vec3& radiance, float sourceWeight,
  std::vector<SpecularDeposit>& out)
{
  const glm::vec2 c = field.CellCoordinates(target, x);
  const int i0 = static_cast<int>(std::floor(c.x)), j0 = static_cast<int>(std::floor(c.y));
  const float fi = c.x - static_cast<float>(i0), fj = c.y - static_cast<float>(j0);
  std::int64_t cells[4];
  float weights[4];
  float weightSum = 0.0f;
  for (int t = 0; t < 4; ++t)
  {
    const int di = t & 1, dj = t >> 1;
    cells[t] = field.FindCell(target, i0 + di, j0 + dj, surface);
    weights[t] = cells[t] < 0 ? 0.0f : (di ? fi : 1.0f - fi) * (dj ? fj : 1.0f - fj);
    weightSum += weights[t];
  }
  if (!(weightSum > 0.0f))
  {
    return false;
  }
  const float scale = sourceWeight / field.GetSubfield(target).Weight / weightSum;
  for (int t = 0; t < 4; ++t)
  {
    if (weights[t] > 0.0f)
    {
      out.push_back({ static_cast<std::uint32_t>(target), static_cast<std::size_t>(cells[t]),
        radiance * (scale * weights[t]) });
    }
  }
  return true;
}

// Sends the unshot radiance of every crossing of subfield k one step along its lines.
void ShootSubfield(LightField& field, std::size_t k, BlockState& state)
{
  const LightFieldSettings& settings = field.Settings();
  const int n = settings.RaysPerSide;
  Subfield& f = field.GetSubfield(k);
  const float fluxPerRadiance = settings.CellSize() * settings.CellSize() * f.Weight;
  const DirectionSet& directions = field.Directions();
  std::vector<Crossing> crossings;
  for (int j = 0; j < n; ++j)
  {
    for (int i = 0; i < n; ++i)
    {
      field.LineCrossings(k, i, j, crossings);
      for (std::size_t q = 0; q < crossings.size(); ++q)
      {
        const Crossing& sender = crossings[q];
        const int sense = field.Orientation(k, sender.Surface);
        const std::ptrdiff_t r = field.Receiver(k, crossings, q);
        if (r == LightField::LineBlocked)
        {
          // Not part of the visible surface (its capacity leaves it out): nothing is shot into a
          // solid. Mirrored light deposited here has no way out: it is lost to the mirror.
          if (sender.Cell < f.UnshotSpecular.size()) // a mirror's crossing
          {
            const glm::vec3 lost = f.UnshotSpecular[sender.Cell] * fluxPerRadiance;
            f.UnshotSpecular[sender.Cell] = glm::vec3(0.0f);
            Add(state.Energy.Shot, lost);
            Add(state.Energy.SpecularLost, lost);
          }
          continue;
        }
        glm::vec3 radiance = field.SampleTexture(
          field.UnshotDiffuse, sender.Surface, field.PointOnLine(k, i, j, sender.Depth));
        const bool mirror = sender.Cell < f.Radiance.size(); // its radiance is stored
        if (mirror)
        {
          radiance += glm::vec3(f.UnshotSpecular[sender.Cell]);
          f.UnshotSpecular[sender.Cell] = glm::vec3(0.0f);
        }
        if (radiance.x <= 0.0f && radiance.y <= 0.0f && radiance.z <= 0.0f)
        {
          continue;
        }
        if (mirror) // else LightField::SentRadiance derives it from the textures
        {
          f.Radiance[sender.Cell] += radiance;
        }
        const glm::vec3 flux = radiance * fluxPerRadiance;
        Add(state.Energy.Shot, flux);
        if (r == LightField::LineEscapes)
        {
          Add(state.Energy.Escaped, flux);
          continue;
        }
        const Crossing& receiver = crossings[static_cast<std::size_t>(r)];
        const SceneMaterial& material = field.MaterialOf(receiver.Surface);
        const glm::vec3 x = field.PointOnLine(k, i, j, receiver.Depth);
        const glm::vec3 reflected = material.Diffuse * flux;
        const TexelWeights w = field.WeightsAt(receiver.Surface, x);
        for (int t = 0; t < 4; ++t)
        {
          state.Reflected[w.Texel[t]] += w.Weight[t] * reflected;
        }
        Add(state.Energy.Absorbed, (glm::vec3(1.0f) - material.Diffuse - material.Specular) * flux);
        if (material.Specular.x <= 0.0f && material.Specular.y <= 0.0f &&
          material.Specular.z <= 0.0f)
        {
          continue;
        }
        // Perfect mirror: into the nearest direction of the mirrored one (Wither 2005 §2.4.1.2).
        const glm::vec3& normal = field.Surfaces()[receiver.Surface].Normal;
        const glm::vec3 travel = static_cast<float>(sense) * f.Direction;
        const glm::vec3 mirrored = travel - 2.0f * glm::dot(travel, normal) * normal;
        bool flipped = false;
        const std::size_t target = directions.Nearest(glm::normalize(mirrored), &flipped);
        const glm::vec3 specularFlux = material.Specular * flux;
        if (field.Orientation(target, receiver.Surface) != (flipped ? -1 : 1))
        {
          Add(state.Energy.SpecularLost, specularFlux);
          continue;
        }
        if (!field.OwnsSubfield(target))
        {
          state.Remote.push_back({ static_cast<std::uint32_t>(target), receiver.Surface, x,
            material.Specular * radiance, f.Weight });
          continue;
        }
        if (!DepositSpecular(field, target, receiver.Surface, x, material.Specular * radiance,
              f.Weight, state.Specular))
        {
          Add(state.Energy.SpecularLost, specularFlux);
        }
      }
    }
  }
}

// Adds the flux of the unshot specular radiance this process holds to `flux`.
void AddUnshotSpecularFlux(const LightField& field, std::array<double, 3>& flux)
{
  const float cellArea = field.Settings().CellSize() * field.Settings().CellSize();
  for (std::size_t k = 0; k < field.SubfieldCount(); ++k)
  {
    const Subfield& f = field.GetSubfield(k);
    for (const glm::vec3& radiance : f.UnshotSpecular)
    {
      Add(flux, radiance * (cellArea * f.Weight));
    }
  }
}

template <typename T>
void Append(std::string& out, const T& value)
{
  out.append(reinterpret_cast<const char*>(&value), sizeof(T));
}

// A distributed field with mirrors: every rank hands the mirrored radiance meant for directions
// it does not hold to their owners, which find the cells (Wither's mirror step, split at the
// direction's owner). Pairs exchange in one global order (rank a sends to b while b receives),
// so blocking sends never wait on each other. What arrives is deposited into `deposits`; the
// flux no cell can carry goes to `lost`.
void ExchangeSpecular(LightField& field, Reducer& reducer, const std::vector<BlockState>& states,
  std::vector<SpecularDeposit>& deposits, std::array<double, 3>& lost)
{
  const int ranks = reducer.Size(), rank = reducer.Rank();
  const std::vector<std::uint32_t> owner = BalanceDirections(field, ranks);
  std::vector<std::string> outgoing(static_cast<std::size_t>(ranks));
  for (const BlockState& s : states)
  {
    for (const RemoteSpecular& r : s.Remote)
    {
      Append(outgoing[owner[r.Target]], r);
    }
  }
  const float cellArea = field.Settings().CellSize() * field.Settings().CellSize();
  for (int from = 0; from < ranks; ++from)
  {
    for (int to = 0; to < ranks; ++to)
    {
      if (from == to)
      {
        continue;
      }
      if (rank == from)
      {
        reducer.Send(outgoing[static_cast<std::size_t>(to)], to);
      }
      else if (rank == to)
      {
        const std::string bytes = reducer.Receive(from);
        if (bytes.size() % sizeof(RemoteSpecular) != 0)
        {
          throw std::runtime_error("a mirrored-radiance message is truncated");
        }
        for (std::size_t at = 0; at < bytes.size(); at += sizeof(RemoteSpecular))
        {
          RemoteSpecular r;
          std::memcpy(&r, bytes.data() + at, sizeof(r));
          if (r.Target >= field.SubfieldCount() || !field.OwnsSubfield(r.Target) ||
            r.Surface >= field.Surfaces().size())
          {
            throw std::runtime_error("mirrored radiance arrived for a direction not held here");
          }
          if (!DepositSpecular(
                field, r.Target, r.Surface, r.Point, r.Radiance, r.SourceWeight, deposits))
          {
            Add(lost, r.Radiance * (cellArea * r.SourceWeight));
          }
        }
      }
    }
  }
}
} // namespace

std::array<double, 3> UnshotFlux(const LightField& field)
{
  std::array<double, 3> flux{};
  for (std::size_t t = 0; t < field.UnshotDiffuse.size(); ++t)
  {
    Add(flux, field.UnshotDiffuse[t] * field.Capacity[t]);
  }
  AddUnshotSpecularFlux(field, flux);
  return flux;
}

LightField::IterationEnergy PropagateIteration(LightField& field, const PropagationOptions& options)
{
  // A gathered field's totals are not sums of what was shot: go on from the propagated ones.
  RestorePropagatedDiffuse(field);
  const auto start = std::chrono::steady_clock::now();
  const std::size_t count = field.SubfieldCount();
  const std::size_t texels = field.TexelCount();
  const std::size_t blocks = DefaultBlockCount(count);
  std::vector<BlockState> states(blocks);
  for (BlockState& s : states)
  {
    s.Reflected.assign(texels, glm::vec3(0.0f));
  }
  std::exception_ptr failure;
  try
  {
    RunInBlocks(count, blocks, options.Progress, 0.0, 1.0,
      [&](std::size_t b, std::size_t k)
      {
        if (field.OwnsSubfield(k))
        {
          ShootSubfield(field, k, states[b]);
        }
      });
  }
  catch (...)
  {
    failure = std::current_exception();
  }
  if (options.Reduce)
  {
    AgreeOnFailure(*options.Reduce, failure); // no rank waits for one that stopped
  }
  else if (failure)
  {
    std::rethrow_exception(failure);
  }

  LightField::IterationEnergy energy;
  energy.Iteration = field.IterationsDone + 1;
  const bool distributed = options.Reduce && options.Reduce->Size() > 1;
  std::vector<SpecularDeposit> received;
  if (distributed && field.HasSpecular())
  {
    std::exception_ptr exchangeFailure;
    try
    {
      ExchangeSpecular(field, *options.Reduce, states, received, energy.SpecularLost);
    }
    catch (...)
    {
      exchangeFailure = std::current_exception();
    }
    AgreeOnFailure(*options.Reduce, exchangeFailure);
  }
  else
  {
    // No owner to hand them to (a distributed field propagated without its reducer, the negative
    // tests): lost.
    const float cellArea = field.Settings().CellSize() * field.Settings().CellSize();
    for (const BlockState& s : states)
    {
      for (const RemoteSpecular& r : s.Remote)
      {
        Add(energy.SpecularLost, r.Radiance * (cellArea * r.SourceWeight));
      }
    }
  }
  std::vector<glm::vec3>& reflected = states[0].Reflected;
  for (std::size_t b = 0; b < blocks; ++b)
  {
    const LightField::IterationEnergy& e = states[b].Energy;
    Add(energy.Shot, e.Shot);
    Add(energy.Escaped, e.Escaped);
    Add(energy.Absorbed, e.Absorbed);
    Add(energy.BackFaces, e.BackFaces);
    Add(energy.SpecularLost, e.SpecularLost);
    if (b > 0)
    {
      for (std::size_t t = 0; t < texels; ++t)
      {
        reflected[t] += states[b].Reflected[t];
      }
      states[b].Reflected = std::vector<glm::vec3>();
    }
  }
  if (options.Reduce)
  {
    ReduceIteration(*options.Reduce, reflected, energy); // the one exchange per iteration
  }
  // Reflected flux -> unshot diffuse radiance (see the header: the discrete capacity keeps the
  // flux exactly).
  for (const Surface& s : field.Surfaces())
  {
    const float area = static_cast<float>(Pi<double>) * s.TexelU * s.TexelV;
    for (std::size_t t = s.TexelOffset; t < s.TexelOffset + s.TexelCount(); ++t)
    {
      const float normalizer =
        options.Normalization == DiffuseNormalization::DiscreteCapacity ? field.Capacity[t] : area;
      const glm::vec3 unshot = normalizer > 0.0f ? reflected[t] / normalizer : glm::vec3(0.0f);
      field.UnshotDiffuse[t] = unshot;
      field.TotalDiffuse[t] += unshot;
    }
  }
  for (const BlockState& s : states)
  {
    for (const SpecularDeposit& d : s.Specular)
    {
      field.GetSubfield(d.Subfield).UnshotSpecular[d.Cell] += d.Radiance;
    }
  }
  for (const SpecularDeposit& d : received)
  {
    field.GetSubfield(d.Subfield).UnshotSpecular[d.Cell] += d.Radiance;
  }
  energy.Unshot = UnshotFlux(field);
  if (distributed && field.HasSpecular())
  {
    // Each rank holds its own directions' unshot specular radiance: the diffuse part (the same
    // on every rank) plus the ranks' specular parts, so that every rank stops alike.
    std::array<double, 3> specular{};
    AddUnshotSpecularFlux(field, specular);
    options.Reduce->SumInPlace(specular.data(), specular.size());
    energy.Unshot = {};
    for (std::size_t t = 0; t < field.UnshotDiffuse.size(); ++t)
    {
      Add(energy.Unshot, field.UnshotDiffuse[t] * field.Capacity[t]);
    }
    Add(energy.Unshot, specular);
  }
  field.IterationsDone = energy.Iteration;
  energy.Seconds = std::chrono::duration<double>(std::chrono::steady_clock::now() - start).count();
  field.EnergyLog.push_back(energy);
  return energy;
}

void Propagate(LightField& field, int iterations, const PropagationOptions& options,
  const std::function<void(const LightField&)>& afterIteration)
{
  const int first = field.IterationsDone;
  const int total = iterations - first;
  for (int it = first; it < iterations; ++it)
  {
    PropagationOptions step = options;
    step.Progress = SubProgress(options.Progress, static_cast<double>(it - first) / total,
      static_cast<double>(it - first + 1) / total);
    PropagateIteration(field, step);
    if (it + 1 == iterations)
    {
      field.CompactRadiance(); // the stored field is compact (RadianceStorage.h), its last
                               // snapshot too; earlier ones keep float to resume exactly
    }
    if (afterIteration)
    {
      afterIteration(field);
    }
  }
  field.CompactRadiance();
}

double UnshotFraction(const LightField& field)
{
  const std::array<double, 3> emitted =
    field.EnergyLog.empty() ? UnshotFlux(field) : field.EnergyLog.front().Shot;
  const std::array<double, 3> unshot =
    field.EnergyLog.empty() ? emitted : field.EnergyLog.back().Unshot;
  const double total = emitted[0] + emitted[1] + emitted[2];
  return total > 0.0 ? (unshot[0] + unshot[1] + unshot[2]) / total : 0.0;
}

bool PropagateToTolerance(LightField& field, double tolerance, int maxIterations,
  const PropagationOptions& options, const std::function<void(const LightField&)>& afterIteration)
{
  if (!(tolerance > 0.0))
  {
    throw std::invalid_argument("the propagation's tolerance must be positive");
  }
  // Share of the way from everything unshot (1) to the tolerance, on a log scale.
  auto progressOf = [&](int done, double fraction)
  {
    const double toward = fraction >= 1.0 ? 0.0 : std::log(fraction) / std::log(tolerance);
    const double cap = maxIterations > 0 ? static_cast<double>(done) / maxIterations : 1.0;
    return std::min(1.0, std::max({ 0.0, toward, cap }));
  };
  double fraction = UnshotFraction(field);
  double reported = 0.0, lastStep = 0.0;
  while (fraction > tolerance && field.IterationsDone < maxIterations)
  {
    // This iteration's share of the bar: what the last one achieved, at least 1/8 of the rest.
    const double begin = std::max(reported, progressOf(field.IterationsDone, fraction));
    const double end = std::min(1.0, begin + std::max(lastStep, (1.0 - begin) / 8.0));
    PropagationOptions step = options;
    step.Progress = SubProgress(options.Progress, begin, end);
    PropagateIteration(field, step);
    fraction = UnshotFraction(field);
    if (fraction <= tolerance || field.IterationsDone >= maxIterations)
    {
      field.CompactRadiance(); // as in Propagate: the last snapshot compact
    }
    if (afterIteration)
    {
      afterIteration(field);
    }
    lastStep = std::max(0.0, progressOf(field.IterationsDone, fraction) - begin);
    reported = end;
  }
  field.CompactRadiance();
  if (options.Progress && !options.Progress(1.0))
  {
    throw AbortedError();
  }
  return fraction <= tolerance;
}

} // namespace vlf
} // namespace mesolight
