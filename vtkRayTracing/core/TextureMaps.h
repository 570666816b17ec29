// SPDX-License-Identifier: BSD-3-Clause
// Texture maps of the ray tracer (Ahern 1999 §1): RGB float images looked up at texture
// coordinates with repeat wrapping, nearest or bilinear; sphere texture coordinates from an
// axis and a meridian; a tangent frame from texture-coordinate derivatives for bump mapping.
#ifndef mesolight_TextureMaps_h
#define mesolight_TextureMaps_h

#include "RgbImage.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>

namespace mesolight
{

enum class TextureFilter
{
  Nearest,
  Bilinear
};

// Colour at texture coordinates (s, t); s grows along a row, t with the row index (VTK order:
// t = 0 is row 0, the bottom). Texel (i, j) covers [i, i+1) x [j, j+1) in units of texels, its
// centre at (i + 0.5, j + 0.5); coordinates repeat outside [0, 1). An empty image reads white.
glm::vec3 SampleTexture(const RgbImage& image, glm::vec2 st, TextureFilter filter);

// Texture coordinates of a point on a sphere (Ahern 1999 §1): t = angle from the axis / pi
// (0 at the pole the axis points to), s = angle around the axis from the meridian / (2 pi),
// counter-clockwise seen from the axis' tip, in [0, 1). axis and meridian need not be unit or
// orthogonal (the meridian is projected onto the equator plane).
glm::vec2 SphereTextureCoordinates(
  const glm::vec3& unitNormal, const glm::vec3& axis, const glm::vec3& meridian);

// A tangent frame (T, B) around a unit normal N, T along increasing s and B along increasing t
// as far as the surface allows, both unit and orthogonal to N.
struct TangentFrame
{
  glm::vec3 Tangent;
  glm::vec3 Bitangent;
};

// From a triangle's positions and texture coordinates (dP/ds, dP/dt made orthogonal to N,
// B = sign * N x T keeps the handedness of the texture). Falls back to FrameAroundNormal when
// the texture coordinates are degenerate (collinear or repeated).
TangentFrame TriangleTangentFrame(
  const glm::vec3& normal, const glm::vec3 p[3], const glm::vec2 st[3]);

// On a sphere: T along the circles of latitude (increasing s), B toward increasing t; at the
// poles, where s is undefined, falls back to FrameAroundNormal.
TangentFrame SphereTangentFrame(
  const glm::vec3& unitNormal, const glm::vec3& axis, const glm::vec3& meridian);

// Any orthonormal frame around N without a fixed reference axis (Duff et al., JCGT 2017): no
// singularity where N crosses a coordinate axis (Ahern's [1 0 0] x N has one).
TangentFrame FrameAroundNormal(const glm::vec3& unitNormal);

// The bump-mapped normal (Ahern 1999 §1): the map's red and green, mapped from [0, 1] to
// [-scale, scale] (0.5 = no tilt), tilt N toward T and B: N' = normalize(N + r T + g B).
glm::vec3 BumpedNormal(
  const glm::vec3& unitNormal, const TangentFrame& frame, const glm::vec3& bump, float scale);

} // namespace mesolight

#endif
