// SPDX-License-Identifier: BSD-3-Clause
#include "TextureProportions.h"

#include <glm/geometric.hpp>

#include <cmath>

namespace mesolight
{

void TextureProportions::AddTriangle(const glm::dvec3& p0, const glm::dvec3& p1,
  const glm::dvec3& p2, const glm::dvec2& t0, const glm::dvec2& t1, const glm::dvec2& t2)
{
  const glm::dvec3 e1 = p1 - p0, e2 = p2 - p0;
  const glm::dvec2 d1 = t1 - t0, d2 = t2 - t0;
  const glm::dvec3 cross = glm::cross(e1, e2);
  const double area = 0.5 * glm::length(cross);
  // The texture area the triangle spans, relative to its own extent in texture coordinates, so
  // that coordinates of any scale are judged alike: a sliver in texture space has no dP/du.
  const double det = d1.x * d2.y - d1.y * d2.x;
  const double extent = glm::dot(d1, d1) + glm::dot(d2, d2);
  if (!(area > 0.0) || !std::isfinite(area) || !(std::abs(det) > 1e-12 * extent) ||
    !std::isfinite(det))
  {
    return; // degenerate in the world or in texture space: it draws no texels
  }
  // [dP/du dP/dv] = [e1 e2] [d1 d2]^-1.
  const glm::dvec3 dPdu = (e1 * d2.y - e2 * d1.y) / det;
  const glm::dvec3 dPdv = (e2 * d1.x - e1 * d2.x) / det;
  const double lengthU = glm::length(dPdu), lengthV = glm::length(dPdv);
  if (!std::isfinite(lengthU) || !std::isfinite(lengthV))
  {
    return;
  }
  this->Area += area;
  this->LengthU += area * lengthU;
  this->LengthV += area * lengthV;
  this->Normals += 0.5 * cross;
}

bool TextureProportions::IsFlat() const
{
  return this->Area > 0.0 && glm::length(this->Normals) >= FlatNormalAgreement * this->Area;
}

double TextureProportions::GetHeightOverWidth() const
{
  return this->LengthU > 0.0 ? this->LengthV / this->LengthU : 0.0;
}

} // namespace mesolight
