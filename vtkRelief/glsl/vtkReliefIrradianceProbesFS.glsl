// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: irradiance from a grid of SH9 radiance probes over the relief's texture
// (e.g. a virtual light field's light at the surface), evaluated at the relief's perturbed
// normal: E(n) = sum_lm A_l L_lm Y_lm(n) with Ramamoorthi and Hanrahan's constants ("An
// efficient representation for irradiance environment maps", eq. 8 and 12), the real SH basis
// of filters/Lighting (EnvironmentMaps.h) in world coordinates.
//
// The texture (vtkIrradianceProbesTexture) is Nu x 7 Nv RGBA, seven blocks of Nv rows: blocks 0-1
// hold red's L_0..L_7, 2-3 green's, 4-5 blue's, block 6 the three L_8. A linear fetch inside a
// block interpolates its coefficients bilinearly between the four nearest probes; the fetch is
// clamped to the block's texel centres, which clamps at the grid's border (probe (i, j) stands
// at ((i + 1/2) / Nu, (j + 1/2) / Nv)). The texture is Nu x 9 Nv: blocks 7-8 hold the
// factors of the renderer's lights 0-3 and 4-7 at each probe (1 where not given).
//
// The relief's own occlusion and inter-reflection at near-zero cost per pixel: V, the
// cosine-weighted share of the hemisphere leaving the relief, and Vs, that of the relief the
// occluded directions meet, precomputed per texel on the exact height-field intersector
// (ReliefVisibleShareMap, ReliefSeenShareMap), are looked up, not marched; the probes'
// irradiance is scaled by it and the relief's multi-bounce inter-reflection added, the model of
// the CPU renderer (ReliefInterReflected in reliefcore/core/ReliefShading.h).

uniform sampler2D mlIrradianceProbes;
uniform vec2 mlProbeGrid; // (Nu, Nv)
// Per cell of the relief: V, V over the share of directions above the macro plane (the share
// of the probes' light that reaches the point), and Vs; 1 x 1 of (1, 1, 1) without.
uniform sampler2D mlReliefVisibleShare;
// 1 when the map's fourth channel holds the share of light 0 (an area emitter) that the relief's
// own shadow lets through (ReliefEmitterShadowMap), else 0.
uniform int mlReliefLightShadow;
// The side walls of a walled relief (ReliefWallShareMap): 4 blocks of mlReliefWallLevels rows
// below the map's mlReliefShareRows rows (walls u = 0, u = 1, v = 0, v = 1, from the lip down);
// 0 levels without. A wall's share runs from the room's at its lip to a slot bottom's at its
// foot: the texel row beside the border (a slot bottom's) is right nowhere on it.
uniform int mlReliefWallLevels;
uniform float mlReliefShareRows;
// Where the view ray met a side wall (mlSideWall): the wall's normal in (u, v) and the hit's
// depth over the wall's depth there; (0, 0) on the height field.
vec2 mlShareWall = vec2(0.0);
float mlShareWallDepth = 0.0;

#define ML_PROBE_BLOCKS 9.0

// The probe texture's coordinates at uv, in block 0.
vec2 mlProbeCoordinates(vec2 uv)
{
  vec2 probe = clamp(uv * mlProbeGrid, vec2(0.5), mlProbeGrid - vec2(0.5));
  return vec2(probe.x / mlProbeGrid.x, probe.y / (ML_PROBE_BLOCKS * mlProbeGrid.y));
}

// SH9 irradiance of the seven fetched blocks averaged over a spread of unit world normals with
// mean n (of length 1 or less) and second moment S = E[n n^T], clamped at 0 (to be multiplied by
// albedo / pi). A_l Y_lm(n) in the order of SH9 (Y00, Y1-1, Y10, Y11 | Y2-2, Y2-1, Y20, Y21 |
// Y22), with A_0 = pi, A_1 = 2 pi / 3, A_2 = pi / 4: polynomials in n of degree 0, 1 and 2, whose
// means the two moments give exactly (a footprint's spread of normals under level of detail; one
// normal: S = n n^T). The constant band keeps its full weight however the normals spread.
vec3 mlShIrradiance(
  vec4 c0, vec4 c1, vec4 c2, vec4 c3, vec4 c4, vec4 c5, vec4 c6, vec3 n, mat3 S)
{
  vec4 w0 = vec4(3.14159265 * 0.282095, 2.09439510 * 0.488603 * vec3(n.y, n.z, n.x));
  vec4 w1 = 0.78539816 *
    vec4(1.092548 * S[0][1], 1.092548 * S[1][2], 0.315392 * (3.0 * S[2][2] - 1.0),
      1.092548 * S[0][2]);
  float w8 = 0.78539816 * 0.546274 * (S[0][0] - S[1][1]);
  vec3 irradiance =
    vec3(dot(c0, w0) + dot(c1, w1), dot(c2, w0) + dot(c3, w1), dot(c4, w0) + dot(c5, w1)) +
    c6.rgb * w8;
  return max(irradiance, vec3(0.0));
}

// The visible-share map's four values at texture coordinates uv (bilinear between its cells,
// clamped inside the map's rows), or the side wall's at its depth where the view ray met one.
vec4 mlReliefShare(vec2 uv)
{
  if (mlReliefWallLevels <= 0)
  {
    return textureLod(mlReliefVisibleShare, uv, 0.0);
  }
  float levels = float(mlReliefWallLevels);
  float rows = mlReliefShareRows + 4.0 * levels;
  if (mlShareWall != vec2(0.0))
  {
    float wall = mlShareWall.x > 0.0 ? 0.0
      : (mlShareWall.x < 0.0 ? 1.0 : (mlShareWall.y > 0.0 ? 2.0 : 3.0));
    float along = mlShareWall.x != 0.0 ? uv.y : uv.x;
    float level = clamp(mlShareWallDepth * levels, 0.5, levels - 0.5);
    return textureLod(mlReliefVisibleShare,
      vec2(along, (mlReliefShareRows + wall * levels + level) / rows), 0.0);
  }
  float row = clamp(uv.y * mlReliefShareRows, 0.5, mlReliefShareRows - 0.5);
  return textureLod(mlReliefVisibleShare, vec2(uv.x, row / rows), 0.0);
}

// The factor of the renderer's light `light` at texture coordinates uv, from the probes
// (bilinear): the scene's shadow of the light times the emitters' irradiance it stands for over
// its own as a point light (EmitterLightFactors); 1 for lights 8 and beyond.
float mlEmitterLightFactor(vec2 uv, int light)
{
  if (light >= 8)
  {
    return 1.0;
  }
  vec2 st = mlProbeCoordinates(uv);
  vec4 v = textureLod(mlIrradianceProbes,
    vec2(st.x, st.y + float(7 + light / 4) / ML_PROBE_BLOCKS), 0.0);
  int c = light - 4 * (light / 4);
  return c == 0 ? v.x : (c == 1 ? v.y : (c == 2 ? v.z : v.w));
}

// The share of light `light` that the relief's own shadow lets through at texture coordinates
// uv from the precomputed map (bilinear between its cells), or -1 where the map does not hold
// it (the light's shadow is then marched). The map averages the shadow over the emitter's area,
// as the CPU renderer's emitter samples do: a single ray to the light's centre gives a hard
// shadow where the area light casts a penumbra as wide as a slot's bottom. The map holds the
// height field's points, and the side walls' where it has them (mlReliefShare): without them a
// hit on a walled relief's side wall (the view ray met the texture's border below the surface,
// mlSideWall, and stopped on it) marches its shadow.
float mlEmitterSelfShadow(vec2 uv, int light)
{
  bool onBorder = any(lessThanEqual(uv, vec2(1e-5))) || any(greaterThanEqual(uv, vec2(1.0 - 1e-5)));
  if (light != 0 || mlReliefLightShadow == 0 ||
    (onBorder && mlWalledRelief() && (mlShareWall == vec2(0.0) || mlReliefWallLevels <= 0)))
  {
    return -1.0;
  }
  return clamp(mlReliefShare(uv).a, 0.0, 1.0);
}

// The renderer's lights' irradiance on the flat wall (unit view normal macroVC) at posVC, with
// the scene's visibility and without the relief's shadow: what the relief an occluded direction
// sees is lit by (the emitters' part of ReliefInterReflected's flat irradiance). VTK lights carry
// irradiance / pi (vtkReliefMapper::ConfigureEmitterLight), hence the pi.
vec3 mlFlatLightIrradiance(vec3 posVC, vec3 macroVC, vec2 uv)
{
  vec3 irradiance = vec3(0.0);
  for (int i = 0; i < mlNumberOfLights; ++i)
  {
    vec3 lightDir;
    float attenuation = mlLightArrival(i, posVC, lightDir);
    irradiance += max(0.0, attenuation * dot(macroVC, -lightDir)) *
      mlEmitterLightFactor(uv, i) * mlLightColor[i];
  }
  return 3.14159265 * irradiance;
}

// The relief's indirect irradiance at texture coordinates uv: the probes' SH9 irradiance at the
// perturbed world normal n (the mean of a footprint's normals, second moment S: mlShIrradiance),
// times the visible share of their light, plus the relief's multi-bounce
// inter-reflection (1 - V) a Vs E_flat / (1 - a (1 - Vs)), a the albedo, E_flat the flat wall's
// irradiance (the probes' at the macro world normal m plus flatLights) -- ReliefInterReflected's
// MultiBounce. With V = 1 (no map) this is the probes' irradiance alone.
vec3 mlProbeIndirect(vec2 uv, vec3 n, mat3 S, vec3 m, vec3 albedo, vec3 flatLights)
{
  vec2 st = mlProbeCoordinates(uv);
  float block = 1.0 / ML_PROBE_BLOCKS;
  vec4 c0 = textureLod(mlIrradianceProbes, st, 0.0);
  vec4 c1 = textureLod(mlIrradianceProbes, st + vec2(0.0, block), 0.0);
  vec4 c2 = textureLod(mlIrradianceProbes, st + vec2(0.0, 2.0 * block), 0.0);
  vec4 c3 = textureLod(mlIrradianceProbes, st + vec2(0.0, 3.0 * block), 0.0);
  vec4 c4 = textureLod(mlIrradianceProbes, st + vec2(0.0, 4.0 * block), 0.0);
  vec4 c5 = textureLod(mlIrradianceProbes, st + vec2(0.0, 5.0 * block), 0.0);
  vec4 c6 = textureLod(mlIrradianceProbes, st + vec2(0.0, 6.0 * block), 0.0);
  vec3 share = clamp(mlReliefShare(uv).rgb, 0.0, 1.0);
  float visible = share.r;
  vec3 irradiance = share.g * mlShIrradiance(c0, c1, c2, c3, c4, c5, c6, n, S);
  if (visible >= 1.0)
  {
    return irradiance;
  }
  vec3 a = clamp(albedo, 0.0, 1.0);
  float occluded = 1.0 - visible;
  vec3 flatIrradiance =
    mlShIrradiance(c0, c1, c2, c3, c4, c5, c6, m, outerProduct(m, m)) + flatLights;
  return irradiance +
    occluded * a * flatIrradiance * share.b / max(1.0 - a * (1.0 - share.b), vec3(1e-9));
}
