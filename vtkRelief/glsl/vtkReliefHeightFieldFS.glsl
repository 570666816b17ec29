// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: height-field access shared by every method. Every read of the relief's
// textures goes through the functions below, so the storage (vtkReliefTextureCache) can change
// without touching the traversals.
//
// Relief texture (Méndez Fernández's thesis, §4.1): depth with 0 = the mesh surface and 1 = the
// deepest point, and the tangent-space normal. Texture space is (u, v, depth).
// ML_FLOAT_TEXTURES: the thesis' float RGBA texture, normal packed as (n+1)/2 in RGB, depth in A;
// a cone-packed texture (vtkConeMapFilter, ML_CONE_PACKED) keeps the normal's x, y in RG and the
// cone ratio (horizontal radius in texture widths per unit of depth) in B.
// Otherwise (compact storage, the default): the depth alone in mlReliefTexture (R, 8 or 16
// bits); the normal in mlNormalTexture (ML_STORED_NORMALS, 8-bit signed octahedral), or, derived
// from the depth as vtkReliefTextureFilter bakes them (Sobel); cone ratios c stored as
// c / (1 + c) in mlConeTexture (8 bits), rounded to narrower cones.

uniform sampler2D mlReliefTexture;
uniform int mlRepeatTexture; // the samplers repeat (else clamp to edge)
#ifndef ML_FLOAT_TEXTURES
#ifdef ML_STORED_NORMALS
uniform sampler2D mlNormalTexture;
#endif
#ifdef ML_CONE_PACKED
uniform sampler2D mlConeTexture;
#endif
#define ML_DEPTH_CHANNEL r
#else
#define ML_DEPTH_CHANNEL a
#endif
uniform float mlDepthScale;    // world depth of depth = 1 over the world length of one u unit
uniform float mlGradientScale; // 1 / depth scale the normals were baked with (0: flat bake)
uniform float mlTexelAspect;   // texture height / width in texels (texels are square)
uniform vec2 mlTextureSize;    // texels

// Texel t of a level of `size` texels as the samplers address it: wrapped or clamped.
ivec2 mlAddressTexel(ivec2 t, ivec2 size)
{
  return mlRepeatTexture != 0 ? (t % size + size) % size : clamp(t, ivec2(0), size - 1);
}

// The depths of level-0 texels i, i + (1, 0), i + (0, 1) and i + (1, 1), as the samplers address
// them (wrapped or clamped), as (d00, d10, d01, d11). With ML_TEXEL_GATHER (compact storage,
// where a shader reads quads: maximum mipmaps, the depth's own normals) one gather at their
// shared corner, which is exact (half a texel from any rounding of the sampler's texel choice);
// textureGather returns (i0, j1), (i1, j1), (i1, j0), (i0, j0). Otherwise four fetches.
vec4 mlTexelQuad(ivec2 i)
{
#ifdef ML_TEXEL_GATHER
  return textureGather(mlReliefTexture, vec2(i + 1) / mlTextureSize).wzxy;
#else
  ivec2 size = ivec2(mlTextureSize);
  ivec2 lo = mlAddressTexel(i, size), hi = mlAddressTexel(i + 1, size);
  return vec4(texelFetch(mlReliefTexture, lo, 0).ML_DEPTH_CHANNEL,
    texelFetch(mlReliefTexture, ivec2(hi.x, lo.y), 0).ML_DEPTH_CHANNEL,
    texelFetch(mlReliefTexture, ivec2(lo.x, hi.y), 0).ML_DEPTH_CHANNEL,
    texelFetch(mlReliefTexture, hi, 0).ML_DEPTH_CHANNEL);
#endif
}

// The four level-0 texels a bilinear lookup at uv weighs, (i0, j0), (i1, j0), (i0, j1), (i1, j1)
// as the samplers address them, and its fraction f.
void mlBilinearTexels(vec2 uv, out ivec2 t[4], out vec2 f)
{
  ivec2 size = ivec2(mlTextureSize);
  vec2 x = uv * mlTextureSize - 0.5;
  ivec2 i0 = ivec2(floor(x));
  f = x - vec2(i0);
  for (int k = 0; k < 4; ++k)
  {
    t[k] = mlAddressTexel(i0 + ivec2(k - 2 * (k / 2), k / 2), size);
  }
}

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
// The view rays this pixel traces (several far away with ML_FAR_RAYS): where they are several,
// their hard self-shadows average over the footprint, and one ray's shadow need not stand in
// for the others' (mlShadowVisibility).
int mlPixelViewRays = 1;
#endif

// The most view rays a pixel traces (ML_FAR_RAYS), each ray's hit kept until the pixel's
// lights are summed (mlLightSetIrradiance).
#ifdef ML_FAR_RAYS
#define ML_RAY_SLOTS ML_FAR_RAYS
#else
#define ML_RAY_SLOTS 1
#endif

// What a kept view ray's shading leaves for the light set, whose lights are summed once all the
// pixel's rays are traced (mlLightSetIrradiance).
struct mlLitRay
{
  vec3 Normal;        // the shading normal, filtered far away (level of detail), view coordinates
  float NormalLength; // the filtered normal's length (Toksvig), 1 near
  mat3 NormalSpread;  // the footprint's spread of normals (mlNormalSpreadVC), zero near
  vec3 Facet;         // the base level's normal at the ray's exact hit, view coordinates
  vec3 ShadowPoint;   // where the ray's shadow marches start, texture space
  vec2 QuadricOrigin; // a curved mesh's view ray entry point (mlQuadricOrigin)
};

// The mip level the height field is sampled at. Marches use explicit levels (implicit
// derivatives are undefined inside divergent loops) and always level 0: marching an averaged
// height field fills the cracks a supersampled frame keeps. With LevelOfDetail on (the default),
// the shading normal at the hit is filtered at mlShadeLod, the pixel footprint's level: the
// normals of the texels a pixel covers (docs/relief-methods.md, "Aliasing").
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
// With the visible normal filters (ML_NORMAL_MOMENTS but not ML_MEAN_NORMALS) m and the length
// are those of the facets the viewer sees (mlVisibleNormal).
// The mean of n.l is not the footprint's light, though: each facet turned from the light adds
// nothing rather than a negative amount, max(0, n.l). With the spread's covariance C
// (mlNormalSpreadVC, view coordinates; zero near and without the visible normal filter), n.l
// over the footprint is taken as normal with mean mu and variance l.C.l, and the clamped mean
// is that of a rectified normal variable, mu Phi(mu / sigma) + sigma phi(mu / sigma) (the
// moments' covariance as a lobe, as LEAN mapping, Olano and Baker 2010, uses it for the
// highlight). Phi: 1/2 + tanh(0.798 (x + 0.0447 x^3)) / 2, within 1.8e-4 of the normal CDF.
mat3 mlNormalSpreadVC = mat3(0.0);
float mlNormalCdf(float x)
{
  return 0.5 + 0.5 * tanh(0.7978845608 * (x + 0.044715 * x * x * x));
}
float mlNormalPdf(float x)
{
  return 0.3989422804 * exp(-0.5 * x * x);
}
// The mean of max(0, x) for x normal with mean mu and the variance given (mu where it is none).
float mlRectifiedMean(float mu, float variance)
{
  if (variance <= 1e-8)
  {
    return mu;
  }
  float sigma = sqrt(variance);
  float x = mu / sigma;
  return mu * mlNormalCdf(x) + sigma * mlNormalPdf(x);
}
// The clamped Lambert term of the VTK lights: l in view coordinates.
float mlFilteredLambert(vec3 m, vec3 l)
{
  return mlRectifiedMean(mlNormalLength * dot(m, l), dot(l, mlNormalSpreadVC * l));
}

// The share of the footprint's facets facing direction l (towards a light, view coordinates)
// that its own relief leaves unshadowed: Smith's shadowing function for a Gaussian (Beckmann)
// distribution of slopes, G1 = 1 / (1 + Lambda(a)), Lambda(a) = (erf(a) - 1) / 2 +
// exp(-a^2) / (2 a sqrt(pi)), a = 1 / (sqrt(2) sigma tan(theta)) with sigma the slopes' spread
// along l's azimuth and theta its angle from the macro normal (Smith 1967, "Geometrical
// shadowing of a random rough surface"; Heitz 2014, "Understanding the masking-shadowing
// function in microfacet-based BRDFs"). The spread is the moments' (mlNormalSpreadVC; the
// normals' spread across the azimuth stands for the slopes'), so near, where it is zero, the
// factor is 1. The clamped Lambert term (mlFilteredLambert) drops the facets turned from the
// light; this drops the share of the ones facing it that their neighbours within the footprint
// hide, which the far shadow ray, starting half a footprint towards the light
// (mlShadowVisibility), does not see.
vec3 mlMacroNormalVC = vec3(0.0, 0.0, 1.0);
float mlFootprintShadowing(vec3 l)
{
  float c = dot(l, mlMacroNormalVC);
  vec3 d = l - mlMacroNormalVC * c;
  float sine = length(d);
  if (c <= 1e-4 || sine < 1e-4)
  {
    return 1.0;
  }
  d /= sine;
  float variance = dot(d, mlNormalSpreadVC * d);
  if (variance <= 1e-8)
  {
    return 1.0;
  }
  float a = c / (sine * sqrt(2.0 * variance));
  // erf(a) = 2 Phi(a sqrt 2) - 1
  float lambda = mlNormalCdf(1.4142135624 * a) - 1.0 + exp(-a * a) / (3.5449077018 * a);
  return 1.0 / (1.0 + max(lambda, 0.0));
}

// Relief-texture samples this fragment took (SampleCountOutput): what a march fetches on any GPU.
// Counted only when that output is asked for; the other variants carry no counter at all.
#if ML_OUTPUT == 5
int mlSampleCount = 0;
#define ML_COUNT_SAMPLE() ++mlSampleCount
#else
#define ML_COUNT_SAMPLE()
#endif

// The edge rule (docs/relief-against-path-tracer.md, "The relief's edge"): a relief neither
// tiled (mlRepeatTexture) nor cut out at its silhouettes (ML_SILHOUETTES) is recessed into its
// surface and walled at the texture rectangle's border: outside [0, 1]^2 the solid reaches the
// surface (depth 0), so a ray below the surface meets a side wall where it reaches the border,
// as on the dense displaced mesh (SurfaceRelief) and the CPU intersector (HeightField::Walled).
bool mlWalledRelief()
{
#ifdef ML_SILHOUETTES
  return false;
#else
  return mlRepeatTexture == 0;
#endif
}

bool mlOutsideWalledRelief(vec2 uv)
{
  return mlWalledRelief() && (any(lessThan(uv, vec2(0.0))) || any(greaterThan(uv, vec2(1.0))));
}

float mlDepthAt(vec2 uv)
{
  ML_COUNT_SAMPLE();
  return mlOutsideWalledRelief(uv) ? 0.0
                                   : textureLod(mlReliefTexture, uv, mlMarchLod).ML_DEPTH_CHANNEL;
}

#ifdef ML_NORMAL_MOMENTS
// Level of detail's normal filters (vtkReliefTextureCache::GetMomentsUploaded): moments
// of the baked unit normal n weighted by w = 1 / nz, the texel's surface area over its base.
uniform sampler2D mlMomentTexture0; // E[w nx^2], E[w ny^2], E[w nx ny], E[w nz^2]
uniform sampler2D mlMomentTexture1; // E[w nx nz], E[w ny nz], E[w nx], E[w ny]
// The relief's mip level that the moment textures' level 0 holds (2): levels 0 and 1 are
// computed here, from the stored normals or, when the normals are the depth's own (not
// uploaded), from the depth's surface cells.
uniform float mlMomentFirstLevel;
#if !defined(ML_STORED_NORMALS) && !defined(ML_SURFACE_NORMALS)
#error "the visible normal filter reads stored normals or the depth's own"
#endif

#ifdef ML_STORED_NORMALS
vec3 mlOctahedralNormal(vec2 e);
#endif

#ifdef ML_SURFACE_NORMALS
// The facet level-0 texel t stands for when the normals are the depth's own: the cell of the
// bilinear surface from texel t to t + 1, its mean slope as a unit normal of the bake's
// convention (mlSobelNormal's, a two- rather than a three-texel stencil) and its mean depth. The
// levels' lookups are taken half a texel back (mlFacetLookupUv), so that the cells cover the
// footprint as the texels do.
vec3 mlSurfaceCellNormal(ivec2 t, out float depth)
{
  ML_COUNT_SAMPLE();
  vec4 d = mlTexelQuad(t); // d00, d10, d01, d11
  depth = 0.25 * (d.x + d.y + d.z + d.w);
  vec2 g = 0.5 * vec2(d.y - d.x + d.w - d.z, d.z - d.x + d.w - d.y); // depth per texel
  float k = mlGradientScale > 0.0 ? 1.0 / mlGradientScale : 0.0;
  return normalize(vec3(k * mlTextureSize.x * g, 1.0));
}
#define mlFacetLookupUv(uv) ((uv) - 0.5 / mlTextureSize)
#else
#define mlFacetLookupUv(uv) (uv)
#endif

// The unit normal of level-0 texel t's facet (and its depth): the stored normal, or the
// surface's cell (ML_SURFACE_NORMALS).
vec3 mlTexelFacet(ivec2 t, out float depth)
{
#ifdef ML_SURFACE_NORMALS
  return mlSurfaceCellNormal(t, depth);
#else
  ML_COUNT_SAMPLE();
  ML_COUNT_SAMPLE();
  depth = texelFetch(mlReliefTexture, t, 0).r;
  return normalize(mlOctahedralNormal(texelFetch(mlNormalTexture, t, 0).rg));
#endif
}

// Adds k times the moments of level-0 texel t's normal (mesolight::NormalMoments): a texel's
// second moment is its normal's outer product, so levels 0 and 1 need no texture of their own.
void mlAddTexelMoments(ivec2 t, float k, inout vec4 a, inout vec4 b)
{
  float depth;
  vec3 n = mlTexelFacet(t, depth);
  float w = k / max(n.z, 1.0 / 16.0);
  a += w * vec4(n.x * n.x, n.y * n.y, n.x * n.y, n.z * n.z);
  b += w * vec4(n.x * n.z, n.y * n.z, n.x, n.y);
}

// The level-0 texels that the bilinear lookup of mip level 0 or 1 at uv weighs, as the sampler's:
// texels wrapped or clamped at their own level, level 1's texel J the mean of level 0's 2J and
// 2J + 1 in each axis (mesolight::ReduceNormalMoments, which builds the uploaded levels). Set up
// once by mlLevelLookupAt; mlLevelLookupTexel gives the n-th of its mlLevelLookupCount texels.
struct mlLevelLookup
{
  ivec2 Corner;   // the lookup's lower-left texel at its level
  vec2 Fraction;  // the bilinear fraction
  ivec2 Size;     // the level's size
  int Children;   // level-0 texels per axis of one texel of the level
};

mlLevelLookup mlLevelLookupAt(vec2 uv, int level)
{
  mlLevelLookup l;
  l.Size = max(ivec2(mlTextureSize) >> level, ivec2(1));
  vec2 x = uv * vec2(l.Size) - 0.5;
  l.Corner = ivec2(floor(x));
  l.Fraction = x - vec2(l.Corner);
  l.Children = 1 << level;
  return l;
}

int mlLevelLookupCount(mlLevelLookup l)
{
  return 4 * l.Children * l.Children;
}

// The n-th level-0 texel of the lookup and its weight (the four bilinear weights, each shared
// evenly by the level's texel's children).
ivec2 mlLevelLookupTexel(mlLevelLookup l, int n, out float weight)
{
  int perCorner = l.Children * l.Children;
  int c = n / perCorner;
  int i = n - c * perCorner;
  ivec2 o = ivec2(c & 1, c >> 1);
  ivec2 t = l.Corner + o;
  t = mlAddressTexel(t, l.Size);
  vec2 axis = mix(1.0 - l.Fraction, l.Fraction, vec2(o));
  weight = axis.x * axis.y / float(perCorner);
  ivec2 child = ivec2(i % l.Children, i / l.Children);
  return min(t * l.Children + child, ivec2(mlTextureSize) - 1);
}

// Adds k times the bilinear lookup of the moments' mip level 0 or 1 at uv.
void mlAddLevelMoments(vec2 uv, int level, float k, inout vec4 a, inout vec4 b)
{
  mlLevelLookup l = mlLevelLookupAt(uv, level);
  for (int n = 0; n < mlLevelLookupCount(l); ++n)
  {
    float weight;
    ivec2 t = mlLevelLookupTexel(l, n, weight);
    mlAddTexelMoments(t, k * weight, a, b);
  }
}

mat3 mlNormalSpread = mat3(0.0); // the footprint's covariance of n, (T, B, N) frame (below)

#ifdef ML_MASKED_FACETS
// The masked facet filter (ML_MASKED_FACETS): the facets of the levels computed per texel (0 and
// 1), each weighed by the area it turns to the viewer, w max(0, n.v), so that facets turned away
// are left out (masked) instead of counting negatively as they do in the moments (S v, below).
// Smith's height-correlated masking on top (C(h)^Lambda, Heitz 2014) no longer paid once far
// pixels took several view rays (docs/relief-methods.md, "Masked facets"); without it each facet
// adds to running sums as it is read: their seen area, its first and second moments.
struct mlSeenFacets
{
  float Area;
  vec3 Mean;
  mat3 Second;
};

// Adds level-0 texel t's facet with base weight k as view direction v ((T, B, N) frame) sees it.
void mlAddSeenFacet(ivec2 t, float k, vec3 v, inout mlSeenFacets seen)
{
  float depth;
  vec3 n = mlTexelFacet(t, depth);
  float s = mlDepthScale * mlGradientScale;
  n = normalize(vec3(s * n.xy, n.z)); // at the rendering's depth scale
  float c = k * max(dot(n, v), 0.0) / max(n.z, 1.0 / 16.0);
  seen.Area += c;
  seen.Mean += c * n;
  seen.Second += c * outerProduct(n, n);
}

// Adds the facets of level 0 or 1 that its bilinear lookup at uv weighs, with k times their
// weights (the texels of mlLevelLookupAt).
void mlAddLevelSeenFacets(vec2 uv, int level, float k, vec3 v, inout mlSeenFacets seen)
{
  mlLevelLookup l = mlLevelLookupAt(uv, level);
  for (int n = 0; n < mlLevelLookupCount(l); ++n)
  {
    float weight;
    ivec2 t = mlLevelLookupTexel(l, n, weight);
    mlAddSeenFacet(t, k * weight, v, seen);
  }
}

// The seen facets' mean normal, and their spread (mlNormalSpread).
vec3 mlSeenFacetNormal(mlSeenFacets seen)
{
  if (seen.Area <= 1e-12)
  {
    mlNormalSpread = mat3(0.0);
    return vec3(0.0, 0.0, 1.0);
  }
  vec3 mean = seen.Mean / seen.Area;
  mlNormalSpread = seen.Second / seen.Area - outerProduct(mean, mean);
  return mean;
}
#endif

// The footprint's visible mean normal from its moments (a: E[w nx^2], E[w ny^2], E[w nx ny],
// E[w nz^2]; b: E[w nx nz], E[w ny nz], E[w nx], E[w ny]), with its length, for v (towards the
// viewer) in the tangent frame (T, B, N) of the shading normal; sets mlNormalSpread.
// A pixel sees each facet in proportion to its projected area, w (n.v) per texel of base (a
// height field seen from above: facets turned away count negatively, as the ones hiding them do
// positively), and n.l is linear in n, so the pixel's mean of n.l is l . S v / E[w n.v] with
// S = E[w n n^T]: the moments the mip chain averaged (LEAN mapping, Olano and Baker 2010, with
// the 3D second-moment matrix). A grazing view thus sees the facets facing it, which the mean
// normal (Toksvig 2005) cannot know. The rendering's depth scale may differ from the bake's: n
// becomes D n / |D n|, D = diag(s, s, 1), its length taken as the area-weighted root mean square.
vec3 mlMomentsVisibleNormal(vec4 a, vec4 b, vec3 v)
{
  float s = mlDepthScale * mlGradientScale;
  float r = sqrt(max(s * s * (a.x + a.y) + a.w, 1e-12) / max(a.x + a.y + a.w, 1e-12));
#ifdef ML_MEAN_NORMALS
  // The mean normal filter: the footprint's plain mean of the unit normals, E[w nz n] (its
  // length: the spread, Toksvig 2005), without a spread for the clamped Lambert term.
  mlNormalSpread = mat3(0.0);
  return vec3(s * b.x, s * b.y, a.w) / r;
#endif
  mat3 S = mat3(s * s * a.x, s * s * a.z, s * b.x, s * s * a.z, s * s * a.y, s * b.y, s * b.x,
    s * b.y, a.w);
  // The spread about the area-weighted mean for the clamped Lambert term (mlFilteredLambert):
  // E[w] = trace S / r^2 (unit normals), the mean E[w n] / E[w] with E[w nz] = 1.
  float area = max(a.x + a.y + a.w, 1e-6);
  vec3 mean = vec3(s * b.z, s * b.w, 1.0) / (r * area);
  mlNormalSpread = S / (r * r * area) - outerProduct(mean, mean);
  // The footprint's projected area over its base area's, in units of v: E[w (D n).v], where
  // E[w nz] = 1 (but for walls steeper than the weight's clamp).
  float projected = dot(v, vec3(s * b.z, s * b.w, 1.0));
#ifdef ML_MASKED_FACETS
  // The masked facet filter leaves the facets turned away out at these levels too, as a
  // distribution: with the footprint's normals taken as normal (Gaussian) with the mean and
  // spread C above, x = n.v is normal with mean mu = mean.v and variance sigma^2 = v.C.v, and
  // the seen facets' mean normal is E[n max(0, x)] / E[max(0, x)]. Since E[n | x] is linear in
  // x, E[n max(0, x)] = mean E[max(0, x)] + C v Phi(mu / sigma), so the seen normal is
  // mean + C v Phi(mu / sigma) / (mu Phi + sigma phi): the moments' mean + C v / mu (below) with
  // x clamped at 0 (as the clamped Lambert term, mlRectifiedMean, clamps n.l), which stays
  // finite where a grazing view makes mu small. Measured on four real maps at 80 degrees and two
  // wall widths under two VTK lights without shadows: the moments' far walls 1.2-5.4 levels
  // too dark, this within -2.6..+0.5 (docs/relief-methods.md, "The masked filter's moments").
  float seenMean = dot(mean, v);
  float seenVariance = dot(v, mlNormalSpread * v);
  float seen = mlRectifiedMean(seenMean, seenVariance);
  if (seen > 1e-4 && seenVariance > 1e-8)
  {
    return mean + (mlNormalSpread * v) * (mlNormalCdf(seenMean / sqrt(seenVariance)) / seen);
  }
#endif
  if (projected <= 0.25 * v.z)
  {
    // The footprint's slopes turn it away from the viewer: too few facets seen to weigh them;
    // the mean normal (its length: the spread, Toksvig 2005).
    return vec3(s * b.x, s * b.y, a.w) / r;
  }
  return (S * v) / (projected * r);
}

// The footprint's visible mean normal at mip level lod (mlMomentsVisibleNormal), or with
// ML_MASKED_FACETS, where the level is computed per texel, that of the facets the viewer sees
// (mlSeenFacetNormal).
vec3 mlVisibleNormal(vec2 uv, vec3 v, float lod)
{
  mlNormalSpread = mat3(0.0);
  vec4 a = vec4(0.0);
  vec4 b = vec4(0.0);
  if (lod < mlMomentFirstLevel)
  {
    // Trilinear as the sampler's, the levels below the texture's from the stored normals.
    int level = int(lod);
    float f = lod - float(level);
#ifdef ML_MASKED_FACETS
    mlSeenFacets seen = mlSeenFacets(0.0, vec3(0.0), mat3(0.0));
    mlAddLevelSeenFacets(mlFacetLookupUv(uv), level, 1.0 - f, v, seen);
    float stored = 0.0;
    if (f > 0.0)
    {
      if (float(level + 1) < mlMomentFirstLevel)
      {
        mlAddLevelSeenFacets(mlFacetLookupUv(uv), level + 1, f, v, seen);
      }
      else
      {
        stored = f;
      }
    }
    vec3 masked = mlSeenFacetNormal(seen);
    if (stored <= 0.0)
    {
      return masked;
    }
    mat3 maskedSpread = mlNormalSpread;
    ML_COUNT_SAMPLE();
    ML_COUNT_SAMPLE();
    vec3 unmasked = mlMomentsVisibleNormal(
      textureLod(mlMomentTexture0, uv, 0.0), textureLod(mlMomentTexture1, uv, 0.0), v);
    mlNormalSpread = (1.0 - stored) * maskedSpread + stored * mlNormalSpread;
    return mix(masked, unmasked, stored);
#else
    mlAddLevelMoments(mlFacetLookupUv(uv), level, 1.0 - f, a, b);
    if (f > 0.0)
    {
      if (float(level + 1) < mlMomentFirstLevel)
      {
        mlAddLevelMoments(mlFacetLookupUv(uv), level + 1, f, a, b);
      }
      else
      {
        ML_COUNT_SAMPLE();
        ML_COUNT_SAMPLE();
        a += f * textureLod(mlMomentTexture0, uv, 0.0);
        b += f * textureLod(mlMomentTexture1, uv, 0.0);
      }
    }
#endif
  }
  else
  {
    ML_COUNT_SAMPLE();
    ML_COUNT_SAMPLE();
    a = textureLod(mlMomentTexture0, uv, lod - mlMomentFirstLevel);
    b = textureLod(mlMomentTexture1, uv, lod - mlMomentFirstLevel);
  }
  return mlMomentsVisibleNormal(a, b, v);
}
#endif

#if !defined(ML_FLOAT_TEXTURES) && defined(ML_STORED_NORMALS)
// A normal (up to its length) from hemispherical octahedral coordinates (Cigolle et al. 2014;
// vtkReliefTextureCache).
vec3 mlOctahedralNormal(vec2 e)
{
  vec2 p = 0.5 * vec2(e.x + e.y, e.x - e.y);
  return vec3(p, 1.0 - abs(p.x) - abs(p.y));
}
#endif

#if defined(ML_FLOAT_TEXTURES) || defined(ML_STORED_NORMALS)
vec3 mlPackedNormalAt(vec2 uv)
{
  ML_COUNT_SAMPLE();
#ifdef ML_FLOAT_TEXTURES
  vec4 texel = textureLod(mlReliefTexture, uv, mlMarchLod);
#ifdef ML_CONE_PACKED
  vec2 nxy = texel.rg * 2.0 - 1.0;
  return vec3(nxy, sqrt(max(0.0, 1.0 - dot(nxy, nxy))));
#else
  return texel.rgb * 2.0 - 1.0;
#endif
#else
  if (mlMarchLod <= 0.0)
  {
    // The four texels' unit normals blended as the float texture's are, by the bilinear weights:
    // blending their octahedral coordinates instead bends the normals between a wall and the
    // flat beside it, which max-mipmap's exact hits show (colour error on real maps).
    ivec2 t[4];
    vec2 f;
    mlBilinearTexels(uv, t, f);
    vec3 n[4];
    for (int k = 0; k < 4; ++k)
    {
      n[k] = normalize(mlOctahedralNormal(texelFetch(mlNormalTexture, t[k], 0).rg));
    }
    return mix(mix(n[0], n[1], f.x), mix(n[2], n[3], f.x), f.y);
  }
  // Level of detail: the filtered coordinates of the level read, as a unit normal (the decoded
  // vector's length is the octahedral map's, not the footprint's spread of normals).
  return normalize(mlOctahedralNormal(textureLod(mlNormalTexture, uv, mlMarchLod).rg));
#endif
}
#endif

#ifdef ML_CONE_PACKED
// Cone ratio at the base level: cone maps are never averaged (an average cone is not a cone).
float mlConeAt(vec2 uv)
{
  ML_COUNT_SAMPLE();
#ifdef ML_FLOAT_TEXTURES
  return max(textureLod(mlReliefTexture, uv, 0.0).b, 0.0);
#else
  float e = textureLod(mlConeTexture, uv, 0.0).r;
  return e / (1.0 - e);
#endif
}

// Depth (x) and cone ratio (y) at uv: one texel's data, so a cone step costs what a linear step
// costs (counted as one sample; compact storage reads it from two small textures).
vec2 mlDepthAndConeAt(vec2 uv)
{
  if (mlOutsideWalledRelief(uv))
  {
    return vec2(0.0); // the edge rule (mlOutsideWalledRelief): solid up to the surface, no cone
  }
#ifndef ML_FLOAT_TEXTURES
  ML_COUNT_SAMPLE();
  float e = textureLod(mlConeTexture, uv, 0.0).r;
  return vec2(textureLod(mlReliefTexture, uv, mlMarchLod).r, e / (1.0 - e));
#elif defined(ML_LEVEL_OF_DETAIL)
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

// (d depth / du, d depth / dv) of the surface marched, the bilinear interpolation of the level-0
// depth texels, at uv: the gradient the exact CPU intersector and the path tracer shade with.
vec2 mlSurfaceGradient(vec2 uv)
{
  ML_COUNT_SAMPLE();
  vec2 x = uv * mlTextureSize - 0.5;
  ivec2 i0 = ivec2(floor(x));
  vec2 f = x - vec2(i0);
  vec4 d = mlTexelQuad(i0); // d00, d10, d01, d11
  return vec2(mix(d.y - d.x, d.w - d.z, f.y), mix(d.z - d.x, d.w - d.y, f.x)) * mlTextureSize;
}

// (d depth / du, d depth / dv) at uv, at level mlMarchLod: the slope the parallax methods step
// along (McGuire & McGuire 2005), smooth across texels as the baked normals are.
vec2 mlDepthGradient(vec2 uv)
{
#ifdef ML_SURFACE_NORMALS
  if (mlMarchLod <= 0.0)
  {
    // The normals are the depth's (not uploaded): their Sobel gradient, from the bilinear depth
    // (both are linear, so the Sobel stencil on the interpolated depth is the interpolation of
    // the texels' Sobel gradients, as the stored normals were filtered): a tap a texel across and
    // half a texel along averages two rows as the stencil's 1-2-1 weights do, 8 taps in all.
    // The surface's own cell gradient (mlSurfaceGradient, what the hit is shaded with) jumps at
    // every texel edge and led iterative parallax astray (mean hit error up to 23% larger, p99
    // up to 50%); plain central differences, without the stencil's smoothing across, up to 24%
    // on a real brick map (docs/relief-methods.md, "The shading normal").
    ML_COUNT_SAMPLE();
    vec2 e = 1.0 / mlTextureSize;
    vec2 h = 0.5 * e;
    float dx = textureLod(mlReliefTexture, uv + vec2(e.x, h.y), 0.0).ML_DEPTH_CHANNEL +
      textureLod(mlReliefTexture, uv + vec2(e.x, -h.y), 0.0).ML_DEPTH_CHANNEL -
      textureLod(mlReliefTexture, uv + vec2(-e.x, h.y), 0.0).ML_DEPTH_CHANNEL -
      textureLod(mlReliefTexture, uv + vec2(-e.x, -h.y), 0.0).ML_DEPTH_CHANNEL;
    float dy = textureLod(mlReliefTexture, uv + vec2(h.x, e.y), 0.0).ML_DEPTH_CHANNEL +
      textureLod(mlReliefTexture, uv + vec2(-h.x, e.y), 0.0).ML_DEPTH_CHANNEL -
      textureLod(mlReliefTexture, uv + vec2(h.x, -e.y), 0.0).ML_DEPTH_CHANNEL -
      textureLod(mlReliefTexture, uv + vec2(-h.x, -e.y), 0.0).ML_DEPTH_CHANNEL;
    return 0.25 * vec2(dx, dy) * mlTextureSize;
  }
#endif
#if defined(ML_FLOAT_TEXTURES) || defined(ML_STORED_NORMALS)
  // Recovered from the baked normal n ~ (k dd/dx, k dd/dy, 1), where x = u and y = v * aspect
  // are measured in texture widths (vtkReliefTextureFilter's convention).
  return mlGradientFromNormal(mlPackedNormalAt(uv));
#else
  // Level of detail, the normals not uploaded (they are the depth's): the Sobel stencil on the
  // filtered depth of the level read, taps one of its texels apart (linear in the depth: the
  // blend of that level's Sobel gradients).
  ML_COUNT_SAMPLE();
  float texels = exp2(mlMarchLod);
  vec2 step = texels / mlTextureSize;
  float d[9];
  for (int j = 0; j < 3; ++j)
  {
    for (int i = 0; i < 3; ++i)
    {
      d[3 * j + i] =
        textureLod(mlReliefTexture, uv + vec2(float(i - 1), float(j - 1)) * step, mlMarchLod).r;
    }
  }
  float gi = ((d[2] + 2.0 * d[5] + d[8]) - (d[0] + 2.0 * d[3] + d[6])) / 8.0;
  float gj = ((d[6] + 2.0 * d[7] + d[8]) - (d[0] + 2.0 * d[1] + d[2])) / 8.0;
  // Per texel of the level -> per unit of u and of v.
  return vec2(gi, gj) * (mlTextureSize / texels);
#endif
}

#if ML_METHOD == ML_MAXIMUM_MIPMAP
uniform sampler2D mlMinDepthPyramid;

// Cell k of level `level` >= ML_PYRAMID_FIRST_LEVEL of the min-depth pyramid
// (vtkReliefMaxMipmapFS.glsl): the minimum depths of its 2 x 2 children (2k, 2k + (1, 0),
// 2k + (0, 1), 2k + (1, 1) of the level below), in float (RGBA32F) or, rounded down, 8-bit
// (RGBA8) storage (vtkMinDepthPyramidTexture); its mip level 0 is the first level stored.
vec4 mlPyramidCell(ivec2 k, int level)
{
  vec4 m = texelFetch(mlMinDepthPyramid, k, level - ML_PYRAMID_FIRST_LEVEL);
#ifndef ML_FLOAT_TEXTURES
  m -= 1e-6; // b / 255 may equal a corner's v / 65535: a rounding of the conversion stays above
#endif
  return m;
}

// The four corner depths (d00, d10, d01, d11) of level-0 cell k, the bilinear patch between
// texels k - 1 and k (clamped into the map: cells 0 and W are the clamp bands outside the
// outermost texel centres), straight from the depth texture. Compact storage: one gather at
// the shared corner of the four texels (textureGather returns (i0, j1), (i1, j1), (i1, j0),
// (i0, j0)), taken one cell inwards at the border, whose band then repeats the edge texels,
// so the sampler's wrap mode does not matter. Float storage (depth in alpha, for measuring):
// four fetches.
vec4 mlCellCorners(ivec2 k)
{
  ivec2 size = ivec2(mlTextureSize);
#ifdef ML_FLOAT_TEXTURES
  ivec2 lo = clamp(k - 1, ivec2(0), size - 1), hi = clamp(k, ivec2(0), size - 1);
  return vec4(texelFetch(mlReliefTexture, lo, 0).a, texelFetch(mlReliefTexture, ivec2(hi.x, lo.y), 0).a,
    texelFetch(mlReliefTexture, ivec2(lo.x, hi.y), 0).a, texelFetch(mlReliefTexture, hi, 0).a);
#else
  ivec2 inner = min(max(k, ivec2(1)), max(size - 1, ivec2(0)));
  vec4 d = mlTexelQuad(inner - 1);
  d = k.x <= 0 ? d.xxzz : (k.x >= size.x ? d.yyww : d);
  d = k.y <= 0 ? d.xyxy : (k.y >= size.y ? d.zwzw : d);
  return d;
#endif
}
#endif
