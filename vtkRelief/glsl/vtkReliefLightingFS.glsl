// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: every VTK light of the renderer, shaded with the Phong model of VTK's own
// vtkOpenGLPolyDataMapper (same attenuation, spot cone and reflect-based specular), so a relief
// surface and a dense mesh of the same height field shade alike. Self-shadowing comes from the
// height field (mlShadowed), evaluated only where a light can contribute.

#define ML_MAX_LIGHTS 8
uniform int mlNumberOfLights;
uniform vec3 mlLightColor[ML_MAX_LIGHTS];       // diffuse colour x intensity
uniform vec3 mlLightDirectionVC[ML_MAX_LIGHTS]; // direction light travels, view coordinates
uniform vec3 mlLightPositionVC[ML_MAX_LIGHTS];
uniform vec3 mlLightAttenuation[ML_MAX_LIGHTS];
uniform float mlLightConeAngle[ML_MAX_LIGHTS];
uniform float mlLightExponent[ML_MAX_LIGHTS];
uniform int mlLightPositional[ML_MAX_LIGHTS];
uniform vec3 mlSpecularColor; // specular x specular colour
uniform float mlSpecularPower;
uniform float mlExposure; // scales the light-set and probe shading
uniform vec3 mlEmission;  // the surface's emitted radiance, added to that shading
uniform mat3 mlWorldToView; // rotation part of the view matrix

#ifdef ML_IRRADIANCE_PROBES
float mlEmitterLightFactor(vec2 uv, int light); // the scene's shadow and the point's error
float mlEmitterSelfShadow(vec2 uv, int light);  // the relief's, precomputed (-1: not held)
#endif

// Light i's direction of travel at posVC and its attenuation there (distance, spot cone), as
// VTK's own shading computes them.
float mlLightArrival(int i, vec3 posVC, out vec3 lightDir)
{
  float attenuation = 1.0;
  lightDir = mlLightDirectionVC[i];
  if (mlLightPositional[i] != 0)
  {
    lightDir = posVC - mlLightPositionVC[i];
    float dist = length(lightDir);
    lightDir = lightDir / max(dist, 1e-30);
    vec3 a = mlLightAttenuation[i];
    attenuation = 1.0 / max(a.x + a.y * dist + a.z * dist * dist, 1e-30);
    if (mlLightConeAngle[i] <= 90.0)
    {
      float coneDot = dot(lightDir, mlLightDirectionVC[i]);
      attenuation = coneDot >= cos(radians(mlLightConeAngle[i]))
        ? attenuation * pow(max(coneDot, 0.0), mlLightExponent[i])
        : 0.0;
    }
  }
  return attenuation;
}

#ifdef ML_SELF_SHADOWING
// The share of a light reaching the facets of the pixel's footprint. Near (level of detail off,
// or a footprint's shading level of 0) one shadow ray from the hit: lit or not. So too for each
// of a far pixel's several view rays (ML_FAR_RAYS, mlPixelViewRays > 1): their hard shadows from
// their own hits average over the footprint as the supersampled frame's subsamples do, measured
// better than each ray's shadow softened (docs/relief-methods.md, "Each far view ray's own
// hard shadow"). A far pixel with one view ray averages the shadows of all its facets too, and one
// hard ray from one of them aliases: there the ray starts half a footprint towards the light
// (the facets' own relief within the footprint darkens them through the clamped Lambert term,
// mlFilteredLambert, not a second time through the ray), and its visibility is soft: 1/2 where
// the ray grazes the height field, clamp(1/2 + g) with g the ray's least clearance above it per
// depth climbed (1 over a flat floor; negative: below it at the first blocked sample), as a
// bundle of rays from across the footprint would be partly blocked where one ray just passes;
// the penumbra narrows to a hard shadow as the shading level falls to 0. As percentage-closer
// filtering (Reeves, Salesin and Cook 1987) softens a shadow map's test over a filter's area.
// Measured on three real maps at 45 and 80 degrees against lifts of 0 (the hit, refinement's
// bracket higher), 0.5 and 1 footprint and a hard test (docs/relief-methods.md, "Aliasing").
// Cone and maximum-mipmap shadow marches report no clearance and stay hard from the lifted
// start. The shadows the footprint's facets cast on each other, which one ray does not see, come
// from the moments (mlFootprintShadowing).
float mlShadowVisibility(vec3 hit, vec3 spanUpPerDepth)
{
#if defined(ML_LEVEL_OF_DETAIL) && !defined(ML_CURVED)
  float blend = clamp(mlShadeLod, 0.0, 1.0); // 0 near: the frame of level of detail off
  if (mlFootprint > 1.0 && blend > 0.0 && mlPixelViewRays == 1)
  {
    float footprint = blend * mlFootprint; // texels
    float along = 0.5 * footprint / max(length(spanUpPerDepth.xy * mlTextureSize), 1e-6);
    mlShadowGap = 1e30;
    bool blocked = mlShadowed(hit + spanUpPerDepth * min(along, hit.z), spanUpPerDepth, true);
    if (mlShadowGap >= 1e29)
    {
      return blocked ? 0.0 : 1.0;
    }
    return clamp(0.5 + mlShadowGap / blend, 0.0, 1.0);
  }
#endif
  return mlShadowed(hit, spanUpPerDepth, true) ? 0.0 : 1.0;
}
#endif

// Accumulates diffuse and specular light at a point of the height field.
//   posVC, normalVC: the hit point and the height field's normal there, view coordinates
//   hit: the hit in texture space; worldToTexture maps a view-space direction to texture space
//   firstLightVisible: 1 when light 0 reaches the point (for measurements), else 0
//   marchShadows: false where the fragment has no usable tangent frame
void mlAccumulateLights(vec3 posVC, vec3 normalVC, vec3 hit, mat3 worldToTexture,
  bool marchShadows, inout vec3 diffuse, inout vec3 specular, out float firstLightVisible)
{
  firstLightVisible = 0.0;
  vec3 viewDir = normalize(-posVC);
  for (int i = 0; i < mlNumberOfLights; ++i)
  {
    vec3 lightDir;
    float attenuation = mlLightArrival(i, posVC, lightDir);
#ifdef ML_IRRADIANCE_PROBES
    attenuation *= mlEmitterLightFactor(hit.xy, i);
#endif
    float df = max(0.0, attenuation * mlFilteredLambert(normalVC, -lightDir));
    if (df <= 0.0)
    {
      continue; // facing away or outside the cone: no shadow march needed
    }
#ifdef ML_SELF_SHADOWING
    vec3 toLight = worldToTexture * (-lightDir);
    // A light at or below the macro-surface horizon is blocked by the surface itself.
    float visible = 1.0;
#ifdef ML_IRRADIANCE_PROBES
    float mapped = mlEmitterSelfShadow(hit.xy, i);
    if (mapped >= 0.0)
    {
      // The area light's shadow by the relief, precomputed: no march (a light at or below the
      // macro plane is 0 in the map too).
      visible = mapped;
    }
    else
#endif
    if (marchShadows)
    {
      visible = toLight.z >= -1e-6 ? 0.0
                                   : mlShadowVisibility(hit, clamp(toLight / -toLight.z, -1e4, 1e4));
    }
    if (visible <= 0.0)
    {
      continue;
    }
#ifdef ML_NORMAL_MOMENTS
    // The facets of the footprint shadowed by its own relief (mlFootprintShadowing).
    visible *= marchShadows ? mlFootprintShadowing(-lightDir) : 1.0;
#endif
    df *= visible;
    attenuation *= visible;
#endif
#ifdef ML_SELF_SHADOWING
    firstLightVisible = i == 0 && visible >= 0.5 ? 1.0 : firstLightVisible;
#else
    firstLightVisible = i == 0 ? 1.0 : firstLightVisible;
#endif
    diffuse += df * mlLightColor[i];
    float sf = attenuation * pow(max(0.0, dot(reflect(lightDir, normalVC), viewDir)), mlSpecularPower * mlSpecularPowerScale);
    specular += sf * mlLightColor[i];
  }
}
