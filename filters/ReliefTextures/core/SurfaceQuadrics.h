// SPDX-License-Identifier: BSD-3-Clause
// Per-vertex quadrics of a curved mesh for relief mapping on arbitrary polygonal surfaces
// (Oliveira & Policarpo 2005, "An efficient representation for surface details", UFRGS RP-351;
// Policarpo, Oliveira & Comba 2005, "Real-time relief mapping on arbitrary polygonal surfaces").
//
// Around each vertex the surface is locally z = a u^2 + b v^2 in its tangent space: z the depth
// below the vertex's tangent plane (along -n), (u, v) offsets in texture coordinates. The relief
// shader lowers the tangent-plane ray by this quadric as it marches, so a ray that passes a convex
// surface leaves the relief layer without a hit (the silhouette of the curved mesh).
#ifndef mesolight_SurfaceQuadrics_h
#define mesolight_SurfaceQuadrics_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <stdexcept>
#include <vector>

namespace mesolight
{

/** Bad input to ComputeSurfaceQuadrics (sizes that disagree, an index out of range). */
class MESOLIGHTRELIEFTEXTURES_EXPORT SurfaceQuadricsError : public std::runtime_error
{
public:
  using std::runtime_error::runtime_error;
};

/**
 * The quadric coefficients of every vertex, (a, b) / s with s = |dP/du| the world length of one
 * texture unit along u at the vertex: the depth below the tangent plane at texture offset (u, v)
 * is s (a' u^2 + b' v^2) for the returned (a', b'). Divided by the relief's depth scale (world
 * depth of depth 1 over s, vtkReliefProperty::DepthScale) they are the quadric in the shader's
 * depth units, and they do not change when the mesh is scaled. Positive for a convex surface
 * (it bends away from its normal).
 *
 * Fitted per vertex by least squares over its one-ring neighbours j: the depth of p_j below the
 * vertex's tangent plane, -(p_j - p_i) . n_i, against a du^2 + 2 c du dv + b dv^2 of their
 * texture offsets (the cross term c is fitted so it does not bias a and b, then dropped, as in
 * the paper: the texture axes are taken as principal directions). Exact for a circular
 * cylinder or sphere sampled on its surface (a chord's depth is then exactly kappa |chord|^2 / 2).
 * A vertex whose neighbours do not determine the fit gets 0; so do coefficients below
 * SurfaceQuadricFlatThreshold (rounding on a plane), so a flat mesh gets exactly 0 everywhere.
 *
 * @param positions  vertex positions
 * @param normals    unit vertex normals (the relief's depth axis is -n)
 * @param tcoords    vertex texture coordinates
 * @param triangles  vertex indices, counter-clockwise or not (orientation is not used)
 * @throws SurfaceQuadricsError if the arrays' sizes disagree or an index is out of range
 */
MESOLIGHTRELIEFTEXTURES_EXPORT std::vector<glm::vec2> ComputeSurfaceQuadrics(
  const std::vector<glm::dvec3>& positions, const std::vector<glm::dvec3>& normals,
  const std::vector<glm::dvec2>& tcoords, const std::vector<std::array<long long, 3>>& triangles);

/** |a'| and |b'| below this are rounding (a surface off its tangent plane by 1e-6 of its
 * width across a whole texture): they are set to 0. */
constexpr double SurfaceQuadricFlatThreshold = 1e-6;

/** Whether any vertex has a non-zero coefficient (the mesh is curved for the relief shader). */
MESOLIGHTRELIEFTEXTURES_EXPORT bool AnySurfaceQuadric(const std::vector<glm::vec2>& quadrics);

} // namespace mesolight

#endif
