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

// mlEncodeSrgb: common/glsl/mlEncodeSrgbFS.glsl, spliced in before this piece.
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
