// SPDX-License-Identifier: BSD-3-Clause
// Shadows of the movable object on the light field's diffuse surfaces (Wither 2005 ch. 4): the
// GPU twin of core/ObjectShadows (ShadowMapBlocked, SampleIrradiance, ObjectShadows::Shade);
// keep the two together. All maps are tiles of one float texture (map m at tile
// (m % mlShadowColumns, m / mlShadowColumns), mlShadowResolution texels a side), read with
// texelFetch so the depth test sees exactly the CPU's texels. mlShadowMode: 0 none, 1 black,
// 2 blend, 3 field, 4 PCF, 5 soft. Positions are in the field's unit sphere. mlShadowedAt shades
// a receiver given by its point, normal and Kd (a relief lit by the field, vtkLightFieldReliefShadowHook:
// the relief's hit point); mlShadowed the light field's own receivers, given per vertex (with
// ML_SHADOW_RECEIVER_GIVEN defined, it and its inputs are left out).

#define ML_SHADOW_MAPS 40
#define ML_SHADOW_EMITTERS 8
#define ML_SHADOW_SAMPLES 128

uniform int mlShadowMode;
uniform sampler2D mlShadowDepth;
uniform int mlShadowColumns;
uniform int mlShadowResolution;
uniform int mlShadowEmitterCount;
uniform vec4 mlShadowParams; // x: depth bias, y: blend alpha, z: PCF kernel, w: removal on
uniform vec4 mlShadowAmbient; // rgb the field's ambient radiance, w 1: ratio, 0: subtraction
uniform vec4 mlShadowMapPosition[ML_SHADOW_MAPS]; // xyz light point, w tan(half angle)
uniform vec4 mlShadowMapAxisX[ML_SHADOW_MAPS];    // w: near plane
uniform vec4 mlShadowMapAxisY[ML_SHADOW_MAPS];
uniform vec4 mlShadowMapAxisZ[ML_SHADOW_MAPS];
uniform vec4 mlShadowEmitterRadiance[ML_SHADOW_EMITTERS]; // rgb Le, w power weight
uniform vec4 mlShadowEmitterNormal[ML_SHADOW_EMITTERS];   // xyz normal
// x: first sample, y: sample count, z: centroid map, w: first sample map (-1: none)
uniform vec4 mlShadowEmitterIndex[ML_SHADOW_EMITTERS];
uniform vec4 mlShadowSample[ML_SHADOW_SAMPLES]; // xyz point on the emitter, w its area

float mlShadowTap(int m, vec3 p, vec3 n, int kernel)
{
  vec3 d = p - mlShadowMapPosition[m].xyz;
  float ez = dot(d, mlShadowMapAxisZ[m].xyz);
  if (mlShadowParams.w > 0.5 && (dot(n, -d) <= 0.0 || ez < mlShadowMapAxisX[m].w))
  {
    return 0.0;
  }
  if (ez == 0.0)
  {
    return 0.0;
  }
  float res = float(mlShadowResolution);
  float scale = 1.0 / (ez * mlShadowMapPosition[m].w);
  float fx = (dot(d, mlShadowMapAxisX[m].xyz) * scale * 0.5 + 0.5) * res;
  float fy = (dot(d, mlShadowMapAxisY[m].xyz) * scale * 0.5 + 0.5) * res;
  if (!(abs(fx) < 2.0 * res && abs(fy) < 2.0 * res))
  {
    return 0.0;
  }
  ivec2 texel = ivec2(int(floor(fx)), int(floor(fy)));
  ivec2 tile = ivec2(m % mlShadowColumns, m / mlShadowColumns) * mlShadowResolution;
  int reach = kernel / 2;
  float inverse = 1.0 / ez;
  int blocked = 0;
  for (int y = -reach; y <= reach; ++y)
  {
    for (int x = -reach; x <= reach; ++x)
    {
      ivec2 t = texel + ivec2(x, y);
      if (t.x < 0 || t.y < 0 || t.x >= mlShadowResolution || t.y >= mlShadowResolution)
      {
        continue;
      }
      float depth = texelFetch(mlShadowDepth, tile + t, 0).r;
      if (depth < 1e30 && inverse < 1.0 / (depth * (1.0 + 1e-4) + mlShadowParams.x))
      {
        ++blocked;
      }
    }
  }
  return float(blocked) / float(kernel * kernel);
}

vec3 mlShadowSampleIrradiance(int e, int i, vec3 p, vec3 n)
{
  vec3 toLight = mlShadowSample[i].xyz - p;
  float d2 = dot(toLight, toLight);
  if (!(d2 > 0.0))
  {
    return vec3(0.0);
  }
  vec3 w = toLight / sqrt(d2);
  float cosLight = max(0.0, -dot(mlShadowEmitterNormal[e].xyz, w));
  float cosReceiver = max(0.0, dot(n, w));
  return mlShadowEmitterRadiance[e].rgb * (mlShadowSample[i].w * cosLight * cosReceiver / d2);
}

// The darkened radiance of a diffuse receiver at p (unit sphere) with unit normal n and albedo
// kd, whose unshadowed radiance is total.
vec3 mlShadowedAt(vec3 total, vec3 p, vec3 n, vec3 kd)
{
  if (mlShadowMode == 0 || mlShadowEmitterCount == 0)
  {
    return total;
  }
  if (mlShadowMode == 1 || mlShadowMode == 2)
  {
    float blocked = 0.0;
    for (int e = 0; e < mlShadowEmitterCount; ++e)
    {
      blocked += mlShadowEmitterRadiance[e].w *
        mlShadowTap(int(mlShadowEmitterIndex[e].z), p, n, 1);
    }
    float alpha = mlShadowMode == 1 ? 1.0 : mlShadowParams.y;
    return total * (1.0 - alpha * (1.0 - max(0.0, 1.0 - blocked)));
  }
  vec3 lost = vec3(0.0);
  bool blocked = false;
  int kernel = mlShadowMode == 4 ? int(mlShadowParams.z) : 1;
  for (int e = 0; e < mlShadowEmitterCount; ++e)
  {
    int first = int(mlShadowEmitterIndex[e].x);
    int count = int(mlShadowEmitterIndex[e].y);
    int firstMap = int(mlShadowEmitterIndex[e].w);
    if (firstMap >= 0) // soft, or field / PCF for an emitter of merged lamps: a map per sample
    {
      for (int i = 0; i < count; ++i)
      {
        float b = mlShadowTap(firstMap + i, p, n, 1);
        if (b > 0.0) // lit fragments (most) skip the irradiance
        {
          blocked = true;
          lost += b * mlShadowSampleIrradiance(e, first + i, p, n);
        }
      }
    }
    else
    {
      float b = mlShadowTap(int(mlShadowEmitterIndex[e].z), p, n, kernel);
      if (b > 0.0)
      {
        blocked = true;
        vec3 direct = vec3(0.0);
        for (int i = 0; i < count; ++i)
        {
          direct += mlShadowSampleIrradiance(e, first + i, p, n);
        }
        lost += b * direct;
      }
    }
  }
  if (!blocked)
  {
    return total;
  }
  if (mlShadowAmbient.w < 0.5)
  {
    return max(vec3(0.0), total - kd / 3.14159265358979 * lost);
  }
  // The share of the lighting the object blocks scales the field's value (ObjectShadows.h: the
  // ratio estimator); Kd cancels per channel.
  vec3 direct = vec3(0.0);
  for (int e = 0; e < mlShadowEmitterCount; ++e)
  {
    int first = int(mlShadowEmitterIndex[e].x);
    int count = int(mlShadowEmitterIndex[e].y);
    for (int i = 0; i < count; ++i)
    {
      direct += mlShadowSampleIrradiance(e, first + i, p, n);
    }
  }
  vec3 lit = mlShadowAmbient.rgb + direct / 3.14159265358979;
  vec3 shadowed = mlShadowAmbient.rgb + max(vec3(0.0), direct - lost) / 3.14159265358979;
  vec3 ratio = vec3(1.0);
  for (int c = 0; c < 3; ++c)
  {
    if (lit[c] > 0.0)
    {
      ratio[c] = clamp(shadowed[c] / lit[c], 0.0, 1.0);
    }
  }
  return total * ratio;
}

#ifndef ML_SHADOW_RECEIVER_GIVEN
in vec3 mlShadowPointVC; // unit sphere
in vec3 mlShadowNormalVC;
in vec3 mlShadowKdVC;

// The darkened radiance of this fragment's diffuse surface, whose unshadowed radiance is total.
vec3 mlShadowed(vec3 total)
{
  return mlShadowedAt(total, mlShadowPointVC, normalize(mlShadowNormalVC), mlShadowKdVC);
}
#endif
