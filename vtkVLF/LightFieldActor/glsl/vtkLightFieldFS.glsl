// SPDX-License-Identifier: BSD-3-Clause
// Light field walkthrough fragment code (Wither 2005 §2.4.2.2), spliced into VTK's polygon
// fragment shader by vtkLightFieldMapper. Radiance comes from two textures:
//   mlAtlas:  every surface's total diffuse radiance (TextureAtlas: gutters, so bilinear never
//             reads a neighbour); alpha 1 marks surfaces with a mirror part;
//   mlScreen: the CPU's screen-space radiance over a pixel rectangle (WalkthroughTracer), alpha
//             > 0 where it holds a value: mirror reflections (progressive, coherent) or every
//             pixel (raytrace).
// The depth test has already decided visibility, so other actors hide and are hidden by these
// fragments exactly. Exposure and tone mapping (the twin of common/DisplayTransform.h) are shared
// by all modes that show radiance.

uniform sampler2D mlAtlas;
uniform sampler2D mlScreen;
uniform ivec2 mlScreenOrigin; // window pixel of mlScreen's texel (0, 0)
uniform ivec2 mlScreenSize;
uniform float mlExposure;
uniform int mlToneMap;   // 0 clamp, 1 Reinhard
uniform int mlAllScreen; // raytrace: every fragment takes the screen value
uniform int mlOverwrite; // negative test: the screen rectangle pasted without alpha
in vec2 mlAtlasTCVC;

// The sRGB curve, 1.055 v^(1/2.4) - 0.055 above 0.0031308, as a minimax fit in v^(1/2), v^(1/4),
// v^(1/8) and v (largest error 0.012 of an 8-bit level over [0.0031308, 1]): a software
// rasteriser (Mesa llvmpipe) evaluates pow as a log and an exp polynomial per channel, which cost
// more than the rest of this fragment; three square roots are instructions.
vec3 mlEncodeSrgb(vec3 v)
{
  v = clamp(v, 0.0, 1.0);
  vec3 s1 = sqrt(v);
  vec3 s2 = sqrt(s1);
  vec3 s3 = sqrt(s2);
  vec3 curve = 0.642423327 * s1 + 0.712051717 * s2 - 0.336847647 * s3 - 0.0175821145 * v;
  return mix(curve, 12.92 * v, vec3(lessThanEqual(v, vec3(0.0031308))));
}

vec3 mlDisplay(vec3 radiance)
{
  vec3 v = max(vec3(0.0), mlExposure * radiance);
  if (mlToneMap == 1)
  {
    v = v / (vec3(1.0) + v);
  }
  return mlEncodeSrgb(v);
}

vec3 mlRadiance()
{
  vec4 atlas = texture(mlAtlas, mlAtlasTCVC);
  ivec2 p = ivec2(gl_FragCoord.xy) - mlScreenOrigin;
  bool inside = all(greaterThanEqual(p, ivec2(0))) && all(lessThan(p, mlScreenSize));
  vec4 screen = inside ? texelFetch(mlScreen, p, 0) : vec4(0.0);
  if (mlOverwrite == 1 && inside)
  {
    return screen.rgb;
  }
  // Mirror fragments (and all fragments in raytrace) take the screen value where it has one.
  float weight = (mlAllScreen == 1 || atlas.a > 0.5) ? step(0.25, screen.a) : 0.0;
  // The movable object's shadow darkens the diffuse value (vtkLightFieldShadowFS.glsl).
  return mix(mlShadowed(atlas.rgb), screen.rgb, weight);
}
