// SPDX-License-Identifier: BSD-3-Clause
// DirectionSet: the directions of the virtual light field's parallel subfields (Wither 2005
// §2.4.1.1), uniformly spread over the upper hemisphere by triangular subdivision, with
// constant-time nearest-direction and three-direction interpolation queries (Wither 2005 §2.4.1.3,
// §3.6).
//
// Construction. Wither subdivides a regular tetrahedron after Slater, "Constant time queries on
// uniformly distributed points on a hemisphere" (JGT 7(1), 2002), and reports ~60% variation in
// solid angle. Here the upper half of a regularly subdivided octahedron is used: the lattice points
// (i, j), |i| + |j| <= n, of the diamond |x| + |y| <= 1 (Listing 6's midpoint subdivision of the
// four upper octahedron faces, n times per edge), mapped onto the hemisphere by the equal-area
// octahedral map (Clarberg, "Fast equal-area mapping of the (hemi)sphere using SIMD", JGT 13(3),
// 2008; the octahedral parameterisation of Praun & Hoppe 2003). Every subdivision triangle then
// covers the same solid angle pi/n^2, so the solid-angle weights are nearly constant, and the map
// is inverted analytically: a lookup maps the direction into the diamond and inspects a few lattice
// points around it (no search over all directions, no GL read-back).
//
// A parallel subfield carries light both ways, so a direction d and -d are one subfield. Of the
// 4n equator points only the 2n with azimuth in [0, pi) are kept; the lattice holds 2n^2 + 2n + 1
// points, the set 2n^2 + 1 directions (n = 16, 32, 64 -> 513, 2049, 8193).
#ifndef mesolight_vlf_DirectionSet_h
#define mesolight_vlf_DirectionSet_h

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

#include <array>
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{

class DirectionSet
{
public:
  // Triangular subdivision of the upper hemisphere: 2*n*n+1 directions (n = 16 -> 513,
  // 32 -> 2049, 64 -> 8193), all with z >= 0; on the equator only one of d and -d is kept.
  // Throws std::invalid_argument for n < 1 or n > 4096.
  explicit DirectionSet(int n);
  // 513, 2049, 8193 (any 2n^2+1); throws std::invalid_argument for other counts.
  static DirectionSet WithCount(std::size_t count);
  // Whether `count` directions make a set (2n^2+1, n >= 1); if not, `why` (when given) gets the
  // sentence WithCount throws.
  static bool IsCount(std::size_t count, std::string* why = nullptr);

  std::size_t Size() const { return this->Directions.size(); }
  const glm::vec3& Direction(std::size_t i) const { return this->Directions[i]; } // unit length
  // Solid-angle weight: the integral over the sphere of direction i's interpolation (hat)
  // function, i.e. 1/3 of the solid angle of every subdivision triangle at it, with the triangles
  // at a dropped equator point credited to its kept antipode. Sum over i = 2*pi; with these
  // weights, sum_i SolidAngle(i) f(d_i) integrates the Interpolate()d function exactly.
  float SolidAngle(std::size_t i) const { return this->SolidAngles[i]; }

  // Nearest direction to a vector (normalised here; NaN/Inf/zero throws std::invalid_argument)
  // in O(1). A subfield carries light both ways, so the nearest of the 4n^2+2 signed directions
  // +-Direction(i) is returned: `flipped` true means `unit` is nearest to -Direction(i) (the
  // caller reads subfield i backwards). This is exactly "unit was in the lower hemisphere and was
  // negated", except within half a lattice cell of the equator, where the exact answer may be
  // the antipode of a kept equator direction.
  // `examined`, when given, receives the number of lattice points compared (at most 16 for any
  // set size: what makes the lookup O(1), checked by the tests).
  std::size_t Nearest(
    const glm::vec3& unit, bool* flipped = nullptr, std::size_t* examined = nullptr) const;

  struct Interpolation
  {
    std::array<std::size_t, 3> Index;
    std::array<float, 3> Weight;
    // As Nearest's `flipped`, for the vertex of largest weight. The three vertices agree except in
    // triangles touching the dropped half of the equator: VertexFlipped has each one's sign
    // (vertex k is -Direction(Index[k]) when VertexFlipped[k]).
    bool Flipped;
    std::array<bool, 3> VertexFlipped;
  };
  // The three directions of the subdivision triangle containing `unit`, with spherical
  // interpolation weights: the ratios of the solid angles of the three sub-triangles `unit` cuts
  // the triangle into (the map is equal-area, so these are the barycentric coordinates in the
  // diamond). Non-negative, sum 1, exactly 1 at a vertex, continuous.
  Interpolation Interpolate(const glm::vec3& unit) const;

  int Subdivisions() const { return this->N; }

  // The equal-area octahedral map of the upper hemisphere onto the diamond |x| + |y| <= 1 and its
  // inverse (exposed for tests and for callers that tabulate over the hemisphere). `unit` must
  // have z >= 0.
  static glm::dvec2 HemisphereToDiamond(const glm::dvec3& unit);
  static glm::dvec3 DiamondToHemisphere(const glm::dvec2& diamond);

private:
  // A lattice point (i, j) of the diamond, |i| + |j| <= n: the kept direction it stands for and
  // whether it is that direction's antipode (a dropped equator point).
  struct LatticePoint
  {
    glm::vec3 Direction{ 0.0f }; // the signed direction of this lattice point
    std::uint32_t Index = 0;
    bool Flipped = false;
    bool Valid = false;
  };
  const LatticePoint& At(int i, int j) const
  {
    return this->Lattice[static_cast<std::size_t>(j + this->N) * (2 * this->N + 1) +
      static_cast<std::size_t>(i + this->N)];
  }
  // `unit` normalised and moved into the upper hemisphere; true if negated.
  static bool ToUpperHemisphere(const glm::vec3& unit, glm::dvec3& upper);

  int N = 0;
  std::vector<glm::vec3> Directions;
  std::vector<float> SolidAngles;
  std::vector<LatticePoint> Lattice; // (2n+1)^2, row j, column i
};

} // namespace vlf
} // namespace mesolight

#endif
