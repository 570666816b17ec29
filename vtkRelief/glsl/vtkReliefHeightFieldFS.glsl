// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: height-field access shared by every method.
//
// Relief texture (Méndez Fernández's thesis, §4.1): tangent-space normal packed as (n+1)/2 in RGB, depth in A with
// 0 = the mesh surface and 1 = the deepest point. Texture space is (u, v, depth). A cone-packed
// texture (vtkConeMapFilter, ML_CONE_PACKED) keeps the normal's x, y in RG and the cone ratio
// (horizontal radius in texture widths per unit of depth) in B, as in the relief thesis.

uniform sampler2D mlReliefTexture;
uniform float mlDepthScale;    // world depth of depth = 1 over the world length of one u unit
uniform float mlGradientScale; // 1 / depth scale the normals were baked with (0: flat bake)
uniform float mlTexelAspect;   // texture height / width in texels (texels are square)
uniform vec2 mlTextureSize;    // texels
uniform int mlLinearSteps;
uniform int mlRefinementSteps;
uniform int mlMinimumSteps; // adaptive step counts: from mlLinearSteps (grazing) to this (head-on)

// The mip level the height field is sampled at. Marches use explicit levels (implicit
// derivatives are undefined inside divergent loops) and always level 0: marching an averaged
// height field fills the cracks a supersampled frame keeps. With LevelOfDetail on, the shading
// normal at the hit is read at mlShadeLod, the pixel footprint's level less one: the normals of
// the texels a pixel covers, filtered (docs/relief-methods.md: 30% less aliasing on Stone).
float mlMarchLod = 0.0;
float mlShadeLod = 0.0;

// Relief-texture samples this fragment took (SampleCountOutput): what a march costs on any GPU.
// Counted only when that output is asked for; the other variants carry no counter at all.
#if ML_OUTPUT == 5
int mlSampleCount = 0;
#define ML_COUNT_SAMPLE() ++mlSampleCount
#else
#define ML_COUNT_SAMPLE()
#endif

float mlDepthAt(vec2 uv)
{
  ML_COUNT_SAMPLE();
  return textureLod(mlReliefTexture, uv, mlMarchLod).a;
}

vec3 mlPackedNormalAt(vec2 uv)
{
  ML_COUNT_SAMPLE();
  vec4 texel = textureLod(mlReliefTexture, uv, mlMarchLod);
#ifdef ML_CONE_PACKED
  vec2 nxy = texel.rg * 2.0 - 1.0;
  return vec3(nxy, sqrt(max(0.0, 1.0 - dot(nxy, nxy))));
#else
  return texel.rgb * 2.0 - 1.0;
#endif
}

#ifdef ML_CONE_PACKED
// Cone ratio at the base level: cone maps are never averaged (an average cone is not a cone).
float mlConeAt(vec2 uv)
{
  ML_COUNT_SAMPLE();
  return max(textureLod(mlReliefTexture, uv, 0.0).b, 0.0);
}

// Depth (x) and cone ratio (y) at uv: one fetch of the packed texel, so a cone step costs what a
// linear step costs; two when level of detail reads the depth from a coarser level.
vec2 mlDepthAndConeAt(vec2 uv)
{
#ifdef ML_LEVEL_OF_DETAIL
  return vec2(mlDepthAt(uv), mlConeAt(uv));
#else
  ML_COUNT_SAMPLE();
  vec4 texel = textureLod(mlReliefTexture, uv, 0.0);
  return vec2(texel.a, max(texel.b, 0.0));
#endif
}
#endif

// (d depth / du, d depth / dv) recovered from the baked normal n ~ (k dd/dx, k dd/dy, 1), where x = u
// and y = v * aspect are measured in texture widths (vtkReliefTextureFilter's convention).
vec2 mlDepthGradient(vec2 uv)
{
  vec3 n = mlPackedNormalAt(uv);
  float nz = max(n.z, 1e-4);
  return vec2(n.x, n.y * mlTexelAspect) * (mlGradientScale / nz);
}
