// SPDX-License-Identifier: BSD-3-Clause
#include "TextureAtlas.h"

#include <algorithm>
#include <cmath>
#include <numeric>
#include <stdexcept>

namespace mesolight
{
namespace vlf
{

TextureAtlas::TextureAtlas(const LightField& field, int maxSide)
  : Field(field)
{
  const std::vector<Surface>& surfaces = field.Surfaces();
  this->Rects.resize(surfaces.size());
  std::vector<std::uint32_t> order(surfaces.size());
  std::iota(order.begin(), order.end(), 0u);
  double area = 0.0;
  int widest = 1;
  for (std::uint32_t s = 0; s < surfaces.size(); ++s)
  {
    this->Rects[s].Width = surfaces[s].TextureWidth + 2;
    this->Rects[s].Height = surfaces[s].TextureHeight + 2;
    area += static_cast<double>(this->Rects[s].Width) * this->Rects[s].Height;
    widest = std::max(widest, this->Rects[s].Width);
  }
  // Tallest first: shelves then waste little height.
  std::stable_sort(order.begin(), order.end(),
    [&](std::uint32_t a, std::uint32_t b)
    { return this->Rects[a].Height > this->Rects[b].Height; });
  const int width = std::max(widest, static_cast<int>(std::ceil(std::sqrt(area * 1.1))));
  if (width > maxSide)
  {
    throw std::length_error(
      "the texture atlas would be wider than " + std::to_string(maxSide) + " texels");
  }
  int x = 0, y = 0, shelf = 0;
  for (const std::uint32_t s : order)
  {
    AtlasRect& r = this->Rects[s];
    if (x + r.Width > width)
    {
      x = 0;
      y += shelf;
      shelf = 0;
    }
    r.X = x;
    r.Y = y;
    x += r.Width;
    shelf = std::max(shelf, r.Height);
  }
  this->AtlasWidth = std::max(1, width);
  this->AtlasHeight = std::max(1, y + shelf);
  if (this->AtlasHeight > maxSide)
  {
    throw std::length_error(
      "the texture atlas would be taller than " + std::to_string(maxSide) + " texels");
  }

  this->Data.assign(static_cast<std::size_t>(this->AtlasWidth) * this->AtlasHeight * 4, 0.0f);
  for (std::uint32_t s = 0; s < surfaces.size(); ++s)
  {
    const Surface& surface = surfaces[s];
    const AtlasRect& r = this->Rects[s];
    const SceneMaterial& material = field.MaterialOf(s);
    const float specular =
      std::max(material.Specular.x, std::max(material.Specular.y, material.Specular.z)) > 0.0f
      ? 1.0f
      : 0.0f;
    for (int b = -1; b <= surface.TextureHeight; ++b)
    {
      // The gutter repeats the edge texels: bilinear there equals the field's clamped bilinear.
      const int sb = std::min(std::max(b, 0), surface.TextureHeight - 1);
      for (int a = -1; a <= surface.TextureWidth; ++a)
      {
        const int sa = std::min(std::max(a, 0), surface.TextureWidth - 1);
        const glm::vec3 value = field.TotalDiffuse[surface.TexelOffset +
          static_cast<std::size_t>(sb) * surface.TextureWidth + sa];
        float* out =
          &this
             ->Data[(static_cast<std::size_t>(r.Y + 1 + b) * this->AtlasWidth + (r.X + 1 + a)) * 4];
        out[0] = value.x;
        out[1] = value.y;
        out[2] = value.z;
        out[3] = specular;
      }
    }
  }
}

std::vector<float> TextureAtlas::FlippedPixels() const
{
  std::vector<float> flipped(this->Data.size());
  const std::size_t row = static_cast<std::size_t>(this->AtlasWidth) * 4;
  for (int y = 0; y < this->AtlasHeight; ++y)
  {
    std::copy_n(&this->Data[static_cast<std::size_t>(y) * row], row,
      &flipped[static_cast<std::size_t>(this->AtlasHeight - 1 - y) * row]);
  }
  return flipped;
}

glm::vec2 TextureAtlas::TextureCoordinates(std::uint32_t surface, const glm::vec3& point) const
{
  // Texel centres of the surface at integers; atlas texel centres at (i + 1/2) / size.
  const Surface& s = this->Field.Surfaces()[surface];
  glm::vec2 t = s.TexelCoordinates(point);
  // Within one texel of the texture the gutter makes GL's bilinear the field's clamped one.
  t.x = std::min(std::max(t.x, -1.0f), static_cast<float>(s.TextureWidth));
  t.y = std::min(std::max(t.y, -1.0f), static_cast<float>(s.TextureHeight));
  const AtlasRect& r = this->Rects[surface];
  return glm::vec2((static_cast<float>(r.X) + 1.5f + t.x) / static_cast<float>(this->AtlasWidth),
    (static_cast<float>(r.Y) + 1.5f + t.y) / static_cast<float>(this->AtlasHeight));
}

glm::vec4 TextureAtlas::SampleBilinear(const glm::vec2& tc) const
{
  const float x = tc.x * static_cast<float>(this->AtlasWidth) - 0.5f;
  const float y = tc.y * static_cast<float>(this->AtlasHeight) - 0.5f;
  const float fx = std::floor(x), fy = std::floor(y);
  const float ax = x - fx, ay = y - fy;
  glm::vec4 sum(0.0f);
  for (int q = 0; q < 4; ++q)
  {
    const int dx = q & 1, dy = q >> 1;
    const int ix = std::min(std::max(static_cast<int>(fx) + dx, 0), this->AtlasWidth - 1);
    const int iy = std::min(std::max(static_cast<int>(fy) + dy, 0), this->AtlasHeight - 1);
    const float w = (dx ? ax : 1.0f - ax) * (dy ? ay : 1.0f - ay);
    const float* p = &this->Data[(static_cast<std::size_t>(iy) * this->AtlasWidth + ix) * 4];
    sum += w * glm::vec4(p[0], p[1], p[2], p[3]);
  }
  return sum;
}

double TextureAtlas::Occupancy() const
{
  double used = 0.0;
  for (const Surface& s : this->Field.Surfaces())
  {
    used += static_cast<double>(s.TexelCount());
  }
  return used / (static_cast<double>(this->AtlasWidth) * this->AtlasHeight);
}

} // namespace vlf
} // namespace mesolight
