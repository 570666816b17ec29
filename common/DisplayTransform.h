// SPDX-License-Identifier: BSD-3-Clause
// DisplayTransform: linear radiance -> display value in [0, 1], the one C++ implementation of
// exposure, tone mapping (clamp or Reinhard's x / (1 + x)) and the sRGB transfer curve, and of
// their inverses. Plain C++ (no VTK types); templates so float and double callers keep their own
// precision (images written from float and from double radiance stay bit for bit what they were).
//
// The GPU twins stay GLSL: vtkVLF/LightFieldActor/glsl/vtkLightFieldFS.glsl (the light field actor
// and vtkCompositeLightFieldMapper: exposure, clamp or Reinhard, sRGB) and the ML_TONE_MAPPING
// block of vtkRelief/glsl/vtkReliefImplFS.glsl (Reinhard without sRGB: relief surfaces are shaded
// like VTK's own actors, whose colours go to the framebuffer as they are). Each class keeps its own
// default, listed in docs/dev/conventions.md.
#ifndef mesolight_DisplayTransform_h
#define mesolight_DisplayTransform_h

#include <algorithm>
#include <cmath>

namespace mesolight
{

// The values are those of the VTK classes' int properties and of the GLSL uniform mlToneMap.
enum class ToneMapOperator
{
  Clamp = 0,   // exposure x radiance, clamped to [0, 1]
  Reinhard = 1 // v / (1 + v) of v = exposure x radiance (Reinhard et al., "Photographic tone
               // reproduction for digital images")
};

struct DisplayTransform
{
  double Exposure = 1.0; // radiance scale before the tone map
  ToneMapOperator ToneMap = ToneMapOperator::Clamp;
  bool EncodeSRGB = true;
};

// Light-set shading of relief surfaces (vtkReliefProperty's defaults, which ParaView's Relief
// Surface representation repeats): a median-cut light set carries the environment's whole
// irradiance (its lights' colours sum to the map's integral of L dOmega), and the view's own
// lights add to it, so a first image at exposure 1 shades well above 1 and, clamped, blows out
// (about a quarter of a sky-lit relief at 250+ of 255). Reinhard's x / (1 + x) keeps it below
// white and leaves dim values nearly linear. No sRGB: relief colours go to the framebuffer as
// VTK's own actors' do.
inline constexpr DisplayTransform ReliefLightSetDisplay{ 1.0, ToneMapOperator::Reinhard, false };

// The sRGB transfer curve of IEC 61966-2-1, on values clamped to [0, 1].
template <typename T>
T ToSRGB(T linear)
{
  linear = std::min(std::max(linear, T(0)), T(1));
  return linear <= T(0.0031308) ? T(12.92) * linear
                                : T(1.055) * std::pow(linear, T(1) / T(2.4)) - T(0.055);
}

// The inverse of ToSRGB, on values clamped to [0, 1].
template <typename T>
T FromSRGB(T encoded)
{
  encoded = std::min(std::max(encoded, T(0)), T(1));
  return encoded <= T(0.04045) ? encoded / T(12.92)
                               : std::pow((encoded + T(0.055)) / T(1.055), T(2.4));
}

// Display value in [0, 1] of one linear radiance channel (negative and NaN give 0).
template <typename T>
T ApplyDisplayTransform(const DisplayTransform& transform, T radiance)
{
  T v = std::max(T(0), static_cast<T>(transform.Exposure) * radiance);
  if (transform.ToneMap == ToneMapOperator::Reinhard)
  {
    v = v / (T(1) + v);
  }
  return transform.EncodeSRGB ? ToSRGB(v) : std::min(v, T(1));
}

// Linear radiance of a display value: the inverse of ApplyDisplayTransform, where display 1 maps
// to the clipping point of Clamp and to 1e6 for Reinhard; 0 at exposure 0.
template <typename T>
T InvertDisplayTransform(const DisplayTransform& transform, T display)
{
  T v = transform.EncodeSRGB ? FromSRGB(display) : std::min(std::max(display, T(0)), T(1));
  if (transform.ToneMap == ToneMapOperator::Reinhard)
  {
    v = v < T(1) ? v / (T(1) - v) : T(1e6);
  }
  const T exposure = static_cast<T>(transform.Exposure);
  return exposure > T(0) ? v / exposure : T(0);
}

} // namespace mesolight

#endif
