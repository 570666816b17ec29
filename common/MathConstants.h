// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file MathConstants.h
 * @brief pi, once, for every type the cores compute in (plain C++17).
 *
 * `mesolight::Pi<float>` is the float nearest to pi and `Pi<double>` the double nearest to pi,
 * the same values as the literals 3.14159265358979323846f and 3.14159265358979323846.
 */
#ifndef mesolight_MathConstants_h
#define mesolight_MathConstants_h

namespace mesolight
{

template <class T>
constexpr T Pi = T(3.14159265358979323846264338327950288L);

} // namespace mesolight

#endif
