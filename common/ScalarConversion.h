// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file ScalarConversion.h
 * @brief Stored scalar <-> unit float conversions shared by the filters (header only).
 *
 * Integer images store [0,1] as [0, max of the type]: unsigned char / 255, unsigned short
 * / 65535, ...; signed integers are divided by their maximum too, negative values staying
 * negative (out of range where [0,1] is expected, as a float's would be: elevation maps below
 * sea level, no-data values); floating-point values are used as they are.
 */
#ifndef mesolight_ScalarConversion_h
#define mesolight_ScalarConversion_h

#include <algorithm>
#include <cmath>
#include <limits>
#include <type_traits>

namespace mesolight
{

template <typename T>
inline double ToUnitValue(T value)
{
  if constexpr (std::is_floating_point<T>::value)
  {
    return static_cast<double>(value);
  }
  else
  {
    return static_cast<double>(value) / static_cast<double>(std::numeric_limits<T>::max());
  }
}

/// Quantize a unit value to an unsigned integer type with rounding and clamping (NaN -> 0).
template <typename T>
inline T FromUnitValue(double value)
{
  static_assert(std::is_integral<T>::value, "integer target expected");
  if (!(value > 0.0)) // also catches NaN
  {
    return T(0);
  }
  const double maxValue = static_cast<double>(std::numeric_limits<T>::max());
  return static_cast<T>(std::lround(std::min(1.0, value) * maxValue));
}

} // namespace mesolight

#endif
