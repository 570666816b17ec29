// SPDX-License-Identifier: BSD-3-Clause
// The one GLSL copy of the sRGB curve (the C++ one is mesolight::ToSRGB, common/DisplayTransform.h),
// spliced in by the light field mapper and the relief mapper.
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
