// SPDX-License-Identifier: BSD-3-Clause
#include "TextureMaps.h"

#include "MathConstants.h"

#include <glm/geometric.hpp>

#include <algorithm>
#include <cmath>

namespace mesolight
{

namespace
{
int Wrap(int i, int n)
{
  const int r = i % n;
  return r < 0 ? r + n : r;
}

glm::vec3 Texel(const RgbImage& image, int i, int j)
{
  const float* p = image.Pixel(Wrap(i, image.Width), Wrap(j, image.Height));
  return glm::vec3(p[0], p[1], p[2]);
}
} // namespace

glm::vec3 SampleTexture(const RgbImage& image, glm::vec2 st, TextureFilter filter)
{
  if (image.Width <= 0 || image.Height <= 0 || image.Rgb.size() < 3u * image.Width * image.Height)
  {
    return glm::vec3(1.0f);
  }
  if (!std::isfinite(st.x) || !std::isfinite(st.y))
  {
    st = glm::vec2(0.0f);
  }
  // Reduce to [0, 1) first so huge coordinates keep their precision in texel units.
  st -= glm::floor(st);
  const float x = st.x * static_cast<float>(image.Width);
  const float y = st.y * static_cast<float>(image.Height);
  if (filter == TextureFilter::Nearest)
  {
    return Texel(image, static_cast<int>(std::floor(x)), static_cast<int>(std::floor(y)));
  }
  const float fx = x - 0.5f;
  const float fy = y - 0.5f;
  const int i0 = static_cast<int>(std::floor(fx));
  const int j0 = static_cast<int>(std::floor(fy));
  const float ax = fx - static_cast<float>(i0);
  const float ay = fy - static_cast<float>(j0);
  const glm::vec3 bottom = (1.0f - ax) * Texel(image, i0, j0) + ax * Texel(image, i0 + 1, j0);
  const glm::vec3 top = (1.0f - ax) * Texel(image, i0, j0 + 1) + ax * Texel(image, i0 + 1, j0 + 1);
  return (1.0f - ay) * bottom + ay * top;
}

namespace
{

// Unit axis and the meridian made orthogonal to it; false when they are parallel or zero.
bool SphereAxes(const glm::vec3& axis, const glm::vec3& meridian, glm::vec3& a, glm::vec3& m)
{
  const float axisLength = glm::length(axis);
  if (!(axisLength > 0.0f))
  {
    return false;
  }
  a = axis / axisLength;
  m = meridian - glm::dot(meridian, a) * a;
  const float meridianLength = glm::length(m);
  if (!(meridianLength > 1e-6f * glm::length(meridian)) || !(meridianLength > 0.0f))
  {
    return false;
  }
  m /= meridianLength;
  return true;
}
} // namespace

glm::vec2 SphereTextureCoordinates(
  const glm::vec3& unitNormal, const glm::vec3& axis, const glm::vec3& meridian)
{
  glm::vec3 a, m;
  if (!SphereAxes(axis, meridian, a, m))
  {
    a = glm::vec3(0.0f, 0.0f, 1.0f);
    m = glm::vec3(1.0f, 0.0f, 0.0f);
  }
  const glm::vec3 east = glm::cross(a, m); // 90 degrees counter-clockwise from the meridian
  const float t = std::acos(glm::clamp(glm::dot(unitNormal, a), -1.0f, 1.0f)) / Pi<float>;
  float s = std::atan2(glm::dot(unitNormal, east), glm::dot(unitNormal, m)) / (2.0f * Pi<float>);
  if (s < 0.0f)
  {
    s += 1.0f;
  }
  return glm::vec2(s >= 1.0f ? 0.0f : s, t);
}

TangentFrame FrameAroundNormal(const glm::vec3& n)
{
  const float sign = std::copysign(1.0f, n.z);
  const float a = -1.0f / (sign + n.z);
  const float b = n.x * n.y * a;
  return TangentFrame{ glm::vec3(1.0f + sign * n.x * n.x * a, sign * b, -sign * n.x),
    glm::vec3(b, sign + n.y * n.y * a, -n.y) };
}

TangentFrame TriangleTangentFrame(
  const glm::vec3& normal, const glm::vec3 p[3], const glm::vec2 st[3])
{
  const glm::vec3 e1 = p[1] - p[0];
  const glm::vec3 e2 = p[2] - p[0];
  const glm::vec2 d1 = st[1] - st[0];
  const glm::vec2 d2 = st[2] - st[0];
  const float determinant = d1.x * d2.y - d2.x * d1.y;
  const float scale = std::max(glm::dot(d1, d1), glm::dot(d2, d2));
  if (!(std::abs(determinant) > 1e-12f * scale) || !(scale > 0.0f))
  {
    return FrameAroundNormal(normal);
  }
  // Solve [e1 e2] = [dPds dPdt] [d1 d2].
  const glm::vec3 dPds = (d2.y * e1 - d1.y * e2) / determinant;
  const glm::vec3 dPdt = (-d2.x * e1 + d1.x * e2) / determinant;
  glm::vec3 tangent = dPds - glm::dot(dPds, normal) * normal;
  const float length = glm::length(tangent);
  if (!(length > 0.0f))
  {
    return FrameAroundNormal(normal);
  }
  tangent /= length;
  glm::vec3 bitangent = glm::cross(normal, tangent);
  if (glm::dot(bitangent, dPdt) < 0.0f)
  {
    bitangent = -bitangent; // mirrored texture: keep B along increasing t
  }
  return TangentFrame{ tangent, bitangent };
}

TangentFrame SphereTangentFrame(
  const glm::vec3& unitNormal, const glm::vec3& axis, const glm::vec3& meridian)
{
  glm::vec3 a, m;
  if (!SphereAxes(axis, meridian, a, m))
  {
    a = glm::vec3(0.0f, 0.0f, 1.0f);
  }
  glm::vec3 tangent = glm::cross(a, unitNormal); // along increasing s (counter-clockwise)
  const float length = glm::length(tangent);
  if (!(length > 1e-6f))
  {
    return FrameAroundNormal(unitNormal);
  }
  tangent /= length;
  // Increasing t moves away from the axis' pole: along T x N (for N = (sin t cos s,
  // sin t sin s, cos t), dN/dt = (cos t cos s, cos t sin s, -sin t) = T x N).
  return TangentFrame{ tangent, glm::cross(tangent, unitNormal) };
}

glm::vec3 BumpedNormal(
  const glm::vec3& n, const TangentFrame& frame, const glm::vec3& bump, float scale)
{
  const float r = (2.0f * bump.x - 1.0f) * scale;
  const float g = (2.0f * bump.y - 1.0f) * scale;
  const glm::vec3 bent = n + r * frame.Tangent + g * frame.Bitangent;
  const float length = glm::length(bent);
  return length > 0.0f && std::isfinite(length) ? bent / length : n;
}

} // namespace mesolight
