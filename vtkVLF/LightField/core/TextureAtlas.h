// SPDX-License-Identifier: BSD-3-Clause
// TextureAtlas: every surface's total diffuse radiance texture of a LightField packed into one
// RGBA float image for the GPU (Wither 2005 §2.4.2.2.3: diffuse surfaces are drawn with their
// total texture maps). Plain C++ (GLM, no VTK types).
//
// Each surface's texture gets a rectangle of (width + 2) x (height + 2) texels: the texture plus
// a 1-texel gutter that repeats its edge texels. GL's bilinear filter at a point of the surface
// then reads only that surface's texels, with the same clamped weights as
// LightField::SampleTexture, so surfaces that share an edge never bleed into each other (no
// seams) and the GPU shows exactly the field's values. Rectangles are packed on shelves.
//
// Alpha carries the surface class: 1 for surfaces with a perfect-specular part (Ks > 0; their
// pixels are composited with the screen-space reflection), 0 for diffuse-only surfaces.
// Row 0 of the image is the lowest v (OpenGL's texture origin).
#ifndef mesolight_vlf_TextureAtlas_h
#define mesolight_vlf_TextureAtlas_h

#include "LightField.h"

#include <glm/vec2.hpp>
#include <glm/vec3.hpp>
#include <glm/vec4.hpp>

#include <cstdint>
#include <string>
#include <vector>

namespace mesolight
{
namespace vlf
{

struct AtlasRect
{
  int X = 0, Y = 0;          // lower-left texel of the rectangle (gutter included)
  int Width = 0, Height = 0; // gutter included
};

class TextureAtlas
{
public:
  // Packs the field's surfaces (largest first, shelves, width chosen near the square root of the
  // total area). Throws std::length_error when the atlas would exceed maxSide texels per side.
  explicit TextureAtlas(const LightField& field, int maxSide = 16384);

  int Width() const { return this->AtlasWidth; }
  int Height() const { return this->AtlasHeight; }
  // RGBA floats, row-major, row 0 = v near 0.
  const std::vector<float>& Pixels() const { return this->Data; }
  // The same image upside down (rows reversed): what a wrong-orientation upload would give.
  std::vector<float> FlippedPixels() const;
  const AtlasRect& Rect(std::uint32_t surface) const { return this->Rects[surface]; }

  // Normalised texture coordinates ([0,1]^2, texel centres at (i + 1/2) / size) of a point on
  // a surface (unit-sphere coordinates, as LightField::Scene()).
  glm::vec2 TextureCoordinates(std::uint32_t surface, const glm::vec3& point) const;

  // What the GPU's bilinear (GL_LINEAR, clamp to edge) lookup returns at normalised texture
  // coordinates: the test's model of the draw.
  glm::vec4 SampleBilinear(const glm::vec2& tc) const;

  // Fraction of the atlas covered by surface texels (without gutters).
  double Occupancy() const;

private:
  const LightField& Field;
  int AtlasWidth = 0;
  int AtlasHeight = 0;
  std::vector<AtlasRect> Rects;
  std::vector<float> Data;
};

} // namespace vlf
} // namespace mesolight

#endif
