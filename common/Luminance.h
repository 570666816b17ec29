// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file Luminance.h
 * @brief The luminance of linear RGB, once, for every Mesolight core (plain C++17).
 *
 * Y = 0.2126 R + 0.7152 G + 0.0722 B: ITU-R BT.709's weights, those of linear sRGB, the
 * primaries of the HDR maps, textures and images Mesolight reads and writes. Debevec's "A median
 * cut algorithm for light probe sampling" and Méndez Fernández's thesis (eq. 11) print them
 * rounded as 0.2125, 0.7154, 0.0721.
 */
#ifndef mesolight_Luminance_h
#define mesolight_Luminance_h

namespace mesolight
{

template <class T>
constexpr T Luminance(T r, T g, T b)
{
  return T(0.2126) * r + T(0.7152) * g + T(0.0722) * b;
}

/// The luminance of the pixel rgb[0..2].
template <class T>
constexpr T Luminance(const T* rgb)
{
  return Luminance(rgb[0], rgb[1], rgb[2]);
}

} // namespace mesolight

#endif
