// SPDX-License-Identifier: BSD-3-Clause
#include "LightSetSplit.h"

#include "MathConstants.h"

#include <algorithm>
#include <numeric>

namespace mesolight
{

namespace
{
// Cosine-lobe convolution per band (Ramamoorthi & Hanrahan): A0 = pi, A1 = 2 pi / 3, A2 = pi / 4.
constexpr double BandWeight[9] = { Pi<double>, 2.0 * Pi<double> / 3.0, 2.0 * Pi<double> / 3.0,
  2.0 * Pi<double> / 3.0, Pi<double> / 4.0, Pi<double> / 4.0, Pi<double> / 4.0, Pi<double> / 4.0,
  Pi<double> / 4.0 };
// Y_lm = constant x polynomial (EvaluateSHBasis).
constexpr double BasisConstant[9] = { 0.282095, 0.488603, 0.488603, 0.488603, 1.092548, 1.092548,
  0.315392, 1.092548, 0.546274 };
} // namespace

//------------------------------------------------------------------------------
void LightSetIrradiance(const std::vector<SetLight>& lights, const double n[3], double e[3])
{
  e[0] = e[1] = e[2] = 0.0;
  for (const SetLight& l : lights)
  {
    const double c =
      std::max(0.0, n[0] * l.Direction[0] + n[1] * l.Direction[1] + n[2] * l.Direction[2]);
    for (int k = 0; k < 3; ++k)
    {
      e[k] += c * l.Irradiance[k];
    }
  }
}

//------------------------------------------------------------------------------
LightSetSplit SplitLightSet(
  const std::vector<SetLight>& lights, int directional, RemainderModel model)
{
  std::vector<size_t> order(lights.size());
  std::iota(order.begin(), order.end(), size_t{ 0 });
  auto luminance = [&](size_t i)
  {
    const double* e = lights[i].Irradiance;
    return Luminance(e[0], e[1], e[2]);
  };
  std::stable_sort(
    order.begin(), order.end(), [&](size_t a, size_t b) { return luminance(a) > luminance(b); });
  const size_t k = static_cast<size_t>(
    std::clamp(directional, 0, static_cast<int>(std::min<size_t>(lights.size(), 1u << 30))));

  LightSetSplit split;
  split.Model = model;
  for (size_t i = 0; i < k; ++i)
  {
    split.Directional.push_back(lights[order[i]]);
  }
  if (model == RemainderModel::None)
  {
    return split;
  }
  for (size_t i = k; i < order.size(); ++i)
  {
    const SetLight& l = lights[order[i]];
    double y[9];
    EvaluateSHBasis(l.Direction, y);
    const int bands = model == RemainderModel::Ambient ? 1 : 9;
    for (int b = 0; b < bands; ++b)
    {
      for (int c = 0; c < 3; ++c)
      {
        split.Remainder.L[b][c] += l.Irradiance[c] * y[b];
      }
    }
  }
  return split;
}

//------------------------------------------------------------------------------
void LightSetSplit::EvaluateRemainder(const double n[3], double e[3]) const
{
  e[0] = e[1] = e[2] = 0.0;
  if (this->Model == RemainderModel::None)
  {
    return;
  }
  IrradianceSH9(this->Remainder, n, e);
  for (int c = 0; c < 3; ++c)
  {
    e[c] = std::max(0.0, e[c]);
  }
}

//------------------------------------------------------------------------------
void LightSetSplit::Evaluate(const double n[3], double e[3]) const
{
  LightSetIrradiance(this->Directional, n, e);
  double r[3];
  this->EvaluateRemainder(n, r);
  for (int c = 0; c < 3; ++c)
  {
    e[c] += r[c];
  }
}

//------------------------------------------------------------------------------
void LightSetSplit::PolynomialCoefficients(float c[9][3]) const
{
  for (int b = 0; b < 9; ++b)
  {
    for (int k = 0; k < 3; ++k)
    {
      c[b][k] = this->Model == RemainderModel::None
        ? 0.0f
        : static_cast<float>(BandWeight[b] * BasisConstant[b] * this->Remainder.L[b][k]);
    }
  }
}

} // namespace mesolight
