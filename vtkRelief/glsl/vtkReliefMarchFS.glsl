// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: the march skeleton, written once for every method (Méndez Fernández's thesis, §4.1-4.2).
//
// A ray through the height field in texture space is p(t) = origin + t * span, t in [0, 1], with
// p.z the depth of the ray. A view ray enters at the surface (origin.z = 0) and span.z = 1; a
// shadow ray runs from where the light ray enters the surface down to a hit point. A sample is
// "below" the height field when its depth is at least the stored depth. Methods are selected at
// compile time (ML_METHOD); they share the searches and refinements below.

float mlCosView = 1.0; // cosine of the view angle, for offset limiting
int mlViewSteps = 10;   // linear (or cone) steps for this view ray, adaptive if asked

// Relief mapping on curved meshes (Oliveira & Policarpo 2005, "An efficient representation for
// surface details"; Policarpo, Oliveira & Comba 2005): below the view ray's entry point the mesh
// is locally the quadric z = a u^2 + b v^2 of the tangent plane (per-vertex coefficients,
// interpolated), so the height field at (u, v) lies mlQuadricDepth deeper than on a flat plane.
// Rays stay straight in the entry point's tangent space (plane coordinates: offsets along the
// tangent plane in texture units, depth z below it); a point's depth in the layer is z less the
// quadric's depth. Beyond the paper, to the same order as the quadric: the layer's sheets are
// parallel to the surface, their radius 1 / kappa less the depth, so at plane depth z an offset d
// is the texture offset d / (1 - kappa z) and the layer lies a d^2 / (1 - kappa z) below the
// plane (a cylinder's exact depth r - |p - axis| to second order). mlLayerStretch is kappa times
// the world depth of depth 1, per axis.
// mlLeftLayer: the search ended without a sample at or below the height field.
vec2 mlQuadric = vec2(0.0);       // (a, b) in depth units per squared texture unit
vec2 mlLayerStretch = vec2(0.0);  // kappa x world depth of depth 1, along u and v
vec2 mlQuadricOrigin = vec2(0.0); // the view ray's entry point, where the quadric touches
bool mlLeftLayer = false;

vec2 mlLayerScale(float z)
{
  return vec2(1.0) / max(vec2(1.0) - mlLayerStretch * z, vec2(0.25));
}

// Depth of the layer's top below the tangent plane under the point p (plane coordinates).
float mlQuadricDepth(vec3 p)
{
  vec2 d = p.xy - mlQuadricOrigin;
  return dot(mlQuadric * mlLayerScale(p.z), d * d);
}

// The texture coordinate of a point in plane coordinates.
vec2 mlLayerUV(vec3 p)
{
  return mlQuadricOrigin + (p.xy - mlQuadricOrigin) * mlLayerScale(p.z);
}

// Ray depth minus height-field depth at t: < 0 above the surface, >= 0 at or below it.
float mlGap(vec3 origin, vec3 span, float t)
{
  vec3 p = origin + t * span;
#ifdef ML_CURVED
  return p.z - mlQuadricDepth(p) - mlDepthAt(mlLayerUV(p));
#else
  return p.z - mlDepthAt(p.xy);
#endif
}

// Linear search (Levoy 1990; the "quasi-safe" first pass of relief mapping): the first sample at
// or below the height field and, in tAbove, the last sample above it. A view ray ends at depth 1,
// never above the height field, so it always returns a hit; on a curved layer it may end where it
// leaves the layer's top instead (ML_CURVED), and then a search without a hit sets mlLeftLayer.
float mlLinearSearch(vec3 origin, vec3 span, float tStart, int steps, out float tAbove)
{
  float dt = (1.0 - tStart) / float(steps);
  tAbove = tStart;
  for (int i = 1; i <= steps; ++i)
  {
    float t = tStart + float(i) * dt;
    if (mlGap(origin, span, t) >= 0.0)
    {
      return t;
    }
    tAbove = t;
  }
#ifdef ML_CURVED
  mlLeftLayer = true;
#endif
  return 1.0;
}

// Binary search between a sample above and one below (Policarpo et al. 2005): each step halves
// the bracket; the midpoint of the final bracket is returned.
float mlBinaryRefine(vec3 origin, vec3 span, float tAbove, float tBelow, int steps)
{
  for (int i = 0; i < steps; ++i)
  {
    float tm = 0.5 * (tAbove + tBelow);
    if (mlGap(origin, span, tm) >= 0.0)
    {
      tBelow = tm;
    }
    else
    {
      tAbove = tm;
    }
  }
  return 0.5 * (tAbove + tBelow);
}

// Interval mapping (Risser et al. 2006; Méndez Fernández's thesis, eq. 3) and the secant method: intersect the ray with
// the straight line through the height field at the bracket's ends, keep the half that still
// brackets the crossing, repeat. One step of it is parallax occlusion mapping's refinement.
float mlIntervalRefine(vec3 origin, vec3 span, float tAbove, float tBelow, int steps)
{
  float gA = mlGap(origin, span, tAbove);
  float gB = mlGap(origin, span, tBelow);
  float t = tBelow;
  for (int i = 0; i < steps; ++i)
  {
    float denom = gA - gB;
    if (denom >= 0.0)
    {
      break; // not a bracket (flat or degenerate): keep the sample below
    }
    t = mix(tAbove, tBelow, gA / denom);
    float g = mlGap(origin, span, t);
    if (g >= 0.0)
    {
      tBelow = t;
      gB = g;
    }
    else
    {
      tAbove = t;
      gA = g;
    }
  }
  return t;
}

// Parallax with slope information (McGuire & McGuire 2005; Méndez Fernández's thesis §4.1.1 d): intersect the ray
// with the tangent plane of the height field at the current estimate. Repeated, it is iterative
// parallax mapping (Premecz 2006). Unsafe: it may converge to any intersection.
float mlSlopeStep(vec3 origin, vec3 span, float t)
{
  vec2 x = origin.xy + t * span.xy;
  float h = mlDepthAt(x);
  vec2 g = mlDepthGradient(x);
  float denom = max(1.0 - dot(g, span.xy), 0.2); // a plane nearly along the ray: damp the step
  return clamp((h + dot(g, origin.xy - x)) / denom, 0.0, 1.0);
}

#ifdef ML_CONE_PACKED
// Cone stepping (Dummer 2006; relaxed: Policarpo & Oliveira 2007). From a point above the
// surface, advance to where the ray leaves the cone of the texel below it. Conservative cones
// are empty: the ray never goes below. Relaxed cones may be entered once: the ray may land below
// the surface, having crossed it exactly once, which brackets the first hit.
// Near steep walls cones are thin and the steps stall; each step is therefore at least an even
// share of what remains of the ray, so the search always reaches a sample below the surface (at
// worst it degrades to a linear search of the remainder). Returns the first t found below the
// surface, with tAbove the point before it.
float mlConeSearch(vec3 origin, vec3 span, int steps, out float tAbove)
{
  // Horizontal travel in texture widths per unit of depth.
  float rate = length(vec2(span.x, span.y * mlTexelAspect)) / max(span.z, 1e-6);
  float t = 0.0;
  tAbove = 0.0;
  for (int i = 0; i < steps; ++i)
  {
    vec3 p = origin + t * span;
#ifdef ML_CURVED
    vec2 depthCone = mlDepthAndConeAt(mlLayerUV(p));
    float depth = depthCone.x + mlQuadricDepth(p); // a convex layer falls away: still empty
#else
    vec2 depthCone = mlDepthAndConeAt(p.xy);
    float depth = depthCone.x;
#endif
    if (p.z >= depth)
    {
      return t;
    }
    float c = depthCone.y;
    float coneStep = c * (depth - p.z) / ((rate + c) * max(span.z, 1e-6));
    tAbove = t;
    t = min(t + max(coneStep, (1.0 - t) / float(steps - i)), 1.0);
  }
#ifdef ML_CURVED
  mlLeftLayer = mlGap(origin, span, t) < 0.0; // the last step reached the ray's end unsampled
#endif
  return t;
}
#endif

// First intersection (or the method's estimate of it) of a view ray entering at origin.
float mlTraceView(vec3 origin, vec3 span)
{
  float tAbove = 0.0;
#if ML_METHOD == ML_TEXTURE_MAPPING || ML_METHOD == ML_BUMP
  return 0.0;
#elif ML_METHOD == ML_PARALLAX
  return mlDepthAt(origin.xy); // constant height around the entry point (Kaneko et al. 2001)
#elif ML_METHOD == ML_PARALLAX_OFFSET_LIMITING
  return mlDepthAt(origin.xy) * mlCosView; // offset no longer than the height (Welsh 2004)
#elif ML_METHOD == ML_PARALLAX_SLOPE
  return mlSlopeStep(origin, span, 0.0);
#elif ML_METHOD == ML_ITERATIVE_PARALLAX
  float t = 0.0;
  for (int i = 0; i < mlViewSteps; ++i)
  {
    t = mlSlopeStep(origin, span, t);
  }
  return t;
#elif ML_METHOD == ML_BINARY_SEARCH
  return mlBinaryRefine(origin, span, 0.0, 1.0, mlRefinementSteps);
#elif ML_METHOD == ML_SECANT
  return mlIntervalRefine(origin, span, 0.0, 1.0, mlRefinementSteps);
#elif ML_METHOD == ML_LINEAR_SEARCH
  return mlLinearSearch(origin, span, 0.0, mlViewSteps, tAbove);
#elif ML_METHOD == ML_PARALLAX_OCCLUSION
  float tBelow = mlLinearSearch(origin, span, 0.0, mlViewSteps, tAbove);
  return mlIntervalRefine(origin, span, tAbove, tBelow, 1);
#elif ML_METHOD == ML_RELIEF
  float tBelow = mlLinearSearch(origin, span, 0.0, mlViewSteps, tAbove);
  return mlBinaryRefine(origin, span, tAbove, tBelow, mlRefinementSteps);
#elif ML_METHOD == ML_INTERVAL
  float tBelow = mlLinearSearch(origin, span, 0.0, mlViewSteps, tAbove);
  return mlIntervalRefine(origin, span, tAbove, tBelow, mlRefinementSteps);
#elif ML_METHOD == ML_RELAXED_CONE_BINARY || ML_METHOD == ML_CONSERVATIVE_CONE
  float tBelow = mlConeSearch(origin, span, mlViewSteps, tAbove);
  return mlBinaryRefine(origin, span, tAbove, tBelow, mlRefinementSteps);
#elif ML_METHOD == ML_RELAXED_CONE_INTERVAL
  float tBelow = mlConeSearch(origin, span, mlViewSteps, tAbove);
  return mlIntervalRefine(origin, span, tAbove, tBelow, mlRefinementSteps);
#elif ML_METHOD == ML_MAXIMUM_MIPMAP
  float tEnd = 1.0;
#ifdef ML_SILHOUETTES
  // A hit outside the texture is discarded, so the trace may stop where the ray leaves it.
  vec2 tOut = mix(vec2(1e30), (step(vec2(0.0), span.xy) - origin.xy) / span.xy,
    notEqual(span.xy, vec2(0.0)));
  tEnd = clamp(min(tOut.x, tOut.y) + 1e-6, 0.0, 1.0);
#endif
  return mlTraceMaxMipmap(origin, span, mlViewSteps, tEnd);
#else
  return 0.0;
#endif
}

// Where a view ray entering at origin, hit at t by the march, met a side wall of the walled
// relief (mlOutsideWalledRelief) instead: it left the rectangle below the surface there, and the
// march's hit is that border to within a linear step. t moves onto the border and the wall's
// normal in (u, v), pointing back into the rectangle, is returned; else (0, 0).
vec2 mlSideWall(vec3 origin, vec3 span, inout float t)
{
  vec2 tOut = mix(vec2(1e30), (step(vec2(0.0), span.xy) - origin.xy) / span.xy,
    notEqual(span.xy, vec2(0.0)));
  float tLeave = min(tOut.x, tOut.y);
  vec3 p = origin + tLeave * span;
  if (!mlWalledRelief() || tLeave > 1.0 || t < tLeave - 1.0 / float(max(mlViewSteps, 1)) ||
    p.z >= textureLod(mlReliefTexture, clamp(p.xy, 0.0, 1.0), 0.0).ML_DEPTH_CHANNEL)
  {
    return vec2(0.0);
  }
  t = tLeave;
  return tOut.x <= tOut.y ? vec2(-sign(span.x), 0.0) : vec2(0.0, -sign(span.y));
}

// Hard self-shadow test (Méndez Fernández's thesis, §4.3): march from where the light ray enters the surface down
// to the hit point; the hit is shadowed when the ray passes below the height field before it.
// The work is proportional to the depth travelled, so shallow hits cost less; cone maps and the
// min-depth pyramid skip empty space as they do for view rays.
// The linear shadow march's least clearance above the height field per depth climbed from the
// hit (1 over a flat floor; negative: below it at the first blocked sample), for level of
// detail's soft far shadows (mlShadowVisibility); the other marches leave it as the caller set it.
float mlShadowGap = 1e30;

// The linear shadow march (stepsPerDepth samples per unit of depth travelled, so a shallow hit
// costs a few), recording the clearance mlShadowGap on a flat mesh.
bool mlShadowedLinear(vec3 origin, vec3 span, vec3 hit, float bias, int stepsPerDepth)
{
  int steps = max(2, int(ceil(float(stepsPerDepth) * hit.z)) + 1);
  float dt = 1.0 / float(steps);
  // Skip the last sample (the hit itself).
  for (int i = 1; i < steps; ++i)
  {
    vec3 p = origin + (float(i) * dt) * span;
#ifdef ML_CURVED
    if (p.z > mlQuadricDepth(p) + mlDepthAt(mlLayerUV(p)) + bias)
#else
    float gap = mlDepthAt(p.xy) + bias - p.z;
    mlShadowGap = min(mlShadowGap, gap / max(hit.z - p.z, 1e-4));
    if (gap < 0.0)
#endif
    {
      return true;
    }
  }
  return false;
}

// linearWhenFar: with maximum-mipmap tracing and level of detail, a far pixel (shading level
// above 0) marches the linear march instead of the exact one.
bool mlShadowed(vec3 hit, vec3 spanUpPerDepth, bool linearWhenFar)
{
  if (hit.z <= 1e-4)
  {
    return false;
  }
  vec3 origin = hit + spanUpPerDepth * hit.z; // origin.z == 0
  vec3 span = hit - origin;
  const float bias = 2e-3; // depth units: avoids self-shadowing acne at the hit itself
#if ML_METHOD == ML_MAXIMUM_MIPMAP
#if defined(ML_LEVEL_OF_DETAIL) && !defined(ML_CURVED)
  // The VTK lights' far shadows. Where level of detail softens a far pixel's shadow
  // (mlShadowVisibility: a footprint over a texel at a shading level above 0), the penumbra
  // needs the linear march's clearance, which the pyramid's skips do not measure; 10 steps per
  // unit of depth, the march the Relief 10+8 default took there, so far pixels shade as before
  // the default became exact. The hard shadows of a far pixel's several view rays take it too:
  // the exact march made them darker than the supersampled frame (its hard shadow times the
  // footprint's averaged Lambert term loses the correlation of a facet's light with its shadow;
  // docs/relief-methods.md, "Each far view ray's own hard shadow"). A light set's lights march
  // exactly at every level from a facet facing the light, which keeps that correlation
  // (mlLightSetIrradiance; docs/relief-methods.md, "Light sets on far pixels: a facing facet's
  // shadow").
  if (linearWhenFar && mlFootprint > 1.0 && mlShadeLod > 0.0)
  {
    return mlShadowedLinear(origin, span, hit, bias, 10);
  }
#endif
  float t = mlTraceMaxMipmap(origin + vec3(0.0, 0.0, -bias), span, mlLinearSteps, 1.0);
  if (mlTraceOutOfIterations)
  {
    // The budget ran out on the way (a ray skimming a broad, nearly flat top walks many cells
    // just above it); where it stopped is not an occluder. The rest of the way is marched as
    // the linear search would: a budget spent is not a shadow (a dark speck at a dome's apex).
    vec3 from = origin + t * span;
    return mlShadowedLinear(from, hit - from, hit, bias, mlLinearSteps);
  }
  return t < 1.0 - 1e-3;
#else
  // The linear search's budget: mlLinearSteps per unit of depth travelled, so a shallow hit costs
  // a few samples. The cone march shares it (its floor is then the linear step), so it never
  // samples more than the linear search it accelerates.
#ifdef ML_CONE_PACKED
  int steps = max(2, int(ceil(float(mlLinearSteps) * hit.z)) + 1);
  float dt = 1.0 / float(steps);
  // The linear search's samples at most, and never nearer the hit than its last one (1 - dt):
  // closer samples see the hit's own surface (acne where the hit sits on a steep wall). Cone
  // steps are taken where they are longer than the linear step.
  // (The integer bound only makes termination evident: every step is at least dt, so t passes
  // 1 - dt within steps - 1 iterations.)
  float rate = length(vec2(span.x, span.y * mlTexelAspect)) / span.z;
  float t = dt;
  for (int i = 1; i < steps && t < 1.0 - dt + 1e-4; ++i)
  {
    vec3 p = origin + t * span;
#ifdef ML_CURVED
    vec2 depthCone = mlDepthAndConeAt(mlLayerUV(p));
    float depth = depthCone.x + mlQuadricDepth(p);
#else
    vec2 depthCone = mlDepthAndConeAt(p.xy);
    float depth = depthCone.x;
#endif
    if (p.z > depth + bias)
    {
      return true;
    }
    float c = depthCone.y;
    t += max(c * (depth - p.z) / ((rate + c) * span.z), dt);
  }
  return false;
#else
  return mlShadowedLinear(origin, span, hit, bias, mlLinearSteps);
#endif
#endif
}
