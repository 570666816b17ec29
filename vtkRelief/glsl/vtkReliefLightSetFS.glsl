// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: an image-based light set (median-cut lights of an HDR environment, Méndez Fernández's thesis
// §5), each light shading and self-shadowing the height field, which gives soft shadows.
//
// The light texture is N x 2: row 0 the unit directions toward the lights (world coordinates)
// and their luminance (A), row 1 the irradiance each delivers at normal incidence (RGB). Lights
// come sorted by luminance, strongest first, so the loop can stop at the first negligible one.
// The loop runs in world coordinates (one normal transform per view ray, not one per light),
// once per pixel for all its view rays, and reads a light's irradiance only if the light faces
// one of them.
// What a pixel does not need is skipped: lights behind every ray's shading normal (beyond the
// spread of a far footprint's normals), below the macro-surface horizon or faced by none of the
// pixel's facets get no shadow march, and with mlShadowedLights > 0 only the strongest facing
// lights are marched; the others are weighted by the visible fraction of those.

uniform sampler2D mlLightSet;
uniform int mlLightSetCount;
uniform float mlLightSetCutoff; // luminance below which lights are skipped
uniform int mlShadowedLights;   // 0: march every facing light

// Irradiance from the light set (to be multiplied by albedo / pi) at each of the pixel's kept
// view rays (rays of them: one but for a far pixel's several, ML_FAR_RAYS), given what each ray's
// shading kept (mlLitRay). The rays take the lights' shadow marches in turn, each light's
// visibility from one ray's hit counting for every ray's n.l: interleaved sampling (Keller and
// Heidrich 2001, "Interleaved Sampling"), so that a pixel marches each light once however many
// view rays it traces, and its rays' hits still spread the lights' shadows over its footprint.
//
// A far pixel's share of a light is the mean over its footprint's facets of visibility times
// max(0, n.l). Two kinds of shadow make it up (Heitz 2014, "Understanding the masking-shadowing
// function in microfacet-based BRDFs": the facets turned away, then the share of the facing ones
// their neighbours hide): the facets turned from the light, which the clamped Lambert term of the
// footprint's spread of normals counts (mlRectifiedMean, as the VTK lights' mlFilteredLambert),
// and the facing facets' cast shadows, which the march measures. So a light's shadow is marched
// from the next ray, in turn, whose own facet (the base level's normal at its exact hit) faces
// the light: a facet turned away is blocked at once by its own slope, and that shadow taken from
// it would count the facets turned away a second time. Where none of the pixel's facets faces the
// light, the light is left out without a march. With the exact march at every level this lit
// far walls under two environments within 3 levels of the supersampled frame's mean brightness
// on every measured cell, where the mean normal's n.l with exact shadows from any ray was up to
// 9.5 levels too dark and with the linear far march up to 7 too bright (docs/relief-methods.md,
// "Light sets on far pixels: a facing facet's shadow").
void mlLightSetIrradiance(mlLitRay ray[ML_RAY_SLOTS], int rays, mat3 worldToTexture,
  bool marchShadows, out vec3 irradiance[ML_RAY_SLOTS])
{
  vec3 unmarched[ML_RAY_SLOTS];
  vec3 normalWC[ML_RAY_SLOTS]; // the filtered normal's direction times its length
  vec3 facetWC[ML_RAY_SLOTS];
  mat3 spreadWC[ML_RAY_SLOTS];
  mat3 viewToWorld = transpose(mlWorldToView); // the view rotation is orthonormal
  for (int r = 0; r < ML_RAY_SLOTS; ++r)
  {
    irradiance[r] = vec3(0.0);
    unmarched[r] = vec3(0.0);
    normalWC[r] = viewToWorld * (ray[r].NormalLength * ray[r].Normal);
    facetWC[r] = viewToWorld * ray[r].Facet;
    spreadWC[r] = viewToWorld * ray[r].NormalSpread * mlWorldToView;
  }
  float marchedWeight = 0.0;
  float visibleWeight = 0.0;
  int marched = 0;
  float wasted = 0.0; // only with ML_NO_SHADOW_CULLING, to measure what culling saves
  for (int i = 0; i < mlLightSetCount; ++i)
  {
    vec4 light = texelFetch(mlLightSet, ivec2(i, 0), 0);
    if (light.a < mlLightSetCutoff)
    {
      break; // sorted: every further light is weaker still
    }
    float ndl[ML_RAY_SLOTS];
    float ndlSum = 0.0;
    for (int r = 0; r < ML_RAY_SLOTS; ++r)
    {
      ndl[r] = r < rays ? max(mlRectifiedMean(dot(normalWC[r], light.xyz),
                                 dot(light.xyz, spreadWC[r] * light.xyz)), 0.0)
                        : 0.0;
      ndlSum += ndl[r];
    }
    if (ndlSum <= 0.0)
    {
#if defined(ML_NO_SHADOW_CULLING) && defined(ML_SELF_SHADOWING)
      vec3 away = worldToTexture * (mlWorldToView * light.xyz);
      if (marchShadows && away.z < -1e-6)
      {
#ifdef ML_CURVED
        mlQuadricOrigin = ray[0].QuadricOrigin;
#endif
        wasted +=
          mlShadowed(ray[0].ShadowPoint, clamp(away / -away.z, -1e4, 1e4), false) ? 1.0 : 0.0;
      }
#endif
      continue; // behind every ray's shading normal
    }
    vec3 lightIrradiance = texelFetch(mlLightSet, ivec2(i, 1), 0).rgb;
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
        for (int r = 0; r < ML_RAY_SLOTS; ++r)
        {
          unmarched[r] += lightIrradiance * ndl[r];
        }
        continue;
      }
      // The next ray in turn whose facet faces the light; none: the light's share is the facets
      // turned away, nothing.
      int shadowRay = -1;
      for (int k = 0; k < ML_RAY_SLOTS; ++k)
      {
        int r = (marched + k) % max(rays, 1);
        if (shadowRay < 0 && k < rays && dot(facetWC[r], light.xyz) > 0.0)
        {
          shadowRay = r;
        }
      }
      if (shadowRay < 0)
      {
        continue;
      }
      // Luminance (Rec. 709) of the light's share of the pixel.
      float weight = dot(lightIrradiance, vec3(0.2126, 0.7152, 0.0722)) * ndlSum;
      marchedWeight += weight;
#ifdef ML_CURVED
      mlQuadricOrigin = ray[shadowRay].QuadricOrigin; // the curved layer of that ray's entry
#endif
      bool blocked =
        mlShadowed(ray[shadowRay].ShadowPoint, clamp(toLight / -toLight.z, -1e4, 1e4), false);
      ++marched;
      if (blocked)
      {
        continue;
      }
      visibleWeight += weight;
    }
#endif
    for (int r = 0; r < ML_RAY_SLOTS; ++r)
    {
      irradiance[r] += lightIrradiance * ndl[r];
    }
  }
  // (1e-30 * wasted keeps the measured, useless marches from being compiled away.)
  float unmarchedVisible = marchedWeight > 0.0 ? visibleWeight / marchedWeight : 1.0;
  for (int r = 0; r < ML_RAY_SLOTS; ++r)
  {
    irradiance[r] += unmarched[r] * unmarchedVisible + vec3(1e-30 * wasted);
  }
}
