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

#ifdef ML_LEVEL_OF_DETAIL
// The pixel footprint (square root of its area, texels) and the refinement steps of this view
// ray: where the footprint exceeds a texel the march needs no finer bracket than the footprint
// (the pixel averages over it), so refinement stops there; the uniform is the budget. The
// define lets the march code read this fragment's count under the uniform's name, unchanged.
float mlFootprint = 0.0;
int mlRefinementBudget()
{
  return mlRefinementSteps;
}
int mlViewRefinementSteps = 0;
#define mlRefinementSteps mlViewRefinementSteps
#endif

// The mip level the height field is sampled at. Marches use explicit levels (implicit
// derivatives are undefined inside divergent loops) and always level 0: marching an averaged
// height field fills the cracks a supersampled frame keeps. With LevelOfDetail on (the default),
// the shading normal at the hit is read at mlShadeLod, the pixel footprint's level less one: the
// normals of the texels a pixel covers, filtered (docs/relief-methods.md, "Aliasing").
float mlMarchLod = 0.0;
float mlShadeLod = 0.0;
// Length of the mip-filtered unit normal at the shading level (Toksvig 2005, "Mipmapping normal
// maps"): 1 where the texels a pixel covers agree, shorter where they spread. Diffuse light is
// linear in the normal, so the mean of n.l over the footprint is |n| times the filtered normal's
// n.l; the specular exponent is lowered (the highlight widened) by Toksvig's factor. 1 (no
// effect) without level of detail, at the base level, and for cone-packed textures, whose
// normal z is rebuilt as unit.
float mlNormalLength = 1.0;
float mlSpecularPowerScale = 1.0;

// Lambert's n.l for a pixel's spread of normals: n.l is linear in n, so the footprint's mean is
// the mean normal's, |n| = mlNormalLength times the filtered direction m's (Toksvig 2005).
// Weighting each facet by the area it shows the viewer (n.v, with the spread taken as even about
// m) was measured worse at 80 degrees (3.66 against 3.28 levels on Stone).
float mlFilteredLambert(vec3 m, vec3 l)
{
  return mlNormalLength * dot(m, l);
}

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
#ifdef ML_LEVEL_OF_DETAIL
// Skip what a pixel cannot show: where the footprint exceeds a texel, linear steps no shorter
// than the footprint (floor: mlMinimumSteps) and binary refinement down to a quarter of it.
// Near (a footprint of at most a texel) the march is the method's own, sample for sample.
// Maximum-mipmap tracing takes its steps as an iteration budget and keeps them.
void mlLevelOfDetailSteps(vec3 span, inout int viewSteps)
{
  mlViewRefinementSteps = mlRefinementBudget();
  if (mlFootprint <= 1.0)
  {
    return;
  }
  float spanTexels = length(span.xy * mlTextureSize);
#if ML_METHOD != ML_MAXIMUM_MIPMAP
  int needed = int(ceil(2.0 * spanTexels / mlFootprint));
  viewSteps = max(min(viewSteps, needed), min(mlMinimumSteps, viewSteps));
#endif
  float stepTexels = spanTexels / float(max(viewSteps, 1));
  int refine = int(ceil(log2(max(stepTexels / mlFootprint, 1.0)))) + 3;
  mlViewRefinementSteps = min(refine, mlRefinementBudget());
}
#endif

vec2 mlGradientFromNormal(vec3 n)
{
  float nz = max(n.z, 1e-4);
  return vec2(n.x, n.y * mlTexelAspect) * (mlGradientScale / nz);
}

vec2 mlDepthGradient(vec2 uv)
{
  return mlGradientFromNormal(mlPackedNormalAt(uv));
}
