// SPDX-License-Identifier: BSD-3-Clause
#include "SurfaceQuadrics.h"

#include <glm/geometric.hpp>
#include <glm/mat2x2.hpp>
#include <glm/mat3x3.hpp>
#include <glm/matrix.hpp>

#include <algorithm>
#include <cmath>
#include <string>

namespace mesolight
{
namespace
{
// Each vertex's one-ring: neighbour lists in one array (compressed rows), duplicates kept out.
void OneRings(size_t vertices, const std::vector<std::array<long long, 3>>& triangles,
  std::vector<size_t>& offsets, std::vector<size_t>& neighbours)
{
  offsets.assign(vertices + 1, 0);
  for (const auto& t : triangles)
  {
    for (long long v : t)
    {
      offsets[static_cast<size_t>(v) + 1] += 2;
    }
  }
  for (size_t i = 0; i < vertices; ++i)
  {
    offsets[i + 1] += offsets[i];
  }
  std::vector<size_t> fill(offsets.begin(), offsets.end() - 1);
  neighbours.assign(offsets.back(), 0);
  for (const auto& t : triangles)
  {
    for (int k = 0; k < 3; ++k)
    {
      const auto v = static_cast<size_t>(t[k]);
      neighbours[fill[v]++] = static_cast<size_t>(t[(k + 1) % 3]);
      neighbours[fill[v]++] = static_cast<size_t>(t[(k + 2) % 3]);
    }
  }
}

bool Determined(double det, double scale)
{
  return std::isfinite(det) && scale > 0.0 && std::abs(det) > 1e-10 * scale;
}
} // namespace

//------------------------------------------------------------------------------
std::vector<glm::vec2> ComputeSurfaceQuadrics(const std::vector<glm::dvec3>& positions,
  const std::vector<glm::dvec3>& normals, const std::vector<glm::dvec2>& tcoords,
  const std::vector<std::array<long long, 3>>& triangles)
{
  const size_t n = positions.size();
  if (normals.size() != n || tcoords.size() != n)
  {
    throw SurfaceQuadricsError("surface quadrics need one normal and one texture coordinate per "
                               "vertex: " +
      std::to_string(n) + " vertices, " + std::to_string(normals.size()) + " normals, " +
      std::to_string(tcoords.size()) + " texture coordinates");
  }
  for (size_t t = 0; t < triangles.size(); ++t)
  {
    for (long long v : triangles[t])
    {
      if (v < 0 || static_cast<size_t>(v) >= n)
      {
        throw SurfaceQuadricsError("triangle " + std::to_string(t) + " names vertex " +
          std::to_string(v) + " of " + std::to_string(n));
      }
    }
  }
  std::vector<size_t> offsets, ring;
  OneRings(n, triangles, offsets, ring);

  std::vector<glm::vec2> quadrics(n, glm::vec2(0.0f));
  std::vector<size_t> seen;
  for (size_t i = 0; i < n; ++i)
  {
    seen.assign(ring.begin() + static_cast<std::ptrdiff_t>(offsets[i]),
      ring.begin() + static_cast<std::ptrdiff_t>(offsets[i + 1]));
    std::sort(seen.begin(), seen.end());
    seen.erase(std::unique(seen.begin(), seen.end()), seen.end());
    const glm::dvec3 normal = normals[i];
    const double normalLength = glm::length(normal);
    if (!(normalLength > 0.0) || !std::isfinite(normalLength))
    {
      continue;
    }
    const glm::dvec3 nrm = normal / normalLength;
    // Normal equations of two fits over the one-ring, offsets (du, dv):
    //  - the tangential offset e_t = P_u du + P_v dv (the world length of a texture unit, s);
    //  - the depth below the tangent plane d = a du^2 + 2 c du dv + b dv^2.
    glm::dmat2 uv(0.0);
    glm::dvec3 ru(0.0), rv(0.0);
    glm::dmat3 q(0.0);
    glm::dvec3 rq(0.0);
    for (size_t j : seen)
    {
      if (j == i)
      {
        continue;
      }
      const glm::dvec3 e = positions[j] - positions[i];
      const glm::dvec2 duv = tcoords[j] - tcoords[i];
      const double depth = -glm::dot(e, nrm);
      const glm::dvec3 tangential = e + depth * nrm;
      uv[0][0] += duv.x * duv.x;
      uv[0][1] += duv.x * duv.y;
      uv[1][1] += duv.y * duv.y;
      ru += tangential * duv.x;
      rv += tangential * duv.y;
      const glm::dvec3 x(duv.x * duv.x, 2.0 * duv.x * duv.y, duv.y * duv.y);
      for (int r = 0; r < 3; ++r)
      {
        for (int c = 0; c < 3; ++c)
        {
          q[c][r] += x[r] * x[c];
        }
      }
      rq += depth * x;
    }
    uv[1][0] = uv[0][1];
    const double detUV = glm::determinant(uv);
    if (!Determined(detUV, uv[0][0] * uv[1][1]))
    {
      continue;
    }
    const glm::dvec3 pu = (uv[1][1] * ru - uv[0][1] * rv) / detUV;
    const double s = glm::length(pu);
    if (!(s > 0.0) || !std::isfinite(s))
    {
      continue;
    }
    double a = 0.0, b = 0.0;
    const double detQ = glm::determinant(q);
    if (Determined(detQ, q[0][0] * q[1][1] * q[2][2]))
    {
      const glm::dvec3 coefficients = glm::inverse(q) * rq;
      a = coefficients.x;
      b = coefficients.z;
    }
    else
    {
      // Too few directions for the cross term (a corner of a grid): a and b alone.
      const double m00 = q[0][0], m01 = q[2][0], m11 = q[2][2];
      const double det = m00 * m11 - m01 * m01;
      if (!Determined(det, m00 * m11))
      {
        continue;
      }
      a = (m11 * rq.x - m01 * rq.z) / det;
      b = (m00 * rq.z - m01 * rq.x) / det;
    }
    a /= s;
    b /= s;
    quadrics[i] =
      glm::vec2(std::abs(a) < SurfaceQuadricFlatThreshold ? 0.0f : static_cast<float>(a),
        std::abs(b) < SurfaceQuadricFlatThreshold ? 0.0f : static_cast<float>(b));
  }
  return quadrics;
}

//------------------------------------------------------------------------------
bool AnySurfaceQuadric(const std::vector<glm::vec2>& quadrics)
{
  return std::any_of(quadrics.begin(), quadrics.end(),
    [](const glm::vec2& q) { return q.x != 0.0f || q.y != 0.0f; });
}

} // namespace mesolight
