// SPDX-License-Identifier: BSD-3-Clause
// Internal to the light field's core (LightField.cxx, LightFieldMemory.cxx): the memory estimate
// a LightField checks against its budget before allocating, and the subfield frame it shares with
// the count of the maps' contents. The public entry point is EstimateMemory (LightField.h).
#pragma once

#include "LightField.h"

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace mesolight
{
namespace vlf
{

// Subfield k's axes for its direction d (LightField.cxx).
void SubfieldFrame(std::size_t k, const glm::vec3& d, glm::vec3& u, glm::vec3& v);

// What a LightField allocates for the surfaces and directions of an already normalised scene
// (AllocatedBytes), plus the propagation's receive buffers: the peak while propagating. With
// sampleStride > 1 the maps are counted for every sampleStride-th direction only and scaled to
// all of them: an approximation in a sampleStride-th of the time, for refusing a field far over
// its budget before the exact count.
MemoryEstimate EstimateFor(const TriangleScene& scene, const std::vector<Surface>& surfaces,
  const DirectionSet& directions, const LightFieldSettings& settings, bool specular,
  std::size_t sampleStride = 1);

// EstimateFor, counted first on 1 in 64 directions where there are 512 or more: an estimate
// whose share on one of `ranks` ranks exceeds 1.5x settings.MemoryBudget is returned as it is
// (SampleStride 64), otherwise the exact count. The sample's error is a few per cent (8193
// directions of 1024 x 1024 lines on the props office: 7.06 against 7.16 GiB), so a field
// that fits is never refused on it.
MemoryEstimate EstimateWithinBudget(const TriangleScene& scene,
  const std::vector<Surface>& surfaces, const DirectionSet& directions,
  const LightFieldSettings& settings, bool specular, std::size_t ranks);

} // namespace vlf
} // namespace mesolight
