// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file TextureProportions.h
 * @brief How a flat surface's texture coordinates draw a map: its height over its width per
 * texture unit (plain C++17 with GLM, no VTK types).
 *
 * A relief texture is drawn undistorted when one unit of v spans the map's height on the ground
 * for every unit of u its width spans: the surface's |dP/dv| / |dP/du| equals the map's ground
 * proportions (vtkReliefPlaneFilter::GetGroundProportions). A square plane under a map twice as
 * wide as tall draws every feature twice as tall as it is. vtkAttachReliefTexture warns then.
 */
#ifndef mesolight_TextureProportions_h
#define mesolight_TextureProportions_h

#include "MesolightReliefTexturesModule.h" // for the export macro only

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace mesolight
{

/**
 * Accumulates triangles (world positions, texture coordinates) and gives, over the triangles
 * whose texture coordinates span an area, their world lengths of one texture unit along u and v
 * (|dP/du|, |dP/dv|, each triangle weighted by its world area), and whether they lie in one
 * direction of facing (a flat surface: the area-weighted normals' sum is at least
 * FlatNormalAgreement of their summed areas). Curved meshes (geometry images) are parametrised
 * with a stretch of their own, so only a flat surface's proportions say how the map is drawn.
 */
class MESOLIGHTRELIEFTEXTURES_EXPORT TextureProportions
{
public:
  /** |sum of area-weighted normals| / sum of areas at or above which the triangles are flat:
   * about cos 1 degree (two equal halves 2 degrees apart are at the limit). */
  static constexpr double FlatNormalAgreement = 0.99985;

  void AddTriangle(const glm::dvec3& p0, const glm::dvec3& p1, const glm::dvec3& p2,
    const glm::dvec2& t0, const glm::dvec2& t1, const glm::dvec2& t2);

  /** The triangles' world area that had usable texture coordinates (0: none). */
  double GetArea() const { return this->Area; }
  /** True when there is area and the triangles face one way (see FlatNormalAgreement). */
  bool IsFlat() const;
  /** Mean |dP/dv| over mean |dP/du|, area weighted: how many times as tall as wide a unit
   * square of texture coordinates is drawn. 0 without area. */
  double GetHeightOverWidth() const;

private:
  double Area = 0.0;
  double LengthU = 0.0;      // sum of area x |dP/du|
  double LengthV = 0.0;      // sum of area x |dP/dv|
  glm::dvec3 Normals{ 0.0 }; // sum of area x unit normal
};

} // namespace mesolight

#endif
