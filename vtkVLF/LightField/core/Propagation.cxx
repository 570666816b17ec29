// SPDX-License-Identifier: BSD-3-Clause
#include "Propagation.h"

#include "MathConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <chrono>
#include <cmath>
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

// What one worker block accumulates during an iteration.
struct BlockState
{
  std::vector<glm::vec3> Reflected; // reflected diffuse flux per texel
  std::vector<SpecularDeposit> Specular;
  LightField::IterationEnergy Energy;
};

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
        const glm::vec2 c = field.CellCoordinates(target, x);
        const int i0 = static_cast<int>(std::floor(c.x)), j0 = static_cast<int>(std::floor(c.y));
        const float fi = c.x - static_cast<float>(i0), fj = c.y - static_cast<float>(j0);
        std::int64_t cells[4];
        float weights[4];
        float weightSum = 0.0f;
        for (int t = 0; t < 4; ++t)
        {
          const int di = t & 1, dj = t >> 1;
          cells[t] = field.FindCell(target, i0 + di, j0 + dj, receiver.Surface);
          weights[t] = cells[t] < 0 ? 0.0f : (di ? fi : 1.0f - fi) * (dj ? fj : 1.0f - fj);
          weightSum += weights[t];
        }
        if (!(weightSum > 0.0f))
        {
          Add(state.Energy.SpecularLost, specularFlux);
          continue;
        }
        const float scale = f.Weight / field.GetSubfield(target).Weight / weightSum;
        for (int t = 0; t < 4; ++t)
        {
          if (weights[t] > 0.0f)
          {
            state.Specular.push_back(
              { static_cast<std::uint32_t>(target), static_cast<std::size_t>(cells[t]),
                material.Specular * radiance * (scale * weights[t]) });
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
  const float cellArea = field.Settings().CellSize() * field.Settings().CellSize();
  for (std::size_t k = 0; k < field.SubfieldCount(); ++k)
  {
    const Subfield& f = field.GetSubfield(k);
    for (const glm::vec3& radiance : f.UnshotSpecular)
    {
      Add(flux, radiance * (cellArea * f.Weight));
    }
  }
  return flux;
}

LightField::IterationEnergy PropagateIteration(LightField& field, const PropagationOptions& options)
{
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
  energy.Unshot = UnshotFlux(field);
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
