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
// (AllocatedBytes), plus the propagation's receive buffers: the peak while propagating.
MemoryEstimate EstimateFor(const TriangleScene& scene, const std::vector<Surface>& surfaces,
  const DirectionSet& directions, const LightFieldSettings& settings, bool specular);

} // namespace vlf
} // namespace mesolight
