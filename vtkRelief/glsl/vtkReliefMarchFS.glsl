// Mesolight relief: the march skeleton, written once for every method (seed 000, §4.1.2-4.2).
//
// A ray through the height field in texture space is p(t) = origin + t * span, t in [0, 1], with
// p.z the depth of the ray. A sample is "below" the height field when its depth is at least the
// stored depth. Methods differ only in how the bracket found by the linear search is refined,
// selected at compile time by ML_REFINE (0: none, 1: one secant step, 2: binary search).

// Linear search (Levoy 1990; the "quasi-safe" first pass of relief mapping): returns the first
// sample at or below the height field and, in tAbove, the last sample above it. A view ray ends at
// depth 1, which is never above the height field, so it always returns a hit.
float mlLinearSearch(vec3 origin, vec3 span, int steps, out float tAbove)
{
  float dt = 1.0 / float(steps);
  tAbove = 0.0;
  for (int i = 1; i <= steps; ++i)
  {
    float t = float(i) * dt;
    vec3 p = origin + t * span;
    if (p.z >= mlDepthAt(p.xy))
    {
      return t;
    }
    tAbove = t;
  }
  return 1.0;
}

// Binary search between a sample above and one below (Policarpo et al. 2005): each step halves
// the bracket; the midpoint of the final bracket is returned.
float mlBinaryRefine(vec3 origin, vec3 span, float tAbove, float tBelow, int steps)
{
  for (int i = 0; i < steps; ++i)
  {
    float tm = 0.5 * (tAbove + tBelow);
    vec3 p = origin + tm * span;
    if (p.z >= mlDepthAt(p.xy))
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

// One secant step (parallax occlusion mapping, Tatarchuk 2006): intersect the ray with the
// straight line through the height field at the two bracketing samples.
float mlSecantRefine(vec3 origin, vec3 span, float tAbove, float tBelow)
{
  vec3 pa = origin + tAbove * span;
  vec3 pb = origin + tBelow * span;
  float da = pa.z - mlDepthAt(pa.xy); // < 0: above
  float db = pb.z - mlDepthAt(pb.xy); // >= 0: below
  float denom = da - db;
  return denom < 0.0 ? mix(tAbove, tBelow, da / denom) : tBelow;
}

// First intersection of a view ray entering the surface at origin (origin.z = 0).
float mlTraceView(vec3 origin, vec3 span)
{
  float tAbove;
  float tBelow = mlLinearSearch(origin, span, mlLinearSteps, tAbove);
#if ML_REFINE == 2
  return mlBinaryRefine(origin, span, tAbove, tBelow, mlRefinementSteps);
#elif ML_REFINE == 1
  return mlSecantRefine(origin, span, tAbove, tBelow);
#else
  return tBelow;
#endif
}

// Hard self-shadow test (seed 000, §4.3): march from where the light ray enters the surface down
// to the hit point; the hit is shadowed when the ray passes below the height field before it.
// The number of samples is proportional to the depth travelled, so shallow hits cost less.
bool mlShadowed(vec3 hit, vec3 spanUpPerDepth)
{
  if (hit.z <= 0.0)
  {
    return false;
  }
  vec3 origin = hit + spanUpPerDepth * hit.z; // origin.z == 0
  vec3 span = hit - origin;
  int steps = max(2, int(ceil(float(mlLinearSteps) * hit.z)) + 1);
  float dt = 1.0 / float(steps);
  // Skip the last sample (the hit itself); a small bias avoids self-shadowing acne.
  for (int i = 1; i < steps; ++i)
  {
    vec3 p = origin + (float(i) * dt) * span;
    if (p.z > mlDepthAt(p.xy) + 2e-3)
    {
      return true;
    }
  }
  return false;
}
