// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file OrthonormalBasis.h
 * @brief An orthonormal basis around a unit vector (plain C++17 with GLM).
 *
 * Duff, Burgess, Christensen, Hery, Kensler, Liani, Villemin, "Building an orthonormal basis,
 * revisited", JCGT 2017: no fixed reference axis, continuous except where n.z changes sign.
 * (b1, b2, n) is right-handed. The path tracer samples around surface normals with it and the
 * light field builds its subfield frames from it, in float.
 */
#ifndef mesolight_OrthonormalBasis_h
#define mesolight_OrthonormalBasis_h

#include <glm/vec3.hpp>

#include <cmath>

namespace mesolight
{

/// b1, b2 such that (b1, b2, n) is an orthonormal basis; n must be unit length.
inline void OrthonormalBasis(const glm::vec3& n, glm::vec3& b1, glm::vec3& b2)
{
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  b1 = glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x);
  b2 = glm::vec3(b, sign + n.y * n.y * a, -n.y);
}

} // namespace mesolight

#endif
