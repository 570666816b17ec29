// SPDX-License-Identifier: BSD-3-Clause
/**
 * @file LightSetSplit.h
 * @brief A light set (directions and irradiances at normal incidence, vtkMedianCutLights) split
 *        for a rasterizer: the K strongest lights as directional lights, the others as one
 *        low-frequency term (plain C++17, no VTK types).
 *
 * Each light i delivers E_i max(0, n.d_i) to a surface of normal n. The K lights of largest
 * luminance stay exact (and can cast shadow maps); the remainder sum_{i>K} E_i max(0, n.d_i)
 * becomes either
 *  - Ambient: its average over all normals, sum E_i / 4 (what a constant term can do best over
 *    the sphere of normals), or
 *  - SphericalHarmonics: the irradiance of its 9-coefficient projection (Ramamoorthi &
 *    Hanrahan, "An efficient representation for irradiance environment maps"): each light is a
 *    delta of weight E_i, L_lm = sum E_i Y_lm(d_i), E(n) = sum A_l L_lm Y_lm(n), clamped at 0.
 * The remainder casts no shadow. docs/light-set-actors.md measures both against the path tracer.
 */
#ifndef mesolight_LightSetSplit_h
#define mesolight_LightSetSplit_h

#include "EnvironmentMaps.h"

#include <vector>

namespace mesolight
{

struct SetLight
{
  double Direction[3] = { 0.0, 0.0, 1.0 };  ///< unit, toward the light
  double Irradiance[3] = { 0.0, 0.0, 0.0 }; ///< RGB at normal incidence
};

enum class RemainderModel
{
  None,              ///< the other lights are dropped (for negative tests)
  Ambient,           ///< a constant: their irradiance averaged over all normals
  SphericalHarmonics ///< their SH9 irradiance
};

struct LightSetSplit
{
  std::vector<SetLight> Directional; ///< the K strongest, strongest first
  RemainderModel Model = RemainderModel::SphericalHarmonics;
  SH9 Remainder; ///< SH radiance coefficients of the others (Ambient: L00 only)

  /// Irradiance of the split at unit normal n (unshadowed): what a rasterizer should shade.
  void Evaluate(const double n[3], double e[3]) const;
  /// Remainder only, clamped at 0.
  void EvaluateRemainder(const double n[3], double e[3]) const;
  /**
   * The remainder as 9 RGB coefficients c_k of the polynomials
   * (1, y, z, x, xy, yz, 3z^2 - 1, xz, x^2 - y^2): E(n) = sum c_k p_k(n), for a shader.
   */
  void PolynomialCoefficients(float c[9][3]) const;
};

/**
 * Splits the lights: the `directional` ones of largest luminance (ties keep the input order)
 * and the rest as `model`. directional is clamped to [0, lights.size()].
 */
MESOLIGHTLIGHTING_EXPORT LightSetSplit SplitLightSet(
  const std::vector<SetLight>& lights, int directional, RemainderModel model);

/// Exact irradiance of all the lights at unit normal n (no shadows).
MESOLIGHTLIGHTING_EXPORT void LightSetIrradiance(
  const std::vector<SetLight>& lights, const double n[3], double e[3]);

} // namespace mesolight

#endif
