// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: an image-based light set (median-cut lights of an HDR environment, Méndez Fernández's thesis
// §5), each light shading and self-shadowing the height field, which gives soft shadows.
//
// The light texture is N x 2: row 0 the unit directions toward the lights (world coordinates)
// and their luminance (A), row 1 the irradiance each delivers at normal incidence (RGB). Lights
// come sorted by luminance, strongest first, so the loop can stop at the first negligible one.
// The loop runs in world coordinates (one normal transform per pixel, not one per light) and
// reads a light's irradiance only if the light faces the pixel.
// What a pixel does not need is skipped: lights behind the shading normal or below the
// macro-surface horizon get no shadow march, and with mlShadowedLights > 0 only the strongest
// facing lights are marched; the others are weighted by the visible fraction of those.

uniform sampler2D mlLightSet;
uniform int mlLightSetCount;
uniform float mlLightSetCutoff; // luminance below which lights are skipped
uniform int mlShadowedLights;   // 0: march every facing light

// Irradiance at the hit from the light set (to be multiplied by albedo / pi).
vec3 mlLightSetIrradiance(vec3 normalVC, vec3 hit, mat3 worldToTexture, bool marchShadows)
{
  vec3 irradiance = vec3(0.0);
  vec3 unmarched = vec3(0.0);
  float marchedWeight = 0.0;
  float visibleWeight = 0.0;
  int marched = 0;
  float wasted = 0.0; // only with ML_NO_SHADOW_CULLING, to measure what culling saves
  vec3 normalWC = transpose(mlWorldToView) * normalVC; // the view rotation is orthonormal
  for (int i = 0; i < mlLightSetCount; ++i)
  {
    vec4 light = texelFetch(mlLightSet, ivec2(i, 0), 0);
    if (light.a < mlLightSetCutoff)
    {
      break; // sorted: every further light is weaker still
    }
    float ndl = dot(normalWC, light.xyz);
    if (ndl <= 0.0)
    {
#if defined(ML_NO_SHADOW_CULLING) && defined(ML_SELF_SHADOWING)
      vec3 away = worldToTexture * (mlWorldToView * light.xyz);
      if (marchShadows && away.z < -1e-6)
      {
        wasted += mlShadowed(hit, clamp(away / -away.z, -1e4, 1e4)) ? 1.0 : 0.0;
      }
#endif
      continue;
    }
    vec3 contribution = texelFetch(mlLightSet, ivec2(i, 1), 0).rgb * ndl;
#ifdef ML_SELF_SHADOWING
    if (marchShadows)
    {
      vec3 toLight = worldToTexture * (mlWorldToView * light.xyz);
      if (toLight.z >= -1e-6)
      {
        continue; // below the macro-surface horizon: blocked without marching
      }
      if (mlShadowedLights > 0 && marched >= mlShadowedLights)
      {
        unmarched += contribution;
        continue;
      }
      ++marched;
      float weight = dot(contribution, vec3(0.2126, 0.7152, 0.0722)); // luminance (Rec. 709)
      marchedWeight += weight;
      if (mlShadowed(hit, clamp(toLight / -toLight.z, -1e4, 1e4)))
      {
        continue;
      }
      visibleWeight += weight;
    }
#endif
    irradiance += contribution;
  }
  // (1e-30 * wasted keeps the measured, useless marches from being compiled away.)
  return irradiance + unmarched * (marchedWeight > 0.0 ? visibleWeight / marchedWeight : 1.0) +
    vec3(1e-30 * wasted);
}
