// SPDX-License-Identifier: BSD-3-Clause
// ObjectLineCache: the light field's lines around a movable object, read once per gather
// (ObjectGatherer's; Wither 2005, "Interactive dynamic objects in a virtual light field", ch. 3).
#ifndef mesolight_vlf_ObjectLineCache_h
#define mesolight_vlf_ObjectLineCache_h

#include "Lookup.h" // For CellInterpolation

#include <glm/vec3.hpp>

#include <cstddef>
#include <cstdint>
#include <vector>

namespace mesolight
{
namespace vlf
{
class LightField;

// The object's lines: for every direction, the crossings of the lines of the small window of
// cells the object's points project to, each with its sending orientation and the radiance it
// sends (Lookup's CellRadiance), read from the field once per Gather instead of once per vertex.
// Lookups through it give exactly Lookup::IncidentRadiance's values (the test compares them).
struct ObjectLineCache
{
  struct Entry
  {
    float Depth;
    int Orientation; // of the surface along the direction (LightField::Orientation)
    glm::vec3 Radiance;
  };
  struct Window
  {
    int I0 = 0, J0 = 0, Width = 0, Height = 0;
    // LightField::CellCoordinates and DepthOf inlined: c = (p . U + 1) / h - 1/2,
    // depth = p . D + start.
    glm::vec3 U{ 0.0f }, V{ 0.0f }, D{ 0.0f };
    float InverseCell = 1.0f, DepthStart = 0.0f;
    std::vector<std::uint32_t> Start; // Width * Height + 1 offsets into Entries
    std::vector<Entry> Entries;
  };
  std::vector<Window> Windows; // per direction (Width 0: not cached, use the lookup)

  // Limits the memory for objects that cover much of the field.
  static constexpr int MaxLines = 400;

  // Reads the windows of the given directions around the box [lower, upper] (unit sphere).
  // emission false: the senders' own emitted radiance left out (Lookup::IncidentRadiance's).
  void Build(const LightField& field, const std::vector<std::uint32_t>& directions,
    const glm::vec3& lower, const glm::vec3& upper, int threads, bool emission = true);
  // Lookup::IncidentRadiance through the window; false when p's cells are not in it.
  bool Incident(
    std::size_t k, int sense, const glm::vec3& p, CellInterpolation cells, glm::vec3& out) const;
};

} // namespace vlf
} // namespace mesolight

#endif
