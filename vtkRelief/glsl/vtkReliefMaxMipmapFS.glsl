// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: exact height-field tracing through a min-depth pyramid ("maximum mipmaps",
// Tevs, Ihrke & Seidel, I3D 2008), for the bilinear surface the GPU samples.
//
// Level 0 holds one texel per cell between texel centres, (W+1) x (H+1) cells including the
// clamp-to-edge border cells: the cell's four corner depths (vtkMinDepthPyramidTexture), whose
// minimum bounds the bilinear patch from above. Level L+1 holds the minimum over 2x2 cells of
// level L; sizes halve rounding down (a complete OpenGL mipmap) and a level's last cell also
// covers the leftover cell below it, so level-0 cell k lies in level-L cell
// min(k >> L, size_L - 1). In cell space x = u W - 0.5, texel i sits at x = i and cell k spans
// [k-1, k].

uniform int mlPyramidLevels;
// Cells per level as (w, h) pairs: textureSize() of a level is unreliable on Mesa llvmpipe.
uniform int mlPyramidSizes[32];

// First t in [t0, t1] where the ray meets the bilinear patch of level-0 cell k, whose corner
// depths d = (d00, d10, d01, d11) the pyramid's level 0 holds, or -1.
float mlIntersectCell(vec3 origin, vec3 span, ivec2 k, vec4 d, float t0, float t1)
{
  float d00 = d.x, d10 = d.y, d01 = d.z, d11 = d.w;
  // Patch-local coordinates a, b (0..1 across the cell) are linear in t.
  vec2 x0 = (origin.xy * mlTextureSize - 0.5) - vec2(k - ivec2(1));
  vec2 dx = span.xy * mlTextureSize;
  // f(a, b) = d00 + (d10-d00) a + (d01-d00) b + (d00-d10-d01+d11) a b
  float e1 = d10 - d00, e2 = d01 - d00, e3 = d00 - d10 - d01 + d11;
  // g(t) = ray depth - f: quadratic A t^2 + B t + C
  float A = -e3 * dx.x * dx.y;
  float B = span.z - e1 * dx.x - e2 * dx.y - e3 * (x0.x * dx.y + x0.y * dx.x);
  float C = origin.z - d00 - e1 * x0.x - e2 * x0.y - e3 * x0.x * x0.y;
  float g0 = (A * t0 + B) * t0 + C;
  if (g0 >= 0.0)
  {
    return t0;
  }
  // Smallest root in [t0, t1] where g turns non-negative.
  float best = -1.0;
  if (abs(A) < 1e-12)
  {
    if (B > 0.0)
    {
      float t = -C / B;
      best = (t >= t0 && t <= t1) ? t : -1.0;
    }
  }
  else
  {
    float disc = B * B - 4.0 * A * C;
    if (disc >= 0.0)
    {
      float q = -0.5 * (B + (B >= 0.0 ? 1.0 : -1.0) * sqrt(disc));
      float r0 = q / A;
      float r1 = abs(q) > 1e-30 ? C / q : r0;
      float lo = min(r0, r1), hi = max(r0, r1);
      if (lo >= t0 && lo <= t1)
      {
        best = lo;
      }
      else if (hi >= t0 && hi <= t1)
      {
        best = hi;
      }
    }
  }
  return best;
}

// Hierarchical traversal: skip whole cells whose minimum depth the ray stays above; descend
// where it may hit; at level 0 intersect the bilinear patch exactly. maxIterations bounds the work.
float mlTraceMaxMipmap(vec3 origin, vec3 span, int maxIterations)
{
  ivec2 cells0 = ivec2(mlTextureSize) + 1;
  int top = mlPyramidLevels - 1;
  // Start near the bottom: a view ray enters at depth 0, where the coarse cells' minimum is
  // (nearly) 0 on real maps, so starting at the top only descends again. Measured on real height
  // maps at 45 and 85 degrees (docs/relief-methods.md): level 1 takes 15-25% fewer samples than the
  // top and never more than levels 3 or 5.
  int level = min(1, top);
  float t = 0.0;
  vec2 dx = span.xy * mlTextureSize;
  // Past a cell boundary by a thousandth of a cell, so float rounding cannot keep the ray in it.
  float nudge = min(1e-3 / max(max(abs(dx.x), abs(dx.y)), 1e-6), 1e-5);
  for (int i = 0; i < maxIterations; ++i)
  {
    vec3 p = origin + t * span;
    vec2 x = p.xy * mlTextureSize - 0.5;
    ivec2 k0 = clamp(ivec2(floor(x)) + 1, ivec2(0), cells0 - 1);
    int scale = 1 << level;
    ivec2 sizeL = ivec2(mlPyramidSizes[2 * level], mlPyramidSizes[2 * level + 1]);
    ivec2 kL = min(k0 >> level, sizeL - 1); // k0 >= 0: a shift, not a (scalarised) division
    // The cell's extent in cell space; first and last cells reach to infinity (clamp extension).
    vec2 lo = vec2(kL * scale) - 1.0;
    vec2 hi = vec2((kL + 1) * scale) - 1.0;
    lo = mix(lo, vec2(-1e30), lessThanEqual(kL, ivec2(0)));
    hi = mix(hi, vec2(1e30), greaterThanEqual(kL, sizeL - 1));
    vec2 tx = vec2(1e30);
    tx.x = dx.x > 0.0 ? (hi.x - x.x) / dx.x : (dx.x < 0.0 ? (lo.x - x.x) / dx.x : 1e30);
    tx.y = dx.y > 0.0 ? (hi.y - x.y) / dx.y : (dx.y < 0.0 ? (lo.y - x.y) / dx.y : 1e30);
    float tExit = min(1.0, t + max(min(tx.x, tx.y), 0.0));
    ML_COUNT_SAMPLE();
    vec4 cell = mlPyramidCell(kL, level);
    float minDepth = min(min(cell.x, cell.y), min(cell.z, cell.w));
    float zExit = origin.z + tExit * span.z;
    if (zExit < minDepth && span.z > 0.0 || max(p.z, zExit) < minDepth)
    {
      // Above everything in this cell: skip it; look wider only when the ray also leaves the
      // parent cell (Tevs, Ihrke & Seidel 2008): inside the same parent the coarser cell was
      // already found too deep, and going up would only come down again.
      t = tExit + nudge;
      vec2 xNext = (origin.xy + t * span.xy) * mlTextureSize - 0.5;
      ivec2 kNext = min(clamp(ivec2(floor(xNext)) + 1, ivec2(0), cells0 - 1) >> level, sizeL - 1);
      if (any(notEqual(kNext >> 1, kL >> 1)))
      {
        level = min(level + 1, top);
      }
    }
    else if (level > 0)
    {
      // Move down to where the ray reaches the cell's bound, then look closer.
      if (span.z > 0.0 && p.z < minDepth)
      {
        t = max(t, (minDepth - origin.z) / span.z);
      }
      level -= 1;
    }
    else
    {
      float hit = mlIntersectCell(origin, span, k0, cell, t, tExit);
      if (hit >= 0.0)
      {
        return hit;
      }
      t = tExit + nudge;
      level = min(level + 1, top);
    }
    if (t >= 1.0)
    {
      return 1.0;
    }
  }
  return t;
}
