// SPDX-License-Identifier: BSD-3-Clause
// Mesolight relief: exact height-field tracing through a min-depth pyramid ("maximum mipmaps",
// Tevs, Ihrke & Seidel, I3D 2008), for the bilinear surface the GPU samples.
//
// Level 0 has one cell between texel centres, (W+1) x (H+1) cells including the clamp-to-edge
// border cells; the traversal reads its four corner depths from the depth texture
// (mlCellCorners: one gather), whose minimum bounds the bilinear patch from above. Levels 1 to
// ML_PYRAMID_FIRST_LEVEL - 1 are not stored; from ML_PYRAMID_FIRST_LEVEL up a cell of level L+1
// holds the minima of its 2x2 cells of level L (RGBA: (0,0), (1,0), (0,1), (1,1)), rounded down
// in the compact storage (vtkMinDepthPyramidTexture). Sizes halve rounding down (a complete
// OpenGL mipmap) and a level's last cell also covers the leftover cell below it, so level-0
// cell k lies in level-L cell min(k >> L, size_L - 1). In cell space x = u W - 0.5, texel i
// sits at x = i and cell k spans [k-1, k].

uniform int mlPyramidLevels; // ML_PYRAMID_FIRST_LEVEL plus the levels stored
uniform float mlPyramidTop; // the map's smallest depth (vtkMinDepthPyramidTexture::GetMinimumDepth)

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

// Does the ray meet the bilinear patch of a level-0 cell (corner depths d, patch-local origin
// a0) within [s0, s1]? g(s) = ray depth - patch depth is quadratic in s; it does if g >= 0 at an
// end or at an interior maximum. No square root: the root is solved once, after the traversal.
bool mlMeetsCell(vec3 origin, vec3 span, vec2 dx, vec2 a0, vec4 d, float s0, float s1)
{
  float e1 = d.y - d.x, e2 = d.z - d.x, e3 = d.x - d.y - d.z + d.w;
  float A = -e3 * dx.x * dx.y;
  float B = span.z - e1 * dx.x - e2 * dx.y - e3 * (a0.x * dx.y + a0.y * dx.x);
  float C = origin.z - d.x - e1 * a0.x - e2 * a0.y - e3 * a0.x * a0.y;
  float sv = A < 0.0 ? clamp(-0.5 * B / A, s0, s1) : s1;
  return max(max((A * s0 + B) * s0 + C, (A * s1 + B) * s1 + C), (A * sv + B) * sv + C) >= 0.0;
}

// Hierarchical traversal, one fetch per iteration: a stored cell (level L >=
// ML_PYRAMID_FIRST_LEVEL) holds the bounds of its 2 x 2 children, so one fetch tests the up to
// three children the ray crosses inside it (split where the ray crosses the cell's midlines).
// The ray skips the cell when it stays above every child's bound and descends into the first
// child it may meet: into that child's own cell when it is stored, else to level 0, whose fetch
// is the cell's four corners (one gather of the depth texture) and whose test is the cell's
// bilinear patch, exactly. A miss there goes on to the next level-0 cell of the same child (a
// walk of at most 2^(ML_PYRAMID_FIRST_LEVEL - 1) cells per axis) without fetching the parent
// again. (Level 1 is not stored, so the pyramid costs 1/3 byte per texel in the compact storage
// with its first level 2.) maxIterations bounds the work; past tEnd (<= 1) the ray is of no
// interest
// and the trace returns 1. A trace that spends maxIterations before either returns where it
// got to and sets mlTraceOutOfIterations: that point is above the surface, not a hit.
bool mlTraceOutOfIterations = false;
// The loop body has one texture fetch and no square root or division: on SIMD hardware that
// runs fragments in lock step (and on llvmpipe, which executes every branch any lane takes) an
// iteration costs the sum of its branches, so the level-0 test shares the iteration's fetch and
// cell arithmetic instead of adding a second fetch and its own exit computation.
float mlTraceMaxMipmap(vec3 origin, vec3 span, int maxIterations, float tEnd)
{
  const int first = ML_PYRAMID_FIRST_LEVEL;
  const int walk = 1 << (first - 1); // level-0 cells per axis of an unstored child
  ivec2 cells0 = ivec2(mlTextureSize) + 1;
  int top = max(mlPyramidLevels - 1, first);
  // Start low: a view ray enters at depth 0, where the coarse cells' minimum is (nearly) 0 on
  // real maps, so starting at the top only descends again (docs/relief-methods.md).
  int level = first;
  // The ray in cell space (x = u W - 0.5; level-0 cell k spans [k-1, k]).
  vec2 x0 = origin.xy * mlTextureSize - 0.5;
  vec2 dx = span.xy * mlTextureSize;
  bvec2 moving = notEqual(dx, vec2(0.0));
  vec2 invDx = vec2(moving.x ? 1.0 / dx.x : 0.0, moving.y ? 1.0 / dx.y : 0.0);
  ivec2 dir = ivec2(greaterThan(dx, vec2(0.0))); // 1 towards higher cells, 0 towards lower
  float invSpanZ = span.z > 0.0 ? 1.0 / span.z : 0.0;
  // The ray enters the map's depth slab at the apex's depth (the whole map's minimum): above it
  // it meets nothing, so the traversal starts there (a map whose highest point lies below the
  // surface, as real height maps often do, would otherwise spend its first iterations there).
  float t = clamp((mlPyramidTop - 1e-6 - origin.z) * invSpanZ, 0.0, 1.0);
  if (t >= tEnd)
  {
    return 1.0;
  }
  // Past a cell boundary by a thousandth of a cell, so float rounding cannot keep the ray in it.
  float nudge = min(1e-3 / max(max(abs(dx.x), abs(dx.y)), 1e-6), 1e-5);
  mlTraceOutOfIterations = false;
  ivec2 hitCell = ivec2(-1);
  vec4 hitDepths = vec4(0.0);
  float hitStart = 0.0, hitEnd = 1.0;
  for (int i = 0; i < maxIterations; ++i)
  {
    vec2 x = x0 + t * dx;
    ivec2 k0 = clamp(ivec2(floor(x)) + 1, ivec2(0), cells0 - 1);
    // Level sizes halve rounding down (a complete mipmap); the last cell covers the leftover.
    ivec2 sizeL = max(cells0 >> level, ivec2(1));
    ivec2 n = min(k0 >> level, sizeL - 1); // k0 >= 0: a shift, not a (scalarised) division
    // The face the ray leaves the cell through on each axis; the edge cells reach to infinity
    // (clamp-to-edge extension).
    bvec2 open = bvec2(moving.x && (dir.x == 1 ? n.x < sizeL.x - 1 : n.x > 0),
      moving.y && (dir.y == 1 ? n.y < sizeL.y - 1 : n.y > 0));
    vec2 face = vec2(((n + dir) << level) - 1);
    vec2 tx = mix(vec2(1e30), (face - x0) * invDx, open);
    bool exitX = tx.x <= tx.y;
    float tExit = clamp(min(tx.x, tx.y), t, tEnd);
    ML_COUNT_SAMPLE();
    bool descend = false;
    if (level == 0)
    {
      vec4 cell = mlCellCorners(n);
      // The cell's corners: its bilinear patch, exactly, from where the ray entered it (the
      // nudge back: the previous cell was tested up to its exit) to where it leaves.
      float s0 = max(t - nudge, 0.0);
      if (mlMeetsCell(origin, span, dx, x0 - vec2(n - ivec2(1)), cell, s0, tExit))
      {
        hitCell = n;
        hitDepths = cell;
        hitStart = s0;
        hitEnd = tExit;
        break;
      }
    }
    else
    {
      vec4 cell = mlPyramidCell(n, level);
      // The children the ray crosses: split [t, tExit] where it crosses the midlines; crossing
      // one flips the child along that axis. (A missing child repeats a present one's bound, so
      // flipping into it is harmless.)
      int cl = level - 1;
      vec2 mid = vec2(((2 * n + 1) << cl) - 1);
      vec2 tm = mix(vec2(1e30), (mid - x0) * invDx, moving);
      bool midX = tm.x <= tm.y;
      float s1 = clamp(min(tm.x, tm.y), t, tExit);
      float s2 = clamp(max(tm.x, tm.y), t, tExit);
      ivec2 q = clamp(min(k0 >> cl, max(cells0 >> cl, ivec2(1)) - 1) - 2 * n, ivec2(0), ivec2(1));
      // The first child the ray may meet, and where the ray enters it.
      bool found = false;
      float aFound = t, mFound = 0.0;
      for (int j = 0; j < 3; ++j)
      {
        float a = j == 0 ? t : (j == 1 ? s1 : s2);
        float b = j == 0 ? s1 : (j == 1 ? s2 : tExit);
        // (A midline crossed before t was crossed before q was found.)
        bool flip = j == 1 ? min(tm.x, tm.y) > t : (j == 2 && max(tm.x, tm.y) > t);
        q = !flip ? q : ((j == 1) == midX ? ivec2(1 - q.x, q.y) : ivec2(q.x, 1 - q.y));
        float m = q.y == 0 ? (q.x == 0 ? cell.x : cell.y) : (q.x == 0 ? cell.z : cell.w);
        bool blocked = (b > a || (j == 0 && tExit <= t)) &&
          max(origin.z + a * span.z, origin.z + b * span.z) >= m;
        if (blocked && !found)
        {
          found = true;
          aFound = a;
          mFound = m;
        }
      }
      if (found)
      {
        // Into this child, where the ray reaches its bound (a level-0 child's bound is its
        // patch's highest corner, so the ray is above the patch until then).
        // (Past a midline by the nudge, so the child is the one found, not its neighbour.)
        descend = true;
        float za = origin.z + aFound * span.z;
        float a = aFound + (aFound > t ? nudge : 0.0);
        t = za < mFound ? max(a, (mFound - origin.z) * invSpanZ) : a;
        // Into the grandchildren at once where they are stored: a grazing ray found blocked at
        // a coarse child nearly always descends again, and every level of the pyramid bounds
        // the surface (Tevs, Ihrke & Seidel 2008), so the level chosen changes the work, never
        // the hit (measured: 0.95x the samples, ms within the timing noise). Below the stored
        // levels, level 0.
        level = cl - 1 >= first ? cl - 1 : (cl >= first ? cl : 0);
      }
    }
    if (!descend)
    {
      // Above every child, or past a level-0 patch: skip the cell. Look wider only when the ray
      // also leaves the parent cell (Tevs, Ihrke & Seidel 2008): inside the same parent the
      // coarser cell was already found too deep, and going up would only come down again. A
      // level-0 cell's parent here is the unstored child it was walked from; leaving it goes
      // back to the first stored level. (At a level's last cell, which also covers the
      // leftover, this may go up early: more work, the same hit.)
      t = tExit + nudge;
      int k = exitX ? n.x : n.y;
      int d = exitX ? dir.x : dir.y;
      int block = level == 0 ? walk : 2;
      int m = k & (block - 1);
      bool leavesParent = d == 1 ? m == block - 1 : m == 0;
      level = leavesParent ? (level == 0 ? first : min(level + 1, top)) : level;
    }
    if (t >= tEnd)
    {
      return 1.0;
    }
  }
  if (hitCell.x >= 0)
  {
    float s = mlIntersectCell(origin, span, hitCell, hitDepths, hitStart, hitEnd);
    return s >= 0.0 ? s : hitStart;
  }
  mlTraceOutOfIterations = true;
  return t;
}

