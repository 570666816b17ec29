// SPDX-License-Identifier: BSD-3-Clause
// Triangles of a planar polygon (an OBJ face with more than three corners), plain C++ with GLM.
#ifndef mesolight_PolygonTriangulation_h
#define mesolight_PolygonTriangulation_h

#include <glm/vec3.hpp>

#include <cstddef>
#include <vector>

namespace mesolight
{

/**
 * Triangles covering the simple polygon `corners` (in order, either winding; nearly planar), as
 * index triples into `corners` wound as the polygon is. Ear clipping (Eberly, "Triangulation by
 * Ear Clipping") in the polygon's plane, so concave faces (an L-shaped roof) are covered exactly
 * rather than by a fan that fills the notch; only strictly convex corners are clipped, so corners
 * on a straight edge (a midpoint shared with a neighbouring face) give no zero-area triangles.
 * A polygon that has no ear left (self-intersecting) has its remainder fanned, as before; one of
 * zero area gives no triangles beyond those already clipped. One of more than
 * MaximumEarClippedCorners corners is fanned whole (ear clipping costs up to the cube of them).
 */
constexpr std::size_t MaximumEarClippedCorners = 1024;
std::vector<glm::uvec3> TriangulatePolygon(const std::vector<glm::vec3>& corners);

} // namespace mesolight

#endif
